#include "core/kinematics/ballbar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/iso230_4.h"

namespace metrofit {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegPerRad = 180.0 / kPi;
constexpr double kCircleTolerance = 1e-3;  ///< of the radius
constexpr std::size_t kMinPointsPerDirection = 24;
constexpr double kMaxGapDeg = 30.0;

/// Step from a to b (rad) wrapped into (-pi, pi].
double angleStep(double a, double b) {
  double d = std::fmod(b - a, 2.0 * kPi);
  if (d > kPi) d -= 2.0 * kPi;
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

/// One sample of the test (see the header comment).
struct Sample {
  Eigen::Vector2d command;  ///< absolute command (for the cyclic error's phase)
  Eigen::Vector2d u;        ///< unit radial vector of the command about the nominal centre
  double drMm = 0.0;        ///< |p - c| - R
  bool ccw = true;
  Eigen::Vector2d d;        ///< axis directions d_x, d_y
  Eigen::Vector2d tangent;  ///< unit tangent of the command path
  Eigen::Vector2d phiDeg;   ///< path angle since the last reversal of X, Y (infinity before the first)
};

/// A cause and its columns in the design matrix.
struct CauseColumns {
  const char* name;
  bool reversal;  ///< changes sign between CCW and CW: needs both directions
  int columns;    ///< 1, or 2 for a cyclic error (a1, a2)
};

/// Path angle travelled since the last reversal of `axis` at every sample (see the header comment).
void reversalAngles(std::vector<Sample>& s, const std::vector<double>& thetaRad, int axis) {
  const double inf = std::numeric_limits<double>::infinity();
  double phi = inf;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (k > 0) {
      if (s[k].d(axis) != s[k - 1].d(axis)) phi = 0.0;  // the axis reversed at k - 1
      if (std::isfinite(phi)) phi += std::abs(angleStep(thetaRad[k - 1], thetaRad[k])) * kDegPerRad;
    }
    s[k].phiDeg(axis) = phi;
  }
}

ValidationError inputError(const MeasuredPath& path, const std::string& what) {
  return ValidationError(ErrorContext{path.source, 0, 0, "x_cmd_mm"}, what);
}

}  // namespace

bool BallbarOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(spikeWidthDeg > 0.0) || !std::isfinite(spikeWidthDeg))
    return no("spike width must be positive (deg)");
  if (!(screwPitchMm >= 0.0) || !std::isfinite(screwPitchMm)) {
    return no("screw pitch must be positive (mm), or 0 for no cyclic error");
  }
  if (!(significance > 0.0) || !std::isfinite(significance)) return no("significance must be positive");
  return true;
}

const BallbarCause* BallbarBreakdown::cause(const std::string& name) const {
  for (const BallbarCause& c : causes) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

bool isCircularTest(const MeasuredPath& path, std::string* why) {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (path.size() < 3) return no("a circular test needs at least 3 points");
  LsqCircle circle;
  try {
    circle = fitLsqCircle(path.command, path.source);
  } catch (const InputError&) {
    return no("the commanded points do not determine a circle");
  }
  double worst = 0.0;
  for (const auto& c : path.command)
    worst = std::max(worst, std::abs((c - circle.centreMm).norm() - circle.radiusMm));
  if (worst > kCircleTolerance * circle.radiusMm) {
    return no("the commanded points are not on one circle (a point is " + num::general(worst, 3) +
              " mm off the circle of radius " + num::general(circle.radiusMm, 6) + " mm)");
  }
  return true;
}

BallbarBreakdown ballbarBreakdown(const MeasuredPath& path, const BallbarOptions& options) {
  std::string why;
  if (!options.isValid(&why)) throw OptionsError(ErrorContext{path.source, 0, 0, "ballbar options"}, why);
  if (path.measured.size() != path.command.size())
    throw inputError(path, "commands and measured points differ in number");
  if (!isCircularTest(path, &why)) throw inputError(path, "no ballbar breakdown: " + why);
  const LsqCircle circle = fitLsqCircle(path.command, path.source);
  const Eigen::Vector2d centre = circle.centreMm;
  const double radius = circle.radiusMm;
  const std::size_t n = path.size();

  // Samples.
  const PathMotion motion = pathMotion(path.command);
  std::vector<Sample> s(n);
  std::vector<double> theta(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d rel = path.command[k] - centre;
    theta[k] = std::atan2(rel.y(), rel.x());
    s[k].command = path.command[k];
    s[k].u = Eigen::Vector2d(std::cos(theta[k]), std::sin(theta[k]));
    s[k].drMm = (path.measured[k] - centre).norm() - radius;
    s[k].d = motion.direction[k];
    s[k].tangent = motion.tangent[k];
    if (!std::isfinite(s[k].drMm)) throw inputError(path, "a measured point is not finite");
  }
  for (std::size_t k = 0; k + 1 < n; ++k) s[k].ccw = angleStep(theta[k], theta[k + 1]) >= 0.0;
  s[n - 1].ccw = s[n - 2].ccw;
  reversalAngles(s, theta, 0);
  reversalAngles(s, theta, 1);

  // Directions present and their coverage.
  bool present[2] = {false, false};  // [0] CCW, [1] CW
  for (const bool ccw : {true, false}) {
    std::vector<double> angles;
    for (std::size_t k = 0; k < n; ++k) {
      if (s[k].ccw == ccw) angles.push_back(theta[k] * kDegPerRad);
    }
    if (angles.empty()) continue;
    const std::string dir = ccw ? "CCW" : "CW";
    if (angles.size() < kMinPointsPerDirection) {
      throw inputError(path, "no ballbar breakdown: the " + dir + " run has " +
                                 std::to_string(angles.size()) + " points, at least " +
                                 std::to_string(kMinPointsPerDirection) + " are needed");
    }
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 360.0 - angles.back();
    for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
    if (gap > kMaxGapDeg) {
      throw inputError(path, "no ballbar breakdown: the " + dir + " run leaves a gap of " +
                                 num::general(gap, 3) + " deg in the circle (at most " +
                                 num::general(kMaxGapDeg, 3) + " deg)");
    }
    present[ccw ? 0 : 1] = true;
  }
  const bool both = present[0] && present[1];

  // Causes and their columns.
  std::vector<CauseColumns> causes = {
      {"backlash_x", true, 1},       {"backlash_y", true, 1},      {"reversal_spike_x", true, 1},
      {"reversal_spike_y", true, 1}, {"lateral_play_x", true, 1},  {"lateral_play_y", true, 1},
      {"servo_mismatch", true, 1},   {"scale_mismatch", false, 1}, {"squareness", false, 1},
      {"straightness_x", false, 1},  {"straightness_y", false, 1}, {"cyclic_error_x", false, 2},
      {"cyclic_error_y", false, 2},
  };
  std::erase_if(causes, [&](const CauseColumns& c) {
    const bool cyclic = c.columns == 2;
    return (c.reversal && !both) || (cyclic && options.screwPitchMm <= 0.0);
  });
  Eigen::Index causeCols = 0;
  for (const CauseColumns& c : causes) causeCols += c.columns;
  const Eigen::Index setupCols = both ? 6 : 3;
  const auto rows = static_cast<Eigen::Index>(n);
  if (rows < 2 * (causeCols + setupCols)) {
    throw inputError(path, "no ballbar breakdown: " + std::to_string(n) + " points for " +
                               std::to_string(causeCols + setupCols) +
                               " terms (at least twice as many needed)");
  }

  Eigen::MatrixXd setup = Eigen::MatrixXd::Zero(rows, setupCols);
  Eigen::MatrixXd cmat(rows, causeCols);
  Eigen::VectorXd y(rows);
  const double w = options.spikeWidthDeg;
  const double pitch = options.screwPitchMm;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const Sample& p = s[static_cast<std::size_t>(r)];
    const double c = p.u.x(), sn = p.u.y();
    const Eigen::Index off = both && !p.ccw ? 3 : 0;
    setup(r, off) = 1.0;
    setup(r, off + 1) = c;
    setup(r, off + 2) = sn;
    y(r) = p.drMm;
    Eigen::Index col = 0;
    for (const CauseColumns& cause : causes) {
      const std::string name = cause.name;
      const double dx = p.d.x(), dy = p.d.y();
      if (name == "backlash_x") {
        cmat(r, col) = -dx / 2.0 * c;
      } else if (name == "backlash_y") {
        cmat(r, col) = -dy / 2.0 * sn;
      } else if (name == "reversal_spike_x") {
        cmat(r, col) = -dx * std::exp(-p.phiDeg.x() / w) * c;
      } else if (name == "reversal_spike_y") {
        cmat(r, col) = -dy * std::exp(-p.phiDeg.y() / w) * sn;
      } else if (name == "lateral_play_x") {
        cmat(r, col) = -dx / 2.0 * sn;
      } else if (name == "lateral_play_y") {
        cmat(r, col) = -dy / 2.0 * c;
      } else if (name == "servo_mismatch") {
        cmat(r, col) = -(p.tangent.x() * c - p.tangent.y() * sn) / 2.0;
      } else if (name == "scale_mismatch") {
        cmat(r, col) = (c * c - sn * sn) / 2.0;
      } else if (name == "squareness") {
        cmat(r, col) = -c * sn;
      } else if (name == "straightness_x") {
        cmat(r, col) = (1.0 - c * c) * sn;
      } else if (name == "straightness_y") {
        cmat(r, col) = (1.0 - sn * sn) * c;
      } else if (name == "cyclic_error_x" || name == "cyclic_error_y") {
        const int axis = name == "cyclic_error_x" ? 0 : 1;
        const double phase = 2.0 * kPi * p.command(axis) / pitch;
        cmat(r, col) = std::sin(phase) * p.u(axis);
        cmat(r, col + 1) = std::cos(phase) * p.u(axis);
      }
      col += cause.columns;
    }
  }

  // The setup terms removed from the deviation and from the cause columns (Frisch-Waugh-Lovell).
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> setupQr(setup);
  const Eigen::VectorXd ys = y - setup * setupQr.solve(y);
  const Eigen::MatrixXd cs = cmat - setup * setupQr.solve(cmat);

  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(cs);
  qr.setThreshold(1e-9);
  if (qr.rank() < causeCols) {
    throw inputError(path, "no ballbar breakdown: the path cannot tell the error signatures apart");
  }
  const Eigen::VectorXd beta = qr.solve(ys);
  const Eigen::VectorXd e = ys - cs * beta;
  const double yy = ys.squaredNorm(), ee = e.squaredNorm();
  const double dof = static_cast<double>(rows - causeCols - setupCols);
  const double s2 = ee / dof;
  const Eigen::MatrixXd rUpper =
      qr.matrixR().topLeftCorner(causeCols, causeCols).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd rInv =
      rUpper.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(causeCols, causeCols));
  const Eigen::MatrixXd perm = qr.colsPermutation().toDenseMatrix().cast<double>();
  const Eigen::MatrixXd cov = s2 * (perm * rInv * rInv.transpose() * perm.transpose());

  // Shares (see the header comment): the variance of each cause's own fitted signature C*_i beta_i,
  // scaled so that together they make R^2 = 1 - |e|^2 / |y*|^2.
  const std::size_t count = causes.size();
  std::vector<double> own(count, 0.0);
  double ownSum = 0.0;
  for (Eigen::Index c = 0, i = 0; i < static_cast<Eigen::Index>(count); ++i) {
    const int width = causes[static_cast<std::size_t>(i)].columns;
    own[static_cast<std::size_t>(i)] = (cs.middleCols(c, width) * beta.segment(c, width)).squaredNorm();
    ownSum += own[static_cast<std::size_t>(i)];
    c += width;
  }
  const double explained = yy > 0.0 ? 1.0 - ee / yy : 0.0;

  BallbarBreakdown out;
  out.options = options;
  out.centreMm = centre;
  out.radiusMm = radius;
  out.bothDirections = both;
  out.points = n;
  out.unexplainedShare = yy > 0.0 ? ee / yy : 1.0;
  out.residualRmsUm = std::sqrt(ee / static_cast<double>(rows)) * 1000.0;
  out.deviationRmsUm = std::sqrt(yy / static_cast<double>(rows)) * 1000.0;
  Eigen::Index col = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const CauseColumns& cause = causes[i];
    BallbarCause b;
    b.name = cause.name;
    b.share = ownSum > 0.0 ? explained * own[i] / ownSum : 0.0;
    if (cause.columns == 1) {
      b.valueUm = beta(col) * 1000.0;
      b.stdErrorUm = std::sqrt(std::max(0.0, cov(col, col))) * 1000.0;
    } else {
      const double a1 = beta(col), a2 = beta(col + 1);
      const double amp = std::hypot(a1, a2);
      const double v11 = cov(col, col), v22 = cov(col + 1, col + 1), v12 = cov(col, col + 1);
      const double var =
          amp > 0.0 ? (a1 * a1 * v11 + 2.0 * a1 * a2 * v12 + a2 * a2 * v22) / (amp * amp) : (v11 + v22) / 2.0;
      b.valueUm = amp * 1000.0;
      b.stdErrorUm = std::sqrt(std::max(0.0, var)) * 1000.0;
    }
    b.significant = std::abs(b.valueUm) > options.significance * b.stdErrorUm;
    out.causes.push_back(b);
    col += cause.columns;
  }
  std::stable_sort(out.causes.begin(), out.causes.end(), [](const BallbarCause& a, const BallbarCause& b) {
    if (a.share != b.share) return a.share > b.share;
    return std::abs(a.valueUm) > std::abs(b.valueUm);
  });
  return out;
}

nlohmann::json ballbarCausesToJson(const BallbarBreakdown& b) {
  nlohmann::json causes = nlohmann::json::array();
  for (const BallbarCause& c : b.causes) {
    causes.push_back({{"name", c.name}, {"value_um", c.valueUm}, {"share", c.share}});
  }
  causes.push_back({{"name", "unexplained"}, {"value_um", b.residualRmsUm}, {"share", b.unexplainedShare}});
  return causes;
}

}  // namespace metrofit
