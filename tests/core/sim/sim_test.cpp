#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/sim/probe_sim.h"
#include "core/sim/thermal_sim.h"
#include "testsupport.h"

namespace metrofit {
namespace {

TEST(ThermalSim, DeterministicBySeed) {
  ThermalSimOptions o;
  o.seed = 11;
  const ThermalLog a = simulateThermalTest(o), b = simulateThermalTest(o);
  ASSERT_EQ(a.rows(), 481u);
  EXPECT_EQ(thermalLogToCsv(a), thermalLogToCsv(b));
  o.seed = 12;
  EXPECT_NE(thermalLogToCsv(a), thermalLogToCsv(simulateThermalTest(o)));
}

TEST(ThermalSim, PhysicsWithoutNoise) {
  ThermalSimOptions o;
  o.noiseTempK = 0.0;
  o.noiseDispUm = 0.0;
  o.ambientAmp = 0.0;
  o.durationMin = 2000;
  o.programme = {{0.0, 4000.0}};
  const ThermalLog log = simulateThermalTest(o);
  const auto& t2 = log.channel("T2").values;
  const auto& d = log.channel("disp_z_um").values;
  // Spindle housing settles at ambient + gainS * Q = 20 + 2.5 * 4 = 30 degC.
  EXPECT_TRUE(test::near(t2.back(), 30.0, 0.05));
  // Column settles at Ta + shareC*(Ts-Ta) / (shareC + 1 - shareC) = 20 + 0.55*10 = 25.5 degC.
  EXPECT_TRUE(test::near(log.channel("T4").values.back(), 25.5, 0.1));
  // Displacement: -(4 * 10 + 2.5 * 5.5) = -53.75 um; monotone growth while heating.
  EXPECT_TRUE(test::near(d.back(), -53.75, 0.3));
  for (std::size_t i = 1; i < d.size(); ++i) ASSERT_LE(d[i], d[i - 1] + 1e-12);
  // The nose sensor (4 min lag) leads the housing sensor (12 min) early on.
  EXPECT_GT(log.channel("T1").values[30], t2[30]);
}

TEST(ThermalSim, InvalidOptions) {
  ThermalSimOptions o;
  o.stepMin = 0.0;
  EXPECT_THROW((void)simulateThermalTest(o), OptionsError);
  o = {};
  o.programme = {{10.0, 1.0}, {5.0, 2.0}};
  EXPECT_THROW((void)simulateThermalTest(o), OptionsError);
}

TEST(ProbeSim, PostureIsAppliedAndDeterministic) {
  ProbeSimOptions o;
  o.noiseMm = 0.0;
  const ProbePointSet s = simulateProbing(o);
  ASSERT_EQ(s.points.size(), 35u);
  const Eigen::Matrix3d R = rotationFromDeg(o.rotationDeg[0], o.rotationDeg[1], o.rotationDeg[2]);
  const Eigen::Vector3d t(o.translationMm[0], o.translationMm[1], o.translationMm[2]);
  for (const auto& p : s.points) {
    EXPECT_LT((p.measured - (R * p.nominal + t)).norm(), 1e-12);
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-15);
  }
  // Rz(90) maps x to y: the convention of docs/file-formats.md#match-result (R = Rz Ry Rx on column vectors).
  EXPECT_LT((rotationFromDeg(0, 0, 90) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  o.seed = 5;
  o.noiseMm = 0.002;
  EXPECT_EQ(probePointsToCsv(simulateProbing(o)), probePointsToCsv(simulateProbing(o)));
}

TEST(Sim, DemoDataIsSimulatorOutput) {
  // The bundled demo files must be exactly what the simulator writes for seed 7.
  ThermalSimOptions t;
  t.seed = 7;
  EXPECT_EQ(test::readText((test::sourceDir() / "resources/demo/data/thermal_demo.csv").string()),
            thermalLogToCsv(simulateThermalTest(t)));
  ProbeSimOptions p;
  p.seed = 7;
  EXPECT_EQ(test::readText((test::sourceDir() / "resources/demo/data/probe_points_demo.csv").string()),
            probePointsToCsv(simulateProbing(p)));
}

}  // namespace
}  // namespace metrofit
