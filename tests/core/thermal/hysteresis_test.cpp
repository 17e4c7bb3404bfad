// Hysteresis analysis (Abdulshahed 2016, grey neural network thermal model, Section 3.1, Fig. 9): loop areas
// and sensor lags.
#include "core/thermal/hysteresis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/sim/thermal_modular_sim.h"
#include "core/sim/thermal_sim.h"
#include "core/thermal/lag_regression.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

const SensorHysteresis& sensor(const HysteresisAnalysis& a, const std::string& name) {
  for (const auto& s : a.sensors) {
    if (s.sensor == name) return s;
  }
  throw std::runtime_error("no sensor " + name);
}

TEST(Hysteresis, FirstOrderLagStepResponse) {
  std::vector<double> t(61), x(61, 1.0);
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = 0.5 * static_cast<double>(k);
  x[0] = 0.0;
  const auto l = firstOrderLagMin(x, t, 4.0);
  // A unit step held from t = 0.5: 1 - e^{-(t - 0)/4} at every sample (sample-and-hold exact).
  for (std::size_t k = 1; k < t.size(); ++k)
    EXPECT_TRUE(test::near(l[k], 1.0 - std::exp(-t[k] / 4.0), 1e-12));
  EXPECT_EQ(firstOrderLagMin(x, t, 0.0), x);
}

TEST(Hysteresis, LagsOfTheSpindleSimulatorSensorsAreRecovered) {
  // With the column term off the displacement is -kS (Ts - Ts0) and T1, T2 are Ts seen through
  // 4 and 12 min lags (thermal_sim.h): the fit must find them within 5 %, the sensors lagging.
  ThermalSimOptions o;
  o.kC = 0.0;
  const ThermalSeries s = selectThermalSeries(simulateThermalTest(o), "disp_z_um", {"T1", "T2"});
  const HysteresisAnalysis a = analyseHysteresis(s);
  EXPECT_TRUE(test::near(sensor(a, "T1").tauMin, 4.0, 0.0, 0.05)) << sensor(a, "T1").tauMin;
  EXPECT_TRUE(test::near(sensor(a, "T2").tauMin, 12.0, 0.0, 0.05)) << sensor(a, "T2").tauMin;
  EXPECT_GT(sensor(a, "T2").r2, 0.999);
  EXPECT_LT(sensor(a, "T2").r2Static, sensor(a, "T2").r2);
  // The slower sensor draws the wider loop.
  EXPECT_GT(sensor(a, "T2").normalisedLoopArea, sensor(a, "T1").normalisedLoopArea);
  // Heating while the spindle runs (10-250 min), cooling after.
  EXPECT_EQ(a.phase[100], 1);
  EXPECT_EQ(a.phase[400], -1);
  EXPECT_EQ(a.heatingRows + a.coolingRows, s.rows());
}

TEST(Hysteresis, LagsOfTheRamSensorsAreRecovered) {
  // Modular simulator with only the ram body growing and a steady ambient: T2 (10 min) and T4
  // (20 min) lag the displacement; within 5 %.
  ModularSimOptions o;
  o.kZ = o.kC = o.kBeam = 0.0;
  o.ambientAmp = 0.0;
  const ThermalSeries s =
      selectThermalSeries(simulateModularTest(ModularTest::ZHeating, o), "disp_z_um", {"T2", "T4"});
  const HysteresisAnalysis a = analyseHysteresis(s);
  EXPECT_TRUE(test::near(sensor(a, "T2").tauMin, 10.0, 0.0, 0.05)) << sensor(a, "T2").tauMin;
  EXPECT_TRUE(test::near(sensor(a, "T4").tauMin, 20.0, 0.0, 0.05)) << sensor(a, "T4").tauMin;
}

TEST(Hysteresis, StrainSensorsShowLessHysteresisThanTheRamTemperature) {
  // Fig. 9's finding on the simulated Z test: the FBGs on the ram respond almost linearly, the ram
  // rear temperature T2 draws a wider loop.
  const ThermalSeries s = selectThermalSeries(simulateModularTest(ModularTest::ZHeating, {}), "disp_z_um",
                                              {"FBG1_ue", "FBG2_ue", "FBG3_ue", "T2"});
  const HysteresisAnalysis a = analyseHysteresis(s);
  for (const char* f : {"FBG1_ue", "FBG2_ue", "FBG3_ue"})
    EXPECT_LT(sensor(a, f).normalisedLoopArea, sensor(a, "T2").normalisedLoopArea) << f;
  EXPECT_GT(sensor(a, "T2").tauMin, 0.0);
}

TEST(Hysteresis, LoopAreaOfACircle) {
  ThermalSeries s;
  s.source = "circle";
  s.targetName = "y";
  s.inputNames = {"x"};
  s.inputs.resize(1);
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    const double th = 2.0 * std::numbers::pi * k / n;
    s.timeMin.push_back(k);
    s.inputs[0].push_back(std::cos(th));
    s.target.push_back(std::sin(th));
  }
  const HysteresisAnalysis a = analyseHysteresis(s);
  EXPECT_TRUE(test::near(a.sensors[0].loopArea, std::numbers::pi, 1e-3, 0.0)) << a.sensors[0].loopArea;
  EXPECT_TRUE(test::near(a.sensors[0].normalisedLoopArea, std::numbers::pi / 4.0, 1e-3));
  const auto j = hysteresisToJson(a);
  EXPECT_EQ(j["sensors"][0]["sensor"], "x");
  EXPECT_TRUE(j["sensors"][0].contains("tau_min"));
}

TEST(Hysteresis, ConstantColumnIsAnError) {
  ThermalSeries s;
  s.source = "h.csv";
  s.targetName = "d_um";
  s.inputNames = {"T1"};
  s.timeMin = {0, 1, 2, 3};
  s.target = {0, 1, 2, 3};
  s.inputs = {{20, 20, 20, 20}};
  try {
    (void)analyseHysteresis(s);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "h.csv: field 'T1': is constant; there is no loop to analyse");
  }
}

}  // namespace
}  // namespace metrofit::thermal
