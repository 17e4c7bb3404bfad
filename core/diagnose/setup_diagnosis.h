#pragma once
// The closed loop for the setup domain (docs/file-formats.md#the-declared-models: constant errors
// of the setup data acting through the relation graph, nothing else).
//
// Data: a CMM report series (core/setup/report.h), one row r per (part, dimension q) with the
// deviation y_r = measured - nominal, the part number p_r and the time t_r (time_min).
//
// Declared model: y_r = (G e)_q + noise, e the constant setup-data errors (one per datum, mm), G the
// gain matrix of the relation graph (model.h, the paper's Eq. 4-5), fitted by least squares over
// all rows of all parts. G is often rank deficient (a work offset and a tool offset feeding the
// same features): the fit is the minimum-norm one and only the residual is used (see
// linear_evidence.h); the notes give the rank.
//
// Candidate effects (docs/file-formats.md#effect-catalogue names), each one extra column of the design:
//   tool_wear:<tool>    the tool's effective length changes linearly with the part number,
//                       e_T(p) = e_T + mm_per_part * p           column G[q][T] * p_r
//                       (for every setup datum of kind "tool");
//   drift:<datum>       the datum drifts linearly in time, e_i(t) = e_i + mm_per_min * t
//                                                                 column G[q][i] * t_r
//                       (for every setup datum).
// The part number is the number in the "part" column when every part name is a number, else the
// part's position in order of appearance (1, 2, ...). When time_min is proportional to the part
// number, tool_wear:T and drift:T are the same column: the tie goes to tool_wear (listed first) and
// the evidence says that the two cannot be told apart.
//
// The loop: fit the declared model plus the accepted effects; try every remaining candidate; accept
// the one with the lowest dBIC when decideAcceptance (linear_evidence.h) says yes; repeat until no
// candidate is accepted. Parameters carry standard errors (sigma^2 (Zp^T Zp)^-1). Diagnosis::effects
// holds the accepted candidates (in the round they were accepted) followed by every other candidate
// as tried in the last round. The residual plot of a candidate shows, per part, the apparent error
// of the affected datum (the least-squares fit of that part's residuals on column G[.][i]) against
// the part number (tool wear) or the time (drift), before and after the effect.
//
// Errors: ValidationError when the measurements do not belong to the model (dimension index out of
// range), when there are fewer rows than the declared model's rank + 1; OptionsError for invalid
// options.
//
// The open world (docs/file-formats.md#residual_check, residual_check.h): rows whose declared-model residual
// has a robust z above the outlier threshold are excluded before the loop
// (Diagnosis::residualCheck->outliers, with row, part and dimension). Every round also tries the generic
// effects of the current residual's strongest structures (variables: row and time in file order, part and
// dimension as levels, and dimension:<d> = the part number on the rows of dimension d, datum:<id> = the part
// number times the datum's gain on each row), each its basis as extra columns, under the same decision with
// an extra penalty 2 ln(tests) for the search; the winner of the round is the candidate with the lowest dBIC,
// so a named effect is given only when it explains the data at least as well as the generic alternative. The
// final residual's check is in residualCheck.
#include <string>

#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/diagnose/linear_evidence.h"
#include "core/setup/model.h"
#include "core/setup/report.h"

namespace metrofit::diagnose {

struct SetupDiagnosisOptions {
  /// Defaults: dBIC < -10, rmse reduction >= 2 % and >= 0.0001 mm (a tenth of a typical CMM
  /// resolution).
  AcceptanceOptions acceptance{10.0, 0.02, 1e-4};
  int maxRounds = 10;  ///< at most this many effects are accepted
  bool isValid(std::string* why) const;
};

/// The loop on a measured report series. The observer is called after every round (iteration =
/// round, best = fit rmse, components rmse and accepted count) and may cancel (the result then
/// holds the rounds done).
Diagnosis diagnoseSetup(const setup::Model& model, const setup::Measurements& measurements,
                        const SetupDiagnosisOptions& options = {}, Observer* observer = nullptr);

}  // namespace metrofit::diagnose
