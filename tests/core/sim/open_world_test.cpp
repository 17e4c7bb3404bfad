// The open-world cases of core/sim/open_world.h: the effect-to-noise ratio is what was asked
// (measured here on the data against the clean data of the same seed, with the declared model's
// columns rebuilt independently), determinism by seed, the noise distributions, the gross errors.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <Eigen/Dense>
#include <boost/math/distributions/students_t.hpp>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/kinematics/cartesian_model.h"
#include "core/sim/circular_sim.h"
#include "core/sim/open_world.h"
#include "core/sim/probe_sim.h"
#include "testsupport.h"

namespace metrofit {
namespace {

const setup::Model& paperModel() {
  static const setup::Model m =
      setup::readModel((test::sourceDir() / "resources/demo/setup/paper_example.json").string());
  return m;
}

double rmsOf(const Eigen::VectorXd& v) {
  return std::sqrt(v.squaredNorm() / static_cast<double>(v.size()));
}

Eigen::VectorXd offColumns(const Eigen::MatrixXd& D, const Eigen::VectorXd& v) {
  return v - D * D.jacobiSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(v);
}

// Observations and declared columns of each domain, rebuilt from the public data structures.
struct Obs {
  Eigen::VectorXd y;
  Eigen::MatrixXd D;
};

Obs thermalObs(const OpenThermalCase& c) {
  const auto n = static_cast<Eigen::Index>(c.log.rows());
  Obs o;
  o.y = Eigen::Map<const Eigen::VectorXd>(c.log.channel(c.target).values.data(), n);
  o.D.resize(n, 1 + static_cast<Eigen::Index>(c.inputs.size()));
  o.D.col(0).setOnes();
  for (std::size_t j = 0; j < c.inputs.size(); ++j)
    o.D.col(static_cast<Eigen::Index>(j) + 1) =
        Eigen::Map<const Eigen::VectorXd>(c.log.channel(c.inputs[j]).values.data(), n);
  return o;
}

Obs kinematicObs(const OpenKinematicCase& c) {
  const auto n = static_cast<Eigen::Index>(c.path.size());
  Obs o;
  o.y.resize(2 * n);
  o.D = Eigen::MatrixXd::Zero(2 * n, 4);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector2d& q = c.path.command[static_cast<std::size_t>(k)];
    o.y.segment<2>(2 * k) = c.path.measured[static_cast<std::size_t>(k)];
    o.D(2 * k, 0) = 1.0;
    o.D(2 * k + 1, 1) = 1.0;
    o.D(2 * k + 1, 2) = q.x();
    o.D(2 * k, 3) = -q.y();
  }
  return o;
}

Obs setupObs(const OpenSetupCase& c) {
  const Eigen::MatrixXd G = setup::gainMatrix(paperModel());
  const auto n = static_cast<Eigen::Index>(c.measurements.rows.size());
  Obs o;
  o.y.resize(n);
  o.D.resize(n, G.cols());
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto& row = c.measurements.rows[static_cast<std::size_t>(r)];
    o.y(r) = row.deviationMm;
    o.D.row(r) = G.row(static_cast<Eigen::Index>(row.dimension));
  }
  return o;
}

Obs matchingObs(const OpenMatchingCase& c) {
  const ProbeSimOptions s = ProbeSimOptions::sPieceDefaults();
  const Eigen::Matrix3d R = rotationFromDeg(s.rotationDeg[0], s.rotationDeg[1], s.rotationDeg[2]);
  const Eigen::Vector3d t(s.translationMm[0], s.translationMm[1], s.translationMm[2]);
  const auto n = static_cast<Eigen::Index>(c.points.points.size());
  Obs o;
  o.y.resize(n);
  o.D.resize(n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const ProbePoint& p = c.points.points[static_cast<std::size_t>(i)];
    const Eigen::Vector3d rn = R * p.normal, rq = R * p.nominal + t;
    o.y(i) = rn.dot(p.measured - rq);
    o.D.row(i) << rn.transpose(), rq.cross(rn).transpose();
  }
  return o;
}

template <class Make, class ToObs>
void checkDomain(OpenWorldDomain domain, Make make, ToObs toObs) {
  const double ratio = 5.0;
  for (const OpenWorldCaseInfo& info : openWorldCases(domain)) {
    SCOPED_TRACE(std::string(toString(domain)) + " " + info.name);
    for (std::uint64_t seed : {3u, 17u}) {
      const auto c = make(info.name, ratio, seed);
      const auto clean = make("clean_gauss", ratio, seed);
      const Obs a = toObs(c), b = toObs(clean);
      ASSERT_EQ(a.y.size(), b.y.size());
      const Eigen::VectorXd diff = a.y - b.y;
      const double sigma = c.truth.noiseSigma;
      ASSERT_GT(sigma, 0.0);
      EXPECT_EQ(c.truth.caseName, info.name);
      EXPECT_EQ(c.truth.form, info.form);
      if (info.kind == OpenCaseKind::Clean) {
        EXPECT_EQ(c.truth.amplitude, 0.0);
        EXPECT_TRUE(c.truth.against.empty());
        if (info.name == "clean_gauss") {
          EXPECT_EQ(diff.cwiseAbs().maxCoeff(), 0.0);
        } else {
          // Other noise, same sigma: the difference is noise of rms about sigma sqrt 2.
          EXPECT_NEAR(rmsOf(diff) / (sigma * std::sqrt(2.0)), 1.0, 0.45);
        }
        continue;
      }
      EXPECT_EQ(c.truth.ratio, ratio);
      if (info.kind == OpenCaseKind::Effect && info.form == "block") {
        // A block of points (scale_damage): the case states the block's size, 24 sigma at ratio 5
        // (A = 4.8 ratio sigma), not its visible rms; the difference to clean data is the block alone.
        EXPECT_NEAR(c.truth.amplitude / sigma, 24.0 / 5.0 * ratio, 1e-9 * ratio);
        EXPECT_NEAR(c.truth.effectRms, rmsOf(diff), 1e-9 * rmsOf(diff) + 1e-15);
        EXPECT_GT(c.truth.visibleRms, 0.0);
        ASSERT_FALSE(c.truth.against.empty());
      } else if (info.kind == OpenCaseKind::Effect && !a.D.isApprox(b.D)) {
        // The case runs its own programme (centrifugal_rpm: seven spindle speeds), so its declared
        // inputs are not the clean log's and (data - clean data) is not the effect: the truth's own
        // figures are checked.
        EXPECT_NEAR(c.truth.visibleRms / sigma, ratio, 1e-9 * ratio);
        EXPECT_GE(c.truth.effectRms, c.truth.visibleRms * (1.0 - 1e-9));
        ASSERT_FALSE(c.truth.against.empty());
      } else if (info.kind == OpenCaseKind::Effect) {
        // The asked ratio, measured: the part of (data - clean data) the declared model cannot absorb.
        EXPECT_NEAR(rmsOf(offColumns(a.D, diff)) / sigma, ratio, 1e-6 * ratio);
        EXPECT_NEAR(c.truth.visibleRms / sigma, ratio, 1e-9 * ratio);
        EXPECT_NEAR(c.truth.effectRms, rmsOf(diff), 1e-9 * rmsOf(diff) + 1e-15);
        EXPECT_GE(c.truth.effectRms, c.truth.visibleRms * (1.0 - 1e-9));
        ASSERT_FALSE(c.truth.against.empty());
        EXPECT_FALSE(c.truth.outlierUnit.has_value());
      } else {
        // One unit off by the gross error, every other observation unchanged.
        ASSERT_TRUE(c.truth.outlierUnit.has_value());
        ASSERT_TRUE(c.truth.outlierRow.has_value());
        EXPECT_EQ(*c.truth.outlierRow, static_cast<long>(*c.truth.outlierUnit) + 1);
        ASSERT_TRUE(c.truth.position.has_value());
        const auto units = static_cast<double>(a.y.size() / (domain == OpenWorldDomain::Kinematic ? 2 : 1));
        EXPECT_DOUBLE_EQ(*c.truth.position, static_cast<double>(*c.truth.outlierUnit) / (units - 1.0));
        const double gross = 6.0 * ratio * sigma;
        const Eigen::Index per = domain == OpenWorldDomain::Kinematic ? 2 : 1;
        const Eigen::Index u = static_cast<Eigen::Index>(*c.truth.outlierUnit) * per;
        EXPECT_NEAR(diff.segment(u, per).norm(), gross, 1e-9 * gross);
        Eigen::VectorXd rest = diff;
        rest.segment(u, per).setZero();
        EXPECT_LT(rest.cwiseAbs().maxCoeff(), 1e-12 * gross);
      }
    }
  }
}

TEST(OpenWorld, ThermalRatioIsWhatWasAsked) {
  checkDomain(
      OpenWorldDomain::Thermal,
      [](const std::string& n, double r, std::uint64_t s) { return openWorldThermal(n, r, s); }, thermalObs);
}

TEST(OpenWorld, KinematicRatioIsWhatWasAsked) {
  checkDomain(
      OpenWorldDomain::Kinematic,
      [](const std::string& n, double r, std::uint64_t s) { return openWorldKinematic(n, r, s); },
      kinematicObs);
}

TEST(OpenWorld, SetupRatioIsWhatWasAsked) {
  checkDomain(
      OpenWorldDomain::Setup,
      [](const std::string& n, double r, std::uint64_t s) { return openWorldSetup(paperModel(), n, r, s); },
      setupObs);
}

TEST(OpenWorld, MatchingRatioIsWhatWasAsked) {
  checkDomain(
      OpenWorldDomain::Matching,
      [](const std::string& n, double r, std::uint64_t s) { return openWorldMatching(n, r, s); },
      matchingObs);
}

TEST(OpenWorld, RatioScalesTheEffect) {
  const auto a = openWorldThermal("sensor_rezero", 2.0, 5), b = openWorldThermal("sensor_rezero", 8.0, 5);
  EXPECT_NEAR(b.truth.amplitude / a.truth.amplitude, 4.0, 1e-9);
  EXPECT_NEAR(b.truth.visibleRms / b.truth.noiseSigma, 8.0, 1e-9);
}

TEST(OpenWorld, DeterministicBySeed) {
  for (const auto& info : openWorldCases(OpenWorldDomain::Kinematic)) {
    const auto a = openWorldKinematic(info.name, 5.0, 9), b = openWorldKinematic(info.name, 5.0, 9),
               c = openWorldKinematic(info.name, 5.0, 10);
    EXPECT_EQ(measuredPathToCsv(a.path), measuredPathToCsv(b.path)) << info.name;
    EXPECT_NE(measuredPathToCsv(a.path), measuredPathToCsv(c.path)) << info.name;
    EXPECT_EQ(a.truth.description, b.truth.description);
  }
  for (const auto& info : openWorldCases(OpenWorldDomain::Thermal)) {
    const auto a = openWorldThermal(info.name, 5.0, 9), b = openWorldThermal(info.name, 5.0, 9),
               c = openWorldThermal(info.name, 5.0, 10);
    EXPECT_EQ(thermalLogToCsv(a.log), thermalLogToCsv(b.log)) << info.name;
    EXPECT_NE(thermalLogToCsv(a.log), thermalLogToCsv(c.log)) << info.name;
  }
  for (const auto& info : openWorldCases(OpenWorldDomain::Matching)) {
    const auto a = openWorldMatching(info.name, 5.0, 9), b = openWorldMatching(info.name, 5.0, 9),
               c = openWorldMatching(info.name, 5.0, 10);
    EXPECT_EQ(probePointsToCsv(a.points), probePointsToCsv(b.points)) << info.name;
    EXPECT_NE(probePointsToCsv(a.points), probePointsToCsv(c.points)) << info.name;
  }
  for (const auto& info : openWorldCases(OpenWorldDomain::Setup)) {
    const auto a = openWorldSetup(paperModel(), info.name, 5.0, 9),
               b = openWorldSetup(paperModel(), info.name, 5.0, 9),
               c = openWorldSetup(paperModel(), info.name, 5.0, 10);
    ASSERT_EQ(a.measurements.rows.size(), b.measurements.rows.size());
    bool same = true, differs = false;
    for (std::size_t r = 0; r < a.measurements.rows.size(); ++r) {
      same &= a.measurements.rows[r].deviationMm == b.measurements.rows[r].deviationMm;
      differs |= a.measurements.rows[r].deviationMm != c.measurements.rows[r].deviationMm;
    }
    EXPECT_TRUE(same) << info.name;
    EXPECT_TRUE(differs) << info.name;
  }
}

// Moments of many draws with sigma 1.
struct Moments {
  double mean = 0, var = 0, kurtosis = 0;
  std::vector<double> x;
};
Moments draw(NoiseKind kind, int n, std::uint64_t seed) {
  Rng rng(seed);
  Moments m;
  m.x.resize(static_cast<std::size_t>(n));
  for (auto& v : m.x) v = drawNoise(rng, kind, 1.0);
  for (double v : m.x) m.mean += v / n;
  double m2 = 0, m4 = 0;
  for (double v : m.x) {
    const double d = v - m.mean;
    m2 += d * d / n;
    m4 += d * d * d * d / n;
  }
  m.var = m2;
  m.kurtosis = m4 / (m2 * m2);
  return m;
}

double tailFraction(const std::vector<double>& x, double q) {
  double k = 0;
  for (double v : x) k += std::abs(v) > q;
  return k / static_cast<double>(x.size());
}

TEST(OpenWorldNoise, GaussianMoments) {
  const Moments m = draw(NoiseKind::Gaussian, 400000, 1);
  EXPECT_NEAR(m.mean, 0.0, 0.01);
  EXPECT_NEAR(m.var, 1.0, 0.01);
  EXPECT_NEAR(m.kurtosis, 3.0, 0.05);
}

TEST(OpenWorldNoise, LaplaceMomentsAndTail) {
  const Moments m = draw(NoiseKind::Laplace, 400000, 2);
  EXPECT_NEAR(m.mean, 0.0, 0.01);
  EXPECT_NEAR(m.var, 1.0, 0.015);
  EXPECT_NEAR(m.kurtosis, 6.0, 0.25);
  // P(|x| > q) = exp(-q sqrt 2) for unit variance.
  for (double q : {1.0, 2.0, 4.0})
    EXPECT_NEAR(tailFraction(m.x, q) / std::exp(-q * std::sqrt(2.0)), 1.0, q < 3 ? 0.02 : 0.1) << q;
}

TEST(OpenWorldNoise, StudentT5Tail) {
  const Moments m = draw(NoiseKind::StudentT5, 400000, 3);
  EXPECT_NEAR(m.mean, 0.0, 0.01);
  EXPECT_NEAR(m.var, 1.0, 0.03);
  EXPECT_GT(m.kurtosis, 6.5);  // 9 in theory; the estimate converges slowly (infinite 8th moment)
  // Tails against the Student t(5) distribution of Boost.Math, scaled to unit variance.
  const boost::math::students_t t5(5.0);
  for (double q : {1.0, 2.0, 3.0, 5.0}) {
    const double expected = 2.0 * boost::math::cdf(boost::math::complement(t5, q / std::sqrt(3.0 / 5.0)));
    EXPECT_NEAR(tailFraction(m.x, q) / expected, 1.0, q < 4 ? 0.03 : 0.12) << q;
  }
}

TEST(OpenWorldNoise, CleanDataCarryTheNoiseAsked) {
  // The kinematic clean data minus the declared machine: pooled over seeds, the kurtosis of the noise.
  auto kurtosisOf = [](const std::string& name) {
    std::vector<double> r;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      const OpenKinematicCase c = openWorldKinematic(name, 1.0, seed);
      const auto exact = simulateMachine(CircularSimOptions::defaultErrors(), c.path.command, 0.0, seed);
      for (std::size_t k = 0; k < exact.size(); ++k)
        for (int a = 0; a < 2; ++a) r.push_back((c.path.measured[k](a) - exact[k](a)) / c.truth.noiseSigma);
    }
    double m2 = 0, m4 = 0;
    for (double v : r) {
      m2 += v * v / static_cast<double>(r.size());
      m4 += v * v * v * v / static_cast<double>(r.size());
    }
    return std::make_pair(m2, m4 / (m2 * m2));
  };
  const auto g = kurtosisOf("clean_gauss"), l = kurtosisOf("clean_laplace"), t = kurtosisOf("clean_t5");
  EXPECT_NEAR(g.first, 1.0, 0.03);
  EXPECT_NEAR(l.first, 1.0, 0.04);
  EXPECT_NEAR(t.first, 1.0, 0.08);
  EXPECT_NEAR(g.second, 3.0, 0.15);
  EXPECT_NEAR(l.second, 6.0, 0.6);
  EXPECT_GT(t.second, 5.5);
}

TEST(OpenWorld, TruthNamesContractVariables) {
  // The vocabulary of docs/file-formats.md#residual_check: T2 and spindle_rpm are columns of the log.
  const std::set<std::string> plain{"time", "row",    "angle", "direction", "reversal",    "x",  "y",
                                    "z",    "normal", "part",  "T2",        "spindle_rpm", "nx", "ny"};
  auto ok = [&](const std::string& a) {
    return plain.count(a) || a.rfind("surface:", 0) == 0 || a.rfind("dimension:", 0) == 0 ||
           a.rfind("datum:", 0) == 0;
  };
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    for (const auto& i : openWorldCases(OpenWorldDomain::Thermal))
      for (const auto& a : openWorldThermal(i.name, 3.0, seed).truth.against) EXPECT_TRUE(ok(a)) << a;
    for (const auto& i : openWorldCases(OpenWorldDomain::Kinematic))
      for (const auto& a : openWorldKinematic(i.name, 3.0, seed).truth.against) EXPECT_TRUE(ok(a)) << a;
    for (const auto& i : openWorldCases(OpenWorldDomain::Matching))
      for (const auto& a : openWorldMatching(i.name, 3.0, seed).truth.against) EXPECT_TRUE(ok(a)) << a;
    for (const auto& i : openWorldCases(OpenWorldDomain::Setup))
      for (const auto& a : openWorldSetup(paperModel(), i.name, 3.0, seed).truth.against)
        EXPECT_TRUE(ok(a)) << a;
  }
}

TEST(OpenWorld, StepIsAStepInTime) {
  const OpenThermalCase c = openWorldThermal("sensor_rezero", 5.0, 4);
  const OpenThermalCase clean = openWorldThermal("clean_gauss", 5.0, 4);
  const auto& y = c.log.channel(c.target).values;
  const auto& y0 = clean.log.channel(c.target).values;
  // Zero before the change, one constant after it, the change inside [0.25, 0.75] of the test.
  std::size_t first = y.size();
  for (std::size_t k = 0; k < y.size(); ++k)
    if (std::abs(y[k] - y0[k]) > 1e-12) {
      first = k;
      break;
    }
  ASSERT_LT(first, y.size());
  const double span = c.log.timeMin.back() - c.log.timeMin.front();
  EXPECT_GE(c.log.timeMin[first] - c.log.timeMin.front(), 0.25 * span - 1.0);
  EXPECT_LE(c.log.timeMin[first] - c.log.timeMin.front(), 0.75 * span + 1.0);
  for (std::size_t k = first; k < y.size(); ++k) EXPECT_NEAR(y[k] - y0[k], y[first] - y0[first], 1e-9);
  EXPECT_NEAR(std::abs(y[first] - y0[first]), c.truth.amplitude, 1e-9);
  ASSERT_TRUE(c.truth.position.has_value());
  EXPECT_NEAR(*c.truth.position * span, c.log.timeMin[first] - c.log.timeMin.front(), 1.0);
}

TEST(OpenWorld, ReversalSpikeDecays) {
  const OpenKinematicCase c = openWorldKinematic("reversal_spike", 5.0, 2);
  const OpenKinematicCase clean = openWorldKinematic("clean_gauss", 5.0, 2);
  // The CCW loop starts at angle 0: x moves -x until 180 deg and +x from there (the move into row
  // 181 is the first +x move); the spike is largest there and has decayed 40 samples later.
  const double before = std::abs(c.path.measured[180].x() - clean.path.measured[180].x());
  const double at = std::abs(c.path.measured[181].x() - clean.path.measured[181].x());
  const double later = std::abs(c.path.measured[221].x() - clean.path.measured[221].x());
  EXPECT_EQ(before, 0.0);
  EXPECT_NEAR(at, c.truth.amplitude, 1e-9);
  EXPECT_LT(later, 1e-3 * at);
}

TEST(OpenWorld, BadArgumentsAreOptionsErrors) {
  EXPECT_THROW(openWorldThermal("nope", 5.0, 1), OptionsError);
  EXPECT_THROW(openWorldKinematic("thermal_drift", 0.0, 1), OptionsError);
  EXPECT_NO_THROW(openWorldKinematic("clean_t5", 0.0, 1));
  OpenWorldOptions o;
  o.noiseSigma = -1.0;
  EXPECT_THROW(openWorldMatching("surface_bow", 5.0, 1, o), OptionsError);
  o = {};
  o.setupParts = 2;
  EXPECT_THROW(openWorldSetup(paperModel(), "reclamp_step", 5.0, 1, o), OptionsError);
}

}  // namespace
}  // namespace metrofit
