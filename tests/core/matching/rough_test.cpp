// Rough matching (Jiang et al. 2018, Section 2.1-2.2, Eq. 3-7).
#include "core/matching/rough.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

TEST(Rough, LocalFrameOfEq3OnAHandBuiltTriangle) {
  // X0 = origin, X2 along x (i), X1 above the x axis in the xy plane.
  LocalFrame f;
  ASSERT_TRUE(localFrame({0, 0, 0}, {1, 1, 0}, {2, 0, 0}, &f));
  // i = (1,0,0); k = (X1 - X0) x i / |.| = (1,1,0) x (1,0,0) = (0,0,-1); j = i x k = (0,1,0).
  EXPECT_TRUE(f.axes.col(0).isApprox(Eigen::Vector3d(1, 0, 0), 1e-15));
  EXPECT_TRUE(f.axes.col(1).isApprox(Eigen::Vector3d(0, 1, 0), 1e-15));
  EXPECT_TRUE(f.axes.col(2).isApprox(Eigen::Vector3d(0, 0, -1), 1e-15));
  EXPECT_NEAR(f.axes.determinant(), -1.0, 1e-15);  // left-handed, as printed; cancels in R0
  EXPECT_FALSE(localFrame({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, &f));
}

TEST(Rough, ExactDataGiveTheExactPosture) {
  for (const Eigen::Vector3d& deg : {Eigen::Vector3d(0.02, -0.015, 0.05), Eigen::Vector3d(3.0, -4.0, 25.0)}) {
    const Eigen::Vector3d t(1.2, -0.8, 0.5);
    const ProbePointSet set = test::simulatedBlock(deg.x(), deg.y(), deg.z(), t, 0.0);
    const Pose truth = Pose::fromAnglesDeg(deg, t);
    const RoughResult automatic = roughMatch(set);
    EXPECT_LT(test::poseDistance(automatic.posture, truth), 1e-11);
    const RoughResult byId = roughMatch(set, std::vector<std::string>{"P001", "P020", "P035"});
    EXPECT_LT(test::poseDistance(byId.posture, truth), 1e-11);
    // Eq. (4): A0 = R0^T maps the actual frame onto the theoretical one and is the inverse posture.
    EXPECT_TRUE((automatic.alignment * automatic.actual.axes).isApprox(automatic.theoretical.axes, 1e-12));
    EXPECT_NEAR(automatic.alignment.determinant(), 1.0, 1e-12);
    // Eq. (5), (7): PE0 holds the angles of A0 = R^T and T0 = -R^T t.
    const Eigen::Vector3d paper = eulerZyxDeg(truth.rotation.transpose());
    const Eigen::Vector3d T0 = -(truth.rotation.transpose() * t);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(automatic.pe0[static_cast<std::size_t>(j)], paper(j), 1e-10);
      EXPECT_NEAR(automatic.pe0[static_cast<std::size_t>(3 + j)], T0(j), 1e-10);
    }
  }
}

TEST(Rough, SmallRotationAnglesAreTheNegatedPostureAngles) {
  const ProbePointSet set = test::simulatedBlock(0.02, -0.015, 0.05, {0.12, -0.08, 0.05}, 0.0);
  const RoughResult r = roughMatch(set);
  // First order only: the products of the angles (~1e-5 deg here) separate A0's angles from -R's.
  EXPECT_NEAR(r.pe0[0], -0.02, 1e-4);
  EXPECT_NEAR(r.pe0[1], 0.015, 1e-4);
  EXPECT_NEAR(r.pe0[2], -0.05, 1e-4);
}

TEST(Rough, AutomaticReferencesSpanTheLargestTriangle) {
  const ProbePointSet set = test::simulatedBlock(0.0, 0.0, 0.0, {0, 0, 0}, 0.0);
  const auto ref = chooseReferencePoints(set);
  auto area = [&](std::size_t a, std::size_t b, std::size_t c) {
    const auto& P = set.points;
    return (P[b].nominal - P[a].nominal).cross(P[c].nominal - P[a].nominal).norm();
  };
  double best = 0.0;
  const std::size_t n = set.points.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) best = std::max(best, area(a, b, c));
  EXPECT_NEAR(area(ref[0], ref[1], ref[2]), best, 1e-9 * best);
  // X0-X2 is the longest side.
  const auto& P = set.points;
  const double d02 = (P[ref[2]].nominal - P[ref[0]].nominal).norm();
  EXPECT_GE(d02, (P[ref[1]].nominal - P[ref[0]].nominal).norm());
  EXPECT_GE(d02, (P[ref[2]].nominal - P[ref[1]].nominal).norm());
}

TEST(Rough, NoisyDataGiveACloseStart) {
  const ProbePointSet set = test::simulatedBlock(0.5, -0.3, 1.0, {1.0, 2.0, -1.0}, 0.002, 3);
  const RoughResult r = roughMatch(set);
  EXPECT_LT(test::poseDistance(r.posture, Pose::fromAnglesDeg({0.5, -0.3, 1.0}, {1.0, 2.0, -1.0})), 0.01);
}

TEST(Rough, BadReferencesAreNamed) {
  const ProbePointSet set = test::simulatedBlock(0.0, 0.0, 0.0, {0, 0, 0}, 0.0);
  try {
    roughMatch(set, std::vector<std::string>{"P001", "P002", "nope"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "simulated probing: field 'reference': no point with id 'nope'");
  }
  EXPECT_THROW(roughMatch(set, std::vector<std::string>{"P001", "P001", "P003"}), ValidationError);
  EXPECT_THROW(roughMatch(set, std::vector<std::string>{"P001", "P002"}), ValidationError);
  // P001, P004, P007... lie on one grid line of the top face (x varies only with i).
  try {
    roughMatch(set, std::vector<std::string>{"P001", "P004", "P007"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("are collinear"), std::string::npos) << e.what();
  }
  ProbePointSet line = test::setFrom({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, Pose{});
  EXPECT_THROW(chooseReferencePoints(line), ValidationError);
}

}  // namespace
}  // namespace metrofit::matching
