#pragma once
// Identification of the 2D actuator errors from a measured path or a circular test (beyond the
// paper, which takes the errors as known). Lengths in mm, angles in degrees at the API.
//
// Model (IEEE Access, kinematic compensation algorithm, Eq. 9 read as in cartesian_model.h): the tool
// reaches, for command Pr_k,
//   P(Pr_k; o, a, b) = o + ir(a) x_k + jr(b) y_k,  ir = (cos a, sin a), jr = (-sin b, cos b).
// Parameters theta = (o_x, o_y, a, b) minimise the sum of squared residual distances
//   S(theta) = sum_k |r_k|^2,  r_k = P(Pr_k; theta) - Pmeas_k,
// by Levenberg-Marquardt (Marquardt's diagonal scaling, each step a least-squares solve of
// [J; sqrt(lambda) D] delta = [-r; 0] with Eigen's Householder QR, Nielsen's damping update; the one
// solver of core/optim/least_squares.h). The
// Jacobian is analytic: dr/do = I, dr/da = x_k (-sin a, cos a), dr/db = y_k (-cos b, -sin b).
// The start is the linear least-squares affine fit Pmeas = o + M Pr with a = atan2(M21, M11),
// b = atan2(-M12, M22), so the large errors of the paper's Fig. 11 (10 deg, 15 deg) converge as
// easily as real machines' micro-radians.
//
// Uncertainty: Cov(theta) = s^2 (J^T J)^-1 at the solution, s^2 = S / (2N - 4) (the residual
// variance per coordinate, N points, 4 parameters); the standard errors are the square roots of
// its diagonal, the squareness's from Var(b) + Var(a) - 2 Cov(a, b). They assume independent
// noise of equal variance in x and y.
//
// rmse_mm = sqrt(S / N), the root mean square of the residual distances |r_k|.
//
// Degenerate input is an InputError naming the file and field: fewer than 3 points, non-finite
// values, command or measured points all identical or all on one line (the spread across the
// path below 1e-4 of the spread along it: one axis is not observed), a mirrored measured path
// (det M < 0: the columns of one axis swapped or negated), and identified angles beyond +-45 deg.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/common/run.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/measured_path.h"

namespace metrofit {

class JsonReader;

struct IdentifyOptions {
  long maxIterations = 100;
  /// Converged when a step changes the modelled positions by less than this (RMS, mm).
  double stepToleranceMm = 1e-10;
  /// Converged when an accepted step lowers S by less than this fraction of S.
  double costTolerance = 1e-12;
  /// Initial damping lambda (relative to diag(J^T J)).
  double initialDamping = 1e-3;
  /// Start from the affine fit (see above); false starts from o = 0, a = b = 0.
  bool affineStart = true;
  bool keepTrace = false;

  bool isValid(std::string* why) const;
};

struct IdentifyResult {
  ActuatorErrors2 errors;          ///< the estimate
  ActuatorErrors2 standardErrors;  ///< standard errors of the same fields (mm, deg)
  double squarenessStdErrDeg = 0.0;
  /// Covariance of (o_x mm, o_y mm, a deg, b deg).
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
  double rmseMm = 0.0;    ///< sqrt(S / N)
  double sigmaMm = 0.0;   ///< s = sqrt(S / (2N - 4))
  double maxAbsMm = 0.0;  ///< largest |r_k|
  std::size_t points = 0;
  std::vector<Eigen::Vector2d> residuals;  ///< Pmeas_k - P(Pr_k; theta), mm
  ActuatorErrors2 initialEstimate;         ///< from the affine fit
  RunInfo run;
};

/// Throws InputError when the path cannot identify the four parameters (see the header comment).
void checkIdentifiable(const MeasuredPath& path);

/// Identifies o, a, b from the path (see the header comment). The observer sees every LM iteration
/// (core/optim/least_squares.h: one accepted step, or the last trials):
/// best = rmse (mm), components rmse_mm and damping, bestX = (o_x, o_y, a_deg, b_deg).
IdentifyResult identifyActuatorErrors(const MeasuredPath& path, const IdentifyOptions& options = {},
                                      Observer* observer = nullptr);

/// The identify JSON (docs/file-formats.md#kinematic-identify-result): origin_mm, x_axis_angle_deg,
/// y_axis_angle_deg, rmse_mm, plus squareness_deg, standard_errors, sigma_mm, max_abs_mm, points, iterations,
/// termination.
nlohmann::json identifyResultToJson(const IdentifyResult& result);

/// Reads the errors back from identify's JSON (origin_mm [x, y], x_axis_angle_deg,
/// y_axis_angle_deg; extra keys ignored). ValidationError naming `source` and the field.
ActuatorErrors2 actuatorErrorsFromJson(const nlohmann::json& json, const std::string& source);
/// The "origin_mm" array of identify's and identify3's JSON: origin.size() finite numbers ([x, y] or
/// [x, y, z]) into `origin`. ValidationError from the reader naming the field (origin_mm, origin_mm[i]).
void originFromJson(const JsonReader& object, Eigen::Ref<Eigen::VectorXd> origin);
ActuatorErrors2 readActuatorErrors(const std::string& path);

}  // namespace metrofit
