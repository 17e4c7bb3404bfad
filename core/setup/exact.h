#pragma once
// The exact optimum of the setup correction (objective.h), by linear and mixed-integer
// programming with GLPK (glp_simplex, glp_intopt; no home-made solver). The paper (Stryczek 2016,
// Eq. 8-10) asks, in words, for the solutions of maximal f1 on the 0.001 mm grid and, among
// those, the one of least |x| (f2); the max-min is a linear programme, so no search is needed.
//
// Variables in grid units: x_i = lower_i + s k_i (s = step_mm), so x_i / s = c_i + k_i with
// c_i = lower_i / s, and t = f1 / s. G is integer (arc weights are +1 / -1, model.h), so
// y_q = (G k)_q is an integer. Dimensions with the same gain row are merged (their constraints
// intersect). For every dimension q, with e_q the deviation and [lo_q, up_q] the tolerance:
//   t + (G k)_q <= bp_q = (up_q - e_q)/s - (G c)_q        (t <= up_q - e'_q, in steps)
//   t - (G k)_q <= bm_q = (e_q - lo_q)/s + (G c)_q        (t <= e'_q - lo_q)
//   0 <= k_i <= K_i = floor((upper_i - lower_i)/s)
//
// Stage 1, LP (glp_simplex): k continuous, maximise t. t_LP s is the continuous optimum of f1,
//   an upper bound for every grid point (reported as lp_f1); the rounded LP point is a first
//   grid point (t_0 = its f1 / s).
// Stage 2, f1 on the grid. On the grid t(k) = min_q min(bp_q - y_q, bm_q + y_q) with integer
//   y_q, so the optimum is one of the finitely many values bp_q + j, bm_q + j (j integer) in
//   [t_0, t_LP]. Feasibility is monotone in t, and for a FIXED t the constraints become integer
//   intervals  ceil(t - bm_q) <= (G k)_q <= floor(bp_q - t)  (a tighter, integer-rounded
//   polytope). The largest feasible candidate is found by bisection in two phases, on one
//   problem object whose row bounds change from probe to probe (dual simplex, warm-started: the
//   objective is zero, so every basis stays dual feasible). Phase A probes only LP relaxations
//   (about a millisecond each at 500 x 5000): an infeasible relaxation proves that no grid point
//   reaches that value (nor any higher one); an integral vertex is a grid point. It ends with
//   the largest level whose relaxation is feasible. Phase B probes MILPs (glp_intopt from the LP
//   basis, depth first on the most fractional variable), that level first: usually it has a grid
//   point and f1 is settled by one branch and bound; else bisection continues below it. Every
//   feasible probe returns a grid point (whose exact f1 then raises the lower end). f1 is
//   certified optimal on the grid when the next larger candidate value is proven infeasible (or
//   no candidate lies between t_0 and t_LP). This is far faster than branch and bound on
//   "maximise t" directly, whose LP bound is flat (20-90 ms instead of 0.05-0.3 ms on the
//   paper's example).
// Stage 3, least norm: the f1-optimal grid points are the integer points of the polytope at
//   t = t* (within 1e-6 s, i.e. 1e-9 mm at s = 0.001); minimise |x|^2 = s^2 sum_i (c_i + k_i)^2
//   over them. This separable convex integer QP is solved EXACTLY by outer approximation on the
//   integers: z_i >= phi_i(k_i) = (c_i + k_i)^2 is represented by secant cuts through
//   consecutive integers (j, phi(j)) - (j+1, phi(j+1)), valid at every integer k_i and tight at
//   j and j+1; minimise sum_i z_i. Cheap LP rounds first add the secant under every fractional
//   k_i (the piecewise-linear interpolation of phi); then MILP rounds (glp_intopt, with the
//   best point so far as incumbent): when the solution has z_i = phi_i(k_i) for all i, the MILP
//   optimum (a lower bound, since every cut is valid) is attained by a feasible point, which is
//   therefore a least-norm point. Otherwise the two secants around each violated k_i are added
//   and the MILP solved again (finitely many secants exist, so this terminates). Ties in |x| are
//   broken by the solver.
//
// Certificate (what is proven, within GLPK's tolerances): lp_f1 = continuous optimum of f1; f1
// optimal on the grid (nextF1Infeasible: the next value above it, proven unreachable); |x|
// minimal in L2 among the f1-optimal grid points when the least-norm status is "optimal"
// (f2LowerBound = f2 then). A time limit or cancellation leaves the best point found, with a
// status that says so.
//
// Thread safety: GLPK keeps its environment per thread (Debian's libglpk is built reentrant with
// thread-local storage); solveExact may run on several threads at once, every call uses its own
// problem objects and silences GLPK's terminal output (glp_term_out(GLP_OFF)) for its thread.
// A worker thread that called solveExact should call releaseExactSolverThread() before it ends
// (glp_free_env), else the thread's GLPK environment leaks. Core never prints.
#include <limits>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/setup/objective.h"

namespace metrofit::setup {

struct ExactOptions {
  double timeLimitSeconds = 0.0;  ///< per GLPK call; 0 = none
  int maxNormRounds = 500;        ///< least-norm MILP rounds before giving up the f2 proof
  bool leastNorm = true;          ///< stage 3 on/off (off: the stage-2 point is returned)
  bool keepTrace = true;

  bool isValid(std::string* why) const;
};

struct ExactCertificate {
  std::string solver;                                        ///< "GLPK 5.0"
  std::string lpStatus;                                      ///< "optimal", ...
  double lpF1 = std::numeric_limits<double>::quiet_NaN();    ///< continuous optimum of f1, mm
  std::string milpStatus;                                    ///< stage 2: "optimal", "time limit", ...
  bool f1Optimal = false;                                    ///< f1 proven optimal on the grid
  double gridF1 = std::numeric_limits<double>::quiet_NaN();  ///< f1 of the returned point, mm
  /// The smallest f1 value above gridF1 that some grid point could have, proven unreachable (NaN when gridF1
  /// already equals the LP bound).
  double nextF1Infeasible = std::numeric_limits<double>::quiet_NaN();
  int feasibilityProbes = 0;  ///< stage-2 feasibility probes (LP relaxations and MILPs)
  std::string normStatus;     ///< "optimal", "round limit", "skipped", ...
  bool f2Optimal = false;     ///< |x| proven minimal among f1-optimal
  double f2LowerBound = 0.0;  ///< proven lower bound on that |x|, mm
  int normRounds = 0;         ///< stage-3 MILPs solved
  int cuts = 0;               ///< secant cuts added in stage 3
  long solverCalls = 0;       ///< glp_simplex + glp_intopt calls
};

struct ExactResult {
  std::vector<double> x;  ///< corrections (mm), on the grid within the bounds
  SetupScore score;
  double bonus = 0.0;  ///< f1(x) - f1(0)
  ExactCertificate certificate;
  RunInfo run;  ///< trace: one entry per stage / least-norm round; evaluations = solver calls
};

/// Solves the setup problem exactly (see above). Throws OptionsError for invalid options.
ExactResult solveExact(const SetupInstance& instance, const ExactOptions& options = {},
                       Observer* observer = nullptr);

/// Frees the calling thread's GLPK environment (call at the end of worker threads).
void releaseExactSolverThread();

}  // namespace metrofit::setup
