#pragma once
// Nelder-Mead downhill simplex (J. A. Nelder, R. Mead, "A simplex method for function
// minimization", Computer Journal 7, 1965) with the standard coefficients
//   reflection alpha = 1, expansion gamma = 2, contraction rho = 0.5, shrink sigma = 0.5,
// in the formulation of Lagarias et al. (SIAM J. Optim. 9, 1998). Minimisation. One iteration:
// order the n + 1 vertices f(x_1) <= ... <= f(x_{n+1}), centroid c of the n best, then
//   reflect   x_r = c + alpha (c - x_{n+1});        f_1 <= f_r < f_n: accept x_r
//   expand    f_r < f_1:   x_e = c + gamma (x_r - c); accept the better of x_e, x_r
//   contract  f_n <= f_r < f_{n+1}: outside x_c = c + rho (x_r - c), accept if f_c <= f_r;
//             f_r >= f_{n+1}:       inside  x_c = c - rho (c - x_{n+1}), accept if f_c < f_{n+1};
//   shrink    otherwise: x_i = x_1 + sigma (x_i - x_1), i = 2 .. n+1.
// In the project it is the "simplex" half of the paper's comparison method GA-simplex (Jiang 2018, posture
// adjustment by SADE, Section 4.2, after Yan et al. 2004; see gasimplex.h), and a local refiner on its own.
//
// Start: Options::start, or (when empty) a uniform random feasible point drawn from common.seed, so
// the method is deterministic given (start, seed). Initial simplex: x_0 and x_0 + h_i e_i with
// h_i = initialStep (upper_i - lower_i), at least one grid step; when x_0 + h_i e_i would leave the
// box the vertex goes to x_0 - h_i e_i instead.
// Bounds and grid: every vertex goes through the tracker, which snaps it onto the feasible set
// (clamp into the box, round to the grid); the method continues from the snapped point.
// Stops when (Termination::Converged) the simplex is small in both senses,
//   f_{n+1} - f_1 <= tolerance  and  max_{i,j} |x_ij - x_1j| / (upper_j - lower_j) <= tolerance,
// or when the budget is used (BudgetExhausted), the target is met or the observer stops it.
// Trace: entry 0 is the initial simplex (n + 1 evaluations), then one entry per iteration.
#include <string>
#include <vector>

#include "core/optim/algorithm.h"

namespace metrofit::optim {

class NelderMead final : public Algorithm {
 public:
  static constexpr double kReflection = 1.0;
  static constexpr double kExpansion = 2.0;
  static constexpr double kContraction = 0.5;
  static constexpr double kShrink = 0.5;

  struct Options {
    CommonOptions common;
    /// Start point (problem dimension; snapped onto the feasible set). Empty: random from the seed.
    std::vector<double> start;
    double initialStep = 0.1;  ///< initial simplex edge as a fraction of each variable's range, (0, 1]
    double tolerance = 1e-8;   ///< convergence tolerance on the f spread and the relative x spread, >= 0

    bool isValid(std::string* why) const;
  };

  NelderMead() = default;
  explicit NelderMead(Options options) : options_(std::move(options)) {}

  std::string name() const override { return "nelder-mead"; }
  const Options& options() const { return options_; }
  /// Throws OptionsError also when the start point's size differs from the problem's dimension.
  Result optimise(const Problem& problem, Observer* observer = nullptr) const override;

  /// Runs the simplex on an existing tracker (which counts, snaps, traces and owns the budget),
  /// starting at `start` (snapped by the tracker). When `startValue` is finite it is taken as f(start)
  /// and not evaluated again (the caller evaluated start through the same tracker). Calls
  /// tracker.endIteration() after the initial simplex and after every iteration. Returns true when
  /// the simplex converged, false when the tracker said stop (budget, target or observer).
  static bool refine(Tracker& tracker, std::vector<double> start, double startValue, double initialStep,
                     double tolerance);

 private:
  Options options_;
};

}  // namespace metrofit::optim
