// Validation of the fit input and the translation / scale elimination of Eq. (9).
#include "core/matching/fit_input.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

std::string errorOf(const ProbePointSet& set, const DofLocks& locks, bool scale, FitKind kind) {
  try {
    requireDeterminable(set, locks, scale, kind, "closed-form fit");
  } catch (const ValidationError& e) {
    return e.what();
  }
  return {};
}

const Pose kPose = Pose::fromAnglesDeg({0.1, -0.2, 0.3}, {1.0, 2.0, 3.0});

TEST(FitInput, TooFewPoints) {
  const ProbePointSet two = test::setFrom({{0, 0, 0}, {10, 0, 0}}, kPose);
  EXPECT_EQ(errorOf(two, {}, false, FitKind::LeastSquares),
            "test.csv: has 2 points, the closed-form fit needs at least 3 (three non-collinear points fix a "
            "rotation)");
  // Translation only: one point is enough.
  DofLocks rot;
  rot.lock(Dof::Rx);
  rot.lock(Dof::Ry);
  rot.lock(Dof::Rz);
  EXPECT_EQ(errorOf(test::setFrom({{1, 2, 3}}, kPose), rot, false, FitKind::LeastSquares), "");
  // Minimax along normals: one more point than free parameters.
  const ProbePointSet six = test::setFrom({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}},
                                          kPose, std::vector<Eigen::Vector3d>(6, Eigen::Vector3d::UnitZ()));
  EXPECT_NE(
      errorOf(six, {}, false, FitKind::Minimax).find("has 6 points, the closed-form fit needs at least 7"),
      std::string::npos);
}

TEST(FitInput, CoincidentAndCollinearPoints) {
  const ProbePointSet same = test::setFrom({{5, 5, 5}, {5, 5, 5}, {5, 5, 5}}, kPose);
  EXPECT_NE(errorOf(same, {}, false, FitKind::LeastSquares).find("all 3 nominal points coincide"),
            std::string::npos);
  const ProbePointSet line = test::setFrom({{0, 0, 0}, {10, 10, 0}, {20, 20, 0}, {35, 35, 0}}, kPose);
  const std::string e = errorOf(line, {}, false, FitKind::LeastSquares);
  EXPECT_EQ(e.rfind("test.csv: the nominal points are collinear (all on one line)", 0), 0u) << e;
  // A skew line with rounding in every coordinate is still recognised as a line.
  std::vector<Eigen::Vector3d> skew;
  for (int k = 0; k < 5; ++k)
    skew.push_back(Eigen::Vector3d(0.1, 0.7, 0.3) * (1.3 * k) + Eigen::Vector3d(5, -2, 1));
  const std::string e2 = errorOf(test::setFrom(skew, kPose), {}, false, FitKind::LeastSquares);
  EXPECT_NE(e2.find("the nominal points are collinear"), std::string::npos) << e2;
  // With every rotation locked, a line of points fixes the translation.
  DofLocks rot;
  rot.lock(Dof::Rx);
  rot.lock(Dof::Ry);
  rot.lock(Dof::Rz);
  EXPECT_EQ(errorOf(line, rot, false, FitKind::LeastSquares), "");
  // Along the x axis only rx is undetermined: locking it is enough.
  const ProbePointSet xline = test::setFrom({{0, 0, 0}, {10, 0, 0}, {20, 0, 0}}, kPose);
  DofLocks rx;
  rx.lock(Dof::Rx);
  EXPECT_NE(errorOf(xline, {}, false, FitKind::LeastSquares), "");
  EXPECT_EQ(errorOf(xline, rx, false, FitKind::LeastSquares), "");
}

TEST(FitInput, PlanarDataNeedTwoDistinctPointsAndLockRxRyZ) {
  ProbePointSet planar =
      test::setFrom({{0, 0, 0}, {10, 10, 0}, {20, 20, 0}}, Pose::fromAnglesDeg({0, 0, 1}, {1, 1, 0}));
  planar.planar = true;
  const DofLocks locks = effectiveLocks(planar, {});
  EXPECT_EQ(locks.toString(), "rx,ry,z");
  // Collinear is fine in the plane: the in-plane rotation is determined by the line's direction.
  EXPECT_EQ(errorOf(planar, locks, false, FitKind::LeastSquares), "");
  planar.points.resize(1);
  EXPECT_NE(errorOf(planar, locks, false, FitKind::LeastSquares).find("needs at least 2"), std::string::npos);
}

TEST(FitInput, ParallelNormalsLeaveInPlaneMotionUndeterminedForMinimax) {
  std::vector<Eigen::Vector3d> q;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) q.emplace_back(10.0 * i, 10.0 * j, 0.0);
  const ProbePointSet top =
      test::setFrom(q, kPose, std::vector<Eigen::Vector3d>(q.size(), Eigen::Vector3d::UnitZ()));
  const std::string e = errorOf(top, {}, false, FitKind::Minimax);
  EXPECT_NE(e.find("the normals leave"), std::string::npos) << e;
  EXPECT_NE(e.find("undetermined"), std::string::npos) << e;
  // Locking the in-plane motion (x, y, rz) makes the plane fit well posed.
  DofLocks inPlane;
  inPlane.lock(Dof::X);
  inPlane.lock(Dof::Y);
  inPlane.lock(Dof::Rz);
  EXPECT_EQ(errorOf(top, inPlane, false, FitKind::Minimax), "");
  // The least-squares fit uses whole distances, which see the in-plane motion.
  EXPECT_EQ(errorOf(top, {}, false, FitKind::LeastSquares), "");
}

TEST(FitInput, CollinearMeasurementsOfAGoodPartAreRejected) {
  ProbePointSet set = test::setFrom({{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 5}}, kPose);
  for (std::size_t i = 0; i < set.points.size(); ++i)
    set.points[i].measured = Eigen::Vector3d(1.0 * i, 0.0, 0.0);
  const std::string e = errorOf(set, {}, false, FitKind::LeastSquares);
  EXPECT_NE(e.find("the measured points are collinear or coincide"), std::string::npos) << e;
}

TEST(FitInput, OptimalTranslationAndScaleAreTheLeastSquaresOnes) {
  const ProbePointSet set = test::simulatedBlock(0.1, 0.2, -0.3, {0.5, -0.4, 0.3}, 0.01, 7);
  const CentredPoints c = centredPoints(set);
  const Eigen::Matrix3d R = rotationZyx(Eigen::Vector3d(0.1, 0.2, -0.29) * kRadPerDeg);
  auto ss = [&](const Pose& p) {
    double s = 0.0;
    for (const auto& pt : set.points) s += (pt.measured - p.apply(pt.nominal)).squaredNorm();
    return s;
  };
  for (bool scale : {false, true}) {
    for (int lockMask : {0, 1, 5, 7}) {
      DofLocks locks;
      for (int j = 0; j < 3; ++j)
        if (lockMask & (1 << j)) locks.lock(static_cast<Dof>(3 + j), 0.1 * (j + 1));
      double reported = 0.0;
      const Pose best = optimalTranslationScale(c, R, locks, scale, &reported);
      EXPECT_NEAR(reported, ss(best), 1e-9 * ss(best));
      for (int j = 0; j < 3; ++j) {
        if (locks.locked[3 + j]) {
          EXPECT_EQ(best.translation(j), 0.1 * (j + 1));
        }
      }
      if (!scale) {
        EXPECT_EQ(best.scale, 1.0);
      }
      // No perturbation of a free translation component or of the scale lowers the sum of squares.
      for (int j = 0; j < 4; ++j) {
        if (j < 3 && locks.locked[3 + j]) continue;
        if (j == 3 && !scale) continue;
        for (double h : {1e-4, -1e-4}) {
          Pose p = best;
          if (j < 3)
            p.translation(j) += h;
          else
            p.scale += h * 1e-3;
          EXPECT_GT(ss(p), ss(best)) << "mask " << lockMask << " scale " << scale << " j " << j;
        }
      }
    }
  }
}

// Points on a sphere with radial normals (the Wenzel lens points, a probed ball): the deviations along
// the normals do not change under any rotation about the centre, so the minimax fit needs rx, ry, rz
// locked; the positions alone fix them for least squares. locksToDetermine finds exactly those three.
TEST(FitInput, LocksToDetermineLocksTheRotationsASphereCannotFix) {
  std::vector<Eigen::Vector3d> points, normals;
  const Eigen::Vector3d centre(40.0, -12.0, 7.0);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 6; ++j) {
      const double polar = 0.2 + 0.25 * i, azimuth = 1.05 * j + 0.3 * i;
      const Eigen::Vector3d n(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                              std::cos(polar));
      points.push_back(centre + 12.5 * n);
      normals.push_back(n);
    }
  }
  const ProbePointSet sphere = test::setFrom(points, kPose, normals);
  EXPECT_NE(errorOf(sphere, {}, false, FitKind::Minimax).find("undetermined"), std::string::npos);
  const std::optional<DofLocks> locks = locksToDetermine(sphere, {}, false, FitKind::Minimax);
  ASSERT_TRUE(locks.has_value());
  EXPECT_EQ(locks->toString(), "rx,ry,rz");
  EXPECT_EQ(errorOf(sphere, *locks, false, FitKind::Minimax), "");
  EXPECT_EQ(locksToDetermine(sphere, {}, false, FitKind::LeastSquares)->toString(), "")
      << "positions fix the rotation";
  // A user lock is kept at its value. With z locked a rotation about the centre must keep the centre's
  // z: only rotations about axes through the centre parallel to the xy plane... are left, two of them,
  // so two rotation locks are enough (rx and ry would leave the rotation about z through the centre).
  DofLocks z;
  z.lock(Dof::Z, 0.5);
  EXPECT_EQ(locksToDetermine(sphere, z, false, FitKind::Minimax)->toString(), "rx,rz,z");
  EXPECT_EQ(locksToDetermine(sphere, z, false, FitKind::Minimax)->value[5], 0.5);
  // No lock helps two points: nullopt, requireDeterminable's error stands.
  EXPECT_FALSE(
      locksToDetermine(test::setFrom({{0, 0, 0}, {10, 0, 0}}, kPose), {}, false, FitKind::LeastSquares));
}

}  // namespace
}  // namespace metrofit::matching
