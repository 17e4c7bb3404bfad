#pragma once
// The closed loop in the thermal domain (issue 8, CONTRACT.md "The declared models", "diagnose").
//
// Declared model: the target is a static linear function of the declared inputs,
//   y(k) = c0 + sum_j b_j x_j(k) + e(k),
// fitted by least squares on the first `trainFraction` of the rows (thermal::fitRowCount, as
// `thermal fit`), held out on the rest.
//
// Candidate effects (CONTRACT.md names), each adding one parameter with the linear coefficients
// refitted:
//   `lag`          every declared input through the first-order lag L_tau of effects_thermal.h;
//                  tau by a 1-D search (log-spaced grid over [dt / 2, fit span], then golden
//                  section on log tau) minimising the fit rows' sum of squares;
//   `lag:<col>`    the same for one declared input;
//   `input:<col>`  every numeric column of the log that is neither declared, the target nor time,
//                  with a static coefficient (change since the first row);
//   `drift`        a time term per_min * (t - t0).
// Standard errors: linear coefficients from s^2 (X^T X)^-1 on the fit rows; tau from the curvature
// of the profile sum of squares, Var(tau) = 2 s^2 / S''(tau). Both assume white residuals.
//
// Acceptance on evidence (out of sample): a candidate is accepted only when its held-out rmse is
// at least `minHeldoutGain` (10 %) below the current model's *and* the held-out error it explains,
// sqrt(h_before^2 - h_after^2), is at least `minExplainedNoise` (2) times the noise level (the rms of
// the first differences of the declared model's fit residual / sqrt 2) *and* the fit rows show
// in-sample evidence (n ln(SSE_before / SSE_after) > ln n: the Bayesian information criterion of
// the fit rows falls), so that an effect the fit rows cannot determine does not win by a lucky
// extrapolation of poorly determined coefficients. Among the candidates that
// pass, the one with the lowest ln(h_after / h_before) + ln(rmse_after / rmse_before) (evidence in
// both parts of the data) is accepted, the model refitted with it, and the
// remaining candidates tried again, until none passes. An accepted effect therefore never makes
// the held-out error worse. Earlier accepted lags keep their tau when later effects are added.
// Two effects in one log can each extrapolate worse alone than the declared model (each absorbs
// part of the other on the fit rows): when no single candidate passes, the three with the strongest
// in-sample evidence are each tried with every other candidate (a lag re-estimated with the other
// effect present) under
// the same tests with the penalty of two parameters, and the best passing pair is accepted as two
// candidates of that round ("accepted together with ...").
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/thermal/thermal_log.h"

namespace metrofit::diagnose {

struct ThermalDiagnosisOptions {
  std::string target;
  std::vector<std::string> inputs;  ///< the declared inputs
  double trainFraction = 0.5;       ///< fit on the first fraction of the rows, hold out the rest
  double minHeldoutGain = 0.10;     ///< relative held-out rmse reduction needed
  double minExplainedNoise = 2.0;   ///< explained held-out rms needed, in noise levels
  int maxRounds = 6;                ///< at most this many effects are accepted
  int lagGridPoints = 36;           ///< tau grid of the 1-D search
  bool tryPairs = true;             ///< when no single candidate passes, try pairs (see above)

  bool isValid(std::string* why) const;
};

/// Runs the loop on `log` (see the header comment). InputError (ValidationError) naming the file
/// and column when the target or an input is missing, inputs repeat, there are too few rows for
/// the fit and held-out parts, or an input is constant on the fit rows; OptionsError for invalid
/// options. The observer sees one step per candidate tried (best = current held-out rmse); when it
/// stops the loop, the diagnosis so far is returned with the note "cancelled".
Diagnosis diagnoseThermal(const ThermalLog& log, const ThermalDiagnosisOptions& options,
                          Observer* observer = nullptr);

}  // namespace metrofit::diagnose
