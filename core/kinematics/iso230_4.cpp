#include "core/kinematics/iso230_4.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double wrap360(double deg) {
  double a = std::fmod(deg, 360.0);
  if (a < 0.0) a += 360.0;
  if (a >= 360.0) a -= 360.0;
  return a;
}

/// Step from a to b wrapped into (-180, 180].
double angleStep(double a, double b) {
  double d = std::fmod(b - a, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; }), s.end());
  return s;
}

/// Kasa's algebraic fit: x^2 + y^2 + D x + E y + F = 0 in the least-squares sense (data centred on their
/// mean for conditioning). nullopt for fewer than 3 points or points on a line.
std::optional<LsqCircle> kasaFit(const std::vector<Eigen::Vector2d>& points) {
  const auto n = static_cast<Eigen::Index>(points.size());
  if (n < 3) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(n);
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector2d q = points[static_cast<std::size_t>(k)] - mean;
    a.row(k) << q.x(), q.y(), 1.0;
    b(k) = -q.squaredNorm();
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(1e-12);
  if (qr.rank() < 3) return std::nullopt;
  const Eigen::Vector3d x = qr.solve(b);
  LsqCircle c;
  c.centreMm = mean + Eigen::Vector2d(-x(0) / 2.0, -x(1) / 2.0);
  const double r2 = x(0) * x(0) / 4.0 + x(1) * x(1) / 4.0 - x(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  c.radiusMm = std::sqrt(r2);
  return c;
}

std::optional<LsqCircle> geometricFit(const std::vector<Eigen::Vector2d>& points) {
  std::optional<LsqCircle> start = kasaFit(points);
  if (!start) return std::nullopt;
  LsqCircle c = *start;
  const auto n = static_cast<Eigen::Index>(points.size());
  Eigen::MatrixXd j(n, 3);
  Eigen::VectorXd e(n);
  for (int iteration = 0; iteration < 100; ++iteration) {
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::Vector2d d = points[static_cast<std::size_t>(k)] - c.centreMm;
      const double r = d.norm();
      const Eigen::Vector2d u = r > 0.0 ? Eigen::Vector2d(d / r) : Eigen::Vector2d::Zero();
      j.row(k) << -u.x(), -u.y(), -1.0;
      e(k) = r - c.radiusMm;
    }
    const Eigen::Vector3d step = j.colPivHouseholderQr().solve(-e);
    if (!step.allFinite()) return std::nullopt;
    c.centreMm += step.head<2>();
    c.radiusMm += step(2);
    if (step.norm() <= 1e-13 * std::max(1.0, c.radiusMm)) break;
  }
  double sum = 0.0;
  for (const auto& p : points) sum += std::pow((p - c.centreMm).norm() - c.radiusMm, 2);
  c.rmsMm = std::sqrt(sum / static_cast<double>(n));
  if (!(c.radiusMm > 0.0) || !c.centreMm.allFinite() || !std::isfinite(c.rmsMm)) return std::nullopt;
  return c;
}

/// A polar sample about some centre: angle (deg, [0, 360)) and radius (or radius minus a constant).
struct Polar {
  double angleDeg;
  double radius;
};

/// The fit of one set of samples and their radii about its centre.
struct Fitted {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< absolute, or relative to c_nom when linearised
  double radiusDeviation = 0.0;                      ///< LSQ radius - R_nom
  std::vector<Polar> polar;                          ///< about the fitted centre
};

std::optional<Fitted> fitSamples(const CircularTrace& t, const std::vector<std::size_t>& idx) {
  if (idx.size() < 3) return std::nullopt;
  Fitted f;
  f.polar.reserve(idx.size());
  if (t.nominalRadiusMm) {
    const double r0 = *t.nominalRadiusMm;
    std::vector<Eigen::Vector2d> pts;
    pts.reserve(idx.size());
    for (const std::size_t k : idx) {
      const double a = t.angleDeg[k] / kDegPerRad;
      pts.push_back(t.nominalCentreMm + (r0 + t.deviationMm[k]) * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
    const std::optional<LsqCircle> c = geometricFit(pts);
    if (!c) return std::nullopt;
    f.centre = c->centreMm;
    f.radiusDeviation = c->radiusMm - r0;
    for (const auto& p : pts) {
      const Eigen::Vector2d d = p - c->centreMm;
      f.polar.push_back({wrap360(std::atan2(d.y(), d.x()) * kDegPerRad), d.norm()});
    }
    return f;
  }
  // Linearised (limacon): d = dr + cx cos + cy sin.
  const auto n = static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::size_t i = idx[static_cast<std::size_t>(k)];
    const double th = t.angleDeg[i] / kDegPerRad;
    a.row(k) << 1.0, std::cos(th), std::sin(th);
    b(k) = t.deviationMm[i];
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(1e-10);
  if (qr.rank() < 3) return std::nullopt;
  const Eigen::Vector3d x = qr.solve(b);
  if (!x.allFinite()) return std::nullopt;
  f.radiusDeviation = x(0);
  f.centre = Eigen::Vector2d(x(1), x(2));
  for (const std::size_t i : idx) {
    const double th = t.angleDeg[i] / kDegPerRad;
    f.polar.push_back({t.angleDeg[i], t.deviationMm[i] - x(1) * std::cos(th) - x(2) * std::sin(th)});
  }
  return f;
}

/// Largest |r_query(theta) - r_reference(theta)| with the reference interpolated linearly in angle
/// (see the header comment); nullopt when no query angle lies within the reference's coverage.
std::optional<double> largestDifference(const std::vector<Polar>& query, std::vector<Polar> reference) {
  if (reference.size() < 2 || query.empty()) return std::nullopt;
  std::sort(reference.begin(), reference.end(),
            [](const Polar& a, const Polar& b) { return a.angleDeg < b.angleDeg; });
  std::vector<double> gaps;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const double next =
        k + 1 < reference.size() ? reference[k + 1].angleDeg : reference.front().angleDeg + 360.0;
    const double g = next - reference[k].angleDeg;
    if (g > 1e-12) gaps.push_back(g);
  }
  if (gaps.empty()) return std::nullopt;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  const double limit = 2.0 * gaps[gaps.size() / 2] + 1e-9;
  std::optional<double> largest;
  for (const Polar& q : query) {
    const auto it = std::upper_bound(reference.begin(), reference.end(), q.angleDeg,
                                     [](double a, const Polar& p) { return a < p.angleDeg; });
    Polar prev = it == reference.begin() ? reference.back() : *(it - 1);
    Polar next = it == reference.end() ? reference.front() : *it;
    if (it == reference.begin()) prev.angleDeg -= 360.0;
    if (it == reference.end()) next.angleDeg += 360.0;
    const double gap = next.angleDeg - prev.angleDeg;
    if (gap > limit) continue;
    const double r = gap > 1e-12
                         ? prev.radius + (next.radius - prev.radius) * (q.angleDeg - prev.angleDeg) / gap
                         : prev.radius;
    const double d = std::abs(q.radius - r);
    if (!largest || d > *largest) largest = d;
  }
  return largest;
}

}  // namespace

CircularTrace circularTraceOf(const MeasuredPath& path) {
  const std::size_t n = path.size();
  const ErrorContext where{path.source, 0, 0, "x_cmd_mm"};
  if (n < 3)
    throw ValidationError(where, "a circular test needs at least 3 points, got " + std::to_string(n));
  CircularTrace t;
  t.source = path.source;
  t.lines = path.lines;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& c : path.command) centre += c;
  centre /= static_cast<double>(n);
  double radius = 0.0;
  for (const auto& c : path.command) radius += (c - centre).norm();
  radius /= static_cast<double>(n);
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw ValidationError(where, "the commanded points do not describe a circle (radius 0)");
  }
  t.nominalCentreMm = centre;
  t.nominalRadiusMm = radius;
  t.counterClockwise.assign(n, true);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Eigen::Vector2d u = path.command[k] - centre, v = path.command[k + 1] - centre;
    t.counterClockwise[k] = u.x() * v.y() - u.y() * v.x() >= 0.0;
  }
  t.counterClockwise[n - 1] = t.counterClockwise[n - 2];
  t.angleDeg.reserve(n);
  t.deviationMm.reserve(n);
  for (const auto& p : path.measured) {
    const Eigen::Vector2d d = p - centre;
    t.angleDeg.push_back(wrap360(std::atan2(d.y(), d.x()) * kDegPerRad));
    t.deviationMm.push_back(d.norm() - radius);
  }
  return t;
}

bool isRadialCircularTest(const CsvTable& table) {
  return table.columnIndex("x_cmd_mm") < 0 && table.columnIndex("angle_deg") >= 0 &&
         (table.columnIndex("deviation_um") >= 0 || table.columnIndex("deviation_mm") >= 0);
}

CircularTrace radialTraceFromCsv(const CsvTable& t) {
  const std::size_t ang = t.requireColumn("angle_deg");
  const int um = t.columnIndex("deviation_um"), mm = t.columnIndex("deviation_mm");
  if (um < 0 && mm < 0) (void)t.requireColumn("deviation_um");
  if (um >= 0 && mm >= 0) {
    throw ValidationError(ErrorContext{t.source(), 0, 0, "deviation_mm"},
                          "give the radial deviation once: deviation_um or deviation_mm, not both");
  }
  const std::size_t dev = static_cast<std::size_t>(um >= 0 ? um : mm);
  const double scale = um >= 0 ? 1e-3 : 1.0;
  const int dir = t.columnIndex("direction"), run = t.columnIndex("run"), rad = t.columnIndex("radius_mm");
  t.requireRows(3);
  const std::size_t n = t.rowCount();
  CircularTrace tr;
  tr.source = t.source();
  tr.radialOnly = true;
  std::vector<double> raw(n);
  for (std::size_t r = 0; r < n; ++r) {
    raw[r] = t.number(r, ang);
    tr.angleDeg.push_back(wrap360(raw[r]));
    tr.deviationMm.push_back(t.number(r, dev) * scale);
    tr.lines.push_back(t.lineOf(r));
    if (run >= 0) {
      const double v = t.number(r, static_cast<std::size_t>(run));
      if (v != std::floor(v) || std::abs(v) > 1e9) {
        throw ValidationError(ErrorContext{t.source(), t.lineOf(r), run + 1, "run"},
                              "'" + t.cell(r, static_cast<std::size_t>(run)) + "' is not a whole run number");
      }
      tr.run.push_back(static_cast<long>(v));
    }
    if (rad >= 0) {
      const double v = t.number(r, static_cast<std::size_t>(rad));
      const ErrorContext where{t.source(), t.lineOf(r), rad + 1, "radius_mm"};
      if (!(v > 0.0)) throw ValidationError(where, "the nominal radius must be positive");
      if (!tr.nominalRadiusMm) {
        tr.nominalRadiusMm = v;
      } else if (std::abs(v - *tr.nominalRadiusMm) > 1e-9 * std::max(1.0, v)) {
        throw ValidationError(where, "the nominal radius must be the same on every row (" +
                                         CsvWriter::formatNumber(*tr.nominalRadiusMm) + " on the first)");
      }
    }
  }
  tr.counterClockwise.assign(n, true);
  if (dir >= 0) {
    for (std::size_t r = 0; r < n; ++r) {
      const std::string v = lower(t.cell(r, static_cast<std::size_t>(dir)));
      if (v == "ccw" || v == "counterclockwise" || v == "counter-clockwise" || v == "anticlockwise" ||
          v == "anti-clockwise" || v == "+1" || v == "1" || v == "+") {
        tr.counterClockwise[r] = true;
      } else if (v == "cw" || v == "clockwise" || v == "-1" || v == "-") {
        tr.counterClockwise[r] = false;
      } else {
        throw ParseError(ErrorContext{t.source(), t.lineOf(r), dir + 1, "direction"},
                         "'" + t.cell(r, static_cast<std::size_t>(dir)) + "' is not a direction (ccw or cw)");
      }
    }
  } else {
    for (std::size_t k = 0; k + 1 < n; ++k) tr.counterClockwise[k] = angleStep(raw[k], raw[k + 1]) >= 0.0;
    tr.counterClockwise[n - 1] = tr.counterClockwise[n - 2];
  }
  return tr;
}

CircularTrace circularTraceFromCsv(const CsvTable& table) {
  if (isRadialCircularTest(table)) return radialTraceFromCsv(table);
  return circularTraceOf(measuredPathFromCsv(table));
}

CircularTrace readCircularTrace(const std::string& path, const CsvReadOptions& csv) {
  return circularTraceFromCsv(readCsvFile(path, csv));
}

LsqCircle fitLsqCircle(const std::vector<Eigen::Vector2d>& points, const std::string& source) {
  const ErrorContext where{source, 0, 0, {}};
  if (points.size() < 3) {
    throw ValidationError(
        where, "a least-squares circle needs at least 3 points, got " + std::to_string(points.size()));
  }
  const std::optional<LsqCircle> c = geometricFit(points);
  if (!c) throw ValidationError(where, "the points do not determine a circle (they lie on a line)");
  return *c;
}

const Iso230Direction* Iso230Result::direction(bool counterClockwise) const {
  for (const auto& d : directions) {
    if (d.counterClockwise == counterClockwise) return &d;
  }
  return nullptr;
}

Iso230Result evaluateIso230_4(const CircularTrace& t) {
  Iso230Result res;
  res.nominalCentreMm = t.nominalCentreMm;
  res.nominalRadiusMm = t.nominalRadiusMm;
  res.linearised = !t.nominalRadiusMm.has_value();
  std::vector<Polar> polar[2];  // [0] CCW, [1] CW, about c_both
  std::vector<std::size_t> all;
  for (const bool ccw : {true, false}) {
    std::vector<std::size_t> idx;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t.counterClockwise[k] == ccw) idx.push_back(k);
    }
    all.insert(all.end(), idx.begin(), idx.end());
    const std::optional<Fitted> f = fitSamples(t, idx);
    if (!f) continue;
    Iso230Direction d;
    d.counterClockwise = ccw;
    d.points = idx.size();
    d.lsqCentreMm = f->centre;
    d.lsqRadiusDeviationMm = f->radiusDeviation;
    if (t.nominalRadiusMm) d.lsqRadiusMm = *t.nominalRadiusMm + f->radiusDeviation;
    const auto [lo, hi] = std::minmax_element(
        f->polar.begin(), f->polar.end(), [](const Polar& a, const Polar& b) { return a.radius < b.radius; });
    d.circularDeviationMm = hi->radius - lo->radius;
    d.radialDeviationMinMm = d.radialDeviationMaxMm = t.deviationMm[idx.front()];
    for (const std::size_t k : idx) {
      d.radialDeviationMinMm = std::min(d.radialDeviationMinMm, t.deviationMm[k]);
      d.radialDeviationMaxMm = std::max(d.radialDeviationMaxMm, t.deviationMm[k]);
    }
    res.directions.push_back(d);
  }
  if (res.directions.size() == 2) {
    std::sort(all.begin(), all.end());
    const std::optional<Fitted> both = fitSamples(t, all);
    if (both) {
      res.hysteresisCentreMm = both->centre;
      for (std::size_t i = 0; i < all.size(); ++i)
        polar[t.counterClockwise[all[i]] ? 0 : 1].push_back(both->polar[i]);
      const std::optional<double> a = largestDifference(polar[1], polar[0]);
      const std::optional<double> b = largestDifference(polar[0], polar[1]);
      if (a || b) res.circularHysteresisMm = std::max(a.value_or(0.0), b.value_or(0.0));
    }
  }
  return res;
}

nlohmann::json iso230ResultToJson(const Iso230Result& r) {
  using nlohmann::json;
  auto xy = [](const Eigen::Vector2d& v) { return json::array({v.x(), v.y()}); };
  auto optional = [](const std::optional<double>& v, double scale) {
    return v ? json(*v * scale) : json(nullptr);
  };
  json j;
  j["nominal_centre_mm"] = xy(r.nominalCentreMm);
  j["nominal_radius_mm"] = optional(r.nominalRadiusMm, 1.0);
  j["linearised"] = r.linearised;
  j["f_about"] = "nominal centre";
  j["circular_hysteresis_h_um"] = optional(r.circularHysteresisMm, 1000.0);
  j["hysteresis_centre_mm"] = r.circularHysteresisMm ? xy(r.hysteresisCentreMm) : json(nullptr);
  for (const bool ccw : {true, false}) {
    const Iso230Direction* d = r.direction(ccw);
    json& o = j[ccw ? "ccw" : "cw"];
    if (d == nullptr) {
      o = nullptr;
      continue;
    }
    o["points"] = d->points;
    o["circular_deviation_g_um"] = d->circularDeviationMm * 1000.0;
    o["radial_deviation_f_max_um"] = d->radialDeviationMaxMm * 1000.0;
    o["radial_deviation_f_min_um"] = d->radialDeviationMinMm * 1000.0;
    o["lsq_centre_mm"] = xy(d->lsqCentreMm);
    o["lsq_radius_mm"] = optional(d->lsqRadiusMm, 1.0);
    o["lsq_radius_deviation_um"] = d->lsqRadiusDeviationMm * 1000.0;
  }
  return j;
}

}  // namespace metrofit
