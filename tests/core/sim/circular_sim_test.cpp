// The circular-test simulator (core/sim/circular_sim.h): loop order and direction, the machine
// model, determinism by seed, noise level, option checks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/sim/circular_sim.h"
#include "testsupport.h"

namespace metrofit {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

TEST(CircularSim, OneLoopCounterClockwiseThenOneClockwise) {
  CircularSimOptions o;
  o.radiusMm = 25.0;
  o.centreMm = Eigen::Vector2d(10.0, -5.0);
  o.pointsPerLoop = 36;
  o.startAngleDeg = 90.0;
  const auto cmd = circularTestCommands(o);
  ASSERT_EQ(cmd.size(), 72u);
  EXPECT_LT((cmd[0] - Eigen::Vector2d(10.0, 20.0)).norm(), 1e-12);
  EXPECT_LT((cmd[36] - cmd[0]).norm(), 1e-12);  // the CW loop starts where the CCW loop started
  for (std::size_t k = 0; k + 1 < cmd.size(); ++k) {
    EXPECT_NEAR((cmd[k] - o.centreMm).norm(), 25.0, 1e-12);
    if (k == 35) continue;  // the turn-around
    const double turn = cross(cmd[k] - o.centreMm, cmd[k + 1] - o.centreMm);
    if (k < 35)
      EXPECT_GT(turn, 0.0) << k;  // counter-clockwise
    else
      EXPECT_LT(turn, 0.0) << k;  // clockwise
  }
}

TEST(CircularSim, MeasuredIsTheModelPlusNoiseAndDeterministicBySeed) {
  CircularSimOptions o;
  o.noiseMm = 0.0;
  const MeasuredPath clean = simulateCircularTest(o);
  const CartesianMachine2 m = CartesianMachine2::fromErrors(o.errors);
  for (std::size_t k = 0; k < clean.size(); ++k) EXPECT_EQ(clean.measured[k], m.forward(clean.command[k]));

  o.noiseMm = 0.001;
  o.seed = 11;
  const MeasuredPath a = simulateCircularTest(o), b = simulateCircularTest(o);
  o.seed = 12;
  const MeasuredPath c = simulateCircularTest(o);
  double ss = 0.0;
  bool differs = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a.measured[k], b.measured[k]);
    differs |= a.measured[k] != c.measured[k];
    ss += (a.measured[k] - clean.measured[k]).squaredNorm();
  }
  EXPECT_TRUE(differs);
  const double sigma = std::sqrt(ss / (2.0 * a.size()));
  EXPECT_NEAR(sigma, 0.001, 0.0001);
  EXPECT_EQ(a.source, "simulated circular test");
}

TEST(CircularSim, InvalidOptionsAreRejected) {
  CircularSimOptions o;
  std::string why;
  EXPECT_TRUE(o.isValid(&why)) << why;
  o.radiusMm = 0.0;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_THROW(simulateCircularTest(o), OptionsError);
  o = {};
  o.pointsPerLoop = 2;
  EXPECT_FALSE(o.isValid(&why));
  o = {};
  o.noiseMm = -1.0;
  EXPECT_FALSE(o.isValid(&why));
  o = {};
  o.errors.xAxisAngleDeg = 60.0;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_NE(why.find("45"), std::string::npos);
  EXPECT_THROW(simulateMachine(CircularSimOptions::defaultErrors(), {{0, 0}}, NAN, 1), OptionsError);
}

}  // namespace
}  // namespace metrofit
