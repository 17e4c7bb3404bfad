#include "core/kinematics/identification.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/json_util.h"
#include "core/optim/least_squares.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kCollinearRatio = 1e-8;  // (spread across / spread along)^2, i.e. 1e-4 in length

const char* const kCmdFields = "x_cmd_mm,y_cmd_mm";
const char* const kMeasFields = "x_meas_mm,y_meas_mm";

[[noreturn]] void fail(const MeasuredPath& p, const std::string& field, const std::string& what,
                       long line = 0) {
  throw ValidationError(ErrorContext{p.source, line, 0, field}, what);
}

/// Spread of a point set: eigenvalues of its 2x2 covariance (ascending).
Eigen::Vector2d spread(const std::vector<Eigen::Vector2d>& pts) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix2d c = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) c += (p - mean) * (p - mean).transpose();
  c /= static_cast<double>(pts.size());
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(c, Eigen::EigenvaluesOnly).eigenvalues();
}

void checkSpread(const MeasuredPath& p, const std::vector<Eigen::Vector2d>& pts, const char* field,
                 const char* what) {
  const Eigen::Vector2d ev = spread(pts);
  const double scale = std::max(1.0, pts.front().cwiseAbs().maxCoeff());
  if (!(ev(1) > 1e-24 * scale * scale)) {
    fail(p, field,
         std::string("all ") + std::to_string(pts.size()) + " " + what +
             " points are identical: the path must span both axes");
  }
  if (ev(0) < kCollinearRatio * ev(1)) {
    fail(p, field,
         std::string("all ") + std::to_string(pts.size()) + " " + what +
             " points lie on one line: the path must span both axes (a circular test does)");
  }
}

struct Residuals {
  Eigen::VectorXd r;  // 2N: (x_0, y_0, x_1, y_1, ...)
  Eigen::MatrixXd J;  // 2N x 4
};

/// Residuals P(Pr; theta) - Pmeas and their Jacobian; theta = (o_x, o_y, a rad, b rad).
void evaluate(const MeasuredPath& p, const Eigen::Vector4d& th, Residuals& out, bool withJ) {
  const std::size_t n = p.size();
  out.r.resize(static_cast<Eigen::Index>(2 * n));
  if (withJ) out.J.resize(static_cast<Eigen::Index>(2 * n), 4);
  const double ca = std::cos(th(2)), sa = std::sin(th(2)), cb = std::cos(th(3)), sb = std::sin(th(3));
  for (std::size_t k = 0; k < n; ++k) {
    const double x = p.command[k].x(), y = p.command[k].y();
    const auto i = static_cast<Eigen::Index>(2 * k);
    out.r(i) = th(0) + ca * x - sb * y - p.measured[k].x();
    out.r(i + 1) = th(1) + sa * x + cb * y - p.measured[k].y();
    if (!withJ) continue;
    out.J(i, 0) = 1.0;
    out.J(i, 1) = 0.0;
    out.J(i, 2) = -sa * x;
    out.J(i, 3) = -cb * y;
    out.J(i + 1, 0) = 0.0;
    out.J(i + 1, 1) = 1.0;
    out.J(i + 1, 2) = ca * x;
    out.J(i + 1, 3) = -sb * y;
  }
}

std::string fmt(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double wrapRad(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

/// Linear least-squares affine fit Pmeas = o + M Pr; returns the start (o, a, b) and det M.
Eigen::Vector4d affineStart(const MeasuredPath& p, double* detM) {
  const auto n = static_cast<Eigen::Index>(p.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::MatrixXd B(n, 2);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto& c = p.command[static_cast<std::size_t>(k)];
    A.row(k) << 1.0, c.x(), c.y();
    B.row(k) = p.measured[static_cast<std::size_t>(k)].transpose();
  }
  const Eigen::MatrixXd X = A.colPivHouseholderQr().solve(B);  // rows: o^T, M^T col0, M^T col1
  Eigen::Matrix2d M;
  M << X(1, 0), X(2, 0), X(1, 1), X(2, 1);
  *detM = M.determinant();
  return {X(0, 0), X(0, 1), std::atan2(M(1, 0), M(0, 0)), std::atan2(-M(0, 1), M(1, 1))};
}

ActuatorErrors2 toErrors(const Eigen::Vector4d& th) {
  ActuatorErrors2 e;
  e.originMm = th.head<2>();
  e.xAxisAngleDeg = wrapRad(th(2)) / kDeg;
  e.yAxisAngleDeg = wrapRad(th(3)) / kDeg;
  return e;
}

}  // namespace

bool IdentifyOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (maxIterations < 1) return no("maxIterations must be at least 1");
  if (!(stepToleranceMm >= 0.0) || !std::isfinite(stepToleranceMm)) return no("stepToleranceMm must be >= 0");
  if (!(costTolerance >= 0.0 && costTolerance < 1.0)) return no("costTolerance must be in [0, 1)");
  if (!(initialDamping > 0.0) || !std::isfinite(initialDamping)) return no("initialDamping must be positive");
  return true;
}

void checkIdentifiable(const MeasuredPath& p) {
  if (p.command.size() != p.measured.size()) {
    fail(p, kMeasFields,
         "has " + std::to_string(p.measured.size()) + " measured points for " +
             std::to_string(p.command.size()) + " commands");
  }
  if (p.size() < 3) {
    fail(p, {},
         "has " + std::to_string(p.size()) + " point" + (p.size() == 1 ? "" : "s") +
             ", at least 3 not on one line are needed to identify origin and both axis angles");
  }
  for (std::size_t k = 0; k < p.size(); ++k) {
    const long line = k < p.lines.size() ? p.lines[k] : 0;
    if (!p.command[k].allFinite()) fail(p, kCmdFields, "not a finite number", line);
    if (!p.measured[k].allFinite()) fail(p, kMeasFields, "not a finite number", line);
  }
  checkSpread(p, p.command, kCmdFields, "command");
  checkSpread(p, p.measured, kMeasFields, "measured");
}

IdentifyResult identifyActuatorErrors(const MeasuredPath& p, const IdentifyOptions& o, Observer* observer) {
  requireValid(o, "identification options");
  checkIdentifiable(p);
  const double n = static_cast<double>(p.size());

  double detM = 0.0;
  Eigen::Vector4d th = affineStart(p, &detM);
  if (!(detM > 0.0)) {
    fail(p, kMeasFields,
         "the measured path is mirrored with respect to the commands (det of the fitted axis matrix " +
             fmt(detM) + " <= 0): is an axis swapped or its sign reversed?");
  }

  if (!o.affineStart) th.setZero();

  IdentifyResult res;
  res.points = p.size();
  res.initialEstimate = toErrors(th);
  RunInfo& run = res.run;

  // Levenberg-Marquardt with Marquardt's scaling and Nielsen's damping (core/optim/least_squares.h).
  // The step test is on the RMS change of the modelled positions: |J delta| / sqrt(N) <= stepToleranceMm.
  optim::LeastSquaresOptions lo;
  lo.maxIterations = o.maxIterations;
  lo.initialDamping = o.initialDamping;
  lo.costTolerance = o.costTolerance;
  lo.modelStepTolerance = o.stepToleranceMm * std::sqrt(n);
  const optim::Residual f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    Residuals out;
    evaluate(p, x, out, J != nullptr);
    r = std::move(out.r);
    if (J) *J = std::move(out.J);
  };
  FunctionObserver report([&](const IterationSummary& g) {
    IterationSummary s = g;
    s.best = std::sqrt(2.0 * g.best / n);  // cost 1/2 S -> rmse
    s.components = {{"rmse_mm", s.best}, {"damping", g.components.at(1).value}};
    const ActuatorErrors2 e = toErrors(Eigen::Map<const Eigen::Vector4d>(g.bestX.data()));
    s.bestX = {e.originMm.x(), e.originMm.y(), e.xAxisAngleDeg, e.yAxisAngleDeg};
    s.progress = -1.0;
    return notify(observer, run, s, o.keepTrace) ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  Eigen::VectorXd x = th;
  const optim::LeastSquaresSummary sum = optim::solveLeastSquares(f, x, lo, &report);
  th = x;
  run.termination = optim::toTermination(sum.termination);
  run.message = sum.message;
  run.iterations = sum.iterations;
  run.evaluations = sum.residualEvaluations + sum.jacobianEvaluations;
  Residuals cur{sum.residuals, sum.jacobian};

  res.errors = toErrors(th);
  for (const double ang : {res.errors.xAxisAngleDeg, res.errors.yAxisAngleDeg}) {
    if (std::abs(ang) > ActuatorErrors2::kMaxAngleDeg) {
      fail(p, kMeasFields,
           "identified axis angle " + fmt(ang) +
               " deg is beyond +-45 deg: is the measured path rotated, or are its columns swapped?");
    }
  }

  // Residuals and statistics at the solution (cur holds r and J at th).
  const double ssr = cur.r.squaredNorm();
  res.rmseMm = std::sqrt(ssr / n);
  res.sigmaMm = std::sqrt(ssr / (2.0 * n - 4.0));
  res.residuals.resize(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    res.residuals[k] = -cur.r.segment<2>(static_cast<Eigen::Index>(2 * k));
    res.maxAbsMm = std::max(res.maxAbsMm, res.residuals[k].norm());
  }

  // Cov = s^2 (J^T J)^-1 through the column-pivoted QR of J: J P = Q R => (J^T J)^-1 = P R^-1 R^-T P^T.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(cur.J);
  if (cur.J.rows() != cur.r.size() || qr.rank() < 4) {
    run.termination = Termination::Failed;
    run.message = "the Jacobian is rank deficient: the parameters are not all observable";
  } else {
    const Eigen::Matrix4d R = qr.matrixR().topLeftCorner<4, 4>().triangularView<Eigen::Upper>();
    const Eigen::Matrix4d Rinv = R.triangularView<Eigen::Upper>().solve(Eigen::Matrix4d::Identity());
    const Eigen::Matrix4d P = qr.colsPermutation().toDenseMatrix().cast<double>();
    Eigen::Matrix4d cov = res.sigmaMm * res.sigmaMm * (P * Rinv * Rinv.transpose() * P.transpose());
    const Eigen::Vector4d toUnits(1.0, 1.0, 1.0 / kDeg, 1.0 / kDeg);
    cov = toUnits.asDiagonal() * cov * toUnits.asDiagonal();
    res.covariance = cov;
    res.standardErrors.originMm = Eigen::Vector2d(std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1)));
    res.standardErrors.xAxisAngleDeg = std::sqrt(cov(2, 2));
    res.standardErrors.yAxisAngleDeg = std::sqrt(cov(3, 3));
    res.squarenessStdErrDeg = std::sqrt(std::max(0.0, cov(2, 2) + cov(3, 3) - 2.0 * cov(2, 3)));
  }
  return res;
}

nlohmann::json identifyResultToJson(const IdentifyResult& r) {
  nlohmann::json j;
  j["origin_mm"] = {r.errors.originMm.x(), r.errors.originMm.y()};
  j["x_axis_angle_deg"] = r.errors.xAxisAngleDeg;
  j["y_axis_angle_deg"] = r.errors.yAxisAngleDeg;
  j["rmse_mm"] = r.rmseMm;
  j["squareness_deg"] = r.errors.squarenessDeg();
  j["standard_errors"] = {
      {"origin_mm", {r.standardErrors.originMm.x(), r.standardErrors.originMm.y()}},
      {"x_axis_angle_deg", r.standardErrors.xAxisAngleDeg},
      {"y_axis_angle_deg", r.standardErrors.yAxisAngleDeg},
      {"squareness_deg", r.squarenessStdErrDeg},
  };
  j["sigma_mm"] = r.sigmaMm;
  j["max_abs_mm"] = r.maxAbsMm;
  j["points"] = r.points;
  j["iterations"] = r.run.iterations;
  j["termination"] = toString(r.run.termination);
  j["model"] = "P = origin + x_cmd (cos a, sin a) + y_cmd (-sin b, cos b); squareness = b - a";
  return j;
}

void originFromJson(const JsonReader& object, Eigen::Ref<Eigen::VectorXd> origin) {
  const auto count = static_cast<std::size_t>(origin.size());
  const JsonReader o = object.array("origin_mm");
  if (o.size() != count) {
    std::string axes = "[";
    for (std::size_t i = 0; i < count; ++i) axes += std::string(i ? ", " : "") + "xyz"[i % 3];
    o.fail("expected " + std::to_string(count) + " numbers " + axes + "], found " + std::to_string(o.size()) +
           " element" + (o.size() == 1 ? "" : "s"));
  }
  for (std::size_t i = 0; i < count; ++i) {
    const JsonReader el = o.at(i);
    if (!el.json().is_number()) el.fail(std::string("expected a number, found ") + el.json().type_name());
    const double v = el.json().get<double>();
    if (!std::isfinite(v)) el.fail("not a finite number");
    origin(static_cast<Eigen::Index>(i)) = v;
  }
}

ActuatorErrors2 actuatorErrorsFromJson(const nlohmann::json& json, const std::string& source) {
  const JsonReader r(json, source);
  r.requireObject();
  ActuatorErrors2 e;
  originFromJson(r, e.originMm);
  e.xAxisAngleDeg = r.number("x_axis_angle_deg");
  e.yAxisAngleDeg = r.number("y_axis_angle_deg");
  for (const char* key : {"x_axis_angle_deg", "y_axis_angle_deg"}) {
    const double v = r.number(key);
    if (std::abs(v) > ActuatorErrors2::kMaxAngleDeg) {
      r.fail(fmt(v) + " deg is beyond +-45 deg (an actuator orientation error)", key);
    }
  }
  return e;
}

ActuatorErrors2 readActuatorErrors(const std::string& path) {
  return actuatorErrorsFromJson(readJsonFile(path), path);
}

}  // namespace metrofit
