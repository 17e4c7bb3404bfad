#pragma once
// The paper's statistical validation (Stryczek 2016, "Validate the results of the proposed
// scheme", Fig. 18): N measurement sets made by the simulator (core/sim/setup_sim.h, Eq. 12-13:
// setup-data errors w1 (1 - 2r), random errors w2 (1 - 2r)); for each set the budget before
// correction f1(0), the exact optimum (exact.h), and M trials of every chosen metaheuristic with
// its gap to the exact f1. The paper ran N = 100 sets x M = 10 trials of CRIPSO (5000 solutions
// each) and plotted the series sorted by the initial budget (sortedByBefore()).
//
// Runs on `threads` worker threads (the caller waits), one set at a time per thread; deterministic: set j
// uses simulateSetupSet(model, simulation, j) and trial t of method m uses the seed trialSeed(seed, j, m, t),
// so the result does not depend on the number of threads or their timing. Cancellable via a CancelToken (it
// also stops the running metaheuristics); a cancelled run returns the sets that were complete. The progress
// callback is called (serialised) after every finished set.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/sim/setup_sim.h"

namespace metrofit::setup {

struct ValidationOptions {
  std::size_t sets = 100;                      ///< N measurement sets (paper: 100)
  int trials = 10;                             ///< M trials per set and method (paper: 10)
  std::vector<std::string> methods{"cripso"};  ///< metaheuristics (setupMetaheuristicNames())
  long budget = kPaperBudget;                  ///< evaluations per trial (paper: 5000)
  SetupSimOptions simulation;                  ///< w1, w2 and the seed of the sets
  std::uint64_t seed = 1;                      ///< seed of the trials
  int threads = 0;                             ///< worker threads; 0 = hardware concurrency

  bool isValid(std::string* why) const;
};

struct ValidationTrial {
  std::string method;
  int trial = 0;
  std::uint64_t seed = 0;
  double f1 = 0.0, f2 = 0.0, f = 0.0;  ///< of the trial's best point, mm
  double gapF1 = 0.0;                  ///< exact f1 - f1 (>= 0)
};

struct ValidationSet {
  std::size_t index = 0;
  double f1Before = 0.0;  ///< f1(0), mm
  double exactF1 = 0.0, exactF2 = 0.0;
  bool exactProven = false;  ///< f1 optimal on the grid and |x| minimal (certificate)
  std::vector<ValidationTrial> trials;
};

struct ValidationResult {
  std::vector<ValidationSet> sets;  ///< completed sets, by index
  bool cancelled = false;
  /// Indices into `sets`, by ascending f1Before (ties by set index): the order of Fig. 18.
  std::vector<std::size_t> sortedByBefore() const;
};

/// Seed of trial t of method number m on set j.
std::uint64_t trialSeed(std::uint64_t seed, std::size_t set, std::size_t method, int trial);

/// Runs the validation (see above). Throws OptionsError for invalid options.
ValidationResult runValidation(const Model& model, const ValidationOptions& options,
                               CancelToken* cancel = nullptr,
                               const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace metrofit::setup
