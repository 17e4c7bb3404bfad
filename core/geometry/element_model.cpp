#include "core/geometry/element_model.h"

#include <Eigen/Geometry>
#include <cmath>

namespace metrofit::geometry {
namespace {

Eigen::Vector3d unitFromSlopes(double a, double b) {
  const Eigen::Vector3d v(a, b, 1.0);
  return v / v.norm();
}

/// The sign that makes the largest component positive.
Eigen::Vector3d largestPositive(const Eigen::Vector3d& v) {
  Eigen::Index i = 0;
  v.cwiseAbs().maxCoeff(&i);
  return v(i) < 0.0 ? Eigen::Vector3d(-v) : v;
}

}  // namespace

double elementResidual(const FittedElement& e, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = p - e.centre;
  switch (e.kind) {
    case ElementKind::Plane:
      return e.axis.dot(w);
    case ElementKind::Line:
      return (w - w.dot(e.axis) * e.axis).norm();
    case ElementKind::Circle:
      return (w - w.dot(e.axis) * e.axis).norm() - e.radiusMm;
    case ElementKind::Sphere:
      return w.norm() - e.radiusMm;
    case ElementKind::Cylinder:
      return (w - w.dot(e.axis) * e.axis).norm() - e.radiusMm;
    case ElementKind::Cone: {
      const double h = w.dot(e.axis);
      const double rho = (w - h * e.axis).norm();
      return (rho - e.radiusMm - h * std::tan(e.halfAngleRad)) * std::cos(e.halfAngleRad);
    }
  }
  return 0.0;
}

ElementFoot footOnElement(const FittedElement& e, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = p - e.centre;
  // A unit vector perpendicular to the axis, for a point on the axis.
  const auto anyPerpendicular = [&e] {
    const Eigen::Vector3d a = e.axis.cwiseAbs().minCoeff() == std::abs(e.axis.x()) ? Eigen::Vector3d::UnitX()
                                                                                   : Eigen::Vector3d::UnitY();
    return Eigen::Vector3d(a - a.dot(e.axis) * e.axis).normalized();
  };
  const auto radial = [&](const Eigen::Vector3d& v) {
    const Eigen::Vector3d r = v - v.dot(e.axis) * e.axis;
    // On the axis (to rounding: the radial part of a point on it is ~1e-16 of its distance) the
    // direction is undefined.
    return r.norm() > 1e-12 * (1.0 + v.norm()) ? Eigen::Vector3d(r / r.norm()) : anyPerpendicular();
  };
  ElementFoot f;
  switch (e.kind) {
    case ElementKind::Plane:
      f.normal = e.axis;
      break;
    case ElementKind::Line:
      f.hasNormal = false;
      f.point = e.centre + w.dot(e.axis) * e.axis;
      return f;
    case ElementKind::Circle:
    case ElementKind::Cylinder:
      f.normal = radial(w);
      break;
    case ElementKind::Sphere:
      f.normal = w.norm() > 1e-12 * (1.0 + e.centre.norm()) ? Eigen::Vector3d(w / w.norm())
                                                            : Eigen::Vector3d::UnitX();
      break;
    case ElementKind::Cone: {
      const double a = e.halfAngleRad;
      f.normal = std::cos(a) * radial(w) - std::sin(a) * e.axis;
      break;
    }
  }
  f.point = p - elementResidual(e, p) * f.normal;
  return f;
}

namespace detail {

ElementModel::ElementModel(ElementKind kind, double fixedRadius, const std::vector<Eigen::Vector3d>& points,
                           const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, double lengthScale)
    : kind_(kind), fixedR_(fixedRadius), o_(origin), F_(frame), L_(lengthScale) {
  q_.reserve(points.size());
  for (const auto& p : points) q_.push_back(F_.transpose() * (p - o_));
}

int ElementModel::size() const {
  const int f = fixedRadius() ? 1 : 0;
  switch (kind_) {
    case ElementKind::Plane:
      return 3;
    case ElementKind::Line:
      return 4;
    case ElementKind::Circle:
      return 3 - f;
    case ElementKind::Sphere:
      return 4 - f;
    case ElementKind::Cylinder:
      return 5 - f;
    case ElementKind::Cone:
      return 6;
  }
  return 0;
}

double ElementModel::residual(const Eigen::VectorXd& x, std::size_t i) const {
  const Eigen::Vector3d& q = q_[i];
  switch (kind_) {
    case ElementKind::Plane:
      return unitFromSlopes(x(0), x(1)).dot(q) - x(2);
    case ElementKind::Line: {
      const Eigen::Vector3d u = unitFromSlopes(x(2), x(3));
      const Eigen::Vector3d w = q - Eigen::Vector3d(x(0), x(1), 0.0);
      return (w - w.dot(u) * u).norm();
    }
    case ElementKind::Circle:
      return std::hypot(q.x() - x(0), q.y() - x(1)) - (fixedRadius() ? fixedR_ : x(2));
    case ElementKind::Sphere:
      return (q - x.head<3>()).norm() - (fixedRadius() ? fixedR_ : x(3));
    case ElementKind::Cylinder: {
      const Eigen::Vector3d u = unitFromSlopes(x(2), x(3));
      const Eigen::Vector3d w = q - Eigen::Vector3d(x(0), x(1), 0.0);
      return (w - w.dot(u) * u).norm() - (fixedRadius() ? fixedR_ : x(4));
    }
    case ElementKind::Cone: {
      const Eigen::Vector3d u = unitFromSlopes(x(2), x(3));
      const Eigen::Vector3d w = q - Eigen::Vector3d(x(0), x(1), 0.0);
      const double h = w.dot(u);
      const double rho = (w - h * u).norm();
      return (rho - x(4)) * std::cos(x(5)) - h * std::sin(x(5));
    }
  }
  return 0.0;
}

double ElementModel::scale(int j) const {
  switch (kind_) {
    case ElementKind::Plane:
      return j < 2 ? L_ : 1.0;
    case ElementKind::Line:
    case ElementKind::Cylinder:
      return j == 2 || j == 3 ? L_ : 1.0;
    case ElementKind::Cone:
      return j == 2 || j == 3 || j == 5 ? L_ : 1.0;
    case ElementKind::Circle:
    case ElementKind::Sphere:
      return 1.0;
  }
  return 1.0;
}

std::string ElementModel::role(int j) const {
  switch (kind_) {
    case ElementKind::Plane:
      return j < 2 ? "normal direction" : "offset";
    case ElementKind::Line:
      return j < 2 ? "position" : "direction";
    case ElementKind::Circle:
      return j < 2 ? "centre" : "radius";
    case ElementKind::Sphere:
      return j < 3 ? "centre" : "radius";
    case ElementKind::Cylinder:
      return j < 2 ? "axis position" : j < 4 ? "axis direction" : "radius";
    case ElementKind::Cone:
      return j < 2 ? "axis position" : j < 4 ? "axis direction" : j == 4 ? "radius" : "half angle";
  }
  return {};
}

FittedElement ElementModel::element(const Eigen::VectorXd& x) const {
  FittedElement e;
  e.kind = kind_;
  switch (kind_) {
    case ElementKind::Plane: {
      const Eigen::Vector3d n = unitFromSlopes(x(0), x(1));
      e.axis = largestPositive(F_ * n);
      e.centre = o_ + F_ * (x(2) * n);
      break;
    }
    case ElementKind::Line:
    case ElementKind::Cylinder: {
      const Eigen::Vector3d u = unitFromSlopes(x(2), x(3));
      const Eigen::Vector3d p0(x(0), x(1), 0.0);
      e.axis = largestPositive(F_ * u);
      e.centre = o_ + F_ * (p0 - p0.dot(u) * u);
      if (kind_ == ElementKind::Cylinder) e.radiusMm = fixedRadius() ? fixedR_ : x(4);
      break;
    }
    case ElementKind::Circle:
      e.axis = largestPositive(F_.col(2));
      e.centre = o_ + F_ * Eigen::Vector3d(x(0), x(1), 0.0);
      e.radiusMm = fixedRadius() ? fixedR_ : x(2);
      break;
    case ElementKind::Sphere:
      e.centre = o_ + F_ * x.head<3>();
      e.radiusMm = fixedRadius() ? fixedR_ : x(3);
      break;
    case ElementKind::Cone: {
      const Eigen::Vector3d u = unitFromSlopes(x(2), x(3));
      const Eigen::Vector3d p0(x(0), x(1), 0.0);
      const double h0 = -p0.dot(u);
      const double t = std::tan(x(5));
      e.centre = o_ + F_ * (p0 + h0 * u);
      e.radiusMm = x(4) + h0 * t;
      e.axis = t < 0.0 ? Eigen::Vector3d(-(F_ * u)) : Eigen::Vector3d(F_ * u);
      e.halfAngleRad = std::abs(x(5));
      const double ta = std::tan(e.halfAngleRad);
      e.apex = ta > 1e-9 ? Eigen::Vector3d(e.centre - (e.radiusMm / ta) * e.axis) : e.centre;
      break;
    }
  }
  return e;
}

}  // namespace detail
}  // namespace metrofit::geometry
