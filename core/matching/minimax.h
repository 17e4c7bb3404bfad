#pragma once
// Minimax posture fit: the posture that minimises the largest deviation,
//   F(x) = max_i |d_i(x)|,   x = (rx, ry, rz, tx, ty, tz[, s]) minus the locked parameters,
// with d_i = (p_i - (s R q_i + t)) . (R n_i) = n_i . (R^T (p_i - t)) - s q_i . n_i where the set has
// normals, d_i = |p_i - (s R q_i + t)| else (evaluation.h). This is the "bring every point inside the
// tolerance" fit (Chebyshev / zone fit).
//
// Method: sequential linear programming with a trust region (the classical minimax method of
// K. Madsen, "An algorithm for minimax solution of overdetermined systems of non-linear equations",
// IMA J. Appl. Math. 16, 1975). At the current x the deviations are linearised,
//   d_i(x + dx) ~ d_i(x) + g_i . dx,   g_i = grad d_i (analytic: dd/dangle_j = n_i . (dR_j^T (p_i - t)),
//   dd/dt = -R n_i, dd/ds = -q_i . n_i; for distances the gradient of |r_i|, r_hat_i^T dr_i/dx),
// and the LP
//   minimise z  subject to  -z <= d_i + g_i . dx <= z  (only d + g.dx <= z for distances),
//                           |dx_j| <= Delta (trust region),  locked parameters absent (fixed),
// is solved with GLPK's simplex. The step is taken when the exactly re-evaluated F decreases by at
// least 1 % of the LP's predicted decrease F(x) - z*; Delta doubles after a good step on the trust
// region boundary and shrinks to a quarter of the step after a poor or rejected one. Rotation and
// scale steps are scaled by the RMS radius L of the nominal points (L dangle, L ds in mm) so that the
// trust region is one length for all variables. Stops when the predicted decrease is below
// 1e-12 (1 + F) mm (first-order stationary: no descent direction), when Delta < 1e-12 (1 + L) mm, or
// at maxIterations. The fit starts from a given posture (normally the least-squares optimum with the
// same locks), so the result's max deviation is never larger than the start's.
// Certification: the reported maxAbsMm is re-evaluated exactly (evaluation.h maxAbsDeviation) at the
// final posture, never taken from the LP; `active` lists the points within 1e-9 mm of it.
#include <vector>

#include "core/common/run.h"
#include "core/matching/pose.h"
#include "core/matching/probe_points.h"

namespace metrofit::matching {

struct MinimaxOptions {
  bool allowScale = false;
  DofLocks locks;             ///< effective locks
  int maxIterations = 500;    ///< LP iterations (>= 1)
  double initialTrustMm = 0;  ///< 0: max(F(start), 1e-3) mm
  bool keepTrace = true;

  bool isValid(std::string* why) const;
};

struct MinimaxResult {
  Pose pose;
  double maxAbsMm = 0.0;       ///< exact max |d_i| at pose
  double startMaxAbsMm = 0.0;  ///< at the start posture
  std::vector<std::size_t> active;
  int lpSolves = 0;
  double finalTrustMm = 0.0;
  double lastPredictedDecreaseMm = 0.0;
  RunInfo run;  ///< one trace entry per LP iteration: best = current max |d|, evaluations = LP solves
};

MinimaxResult minimaxFit(const ProbePointSet& set, const Pose& start, const MinimaxOptions& options,
                         Observer* observer = nullptr);

}  // namespace metrofit::matching
