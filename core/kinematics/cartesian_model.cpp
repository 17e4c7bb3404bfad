#include "core/kinematics/cartesian_model.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/LU>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/run.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMinDet = 1e-9;

[[noreturn]] void badDirections(const std::string& what) {
  throw InputError(ErrorContext{{}, 0, 0, "directions"}, what);
}

template <class V>
V unitDirection(const V& v, const char* name) {
  if (!v.allFinite()) badDirections(std::string(name) + " is not finite");
  const double n = v.norm();
  if (!(n > 0.0)) badDirections(std::string(name) + " is the zero vector");
  return v / n;
}

}  // namespace

Eigen::Vector2d ActuatorErrors2::xDirection() const {
  const double a = xAxisAngleDeg * kDeg;
  return {std::cos(a), std::sin(a)};
}

Eigen::Vector2d ActuatorErrors2::yDirection() const {
  const double b = yAxisAngleDeg * kDeg;
  return {-std::sin(b), std::cos(b)};
}

bool ActuatorErrors2::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!originMm.allFinite()) return no("origin_mm must be finite");
  if (!std::isfinite(xAxisAngleDeg) || !std::isfinite(yAxisAngleDeg)) return no("axis angles must be finite");
  if (std::abs(xAxisAngleDeg) > kMaxAngleDeg || std::abs(yAxisAngleDeg) > kMaxAngleDeg) {
    char buf[160];
    metrofit::c_snprintf(
        buf, sizeof buf,
        "axis angles must be within +-45 deg (orientation errors of the actuators), got a = %g, b = %g",
        xAxisAngleDeg, yAxisAngleDeg);
    return no(buf);
  }
  return true;
}

// ---- 2D ---------------------------------------------------------------------------------------

CartesianMachine2::CartesianMachine2()
    : ox_(Eigen::Vector2d::Zero()),
      oy_(Eigen::Vector2d::Zero()),
      ir_(Eigen::Vector2d::UnitX()),
      jr_(Eigen::Vector2d::UnitY()),
      inv_(Eigen::Matrix2d::Identity()) {}

CartesianMachine2::CartesianMachine2(const Eigen::Vector2d& originX, const Eigen::Vector2d& originY,
                                     const Eigen::Vector2d& dirX, const Eigen::Vector2d& dirY)
    : ox_(originX), oy_(originY), ir_(unitDirection(dirX, "ir")), jr_(unitDirection(dirY, "jr")) {
  if (!ox_.allFinite() || !oy_.allFinite()) throw InputError(ErrorContext{{}, 0, 0, "origins"}, "not finite");
  const Eigen::Matrix2d m = directions();
  if (std::abs(m.determinant()) < kMinDet) badDirections("ir and jr are parallel (det [ir jr] = 0)");
  inv_ = m.inverse();
}

CartesianMachine2 CartesianMachine2::fromErrors(const ActuatorErrors2& e) {
  requireValid(e, "actuator errors");
  return CartesianMachine2(e.originMm, e.originMm, e.xDirection(), e.yDirection());
}

ActuatorErrors2 CartesianMachine2::errors() const {
  ActuatorErrors2 e;
  e.originMm = oy_;
  e.xAxisAngleDeg = std::atan2(ir_.y(), ir_.x()) / kDeg;
  e.yAxisAngleDeg = std::atan2(-jr_.x(), jr_.y()) / kDeg;
  return e;
}

Eigen::Matrix2d CartesianMachine2::directions() const {
  Eigen::Matrix2d m;
  m.col(0) = ir_;
  m.col(1) = jr_;
  return m;
}

Eigen::Vector2d CartesianMachine2::intersectionDistances() const {
  Eigen::Matrix2d a;  // [-ir  jr] (Eq. 5)
  a.col(0) = -ir_;
  a.col(1) = jr_;
  return a.inverse() * originOffset();  // Eq. 6
}

Eigen::Vector2d CartesianMachine2::intersectionPoint() const {
  return ox_ - intersectionDistances().x() * ir_;
}

Eigen::Vector2d CartesianMachine2::forward(const Eigen::Vector2d& pr) const {
  return ox_ + ir_ * pr.x() + originOffset() + jr_ * pr.y();  // Eq. 9
}

Eigen::Vector2d CartesianMachine2::inverse(const Eigen::Vector2d& p) const {
  return inv_ * (p - ox_ - originOffset());  // Eq. 15
}

// ---- 3 axes -----------------------------------------------------------------------------------

CartesianMachine3::CartesianMachine3()
    : origins_(Eigen::Matrix3d::Zero()),
      directions_(Eigen::Matrix3d::Identity()),
      inv_(Eigen::Matrix3d::Identity()) {}

CartesianMachine3::CartesianMachine3(const Eigen::Matrix3d& origins, const Eigen::Matrix3d& directions)
    : origins_(origins) {
  if (!origins_.allFinite()) throw InputError(ErrorContext{{}, 0, 0, "origins"}, "not finite");
  directions_.col(0) = unitDirection(Eigen::Vector3d(directions.col(0)), "i");
  directions_.col(1) = unitDirection(Eigen::Vector3d(directions.col(1)), "j");
  directions_.col(2) = unitDirection(Eigen::Vector3d(directions.col(2)), "k");
  if (std::abs(directions_.determinant()) < kMinDet)
    badDirections("i, j and k are coplanar (det [i j k] = 0)");
  inv_ = directions_.inverse();
}

Eigen::Vector3d CartesianMachine3::forward(const Eigen::Vector3d& pr) const {
  const Eigen::Vector3d ox = origins_.col(0), oy = origins_.col(1), oz = origins_.col(2);
  return ox + directions_.col(0) * pr.x() + (oy - ox) + directions_.col(1) * pr.y() + (oz - oy) +
         directions_.col(2) * pr.z();
}

Eigen::Vector3d CartesianMachine3::inverse(const Eigen::Vector3d& p) const {
  return inv_ * (p - origins_.col(2));
}

// ---- paths ------------------------------------------------------------------------------------

std::vector<Eigen::Vector2d> compensatePath(const CartesianMachine2& machine,
                                            const std::vector<Eigen::Vector2d>& nominal) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(nominal.size());
  for (const auto& p : nominal) out.push_back(machine.inverse(p));
  return out;
}

std::vector<Eigen::Vector2d> runPath(const CartesianMachine2& machine,
                                     const std::vector<Eigen::Vector2d>& commands) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(commands.size());
  for (const auto& c : commands) out.push_back(machine.forward(c));
  return out;
}

}  // namespace metrofit
