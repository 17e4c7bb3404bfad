#pragma once
// Identification of the three-axis actuator errors from circular tests in the XY, YZ and ZX planes
// (the Cartesian model of IEEE Access, kinematic compensation algorithm; Eq. 9 in three axes as in
// cartesian_model.h; the paper itself runs the 2D machine only). Lengths in mm, angles in degrees at the API.
//
// Planes and their in-plane axes (u, v), each a right-handed pair as XY is:
//   XY: (x, y)    YZ: (y, z)    ZX: (z, x)
// A circular test in a plane commands (u, v) with the third coordinate 0 and measures the tool's
// (u, v); its CSV is u_cmd_mm,v_cmd_mm,u_meas_mm,v_meas_mm with the plane's letters (XY:
// x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm as docs/file-formats.md#circular-test; YZ:
// y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm; ZX: z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm).
//
// Errors. As in 2D, a plane's u axis is seen at the angle a from u, its v axis at b from v (CCW
// in the plane positive): the projection of the u actuator's direction onto the plane is
// (cos a, sin a), of the v actuator's (-sin b, cos b). Each actuator appears in two planes, so the
// six angles are
//   X: a_xy (towards +y) and b_zx (towards -z);  Y: b_xy (towards -x) and a_yz (towards +z);
//   Z: a_zx (towards +x) and b_yz (towards -y),
// and the unit directions of the three-axis model are
//   i = n(1, tan a_xy, -tan b_zx),  j = n(-tan b_xy, 1, tan a_yz),  k = n(tan a_zx, -tan b_yz, 1)
// (n: normalised). Squareness in a plane is b - a (deg) as in 2D: S_xy = b_xy - a_xy,
// S_yz = b_yz - a_yz, S_zx = b_zx - a_zx. Origin o = Oz (cartesian_model.h: P = Oz + [i j k] Pr).
//
// Fit. theta = (o_x, o_y, o_z, a_xy, b_xy, a_yz, b_yz, a_zx, b_zx) minimises the sum over the
// three tests of |(P(Pr; theta))_(u,v) - Pmeas|^2, P = o + [i j k] Pr, by Levenberg-Marquardt
// (core/optim/least_squares.h: Eigen LDLT of J^T J + lambda D^T D with Marquardt's scaling D,
// central-difference Jacobian, Nielsen's damping update);
// the start is the 2D identification of every plane (identification.h: the angles directly, each
// origin component the mean of the two planes that see it). Every origin component is seen by two
// planes, every angle by one: nine parameters from twelve plane parameters.
// Uncertainty: Cov = s^2 (J^T J)^-1, s^2 = SSE / (2N - 9), N points in all three tests.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/common/run.h"
#include "core/io/csv.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {

enum class TestPlane { XY = 0, YZ = 1, ZX = 2 };
inline constexpr std::array<TestPlane, 3> kTestPlanes{TestPlane::XY, TestPlane::YZ, TestPlane::ZX};

/// "xy", "yz", "zx".
const char* planeName(TestPlane plane);
/// Machine axis indices (0 = x, 1 = y, 2 = z) of the plane's u and v.
std::array<int, 2> planeAxes(TestPlane plane);
/// The plane's CSV columns: {u_cmd_mm, v_cmd_mm, u_meas_mm, v_meas_mm} with its letters.
std::array<std::string, 4> planeColumns(TestPlane plane);

/// A plane's circular test from CSV (columns of planeColumns; the path holds (u, v)).
MeasuredPath planePathFromCsv(const CsvTable& table, TestPlane plane);
MeasuredPath readPlanePath(const std::string& path, TestPlane plane, const CsvReadOptions& csv = {});
std::string planePathToCsv(const MeasuredPath& path, TestPlane plane);

/// The three-axis actuator errors (see the header comment).
struct ActuatorErrors3 {
  Eigen::Vector3d originMm = Eigen::Vector3d::Zero();
  std::array<double, 3> uAngleDeg{0.0, 0.0, 0.0};  ///< a_xy, a_yz, a_zx (index: TestPlane)
  std::array<double, 3> vAngleDeg{0.0, 0.0, 0.0};  ///< b_xy, b_yz, b_zx

  double squarenessDeg(TestPlane p) const {
    return vAngleDeg[static_cast<int>(p)] - uAngleDeg[static_cast<int>(p)];
  }
  /// Columns i, j, k (unit vectors).
  Eigen::Matrix3d directions() const;
  /// The model: all origins o (only Oz is observable), directions().
  CartesianMachine3 machine() const;
  /// The 2D errors a test in `plane` sees (its u, v origin components and angles).
  ActuatorErrors2 inPlane(TestPlane plane) const;
  /// Finite values, every angle within +-45 deg.
  bool isValid(std::string* why) const;

  /// A plausible machine for the simulator: origin (4, -3, 2) um, a few arcsec per axis, squareness
  /// -0.0026 deg (XY), +0.0015 deg (YZ), -0.0010 deg (ZX).
  static ActuatorErrors3 plausible();
};

struct Identify3Options {
  long maxIterations = 100;
  double costTolerance = 1e-14;  ///< converged when a step lowers SSE by less than this fraction
  double initialDamping = 1e-3;
  bool keepTrace = false;

  bool isValid(std::string* why) const;
};

struct PlaneFit3 {
  std::string source;
  std::size_t points = 0;
  double rmseMm = 0.0;                     ///< of this test's residuals under the joint model
  IdentifyResult separate;                 ///< the test's own 2D identification (the start)
  std::vector<Eigen::Vector2d> residuals;  ///< measured - modelled (u, v), mm
};

struct Identify3Result {
  ActuatorErrors3 errors;
  ActuatorErrors3 standardErrors;               ///< of the same fields
  std::array<double, 3> squarenessStdErrDeg{};  ///< per plane
  std::array<PlaneFit3, 3> planes;              ///< index: TestPlane
  double rmseMm = 0.0;                          ///< sqrt(SSE / N)
  double sigmaMm = 0.0;                         ///< sqrt(SSE / (2N - 9))
  std::size_t points = 0;
  RunInfo run;
};

/// Identifies the nine parameters from the three tests (index: TestPlane). ValidationError naming
/// the test's file and the plane's field for a test that cannot be identified (identification.h's
/// checks with the plane's column names). The observer sees every LM iteration: best = rmse (mm),
/// bestX = theta (mm, deg).
Identify3Result identifyActuatorErrors3(const std::array<MeasuredPath, 3>& tests,
                                        const Identify3Options& options = {}, Observer* observer = nullptr);

/// Compensated references in three axes (Eq. 15 in three axes, CartesianMachine3::inverse): for every
/// nominal point P the command Pr = [i j k]^-1 (P - o), so the modelled machine lands on P.
std::vector<Eigen::Vector3d> compensatePath3(const ActuatorErrors3& errors,
                                             const std::vector<Eigen::Vector3d>& nominal);
/// A nominal path x_mm,y_mm,z_mm (ValidationError without rows; errors name file, line, field).
std::vector<Eigen::Vector3d> nominalPath3FromCsv(const CsvTable& table);
/// CSV x_cmd_mm,y_cmd_mm,z_cmd_mm (shortest round-trip numbers).
std::string commandPath3ToCsv(const std::vector<Eigen::Vector3d>& commands);

/// JSON: origin_mm [x, y, z]; planes {xy: {x_axis_angle_deg, y_axis_angle_deg, squareness_deg,
/// squareness_std_err_deg, rmse_mm, points, source}, yz: {y_axis_angle_deg, z_axis_angle_deg, ...},
/// zx: {z_axis_angle_deg, x_axis_angle_deg, ...}}; squareness_deg {xy, yz, zx}; directions {x, y, z}
/// (unit vectors); standard_errors {origin_mm}; rmse_mm, sigma_mm, points, iterations, termination,
/// model.
nlohmann::json identify3ResultToJson(const Identify3Result& result);
/// Reads origin_mm and planes.*.*_axis_angle_deg back (extra keys ignored); ValidationError naming
/// `source` and the field.
ActuatorErrors3 actuatorErrors3FromJson(const nlohmann::json& json, const std::string& source);
ActuatorErrors3 readActuatorErrors3(const std::string& path);

}  // namespace metrofit
