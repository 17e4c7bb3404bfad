#pragma once
// The Cartesian machine model of the kinematic-compensation paper (IEEE Access, kinematic compensation
// algorithm, Section IV), in 2D as the paper and with three axes for real machines. Lengths in mm, angles in
// degrees at the API.
//
// 2D (paper Eq. 1-15). The X actuator starts at Oxr and moves along the unit vector ir; the Y
// actuator, carried by the X actuator (serial chain, X first), starts at Oyr and moves along jr:
//   Oxr = [Oxri, Oxrj]^T, Oyr = [Oyri, Oyrj]^T, ir = [irx, iry]^T, jr = [jrx, jry]^T   (Eq. 1)
//   dOr = Oyr - Oxr                                                                     (Eq. 2)
// The actuator axes (the lines Oxr + s ir and Oyr + t jr) meet at the intersection point I; with
// the signed distances mx, my of the paper
//   -mx ir + my jr = dOr                                                            (Eq. 3, 4)
//   [-ir  jr] [mx my]^T = dOr   =>   [mx my]^T = [-ir  jr]^-1 dOr                   (Eq. 5, 6)
//   I = Oxr - mx ir = Oyr - my jr.
// Joint (actuator) coordinates Pr = [Pir, Pjr]^T (Eq. 7), tool position P = [Pi, Pj]^T (Eq. 8):
//   direct kinematics   P  = Oxr + ir Pir + dOr + jr Pjr                                (Eq. 9)
//   inverse kinematics  Pr = [ir jr]^-1 (P - Oxr - dOr)                         (Eq. 10-15)
// Reading of Eq. 9: Oxr + dOr = Oyr, so P = Oyr + [ir jr] Pr. Only Oyr (the point the tool reaches
// at Pr = 0) is observable from tool positions; Oxr alone only moves the intersection point.
//
// The error parameters of docs/file-formats.md#kinematic-identify-result are exactly the observable ones:
//   origin o = Oyr (origin_mm), ir = (cos a, sin a) (x_axis_angle_deg a),
//   jr = (-sin b, cos b) (y_axis_angle_deg b), squareness error = b - a,
// so that P = o + [ir jr] Pr and Pr = [ir jr]^-1 (P - o); det [ir jr] = cos(b - a).
// A positive angle turns an axis counter-clockwise; "measured clockwise" in the paper is negative.
//
// Three axes: actuators X, Y, Z with origins Ox, Oy, Oz and unit directions i, j, k, serial chain
// X -> Y -> Z. Eq. 9 extends to
//   P = Ox + i Px + (Oy - Ox) + j Py + (Oz - Oy) + k Pz = Oz + [i j k] Pr
// and Eq. 15 to Pr = [i j k]^-1 (P - Oz). identification3.h identifies it from circular tests in the XY,
// YZ and ZX planes (ActuatorErrors3::machine()).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace metrofit {

/// The 2D actuator errors as docs/file-formats.md#kinematic-identify-result parametrises them (see the header
/// comment).
struct ActuatorErrors2 {
  Eigen::Vector2d originMm = Eigen::Vector2d::Zero();  ///< o = Oyr: where the tool is at Pr = 0
  double xAxisAngleDeg = 0.0;                          ///< a: ir = (cos a, sin a)
  double yAxisAngleDeg = 0.0;                          ///< b: jr = (-sin b, cos b)

  /// Squareness error b - a (deg): the angle between ir and jr is 90 deg + (b - a).
  double squarenessDeg() const { return yAxisAngleDeg - xAxisAngleDeg; }
  Eigen::Vector2d xDirection() const;  ///< ir
  Eigen::Vector2d yDirection() const;  ///< jr
  /// Finite values, |a| and |b| at most kMaxAngleDeg (an orientation error, not a rotated machine).
  bool isValid(std::string* why) const;

  static constexpr double kMaxAngleDeg = 45.0;
};

/// The 2D machine of Section IV with both actuator origins (Eq. 1-15).
class CartesianMachine2 {
 public:
  /// The ideal machine: Oxr = Oyr = 0, ir = (1, 0), jr = (0, 1).
  CartesianMachine2();
  /// Directions are normalised; InputError (field 'directions') when one is zero, not finite, or
  /// the two are parallel (|det [ir jr]| < 1e-9).
  CartesianMachine2(const Eigen::Vector2d& originX, const Eigen::Vector2d& originY,
                    const Eigen::Vector2d& dirX, const Eigen::Vector2d& dirY);
  /// The machine of the identify result's errors (docs/file-formats.md#kinematic-identify-result), with Oxr =
  /// Oyr = o (so dOr = 0); throws OptionsError when `errors` is invalid.
  static CartesianMachine2 fromErrors(const ActuatorErrors2& errors);

  /// The observable errors: origin Oyr, a = atan2(iry, irx), b = atan2(-jrx, jry).
  ActuatorErrors2 errors() const;

  const Eigen::Vector2d& originX() const { return ox_; }  ///< Oxr
  const Eigen::Vector2d& originY() const { return oy_; }  ///< Oyr
  const Eigen::Vector2d& dirX() const { return ir_; }     ///< ir
  const Eigen::Vector2d& dirY() const { return jr_; }     ///< jr
  /// The non-orthogonal transformation matrix [ir jr] (Eq. 13).
  Eigen::Matrix2d directions() const;
  /// dOr = Oyr - Oxr (Eq. 2).
  Eigen::Vector2d originOffset() const { return oy_ - ox_; }
  /// [mx, my] of Eq. 6.
  Eigen::Vector2d intersectionDistances() const;
  /// The intersection point I = Oxr - mx ir of the actuator axes (Eq. 3-6).
  Eigen::Vector2d intersectionPoint() const;

  /// Direct kinematics, Eq. 9: tool position P for joint coordinates Pr.
  Eigen::Vector2d forward(const Eigen::Vector2d& joints) const;
  /// Inverse kinematics, Eq. 15: joint coordinates Pr that put the tool at P.
  Eigen::Vector2d inverse(const Eigen::Vector2d& position) const;

 private:
  Eigen::Vector2d ox_, oy_, ir_, jr_;
  Eigen::Matrix2d inv_;  ///< [ir jr]^-1
};

/// The three-axis Cartesian machine (serial chain X -> Y -> Z), see the header comment.
class CartesianMachine3 {
 public:
  /// The ideal machine: all origins 0, directions the unit axes.
  CartesianMachine3();
  /// origins: columns Ox, Oy, Oz; directions: columns i, j, k (normalised here). InputError (field
  /// 'directions') when a direction is zero or not finite or the three are (nearly) coplanar
  /// (|det| < 1e-9).
  CartesianMachine3(const Eigen::Matrix3d& origins, const Eigen::Matrix3d& directions);

  const Eigen::Matrix3d& origins() const { return origins_; }        ///< columns Ox, Oy, Oz
  const Eigen::Matrix3d& directions() const { return directions_; }  ///< columns i, j, k
  /// The point the tool reaches at Pr = 0: Oz (the chain's sum Ox + (Oy - Ox) + (Oz - Oy)).
  Eigen::Vector3d effectiveOrigin() const { return origins_.col(2); }

  /// P = Ox + i Px + (Oy - Ox) + j Py + (Oz - Oy) + k Pz (Eq. 9 in three axes).
  Eigen::Vector3d forward(const Eigen::Vector3d& joints) const;
  /// Pr = [i j k]^-1 (P - Oz) (Eq. 15 in three axes).
  Eigen::Vector3d inverse(const Eigen::Vector3d& position) const;

 private:
  Eigen::Matrix3d origins_, directions_, inv_;
};

/// Compensated references (Section IV, Eq. 15): for every nominal point P the command Pr with
/// forward(Pr) = P, so the modelled machine lands on the nominal path.
std::vector<Eigen::Vector2d> compensatePath(const CartesianMachine2& machine,
                                            const std::vector<Eigen::Vector2d>& nominal);
/// The path the modelled machine follows for the given commands (Eq. 9 for every point).
std::vector<Eigen::Vector2d> runPath(const CartesianMachine2& machine,
                                     const std::vector<Eigen::Vector2d>& commands);

}  // namespace metrofit
