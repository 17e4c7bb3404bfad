#pragma once
// The workpiece posture and its degrees of freedom (docs/file-formats.md#match-result).
//
// Posture: p = s R q + t, q the nominal point, p the measured one (mm), column vectors, with
//   R = Rz(rz) Ry(ry) Rx(rx)                       (rotation_deg = [rx, ry, rz], degrees)
// and s = 1 unless an isotropic scale is fitted.
//
// The matching paper (Jiang et al., Mech. Sci. 9, 2018, Eq. 1-5) writes row vectors and the
// *alignment* of the actual set onto the theoretical one, P' = P R0 + T0. In column vectors that is
// q ~ A p + T with A = R0^T, i.e. A is the inverse of the posture rotation: A = R^T, T = -R^T t.
// Its Eq. 4 matrix is (Rz(gamma) Ry(beta) Rx(alpha))^T, so the paper's angles (alpha, beta, gamma)
// are eulerZyxDeg(A) = eulerZyxDeg(R^T), while the match result's rotation_deg is eulerZyxDeg(R). For small
// rotations alpha ~ -rx, beta ~ -ry, gamma ~ -rz.
#include <array>
#include <string>

#include <Eigen/Core>

namespace metrofit::matching {

/// Degrees of freedom of a posture in the order of the match result (docs/file-formats.md#match-result): rx,
/// ry, rz (deg), x, y, z (mm).
enum class Dof { Rx = 0, Ry = 1, Rz = 2, X = 3, Y = 4, Z = 5 };
inline constexpr int kDofCount = 6;
/// "rx", "ry", "rz", "x", "y", "z".
const char* dofName(int dof);

/// Degree-of-freedom locks: a locked parameter keeps `value` (deg for angles, mm for translations;
/// 0 by default: "this axis is not adjusted"). Fits treat locks as constraints: the result is the
/// optimum over the free parameters, not a free optimum with the locked ones zeroed afterwards.
struct DofLocks {
  std::array<bool, kDofCount> locked{};
  std::array<double, kDofCount> value{};

  bool isLocked(Dof d) const { return locked[static_cast<int>(d)]; }
  void lock(Dof d, double v = 0.0) {
    locked[static_cast<int>(d)] = true;
    value[static_cast<int>(d)] = v;
  }
  bool any() const;
  bool anyRotation() const;
  int freeCount() const;
  /// Locks of both (values of `other` win where both lock).
  DofLocks merged(const DofLocks& other) const;
  /// "rx,z" (the locked names in that order), "" when none.
  std::string toString() const;
  /// Finite values, angles within +-45 deg.
  bool isValid(std::string* why) const;
  /// Parses "rx,ry,z" (names as dofName, case-insensitive, spaces allowed, each at most once);
  /// values 0. OptionsError naming `field` on an unknown or repeated name.
  static DofLocks parse(const std::string& list, const std::string& field);
};

struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  Eigen::Vector3d apply(const Eigen::Vector3d& q) const { return scale * (rotation * q) + translation; }
  /// [rx, ry, rz] in degrees (R = Rz Ry Rx).
  Eigen::Vector3d anglesDeg() const;
  /// x -> this(other(x)).
  Pose compose(const Pose& other) const;
  /// The inverse map (scale 1/s).
  Pose inverse() const;

  static Pose fromAnglesDeg(const Eigen::Vector3d& anglesDeg, const Eigen::Vector3d& translation,
                            double scale = 1.0);
};

/// R = Rz(a.z) Ry(a.y) Rx(a.x), angles in radians.
Eigen::Matrix3d rotationZyx(const Eigen::Vector3d& anglesRad);

/// The parameters the iterative fits (constrained closed form, minimax) work on: angles (rad),
/// translation (mm), scale; pose() builds the map p = s R q + t.
struct PoseParams {
  Eigen::Vector3d angles = Eigen::Vector3d::Zero();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  double s = 1.0;

  Pose pose() const {
    Pose p;
    p.rotation = rotationZyx(angles);
    p.translation = t;
    p.scale = s;
    return p;
  }
};
/// The angles (radians) of R = Rz Ry Rx: x = atan2(R21, R22), y = atan2(-R20, hypot(R21, R22)),
/// z = atan2(R10, R00) (0-based indices; the paper's Eq. 5 with atan2 instead of arctan so that the
/// quadrant is kept). Unique for |y| < 90 deg.
Eigen::Vector3d eulerZyx(const Eigen::Matrix3d& R);
Eigen::Vector3d eulerZyxDeg(const Eigen::Matrix3d& R);
/// dR/d(angle_j) of R = Rz Ry Rx at `anglesRad`, j = x, y, z.
std::array<Eigen::Matrix3d, 3> rotationZyxDerivatives(const Eigen::Vector3d& anglesRad);

inline constexpr double kDegPerRad = 57.295779513082320876798154814105;
inline constexpr double kRadPerDeg = 0.017453292519943295769236907684886;

}  // namespace metrofit::matching
