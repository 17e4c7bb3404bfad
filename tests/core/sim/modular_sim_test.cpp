// The simulated Z, C and combined heating tests (core/sim/thermal_modular_sim.h).
#include "core/sim/thermal_modular_sim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "testsupport.h"

namespace metrofit {
namespace {

double peakAbs(const std::vector<double>& v) {
  double p = 0.0;
  for (double x : v) p = std::max(p, std::abs(x - v.front()));
  return p;
}

TEST(ModularSim, ColumnsAndDeterminism) {
  ModularSimOptions o;
  o.seed = 5;
  const ThermalLog a = simulateModularTest(ModularTest::ZHeating, o);
  EXPECT_EQ(a.rows(), 241u);
  std::vector<std::string> names;
  for (const auto& c : a.channels) names.push_back(c.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"z_speed_mpm", "c_rpm", "T1", "T2", "T3", "T4", "T5", "T6", "T_amb",
                                      "FBG1_ue", "FBG2_ue", "FBG3_ue", "FBG4_ue", "disp_z_um"}));
  EXPECT_EQ(channelKind(a.channel("FBG1_ue")), ChannelKind::Strain);
  EXPECT_EQ(thermalLogToCsv(a), thermalLogToCsv(simulateModularTest(ModularTest::ZHeating, o)));
  o.seed = 6;
  EXPECT_NE(thermalLogToCsv(a), thermalLogToCsv(simulateModularTest(ModularTest::ZHeating, o)));
  // Each test draws from its own stream.
  EXPECT_NE(a.channel("T_amb").values, simulateModularTest(ModularTest::CHeating, o).channel("T_amb").values);
}

TEST(ModularSim, ErrorSizesOfThePaper) {
  // Sections 4.1-4.3: Z test > 100 um, C test > 80 um, combined ~95 um (here within 15 %).
  const ModularSimOptions o;
  const double z = peakAbs(simulateModularTest(ModularTest::ZHeating, o).channel("disp_z_um").values);
  const double c = peakAbs(simulateModularTest(ModularTest::CHeating, o).channel("disp_z_um").values);
  const double h = peakAbs(simulateModularTest(ModularTest::Combined, o).channel("disp_z_um").values);
  EXPECT_GT(z, 95.0);
  EXPECT_LT(z, 130.0);
  EXPECT_GT(c, 75.0);
  EXPECT_LT(c, 110.0);
  EXPECT_TRUE(test::near(h, 95.0, 15.0)) << h;
  // The drives are on for the first two hours only.
  const ThermalLog zl = simulateModularTest(ModularTest::ZHeating, o);
  EXPECT_EQ(zl.channel("z_speed_mpm").values[60], 70.0);
  EXPECT_EQ(zl.channel("z_speed_mpm").values[130], 0.0);
  EXPECT_EQ(zl.channel("c_rpm").values[60], 0.0);
}

TEST(ModularSim, CombinedTestIsTheSuperpositionOfTheModules) {
  // The network is linear: without noise and ambient change, the combined test at half the drive
  // levels is half the Z test plus half the C test (the premise of Section 4.3's modular models).
  ModularSimOptions o;
  o.noiseTempK = o.noiseStrainUe = o.noiseDispUm = 0.0;
  o.ambientAmp = 0.0;
  o.combinedZSpeedMpm = 0.5 * o.zSpeedMpm;
  o.combinedCRpm = 0.5 * o.cRpm;
  const ThermalLog z = simulateModularTest(ModularTest::ZHeating, o);
  const ThermalLog c = simulateModularTest(ModularTest::CHeating, o);
  const ThermalLog h = simulateModularTest(ModularTest::Combined, o);
  for (const char* col : {"disp_z_um", "FBG1_ue", "FBG4_ue", "T2"}) {
    const auto& vz = z.channel(col).values;
    const auto& vc = c.channel(col).values;
    const auto& vh = h.channel(col).values;
    for (std::size_t k = 0; k < vh.size(); ++k) {
      const double sum = 0.5 * (vz[k] - vz[0]) + 0.5 * (vc[k] - vc[0]);
      ASSERT_TRUE(test::near(vh[k] - vh[0], sum, 1e-9)) << col << " row " << k;
    }
  }
}

TEST(ModularSim, InvalidOptions) {
  ModularSimOptions o;
  o.lagT[1] = 0.0;
  try {
    (void)simulateModularTest(ModularTest::CHeating, o);
    FAIL();
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(), "field 'modular thermal simulation': sensor lags must be positive");
  }
  EXPECT_STREQ(toString(ModularTest::Combined), "combined");
}

}  // namespace
}  // namespace metrofit
