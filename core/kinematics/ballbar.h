#pragma once
// Ballbar-style breakdown of a circular test into named causes (issue 32 item 3): the radial deviation
// of the measured path, CCW and CW, fitted by linear least squares to the signatures of the usual
// machine errors, each cause with a value in um and its share of the radial deviation.
//
// Data. A circular test in the x/y form (docs/file-formats.md#circular-test): commands c_k on a circle,
// measured points p_k. The nominal circle is the least-squares circle of the commands (centre c, radius
// R; iso230_4.h fitLsqCircle). For each point: the commanded angle theta_k and unit radial vector
// u_k = (c_k - c) / |c_k - c| = (cos theta, sin theta), the radial deviation dr_k = |p_k - c| - R, the
// direction of travel s_k = +1 CCW / -1 CW (the turn from c_k to c_{k+1} about c, the last point taking
// its predecessor's, as iso230_4.h), and from the command sequence (effects.h pathMotion) each axis'
// direction of motion d_x, d_y in {-1, +1} (the sign of its last move) and the unit tangent t.
//
// Signatures. Every cause is an error e = (e_x, e_y) of the axes, written from its physical definition;
// to first order in |e| / R it changes the radius by dr = e . u = e_x cos theta + e_y sin theta (the
// neglected term is |e|^2 / 2R: 0.0005 um for e = 10 um at R = 100 mm). Value = the parameter, in um.
//   backlash_x       b: the X axis lags by b/2 behind its direction of motion (lost motion b at each
//                    reversal of X, i.e. at theta = 0 and 180 deg): e_x = -d_x b/2, dr = -d_x (b/2) cos.
//                    Radially a step of b at each X reversal; on a circle CCW: dr = (b/2) sgn(sin) cos.
//   backlash_y       the same for Y (reversals at 90 and 270 deg): e_y = -d_y b/2.
//   reversal_spike_x h: a transient lag after each reversal of X that decays with the angle phi travelled
//                    since it: e_x = -d_x h exp(-phi / w), w = spikeWidthDeg (h > 0: the axis sticks, the
//                    spike points outwards). phi is measured from the command point where the axis'
//                    direction changed (the last point before its first move in the new direction); no
//                    spike before the first reversal in the data.
//   reversal_spike_y the same for Y.
//   lateral_play_x   p: the X carriage shifts across its travel (in Y) by p when X reverses:
//                    e_y = -d_x p/2 (positive p: it lies towards -Y while X moves in +X).
//   lateral_play_y   the Y carriage in X: e_x = -d_y p/2.
//   servo_mismatch   m = v (tau_x - tau_y): first-order servo lags tau_x, tau_y at the path speed v
//                    (effects.h servo_lag) give e = -v (tau_x t_x, tau_y t_y); a common lag is tangential
//                    (t . u = 0), the mismatch gives dr = -(m/2) (t_x cos - t_y sin) = s (m/2) sin 2 theta:
//                    an ellipse along +-45 deg that turns over between CCW and CW. m is the difference of
//                    the two axes' following errors at the test's feed (positive: X lags more).
//   scale_mismatch   m = (sx - sy) R: axis scale errors sx, sy (e_x = sx x, e_y = sy y, x = R cos theta):
//                    dr = R (sx cos^2 + sy sin^2) = R (sx + sy)/2 + (m/2) cos 2 theta. The common part is a
//                    radius change (see setup terms); m > 0: the X axis travels further than Y.
//   squareness       q = S R with S = b - a of identification.h (squareness_deg in rad; the angle between
//                    the axes is 90 deg + S): P = x (cos a, sin a) + y (-sin b, cos b) gives, to first
//                    order, e = (-b y, a x), dr = -S R sin cos = -(q/2) sin 2 theta (the rotation (a + b)/2
//                    is tangential). q = S R is the shear over the test radius.
//   straightness_x   d: the X axis bows in Y, e_y = d (1 - x^2 / R^2) over x in [-R, R] relative to the line
//                    through its ends (d > 0: the middle of the travel lies towards +Y): dr = d sin^3 theta.
//   straightness_y   the Y axis bows in X: e_x = d (1 - y^2 / R^2), dr = d cos^3 theta.
//   cyclic_error_x   A: a periodic error of X with the screw pitch P (screwPitchMm, the period in X's
//                    travel): e_x = A sin(2 pi x / P + phi0) with x the absolute command; fitted as
//                    a1 sin + a2 cos, value A = sqrt(a1^2 + a2^2) >= 0. Only when screwPitchMm > 0.
//   cyclic_error_y   the same for Y.
// Setup terms (not machine errors, removed and not reported): per direction of travel a centre offset
// (cos theta, sin theta) and a radius offset (1): the ballbar set-up, its length and a drift between the
// runs. They absorb the common part of the scale errors and 3/4 of the straightness signature (its
// sin / cos theta part); the breakdown rests on the rest.
//
// Directions. The reversal causes (backlash, spikes, lateral play, servo mismatch) change sign between
// CCW and CW while the geometric ones (scale, squareness, straightness, cyclic) do not; this is what tells
// e.g. servo mismatch (s sin 2 theta) from squareness (sin 2 theta). With one direction only the geometric
// causes are fitted.
//
// Fit. dr = N g + C beta + e with N the setup columns and C the cause columns, solved by least squares
// (Eigen ColPivHouseholderQR; rank-deficient columns are an error). By Frisch-Waugh-Lovell the causes
// are the fit of y* = (I - H_N) dr on C* = (I - H_N) C (the setup terms removed from both), C*^T e = 0.
// Share: how much of the radial deviation's variance (after the setup terms) each cause explains. The
// fit explains R^2 = 1 - |e|^2 / |y*|^2 of |y*|^2; cause i's own signature C*_i beta_i has the variance
// V_i = |C*_i beta_i|^2, and share_i = R^2 V_i / sum_j V_j, unexplained = 1 - R^2 = |e|^2 / |y*|^2: shares
// and unexplained add up to 1, every share is >= 0 and 0 for a cause whose value is 0, and for orthogonal
// signatures V_i is exactly the part of |y*|^2 that cause explains (sum_j V_j = R^2 |y*|^2). Correlated
// signatures add cross terms 2 beta_i beta_j C*_i . C*_j to the explained variance; they are shared in
// proportion to V_i. (Pratt's beta_i C*_i . y* turns negative when two correlated signatures partly cancel,
// as backlash X and Y of 8 and 5 um do, their columns correlating at -0.64; the Shapley / LMG split of R^2
// gives shares to causes whose value is 0 but whose signature resembles a present one, e.g. 30 % to servo
// mismatch on a test with backlash alone. Both would mislead a ranking.) When y* = 0 every share is 0 and
// unexplained is 1.
// Uncertainty: Cov(beta) = s^2 (C*^T C*)^-1, s^2 = |e|^2 / (n - columns); for a cyclic amplitude the
// first-order propagation of (a1, a2). Significant: |value| > significance * standard error.
// Ranking: by share, largest first (ties by |value|): the order in which the causes explain the trace.
//
// Input problems are ValidationError naming the source and field x_cmd_mm: commands not on one circle
// (a command's distance from the LSQ circle above 1e-3 R), a direction with fewer than 24 points or an
// angular gap above 30 deg, or signatures that the path cannot tell apart (rank-deficient columns).
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/kinematics/measured_path.h"

namespace metrofit {

struct BallbarOptions {
  /// w of the reversal spikes (deg of path angle; the spike falls to 1/e after w).
  double spikeWidthDeg = 2.0;
  /// Pitch of the screws (mm of axis travel per period of the cyclic error); 0: cyclic error not fitted.
  double screwPitchMm = 0.0;
  /// A cause is significant when |value| exceeds this many standard errors.
  double significance = 3.0;

  bool isValid(std::string* why) const;
};

struct BallbarCause {
  std::string name;         ///< backlash_x, ..., cyclic_error_y (see the header comment)
  double valueUm = 0.0;     ///< signed parameter; cyclic: amplitude >= 0
  double stdErrorUm = 0.0;  ///< standard error of the value
  double share = 0.0;       ///< share of the radial variance (see the header comment)
  bool significant = false;
};

struct BallbarBreakdown {
  std::vector<BallbarCause> causes;  ///< ranked: share descending, ties by |value|
  double unexplainedShare = 1.0;     ///< |e|^2 / |y*|^2
  double residualRmsUm = 0.0;        ///< RMS of the residual e
  double deviationRmsUm = 0.0;       ///< RMS of y* (radial deviation without the setup terms)
  Eigen::Vector2d centreMm = Eigen::Vector2d::Zero();  ///< nominal centre (LSQ circle of the commands)
  double radiusMm = 0.0;                               ///< nominal radius
  bool bothDirections = false;
  std::size_t points = 0;
  BallbarOptions options;

  /// The cause of that name, nullptr when it was not fitted.
  const BallbarCause* cause(const std::string& name) const;
};

/// True when the commands lie on one circle (within 1e-3 of its radius) with at least 3 points; else
/// false and `why` says what is wrong.
bool isCircularTest(const MeasuredPath& path, std::string* why = nullptr);

/// The breakdown of the header comment. OptionsError for invalid options; ValidationError naming the
/// path's source (field x_cmd_mm) for the input problems of the header comment.
BallbarBreakdown ballbarBreakdown(const MeasuredPath& path, const BallbarOptions& options = {});

/// The "causes" array of `kinematic identify` (docs/file-formats.md#kinematic-identify-result): the
/// ranked causes as {name, value_um, share}, then {"name": "unexplained", value_um: RMS of the residual,
/// share: the remainder}.
nlohmann::json ballbarCausesToJson(const BallbarBreakdown& breakdown);

}  // namespace metrofit
