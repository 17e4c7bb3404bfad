// The closed-form least-squares reference (Horn / Umeyama) and its constrained form with DOF locks.
#include "core/matching/closed_form.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/common/rng.h"
#include "matching_fixtures.h"

namespace metrofit::matching {
namespace {

double sumSquares(const ProbePointSet& set, const Pose& p) {
  double s = 0.0;
  for (const auto& pt : set.points) s += (pt.measured - p.apply(pt.nominal)).squaredNorm();
  return s;
}

Eigen::Matrix4d homogeneous(const Pose& p) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
  H.topLeftCorner<3, 3>() = p.scale * p.rotation;
  H.topRightCorner<3, 1>() = p.translation;
  return H;
}

void matrices(const ProbePointSet& set, Eigen::Matrix3Xd& Q, Eigen::Matrix3Xd& P) {
  Q.resize(3, static_cast<Eigen::Index>(set.points.size()));
  P.resize(3, static_cast<Eigen::Index>(set.points.size()));
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    Q.col(static_cast<Eigen::Index>(i)) = set.points[i].nominal;
    P.col(static_cast<Eigen::Index>(i)) = set.points[i].measured;
  }
}

TEST(ClosedForm, RecoversTheSimulatedPostureExactly) {
  for (const Eigen::Vector3d& deg :
       {Eigen::Vector3d(0.02, -0.015, 0.05), Eigen::Vector3d(5.0, -12.0, 40.0)}) {
    const Eigen::Vector3d t(0.12, -0.08, 0.05);
    const ProbePointSet set = test::simulatedBlock(deg.x(), deg.y(), deg.z(), t, 0.0);
    const ClosedFormResult r = closedFormFit(set, {});
    EXPECT_FALSE(r.constrained);
    EXPECT_LT((r.pose.anglesDeg() - deg).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((r.pose.translation - t).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_EQ(r.pose.scale, 1.0);
    EXPECT_LT(r.sumSquares, 1e-18);
  }
}

TEST(ClosedForm, EqualsEigenUmeyamaWithAndWithoutScale) {
  ProbePointSet set = test::simulatedBlock(1.0, -2.0, 3.0, {10.0, -5.0, 2.0}, 0.01, 11);
  for (auto& p : set.points) p.measured = 1.0002 * p.measured;  // a thermal scale
  Eigen::Matrix3Xd Q, P;
  matrices(set, Q, P);
  for (bool scale : {false, true}) {
    const Eigen::Matrix4d eigen = Eigen::umeyama(Q, P, scale);
    const Pose ours = umeyamaFit(set, scale);
    EXPECT_LT((homogeneous(ours) - eigen).cwiseAbs().maxCoeff(), 1e-10) << "scale " << scale;
    const ClosedFormResult r = closedFormFit(set, {scale, {}, 100});
    EXPECT_LT((homogeneous(r.pose) - eigen).cwiseAbs().maxCoeff(), 1e-10);
  }
  EXPECT_NEAR(umeyamaFit(set, true).scale, 1.0002, 1e-5);  // noise 0.01 mm on a 200 mm block
}

TEST(ClosedForm, AllRotationsLockedGiveTheCentroidDifference) {
  const ProbePointSet set = test::simulatedBlock(0.3, 0.1, -0.2, {0.4, 0.5, -0.6}, 0.005, 2);
  ClosedFormOptions o;
  o.locks.lock(Dof::Rx);
  o.locks.lock(Dof::Ry);
  o.locks.lock(Dof::Rz);
  const ClosedFormResult r = closedFormFit(set, o);
  EXPECT_TRUE(r.constrained);
  Eigen::Vector3d diff = Eigen::Vector3d::Zero();
  for (const auto& p : set.points) diff += p.measured - p.nominal;
  diff /= static_cast<double>(set.points.size());
  EXPECT_TRUE(r.pose.rotation.isIdentity(0.0));
  EXPECT_LT((r.pose.translation - diff).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ClosedForm, TranslationLockedGivesTheRotationAboutTheOrigin) {
  // Hand-derived: with t = 0 the optimum maximises tr(R^T sum p q^T) (uncentred Kabsch).
  const ProbePointSet set = test::simulatedBlock(0.3, 0.1, -0.2, {0.4, 0.5, -0.6}, 0.005, 2);
  ClosedFormOptions o;
  o.locks.lock(Dof::X);
  o.locks.lock(Dof::Y);
  o.locks.lock(Dof::Z);
  const ClosedFormResult r = closedFormFit(set, o);
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  for (const auto& p : set.points) K += p.measured * p.nominal.transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(K, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d S = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2) = -1;
  const Eigen::Matrix3d R = svd.matrixU() * S.asDiagonal() * svd.matrixV().transpose();
  EXPECT_LT((r.pose.rotation - R).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(r.pose.translation, Eigen::Vector3d::Zero());
}

TEST(ClosedForm, PlanarRotationAboutZHandDerived) {
  // Only rz free (x, y, z, rx, ry locked at 0): rz = atan2(sum (q x p)_z, sum q.p) in the plane.
  Rng rng(4);
  std::vector<Eigen::Vector3d> q, off;
  for (int i = 0; i < 12; ++i) {
    q.emplace_back(rng.uniform(-50, 50), rng.uniform(-50, 50), 0.0);
    off.emplace_back(rng.normal(0, 0.01), rng.normal(0, 0.01), 0.0);
  }
  ProbePointSet set = test::setFrom(q, Pose::fromAnglesDeg({0, 0, 0.7}, {0, 0, 0}), {}, off);
  set.planar = true;
  ClosedFormOptions o;
  for (Dof d : {Dof::Rx, Dof::Ry, Dof::X, Dof::Y, Dof::Z}) o.locks.lock(d);
  const ClosedFormResult r = closedFormFit(set, o);
  double cross = 0.0, dot = 0.0;
  for (const auto& p : set.points) {
    cross += p.nominal.x() * p.measured.y() - p.nominal.y() * p.measured.x();
    dot += p.nominal.x() * p.measured.x() + p.nominal.y() * p.measured.y();
  }
  const Eigen::Vector3d a = r.pose.anglesDeg();
  EXPECT_NEAR(a.z(), std::atan2(cross, dot) * kDegPerRad, 1e-12);
  EXPECT_EQ(a.x(), 0.0);
  EXPECT_EQ(a.y(), 0.0);
}

TEST(ClosedForm, LocksAreConstrainedOptimaNotZeroedSolutions) {
  // rz locked at 0 while the part is turned by 0.05 deg about z: the constrained optimum compensates
  // with the translation, so it differs from "free optimum with rz set to 0" and is strictly better.
  const ProbePointSet set = test::simulatedBlock(0.02, -0.015, 0.05, {0.12, -0.08, 0.05}, 0.002, 9);
  ClosedFormOptions o;
  o.locks.lock(Dof::Rz);
  o.locks.lock(Dof::Z, 0.04);
  const ClosedFormResult r = closedFormFit(set, o);
  const Eigen::Vector3d a = r.pose.anglesDeg();
  EXPECT_EQ(a.z(), 0.0);
  EXPECT_EQ(r.pose.translation.z(), 0.04);
  Pose zeroed = umeyamaFit(set, false);
  Eigen::Vector3d za = zeroed.anglesDeg();
  za.z() = 0.0;
  zeroed = Pose::fromAnglesDeg(za, {zeroed.translation.x(), zeroed.translation.y(), 0.04});
  EXPECT_LT(r.sumSquares, sumSquares(set, zeroed));
  // Stationary in every free parameter: central differences of SS vanish.
  const double ss = sumSquares(set, r.pose);
  EXPECT_NEAR(r.sumSquares, ss, 1e-12 * ss);
  for (int j = 0; j < 4; ++j) {
    const double h = j < 2 ? 1e-6 : 1e-5;
    auto at = [&](double delta) {
      Eigen::Vector3d ang = a;
      Eigen::Vector3d t = r.pose.translation;
      if (j < 2)
        ang(j) += delta;
      else
        t(j - 2) += delta;
      return sumSquares(set, Pose::fromAnglesDeg(ang, t));
    };
    // A parabola through the three values has its vertex within 1 % of h of the optimum.
    const double up = at(h), down = at(-h);
    EXPECT_GT(up, ss) << j;
    EXPECT_GT(down, ss) << j;
    EXPECT_LT(std::abs(up - down), 0.02 * (up + down - 2 * ss)) << j;
  }
}

TEST(ClosedForm, LockedScaleFitKeepsLocksAndFindsTheScale) {
  ProbePointSet set = test::simulatedBlock(0.0, 0.0, 0.2, {0.3, 0.0, 0.0}, 0.0);
  for (auto& p : set.points) p.measured = 1.0005 * p.measured;
  ClosedFormOptions o;
  o.allowScale = true;
  o.locks.lock(Dof::Rx);
  o.locks.lock(Dof::Ry);
  const ClosedFormResult r = closedFormFit(set, o);
  EXPECT_NEAR(r.pose.scale, 1.0005, 1e-12);
  EXPECT_NEAR(r.pose.anglesDeg().z(), 0.2, 1e-10);
  EXPECT_LT(r.sumSquares, 1e-18);
}

}  // namespace
}  // namespace metrofit::matching
