// footOnElement (core/geometry/element_fit.h): the foot and normal of a point on each element, against
// the closed forms written here (the foot on a sphere is c + r (p - c)/|p - c|, ...), and the identity
// p = foot + d n with d the element's residual, which nominals from a fitted element rely on
// (core/project/nominals.h: the deviation along the normal is the fit's residual).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/common/rng.h"
#include "core/geometry/element_fit.h"

namespace metrofit::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

FittedElement element(ElementKind kind) {
  FittedElement e;
  e.kind = kind;
  e.centre = Eigen::Vector3d(12.0, -4.0, 7.5);
  e.axis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  e.radiusMm = kind == ElementKind::Plane || kind == ElementKind::Line ? 0.0 : 25.0;
  if (kind == ElementKind::Cone) e.halfAngleRad = 20.0 * kPi / 180.0;
  return e;
}

TEST(ElementFoot, PointEqualsFootPlusResidualAlongTheNormal) {
  Rng rng(11);
  for (ElementKind kind : {ElementKind::Plane, ElementKind::Line, ElementKind::Circle, ElementKind::Sphere,
                           ElementKind::Cylinder, ElementKind::Cone}) {
    const FittedElement e = element(kind);
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d p =
          e.centre + Eigen::Vector3d(rng.uniform(-40, 40), rng.uniform(-40, 40), rng.uniform(-15, 15));
      const ElementFoot f = footOnElement(e, p);
      const double d = elementResidual(e, p);
      if (kind == ElementKind::Line) {
        EXPECT_FALSE(f.hasNormal);
        EXPECT_NEAR((p - f.point).norm(), d, 1e-9);
        EXPECT_NEAR((f.point - e.centre).cross(e.axis).norm(), 0.0, 1e-9);  // on the axis
        continue;
      }
      ASSERT_TRUE(f.hasNormal);
      EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12) << toString(kind);
      EXPECT_LT((p - (f.point + d * f.normal)).norm(), 1e-9) << toString(kind) << " point " << i;
      EXPECT_NEAR(elementResidual(e, f.point), 0.0, 1e-9) << toString(kind);  // the foot is on the element
    }
  }
}

TEST(ElementFoot, ClosedFormsOfSphereCylinderPlaneAndCone) {
  const Eigen::Vector3d p(40.0, 3.0, -2.0);
  {
    const FittedElement s = element(ElementKind::Sphere);
    const Eigen::Vector3d u = (p - s.centre).normalized();
    const ElementFoot f = footOnElement(s, p);
    EXPECT_LT((f.point - (s.centre + 25.0 * u)).norm(), 1e-12);
    EXPECT_LT((f.normal - u).norm(), 1e-12);
  }
  {
    const FittedElement c = element(ElementKind::Cylinder);
    const Eigen::Vector3d w = p - c.centre;
    const Eigen::Vector3d radial = (w - w.dot(c.axis) * c.axis).normalized();
    const ElementFoot f = footOnElement(c, p);
    EXPECT_LT((f.point - (c.centre + w.dot(c.axis) * c.axis + 25.0 * radial)).norm(), 1e-12);
    EXPECT_LT((f.normal - radial).norm(), 1e-12);
  }
  {
    const FittedElement pl = element(ElementKind::Plane);
    const ElementFoot f = footOnElement(pl, p);
    EXPECT_LT((f.point - (p - pl.axis.dot(p - pl.centre) * pl.axis)).norm(), 1e-12);
    EXPECT_LT((f.normal - pl.axis).norm(), 1e-12);
  }
  {
    // The cone's normal is perpendicular to its surface line through the foot (the generator from the
    // apex), not radial.
    const FittedElement k = element(ElementKind::Cone);
    FittedElement withApex = k;
    const ElementFoot f = footOnElement(k, p);
    const double h = (f.point - k.centre).dot(k.axis);
    const Eigen::Vector3d w = f.point - k.centre;
    const Eigen::Vector3d radial = (w - h * k.axis).normalized();
    const Eigen::Vector3d generator =
        (std::cos(k.halfAngleRad) * k.axis + std::sin(k.halfAngleRad) * radial).normalized();
    EXPECT_NEAR(f.normal.dot(generator), 0.0, 1e-12);
    EXPECT_NEAR(f.normal.dot(k.axis), -std::sin(k.halfAngleRad), 1e-12);  // outwards and towards the apex
    (void)withApex;
  }
}

TEST(ElementFoot, PointOnTheAxisGetsAPerpendicularUnitNormal) {
  const FittedElement c = element(ElementKind::Cylinder);
  const ElementFoot f = footOnElement(c, c.centre + 3.0 * c.axis);
  EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(f.normal.dot(c.axis), 0.0, 1e-12);
  EXPECT_TRUE(f.point.allFinite());
}

}  // namespace
}  // namespace metrofit::geometry
