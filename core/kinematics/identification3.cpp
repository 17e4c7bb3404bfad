#include "core/kinematics/identification3.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/json_util.h"
#include "core/optim/least_squares.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kParams = 9;
using Theta = Eigen::Matrix<double, kParams, 1>;

const char* const kLetters = "xyz";

std::string fmt(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// "x_cmd_mm,y_cmd_mm" style field names of identification.cpp rewritten with the plane's letters.
std::string planeField(const std::string& field, TestPlane plane) {
  const auto ax = planeAxes(plane);
  std::string out = field;
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    if ((out[i] == 'x' || out[i] == 'y') && out[i + 1] == '_' && (i == 0 || out[i - 1] == ',')) {
      out[i] = kLetters[ax[out[i] == 'x' ? 0 : 1]];
    }
  }
  return out;
}

ActuatorErrors3 fromTheta(const Theta& t) {
  ActuatorErrors3 e;
  e.originMm = t.head<3>();
  for (int p = 0; p < 3; ++p) {
    e.uAngleDeg[static_cast<std::size_t>(p)] = t(3 + 2 * p) / kDeg;
    e.vAngleDeg[static_cast<std::size_t>(p)] = t(4 + 2 * p) / kDeg;
  }
  return e;
}

Theta toTheta(const ActuatorErrors3& e) {
  Theta t;
  t.head<3>() = e.originMm;
  for (int p = 0; p < 3; ++p) {
    t(3 + 2 * p) = e.uAngleDeg[static_cast<std::size_t>(p)] * kDeg;
    t(4 + 2 * p) = e.vAngleDeg[static_cast<std::size_t>(p)] * kDeg;
  }
  return t;
}

Eigen::Vector3d to3(TestPlane plane, const Eigen::Vector2d& uv) {
  const auto ax = planeAxes(plane);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  p(ax[0]) = uv.x();
  p(ax[1]) = uv.y();
  return p;
}

Eigen::Vector2d toPlane(TestPlane plane, const Eigen::Vector3d& p) {
  const auto ax = planeAxes(plane);
  return {p(ax[0]), p(ax[1])};
}

/// Residuals model - measured, (u, v) per point, the three tests one after the other.
Eigen::VectorXd residuals(const std::array<MeasuredPath, 3>& tests, const Theta& th) {
  const CartesianMachine3 machine = fromTheta(th).machine();  // Eq. 9 in three axes
  std::size_t n = 0;
  for (const auto& t : tests) n += t.size();
  Eigen::VectorXd r(static_cast<Eigen::Index>(2 * n));
  Eigen::Index i = 0;
  for (const TestPlane plane : kTestPlanes) {
    const MeasuredPath& t = tests[static_cast<std::size_t>(plane)];
    for (std::size_t k = 0; k < t.size(); ++k) {
      const Eigen::Vector2d m = toPlane(plane, machine.forward(to3(plane, t.command[k])));
      r.segment<2>(i) = m - t.measured[k];
      i += 2;
    }
  }
  return r;
}

Eigen::MatrixXd jacobian(const std::array<MeasuredPath, 3>& tests, const Theta& th, Eigen::Index rows) {
  Eigen::MatrixXd J(rows, kParams);
  for (int c = 0; c < kParams; ++c) {
    const double h = c < 3 ? 1e-6 : 1e-7;  // mm, rad
    Theta p = th, m = th;
    p(c) += h;
    m(c) -= h;
    J.col(c) = (residuals(tests, p) - residuals(tests, m)) / (2.0 * h);
  }
  return J;
}

}  // namespace

const char* planeName(TestPlane plane) {
  switch (plane) {
    case TestPlane::XY:
      return "xy";
    case TestPlane::YZ:
      return "yz";
    case TestPlane::ZX:
      return "zx";
  }
  return "?";
}

std::array<int, 2> planeAxes(TestPlane plane) {
  switch (plane) {
    case TestPlane::XY:
      return {0, 1};
    case TestPlane::YZ:
      return {1, 2};
    case TestPlane::ZX:
      return {2, 0};
  }
  return {0, 1};
}

std::array<std::string, 4> planeColumns(TestPlane plane) {
  const auto ax = planeAxes(plane);
  const std::string u(1, kLetters[ax[0]]), v(1, kLetters[ax[1]]);
  return {u + "_cmd_mm", v + "_cmd_mm", u + "_meas_mm", v + "_meas_mm"};
}

MeasuredPath planePathFromCsv(const CsvTable& t, TestPlane plane) {
  const auto cols = planeColumns(plane);
  std::array<std::size_t, 4> c{};
  for (std::size_t i = 0; i < 4; ++i) c[i] = t.requireColumn(cols[i]);
  MeasuredPath p;
  p.source = t.source();
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    p.command.emplace_back(t.number(r, c[0]), t.number(r, c[1]));
    p.measured.emplace_back(t.number(r, c[2]), t.number(r, c[3]));
    p.lines.push_back(t.lineOf(r));
  }
  return p;
}

MeasuredPath readPlanePath(const std::string& path, TestPlane plane, const CsvReadOptions& csv) {
  return planePathFromCsv(readCsvFile(path, csv), plane);
}

std::string planePathToCsv(const MeasuredPath& p, TestPlane plane) {
  const auto cols = planeColumns(plane);
  CsvWriter w;
  w.row({cols[0], cols[1], cols[2], cols[3]});
  for (std::size_t i = 0; i < p.size(); ++i) {
    w.row({CsvWriter::formatNumber(p.command[i].x()), CsvWriter::formatNumber(p.command[i].y()),
           CsvWriter::formatNumber(p.measured[i].x()), CsvWriter::formatNumber(p.measured[i].y())});
  }
  return w.text();
}

Eigen::Matrix3d ActuatorErrors3::directions() const {
  const auto t = [](double deg) { return std::tan(deg * kDeg); };
  const double axy = uAngleDeg[0], ayz = uAngleDeg[1], azx = uAngleDeg[2];
  const double bxy = vAngleDeg[0], byz = vAngleDeg[1], bzx = vAngleDeg[2];
  Eigen::Matrix3d D;
  D.col(0) = Eigen::Vector3d(1.0, t(axy), -t(bzx)).normalized();
  D.col(1) = Eigen::Vector3d(-t(bxy), 1.0, t(ayz)).normalized();
  D.col(2) = Eigen::Vector3d(t(azx), -t(byz), 1.0).normalized();
  return D;
}

CartesianMachine3 ActuatorErrors3::machine() const {
  Eigen::Matrix3d origins;
  origins.colwise() = originMm;
  return CartesianMachine3(origins, directions());
}

ActuatorErrors2 ActuatorErrors3::inPlane(TestPlane plane) const {
  ActuatorErrors2 e;
  e.originMm = toPlane(plane, originMm);
  e.xAxisAngleDeg = uAngleDeg[static_cast<std::size_t>(plane)];
  e.yAxisAngleDeg = vAngleDeg[static_cast<std::size_t>(plane)];
  return e;
}

bool ActuatorErrors3::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!originMm.allFinite()) return no("origin must be finite");
  for (const TestPlane p : kTestPlanes) {
    for (const double a : {uAngleDeg[static_cast<std::size_t>(p)], vAngleDeg[static_cast<std::size_t>(p)]}) {
      if (!std::isfinite(a) || std::abs(a) > ActuatorErrors2::kMaxAngleDeg) {
        return no(std::string("axis angles of plane ") + planeName(p) +
                  " must be finite and within +-45 deg");
      }
    }
  }
  return true;
}

ActuatorErrors3 ActuatorErrors3::plausible() {
  ActuatorErrors3 e;
  e.originMm = Eigen::Vector3d(0.004, -0.003, 0.002);
  e.uAngleDeg = {0.0006, 0.0004, -0.0003};
  e.vAngleDeg = {-0.0020, 0.0019, -0.0013};
  return e;
}

bool Identify3Options::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (maxIterations < 1) return no("maxIterations must be at least 1");
  if (!(costTolerance >= 0.0 && costTolerance < 1.0)) return no("costTolerance must be in [0, 1)");
  if (!(initialDamping > 0.0) || !std::isfinite(initialDamping)) return no("initialDamping must be positive");
  return true;
}

Identify3Result identifyActuatorErrors3(const std::array<MeasuredPath, 3>& tests, const Identify3Options& o,
                                        Observer* observer) {
  requireValid(o, "three-plane identification options");
  Identify3Result res;
  // Every test alone (identification.h), with the plane's own column names in messages.
  for (const TestPlane plane : kTestPlanes) {
    const MeasuredPath& t = tests[static_cast<std::size_t>(plane)];
    PlaneFit3& pf = res.planes[static_cast<std::size_t>(plane)];
    pf.source = t.source;
    pf.points = t.size();
    try {
      pf.separate = identifyActuatorErrors(t);
    } catch (const ValidationError& e) {
      ErrorContext c = e.context();
      c.field = planeField(c.field, plane);
      throw ValidationError(c, std::string("(") + planeName(plane) + " test) " + e.detail());
    }
    if (pf.separate.run.termination == Termination::Failed) {
      throw ValidationError(ErrorContext{t.source, 0, 0, {}},
                            std::string("(") + planeName(plane) + " test) " + pf.separate.run.message);
    }
    res.points += t.size();
  }

  // Start: the plane angles; each origin component the mean of the two planes that see it.
  ActuatorErrors3 start;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), count = Eigen::Vector3d::Zero();
  for (const TestPlane plane : kTestPlanes) {
    const ActuatorErrors2& e = res.planes[static_cast<std::size_t>(plane)].separate.errors;
    const auto ax = planeAxes(plane);
    start.uAngleDeg[static_cast<std::size_t>(plane)] = e.xAxisAngleDeg;
    start.vAngleDeg[static_cast<std::size_t>(plane)] = e.yAxisAngleDeg;
    for (int i = 0; i < 2; ++i) {
      sum(ax[static_cast<std::size_t>(i)]) += e.originMm(i);
      count(ax[static_cast<std::size_t>(i)]) += 1.0;
    }
  }
  start.originMm = sum.cwiseQuotient(count);

  // Levenberg-Marquardt (core/optim/least_squares.h: Marquardt's scaling, Nielsen's damping, LDLT of
  // the normal equations) with the central-difference Jacobian of jacobian() above.
  RunInfo& run = res.run;
  const double n = static_cast<double>(res.points);
  optim::LeastSquaresOptions lo;
  lo.maxIterations = o.maxIterations;
  lo.initialDamping = o.initialDamping;
  lo.costTolerance = o.costTolerance;
  lo.linearSolver = optim::LeastSquaresOptions::LinearSolver::NormalEquations;
  const optim::Residual f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    const Theta th = x;
    r = residuals(tests, th);
    if (J) *J = jacobian(tests, th, r.size());
  };
  FunctionObserver report([&](const IterationSummary& g) {
    IterationSummary s = g;
    s.best = std::sqrt(2.0 * g.best / n);  // cost 1/2 SSE -> rmse
    s.components = {{"rmse_mm", s.best}, {"damping", g.components.at(1).value}};
    const ActuatorErrors3 e = fromTheta(Eigen::Map<const Theta>(g.bestX.data()));
    s.bestX = {e.originMm.x(), e.originMm.y(), e.originMm.z(), e.uAngleDeg[0], e.vAngleDeg[0],
               e.uAngleDeg[1], e.vAngleDeg[1], e.uAngleDeg[2], e.vAngleDeg[2]};
    s.progress = -1.0;
    return notify(observer, run, s, o.keepTrace) ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  Eigen::VectorXd x = toTheta(start);
  const optim::LeastSquaresSummary fit = optim::solveLeastSquares(f, x, lo, &report);
  const Theta th = x;
  run.termination = optim::toTermination(fit.termination);
  run.message = fit.message;
  run.iterations = fit.iterations;
  run.evaluations = fit.residualEvaluations + (1 + 2 * kParams) * fit.jacobianEvaluations;
  const Eigen::VectorXd& r = fit.residuals;
  const double cost = r.squaredNorm();  // SSE

  res.errors = fromTheta(th);
  std::string why;
  if (!res.errors.isValid(&why)) {
    throw ValidationError(ErrorContext{tests[0].source, 0, 0, {}},
                          "identified errors are not plausible: " + why);
  }
  res.rmseMm = std::sqrt(cost / n);
  res.sigmaMm = std::sqrt(cost / std::max(1.0, 2.0 * n - kParams));
  Eigen::Index i = 0;
  for (const TestPlane plane : kTestPlanes) {
    PlaneFit3& pf = res.planes[static_cast<std::size_t>(plane)];
    double ss = 0.0;
    for (std::size_t k = 0; k < pf.points; ++k) {
      const Eigen::Vector2d d = -r.segment<2>(i);
      pf.residuals.push_back(d);
      ss += d.squaredNorm();
      i += 2;
    }
    pf.rmseMm = std::sqrt(ss / static_cast<double>(pf.points));
  }

  const Eigen::MatrixXd& J = fit.jacobian;
  const Eigen::Matrix<double, kParams, kParams> JtJ =
      J.rows() == r.size() ? Eigen::Matrix<double, kParams, kParams>(J.transpose() * J)
                           : Eigen::Matrix<double, kParams, kParams>::Zero();
  const Eigen::FullPivLU<Eigen::Matrix<double, kParams, kParams>> lu(JtJ);
  if (lu.rank() < kParams) {
    run.termination = Termination::Failed;
    run.message = "the Jacobian is rank deficient: the parameters are not all observable";
  } else {
    Eigen::Matrix<double, kParams, kParams> cov = res.sigmaMm * res.sigmaMm * lu.inverse();
    Theta toUnits = Theta::Constant(1.0 / kDeg);
    toUnits.head<3>().setOnes();
    cov = toUnits.asDiagonal() * cov * toUnits.asDiagonal();
    const Theta se = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
    res.standardErrors.originMm = se.head<3>();
    for (int p = 0; p < 3; ++p) {
      const int a = 3 + 2 * p, b = 4 + 2 * p;
      res.standardErrors.uAngleDeg[static_cast<std::size_t>(p)] = se(a);
      res.standardErrors.vAngleDeg[static_cast<std::size_t>(p)] = se(b);
      res.squarenessStdErrDeg[static_cast<std::size_t>(p)] =
          std::sqrt(std::max(0.0, cov(a, a) + cov(b, b) - 2.0 * cov(a, b)));
    }
  }
  return res;
}

std::vector<Eigen::Vector3d> compensatePath3(const ActuatorErrors3& errors,
                                             const std::vector<Eigen::Vector3d>& nominal) {
  std::string why;
  if (!errors.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "three-axis errors"}, why);
  const CartesianMachine3 machine = errors.machine();
  std::vector<Eigen::Vector3d> out;
  out.reserve(nominal.size());
  for (const auto& p : nominal) out.push_back(machine.inverse(p));
  return out;
}

std::vector<Eigen::Vector3d> nominalPath3FromCsv(const CsvTable& t) {
  const std::size_t xc = t.requireColumn("x_mm"), yc = t.requireColumn("y_mm"), zc = t.requireColumn("z_mm");
  t.requireRows(1);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t r = 0; r < t.rowCount(); ++r)
    out.emplace_back(t.number(r, xc), t.number(r, yc), t.number(r, zc));
  return out;
}

std::string commandPath3ToCsv(const std::vector<Eigen::Vector3d>& commands) {
  CsvWriter w;
  w.row({"x_cmd_mm", "y_cmd_mm", "z_cmd_mm"});
  for (const auto& c : commands) {
    w.row({CsvWriter::formatNumber(c.x()), CsvWriter::formatNumber(c.y()), CsvWriter::formatNumber(c.z())});
  }
  return w.text();
}

nlohmann::json identify3ResultToJson(const Identify3Result& r) {
  using nlohmann::json;
  json j;
  const ActuatorErrors3& e = r.errors;
  j["origin_mm"] = {e.originMm.x(), e.originMm.y(), e.originMm.z()};
  json planes = json::object(), squareness = json::object();
  for (const TestPlane p : kTestPlanes) {
    const auto ax = planeAxes(p);
    const auto idx = static_cast<std::size_t>(p);
    const PlaneFit3& pf = r.planes[idx];
    json q;
    q[std::string(1, kLetters[ax[0]]) + "_axis_angle_deg"] = e.uAngleDeg[idx];
    q[std::string(1, kLetters[ax[1]]) + "_axis_angle_deg"] = e.vAngleDeg[idx];
    q["squareness_deg"] = e.squarenessDeg(p);
    q["squareness_std_err_deg"] = r.squarenessStdErrDeg[idx];
    q["rmse_mm"] = pf.rmseMm;
    q["points"] = pf.points;
    q["source"] = pf.source;
    planes[planeName(p)] = q;
    squareness[planeName(p)] = e.squarenessDeg(p);
  }
  j["planes"] = planes;
  j["squareness_deg"] = squareness;
  const Eigen::Matrix3d D = e.directions();
  j["directions"] = {{"x", {D(0, 0), D(1, 0), D(2, 0)}},
                     {"y", {D(0, 1), D(1, 1), D(2, 1)}},
                     {"z", {D(0, 2), D(1, 2), D(2, 2)}}};
  j["standard_errors"] = {
      {"origin_mm",
       {r.standardErrors.originMm.x(), r.standardErrors.originMm.y(), r.standardErrors.originMm.z()}}};
  j["rmse_mm"] = r.rmseMm;
  j["sigma_mm"] = r.sigmaMm;
  j["points"] = r.points;
  j["iterations"] = r.run.iterations;
  j["termination"] = toString(r.run.termination);
  j["model"] =
      "P = origin + [i j k] Pr; in plane (u, v) the u axis at (cos a, sin a), the v axis at (-sin b, cos b); "
      "squareness = b - a";
  return j;
}

ActuatorErrors3 actuatorErrors3FromJson(const nlohmann::json& json, const std::string& source) {
  const JsonReader r(json, source);
  r.requireObject();
  ActuatorErrors3 e;
  originFromJson(r, e.originMm);
  const JsonReader planes = r.object("planes");
  for (const TestPlane p : kTestPlanes) {
    const JsonReader q = planes.object(planeName(p));
    const auto ax = planeAxes(p);
    const std::string uk = std::string(1, kLetters[ax[0]]) + "_axis_angle_deg";
    const std::string vk = std::string(1, kLetters[ax[1]]) + "_axis_angle_deg";
    const auto idx = static_cast<std::size_t>(p);
    e.uAngleDeg[idx] = q.number(uk);
    e.vAngleDeg[idx] = q.number(vk);
    for (const auto& [key, v] : {std::pair{uk, e.uAngleDeg[idx]}, std::pair{vk, e.vAngleDeg[idx]}}) {
      if (!std::isfinite(v) || std::abs(v) > ActuatorErrors2::kMaxAngleDeg) {
        q.fail(fmt(v) + " deg is beyond +-45 deg (an actuator orientation error)", key);
      }
    }
  }
  return e;
}

ActuatorErrors3 readActuatorErrors3(const std::string& path) {
  return actuatorErrors3FromJson(readJsonFile(path), path);
}

}  // namespace metrofit
