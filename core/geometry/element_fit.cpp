#include "core/geometry/element_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/geometry/element_model.h"
#include "core/optim/least_squares.h"

namespace metrofit::geometry {
namespace {

using detail::ElementModel;
using Index = std::vector<std::size_t>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;

Eigen::Matrix3d frameWithZ(const Eigen::Vector3d& zIn) {
  const Eigen::Vector3d z = zIn.normalized();
  const Eigen::Vector3d t = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = (t - t.dot(z) * z).normalized();
  Eigen::Matrix3d F;
  F.col(0) = x;
  F.col(1) = z.cross(x);
  F.col(2) = z;
  return F;
}

/// Centroid, principal axes (columns, by decreasing spread) and RMS radius of the points idx.
struct Principal {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  double rms = 0.0;
};

Principal principal(const std::vector<Eigen::Vector3d>& pts, const Index& idx) {
  Principal p;
  for (std::size_t i : idx) p.centroid += pts[i];
  p.centroid /= static_cast<double>(idx.size());
  Eigen::MatrixXd A(static_cast<Eigen::Index>(idx.size()), 3);
  for (std::size_t r = 0; r < idx.size(); ++r)
    A.row(static_cast<Eigen::Index>(r)) = (pts[idx[r]] - p.centroid).transpose();
  p.rms = std::sqrt(A.squaredNorm() / static_cast<double>(idx.size()));
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinV);
  p.axes = svd.matrixV();
  if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);
  return p;
}

/// Algebraic (Kasa) circle of the local (x, y) of q: |q|^2 = 2 c.q + k. Returns (x0, y0, r).
Eigen::Vector3d kasaCircle(const std::vector<Eigen::Vector3d>& q) {
  Eigen::MatrixXd A(static_cast<Eigen::Index>(q.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(q.size()));
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    A(r, 0) = 2.0 * q[i].x();
    A(r, 1) = 2.0 * q[i].y();
    A(r, 2) = 1.0;
    b(r) = q[i].head<2>().squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  double r2 = s(2) + s.head<2>().squaredNorm();
  if (!(r2 > 0.0) || !std::isfinite(r2)) {
    r2 = 0.0;
    for (const auto& p : q) r2 += (p.head<2>() - s.head<2>()).squaredNorm();
    r2 /= static_cast<double>(q.size());
  }
  return {s(0), s(1), std::sqrt(r2)};
}

/// Algebraic sphere: (cx, cy, cz, r).
Eigen::Vector4d kasaSphere(const std::vector<Eigen::Vector3d>& q) {
  Eigen::MatrixXd A(static_cast<Eigen::Index>(q.size()), 4);
  Eigen::VectorXd b(static_cast<Eigen::Index>(q.size()));
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    A.block<1, 3>(r, 0) = 2.0 * q[i].transpose();
    A(r, 3) = 1.0;
    b(r) = q[i].squaredNorm();
  }
  const Eigen::Vector4d s = A.colPivHouseholderQr().solve(b);
  double r2 = s(3) + s.head<3>().squaredNorm();
  if (!(r2 > 0.0) || !std::isfinite(r2)) {
    r2 = 0.0;
    for (const auto& p : q) r2 += (p - s.head<3>()).squaredNorm();
    r2 /= static_cast<double>(q.size());
  }
  return {s(0), s(1), s(2), std::sqrt(r2)};
}

std::vector<Eigen::Vector3d> local(const std::vector<Eigen::Vector3d>& pts, const Index& idx,
                                   const Eigen::Vector3d& o, const Eigen::Matrix3d& F) {
  std::vector<Eigen::Vector3d> q;
  q.reserve(idx.size());
  for (std::size_t i : idx) q.push_back(F.transpose() * (pts[i] - o));
  return q;
}

struct Candidate {
  ElementModel model;
  Eigen::VectorXd x;
};

/// Start models and parameters for the points idx (element_fit.h: starts).
std::vector<Candidate> starts(ElementKind kind, double fixedR, const std::vector<Eigen::Vector3d>& pts,
                              const Index& idx) {
  const Principal pc = principal(pts, idx);
  const double L = pc.rms;
  std::vector<Candidate> out;
  auto add = [&](const Eigen::Matrix3d& F,
                 const std::function<Eigen::VectorXd(const std::vector<Eigen::Vector3d>&)>& x0) {
    const ElementModel m(kind, fixedR, pts, pc.centroid, F, L);
    out.push_back({m, x0(local(pts, idx, pc.centroid, F))});
  };
  switch (kind) {
    case ElementKind::Plane:
      add(frameWithZ(pc.axes.col(2)),
          [](const std::vector<Eigen::Vector3d>&) { return Eigen::VectorXd(Eigen::VectorXd::Zero(3)); });
      break;
    case ElementKind::Line:
      add(frameWithZ(pc.axes.col(0)),
          [](const std::vector<Eigen::Vector3d>&) { return Eigen::VectorXd(Eigen::VectorXd::Zero(4)); });
      break;
    case ElementKind::Circle:
      add(frameWithZ(pc.axes.col(2)), [&](const std::vector<Eigen::Vector3d>& q) {
        const Eigen::Vector3d c = kasaCircle(q);
        Eigen::VectorXd x(fixedR > 0.0 ? 2 : 3);
        x(0) = c(0);
        x(1) = c(1);
        if (fixedR <= 0.0) x(2) = c(2);
        return x;
      });
      break;
    case ElementKind::Sphere:
      add(pc.axes, [&](const std::vector<Eigen::Vector3d>& q) {
        const Eigen::Vector4d s = kasaSphere(q);
        if (fixedR > 0.0) {
          // The algebraic centre, moved along its direction from the centroid so that the radius is R.
          return Eigen::VectorXd(s.head<3>() * (s(3) > 0.0 ? fixedR / s(3) : 1.0));
        }
        return Eigen::VectorXd(s);
      });
      break;
    case ElementKind::Cylinder:
      for (int j = 0; j < 3; ++j) {
        add(frameWithZ(pc.axes.col(j)), [&](const std::vector<Eigen::Vector3d>& q) {
          const Eigen::Vector3d c = kasaCircle(q);
          Eigen::VectorXd x = Eigen::VectorXd::Zero(fixedR > 0.0 ? 4 : 5);
          x(0) = c(0);
          x(1) = c(1);
          if (fixedR <= 0.0) x(4) = c(2);
          return x;
        });
      }
      break;
    case ElementKind::Cone:
      for (int j = 0; j < 3; ++j) {
        add(frameWithZ(pc.axes.col(j)), [&](const std::vector<Eigen::Vector3d>& q) {
          const Eigen::Vector3d c = kasaCircle(q);
          // rho = r0 + t h by linear least squares.
          Eigen::MatrixXd A(static_cast<Eigen::Index>(q.size()), 2);
          Eigen::VectorXd b(static_cast<Eigen::Index>(q.size()));
          for (std::size_t i = 0; i < q.size(); ++i) {
            A(static_cast<Eigen::Index>(i), 0) = 1.0;
            A(static_cast<Eigen::Index>(i), 1) = q[i].z();
            b(static_cast<Eigen::Index>(i)) = (q[i].head<2>() - c.head<2>()).norm();
          }
          Eigen::Vector2d s = A.colPivHouseholderQr().solve(b);
          if (!s.allFinite()) s = Eigen::Vector2d(c(2), 0.0);
          Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
          x(0) = c(0);
          x(1) = c(1);
          x(4) = s(0);
          x(5) = std::atan(s(1));
          return x;
        });
      }
      break;
  }
  return out;
}

/// Renumbers the stages' iterations into one run and forwards them to the user's observer.
class StageObserver final : public Observer {
 public:
  StageObserver(Observer* user, RunInfo& run, bool keepTrace)
      : user_(user), run_(run), keepTrace_(keepTrace) {}
  ObserverDecision onIteration(const IterationSummary& s) override {
    IterationSummary t = s;
    t.iteration = next_++;
    t.evaluations = evaluations_ + s.evaluations;
    t.bestX.clear();
    t.progress = -1.0;
    if (notify(user_, run_, t, keepTrace_)) {
      cancelled_ = true;
      return ObserverDecision::Stop;
    }
    return ObserverDecision::Continue;
  }
  /// A stage ended after `evaluations` evaluations of its own.
  void endStage(long evaluations) { evaluations_ += evaluations; }
  bool cancelled() const { return cancelled_; }

 private:
  Observer* user_;
  RunInfo& run_;
  bool keepTrace_;
  long next_ = 0;
  long evaluations_ = 0;
  bool cancelled_ = false;
};

struct LsFit {
  ElementModel model;
  Eigen::VectorXd x;
  optim::LeastSquaresSummary summary;
};

optim::LeastSquaresSummary solveLs(const ElementModel& m, Eigen::VectorXd& x, const Index& idx,
                                   long maxIterations, StageObserver& obs) {
  const optim::Residual f = [&](const Eigen::VectorXd& xx, Eigen::VectorXd& r, Eigen::MatrixXd*) {
    r.resize(static_cast<Eigen::Index>(idx.size()));
    for (std::size_t k = 0; k < idx.size(); ++k) r(static_cast<Eigen::Index>(k)) = m.residual(xx, idx[k]);
  };
  optim::LeastSquaresOptions o;
  o.jacobian = optim::LeastSquaresOptions::Jacobian::ForwardDifference;
  o.maxIterations = maxIterations;
  o.costTolerance = 1e-14;
  o.stepTolerance = 1e-14;
  optim::LeastSquaresSummary s = optim::solveLeastSquares(f, x, o, &obs);
  obs.endStage(s.residualEvaluations + s.jacobianEvaluations);
  return s;
}

[[noreturn]] void degenerate(const std::string& source, ElementKind kind, const std::string& why) {
  throw ValidationError(ErrorContext{source, 0, 0, {}},
                        std::string("the points do not determine a ") + toString(kind) + " (" + why + ")");
}

LsFit fitFromStarts(const PointSet& set, ElementKind kind, double fixedR, const Index& idx,
                    long maxIterations, StageObserver& obs) {
  std::vector<Candidate> cands = starts(kind, fixedR, set.points, idx);
  std::optional<LsFit> best;
  std::string why = "no start";
  for (auto& c : cands) {
    if (!c.x.allFinite()) continue;
    Eigen::VectorXd x = c.x;
    optim::LeastSquaresSummary s = solveLs(c.model, x, idx, maxIterations, obs);
    if (s.termination == optim::LeastSquaresTermination::Failed || !x.allFinite()) {
      why = s.message;
      continue;
    }
    if (!best || s.finalCost < best->summary.finalCost) best = LsFit{c.model, x, s};
    if (obs.cancelled()) break;
  }
  if (!best) degenerate(set.source, kind, why);
  return *best;
}

double median(std::vector<double> v) {
  const std::size_t n = v.size();
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n / 2), v.end());
  const double hi = v[n / 2];
  if (n % 2 == 1) return hi;
  return 0.5 * (hi + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n / 2)));
}

/// The angular coverage of the fitted points (element_fit.h).
double coverageDeg(const FittedElement& e, const std::vector<Eigen::Vector3d>& pts, const Index& idx) {
  if (e.kind == ElementKind::Plane || e.kind == ElementKind::Line) return 0.0;
  if (e.kind == ElementKind::Sphere) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> u;
    for (std::size_t i : idx) {
      const Eigen::Vector3d w = pts[i] - e.centre;
      if (w.norm() > 0.0) u.push_back(w.normalized());
    }
    for (const auto& v : u) mean += v;
    if (u.empty()) return 0.0;
    if (mean.norm() < 1e-3 * static_cast<double>(u.size())) return 180.0;
    mean.normalize();
    double half = 0.0;
    for (const auto& v : u) half = std::max(half, std::acos(std::clamp(v.dot(mean), -1.0, 1.0)));
    return half * kDeg;
  }
  const Eigen::Matrix3d F = frameWithZ(e.axis);
  std::vector<double> phi;
  for (std::size_t i : idx) {
    const Eigen::Vector3d q = F.transpose() * (pts[i] - e.centre);
    if (q.head<2>().norm() > 0.0) phi.push_back(std::atan2(q.y(), q.x()));
  }
  if (phi.size() < 2) return 0.0;
  std::sort(phi.begin(), phi.end());
  double gap = phi.front() + 2.0 * kPi - phi.back();
  for (std::size_t i = 1; i < phi.size(); ++i) gap = std::max(gap, phi[i] - phi[i - 1]);
  return 360.0 - gap * kDeg;
}

std::vector<double> reported(const FittedElement& e) {
  return {e.centre.x(), e.centre.y(), e.centre.z(), e.axis.x(),
          e.axis.y(),   e.axis.z(),   e.radiusMm,   e.halfAngleRad * kDeg};
}

/// Standard errors, noise amplification and the condition text (element_fit.h).
void assess(const LsFit& ls, const Index& idx, const std::vector<Eigen::Vector3d>& pts,
            ElementFitResult& res) {
  const ElementModel& m = ls.model;
  const int k = m.size();
  const auto rows = static_cast<Eigen::Index>(idx.size());
  const Eigen::MatrixXd& J = ls.summary.jacobian;
  res.coverageDeg = coverageDeg(res.element, pts, idx);
  std::string where;
  if (res.element.kind == ElementKind::Sphere)
    where = "; the points cover a cap of half angle " + num::fixed(res.coverageDeg, 1) + " deg";
  else if (res.element.kind != ElementKind::Plane && res.element.kind != ElementKind::Line)
    where = "; the points cover " + num::fixed(res.coverageDeg, 1) + " deg around the axis";
  if (J.rows() != rows || J.cols() != k || !J.allFinite()) {
    res.wellConditioned = false;
    res.condition = "unknown: no Jacobian at the solution" + where;
    return;
  }
  Eigen::MatrixXd Js = J;
  for (int j = 0; j < k; ++j) Js.col(j) /= m.scale(j);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  const double smin = sv(sv.size() - 1), smax = sv(0);
  Eigen::Index worst = 0;
  svd.matrixV().col(k - 1).cwiseAbs().maxCoeff(&worst);
  const bool singular = !(smin > 1e-12 * std::max(smax, 1e-300));
  res.noiseAmplification = singular ? 1e12 : std::min(1e12, std::sqrt(static_cast<double>(rows)) / smin);
  res.wellConditioned = !singular && res.noiseAmplification <= kWellConditionedAmplification;

  // Standard errors: Cov = s^2 (J^T J)^-1, propagated to the reported quantities by central differences.
  const long dof = static_cast<long>(rows) - k;
  std::string seText;
  if (!singular && dof > 0) {
    const double s2 = ls.summary.residuals.squaredNorm() / static_cast<double>(dof);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svdJ(J, Eigen::ComputeThinV);
    const Eigen::VectorXd inv = svdJ.singularValues().cwiseInverse().cwiseAbs2();
    const Eigen::MatrixXd cov = s2 * svdJ.matrixV() * inv.asDiagonal() * svdJ.matrixV().transpose();
    const std::vector<double> q0 = reported(m.element(ls.x));
    Eigen::MatrixXd D(static_cast<Eigen::Index>(q0.size()), k);
    for (int j = 0; j < k; ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(ls.x(j))) / std::max(1.0, m.scale(j));
      Eigen::VectorXd xp = ls.x, xm = ls.x;
      xp(j) += h;
      xm(j) -= h;
      const std::vector<double> qp = reported(m.element(xp)), qm = reported(m.element(xm));
      for (std::size_t r = 0; r < q0.size(); ++r)
        D(static_cast<Eigen::Index>(r), j) = (qp[r] - qm[r]) / (2.0 * h);
    }
    const Eigen::MatrixXd covQ = D * cov * D.transpose();
    const char* names[] = {"centre_x_mm", "centre_y_mm", "centre_z_mm", "axis_x",
                           "axis_y",      "axis_z",      "radius_mm",   "half_angle_deg"};
    const ElementKind kind = m.kind();
    for (int r = 0; r < 8; ++r) {
      if (r >= 3 && r < 6 && kind == ElementKind::Sphere) continue;
      if (r == 6 && (kind == ElementKind::Plane || kind == ElementKind::Line || m.fixedRadius())) continue;
      if (r == 7 && kind != ElementKind::Cone) continue;
      const double v = covQ(r, r);
      res.standardErrors.push_back({names[r], std::isfinite(v) && v > 0.0 ? std::sqrt(v) : 0.0});
    }
    // The standard error of the worst-determined parameter combination, in mm.
    seText = ", its standard error " + num::general(std::sqrt(s2) * (singular ? 0.0 : 1.0 / smin), 3) + " mm";
  }
  const std::string amp = num::general(res.noiseAmplification, 3);
  if (singular) {
    res.condition = "degenerate: the points do not fix the " + m.role(static_cast<int>(worst)) + where;
  } else if (res.wellConditioned) {
    res.condition = "well conditioned: noise amplification " + amp + where;
  } else if (res.noiseAmplification <= kBadConditionAmplification) {
    res.condition = "weakly conditioned: noise amplification " + amp + " > " +
                    num::general(kWellConditionedAmplification, 3) + " (the " +
                    m.role(static_cast<int>(worst)) + " is the least determined" + seText + ")" + where;
  } else {
    res.condition = "badly conditioned: noise amplification " + amp + " > " +
                    num::general(kBadConditionAmplification, 3) + " (the " + m.role(static_cast<int>(worst)) +
                    " is poorly determined" + seText + ")" + where;
  }
}

}  // namespace

const char* toString(ElementKind kind) {
  switch (kind) {
    case ElementKind::Plane:
      return "plane";
    case ElementKind::Line:
      return "line";
    case ElementKind::Circle:
      return "circle";
    case ElementKind::Sphere:
      return "sphere";
    case ElementKind::Cylinder:
      return "cylinder";
    case ElementKind::Cone:
      return "cone";
  }
  return "?";
}

const char* toString(FitCriterion c) {
  return c == FitCriterion::Minimax ? "minimax" : "ls";
}

bool parseElementKind(std::string_view text, ElementKind* kind) {
  for (ElementKind k : {ElementKind::Plane, ElementKind::Line, ElementKind::Circle, ElementKind::Sphere,
                        ElementKind::Cylinder, ElementKind::Cone}) {
    if (text == toString(k)) {
      *kind = k;
      return true;
    }
  }
  return false;
}

bool parseFitCriterion(std::string_view text, FitCriterion* c) {
  if (text == "ls") {
    *c = FitCriterion::LeastSquares;
    return true;
  }
  if (text == "minimax") {
    *c = FitCriterion::Minimax;
    return true;
  }
  return false;
}

bool takesFixedRadius(ElementKind kind) {
  return kind == ElementKind::Sphere || kind == ElementKind::Circle || kind == ElementKind::Cylinder;
}

std::size_t minimumPoints(ElementKind kind, bool fixedRadius) {
  const std::size_t f = fixedRadius && takesFixedRadius(kind) ? 1 : 0;
  switch (kind) {
    case ElementKind::Plane:
      return 3;
    case ElementKind::Line:
      return 2;
    case ElementKind::Circle:
      return 3 - f;
    case ElementKind::Sphere:
      return 4 - f;
    case ElementKind::Cylinder:
      return 5 - f;
    case ElementKind::Cone:
      return 6;
  }
  return 0;
}

bool ElementFitOptions::isValid(std::string* why) const {
  auto no = [why](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  if (!(fixedRadiusMm >= 0.0) || !std::isfinite(fixedRadiusMm))
    return no("the fixed radius must be a positive number of mm");
  if (fixedRadiusMm > 0.0 && !takesFixedRadius(element))
    return no(std::string("a fixed radius applies to a sphere, circle or cylinder, not a ") +
              toString(element));
  if (!(robustK > 0.0) || !std::isfinite(robustK)) return no("the robust limit k must be > 0");
  if (robustMaxRounds < 1) return no("the robust round limit must be >= 1");
  if (maxIterations < 1) return no("the iteration limit must be >= 1");
  if (minimaxMaxIterations < 1) return no("the minimax iteration limit must be >= 1");
  return true;
}

ElementFitResult fitElement(const PointSet& set, const ElementFitOptions& o, Observer* observer) {
  requireValid(o, "fit-element options");
  const double fixedR = o.fixedRadiusMm;
  const ElementKind kind = o.element;
  const std::size_t n = set.points.size();
  const std::size_t need = minimumPoints(kind, fixedR > 0.0);
  if (n < need) {
    throw ValidationError(ErrorContext{set.source, 0, 0, {}}, std::string("a ") + toString(kind) +
                                                                  (fixedR > 0.0 ? " of fixed radius" : "") +
                                                                  " needs at least " + std::to_string(need) +
                                                                  " points, got " + std::to_string(n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!set.points[i].allFinite())
      throw ValidationError(ErrorContext{set.source, 0, 0, {}},
                            "point " + std::to_string(i + 1) + " is not finite");
  }

  {
    // Coincident points determine nothing; collinear points determine only a line.
    Index all(n);
    std::iota(all.begin(), all.end(), std::size_t{0});
    Eigen::MatrixXd A(static_cast<Eigen::Index>(n), 3);
    const Principal pc = principal(set.points, all);
    for (std::size_t i = 0; i < n; ++i)
      A.row(static_cast<Eigen::Index>(i)) = (set.points[i] - pc.centroid).transpose();
    const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::MatrixXd>(A).singularValues();
    if (!(sv(0) > 0.0)) degenerate(set.source, kind, "all points coincide");
    if (kind != ElementKind::Line && sv(1) <= 1e-9 * sv(0))
      degenerate(set.source, kind, "the points are collinear");
  }

  ElementFitResult res;
  res.criterion = o.criterion;
  res.fixedRadius = fixedR > 0.0;
  StageObserver obs(observer, res.run, o.keepTrace);

  Index idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  LsFit ls = fitFromStarts(set, kind, fixedR, idx, o.maxIterations, obs);

  if (o.robust && !obs.cancelled()) {
    const auto k = static_cast<std::size_t>(ls.model.size());
    // Least trimmed squares concentration steps on h = (n + k + 1) / 2 points.
    const std::size_t h = (n + k + 1) / 2;
    if (h > k && h < n) {
      Index prev;
      for (int round = 0; round < 50 && !obs.cancelled(); ++round) {
        std::vector<std::pair<double, std::size_t>> a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = {std::abs(ls.model.residual(ls.x, i)), i};
        std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(h), a.end());
        Index sub(h);
        for (std::size_t j = 0; j < h; ++j) sub[j] = a[j].second;
        std::sort(sub.begin(), sub.end());
        if (sub == prev) break;
        prev = sub;
        ls.summary = solveLs(ls.model, ls.x, sub, o.maxIterations, obs);
      }
    }
    // Then the MAD rule, iterated until the kept set stops changing.
    for (int round = 0; round < o.robustMaxRounds && !obs.cancelled(); ++round) {
      std::vector<double> r(n), kept;
      for (std::size_t i = 0; i < n; ++i) r[i] = ls.model.residual(ls.x, i);
      for (std::size_t i : idx) kept.push_back(r[i]);
      const double med = median(kept);
      for (double& v : kept) v = std::abs(v - med);
      const double mad = median(kept);
      res.robustThresholdMm = std::max(o.robustK * 1.4826 * mad, std::max(o.robustFloorMm, 1e-6));
      Index next;
      for (std::size_t i = 0; i < n; ++i)
        if (std::abs(r[i] - med) <= res.robustThresholdMm) next.push_back(i);
      if (next.size() < need + 1) break;  // too few left: keep the previous set
      const bool same = next == idx;
      idx = next;
      ls.summary = solveLs(ls.model, ls.x, idx, o.maxIterations, obs);
      if (same) break;
    }
    // The final least-squares fit on the kept points (the J and residuals of the assessment). A
    // circle's plane is a frame, not a parameter: it is made again from the kept points.
    if (kind == ElementKind::Circle && !obs.cancelled())
      ls = fitFromStarts(set, kind, fixedR, idx, o.maxIterations, obs);
    else
      ls.summary = solveLs(ls.model, ls.x, idx, o.maxIterations, obs);
    std::vector<bool> in(n, false);
    for (std::size_t i : idx) in[i] = true;
    for (std::size_t i = 0; i < n; ++i)
      if (!in[i]) res.excluded.push_back(i);
  }
  if (!ls.x.allFinite()) degenerate(set.source, kind, "no finite solution");

  Eigen::VectorXd x = ls.x;
  if (o.criterion == FitCriterion::Minimax && !obs.cancelled()) {
    struct Forward final : Observer {
      StageObserver* s;
      ObserverDecision onIteration(const IterationSummary& it) override { return s->onIteration(it); }
    } fwd;
    fwd.s = &obs;
    detail::MinimumZoneOutcome mz = detail::minimumZone(ls.model, x, idx, o.minimaxMaxIterations, &fwd);
    res.lpSolves = mz.lpSolves;
    // Never worse than the start (the least-squares element).
    if (mz.x.allFinite()) x = mz.x;
    res.certificate = mz.certificate;
    if (mz.termination == Termination::Failed) {
      res.run.termination = Termination::Failed;
      res.run.message = mz.message;
    } else {
      res.run.message = mz.message;
    }
  } else {
    res.run.termination = optim::toTermination(ls.summary.termination);
    res.run.message = ls.summary.message;
  }
  if (obs.cancelled()) {
    res.run.termination = Termination::Cancelled;
    res.run.message = "stopped by observer";
  }

  res.element = ls.model.element(x);
  res.residualsMm.resize(n);
  for (std::size_t i = 0; i < n; ++i) res.residualsMm[i] = elementResidual(res.element, set.points[i]);
  double lo = 0.0, hi = 0.0, ss = 0.0, ma = 0.0;
  bool first = true;
  for (std::size_t i : idx) {
    const double d = res.residualsMm[i];
    lo = first ? d : std::min(lo, d);
    hi = first ? d : std::max(hi, d);
    first = false;
    ss += d * d;
    ma = std::max(ma, std::abs(d));
  }
  res.formMm = kind == ElementKind::Line ? 2.0 * hi : hi - lo;
  res.rmseMm = std::sqrt(ss / static_cast<double>(idx.size()));
  res.maxAbsMm = ma;
  // Assessment of the least-squares fit on the fitted points (its J and residual variance).
  FittedElement keep = res.element;
  res.element = ls.model.element(ls.x);
  assess(ls, idx, set.points, res);
  res.element = keep;
  auto finite = [](const Eigen::Vector3d& v) { return v.allFinite(); };
  if (!finite(res.element.centre) || !finite(res.element.axis) || !std::isfinite(res.element.radiusMm) ||
      !std::isfinite(res.formMm) || !std::isfinite(res.rmseMm) || !finite(res.element.apex))
    degenerate(set.source, kind, "the fit has no finite solution");
  if (res.condition.rfind("degenerate", 0) == 0) degenerate(set.source, kind, res.condition);
  return res;
}

}  // namespace metrofit::geometry
