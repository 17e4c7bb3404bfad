#include "core/matching/pose.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "core/common/error.h"

namespace metrofit::matching {

const char* dofName(int dof) {
  static const char* const names[kDofCount] = {"rx", "ry", "rz", "x", "y", "z"};
  return dof >= 0 && dof < kDofCount ? names[dof] : "?";
}

bool DofLocks::any() const {
  for (bool l : locked)
    if (l) return true;
  return false;
}

bool DofLocks::anyRotation() const {
  return locked[0] || locked[1] || locked[2];
}

int DofLocks::freeCount() const {
  int n = 0;
  for (bool l : locked) n += l ? 0 : 1;
  return n;
}

DofLocks DofLocks::merged(const DofLocks& other) const {
  DofLocks m = *this;
  for (int i = 0; i < kDofCount; ++i) {
    if (other.locked[i]) {
      m.locked[i] = true;
      m.value[i] = other.value[i];
    }
  }
  return m;
}

std::string DofLocks::toString() const {
  std::string s;
  for (int i = 0; i < kDofCount; ++i) {
    if (!locked[i]) continue;
    if (!s.empty()) s += ',';
    s += dofName(i);
  }
  return s;
}

bool DofLocks::isValid(std::string* why) const {
  for (int i = 0; i < kDofCount; ++i) {
    if (!std::isfinite(value[i]) || (i < 3 && std::abs(value[i]) > 45.0)) {
      if (why)
        *why = std::string("locked value of ") + dofName(i) + " must be finite (angles within +-45 deg)";
      return false;
    }
  }
  return true;
}

DofLocks DofLocks::parse(const std::string& list, const std::string& field) {
  DofLocks locks;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::string name;
    for (char c : item) {
      if (!std::isspace(static_cast<unsigned char>(c)))
        name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (name.empty()) continue;
    int found = -1;
    for (int i = 0; i < kDofCount; ++i) {
      if (name == dofName(i)) found = i;
    }
    if (found < 0) {
      throw OptionsError(ErrorContext{{}, 0, 0, field},
                         "unknown degree of freedom '" + item + "' (one of rx, ry, rz, x, y, z)");
    }
    if (locks.locked[found]) {
      throw OptionsError(ErrorContext{{}, 0, 0, field},
                         std::string("'") + dofName(found) + "' is given twice");
    }
    locks.locked[found] = true;
  }
  return locks;
}

Eigen::Matrix3d rotationZyx(const Eigen::Vector3d& a) {
  const double cx = std::cos(a.x()), sx = std::sin(a.x());
  const double cy = std::cos(a.y()), sy = std::sin(a.y());
  const double cz = std::cos(a.z()), sz = std::sin(a.z());
  Eigen::Matrix3d R;
  R << cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx,  //
      sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx,   //
      -sy, cy * sx, cy * cx;
  return R;
}

Eigen::Vector3d eulerZyx(const Eigen::Matrix3d& R) {
  return {std::atan2(R(2, 1), R(2, 2)), std::atan2(-R(2, 0), std::hypot(R(2, 1), R(2, 2))),
          std::atan2(R(1, 0), R(0, 0))};
}

Eigen::Vector3d eulerZyxDeg(const Eigen::Matrix3d& R) {
  return eulerZyx(R) * kDegPerRad;
}

std::array<Eigen::Matrix3d, 3> rotationZyxDerivatives(const Eigen::Vector3d& a) {
  const double cx = std::cos(a.x()), sx = std::sin(a.x());
  const double cy = std::cos(a.y()), sy = std::sin(a.y());
  const double cz = std::cos(a.z()), sz = std::sin(a.z());
  Eigen::Matrix3d Rx, Ry, Rz, dRx, dRy, dRz;
  Rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  Ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  Rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  dRx << 0, 0, 0, 0, -sx, -cx, 0, cx, -sx;
  dRy << -sy, 0, cy, 0, 0, 0, -cy, 0, -sy;
  dRz << -sz, -cz, 0, cz, -sz, 0, 0, 0, 0;
  return {Rz * Ry * dRx, Rz * dRy * Rx, dRz * Ry * Rx};
}

Eigen::Vector3d Pose::anglesDeg() const {
  return eulerZyxDeg(rotation);
}

Pose Pose::compose(const Pose& o) const {
  Pose c;
  c.rotation = rotation * o.rotation;
  c.scale = scale * o.scale;
  c.translation = scale * (rotation * o.translation) + translation;
  return c;
}

Pose Pose::inverse() const {
  Pose inv;
  inv.rotation = rotation.transpose();
  inv.scale = 1.0 / scale;
  inv.translation = -(inv.scale * (inv.rotation * translation));
  return inv;
}

Pose Pose::fromAnglesDeg(const Eigen::Vector3d& deg, const Eigen::Vector3d& t, double s) {
  Pose p;
  p.rotation = rotationZyx(deg * kRadPerDeg);
  p.translation = t;
  p.scale = s;
  return p;
}

}  // namespace metrofit::matching
