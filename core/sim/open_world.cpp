#include "core/sim/open_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Dense>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/sim/circular_sim.h"
#include "core/sim/effects_kinematic.h"
#include "core/sim/effects_setup.h"
#include "core/sim/effects_thermal.h"
#include "core/sim/probe_sim.h"

namespace metrofit {
namespace {

constexpr double kPi = std::numbers::pi;

// Independent streams of one seed (base data use the seed itself).
constexpr std::uint64_t kEffectStream = 0x0e7f3c75a1d2b4c9ULL;
constexpr std::uint64_t kNoiseStream = 0x6b2f9e04c3a85d17ULL;

constexpr double kThermalSigmaUm = 0.25;
constexpr double kKinematicSigmaMm = 0.0005;
constexpr double kSetupSigmaMm = 0.005;
constexpr double kMatchingSigmaMm = 0.006;

[[noreturn]] void fail(const std::string& field, const std::string& why) {
  throw OptionsError(ErrorContext{{}, 0, 0, field}, why);
}

std::string fmt(const char* f, double a, double b = 0.0, double c = 0.0) {
  char buf[160];
  metrofit::c_snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

OpenWorldCaseInfo lookUp(OpenWorldDomain domain, const std::string& name) {
  for (const auto& c : openWorldCases(domain))
    if (c.name == name) return c;
  std::string known;
  for (const auto& c : openWorldCases(domain)) known += (known.empty() ? "" : ", ") + c.name;
  fail("case", std::string("unknown open-world case '") + name + "' of the " + toString(domain) +
                   " domain (known: " + known + ")");
}

NoiseKind cleanNoise(const std::string& name) {
  if (name == "clean_laplace") return NoiseKind::Laplace;
  if (name == "clean_t5") return NoiseKind::StudentT5;
  return NoiseKind::Gaussian;
}

/// One case under construction: the observations' effect shape (unit amplitude), the declared
/// model's columns linearised at the clean data, and the truth.
struct Draft {
  OpenWorldCaseInfo info;
  Eigen::VectorXd shape;     // n observations (zero for clean data)
  Eigen::MatrixXd declared;  // n x p
  OpenWorldTruth truth;
  /// > 0: the amplitude is this * ratio * sigma (a block of points: its size, not its visible rms,
  /// is what the case states), else sized by the visible rms.
  double sigmasPerRatio = 0.0;
};

Draft startDraft(OpenWorldDomain domain, const std::string& name, double ratio, const OpenWorldOptions& o,
                 double defaultSigma, Eigen::Index n) {
  Draft d;
  d.info = lookUp(domain, name);
  if (!(o.noiseSigma >= 0.0) || !std::isfinite(o.noiseSigma)) fail("noise_sigma", "must be finite and >= 0");
  if (!(o.outlierSigmasPerRatio > 0.0) || !std::isfinite(o.outlierSigmasPerRatio))
    fail("outlier_sigmas_per_ratio", "must be finite and > 0");
  if (d.info.kind != OpenCaseKind::Clean && (!(ratio > 0.0) || !std::isfinite(ratio)))
    fail("ratio", "the effect-to-noise ratio must be finite and > 0");
  d.shape = Eigen::VectorXd::Zero(n);
  d.truth.caseName = name;
  d.truth.kind = d.info.kind;
  d.truth.form = d.info.form;
  d.truth.noise = d.info.kind == OpenCaseKind::Clean ? cleanNoise(name) : o.noise;
  d.truth.noiseSigma = o.noiseSigma > 0.0 ? o.noiseSigma : defaultSigma;
  d.truth.ratio = d.info.kind == OpenCaseKind::Clean ? 0.0 : ratio;
  return d;
}

double rms(const Eigen::VectorXd& v) {
  return v.size() ? std::sqrt(v.squaredNorm() / static_cast<double>(v.size())) : 0.0;
}

/// v minus its least-squares fit on the columns of D (rank deficiency allowed).
Eigen::VectorXd offColumns(const Eigen::MatrixXd& D, const Eigen::VectorXd& v) {
  if (D.cols() == 0) return v;
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(D);
  return v - D * cod.solve(v);
}

/// Sizes the effect, draws the noise and returns what is added to the clean observations.
/// One of the S-piece's surfaces drawn at random, its points and its longest extent: the position
/// along it is u = (q_axis - mid) / half in [-1, 1] (surface_bow, surface_tilt).
struct SurfaceSpan {
  std::string name;
  std::vector<std::size_t> points;
  Eigen::Index axis = 0;
  double mid = 0.0, half = 1.0;
  double u(const ProbePoint& p) const { return (p.nominal(axis) - mid) / half; }
};

SurfaceSpan pickSurface(Rng& rng, const std::vector<ProbePoint>& pts) {
  const char* surfaces[3] = {"ruled+", "ruled-", "plane"};
  SurfaceSpan s;
  s.name = surfaces[rng.below(3)];
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].surface == s.name) {
      s.points.push_back(i);
      lo = lo.cwiseMin(pts[i].nominal);
      hi = hi.cwiseMax(pts[i].nominal);
    }
  (hi - lo).maxCoeff(&s.axis);
  s.mid = 0.5 * (lo(s.axis) + hi(s.axis));
  s.half = 0.5 * (hi(s.axis) - lo(s.axis));
  return s;
}

Eigen::VectorXd finish(Draft& d, std::uint64_t seed, const OpenWorldOptions& o) {
  OpenWorldTruth& t = d.truth;
  const double sigma = t.noiseSigma;
  if (t.kind == OpenCaseKind::Effect && d.sigmasPerRatio > 0.0) {
    t.amplitude = d.sigmasPerRatio * t.ratio * sigma;
  } else if (t.kind == OpenCaseKind::Effect) {
    const double visibleShape = rms(offColumns(d.declared, d.shape));
    if (!(visibleShape > 1e-12 * std::max(1.0, rms(d.shape))))
      fail("case", "the effect of case '" + t.caseName + "' is absorbed by the declared model");
    t.amplitude = t.ratio * sigma / visibleShape;
  } else if (t.kind == OpenCaseKind::Outlier) {
    t.amplitude = o.outlierSigmasPerRatio * t.ratio * sigma;
  }
  const Eigen::VectorXd effect = t.amplitude * d.shape;
  t.effectRms = rms(effect);
  t.visibleRms = rms(offColumns(d.declared, effect));
  Rng noise(seed ^ kNoiseStream);
  Eigen::VectorXd added = effect;
  for (Eigen::Index i = 0; i < added.size(); ++i) added(i) += drawNoise(noise, t.noise, sigma);
  return added;
}

}  // namespace

// ---- noise ----------------------------------------------------------------------------------------

const char* toString(NoiseKind kind) {
  switch (kind) {
    case NoiseKind::Laplace:
      return "laplace";
    case NoiseKind::StudentT5:
      return "t5";
    case NoiseKind::Gaussian:
      break;
  }
  return "gauss";
}

double drawNoise(Rng& rng, NoiseKind kind, double sigma) {
  switch (kind) {
    case NoiseKind::Laplace: {
      double u = 0.0;
      do u = rng.uniform() - 0.5;
      while (u == -0.5);
      const double b = sigma / std::numbers::sqrt2;
      return -b * (u < 0.0 ? -1.0 : 1.0) * std::log(1.0 - 2.0 * std::abs(u));
    }
    case NoiseKind::StudentT5: {
      const double z = rng.normal();
      double v = 0.0;
      for (int i = 0; i < 5; ++i) {
        const double g = rng.normal();
        v += g * g;
      }
      return sigma * std::sqrt(3.0 / 5.0) * z / std::sqrt(v / 5.0);
    }
    case NoiseKind::Gaussian:
      break;
  }
  return rng.normal(0.0, sigma);
}

// ---- cases ----------------------------------------------------------------------------------------

const char* toString(OpenWorldDomain domain) {
  switch (domain) {
    case OpenWorldDomain::Kinematic:
      return "kinematic";
    case OpenWorldDomain::Setup:
      return "setup";
    case OpenWorldDomain::Matching:
      return "matching";
    case OpenWorldDomain::Thermal:
      break;
  }
  return "thermal";
}

std::vector<OpenWorldCaseInfo> openWorldCases(OpenWorldDomain domain) {
  using K = OpenCaseKind;
  std::vector<OpenWorldCaseInfo> c;
  switch (domain) {
    case OpenWorldDomain::Thermal:
      c = {{"sensor_rezero", K::Effect, "step"},
           {"coolant_cycle", K::Effect, "periodic"},
           {"quadratic_T2", K::Effect, "smooth"},
           {"centrifugal_rpm", K::Effect, "smooth"},
           {"outlier_spike", K::Outlier, "spike"}};
      break;
    case OpenWorldDomain::Kinematic:
      c = {{"thermal_drift", K::Effect, "smooth"},    {"reversal_spike", K::Effect, "smooth"},
           {"straightness_bow", K::Effect, "smooth"}, {"scale_damage", K::Effect, "block"},
           {"local_bump", K::Effect, "smooth"},       {"outlier_point", K::Outlier, "spike"}};
      break;
    case OpenWorldDomain::Setup:
      c = {{"reclamp_step", K::Effect, "step"},
           {"fixture_alternation", K::Effect, "level"},
           {"dimension_wear", K::Effect, "smooth"},
           {"tool_runin", K::Effect, "smooth"},
           {"outlier_row", K::Outlier, "spike"}};
      break;
    case OpenWorldDomain::Matching:
      c = {{"surface_bow", K::Effect, "smooth"},
           {"plate_bending", K::Effect, "smooth"},
           {"probe_lobing", K::Effect, "periodic"},
           {"surface_tilt", K::Effect, "smooth"},
           {"outlier_point", K::Outlier, "spike"}};
      break;
  }
  for (const char* clean : {"clean_gauss", "clean_laplace", "clean_t5"}) c.push_back({clean, K::Clean, ""});
  return c;
}

// ---- thermal --------------------------------------------------------------------------------------

OpenThermalCase openWorldThermal(const std::string& name, double ratio, std::uint64_t seed,
                                 const OpenWorldOptions& o) {
  ThermalEffectsOptions base;  // the declared model exact, no effect, no noise
  base.seed = seed;
  base.noiseUm = 0.0;
  // centrifugal_rpm: a stepped speed programme (seven speeds, each in both halves of the log), so
  // that a function of the speed has a shape and not just two levels.
  if (name == "centrifugal_rpm")
    base.sensors.programme = {{0.0, 0.0},      {10.0, 1500.0},  {40.0, 3000.0},  {70.0, 4500.0},
                              {100.0, 6000.0}, {130.0, 7500.0}, {160.0, 9000.0}, {190.0, 4500.0},
                              {220.0, 7500.0}, {250.0, 3000.0}, {280.0, 6000.0}, {310.0, 1500.0},
                              {340.0, 9000.0}, {370.0, 0.0},    {420.0, 4500.0}};
  OpenThermalCase out;
  out.log = simulateThermalEffects(base);
  out.target = base.target;
  out.inputs = base.declaredInputs;
  const std::size_t n = out.log.rows();
  const auto N = static_cast<Eigen::Index>(n);
  Draft d = startDraft(OpenWorldDomain::Thermal, name, ratio, o, kThermalSigmaUm, N);
  d.declared.resize(N, static_cast<Eigen::Index>(out.inputs.size()) + 1);
  d.declared.col(0).setOnes();
  for (std::size_t j = 0; j < out.inputs.size(); ++j) {
    const std::vector<double>& x = out.log.channel(out.inputs[j]).values;
    d.declared.col(static_cast<Eigen::Index>(j) + 1) = Eigen::Map<const Eigen::VectorXd>(x.data(), N);
  }
  const std::vector<double>& t = out.log.timeMin;
  const double t0 = t.front(), span = t.back() - t.front();
  Rng rng(seed ^ kEffectStream);
  OpenWorldTruth& tr = d.truth;
  if (name == "sensor_rezero") {
    const double ts = t0 + span * rng.uniform(0.25, 0.75);
    tr.position = (ts - t0) / span;
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k) d.shape(static_cast<Eigen::Index>(k)) = t[k] >= ts ? sign : 0.0;
    tr.against = {"time", "row"};
    tr.description = fmt("step of the target at t = %.1f min, sign %+.0f", ts - t0, sign);
  } else if (name == "coolant_cycle") {
    const double period = rng.uniform(30.0, 60.0), phase = rng.uniform(0.0, 2.0 * kPi);
    for (std::size_t k = 0; k < n; ++k)
      d.shape(static_cast<Eigen::Index>(k)) = std::sin(2.0 * kPi * (t[k] - t0) / period + phase);
    tr.against = {"time", "row"};
    tr.description = fmt("sine of period %.1f min, phase %.0f deg", period, phase * 180.0 / kPi);
  } else if (name == "quadratic_T2") {
    const std::vector<double>& x = out.log.channel("T2").values;
    double range = 0.0;
    for (double v : x) range = std::max(range, std::abs(v - x.front()));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double u = (x[k] - x.front()) / range;
      d.shape(static_cast<Eigen::Index>(k)) = sign * u * u;
    }
    tr.against = {"T2"};
    tr.description = fmt("%+.0f ((T2 - T2_0) / %.2f K)^2", sign, range);
  } else if (name == "centrifugal_rpm") {
    const std::vector<double>& x = out.log.channel("spindle_rpm").values;
    double top = 0.0;
    for (double v : x) top = std::max(top, std::abs(v));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double u = x[k] / top;
      d.shape(static_cast<Eigen::Index>(k)) = sign * u * u;
    }
    tr.against = {"spindle_rpm"};
    tr.description = fmt("centrifugal growth %+.0f (rpm / %.0f)^2", sign, top);
  } else if (name == "outlier_spike") {
    const std::size_t k = static_cast<std::size_t>(rng.below(n));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    d.shape(static_cast<Eigen::Index>(k)) = sign;
    tr.outlierUnit = k;
    tr.position = static_cast<double>(k) / static_cast<double>(n - 1);
    tr.outlierRow = static_cast<long>(k) + 1;
    tr.description = fmt("gross error of sign %+.0f at data row %.0f", sign, static_cast<double>(k + 1));
  }
  const Eigen::VectorXd added = finish(d, seed, o);
  std::vector<double>& y = out.log.channels[static_cast<std::size_t>(out.log.indexOf(out.target))].values;
  for (std::size_t k = 0; k < n; ++k) y[k] += added(static_cast<Eigen::Index>(k));
  if (tr.kind != OpenCaseKind::Clean) tr.description += fmt(", amplitude %.4g um", tr.amplitude);
  out.log.source = "simulated open-world thermal case '" + name + "'";
  out.truth = std::move(tr);
  return out;
}

// ---- kinematic ------------------------------------------------------------------------------------

OpenKinematicCase openWorldKinematic(const std::string& name, double ratio, std::uint64_t seed,
                                     const OpenWorldOptions& o) {
  CircularSimOptions c;
  c.seed = seed;
  c.noiseMm = 0.0;
  OpenKinematicCase out;
  out.path = simulateCircularTest(c);
  const std::vector<Eigen::Vector2d>& cmd = out.path.command;
  const std::size_t n = cmd.size();
  const auto N = static_cast<Eigen::Index>(2 * n);
  Draft d = startDraft(OpenWorldDomain::Kinematic, name, ratio, o, kKinematicSigmaMm, N);
  d.declared = Eigen::MatrixXd::Zero(N, 4);
  for (std::size_t k = 0; k < n; ++k) {
    const auto ix = static_cast<Eigen::Index>(2 * k), iy = ix + 1;
    d.declared(ix, 0) = 1.0;          // origin x
    d.declared(iy, 1) = 1.0;          // origin y
    d.declared(iy, 2) = cmd[k].x();   // X axis orientation a
    d.declared(ix, 3) = -cmd[k].y();  // Y axis orientation b
  }
  auto set = [&](std::size_t k, const Eigen::Vector2d& v) {
    d.shape(static_cast<Eigen::Index>(2 * k)) = v.x();
    d.shape(static_cast<Eigen::Index>(2 * k + 1)) = v.y();
  };
  Rng rng(seed ^ kEffectStream);
  OpenWorldTruth& tr = d.truth;
  if (name == "thermal_drift") {
    const double theta = rng.uniform(0.0, 2.0 * kPi);
    const Eigen::Vector2d u(std::cos(theta), std::sin(theta));
    const double tau = 0.5 * static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k) set(k, (1.0 - std::exp(-static_cast<double>(k) / tau)) * u);
    tr.against = {"time", "row"};
    tr.description = fmt("offset growing as 1 - exp(-row / %.0f) along %.0f deg", tau, theta * 180.0 / kPi);
  } else if (name == "reversal_spike") {
    const double L = rng.uniform(2.0, 5.0);
    const PathMotion m = pathMotion(cmd);
    for (int axis = 0; axis < 2; ++axis) {
      long since = -1;  // no reversal yet
      for (std::size_t k = 0; k < n; ++k) {
        if (k > 0 && m.direction[k](axis) != m.direction[k - 1](axis)) since = 0;
        if (since >= 0) {
          d.shape(static_cast<Eigen::Index>(2 * k) + axis) =
              -m.direction[k](axis) * std::exp(-static_cast<double>(since) / L);
          ++since;
        }
      }
    }
    tr.against = {"reversal", "angle"};
    tr.description = fmt("spike after every axis reversal decaying over %.2f samples", L);
  } else if (name == "straightness_bow") {
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double u = (cmd[k].x() - c.centreMm.x()) / c.radiusMm;
      set(k, Eigen::Vector2d(0.0, sign * u * u));
    }
    tr.against = {"x", "y", "angle"};
    tr.description = fmt("X guideway bow: y %+.0f ((x - cx) / R)^2", sign);
  } else if (name == "scale_damage") {
    // A damaged stretch of the X scale: the X reading is off by A while the head is over it. The
    // stretch is the x range of ten consecutive points of the first loop's upper half (path points
    // k0 .. k0 + 9, one point per 360 / n deg), so every pass over it, upper and lower half of both
    // loops, has ten consecutive points off.
    const double step = 360.0 / static_cast<double>(c.pointsPerLoop);
    const auto k0 = static_cast<long>(20.0 / step) +
                    static_cast<long>(rng.below(static_cast<std::uint64_t>(std::max(1.0, 130.0 / step))));
    const double a0 = (c.startAngleDeg + (static_cast<double>(k0) - 0.5) * step) * kPi / 180.0;
    const double a1 = (c.startAngleDeg + (static_cast<double>(k0) + 9.5) * step) * kPi / 180.0;
    const double xHi = c.centreMm.x() + c.radiusMm * std::cos(a0);
    const double xLo = c.centreMm.x() + c.radiusMm * std::cos(a1);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k)
      if (cmd[k].x() > xLo && cmd[k].x() < xHi) {
        set(k, Eigen::Vector2d(sign, 0.0));
        tr.blockUnits.push_back(k);
        tr.blockRows.push_back(static_cast<long>(k) + 1);
      }
    d.sigmasPerRatio = 24.0 / 5.0;  // 24 sigma at the default ratio 5
    tr.against = {"x", "angle", "row"};
    tr.description = fmt("damaged X scale over x %.2f .. %.2f mm, sign %+.0f", xLo, xHi, sign) +
                     fmt(", %.0f points", static_cast<double>(tr.blockUnits.size()));
  } else if (name == "local_bump") {
    // A worn spot of the X ball screw: the X error rises and falls over a short stretch of x, a bump
    // exp(-((x - x0) / w)^2 / 2) with w = 8 % of R at x0 uniform within +-0.6 R of the centre.
    const double x0 = c.centreMm.x() + c.radiusMm * rng.uniform(-0.6, 0.6), w = 0.08 * c.radiusMm;
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double u = (cmd[k].x() - x0) / w;
      set(k, Eigen::Vector2d(sign * std::exp(-0.5 * u * u), 0.0));
    }
    tr.against = {"x", "angle"};
    tr.description = fmt("X error bump at x = %.1f mm, width %.1f mm, sign %+.0f", x0, w, sign);
  } else if (name == "outlier_point") {
    const std::size_t k = static_cast<std::size_t>(rng.below(n));
    const double theta = rng.uniform(0.0, 2.0 * kPi);
    set(k, Eigen::Vector2d(std::cos(theta), std::sin(theta)));
    tr.outlierUnit = k;
    tr.position = static_cast<double>(k) / static_cast<double>(n - 1);
    tr.outlierRow = static_cast<long>(k) + 1;
    tr.description =
        fmt("gross error at data row %.0f along %.0f deg", static_cast<double>(k + 1), theta * 180.0 / kPi);
  }
  const Eigen::VectorXd added = finish(d, seed, o);
  for (std::size_t k = 0; k < n; ++k)
    out.path.measured[k] +=
        Eigen::Vector2d(added(static_cast<Eigen::Index>(2 * k)), added(static_cast<Eigen::Index>(2 * k + 1)));
  if (tr.kind != OpenCaseKind::Clean) tr.description += fmt(", amplitude %.4g mm", tr.amplitude);
  out.path.source = "simulated open-world circular test '" + name + "'";
  out.truth = std::move(tr);
  return out;
}

// ---- setup ----------------------------------------------------------------------------------------

OpenSetupCase openWorldSetup(const setup::Model& model, const std::string& name, double ratio,
                             std::uint64_t seed, const OpenWorldOptions& o) {
  if (o.setupParts < 4) fail("setup_parts", "at least 4 parts are needed");
  SetupEffectsSimOptions so;
  so.base.w2 = 0.0;
  so.base.resolutionMm = 0.0;
  so.base.parts = o.setupParts;
  so.base.minutesPerPart = 12.0;
  so.base.seed = seed;
  so.timeJitter = 0.5;
  OpenSetupCase out;
  out.measurements =
      setup::cmmReportFromCsv(parseCsv(simulateSetupEffectsReport(model, so), "simulated report"), model);
  setup::Measurements& m = out.measurements;
  const std::size_t n = m.rows.size();
  const auto N = static_cast<Eigen::Index>(n);
  const Eigen::MatrixXd G = setup::gainMatrix(model);
  Draft d = startDraft(OpenWorldDomain::Setup, name, ratio, o, kSetupSigmaMm, N);
  d.declared.resize(N, G.cols());
  for (std::size_t r = 0; r < n; ++r)
    d.declared.row(static_cast<Eigen::Index>(r)) = G.row(static_cast<Eigen::Index>(m.rows[r].dimension));
  // Part number of every row: the position of its part in order of appearance (1-based).
  std::vector<int> partNo(n);
  for (std::size_t r = 0; r < n; ++r)
    partNo[r] =
        static_cast<int>(std::find(m.parts.begin(), m.parts.end(), m.rows[r].part) - m.parts.begin()) + 1;
  const int P = static_cast<int>(m.parts.size());
  auto reaches = [&](Eigen::Index i) {
    std::vector<std::string> dims;
    for (Eigen::Index q = 0; q < G.rows(); ++q)
      if (G(q, i) != 0.0) dims.push_back("dimension:" + model.dimensions[static_cast<std::size_t>(q)].id);
    return dims;
  };
  auto pickDatum = [&](Rng& rng, bool wksOnly) {
    std::vector<Eigen::Index> ok;
    for (Eigen::Index i = 0; i < G.cols(); ++i)
      if (G.col(i).cwiseAbs().maxCoeff() > 0.0 &&
          (!wksOnly || model.setup[static_cast<std::size_t>(i)].kind == setup::DatumKind::Wks))
        ok.push_back(i);
    if (ok.empty()) fail("model", "no setup datum of the model reaches a dimension");
    return ok[rng.below(ok.size())];
  };
  Rng rng(seed ^ kEffectStream);
  OpenWorldTruth& tr = d.truth;
  if (name == "reclamp_step") {
    const Eigen::Index i = pickDatum(rng, false);
    const int pStar = P / 4 + static_cast<int>(rng.below(static_cast<std::uint64_t>(3 * P / 4 - P / 4 + 1)));
    tr.position = static_cast<double>(pStar - 1) / static_cast<double>(P - 1);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t r = 0; r < n; ++r)
      if (partNo[r] >= pStar)
        d.shape(static_cast<Eigen::Index>(r)) = sign * G(static_cast<Eigen::Index>(m.rows[r].dimension), i);
    tr.against = {"part", "time", "row"};
    for (auto& s : reaches(i)) tr.against.push_back(s);
    tr.description = "setup datum " + model.setup[static_cast<std::size_t>(i)].id +
                     fmt(" steps (sign %+.0f) from part %.0f", sign, pStar);
  } else if (name == "fixture_alternation") {
    bool anyWks = false;
    for (Eigen::Index i = 0; i < G.cols(); ++i)
      anyWks |= model.setup[static_cast<std::size_t>(i)].kind == setup::DatumKind::Wks &&
                G.col(i).cwiseAbs().maxCoeff() > 0.0;
    const Eigen::Index i = pickDatum(rng, anyWks);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t r = 0; r < n; ++r)
      if (partNo[r] % 2 == 0)
        d.shape(static_cast<Eigen::Index>(r)) = sign * G(static_cast<Eigen::Index>(m.rows[r].dimension), i);
    tr.against = {"part", "row"};
    for (auto& s : reaches(i)) tr.against.push_back(s);
    tr.description = "even parts in fixture B, its locator off on " +
                     model.setup[static_cast<std::size_t>(i)].id + fmt(" (sign %+.0f)", sign);
  } else if (name == "dimension_wear") {
    const std::size_t q = static_cast<std::size_t>(rng.below(model.dimensions.size()));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t r = 0; r < n; ++r)
      if (m.rows[r].dimension == q) {
        const double u = static_cast<double>(partNo[r] - 1) / static_cast<double>(P - 1);
        d.shape(static_cast<Eigen::Index>(r)) = sign * u * u;
      }
    tr.against = {"dimension:" + model.dimensions[q].id, "part", "time", "row"};
    tr.description =
        "dimension " + model.dimensions[q].id + fmt(" wears as %+.0f ((p - 1) / (P - 1))^2", sign);
  } else if (name == "tool_runin") {
    // A new tool runs in: its effective length changes fast over the first parts and then settles,
    // 1 - exp(-(p - 1) / p0) with p0 uniform in [1.5, 3] parts (tool_wear is a constant rate).
    std::vector<Eigen::Index> tools;
    for (Eigen::Index i = 0; i < G.cols(); ++i)
      if (model.setup[static_cast<std::size_t>(i)].kind == setup::DatumKind::Tool &&
          G.col(i).cwiseAbs().maxCoeff() > 0.0)
        tools.push_back(i);
    const Eigen::Index i = tools.empty() ? pickDatum(rng, false) : tools[rng.below(tools.size())];
    const double p0 = rng.uniform(1.5, 3.0);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t r = 0; r < n; ++r)
      d.shape(static_cast<Eigen::Index>(r)) = sign * G(static_cast<Eigen::Index>(m.rows[r].dimension), i) *
                                              (1.0 - std::exp(-static_cast<double>(partNo[r] - 1) / p0));
    const std::string id = model.setup[static_cast<std::size_t>(i)].id;
    tr.against = {"datum:" + id, "part", "time", "row"};
    for (auto& s2 : reaches(i)) tr.against.push_back(s2);
    tr.description = "tool " + id + fmt(" runs in as %+.0f (1 - exp(-(p - 1) / %.2f))", sign, p0);
  } else if (name == "outlier_row") {
    const std::size_t r = static_cast<std::size_t>(rng.below(n));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    d.shape(static_cast<Eigen::Index>(r)) = sign;
    tr.outlierUnit = r;
    tr.position = static_cast<double>(r) / static_cast<double>(n - 1);
    tr.outlierRow = static_cast<long>(r) + 1;
    tr.outlierPart = m.rows[r].part;
    tr.outlierDimension = model.dimensions[m.rows[r].dimension].id;
    tr.description = "gross error (sign " + std::string(sign > 0 ? "+" : "-") + ") at part " +
                     tr.outlierPart + ", dimension " + tr.outlierDimension;
  }
  const Eigen::VectorXd added = finish(d, seed, o);
  std::vector<double> sum(model.dimensions.size(), 0.0);
  for (std::size_t r = 0; r < n; ++r) {
    m.rows[r].deviationMm += added(static_cast<Eigen::Index>(r));
    sum[m.rows[r].dimension] += m.rows[r].deviationMm;
  }
  for (std::size_t q = 0; q < sum.size(); ++q)
    if (m.samples[q] > 0) m.deviationMm[q] = sum[q] / m.samples[q];
  if (tr.kind != OpenCaseKind::Clean) tr.description += fmt(", amplitude %.4g mm", tr.amplitude);
  out.truth = std::move(tr);
  return out;
}

// ---- matching -------------------------------------------------------------------------------------

OpenMatchingCase openWorldMatching(const std::string& name, double ratio, std::uint64_t seed,
                                   const OpenWorldOptions& o) {
  ProbeSimOptions ps = ProbeSimOptions::sPieceDefaults();
  ps.seed = seed;
  ps.noiseMm = 0.0;
  OpenMatchingCase out;
  out.points = simulateProbing(ps);
  std::vector<ProbePoint>& pts = out.points.points;
  const std::size_t n = pts.size();
  const auto N = static_cast<Eigen::Index>(n);
  Draft d = startDraft(OpenWorldDomain::Matching, name, ratio, o, kMatchingSigmaMm, N);
  d.declared.resize(N, 6);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& q = pts[i].nominal;
    const Eigen::Vector3d& nn = pts[i].normal;
    d.declared.row(static_cast<Eigen::Index>(i)) << nn.transpose(), q.cross(nn).transpose();
  }
  Rng rng(seed ^ kEffectStream);
  OpenWorldTruth& tr = d.truth;
  if (name == "surface_bow") {
    const SurfaceSpan span = pickSurface(rng, pts);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    double mean = 0.0;
    for (std::size_t i : span.points) {
      const double u = span.u(pts[i]);
      d.shape(static_cast<Eigen::Index>(i)) = u * u;
      mean += u * u / static_cast<double>(span.points.size());
    }
    for (std::size_t i : span.points)
      d.shape(static_cast<Eigen::Index>(i)) = sign * (d.shape(static_cast<Eigen::Index>(i)) - mean);
    tr.against = {"surface:" + span.name};
    tr.description = "bow of surface " + span.name + " along " + std::string(1, "xyz"[span.axis]) +
                     fmt(", sign %+.0f", sign);
  } else if (name == "plate_bending") {
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double u = (pts[i].nominal.x() - 160.0) / 160.0;
      d.shape(static_cast<Eigen::Index>(i)) = sign * pts[i].normal.z() * u * u;
    }
    tr.against = {"x", "surface:plane"};
    tr.description = fmt("base plate bent: z %+.0f ((x - 160) / 160)^2", sign);
  } else if (name == "probe_lobing") {
    const double phi0 = rng.uniform(0.0, 2.0 * kPi / 3.0);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d& nn = pts[i].normal;
      const double h = std::hypot(nn.x(), nn.y());
      const double phi = std::atan2(nn.y(), nn.x());
      d.shape(static_cast<Eigen::Index>(i)) = h > 0.0 ? -h * std::cos(3.0 * (phi - phi0)) : 0.0;
    }
    tr.against = {"normal", "direction", "nx", "ny"};
    tr.description = fmt("three-lobed probe pre-travel, lobe at %.0f deg", phi0 * 180.0 / kPi);
  } else if (name == "surface_tilt") {
    // One surface is machined tilted (a worn fixture face): its deviation along the normal grows
    // linearly along its longest extent, A u with u in [-1, 1] and zero mean on the surface (its
    // offset is the catalogue's surface_offset; the tilt is what no entry models).
    const SurfaceSpan span = pickSurface(rng, pts);
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    double mean = 0.0;
    for (std::size_t i : span.points) mean += span.u(pts[i]) / static_cast<double>(span.points.size());
    for (std::size_t i : span.points) d.shape(static_cast<Eigen::Index>(i)) = sign * (span.u(pts[i]) - mean);
    tr.against = {"surface:" + span.name};
    tr.description = "tilt of surface " + span.name + " along " + std::string(1, "xyz"[span.axis]) +
                     fmt(", sign %+.0f", sign);
  } else if (name == "outlier_point") {
    const std::size_t i = static_cast<std::size_t>(rng.below(n));
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    d.shape(static_cast<Eigen::Index>(i)) = sign;
    tr.outlierUnit = i;
    tr.position = static_cast<double>(i) / static_cast<double>(n - 1);
    tr.outlierRow = static_cast<long>(i) + 1;
    tr.outlierId = pts[i].id;
    tr.description = "gross error (sign " + std::string(sign > 0 ? "+" : "-") + ") at point " + pts[i].id;
  }
  const Eigen::VectorXd added = finish(d, seed, o);
  const Eigen::Matrix3d R = rotationFromDeg(ps.rotationDeg[0], ps.rotationDeg[1], ps.rotationDeg[2]);
  for (std::size_t i = 0; i < n; ++i)
    pts[i].measured += R * pts[i].normal * added(static_cast<Eigen::Index>(i));
  if (tr.kind != OpenCaseKind::Clean) tr.description += fmt(", amplitude %.4g mm", tr.amplitude);
  out.points.source = "simulated open-world probing '" + name + "'";
  out.truth = std::move(tr);
  return out;
}

}  // namespace metrofit
