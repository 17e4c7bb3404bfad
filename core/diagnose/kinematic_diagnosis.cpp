#include "core/diagnose/kinematic_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/diagnose/loop.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/path_variables.h"
#include "core/optim/least_squares.h"

namespace metrofit::diagnose {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

using A = PhraseArg;

/// A number with `digits` significant digits ("n/a" when not finite); um(): millimetres shown in um.
PhraseArg num(double v, int digits = 3) {
  return A::numberOrNa(v, digits);
}
PhraseArg um(double mm, int digits = 3) {
  return num(mm * 1000.0, digits);
}

/// Which effects the model has.
/// A generic effect (`unexplained:<against>`): displacement G g of every point, G in observation
/// space (x, y rows per point; one set of basis columns per coordinate).
struct GenericTerm {
  std::shared_ptr<const Eigen::MatrixXd> columns;  ///< 2n x q
  GenericForm shape;
  /// columns = genericBasis(shape) toBasis minus its part in the model's Jacobian (absorbed by the
  /// other parameters): the coefficients c of the columns are toBasis c of the shape's own basis.
  std::shared_ptr<const Eigen::MatrixXd> toBasis;
};

struct State {
  bool backlash = false, scale = false, servo = false;
  bool cyclic[2] = {false, false};
  std::vector<GenericTerm> generic;
};

/// All parameters (angles in rad, scale in ppm, cyclic as c sin + s cos with frequency f in 1/mm).
struct Params {
  double ox = 0, oy = 0, a = 0, b = 0;
  double bx = 0, by = 0, sx = 0, sy = 0, tau = 0;
  double cc[2] = {0, 0}, cs[2] = {0, 0}, f[2] = {0, 0};
  std::vector<double> g;  ///< generic coefficients, in the order of State::generic
};

/// Index of each parameter in the packed vector of a state (-1: absent).
struct Layout {
  int bx = -1, sx = -1, tau = -1, cy[2] = {-1, -1};
  int gen = -1, genCount = 0;
  int p = 4;
};

Layout layoutOf(const State& s) {
  Layout l;
  if (s.backlash) {
    l.bx = l.p;
    l.p += 2;
  }
  if (s.scale) {
    l.sx = l.p;
    l.p += 2;
  }
  if (s.servo) l.tau = l.p++;
  for (int a = 0; a < 2; ++a) {
    if (s.cyclic[a]) {
      l.cy[a] = l.p;
      l.p += 3;
    }
  }
  for (const GenericTerm& t : s.generic) l.genCount += static_cast<int>(t.columns->cols());
  if (l.genCount > 0) {
    l.gen = l.p;
    l.p += l.genCount;
  }
  return l;
}

Eigen::VectorXd pack(const State& s, const Params& q) {
  const Layout l = layoutOf(s);
  Eigen::VectorXd v(l.p);
  v.head<4>() << q.ox, q.oy, q.a, q.b;
  if (l.bx >= 0) v.segment<2>(l.bx) << q.bx, q.by;
  if (l.sx >= 0) v.segment<2>(l.sx) << q.sx, q.sy;
  if (l.tau >= 0) v(l.tau) = q.tau;
  for (int a = 0; a < 2; ++a)
    if (l.cy[a] >= 0) v.segment<3>(l.cy[a]) << q.cc[a], q.cs[a], q.f[a];
  for (int j = 0; j < l.genCount; ++j)
    v(l.gen + j) = j < static_cast<int>(q.g.size()) ? q.g[static_cast<std::size_t>(j)] : 0.0;
  return v;
}

Params unpack(const State& s, const Eigen::VectorXd& v, Params q) {
  const Layout l = layoutOf(s);
  q.ox = v(0);
  q.oy = v(1);
  q.a = v(2);
  q.b = v(3);
  if (l.bx >= 0) q.bx = v(l.bx), q.by = v(l.bx + 1);
  if (l.sx >= 0) q.sx = v(l.sx), q.sy = v(l.sx + 1);
  if (l.tau >= 0) q.tau = v(l.tau);
  for (int a = 0; a < 2; ++a)
    if (l.cy[a] >= 0) q.cc[a] = v(l.cy[a]), q.cs[a] = v(l.cy[a] + 1), q.f[a] = v(l.cy[a] + 2);
  q.g.assign(static_cast<std::size_t>(l.genCount), 0.0);
  for (int j = 0; j < l.genCount; ++j) q.g[static_cast<std::size_t>(j)] = v(l.gen + j);
  return q;
}

struct Data {
  const MeasuredPath* path = nullptr;
  PathMotion motion;
  double speed = 0.0;  ///< mm/s
  std::size_t n = 0;
};

/// Residuals P(theta) - Pmeas (x0, y0, x1, ...) and, when J is given, their Jacobian.
void evaluate(const Data& d, const State& s, const Params& q, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
  const Layout l = layoutOf(s);
  const auto m = static_cast<Eigen::Index>(2 * d.n);
  r.resize(m);
  if (J) J->setZero(m, l.p);
  const Eigen::Vector2d ir(std::cos(q.a), std::sin(q.a)), jr(-std::sin(q.b), std::cos(q.b));
  const Eigen::Vector2d dira(-std::sin(q.a), std::cos(q.a)), dirb(-std::cos(q.b), -std::sin(q.b));
  for (std::size_t k = 0; k < d.n; ++k) {
    const Eigen::Vector2d c = d.path->command[k];
    const Eigen::Vector2d& dir = d.motion.direction[k];
    const Eigen::Vector2d& t = d.motion.tangent[k];
    double je[2] = {c.x(), c.y()};
    if (s.backlash) je[0] -= dir.x() * q.bx / 2.0, je[1] -= dir.y() * q.by / 2.0;
    if (s.scale) je[0] += c.x() * q.sx * 1e-6, je[1] += c.y() * q.sy * 1e-6;
    if (s.servo) je[0] -= q.tau * d.speed * t.x(), je[1] -= q.tau * d.speed * t.y();
    double ph[2] = {0, 0};
    for (int a = 0; a < 2; ++a) {
      if (!s.cyclic[a]) continue;
      ph[a] = 2.0 * kPi * q.f[a] * c(a);
      je[a] += q.cc[a] * std::sin(ph[a]) + q.cs[a] * std::cos(ph[a]);
    }
    const Eigen::Vector2d P = Eigen::Vector2d(q.ox, q.oy) + ir * je[0] + jr * je[1];
    const auto i = static_cast<Eigen::Index>(2 * k);
    r.segment<2>(i) = P - d.path->measured[k];
    if (!J) continue;
    auto set = [&](int col, const Eigen::Vector2d& g) { J->block<2, 1>(i, col) = g; };
    set(0, Eigen::Vector2d(1, 0));
    set(1, Eigen::Vector2d(0, 1));
    set(2, dira * je[0]);
    set(3, dirb * je[1]);
    if (l.bx >= 0) set(l.bx, -ir * dir.x() / 2.0), set(l.bx + 1, -jr * dir.y() / 2.0);
    if (l.sx >= 0) set(l.sx, ir * c.x() * 1e-6), set(l.sx + 1, jr * c.y() * 1e-6);
    if (l.tau >= 0) set(l.tau, -(ir * t.x() + jr * t.y()) * d.speed);
    for (int a = 0; a < 2; ++a) {
      if (l.cy[a] < 0) continue;
      const Eigen::Vector2d& ax = a == 0 ? ir : jr;
      set(l.cy[a], ax * std::sin(ph[a]));
      set(l.cy[a] + 1, ax * std::cos(ph[a]));
      set(l.cy[a] + 2, ax * 2.0 * kPi * c(a) * (q.cc[a] * std::cos(ph[a]) - q.cs[a] * std::sin(ph[a])));
    }
  }
  // Generic effects: linear in their coefficients.
  int col = l.gen;
  std::size_t gi = 0;
  for (const GenericTerm& t : s.generic) {
    const Eigen::MatrixXd& G = *t.columns;
    for (Eigen::Index j = 0; j < G.cols(); ++j, ++col, ++gi) {
      const double coef = gi < q.g.size() ? q.g[gi] : 0.0;
      r += coef * G.col(j);
      if (J) J->col(col) = G.col(j);
    }
  }
}

struct Solution {
  bool ok = false;
  Params q;
  Eigen::VectorXd r;
  Eigen::MatrixXd cov;  ///< packed parameters
  double sse = 0.0, rmse = 0.0, maxAbs = 0.0;
  int p = 4;
};

/// Levenberg-Marquardt (core/optim/least_squares.h: Marquardt scaling, Nielsen's damping update) from q0.
Solution solve(const Data& d, const State& s, const Params& q0) {
  Solution sol;
  const Layout l = layoutOf(s);
  sol.p = l.p;
  optim::LeastSquaresOptions lo;
  lo.maxIterations = 200;
  lo.costTolerance = 1e-13;
  const optim::Residual f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    evaluate(d, s, unpack(s, x, q0), r, J);
  };
  Eigen::VectorXd th = pack(s, q0);
  const optim::LeastSquaresSummary sum = optim::solveLeastSquares(f, th, lo);
  const Eigen::VectorXd& r = sum.residuals;
  const Eigen::MatrixXd& J = sum.jacobian;
  const double cost = r.squaredNorm();
  sol.q = unpack(s, th, q0);
  sol.r = r;
  sol.sse = cost;
  const double n = static_cast<double>(d.n);
  sol.rmse = std::sqrt(cost / n);
  for (std::size_t k = 0; k < d.n; ++k)
    sol.maxAbs = std::max(sol.maxAbs, r.segment<2>(static_cast<Eigen::Index>(2 * k)).norm());
  if (J.rows() != r.size() || !std::isfinite(cost)) return sol;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  if (qr.rank() < l.p || 2.0 * n <= l.p) return sol;
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(l.p, l.p).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd Rinv = R.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(l.p, l.p));
  const Eigen::MatrixXd P = qr.colsPermutation().toDenseMatrix().cast<double>();
  sol.cov = cost / (2.0 * n - l.p) * (P * Rinv * Rinv.transpose() * P.transpose());
  sol.ok = true;
  return sol;
}

double bic(const Solution& s, std::size_t n) {
  const double m = 2.0 * static_cast<double>(n);
  return m * std::log(std::max(s.sse, 1e-300) / m) + s.p * std::log(m);
}

double se(const Solution& s, int i) {
  return i >= 0 && s.ok ? std::sqrt(std::max(0.0, s.cov(i, i))) : 0.0;
}

struct CyclicStart {
  bool ok = false;
  Params q;
  int frequencies = 0;
};

/// Grid search of the cyclic error's frequency on axis `a` (linearised about the current solution).
CyclicStart cyclicStart(const Data& d, const State& s, const Solution& cur, int a, double minP, double maxP) {
  CyclicStart out;
  double lo = d.path->command[0](a), hi = lo, maxStep = 0.0;
  for (std::size_t k = 0; k < d.n; ++k) {
    lo = std::min(lo, d.path->command[k](a));
    hi = std::max(hi, d.path->command[k](a));
    if (k > 0) maxStep = std::max(maxStep, std::abs(d.path->command[k](a) - d.path->command[k - 1](a)));
  }
  const double span = hi - lo;
  if (!(span > 0.0)) return out;
  const double pMin = minP > 0.0 ? minP : std::max(3.0 * maxStep, 1e-6);
  const double pMax = maxP > 0.0 ? maxP : span / 2.0;
  if (!(pMax > pMin)) return out;
  const double fMin = 1.0 / pMax, fMax = 1.0 / pMin, df = 1.0 / (8.0 * span);
  const int count = static_cast<int>(std::floor((fMax - fMin) / df)) + 1;
  if (count < 1 || count > 200000) return out;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  evaluate(d, s, cur.q, r, &J);
  const Eigen::Index m = r.size();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(m, J.cols());
  const Eigen::VectorXd r0 = r - Q * (Q.transpose() * r);
  const Eigen::Vector2d ax = a == 0 ? Eigen::Vector2d(std::cos(cur.q.a), std::sin(cur.q.a))
                                    : Eigen::Vector2d(-std::sin(cur.q.b), std::cos(cur.q.b));
  double bestSse = r0.squaredNorm();
  Eigen::Vector2d bestCoef = Eigen::Vector2d::Zero();
  double bestF = 0.0;
  Eigen::MatrixXd G(m, 2);
  for (int i = 0; i < count; ++i) {
    const double f = fMin + df * i;
    for (std::size_t k = 0; k < d.n; ++k) {
      const double ph = 2.0 * kPi * f * d.path->command[k](a);
      const auto row = static_cast<Eigen::Index>(2 * k);
      G.block<2, 1>(row, 0) = ax * std::sin(ph);
      G.block<2, 1>(row, 1) = ax * std::cos(ph);
    }
    G -= Q * (Q.transpose() * G);
    const Eigen::Matrix2d GtG = G.transpose() * G;
    const Eigen::Vector2d Gtr = G.transpose() * r0;
    if (std::abs(GtG.determinant()) < 1e-300) continue;
    const Eigen::Vector2d coef = -GtG.ldlt().solve(Gtr);
    const double sse = (r0 + G * coef).squaredNorm();
    if (sse < bestSse) {
      bestSse = sse;
      bestCoef = coef;
      bestF = f;
    }
  }
  if (bestF == 0.0) return out;
  out.ok = true;
  out.q = cur.q;
  out.q.cc[a] = bestCoef(0);
  out.q.cs[a] = bestCoef(1);
  out.q.f[a] = bestF;
  out.frequencies = count;
  return out;
}

/// Path angle (deg, [0, 360)) and radial residual of every point about the commands' centroid.
void radialPlot(const Data& d, const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                ResidualPlot& plot) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : d.path->command) c += p;
  c /= static_cast<double>(d.n);
  plot.setLabels({Phrase("path angle (deg)")}, {Phrase("radial residual (mm)")});
  for (std::size_t k = 0; k < d.n; ++k) {
    const Eigen::Vector2d v = d.path->command[k] - c;
    double ang = std::atan2(v.y(), v.x()) / kDeg;
    if (ang < 0.0) ang += 360.0;
    const Eigen::Vector2d u = v.norm() > 0.0 ? Eigen::Vector2d(v / v.norm()) : Eigen::Vector2d::UnitX();
    const auto i = static_cast<Eigen::Index>(2 * k);
    // Residual as measured minus modelled (the declared model's convention in identification.h).
    plot.x.push_back(ang);
    plot.before.push_back(-u.dot(before.segment<2>(i)));
    plot.after.push_back(-u.dot(after.segment<2>(i)));
  }
}

ErrorSummary summaryOf(const Solution& s) {
  ErrorSummary e;
  e.rmse = s.rmse;
  e.maxAbs = s.maxAbs;
  return e;
}

}  // namespace

bool KinematicDiagnosisOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(feedMmPerMin > 0.0) || !std::isfinite(feedMmPerMin)) return no("feed must be positive (mm/min)");
  if (!(bicMargin >= 0.0) || !std::isfinite(bicMargin))
    return no("bicMargin must be finite and not negative");
  if (!(minRmseGain >= 0.0 && minRmseGain < 1.0)) return no("minRmseGain must be in [0, 1)");
  if (maxRounds < 0) return no("maxRounds must not be negative");
  if (!(minPeriodMm >= 0.0) || !(maxPeriodMm >= 0.0)) return no("cyclic period bounds must not be negative");
  if (minPeriodMm > 0.0 && maxPeriodMm > 0.0 && !(maxPeriodMm > minPeriodMm))
    return no("maxPeriodMm must exceed minPeriodMm");
  return true;
}

namespace {

Data makeData(const MeasuredPath& path, const KinematicDiagnosisOptions& o) {
  Data d;
  d.path = &path;
  d.n = path.size();
  d.motion = pathMotion(path.command);
  d.speed = o.feedMmPerMin / 60.0;
  return d;
}

/// The residual variables of a path (core/kinematics/path_variables.h, shared with the applied generic
/// effects of applied_kinematic.h): row (the original 1-based point number), the path angle about the
/// centroid, the loop direction (CCW / CW; only when the path runs both), reversal and the commanded
/// x and y.
std::vector<ResidualVariable> kinematicVariables(const Data& d, const std::vector<std::size_t>& orig) {
  PathVariables pv = pathVariables(d.path->command);
  std::vector<ResidualVariable> vars;
  ResidualVariable row, ang, dir, rev, x, y;
  row.name = "row";
  row.naturalOrder = true;
  row.label = {Phrase("data row")};
  for (std::size_t k = 0; k < d.n; ++k) row.values.push_back(static_cast<double>(orig[k] + 1));
  ang.name = "angle";
  ang.kind = ResidualVariable::Kind::Angle;
  ang.label = {Phrase("path angle (deg)")};
  ang.values = std::move(pv.angle);
  dir.name = "direction";
  dir.kind = ResidualVariable::Kind::Category;
  dir.levels = {"CCW", "CW"};
  dir.label = {Phrase("loop direction")};
  dir.values = std::move(pv.direction);
  rev.name = "reversal";
  rev.label = {Phrase("samples since an axis reversed (signed, log scale)")};
  rev.values = std::move(pv.reversal);
  x.name = "x";
  x.label = {Phrase("x (mm)")};
  x.values = std::move(pv.x);
  y.name = "y";
  y.label = {Phrase("y (mm)")};
  y.values = std::move(pv.y);
  vars.push_back(std::move(row));
  vars.push_back(std::move(ang));
  if (pv.bothDirections) vars.push_back(std::move(dir));
  vars.push_back(std::move(rev));
  vars.push_back(std::move(x));
  vars.push_back(std::move(y));
  return vars;
}

/// The check's observations: the residual vector of every point (measured minus modelled; x, y as
/// two components), with the model's Jacobian; the variables repeated on both coordinates.
ResidualCheckInput kinematicCheckInput(const Data& d, const State& s, const Solution& sol,
                                       const std::vector<ResidualVariable>& vars,
                                       const std::vector<std::size_t>& orig) {
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  evaluate(d, s, sol.q, r, &J);
  ResidualCheckInput in;
  in.residual = -r;
  in.modelColumns = J;
  in.components = 2;
  for (const ResidualVariable& v : vars) {
    ResidualVariable w = v;
    w.values.clear();
    for (double x : v.values) {
      w.values.push_back(x);
      w.values.push_back(x);
    }
    in.variables.push_back(std::move(w));
  }
  for (std::size_t k = 0; k < d.n; ++k) {
    in.unitOf.push_back(k);
    in.unitOf.push_back(k);
    in.unitRow.push_back(static_cast<long>(orig[k] + 1));
  }
  return in;
}

LoopRun runKinematic(const MeasuredPath& path, const std::vector<std::size_t>& orig,
                     const KinematicDiagnosisOptions& o, const std::set<std::string>& excluded,
                     Observer* observer) {
  const IdentifyResult base = identifyActuatorErrors(path);  // checks the path (InputError)
  const Data d = makeData(path, o);

  Diagnosis dg;
  dg.domain = "kinematic";
  dg.units = "mm";
  dg.baseline.rmse = base.rmseMm;
  dg.baseline.maxAbs = base.maxAbsMm;
  dg.addNote(
      {Phrase("declared model: origin (%1, %2) um, x axis %3 deg, y axis %4 deg, squareness %5 deg",
              {um(base.errors.originMm.x()), um(base.errors.originMm.y()), num(base.errors.xAxisAngleDeg),
               num(base.errors.yAxisAngleDeg), num(base.errors.squarenessDeg())})});

  State state;
  Params q0;
  q0.ox = base.errors.originMm.x();
  q0.oy = base.errors.originMm.y();
  q0.a = base.errors.xAxisAngleDeg * kDeg;
  q0.b = base.errors.yAxisAngleDeg * kDeg;
  Solution cur = solve(d, state, q0);

  const std::vector<ResidualVariable> vars = kinematicVariables(d, orig);

  /// The kinematic domain of the shared loop (loop.h): the declared actuator errors plus effects,
  /// fitted by nonlinear least squares on the x, y residual of every point, dBIC of the whole model.
  class Domain final : public LoopDomain {
   public:
    Domain(const Data& d, const KinematicDiagnosisOptions& o, const std::vector<ResidualVariable>& vars,
           const std::vector<std::size_t>& orig, Solution start)
        : d_(d), o_(o), vars_(vars), orig_(orig), cur_(std::move(start)) {}

    std::vector<std::string> namedCandidates(const std::set<std::string>& excluded) override {
      // cyclic stays open until both axes have it.
      return openNamedEffects(
          {"backlash", "scale", "cyclic", "servo_lag"},
          {state_.backlash, state_.scale, state_.cyclic[0] && state_.cyclic[1], state_.servo}, excluded);
    }
    // The variables of the named effects (loop.h, "a generic effect of the same variable explains
    // clearly more"): backlash acts at the reversals (reversal, direction), scale along x and y,
    // cyclic along its axis (x or y, its parameter), servo lag by the direction of travel.
    std::vector<std::string> namedVariables(const Candidate& c) const override {
      if (c.name == "backlash") return {"reversal", "direction"};
      if (c.name == "scale") return {"x", "y"};
      if (c.name == "servo_lag") return {"direction"};
      if (c.name == "cyclic")
        for (const Parameter& p : c.parameters)
          if (p.name == "axis")
            if (const auto* a = std::get_if<std::string>(&p.value)) return {*a};
      return {};
    }
    double clearMargin() const override { return o_.bicMargin; }
    ResidualCheck roundCheck() override {
      // A generic effect is the part of f(v) the current model cannot absorb: its basis is projected
      // off the model's Jacobian at the solution (a linear part in x or y is a squareness or scale the
      // declared model already has) and replaced by an orthonormal basis of what is left, so that the
      // joint fit stays well conditioned.
      Eigen::VectorXd r0;
      Eigen::MatrixXd J0;
      evaluate(d_, state_, cur_.q, r0, &J0);
      const Eigen::HouseholderQR<Eigen::MatrixXd> qrJ(J0);
      QJ_ = qrJ.householderQ() * Eigen::MatrixXd::Identity(J0.rows(), J0.cols());
      check_ = kinematicCheckInput(d_, state_, cur_, vars_, orig_);
      return checkResidual(check_);
    }
    std::optional<GenericForm> prepareGeneric(const GenericForm& g) override {
      const ResidualVariable* v = findVariable(check_.variables, g.against);
      if (!v) return std::nullopt;
      // Observation space (x, y per point), one set of columns per coordinate.
      const Eigen::MatrixXd G = variableBasis(g, *v);
      const Eigen::MatrixXd Gp = G - QJ_ * (QJ_.transpose() * G);
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Gp, Eigen::ComputeThinU | Eigen::ComputeThinV);
      Eigen::Index rank = 0;
      const double top = G.norm();
      for (Eigen::Index j = 0; j < svd.singularValues().size(); ++j)
        if (svd.singularValues()(j) > 1e-6 * top) ++rank;
      if (rank == 0) return std::nullopt;
      Eigen::MatrixXd Gk = svd.matrixU().leftCols(rank);
      // Gk = Gp V_r S_r^-1: coefficients c of Gk are V_r S_r^-1 c of the basis G.
      Eigen::MatrixXd toBasis =
          svd.matrixV().leftCols(rank) * svd.singularValues().head(rank).cwiseInverse().asDiagonal();
      terms_[g.against] = GenericTerm{std::make_shared<const Eigen::MatrixXd>(std::move(Gk)), g,
                                      std::make_shared<const Eigen::MatrixXd>(std::move(toBasis))};
      return g;
    }
    bool beginRound(int) override {
      slots_.clear();
      terms_.clear();
      return true;
    }
    std::optional<LoopTrial> tryNamed(const std::string& name, int, std::size_t slot) override {
      return trial(name, nullptr, 0.0, slot);
    }
    std::optional<LoopTrial> tryGeneric(const GenericForm& g, double penalty, int,
                                        std::size_t slot) override {
      return trial("unexplained:" + g.against, &terms_.at(g.against), penalty, slot);
    }
    void accept(std::size_t slot, Candidate& c) override {
      Slot& s = slots_[slot];
      ResidualPlot plot;
      radialPlot(d_, cur_.r, s.sol.r, plot);
      c.plot = std::move(plot);
      state_ = s.state;
      cur_ = std::move(s.sol);
    }
    double currentError() const override { return cur_.rmse; }
    void finish(Diagnosis& dg, std::vector<Candidate*> accepted, bool) override {
      // Each accepted generic effect's coefficients in its shape's own basis, from the final joint
      // fit (what Apply stores: the displacement genericBasis(shape) w on any path, applied_kinematic.h).
      std::size_t at = 0;
      for (const GenericTerm& t : state_.generic) {
        const Eigen::Index q = t.columns->cols();
        Eigen::VectorXd c(q);
        for (Eigen::Index j = 0; j < q; ++j) c(j) = cur_.q.g[at + static_cast<std::size_t>(j)];
        at += static_cast<std::size_t>(q);
        const Eigen::VectorXd w = *t.toBasis * c;
        for (Candidate* a : accepted)
          if (a->generic && a->name == "unexplained:" + t.shape.against)
            a->genericCoefficients.assign(w.data(), w.data() + w.size());
      }
      dg.final = summaryOf(cur_);
      dg.residualCheck = checkResidual(kinematicCheckInput(d_, state_, cur_, vars_, orig_));
    }
    double dataCriterion() const override { return bic(cur_, d_.n); }

   private:
    struct Slot {
      State state;
      Solution sol;
    };

    LoopTrial trial(const std::string& name, const GenericTerm* term, double genericPenalty,
                    std::size_t slot) {
      LoopTrial t;
      Candidate& c = t.candidate;
      c.name = name;
      c.rmseBefore = cur_.rmse;
      State next = state_;
      Solution sol;
      double penalty = 0.0;
      int cyAxis = -1;
      if (name == "backlash") {
        next.backlash = true;
        sol = solve(d_, next, cur_.q);
      } else if (name == "scale") {
        next.scale = true;
        sol = solve(d_, next, cur_.q);
      } else if (name == "servo_lag") {
        next.servo = true;
        sol = solve(d_, next, cur_.q);
      } else if (term) {
        next.generic.push_back(*term);
        c.generic = term->shape;
        sol = solve(d_, next, cur_.q);
        penalty = genericPenalty;
      } else {  // cyclic: the better axis
        for (int a = 0; a < 2; ++a) {
          if (state_.cyclic[a]) continue;
          const CyclicStart cs = cyclicStart(d_, state_, cur_, a, o_.minPeriodMm, o_.maxPeriodMm);
          if (!cs.ok) continue;
          State sa = state_;
          sa.cyclic[a] = true;
          Solution sx = solve(d_, sa, cs.q);
          if (cyAxis < 0 || sx.sse < sol.sse) {
            sol = std::move(sx);
            next = sa;
            cyAxis = a;
            penalty = 2.0 * std::log(std::max(1.0, cs.frequencies / 8.0));
          }
        }
      }
      const Layout l = layoutOf(next);
      if (!sol.ok) {
        c.rmseAfter = cur_.rmse;
        c.setEvidence(
            {cyAxis < 0 && name == "cyclic"
                 ? Phrase("not estimable: no period range to search on this path")
                 : Phrase("not estimable from this path: its parameters are not observable together "
                          "with the declared ones")});
        if (name == "cyclic" && cyAxis < 0) c.parameters.push_back({"axis", std::string("x"), std::nullopt});
      } else {
        t.estimable = true;
        const Params& q = sol.q;
        Phrase text;
        if (name == "backlash") {
          c.parameters = {{"x_mm", q.bx, se(sol, l.bx)}, {"y_mm", q.by, se(sol, l.bx + 1)}};
          text = Phrase("backlash x %1 +- %2 um, y %3 +- %4 um",
                        {um(q.bx), um(se(sol, l.bx), 2), um(q.by), um(se(sol, l.bx + 1), 2)});
        } else if (name == "scale") {
          c.parameters = {{"x_ppm", q.sx, se(sol, l.sx)}, {"y_ppm", q.sy, se(sol, l.sx + 1)}};
          text = Phrase("scale x %1 +- %2 ppm, y %3 +- %4 ppm",
                        {num(q.sx), num(se(sol, l.sx), 2), num(q.sy), num(se(sol, l.sx + 1), 2)});
        } else if (c.generic) {
          // The last generic term's contribution to the modelled positions (x, y of every point).
          const Eigen::MatrixXd& Gk = *next.generic.back().columns;
          const Eigen::Index q0 = Gk.cols();
          Eigen::VectorXd b(q0);
          for (Eigen::Index j = 0; j < q0; ++j) b(j) = q.g[q.g.size() - static_cast<std::size_t>(q0 - j)];
          const GenericSummary gs = summariseContribution(*c.generic, Gk * b, "mm");
          c.parameters = {Parameter{"form", std::string(formName(c.generic->form)), std::nullopt}};
          for (const auto& [k, val] : gs.numbers) c.parameters.push_back({k, val, std::nullopt});
          text = Phrase("%1", {A::text(gs.text)});
        } else if (name == "servo_lag") {
          const double lagMm = q.tau * d_.speed;
          c.parameters = {{"tau_s", q.tau, se(sol, l.tau)}, {"lag_mm", lagMm, se(sol, l.tau) * d_.speed}};
          text = Phrase("servo lag tau %1 +- %2 s at %3 mm/min (%4 um)",
                        {num(q.tau), num(se(sol, l.tau), 2), num(o_.feedMmPerMin), um(lagMm)});
        } else {
          const int a = cyAxis, i0 = l.cy[a];
          const double cc = q.cc[a], cs = q.cs[a], f = q.f[a];
          const double amp = std::hypot(cc, cs);
          const Eigen::Vector2d g = amp > 0.0 ? Eigen::Vector2d(cc / amp, cs / amp) : Eigen::Vector2d(1, 0);
          const double seAmp = std::sqrt(std::max(0.0, g.dot(sol.cov.block<2, 2>(i0, i0) * g)));
          const double period = 1.0 / std::abs(f);
          const double sePeriod = se(sol, i0 + 2) / (f * f);
          double phase = std::atan2(cs, cc) / kDeg;
          if (f < 0.0) phase = 180.0 - phase;  // sin(-w x + p) = sin(w x + 180 - p)
          phase = std::remainder(phase, 360.0);
          c.parameters = {{"axis", std::string(a == 0 ? "x" : "y"), std::nullopt},
                          {"period_mm", period, sePeriod},
                          {"amplitude_mm", amp, seAmp},
                          {"phase_deg", phase, std::nullopt}};
          text =
              Phrase("cyclic on %1: period %2 +- %3 mm, amplitude %4 +- %5 um",
                     {A::name(a == 0 ? "x" : "y"), num(period, 4), num(sePeriod, 2), um(amp), um(seAmp, 2)});
        }
        c.rmseAfter = sol.rmse;
        const double dBic = bic(sol, d_.n) + penalty - bic(cur_, d_.n);
        c.score = dBic;
        const bool strong = dBic < -o_.bicMargin;
        const bool gain = sol.rmse <= (1.0 - o_.minRmseGain) * cur_.rmse;
        const double change = cur_.rmse > 0 ? 100.0 * (sol.rmse - cur_.rmse) / cur_.rmse
                                            : std::numeric_limits<double>::quiet_NaN();  // "n/a"
        Phrases ev = {Phrase("rmse %1 -> %2 um (%3 %), dBIC %4, %5",
                             {um(cur_.rmse), um(sol.rmse), num(change, 2), num(dBic, 4), A::text({text})})};
        if (!strong)
          ev.push_back(Phrase("; rejected: dBIC above -%1", {num(o_.bicMargin)}));
        else if (!gain)
          ev.push_back(Phrase("; rejected: rmse gain below %1 %", {num(100.0 * o_.minRmseGain, 2)}));
        c.setEvidence(std::move(ev));
        t.passes = strong && gain;
        t.complexity = penalty;  // the parameters are in bic() already
      }
      if (slots_.size() <= slot) slots_.resize(slot + 1);
      slots_[slot] = Slot{std::move(next), std::move(sol)};
      return t;
    }

    const Data& d_;
    const KinematicDiagnosisOptions& o_;
    const std::vector<ResidualVariable>& vars_;
    const std::vector<std::size_t>& orig_;
    State state_;
    Solution cur_;
    Eigen::MatrixXd QJ_;
    ResidualCheckInput check_;
    std::map<std::string, GenericTerm> terms_;
    std::vector<Slot> slots_;
  };

  Domain domain(d, o, vars, orig, std::move(cur));
  return runLoop(domain, LoopStyle::everyRound(o.maxRounds, "rmse_mm"), excluded, observer, std::move(dg));
}

}  // namespace

Diagnosis diagnoseKinematic(const MeasuredPath& path, const KinematicDiagnosisOptions& o,
                            Observer* observer) {
  requireValid(o, "kinematic diagnosis options");
  // Gross errors (`outliers`, docs/file-formats.md#residual_check): found on the declared model's residual
  // (robust z per coordinate, see residual_check.h), the points excluded and the loop run without them.
  const IdentifyResult base = identifyActuatorErrors(path);  // checks the path (InputError)
  std::vector<std::size_t> all(path.size());
  std::iota(all.begin(), all.end(), 0);
  ResidualCheckInput in;
  {
    const Data d = makeData(path, o);
    Params q0;
    q0.ox = base.errors.originMm.x();
    q0.oy = base.errors.originMm.y();
    q0.a = base.errors.xAxisAngleDeg * kDeg;
    q0.b = base.errors.yAxisAngleDeg * kDeg;
    const Solution s0 = solve(d, State{}, q0);
    in.residual = s0.r;
    for (std::size_t k = 0; k < path.size(); ++k) {
      in.unitOf.push_back(k);
      in.unitOf.push_back(k);
      in.unitRow.push_back(static_cast<long>(k + 1));
    }
  }
  double threshold = 0.0;
  std::vector<Outlier> outliers = findOutliers(in, {}, &threshold);
  MeasuredPath kept = path;
  std::vector<std::size_t> orig = all;
  if (!outliers.empty()) {
    std::vector<bool> excluded(path.size(), false);
    for (const Outlier& x : outliers) excluded[x.unit] = true;
    kept.command.clear();
    kept.measured.clear();
    kept.lines.clear();
    orig.clear();
    for (std::size_t k = 0; k < path.size(); ++k) {
      if (excluded[k]) continue;
      kept.command.push_back(path.command[k]);
      kept.measured.push_back(path.measured[k]);
      if (k < path.lines.size()) kept.lines.push_back(path.lines[k]);
      orig.push_back(k);
    }
  }
  Diagnosis dg = keepNamedOnlyWhenNeeded(
      [&](const std::set<std::string>& ex) { return runKinematic(kept, orig, o, ex, observer); },
      o.bicMargin);
  attachOutliers(dg, std::move(outliers), threshold, [](const Outlier& x) {
    return Phrase(" row %1 (%2 um)", {A::integer(x.row.value_or(0)), um(x.residual)});
  });
  return dg;
}

}  // namespace metrofit::diagnose
