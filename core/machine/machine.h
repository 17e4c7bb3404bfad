#pragma once
// 5-axis machine topologies and the adjustment values that move the workpiece coordinate system
// (WCS) onto the matched posture (Jiang et al., Mech. Sci. 9, 2018, Section 3, Eq. 12-13).
//
// Input: the posture p = R q + t of the workpiece (docs/file-formats.md#match-result, core/matching/pose.h),
// in the coordinates of the current WCS with the worktable as reference (the paper's "taking worktable as
// reference"). The nominal program is written in WCS coordinates q, so the adjusted WCS must have its
// origin at t and its axes along the columns of R: a nominal point q then lies at R q + t, on the
// workpiece. Linear axis values follow the ISO 841 convention (tool relative to the workpiece), so a
// table-carried X (the "X" before "F" in XFYZBA) counts like a head axis. Angles in degrees, mm.
//
// ---- XFYZBA head-head (table X; head Y, Z, B about y, A about x; the paper's example) ----
// Chain (Zhu et al. 2012, the paper's reference for Eq. 13): the B pivot sits on the Z slide, the A
// pivot at (0, 0, LAB) in the B frame, the cutter location point at (LX, LY, LZ) in the A frame. With
// Rot_x, Rot_y the 4x4 rotations and Tr(.) the 4x4 translations, the cutter location point CL and the
// tool axis at axis positions (SX, SY, SZ, SA, SB) are
//   Eq. (13)  CL = Tr(SX - LX, SY - LY, SZ - LZ - LAB) Rot_y(SB) Tr(0, 0, LAB) Rot_x(SA) Tr(LX, LY, LZ) [0 0
//   0 1]^T Eq. (12)  axis = Rot_y(SB) Rot_x(SA) [0 0 1 0]^T
// (the offsets in the first translation make CL = (SX, SY, SZ) at SA = SB = 0, i.e. the axis values
// are the cutter location point coordinates when the head is vertical). The printed Eq. (12)-(13) are
// garbled in the source text; the above is their reading, re-derived from this chain.
// The adjusted WCS needs CL = t and axis = R e_z (the tool along the WCS z axis):
//   Eq. (12): R e_z = (sin SB cos SA, -sin SA, cos SB cos SA)  =>  SA = asin(-c_y), SB = atan2(c_x, c_z),
//             c = R e_z (unique with |SA| <= 90 deg);
//   Eq. (13): (SX, SY, SZ) = t + (LX, LY, LZ + LAB) - R_y(SB) [(0, 0, LAB) + R_x(SA) (LX, LY, LZ)].
// Two rotary axes set the tool direction only; the rotation about the tool axis that remains,
//   Rot_z(phi) = (R_y(SB) R_x(SA))^T R,   phi = atan2(., .) of that matrix,
// is the control's coordinate rotation of the tilted working plane (HEIDENHAIN CYCL DEF 10 ROT,
// SINUMERIK ROT Z), reported as frame_rotation_deg. Then R = R_y(SB) R_x(SA) R_z(phi) exactly.
//
// ---- Table-table trunnions (AC: tilt A about x carrying C about z; BC: tilt B about y) ----
// The tool stays along the machine z axis; the table carries the workpiece. With a_0 a point on the
// tilt axis and c_0 a point on the C axis (both in WCS coordinates at the zero position), a table point
// x goes to the machine point
//   M(x) = a_0 + Rot_tilt(T) (c_0 - a_0 + Rot_z(C) (x - c_0)),   orientation  Q = Rot_tilt(T) Rot_z(C).
// The adjusted WCS must have its z axis along the tool: Q R e_z = e_z, i.e. R e_z = Rot_z(-C) Rot_tilt(-T)
// e_z:
//   AC: R e_z = (sin C sin T, cos C sin T, cos T),   BC: R e_z = (-cos C sin T, sin C sin T, cos T),
// so T = +-acos(c_z) and C from the in-plane direction of c; of the two solutions the one with
// |C| <= 90 deg is taken (C = 0 when c = e_z: the trunnion's pole). The linear axes then go to the new
// WCS origin (SX, SY, SZ) = M(t), and the remaining rotation about the tool, Rot_z(phi) = Q R, is again
// the control's coordinate rotation. Forward check: M(R q + t) = (SX, SY, SZ) + Rot_z(phi) q for every q.
//
// ---- Head-table (B swivel head about y, C rotary table about z; "head-table") ----
// The table turns the workpiece, the head tilts the tool: a table point x lies at the machine point
//   M(x) = c_0 + Rot_z(C) (x - c_0),   orientation Q = Rot_z(C),
// and the tool of a head whose B pivot is L above the cutter location point (L = pivot_mm, the pivot
// length) at axis values (SX, SY, SZ, B) has
//   CL = (SX, SY, SZ) + (0, 0, L) - Rot_y(B) (0, 0, L),   axis = Rot_y(B) e_z
// (CL = (SX, SY, SZ) at B = 0). The adjusted WCS needs its z axis along the tool: Q R e_z = Rot_y(B) e_z,
// i.e. c = R e_z = Rot_z(-C) (sin B, 0, cos B) = (cos C sin B, -sin C sin B, cos B), so
// B = +-acos(c_z), C = atan2(-c_y, c_x) for B >= 0 (the solution with |C| <= 90 deg is taken, as for the
// trunnions); the linear axes put CL on the new origin, (SX, SY, SZ) = M(t) - (0, 0, L) + Rot_y(B) (0,0,L),
// and the rotation left about the tool, Rot_z(phi) = Rot_y(B)^T Q R, is the control's coordinate rotation.
// Forward check: M(R q + t) = CL + Rot_y(B) Rot_z(phi) q for every q.
//
// Travel: the two rotary axes always have limits; the linear axes (SX, SY, SZ) optionally, in the
// coordinates of the adjustment values.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

namespace metrofit::machine {

enum class Topology {
  Xfyzba,     ///< head-head, the paper's example ("xfyzba")
  AcTable,    ///< table-table trunnion, A tilts about x and carries C ("ac-table")
  BcTable,    ///< table-table trunnion, B tilts about y and carries C ("bc-table")
  HeadTable,  ///< B swivel head about y, C rotary table about z ("head-table")
};

const char* topologyName(Topology t);
/// "xfyzba", "ac-table", "bc-table", "head-table".
std::vector<std::string> topologyNames();
/// OptionsError naming `field` and the known names when `name` is unknown.
Topology parseTopology(const std::string& name, const std::string& field);
/// Names of the two rotary axes in the order of Adjustment::rotaryDeg: A,B | A,C | B,C | B,C.
std::array<const char*, 2> rotaryAxisNames(Topology t);

/// A machine's geometry (lives in the project file under studies.matching.machine).
struct MachineDefinition {
  static constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  Topology topology = Topology::Xfyzba;
  // XFYZBA (Eq. 12-13), mm.
  double lx = 0.0, ly = 0.0, lz = -150.0;  ///< cutter location point in the A frame
  double lab = -100.0;                     ///< A origin (0, 0, LAB) in the B frame
  // Table-table, mm, WCS coordinates at the zero position.
  Eigen::Vector3d tiltAxisPoint{0.0, 0.0, -100.0};  ///< a_0, on the tilt axis (A: parallel x, B: parallel y)
  Eigen::Vector3d rotaryAxisPoint{0.0, 0.0, 0.0};   ///< c_0, on the C axis (parallel z at T = 0)
  // Head-table, mm: the B pivot's height above the cutter location point (the head's pivot length).
  double pivot = 150.0;
  // Travel of the two rotary axes (order of rotaryAxisNames), deg.
  std::array<double, 2> rotaryMinDeg{-120.0, -360.0};
  std::array<double, 2> rotaryMaxDeg{120.0, 360.0};
  // Travel of SX, SY, SZ, mm; +-infinity (the default) when not limited.
  std::array<double, 3> linearMinMm{-kUnlimited, -kUnlimited, -kUnlimited};
  std::array<double, 3> linearMaxMm{kUnlimited, kUnlimited, kUnlimited};

  bool isValid(std::string* why) const;
  /// {"topology": "xfyzba", "LX_mm": .., "LY_mm": .., "LZ_mm": .., "LAB_mm": ..,
  ///  "tilt_axis_point_mm": [x, y, z], "rotary_axis_point_mm": [x, y, z], "pivot_mm": ..,
  ///  "rotary_travel_deg": [[min, max], [min, max]],
  ///  "linear_travel_mm": [[min, max], [min, max], [min, max]] (only when limited; null = no limit)}
  nlohmann::json toJson() const;
  /// Missing keys keep their defaults; ValidationError naming `source` and the field otherwise.
  static MachineDefinition fromJson(const nlohmann::json& j, const std::string& source);
  static MachineDefinition preset(Topology t);
};

/// Adjustment values relative to the current WCS (zero for the identity posture).
struct Adjustment {
  Topology topology = Topology::Xfyzba;
  Eigen::Vector3d linearMm = Eigen::Vector3d::Zero();  ///< SX, SY, SZ
  std::array<double, 2> rotaryDeg{};                   ///< SA, SB | SA, SC | SB, SC
  double frameRotationDeg = 0.0;                       ///< phi, coordinate rotation about the tool axis
  bool withinTravel = true;
  std::string travelMessage;  ///< which axis is outside its travel, empty when within
};

/// Adjustment values for posture (R, t) (see above). R must be a rotation (det +1); the scale of a
/// fit is not realisable by a WCS and is not passed in.
Adjustment adjustmentFor(const MachineDefinition& machine, const Eigen::Matrix3d& R,
                         const Eigen::Vector3d& t);

/// The WCS the machine realises with `values`, in the current WCS's coordinates (forward chain).
struct Frame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d toolAxis = Eigen::Vector3d::UnitZ();  ///< tool direction in WCS coordinates
};
Frame realisedFrame(const MachineDefinition& machine, const Adjustment& values);

/// Eq. (12)-(13) forward, 4x4 homogeneous product as printed: cutter location point and tool axis of
/// the XFYZBA head at axis positions (SX, SY, SZ, SA, SB).
void headHeadForward(const MachineDefinition& machine, const Eigen::Vector3d& linearMm, double saDeg,
                     double sbDeg, Eigen::Vector3d* cutterLocation, Eigen::Vector3d* toolAxis);
/// Table-table forward: machine coordinates of table point x at tilt T and rotary C (see above).
Eigen::Vector3d tableToMachine(const MachineDefinition& machine, double tiltDeg, double cDeg,
                               const Eigen::Vector3d& x);
/// Head-table forward: cutter location point and tool axis of the B head at (SX, SY, SZ, B).
void headTableForward(const MachineDefinition& machine, const Eigen::Vector3d& linearMm, double bDeg,
                      Eigen::Vector3d* cutterLocation, Eigen::Vector3d* toolAxis);

/// {"topology": "xfyzba", "SX_mm": .., "SY_mm": .., "SZ_mm": .., "SA_deg": .., "SB_deg": ..,
///  "frame_rotation_deg": .., "within_travel": true} (rotary keys "S" + rotaryAxisNames + "_deg").
nlohmann::json adjustmentToJson(const Adjustment& a);

}  // namespace metrofit::machine
