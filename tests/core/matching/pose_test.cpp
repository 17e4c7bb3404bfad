// Posture conventions (docs/file-formats.md#match-result: R = Rz(rz) Ry(ry) Rx(rx) on column vectors) and
// locks.
#include "core/matching/pose.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/sim/probe_sim.h"

namespace metrofit::matching {
namespace {

TEST(Pose, RotationIsTheSimulatorsConvention) {
  const Eigen::Vector3d deg(12.0, -7.5, 33.0);
  EXPECT_TRUE(rotationZyx(deg * kRadPerDeg).isApprox(rotationFromDeg(deg.x(), deg.y(), deg.z()), 1e-15));
  // Rz(90) alone turns x into y (column vectors).
  const Eigen::Vector3d y = rotationZyx({0.0, 0.0, 90.0 * kRadPerDeg}) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(y.x(), 0.0, 1e-15);
  EXPECT_NEAR(y.y(), 1.0, 1e-15);
}

TEST(Pose, EulerAnglesRoundTrip) {
  Rng rng(5);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d a(rng.uniform(-3.0, 3.0), rng.uniform(-1.5, 1.5), rng.uniform(-3.0, 3.0));
    EXPECT_LT((eulerZyx(rotationZyx(a)) - a).cwiseAbs().maxCoeff(), 1e-12) << a.transpose();
  }
  // Exactly zero angles give exactly zero back (locked angles stay exact).
  const Eigen::Vector3d z = eulerZyx(rotationZyx({0.0, 0.3, 0.0}));
  EXPECT_EQ(z.x(), 0.0);
  EXPECT_EQ(z.z(), 0.0);
}

TEST(Pose, DerivativesMatchCentralDifferences) {
  const Eigen::Vector3d a(0.2, -0.4, 1.1);
  const auto d = rotationZyxDerivatives(a);
  const double h = 1e-6;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d ap = a, am = a;
    ap(j) += h;
    am(j) -= h;
    const Eigen::Matrix3d fd = (rotationZyx(ap) - rotationZyx(am)) / (2.0 * h);
    EXPECT_LT((fd - d[static_cast<std::size_t>(j)]).cwiseAbs().maxCoeff(), 1e-9) << j;
  }
}

TEST(Pose, ComposeAndInverse) {
  const Pose a = Pose::fromAnglesDeg({1.0, 2.0, 3.0}, {4.0, -5.0, 6.0}, 1.001);
  const Pose b = Pose::fromAnglesDeg({-0.5, 0.1, 7.0}, {0.3, 0.2, -0.1});
  const Eigen::Vector3d q(10.0, 20.0, -30.0);
  EXPECT_LT((a.compose(b).apply(q) - a.apply(b.apply(q))).norm(), 1e-12);
  EXPECT_LT((a.inverse().apply(a.apply(q)) - q).norm(), 1e-12);
  EXPECT_NEAR(a.inverse().scale, 1.0 / 1.001, 1e-15);
}

TEST(DofLocks, ParseNamesAndErrors) {
  const DofLocks l = DofLocks::parse(" RX, z", "--lock");
  EXPECT_TRUE(l.isLocked(Dof::Rx));
  EXPECT_TRUE(l.isLocked(Dof::Z));
  EXPECT_FALSE(l.isLocked(Dof::Ry));
  EXPECT_EQ(l.freeCount(), 4);
  EXPECT_TRUE(l.anyRotation());
  EXPECT_EQ(l.toString(), "rx,z");
  EXPECT_FALSE(DofLocks::parse("", "--lock").any());
  try {
    DofLocks::parse("rx,w", "--lock");
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(), "field '--lock': unknown degree of freedom 'w' (one of rx, ry, rz, x, y, z)");
  }
  EXPECT_THROW(DofLocks::parse("x,X", "--lock"), OptionsError);
  DofLocks bad;
  bad.lock(Dof::Ry, 60.0);
  std::string why;
  EXPECT_FALSE(bad.isValid(&why));
  EXPECT_NE(why.find("ry"), std::string::npos);
}

}  // namespace
}  // namespace metrofit::matching
