// The circular test analysis of the kinematics study (core/study/circular_analysis.h) with its ISO 230-4
// results: a noise-free simulated test of a machine with actuator errors is the circle through the linear
// map M = [ir jr] (plus the origin), an ellipse with semi-axes R s1 and R s2 (the singular values of M,
// computed here with Eigen's JacobiSVD): G = R (s1 - s2) in both directions and H = 0; the loops and the
// radial form's runs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/kinematics/cartesian_model.h"
#include "core/sim/circular_sim.h"
#include "core/study/circular_analysis.h"

namespace metrofit {
namespace {

TEST(CircularAnalysis, SquarenessEllipseGivesGFromTheSingularValues) {
  CircularSimOptions o;
  o.noiseMm = 0.0;
  o.radiusMm = 80.0;
  o.pointsPerLoop = 720;  // 0.5 deg steps: the sampled extremes are within 0.25 deg of the true ones
  o.errors.originMm = Eigen::Vector2d(0.012, -0.007);
  o.errors.xAxisAngleDeg = 0.004;
  o.errors.yAxisAngleDeg = -0.011;
  const MeasuredPath path = simulateCircularTest(o);
  const CircularAnalysis a = analyseCircularTest(path);
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(CartesianMachine2::fromErrors(o.errors).directions());
  const Eigen::Vector2d s = svd.singularValues();
  const double g = o.radiusMm * (s(0) - s(1));
  // Sampling within 0.25 deg of the principal axes loses at most g (1 - cos 0.5 deg) < 1e-9 mm here.
  ASSERT_EQ(a.iso.directions.size(), 2u);
  for (const Iso230Direction& d : a.iso.directions) {
    EXPECT_EQ(d.points, 720u);
    EXPECT_NEAR(d.circularDeviationMm, g, 1e-9);
    // The LSQ centre of the ellipse is the image of the circle's centre: the origin offset.
    EXPECT_NEAR(d.lsqCentreMm.x(), 0.012, 1e-9);
    EXPECT_NEAR(d.lsqCentreMm.y(), -0.007, 1e-9);
  }
  ASSERT_TRUE(a.iso.circularHysteresisMm);
  EXPECT_NEAR(*a.iso.circularHysteresisMm, 0.0, 1e-9);
  EXPECT_GT(g, 0.015);  // 80 mm x 0.015 deg: about 21 um, far above the tolerances
  ASSERT_EQ(a.loops.size(), 2u);
  EXPECT_FALSE(a.radialOnly);
  // The ballbar breakdown (core/kinematics/ballbar.h): the squareness b - a as the shear over the radius.
  ASSERT_TRUE(a.ballbar) << a.ballbarUnavailable;
  ASSERT_FALSE(a.ballbar->causes.empty());
  EXPECT_EQ(a.ballbar->causes.front().name, "squareness");
  EXPECT_NEAR(a.ballbar->causes.front().valueUm, -0.015 * std::numbers::pi / 180.0 * o.radiusMm * 1000.0,
              0.01);
  // Half of the test (the CCW loop alone, 180 of its points): a gap in the circle, no breakdown and why.
  MeasuredPath half = path;
  half.command.resize(180);
  half.measured.resize(180);
  const CircularAnalysis h = analyseCircularTest(half);
  EXPECT_FALSE(h.ballbar);
  EXPECT_NE(h.ballbarUnavailable.find("no ballbar breakdown: the CCW run leaves a gap"), std::string::npos)
      << h.ballbarUnavailable;
}

TEST(CircularAnalysis, RadialRunsStartNewLoopsAndAreNotIdentifiable) {
  // Two CCW runs of the radial form: one direction, two loops (a new run starts a new loop).
  std::string text = "angle_deg,deviation_um,run\n";
  for (int run = 1; run <= 2; ++run) {
    for (int k = 0; k < 36; ++k) {
      text += std::to_string(10 * k) + "," +
              std::to_string(std::cos(3.0 * 10 * k * std::numbers::pi / 180.0)) + "," + std::to_string(run) +
              "\n";
    }
  }
  const CircularAnalysis a = analyseCircularTrace(circularTraceFromCsv(parseCsv(text, "runs.csv")));
  EXPECT_TRUE(a.radialOnly);
  ASSERT_EQ(a.loops.size(), 2u);
  EXPECT_EQ(a.loops[1].first, 36u);
  EXPECT_TRUE(a.loops[0].counterClockwise && a.loops[1].counterClockwise);
  ASSERT_EQ(a.iso.directions.size(), 1u);
  EXPECT_NEAR(a.iso.directions[0].circularDeviationMm, 0.002, 1e-8);  // 2 x 1 um, 6 decimals in the file
  EXPECT_FALSE(a.iso.circularHysteresisMm);
  EXPECT_THROW(
      analyseCircularTrace(circularTraceFromCsv(parseCsv("angle_deg,deviation_um\n0,1\n1,2\n", "two.csv"))),
      ValidationError);
}

}  // namespace
}  // namespace metrofit
