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
//
// ---- The paper's range (summarizeValidation) ----
// The paper (Stryczek 2016) reports, for its 100 sets of the practical example with w1 = 0.03 and w2 = 0.02
// mm, the error budget before correction "within -0.011 to 0.063" (mm). The summary gives the range of f1(0)
// over the run's sets and checks the paper's range against the simulator: the extremes of 100 sets
// scatter (the minimum by some 0.03 mm between simulation seeds), so kPaperRangeReplicates further runs of
// kPaperSets sets (f1(0) only, simulation seeds derived from the run's) give the 1 % and 99 % quantiles
// of the minimum and of the maximum; the paper's range is consistent when its minimum and its maximum
// each lie inside their band. The check applies only with the paper's weights (otherwise: not applicable).
//
// ---- The share of the setup data in the dimension error (estimateSetupShare) ----
// The paper proposes to "estimate the share of the setup data error in the total machining error" (its
// example: a 60 % share, w1 / (w1 + w2) = 0.03 / 0.05). With Eq. 12-13 a set of deviations is
//   e = G s + r,   s_i ~ U(-w1, w1),   r_q ~ U(-w2, w2),   Var U(-w, w) = w^2 / 3,
// so, with P the projector on the columns of G (rank k) and n dimensions, by the method of moments
//   E |(I - P) e|^2 = (n - k) w2^2 / 3                 =>  w2^2 = 3 RSS / (n - k)
//   E |e|^2         = w1^2 ||G||_F^2 / 3 + n w2^2 / 3   =>  w1^2 = (3 |e|^2 - n w2^2) / ||G||_F^2 (>= 0)
// pooled over all sets (sums of RSS, (n - k) and |e|^2). Reported: the weight share w1 / (w1 + w2)
// (the paper's "share", 0.6 for its weights) and the variance share w1^2 ||G||_F^2 / (w1^2 ||G||_F^2 +
// n w2^2), the part of the dimension error variance the setup data explain. On the validation's own
// sets it must recover the configured weights; on measured data (every part of a CMM series one set)
// it says how much of the error a setup correction can address.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
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

/// The paper's range of f1(0) (mm) over its 100 sets, its weights and the tolerance of the check.
inline constexpr double kPaperF1BeforeMinMm = -0.011;
inline constexpr double kPaperF1BeforeMaxMm = 0.063;
inline constexpr double kPaperW1Mm = 0.03;
inline constexpr double kPaperW2Mm = 0.02;
inline constexpr int kPaperRangeReplicates = 200;
inline constexpr std::size_t kPaperSets = 100;

struct ShareEstimate {
  std::size_t sets = 0;        ///< deviation vectors used
  double w1Mm = 0.0;           ///< estimated weight of the setup-data errors
  double w2Mm = 0.0;           ///< estimated weight of the random errors
  double weightShare = 0.0;    ///< w1 / (w1 + w2) (0 when both are 0)
  double varianceShare = 0.0;  ///< share of the dimension error variance explained by the setup data
};

/// The method-of-moments estimate above from deviation vectors (one value per model dimension each).
/// OptionsError when a vector has the wrong size or the model has no more dimensions than the rank of G.
ShareEstimate estimateSetupShare(const Model& model, const std::vector<std::vector<double>>& deviationSets);

/// The deviation vectors of measured data for estimateSetupShare: one per part that has every model
/// dimension (rows of the same part and dimension averaged); when no part is complete, the measurements'
/// mean deviations as one set.
std::vector<std::vector<double>> partDeviationSets(const Model& model, const Measurements& measurements);

struct ValidationMethodSummary {
  std::string method;
  std::size_t trials = 0;
  double meanF1 = 0.0;         ///< mm
  double meanGapF1 = 0.0;      ///< mean of exact f1 - f1, mm
  double maxGapF1 = 0.0;       ///< mm
  std::size_t withinStep = 0;  ///< trials within one grid step of the exact f1
};

struct ValidationSummary {
  std::size_t sets = 0;
  double f1BeforeMin = 0.0, f1BeforeMax = 0.0, f1BeforeMean = 0.0;  ///< mm
  double exactF1Mean = 0.0;                                         ///< mm
  double bonusMean = 0.0;                                           ///< mean of exact f1 - f1(0), mm
  std::size_t exactProven = 0;
  bool paperRangeApplies = false;  ///< the run used the paper's weights
  bool paperRangeConsistent = false;
  double minBandLo = 0.0, minBandHi = 0.0;       ///< 1 % / 99 % quantiles of min f1(0) over N sets, mm
  double maxBandLo = 0.0, maxBandHi = 0.0;       ///< the same for max f1(0), mm
  std::vector<ValidationMethodSummary> methods;  ///< in the order of options.methods
  ShareEstimate share;                           ///< estimateSetupShare on the simulated sets
};

/// The paper's reading of Fig. 18 ("for a 60 % share and an initial error budget of 0.022 the foreseen
/// error budget amounted to 0.085"): the f1 after correction (exact optimum) the validation foresees for
/// a set with f1(0) = f1Before, from the least-squares line of exact f1 on f1(0) over the sets. A
/// measured set that reaches less than that has a smaller setup share than the validation's. NaN with
/// fewer than 2 sets or no spread in f1(0).
double foreseenF1(const ValidationResult& result, double f1Before);

/// Summary of a (possibly cancelled) run; `options` are the ones it ran with.
ValidationSummary summarizeValidation(const Model& model, const ValidationOptions& options,
                                      const ValidationResult& result);

/// Runs the validation (see above). Throws OptionsError for invalid options.
ValidationResult runValidation(const Model& model, const ValidationOptions& options,
                               CancelToken* cancel = nullptr,
                               const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace metrofit::setup
