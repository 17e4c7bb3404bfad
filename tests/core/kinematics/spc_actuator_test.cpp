// SPC regression offset angle -> actuator errors -> compensation (core/kinematics/spc_actuator.h).
// Every reference is computed here from the kinematic-compensation paper's Eq. 9 written out in the test
// (never through CartesianMachine2 or the simulator): the measured edges, the injected errors, and the check
// that the compensated references land on the nominal path.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/spc_actuator.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Truth {
  double ox, oy, aDeg, bDeg;
};

/// Eq. 9 of the paper in the parametrisation of docs/file-formats.md#kinematic-identify-result, written out:
/// P = o + x (cos a, sin a) + y (-sin b, cos b).
void machine(const Truth& t, double x, double y, double* px, double* py) {
  const double a = t.aDeg * kDeg, b = t.bDeg * kDeg;
  *px = t.ox + x * std::cos(a) - y * std::sin(b);
  *py = t.oy + x * std::sin(a) + y * std::cos(b);
}

/// An edge along `axis` at the nominal cross coordinate c, n points over [-L/2, L/2], with
/// N(0, noise^2) on both measured coordinates (std::mt19937_64, not metrofit::Rng).
AxisFeatureSeries edge(const Truth& t, char axis, double c, int n, double noise, unsigned seed,
                       double length = 300.0) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<double> nd(0.0, noise > 0.0 ? noise : 1.0);
  AxisFeatureSeries s;
  s.source = std::string(1, axis) + "-edge.csv";
  s.nominalCrossMm = c;
  for (int k = 0; k < n; ++k) {
    const double u = -length / 2 + length * k / (n - 1);
    double px, py;
    if (axis == 'x') {
      machine(t, u, c, &px, &py);
    } else {
      machine(t, c, u, &px, &py);
    }
    if (noise > 0.0) {
      px += nd(gen);
      py += nd(gen);
    }
    s.positionMm.push_back(axis == 'x' ? px : py);
    s.deviationMm.push_back(axis == 'x' ? py - c : px - c);
  }
  return s;
}

TEST(SpcActuator, PaperFig11ErrorsComeBackExactlyFromNoiseFreeEdges) {
  // Fig. 11 (a): X actuator 10 deg, Y actuator 15 deg, both measured clockwise (negative here),
  // and actuators away from the origin; edges machined off the axes (y0 = 40, x0 = -25).
  const Truth t{1.5, -2.0, -10.0, -15.0};
  const auto xf = edge(t, 'x', 40.0, 20, 0.0, 1);
  const auto yf = edge(t, 'y', -25.0, 20, 0.0, 2);
  // Noise-free: the standard errors are at the rounding level, every parameter counts.
  const SpcActuatorResult r = actuatorErrorsFromSpc(xf, yf);
  EXPECT_NEAR(r.x.line.angleDeg, -10.0, 1e-9);  // the offset angle IS the X actuator angle
  EXPECT_NEAR(r.y.line.angleDeg, 15.0, 1e-9);   // = -b
  EXPECT_NEAR(r.errors.xAxisAngleDeg, -10.0, 1e-9);
  EXPECT_NEAR(r.errors.yAxisAngleDeg, -15.0, 1e-9);
  EXPECT_NEAR(r.errors.originMm.x(), 1.5, 1e-9);
  EXPECT_NEAR(r.errors.originMm.y(), -2.0, 1e-9);
  EXPECT_NEAR(r.errors.squarenessDeg(), -5.0, 1e-9);
  // Residuals at the rounding level are not charted (their limits would flag rounding noise).
  EXPECT_FALSE(r.x.residualChart.has_value());
  EXPECT_TRUE(r.apply) << r.reason;
}

TEST(SpcActuator, CompensatedReferencesLandOnTheNominalCircle) {
  const Truth t{0.02, -0.015, 0.004, -0.006};
  const SpcActuatorResult r =
      actuatorErrorsFromSpc(edge(t, 'x', 0.0, 60, 0.0002, 3), edge(t, 'y', 0.0, 60, 0.0002, 4));
  ASSERT_TRUE(r.apply) << r.reason;
  std::vector<Eigen::Vector2d> nominal;
  for (int k = 0; k < 72; ++k) {
    const double th = 2 * std::numbers::pi * k / 72;
    nominal.emplace_back(50.0 * std::cos(th), 50.0 * std::sin(th));
  }
  const auto refs = compensatePath(CartesianMachine2::fromErrors(r.errors), nominal);
  double before = 0.0, after = 0.0;
  for (std::size_t k = 0; k < nominal.size(); ++k) {
    double px, py;
    machine(t, nominal[k].x(), nominal[k].y(), &px, &py);  // uncompensated: the nominal as command
    before = std::max(before, std::hypot(px - nominal[k].x(), py - nominal[k].y()));
    machine(t, refs[k].x(), refs[k].y(), &px, &py);  // the true machine on the references
    after = std::max(after, std::hypot(px - nominal[k].x(), py - nominal[k].y()));
  }
  EXPECT_GT(before, 0.02);
  EXPECT_LT(after, 0.002) << "before " << before;  // 0.2 um noise over 300 mm edges
  EXPECT_LT(after, before / 10.0);
}

TEST(SpcActuator, NoisyEdgesRecoverTheInjectedErrorsWithinTheirStandardErrors) {
  const Truth t{0.010, -0.020, 0.010, -0.020};
  for (unsigned seed = 10; seed < 15; ++seed) {
    const auto xf = edge(t, 'x', 0.0, 50, 0.0005, seed);
    const auto yf = edge(t, 'y', 0.0, 50, 0.0005, seed + 100);
    const SpcActuatorResult r = actuatorErrorsFromSpc(xf, yf);
    // (apply is not asserted: a 3-sigma chart of iid residuals raises a false alarm now and then)
    ASSERT_TRUE(r.x.slopeSignificant && r.y.slopeSignificant);
    // se(slope) ~ 0.5 um / sqrt(Sxx) ~ 1.2e-6 -> 7e-5 deg; 5 se.
    EXPECT_NEAR(r.errors.xAxisAngleDeg, 0.010, 5 * r.x.line.slopeStdErr / kDeg);
    EXPECT_NEAR(r.errors.yAxisAngleDeg, -0.020, 5 * r.y.line.slopeStdErr / kDeg);
    EXPECT_NEAR(r.errors.originMm.x(), 0.010, 5 * r.y.interceptStdErr);
    EXPECT_NEAR(r.errors.originMm.y(), -0.020, 5 * r.x.interceptStdErr);
    EXPECT_TRUE(r.x.residualChart.has_value());
    EXPECT_NEAR(r.x.residualSigmaMm, 0.0005, 0.0002);
  }
}

TEST(SpcActuator, SystematicErrorIsEq20WithTheNominalDeviationZero) {
  const Truth t{0.0, 0.030, 0.0, 0.0};
  const auto xf = edge(t, 'x', 0.0, 30, 0.0005, 7);
  const SpcActuatorResult r = actuatorErrorsFromSpc(xf, edge(t, 'y', 0.0, 30, 0.0005, 8));
  double mean = 0.0;
  for (const double d : xf.deviationMm) mean += d / static_cast<double>(xf.deviationMm.size());
  EXPECT_NEAR(r.x.systematicErrorMm, 0.0 - mean, 1e-15);
  EXPECT_NEAR(r.x.systematicErrorMm, -0.030, 0.0005);
}

TEST(SpcActuator, AnErrorFreeMachineIsNotCompensated) {
  const Truth t{0.0, 0.0, 0.0, 0.0};
  SpcActuatorOptions o;
  o.coverageFactor = 4.0;  // no parameter of pure noise beyond 4 se in this seed
  const SpcActuatorResult r =
      actuatorErrorsFromSpc(edge(t, 'x', 0.0, 40, 0.001, 21), edge(t, 'y', 0.0, 40, 0.001, 22), o);
  EXPECT_FALSE(r.apply);
  EXPECT_EQ(r.reason.rfind("not compensated: no slope or intercept", 0), 0u) << r.reason;
  EXPECT_EQ(r.errors.xAxisAngleDeg, 0.0);
  EXPECT_EQ(r.errors.yAxisAngleDeg, 0.0);
  EXPECT_EQ(r.errors.originMm, Eigen::Vector2d::Zero());
}

TEST(SpcActuator, ASpecialCauseInTheResidualsStopsTheCompensation) {
  const Truth t{0.01, 0.01, 0.01, 0.01};
  auto xf = edge(t, 'x', 0.0, 50, 0.0005, 31);
  for (std::size_t k = 20; k < 25; ++k) xf.deviationMm[k] += 0.01;  // one subgroup shifted by 10 um
  const SpcActuatorResult r = actuatorErrorsFromSpc(xf, edge(t, 'y', 0.0, 50, 0.0005, 32));
  ASSERT_TRUE(r.x.residualChart.has_value());
  EXPECT_FALSE(r.x.residualChart->inControl());
  EXPECT_FALSE(r.apply);
  EXPECT_NE(r.reason.find("out of control (x-edge.csv)"), std::string::npos) << r.reason;
}

TEST(SpcActuator, BadSeriesNameTheFile) {
  const Truth t{0.0, 0.0, 0.01, 0.0};
  auto xf = edge(t, 'x', 0.0, 2, 0.0, 1);
  try {
    actuatorErrorsFromSpc(xf, edge(t, 'y', 0.0, 10, 0.0, 1));
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("x-edge.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at least 3"), std::string::npos) << e.what();
  }
  // Columns swapped: position and deviation exchanged give a ~90 deg offset angle.
  auto yf = edge(t, 'y', 0.0, 10, 0.0, 1);
  std::swap(yf.positionMm, yf.deviationMm);
  for (auto& d : yf.positionMm) d += 1e-3 * (&d - yf.positionMm.data());
  try {
    actuatorErrorsFromSpc(edge(t, 'x', 0.0, 10, 0.0, 1), yf);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("y-edge.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("swapped"), std::string::npos) << e.what();
  }
  SpcActuatorOptions o;
  o.subgroupSize = 1;
  EXPECT_THROW(actuatorErrorsFromSpc(edge(t, 'x', 0.0, 10, 0.0, 1), edge(t, 'y', 0.0, 10, 0.0, 1), o),
               OptionsError);
}

// The options of the SPC route are validated as the SPC chart's options are (one check): the same
// verdicts and messages for the coverage factor within the A2/D3/D4 table; the residual chart is an
// X-bar/R chart, so subgroups of 1 (individuals, which the SPC options take) are refused.
TEST(SpcActuator, OptionsValidatedAsTheSpcChartOptions) {
  for (const int size : {0, 1, 2, 5, 25, 26}) {
    for (const double k : {-1.0, 0.0, 2.0, std::numeric_limits<double>::infinity()}) {
      SpcActuatorOptions a;
      a.subgroupSize = size;
      a.coverageFactor = k;
      SpcOptions s;
      s.subgroupSize = size;
      s.coverageFactor = k;
      std::string whyA, whyS;
      const bool okA = a.isValid(&whyA);
      const bool okS = s.isValid(&whyS);
      EXPECT_EQ(okA, size >= 2 && size <= 25 && k == 2.0) << size << " " << k;
      EXPECT_EQ(okS, size >= 1 && size <= 25 && k == 2.0) << size << " " << k;
      if (size >= 2 && size <= 25) {
        EXPECT_EQ(okA, okS) << size << " " << k;
        EXPECT_EQ(whyA, whyS);
      }
    }
  }
  SpcActuatorOptions one;
  one.subgroupSize = 1;
  std::string whyOne;
  EXPECT_FALSE(one.isValid(&whyOne));
  EXPECT_EQ(whyOne, "subgroup size must be between 2 and 25 (the range of the A2/D3/D4 table), got 1");
  SpcActuatorOptions o;
  o.subgroupSize = 26;
  std::string why;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_NE(why.find("subgroup size must be between 2 and 25"), std::string::npos) << why;
  EXPECT_NE(why.find("26"), std::string::npos) << why;
}

}  // namespace
}  // namespace metrofit
