// The least-squares element fits against an independent implementation in the same run: Eigen's
// unsupported LevenbergMarquardt (MINPACK's lmder) with numerical derivatives, on noisy points, with
// its own parametrisations (a point and an unnormalised direction for the axis, the apex for the
// cone), started near the truth. Both must reach the same minimum of the sum of squared orthogonal
// distances: equal cost, equal element.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include "core/common/rng.h"
#include "core/geometry/element_fit.h"

namespace metrofit::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Functor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  using QRSolver = Eigen::ColPivHouseholderQR<JacobianType>;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  const std::vector<Eigen::Vector3d>* p = nullptr;
  int params = 0;
  std::function<double(const Eigen::VectorXd&, const Eigen::Vector3d&)> d;
  int inputs() const { return params; }
  int values() const { return static_cast<int>(p->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    for (std::size_t i = 0; i < p->size(); ++i) f(static_cast<Eigen::Index>(i)) = d(x, (*p)[i]);
    return 0;
  }
};

Eigen::VectorXd eigenLm(Functor f, Eigen::VectorXd x) {
  Eigen::NumericalDiff<Functor, Eigen::Central> nd(f);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Functor, Eigen::Central>> lm(nd);
  lm.setXtol(1e-14);
  lm.setFtol(1e-14);
  lm.setMaxfev(20000);
  lm.minimize(x);
  return x;
}

double cost(const ElementFitResult& r) {
  double s = 0.0;
  for (double d : r.residualsMm) s += d * d;
  return s;
}

double axisAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}

std::vector<Eigen::Vector3d> noisyAround(const Eigen::Vector3d& axis,
                                         const std::function<double(double)>& radiusAt, std::uint64_t seed,
                                         double sigma) {
  Rng rng(seed);
  const Eigen::Vector3d u = axis.normalized();
  const Eigen::Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 60; ++i) {
    const double h = 10.0 + 0.8 * i, ph = 2.0 * kPi * i / 7.3;
    const double r = radiusAt(h) + sigma * rng.normal();
    p.push_back(Eigen::Vector3d(3, -4, 5) + h * u + r * (std::cos(ph) * e1 + std::sin(ph) * e2));
  }
  return p;
}

TEST(IndependentFit, CylinderMatchesEigenLevenbergMarquardt) {
  const Eigen::Vector3d axis(0.2, 0.5, 1.0);
  const auto p = noisyAround(
      axis, [](double) { return 15.0; }, 21, 0.01);
  ElementFitOptions o;
  o.element = ElementKind::Cylinder;
  const ElementFitResult ours = fitElement(PointSet{"cyl", p}, o);
  Functor f;
  f.p = &p;
  f.params = 7;  // point P, direction v (unnormalised), r
  f.d = [](const Eigen::VectorXd& x, const Eigen::Vector3d& q) {
    const Eigen::Vector3d P = x.head<3>(), v = x.segment<3>(3).normalized();
    const Eigen::Vector3d w = q - P;
    return (w - w.dot(v) * v).norm() - x(6);
  };
  Eigen::VectorXd x0(7);
  x0 << 3.1, -4.1, 5.1, 0.21, 0.49, 1.0, 14.9;
  const Eigen::VectorXd x = eigenLm(f, x0);
  double refCost = 0.0;
  for (const auto& q : p) refCost += std::pow(f.d(x, q), 2);
  const Eigen::Vector3d refAxis = x.segment<3>(3).normalized();
  EXPECT_NEAR(cost(ours), refCost, 1e-10 * refCost);
  EXPECT_LT(axisAngle(ours.element.axis, refAxis), 1e-6);
  EXPECT_NEAR(ours.element.radiusMm, x(6), 1e-6);
  const Eigen::Vector3d w = ours.element.centre - x.head<3>();
  EXPECT_LT((w - w.dot(refAxis) * refAxis).norm(), 1e-6);
}

TEST(IndependentFit, ConeMatchesEigenLevenbergMarquardt) {
  const Eigen::Vector3d axis(-0.3, 0.1, 1.0);
  const double t = std::tan(25.0 * kPi / 180.0);
  const auto p = noisyAround(
      axis, [t](double h) { return 5.0 + h * t; }, 22, 0.01);
  ElementFitOptions o;
  o.element = ElementKind::Cone;
  const ElementFitResult ours = fitElement(PointSet{"cone", p}, o);
  Functor f;
  f.p = &p;
  f.params = 7;  // apex A, direction v (unnormalised, towards the opening), half angle
  f.d = [](const Eigen::VectorXd& x, const Eigen::Vector3d& q) {
    const Eigen::Vector3d A = x.head<3>(), v = x.segment<3>(3).normalized();
    const Eigen::Vector3d w = q - A;
    const double h = w.dot(v), rho = (w - h * v).norm();
    return (rho - h * std::tan(x(6))) * std::cos(x(6));
  };
  const Eigen::Vector3d u = axis.normalized();
  const Eigen::Vector3d apex = Eigen::Vector3d(3, -4, 5) - (5.0 / t) * u;
  Eigen::VectorXd x0(7);
  x0 << apex.x() + 0.1, apex.y() - 0.1, apex.z(), u.x() + 0.01, u.y(), u.z(), 25.5 * kPi / 180.0;
  const Eigen::VectorXd x = eigenLm(f, x0);
  double refCost = 0.0;
  for (const auto& q : p) refCost += std::pow(f.d(x, q), 2);
  EXPECT_NEAR(cost(ours), refCost, 1e-9 * refCost);
  EXPECT_LT(axisAngle(ours.element.axis, x.segment<3>(3)), 1e-6);
  EXPECT_NEAR(ours.element.halfAngleRad, x(6), 1e-7);
  EXPECT_LT((ours.element.apex - x.head<3>()).norm(), 1e-4);
}

TEST(IndependentFit, SphereMatchesEigenLevenbergMarquardt) {
  Rng rng(23);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 40; ++i) {
    const double th = 1.2 * i / 40.0, ph = 2.0 * kPi * i / 6.7, r = 40.0 + 0.02 * rng.normal();
    p.emplace_back(1 + r * std::sin(th) * std::cos(ph), 2 + r * std::sin(th) * std::sin(ph),
                   3 + r * std::cos(th));
  }
  ElementFitOptions o;
  o.element = ElementKind::Sphere;
  const ElementFitResult ours = fitElement(PointSet{"sph", p}, o);
  Functor f;
  f.p = &p;
  f.params = 4;
  f.d = [](const Eigen::VectorXd& x, const Eigen::Vector3d& q) { return (q - x.head<3>()).norm() - x(3); };
  Eigen::VectorXd x0(4);
  x0 << 1.5, 1.5, 3.5, 39.0;
  const Eigen::VectorXd x = eigenLm(f, x0);
  EXPECT_LT((ours.element.centre - x.head<3>()).norm(), 1e-6);
  EXPECT_NEAR(ours.element.radiusMm, x(3), 1e-6);
}

}  // namespace
}  // namespace metrofit::geometry
