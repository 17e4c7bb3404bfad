#pragma once
// Posture matching end to end (Jiang et al., Mech. Sci. 9, 2018): one entry point shared by
// the CLI, the GUI and the tests.
//
//   sade        rough matching (Eq. 3-7, rough.h) + SADE fine matching (Eq. 8-11, fine.h), the paper's
//               method with its settings: NP = 30, F0 = 0.3 (0.25-0.4), Gm = 200 (100-500, the paper's
//               optimum was reached after 200 generations), angle bounds from PE0 + k (k = 1 deg)
//   ga-simplex  rough matching + GA-simplex fine matching (the paper's comparison, Yan et al. 2004);
//               the paper gives no settings: NP = 50 and the same evaluation budget as SADE, 80 % GA
//               and 20 % Nelder-Mead (core/optim/gasimplex.h), so that the comparison is at equal cost
//   closed-form the exact least-squares optimum (closed_form.h; constrained with locks)
//   minimax     the smallest largest deviation (minimax.h), started from the closed-form optimum
//
// All four minimise over the same free parameters (fit_input.h: user locks + planar locks, scale with
// allowScale) and are evaluated alike (evaluation.h): before = identity posture, after = the fit.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/common/run.h"
#include "core/matching/closed_form.h"
#include "core/matching/evaluation.h"
#include "core/matching/fine.h"
#include "core/matching/minimax.h"
#include "core/matching/rough.h"
#include "core/optim/gasimplex.h"
#include "core/optim/sade.h"

namespace metrofit::matching {

enum class MatchMethod { Sade, GaSimplex, ClosedForm, Minimax };

/// "sade", "ga-simplex", "closed-form", "minimax".
const char* toString(MatchMethod m);
/// OptionsError naming `field` for an unknown name.
MatchMethod parseMatchMethod(const std::string& name, const std::string& field);

/// The paper's SADE settings (Section 4.2): NP = 30, F0 = 0.3, Gm = 200, CR 0.1 -> 0.9, budget
/// NP (Gm + 1) evaluations.
optim::Sade::Options paperSadeOptions();
/// GA-simplex for the comparison: NP = 50, crossover 0.9, mutation 1/D, 80 % GA / 20 % simplex, the
/// budget of paperSadeOptions().
optim::GaSimplex::Options comparisonGaSimplexOptions();

/// The symmetric tolerance (mm) of a before/after evaluation when none is set.
inline constexpr double kDefaultToleranceMm = 0.05;

struct MatchOptions {
  MatchMethod method = MatchMethod::Sade;
  double toleranceMm = kDefaultToleranceMm;  ///< symmetric tolerance of the before/after evaluation (>= 0)
  bool allowScale = false;
  DofLocks locks;                         ///< user locks (planar locks are added automatically)
  std::vector<std::string> referenceIds;  ///< rough matching references (3 ids) or empty: automatic
  double boundMarginDeg = 1.0;            ///< k1 = k2 = k3 of Section 2.3.2 (> 0)
  optim::Sade::Options sade = paperSadeOptions();
  optim::GaSimplex::Options gaSimplex = comparisonGaSimplexOptions();
  MinimaxOptions minimax;  ///< allowScale / locks are taken from this struct's own fields
  std::uint64_t seed = 1;  ///< seed of the stochastic methods (overrides the optimisers' own seeds)

  bool isValid(std::string* why) const;
};

struct MatchResult {
  MatchMethod method = MatchMethod::Sade;
  Pose pose;  ///< p = s R q + t
  bool allowScale = false;
  DofLocks locks;  ///< effective locks
  ToleranceEvaluation before, after;
  std::optional<RoughResult> rough;                    ///< sade, ga-simplex
  std::optional<ToleranceEvaluation> roughEvaluation;  ///< after rough matching only
  std::optional<FineResult> fine;                      ///< sade, ga-simplex
  std::optional<ClosedFormResult> closedForm;          ///< closed-form, minimax (its start)
  std::optional<MinimaxResult> minimax;                ///< minimax
  RunInfo run;  ///< termination, message, iterations, evaluations and the convergence trace
  std::uint64_t seed = 0;
};

/// Runs the method. InputError (ValidationError / OptionsError) on bad data or options; the observer
/// sees every generation (sade, ga-simplex) or LP iteration (minimax) and may stop the run.
MatchResult matchPosture(const ProbePointSet& set, const MatchOptions& options, Observer* observer = nullptr);

/// docs/file-formats.md#match-result keys (method, rotation_deg, translation_mm, rmse_mm, max_abs_mm,
/// out_of_tolerance {before, after}, scale with allowScale) plus: tolerance_mm, points, normals,
/// planar, locked, before / after (overall and per-surface stats), evaluations, iterations,
/// termination, message, trace [{iteration, evaluations, best_mm}], rough, fine, minimax, seed.
/// The caller adds "machine".
nlohmann::json toJson(const MatchResult& result, const ProbePointSet& set);
/// Stats as JSON: {rmse_mm, max_abs_mm, out_of_tolerance, mean_over_tolerance_mm, points}.
nlohmann::json toJson(const DeviationStats& stats);

}  // namespace metrofit::matching
