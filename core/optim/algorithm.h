#pragma once
// What every metaheuristic in core/optim shares (STYLE.md §2-5):
//  * CommonOptions: evaluation budget, seed, trace switch, optional target objective.
//  * Result: best x (snapped, feasible), best objective (minimised), its components, RunInfo.
//  * Algorithm: a small value type with `optimise(problem, observer) const`; no globals, no I/O,
//    so many instances can run in parallel on one shared (const, thread-safe) problem.
//  * Tracker: the one place that counts evaluations, snaps to the grid, keeps the best, enforces
//    the budget, builds IterationSummary and calls the observer. Algorithms call
//    `tracker.evaluate(x)` for every candidate and `tracker.endIteration()` after every iteration
//    (generation / sweep); the trace therefore has one entry per iteration for every method.
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/optim/problem.h"

namespace metrofit::optim {

struct CommonOptions {
  long maxEvaluations = 5000;  ///< budget of objective evaluations (> 0)
  std::uint64_t seed = 1;      ///< same seed, same trace, bit for bit
  bool keepTrace = true;       ///< store one IterationSummary per iteration in Result::run.trace
  bool traceBestX = false;     ///< also store the best x in every trace entry
  /// Stop as soon as the best objective is <= target (Termination::Converged). -inf: never.
  double targetObjective = -std::numeric_limits<double>::infinity();

  bool isValid(std::string* why) const;
};

struct Result {
  std::string method;
  std::vector<double> bestX;
  double bestObjective = std::numeric_limits<double>::infinity();
  std::vector<double> bestComponents;  ///< the problem's componentNames() at bestX
  RunInfo run;
};

class Algorithm {
 public:
  virtual ~Algorithm() = default;
  virtual std::string name() const = 0;
  /// Runs the method. Throws OptionsError for invalid options or a problem of dimension 0 /
  /// reversed bounds; otherwise always returns a Result (Cancelled when the observer stopped it).
  virtual Result optimise(const Problem& problem, Observer* observer = nullptr) const = 0;
};

/// Validates a problem's bounds (finite, lower <= upper, step >= 0); OptionsError otherwise.
void requireValidProblem(const Problem& problem);

class Tracker {
 public:
  Tracker(std::string method, const Problem& problem, const CommonOptions& options, Observer* observer);

  const Problem& problem() const { return problem_; }
  std::size_t dimension() const { return problem_.dimension(); }
  Rng& rng() { return rng_; }

  /// Snaps x onto the feasible set (in place), evaluates it, updates the best. Returns the
  /// objective. Callers must check `exhausted()` before calling (it is an error to exceed the budget).
  double evaluate(std::span<double> x);
  /// A uniformly random feasible point.
  std::vector<double> randomPoint();

  long evaluations() const { return evaluations_; }
  bool exhausted() const { return evaluations_ >= options_.maxEvaluations; }
  double bestObjective() const { return best_.bestObjective; }
  const std::vector<double>& bestX() const { return best_.bestX; }
  /// Fraction of the budget used.
  double progress() const {
    return static_cast<double>(evaluations_) / static_cast<double>(options_.maxEvaluations);
  }

  /// Ends an iteration: records the trace entry, asks the observer. Returns true when the run
  /// must stop (observer said stop, budget exhausted or target reached); `finish()` then knows why.
  bool endIteration();
  /// The result, with the termination reason set from how the run ended.
  Result finish();

 private:
  std::string method_;
  const Problem& problem_;
  CommonOptions options_;
  Observer* observer_;
  Rng rng_;
  long evaluations_ = 0;
  long iteration_ = 0;
  bool stoppedByObserver_ = false;
  std::vector<double> components_;
  Result best_;
  // The problem's bounds and grid read once (snap is on every evaluation's path; the virtual
  // lower/upper calls and the grid-size division were a third of a setup-problem evaluation).
  std::vector<double> lo_, hi_, kMax_;
  double step_ = 0.0;
  void snap(std::span<double> x) const;
};

}  // namespace metrofit::optim
