// rmse_mm, max_abs_mm and out_of_tolerance exactly as docs/file-formats.md#match-result defines them.
#include "core/matching/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

TEST(Evaluation, DefinitionsWithNormals) {
  // Nominal points on a plane z = 0 with normal +z; measured offsets have normal and tangential parts.
  const std::vector<Eigen::Vector3d> q = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}};
  const std::vector<Eigen::Vector3d> n(4, Eigen::Vector3d::UnitZ());
  const std::vector<Eigen::Vector3d> off = {{0.03, 0, 0.02}, {0, 0, -0.05}, {0, 0.1, 0.05}, {0, 0, 0.0}};
  const ProbePointSet set = test::setFrom(q, Pose{}, n, off);
  const ToleranceEvaluation ev = evaluateTolerance(set, Pose{}, 0.05);
  // Deviations along the normal: 0.02, -0.05, 0.05, 0; distances: |off|.
  EXPECT_NEAR(ev.deviations[0], 0.02, 1e-15);
  EXPECT_NEAR(ev.deviations[1], -0.05, 1e-15);
  EXPECT_NEAR(ev.distances[2], std::hypot(0.1, 0.05), 1e-15);
  // rmse is the RMS of the whole residual distances, not of the normal deviations.
  const double ss = 0.03 * 0.03 + 0.02 * 0.02 + 0.05 * 0.05 + 0.1 * 0.1 + 0.05 * 0.05;
  EXPECT_NEAR(ev.overall.rmseMm, std::sqrt(ss / 4.0), 1e-15);
  EXPECT_NEAR(ev.overall.maxAbsMm, 0.05, 1e-15);
  // |d| > tolerance, strictly: the points at exactly 0.05 are not out.
  EXPECT_EQ(ev.overall.outOfTolerance, 0u);
  const ToleranceEvaluation tight = evaluateTolerance(set, Pose{}, 0.01);
  EXPECT_EQ(tight.overall.outOfTolerance, 3u);
  EXPECT_NEAR(tight.overall.meanOverToleranceMm, (0.01 + 0.04 + 0.04) / 3.0, 1e-15);
  // Per surface (points alternate "even", "odd").
  ASSERT_EQ(tight.surfaces.size(), 2u);
  EXPECT_EQ(tight.surfaces[0].surface, "even");
  EXPECT_EQ(tight.surfaces[0].stats.points, 2u);
  EXPECT_EQ(tight.surfaces[0].stats.outOfTolerance, 2u);
  EXPECT_NEAR(tight.surfaces[1].stats.maxAbsMm, 0.05, 1e-15);
  EXPECT_NEAR(tight.surfaces[1].stats.rmseMm, std::sqrt(0.05 * 0.05 / 2.0), 1e-15);
}

TEST(Evaluation, PositionOnlyDeviationIsTheDistance) {
  const std::vector<Eigen::Vector3d> q = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const std::vector<Eigen::Vector3d> off = {{0.03, 0.04, 0}, {0, 0, 0}, {0, 0, -0.01}};
  const ProbePointSet set = test::setFrom(q, Pose{}, {}, off);
  const ToleranceEvaluation ev = evaluateTolerance(set, Pose{}, 0.02);
  EXPECT_NEAR(ev.deviations[0], 0.05, 1e-15);
  EXPECT_NEAR(ev.overall.maxAbsMm, 0.05, 1e-15);
  EXPECT_EQ(ev.overall.outOfTolerance, 1u);
  EXPECT_EQ(ev.worstPoint, 0u);
}

TEST(Evaluation, UnderAPostureTheNormalTurnsWithThePart) {
  // The whole part is rotated by 30 deg about x and shifted along its rotated normal by 0.01 mm.
  const Pose pose = Pose::fromAnglesDeg({30.0, 0.0, 0.0}, {1.0, 2.0, 3.0});
  const std::vector<Eigen::Vector3d> q = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const std::vector<Eigen::Vector3d> n(3, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d shift = pose.rotation * Eigen::Vector3d::UnitZ() * 0.01;
  const ProbePointSet set = test::setFrom(q, pose, n, {shift, shift, shift});
  const ToleranceEvaluation after = evaluateTolerance(set, pose, 0.005);
  for (double d : after.deviations) EXPECT_NEAR(d, 0.01, 1e-12);
  EXPECT_EQ(after.overall.outOfTolerance, 3u);
  EXPECT_NEAR(maxAbsDeviation(set, pose), 0.01, 1e-12);
  // Before (identity posture) the deviations are those of the unadjusted part.
  const ToleranceEvaluation before = evaluateTolerance(set, Pose{}, 0.005);
  EXPECT_GT(before.overall.maxAbsMm, 1.0);
}

// Per point (match's per_point and --per-point CSV): under a posture written by hand — 90 deg about z,
// then t = (1, 2, 3) — q = (1, 0, 0) with normal (1, 0, 0) lies at (1, 3, 3) with normal (0, 1, 0); a
// measured point (1, 3.5, 3.25) deviates by (0, 0.5, 0.25), d = 0.5 along the turned normal.
TEST(Evaluation, PerPointDeviationVectorsAndTheirCsv) {
  Pose pose;
  pose.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  pose.translation = {1, 2, 3};
  ProbePointSet set;
  set.source = "hand";
  set.hasNormals = true;
  set.points.push_back({"P1", "top", {1, 0, 0}, {1, 0, 0}, {1, 3.5, 3.25}});
  set.points.push_back({"P2", "top", {0, 1, 0}, {0, 1, 0}, {0.25, 2, 3}});  // at (0, 2, 3), normal (-1, 0, 0)
  const ToleranceEvaluation ev = evaluateTolerance(set, pose, 0.1);
  ASSERT_EQ(ev.residuals.size(), 2u);
  EXPECT_NEAR(ev.residuals[0].x(), 0.0, 1e-15);
  EXPECT_NEAR(ev.residuals[0].y(), 0.5, 1e-15);
  EXPECT_NEAR(ev.residuals[0].z(), 0.25, 1e-15);
  EXPECT_NEAR(ev.deviations[0], 0.5, 1e-15);
  EXPECT_NEAR(ev.residuals[1].x(), 0.25, 1e-15);
  EXPECT_NEAR(ev.deviations[1], -0.25, 1e-15) << "outside the material along -x is negative here";
  EXPECT_EQ(perPointCsv(ev, set),
            "id,surface,d_mm,dx_mm,dy_mm,dz_mm\n"
            "P1,top,0.5,0,0.5,0.25\n"
            "P2,top,-0.25,0.25,0,0\n");
}

TEST(Evaluation, BadToleranceOrEmptySet) {
  ProbePointSet empty;
  empty.source = "e.csv";
  EXPECT_THROW(evaluateTolerance(empty, Pose{}, 0.1), ValidationError);
  const ProbePointSet set = test::setFrom({{0, 0, 0}}, Pose{});
  EXPECT_THROW(evaluateTolerance(set, Pose{}, -0.1), OptionsError);
  EXPECT_THROW(evaluateTolerance(set, Pose{}, std::nan("")), OptionsError);
}

}  // namespace
}  // namespace metrofit::matching
