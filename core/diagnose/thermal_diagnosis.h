#pragma once
// The closed loop in the thermal domain (docs/file-formats.md#the-declared-models,
// #diagnose-result, #honest-held-out-rows).
//
// Rows. The first `trainFraction` of the rows are the fit rows (thermal::fitRowCount, as
// `thermal fit`), the rest are held out. Everything the loop decides comes from the fit rows only:
// the coefficients, the noise level, the lag search range, the column scaling and which effects are
// accepted. The held-out rows give `heldout_rmse` (baseline, per candidate, final) and nothing else,
// so scrambling the held-out target changes those figures and nothing else (tested).
//
// Declared model: the target is a static linear function of the declared inputs,
//   y(k) = c0 + sum_j b_j x_j(k) + e(k),
// fitted by least squares on the fit rows.
//
// Declared model `gmc` or `gnnmci` (--declared): the user's grey model, GMC(1,N) by
// least squares or GNNMCI(1,N) trained by PSO with `seed` (core/thermal/thermal_model.h, fitted on
// the fit rows exactly as `thermal fit` fits it: changes since the first row, run over the whole log
// from its first row). The loop then looks for what that model lacks: its prediction g(k) is one
// regressor column of a linear model,
//   y(k) = c0 + a g(k) + (candidate effects' columns) + e(k),
// so a is about 1 when the grey model is right, and an effect is what the grey model cannot
// produce. Prediction as a column rather than an offset y - g: the grey model was fitted without the
// effect and has absorbed part of it in its coefficients; a free a lets the refit take that part back
// (with a = 1 fixed a real effect is smaller and some go unseen). The baseline is this model
// without effects. Candidates: `lag:<col>` (a further first-order lag path of a declared input, beside
// the grey model's own single time constant: a second time constant the grey model lacks),
// `input:<col>`, `drift`; `lag` (every input through one more lag) is not tried: a grey model is
// that lag itself. Every validation fold fits its own grey model on its own rows (same seed).
//
// Candidate effects (docs/file-formats.md#effect-catalogue names), each adding one parameter with the linear
// coefficients refitted:
//   `lag`          every declared input through the first-order lag L_tau of effects_thermal.h;
//                  tau by a 1-D search (log-spaced grid over [dt / 2, fit span], dt the median
//                  step of the fit rows, then Brent's method on log tau) minimising the sum of
//                  squares of the rows being fitted;
//   `lag:<col>`    the same for one declared input;
//   `input:<col>`  every numeric column of the log that is neither declared, the target, another
//                  displacement channel nor time, with a static coefficient (change since row 1);
//   `drift`        a time term per_min * (t - t0).
// Standard errors: linear coefficients from s^2 (X^T X)^-1 on the fit rows; tau from the curvature
// of the profile sum of squares, Var(tau) = 2 s^2 / S''(tau). Both assume white residuals.
//
// Blocked (forward) validation inside the fit rows: a rolling origin with `validationFolds` (K = 3)
// folds. The fit rows are cut at e_f = round(nFit (K + f - 1) / (2 K)), f = 1..K (for K = 3: at 1/2,
// 2/3 and 5/6 of the fit rows); fold f fits on rows [0, e_f) and predicts the next block
// [e_f, e_{f+1}) (e_{K+1} = nFit), as the final model fits the first part of the log and predicts
// the part after it. A lag's tau is searched again inside every fold on that fold's rows. The
// validation error is the pooled rms over the K blocks, cv = sqrt(sum SSE_f / sum rows_f). Rolling
// origin rather than one split: three forward extrapolations of different length average out a
// block that happens to be easy or hard, and the blocks together cover the second half of the fit
// rows. Forward rather than shuffled: a thermal log is autocorrelated, a shuffled fold would
// interpolate between its neighbours and reward effects that do not extrapolate.
//
// Acceptance on evidence: a candidate is accepted only when its validation error is at least
// `minHeldoutGain` (10 %) below the current model's *and* the validation error it explains,
// sqrt(cv_before^2 - cv_after^2), is at least `minExplainedNoise` (1) times the noise level (the rms
// of the first differences of the declared model's fit residual / sqrt 2) *and* the fit rows show
// in-sample evidence (n ln(SSE_before / SSE_after) > ln n: the Bayesian information criterion of
// the fit rows falls), so that an effect the fit rows cannot determine does not win by a lucky
// extrapolation of poorly determined coefficients, *and* a lag's tau is determined (its standard
// error below half of it). Among the candidates that pass, the one with the
// lowest ln(cv_after / cv_before) + ln(rmse_after / rmse_before) is accepted, the model refitted on
// all fit rows with it (its reported parameters come from this fit), and the remaining candidates
// tried again, until none passes. `lag` (every declared input lagged) is accepted over the best
// passing `lag:<col>` only when its validation error is another `minHeldoutGain` lower: the fit rows
// often cannot tell whether an input that hardly changes on them is lagged too, and the specific
// claim is the one they support. (The explained-noise factor was 2 when the held-out half chose the
// effects; the validation blocks are the later half of the fit rows, a quarter of a log, where an
// effect that grows over the log - a drift, a load that comes later - is smaller, and a factor 1
// still asks that the effect explain as much validation error as the whole noise: on clean data
// cv_before is about the noise, so a spurious effect would have to bring cv_after to zero.)
// Earlier accepted lags keep their tau (per fold, and on all fit
// rows) when later effects are added.
// Two effects in one log can each extrapolate worse alone than the declared model (each absorbs
// part of the other on the fit rows): when no single candidate passes, the three with the strongest
// in-sample evidence are each tried with every other candidate (a lag re-estimated with the other
// effect present) under the same tests with the penalty of two parameters, and the best passing
// pair is accepted as two candidates of that round ("accepted together with ...").
//
// The open world (docs/file-formats.md#residual_check, residual_check.h):
//   * Outliers: robust z of the declared model's residual on the fit rows (findOutliers); the rows
//     above the threshold are excluded from every fit (weight 0), listed with their 1-based data row
//     in residual_check.outliers and a note.
//   * Variables the residual may depend on: time (its natural order: Ljung-Box), the data row, and
//     every numeric column of the log but the target (declared inputs too: a non-linear dependence
//     on a declared input is structure the model lacks), on the fit rows.
//   * Generic candidates `unexplained:<against>`: each round, the three strongest structures of the
//     current residual (genericCandidates; never another displacement channel, an output), their
//     basis evaluated on every row so that held-out rows are predicted, compete with the named
//     candidates under the same tests (validation gain, explained noise, in-sample BIC with q
//     parameters plus the search penalty 2 ln(tests)). A passing named effect is preferred to a
//     generic one, unless the generic effect of the same variable (lag:<col> and input:<col>: <col>;
//     drift: time) validates better by the acceptance margin: then the name is rejected ("a named
//     effect must explain what it was chosen for"). Unlike the setup/matching/kinematic loops the
//     thermal loop is not rerun without each name (keepNamedOnlyWhenNeeded): the comparison is made
//     in the round, on the validation error, at the cost of one loop.
//   * residual_check: the final fit-rows residual (outliers excluded) against those variables.
//
// Implementation: every fit is a least-squares fit of standardised columns (centred and scaled on
// the fit rows) from Gram matrices [1 X y]^T [1 X y] accumulated per block of rows (the K + 1 blocks
// of the fit rows and the held-out block): a fold's fit sums its blocks, its validation error is
// y^T y - 2 b^T X^T y + b^T X^T X b of the next block, so one pass over the rows gives every fold,
// the fit on all fit rows and the held-out error. The per-block sums and products of every column
// are stored and reused (a candidate adds one column: one pass over the rows for its products with
// the others); a lag searched over tau makes one column per tau, dropped after use. Speed on long
// logs: above 20 000 rows the lag search's grid and the folds' tau refinement run
// on group means of m = ceil(n / 20 000) consecutive rows (the lag filtered on the group means),
// which only brackets tau; the reported tau is refined on every row (Brent's method to 1e-5 in
// log tau within +-0.05 of the coarse optimum) and every reported and tested error (fit, fold
// validation, held-out) is computed on every row. Pairs: every linear candidate and the lags among
// the six best single fits are partners (before: every candidate). The round's search for
// structure (which generic candidates to try) runs on the same group means; the final residual
// check on every fit row. Sums over rows use four partial sums, the lag filter two interleaved
// chains (equal steps). The observer is also asked inside a candidate (every tau of a lag search,
// with the last step's figures): a stop ends the loop at once with the note "cancelled" (the
// unfinished candidate is not listed). Measured by metrofit-bench --diagnose-scale.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::diagnose {

/// The declared model the loop starts from (see the header comment).
enum class ThermalDeclaredModel { Linear, Gmc, Gnnmci };
/// "linear", "gmc", "gnnmci".
const char* toString(ThermalDeclaredModel m);
/// The model named `name`; OptionsError naming `field` otherwise.
ThermalDeclaredModel thermalDeclaredModel(const std::string& name, const std::string& field = "--declared");

struct ThermalDiagnosisOptions {
  std::string target;
  ThermalDeclaredModel declared = ThermalDeclaredModel::Linear;
  std::uint64_t seed = 1;           ///< GNNMCI's swarm (declared gnnmci)
  std::vector<std::string> inputs;  ///< the declared inputs
  double trainFraction =
      thermal::kDefaultTrainFraction;  ///< fit on the first fraction of the rows, hold out the rest
  double minHeldoutGain = 0.10;        ///< relative validation (blocked CV) rmse reduction needed
  double minExplainedNoise = 1.0;      ///< explained validation rms needed, in noise levels
  int maxRounds = 6;                   ///< at most this many effects are accepted
  int lagGridPoints = 36;              ///< tau grid of the 1-D search
  int validationFolds = 3;             ///< K of the rolling-origin validation inside the fit rows
  bool tryPairs = true;                ///< when no single candidate passes, try pairs (see above)

  bool isValid(std::string* why) const;
};

/// Runs the loop on `log` (see the header comment). InputError (ValidationError) naming the file
/// and column when the target or an input is missing, inputs repeat, there are too few rows for
/// the fit and held-out parts, or an input is constant on the fit rows; OptionsError for invalid
/// options. The observer sees one step per candidate tried (best = the current model's validation
/// rmse, component "cv_rmse"); when it stops the loop, the diagnosis so far is returned with the
/// note "cancelled". A log with gaps (an MTConnect log) is diagnosed on its rows with a value in the
/// target and every input, with the channels complete there (thermal::thermalLogWithoutGaps).
Diagnosis diagnoseThermal(const ThermalLog& log, const ThermalDiagnosisOptions& options,
                          Observer* observer = nullptr);

}  // namespace metrofit::diagnose
