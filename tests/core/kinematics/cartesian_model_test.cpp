// The Cartesian machine model of the IEEE Access kinematic compensation algorithm, Section IV: Eq. 2-6
// (intersection), Eq. 9 (direct), Eq. 15 (inverse), 2D and three axes, and the paper's Fig. 11 cases.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/kinematics/cartesian_model.h"
#include "testsupport.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Vector2d dirAt(double deg) {
  return {std::cos(deg * kDeg), std::sin(deg * kDeg)};
}

std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& c, double r, int n) {
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    out.push_back(c + r * Eigen::Vector2d(std::cos(t), std::sin(t)));
  }
  return out;
}

TEST(CartesianMachine2, IdealMachineIsTheIdentity) {
  const CartesianMachine2 m;
  const Eigen::Vector2d p(12.5, -3.25);
  EXPECT_EQ(m.forward(p), p);
  EXPECT_EQ(m.inverse(p), p);
  EXPECT_EQ(m.intersectionPoint(), Eigen::Vector2d::Zero());
}

TEST(CartesianMachine2, DirectKinematicsIsEq9Literally) {
  const Eigen::Vector2d ox(3.0, -2.0), oy(-1.5, 4.0);
  const Eigen::Vector2d ir = dirAt(7.0), jr = dirAt(90.0 - 4.0);
  const CartesianMachine2 m(ox, oy, ir, jr);
  const Eigen::Vector2d pr(40.0, -25.0);
  const Eigen::Vector2d dOr = oy - ox;                                    // Eq. 2
  const Eigen::Vector2d expected = ox + ir * pr.x() + dOr + jr * pr.y();  // Eq. 9
  EXPECT_TRUE(test::near(m.forward(pr).x(), expected.x(), 1e-12));
  EXPECT_TRUE(test::near(m.forward(pr).y(), expected.y(), 1e-12));
  // Oxr cancels: P = Oyr + [ir jr] Pr.
  const Eigen::Vector2d viaOy = oy + m.directions() * pr;
  EXPECT_TRUE(test::near(m.forward(pr).x(), viaOy.x(), 1e-12));
  EXPECT_TRUE(test::near(m.forward(pr).y(), viaOy.y(), 1e-12));
}

TEST(CartesianMachine2, IntersectionPointSolvesEq3) {
  const Eigen::Vector2d ox(3.0, -2.0), oy(-1.5, 4.0);
  const Eigen::Vector2d ir = dirAt(10.0), jr = dirAt(90.0 + 15.0);
  const CartesianMachine2 m(ox, oy, ir, jr);
  const Eigen::Vector2d mxy = m.intersectionDistances();
  const Eigen::Vector2d lhs = -mxy.x() * ir + mxy.y() * jr;  // Eq. 3
  EXPECT_TRUE(test::near(lhs.x(), (oy - ox).x(), 1e-12));
  EXPECT_TRUE(test::near(lhs.y(), (oy - ox).y(), 1e-12));
  // The point lies on both actuator axes.
  const Eigen::Vector2d I = m.intersectionPoint();
  const Eigen::Vector2d fromY = oy - mxy.y() * jr;
  EXPECT_TRUE(test::near(I.x(), fromY.x(), 1e-12));
  EXPECT_TRUE(test::near(I.y(), fromY.y(), 1e-12));
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  EXPECT_NEAR(cross(I - ox, ir), 0.0, 1e-12);
  EXPECT_NEAR(cross(I - oy, jr), 0.0, 1e-12);
}

TEST(CartesianMachine2, ForwardInverseRoundTripsOnRandomMachines) {
  Rng rng(42);
  for (int trial = 0; trial < 50; ++trial) {
    const CartesianMachine2 m(Eigen::Vector2d(rng.uniform(-10, 10), rng.uniform(-10, 10)),
                              Eigen::Vector2d(rng.uniform(-10, 10), rng.uniform(-10, 10)),
                              dirAt(rng.uniform(-30, 30)), dirAt(90.0 + rng.uniform(-30, 30)));
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector2d p(rng.uniform(-500, 500), rng.uniform(-500, 500));
      const Eigen::Vector2d back = m.forward(m.inverse(p));
      EXPECT_LT((back - p).norm(), 1e-10) << trial;
      const Eigen::Vector2d joints = m.inverse(m.forward(p));
      EXPECT_LT((joints - p).norm(), 1e-10) << trial;
    }
  }
}

TEST(CartesianMachine2, ErrorsRoundTripThroughTheMachine) {
  ActuatorErrors2 e;
  e.originMm = Eigen::Vector2d(0.5, -0.25);
  e.xAxisAngleDeg = 10.0;
  e.yAxisAngleDeg = -15.0;
  const CartesianMachine2 m = CartesianMachine2::fromErrors(e);
  EXPECT_TRUE(test::near(m.errors().xAxisAngleDeg, 10.0, 1e-12));
  EXPECT_TRUE(test::near(m.errors().yAxisAngleDeg, -15.0, 1e-12));
  EXPECT_EQ(m.errors().originMm, e.originMm);
  EXPECT_DOUBLE_EQ(e.squarenessDeg(), -25.0);
  // docs/file-formats.md#kinematic-identify-result: X moves along (cos a, sin a), Y along (-sin b, cos b).
  const Eigen::Vector2d px = m.forward({1.0, 0.0}) - m.forward({0.0, 0.0});
  const Eigen::Vector2d py = m.forward({0.0, 1.0}) - m.forward({0.0, 0.0});
  EXPECT_TRUE(test::near(px.x(), std::cos(10.0 * kDeg), 1e-12));
  EXPECT_TRUE(test::near(px.y(), std::sin(10.0 * kDeg), 1e-12));
  EXPECT_TRUE(test::near(py.x(), -std::sin(-15.0 * kDeg), 1e-12));
  EXPECT_TRUE(test::near(py.y(), std::cos(-15.0 * kDeg), 1e-12));
  // det [ir jr] = cos(b - a).
  EXPECT_TRUE(test::near(m.directions().determinant(), std::cos(25.0 * kDeg), 1e-12));
}

TEST(CartesianMachine2, RejectsDegenerateMachines) {
  EXPECT_THROW(CartesianMachine2({0, 0}, {0, 0}, {1, 0}, {2, 0}), InputError);  // parallel
  EXPECT_THROW(CartesianMachine2({0, 0}, {0, 0}, {0, 0}, {0, 1}), InputError);  // zero
  EXPECT_THROW(CartesianMachine2({0, 0}, {0, 0}, {NAN, 0}, {0, 1}), InputError);
  EXPECT_THROW(CartesianMachine2({INFINITY, 0}, {0, 0}, {1, 0}, {0, 1}), InputError);
  try {
    CartesianMachine2({0, 0}, {0, 0}, {1, 0}, {-3, 0});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field 'directions'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("parallel"), std::string::npos) << e.what();
  }
  ActuatorErrors2 bad;
  bad.yAxisAngleDeg = 50.0;
  std::string why;
  EXPECT_FALSE(bad.isValid(&why));
  EXPECT_NE(why.find("45"), std::string::npos) << why;
  EXPECT_THROW(CartesianMachine2::fromErrors(bad), OptionsError);
  bad.yAxisAngleDeg = NAN;
  EXPECT_FALSE(bad.isValid(nullptr));
}

TEST(CartesianMachine3, ChainReducesToOzAndRoundTrips) {
  Rng rng(7);
  for (int trial = 0; trial < 30; ++trial) {
    Eigen::Matrix3d origins, dirs;
    for (int c = 0; c < 3; ++c) {
      origins.col(c) = Eigen::Vector3d(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
      dirs.col(c) = Eigen::Vector3d::Unit(c) +
                    0.2 * Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    }
    const CartesianMachine3 m(origins, dirs);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.directions().col(c).norm(), 1.0, 1e-14);
    const Eigen::Vector3d pr(rng.uniform(-300, 300), rng.uniform(-300, 300), rng.uniform(-300, 300));
    const Eigen::Vector3d p = m.forward(pr);
    EXPECT_LT((p - (origins.col(2) + m.directions() * pr)).norm(), 1e-10);
    EXPECT_LT((m.inverse(p) - pr).norm(), 1e-10);
    EXPECT_LT((m.forward(m.inverse(pr)) - pr).norm(), 1e-10);
  }
  EXPECT_EQ(CartesianMachine3().forward({1, 2, 3}), Eigen::Vector3d(1, 2, 3));
  Eigen::Matrix3d coplanar;
  coplanar << 1, 0, 1, 0, 1, 1, 0, 0, 0;
  EXPECT_THROW(CartesianMachine3(Eigen::Matrix3d::Zero(), coplanar), InputError);
}

// ---- Fig. 11: circle -> ellipse -> compensated references -> circle ----------------------------
// Table 3 of the paper (its parameters) is not in the text; the cases use the angles the text
// states: (a) X actuator 10 deg, Y actuator 15 deg clockwise; (b) Y actuator 15 deg clockwise;
// (c) position errors of the actuators (Oxr, Oyr away from the origin), no orientation error.

struct Fig11Case {
  const char* name;
  Eigen::Vector2d ox, oy;
  double aDeg, bDeg;
};

// A stable name in test listings (the default printer dumps the bytes, pointer included).
void PrintTo(const Fig11Case& c, std::ostream* os) {
  *os << c.name;
}

class Fig11 : public ::testing::TestWithParam<Fig11Case> {};

TEST_P(Fig11, CircleEllipseCompensatedCircle) {
  const Fig11Case& c = GetParam();
  const CartesianMachine2 m(c.ox, c.oy, dirAt(c.aDeg), dirAt(90.0 + c.bDeg));
  const double R = 50.0;
  const auto nominal = circle(Eigen::Vector2d::Zero(), R, 720);

  // Without compensation the machine follows o + M (circle): an ellipse with semi-axes R s_i,
  // s_i the singular values of M = [ir jr] (square roots of the eigenvalues of M M^T).
  const Eigen::Matrix2d M = m.directions();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M * M.transpose());
  const double sMin = std::sqrt(es.eigenvalues()(0)), sMax = std::sqrt(es.eigenvalues()(1));
  const auto uncompensated = runPath(m, nominal);
  const Eigen::Vector2d centre = m.forward(Eigen::Vector2d::Zero());
  const Eigen::Matrix2d Q = (M * M.transpose()).inverse();
  double rMin = 1e300, rMax = 0.0, devMax = 0.0;
  for (std::size_t k = 0; k < nominal.size(); ++k) {
    const Eigen::Vector2d d = uncompensated[k] - centre;
    EXPECT_NEAR(d.dot(Q * d), R * R, 1e-9 * R * R);  // on the ellipse
    rMin = std::min(rMin, d.norm());
    rMax = std::max(rMax, d.norm());
    devMax = std::max(devMax, (uncompensated[k] - nominal[k]).norm());
  }
  EXPECT_NEAR(rMax, R * sMax, 1e-3 * R);
  EXPECT_NEAR(rMin, R * sMin, 1e-3 * R);

  // Compensated references (Eq. 15) and the path they produce: the nominal circle.
  const auto refs = compensatePath(m, nominal);
  const auto compensated = runPath(m, refs);
  double after = 0.0;
  for (std::size_t k = 0; k < nominal.size(); ++k)
    after = std::max(after, (compensated[k] - nominal[k]).norm());
  EXPECT_LT(after, 1e-10);
  EXPECT_GT(devMax, 1.0);  // the errors are large (mm), so the test shows a real correction

  // The references form the inverse ellipse: semi-axes R / s_i about M^-1 (0 - o).
  const Eigen::Vector2d refCentre = m.inverse(Eigen::Vector2d::Zero());
  double qMin = 1e300, qMax = 0.0;
  for (const auto& r : refs) {
    qMin = std::min(qMin, (r - refCentre).norm());
    qMax = std::max(qMax, (r - refCentre).norm());
  }
  EXPECT_NEAR(qMax, R / sMin, 1e-3 * R);
  EXPECT_NEAR(qMin, R / sMax, 1e-3 * R);
  // "located in the opposite direction to the initial offset": the reference centre is -M^-1 o.
  const Eigen::Vector2d o = m.originY();
  EXPECT_LT((refCentre + M.inverse() * o).norm(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(PaperCases, Fig11,
                         ::testing::Values(Fig11Case{"a_x10_y15cw", {0, 0}, {0, 0}, 10.0, -15.0},
                                           Fig11Case{"b_y15cw", {0, 0}, {0, 0}, 0.0, -15.0},
                                           Fig11Case{"c_origins", {-8.0, 4.0}, {6.0, -5.0}, 0.0, 0.0},
                                           Fig11Case{"all", {-8.0, 4.0}, {6.0, -5.0}, 10.0, -15.0}),
                         [](const ::testing::TestParamInfo<Fig11Case>& info) {
                           return std::string(info.param.name);
                         });

TEST(Fig11, OriginErrorsAloneShiftTheCircleAndTheReferencesShiftBack) {
  // Case (c): with ir = i, jr = j the machine path is the circle moved by Oyr; the references are
  // the circle moved by -Oyr ("in the opposite direction to the initial offset").
  const Eigen::Vector2d ox(-8.0, 4.0), oy(6.0, -5.0);
  const CartesianMachine2 m(ox, oy, {1, 0}, {0, 1});
  const auto nominal = circle({20.0, 10.0}, 30.0, 90);
  const auto path = runPath(m, nominal);
  const auto refs = compensatePath(m, nominal);
  for (std::size_t k = 0; k < nominal.size(); ++k) {
    EXPECT_LT((path[k] - (nominal[k] + oy)).norm(), 1e-12);
    EXPECT_LT((refs[k] - (nominal[k] - oy)).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace metrofit
