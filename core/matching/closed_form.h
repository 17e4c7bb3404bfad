#pragma once
// The least-squares reference fit: minimises the paper's Eq. (8) exactly,
//   SS(R, t, s) = sum_i |p_i - (s R q_i + t)|^2 ,
// the sum behind the match result's rmse_mm (docs/file-formats.md#match-result).
//
// Unconstrained (Horn 1987 / Umeyama 1991, "Least-squares estimation of transformation parameters
// between two point patterns", IEEE PAMI 13(4), Eq. 38-42), from the centred moments:
//   K = (1/n) sum (p_i - mean p)(q_i - mean q)^T = U D V^T (SVD),
//   S = diag(1, 1, sign(det U det V)),   R = U S V^T,
//   s = tr(D S) / ((1/n) sum |q_i - mean q|^2)   (1 without scale),   t = mean p - s R mean q.
// Two passes over the points (means, then K), no copy of the points; identical to Eigen::umeyama.
//
// With degree-of-freedom locks (pose.h DofLocks) the problem is a constrained least squares: the
// locked parameters are held at their values and SS is minimised over the free ones (angles, the free
// translation components, the scale) by Gauss-Newton with a Levenberg-Marquardt safeguard (the
// solver of core/optim/least_squares.h) on the 3n
// residuals r_i = p_i - s R(angles) q_i - t, Jacobian dr/d(angle_j) = -s dR/d(angle_j) q_i,
// dr/dt_j = -e_j, dr/ds = -R q_i, started from the unconstrained optimum with the locked angles
// substituted and the translation / scale that are optimal for that rotation. The residual is linear
// in t and s, so the iteration converges to machine precision in a few steps for small rotations.
#include "core/common/run.h"
#include "core/matching/pose.h"
#include "core/matching/probe_points.h"

namespace metrofit::matching {

struct ClosedFormOptions {
  bool allowScale = false;
  DofLocks locks;           ///< effective locks (fit_input.h effectiveLocks adds the planar ones)
  int maxIterations = 100;  ///< Gauss-Newton iterations of the constrained fit (>= 1)

  bool isValid(std::string* why) const;
};

struct ClosedFormResult {
  Pose pose;
  double sumSquares = 0.0;   ///< SS at the optimum
  bool constrained = false;  ///< locks were present (Gauss-Newton) or not (SVD)
  int iterations = 0;        ///< Gauss-Newton iterations (0 for the SVD solution)
  Termination termination = Termination::Converged;
  std::string message;
};

/// Umeyama / Horn on the points (no validation beyond n >= 1; see fit_input.h requireDeterminable).
Pose umeyamaFit(const ProbePointSet& set, bool allowScale);

/// The least-squares optimum with the options' locks.
ClosedFormResult closedFormFit(const ProbePointSet& set, const ClosedFormOptions& options);

}  // namespace metrofit::matching
