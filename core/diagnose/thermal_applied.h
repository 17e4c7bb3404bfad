#pragma once
// Thermal effects added to a model ("Apply adds the accepted effect to the study's model so
// later runs and compensations include it"). One place turns a set of thermal effects into the
// columns a model fits on, used by the closed loop itself (thermal_diagnosis.h) and by every fit of
// the thermal study (the Thermal page's Models tab, the report's thermal section):
//
//   declared input x_j       x_j, or L_tau[x_j] (lag_regression.h firstOrderLagMin) with `lag` (every
//                            declared input) or `lag:<col>` (that input; overrides `lag`)
//   `input:<col>`            z(t) - z(0) of a further column of the log
//   `drift`                  t - t0 (min)
//   `unexplained:<against>`  the columns of the generic effect's basis (residual_check.h genericBasis
//                            of its fixed shape) on time (min), the data row (1-based) or a column:
//                            "unexplained:<against>#1", "#2", ...
//
// The applied list is what the diagnosis page's Apply stores (studies.diagnosis.thermal.applied,
// effect names and parameter keys of docs/file-formats.md#effect-catalogue):
//   [{"name": "lag:T2", "parameters": {"tau_min": 15.5}}, {"name": "input:spindle_rpm",
//     "parameters": {"coefficient": 0.001}}, {"name": "drift", "parameters": {"per_min": 0.01}},
//    {"name": "unexplained:T2", "parameters": {...}, "shape": {"against": "T2", "form": "smooth", ...}}]
// (a generic effect's "shape": applied_entries.h genericShapeJson; its coefficients are refitted).
// Only a lag's tau is taken from it: the linear coefficients (of the inputs, `input:<col>`'s
// coefficient, `drift`'s per_min) are refitted by every model with the effect's column included,
// as the diagnosis refits them when it adds an effect.
//
// Errors (ValidationError, field "<field>[i].name" or "<field>[i].parameters.tau_min"): an entry that
// is not an object, a missing or unknown name, an effect given twice, a lag without a positive
// finite tau_min, a column the log does not have, `lag:<col>` of a column that is not an input of
// the model, `input:<col>` naming the target.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/run.h"
#include "core/diagnose/residual_check.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"

namespace metrofit {
class Project;
}

namespace metrofit::diagnose {

/// Where the diagnosis page stores the applied thermal effects (the field errors name).
inline constexpr const char* kThermalAppliedField = "studies.diagnosis.thermal.applied";

/// Effects added to the declared thermal model (the closed loop's model state).
struct ThermalEffectSet {
  double lagAll = 0.0;                   ///< > 0: `lag` of every declared input, tau in min
  std::map<std::string, double> lagCol;  ///< `lag:<col>` tau in min (overrides lagAll for that input)
  std::vector<std::string> extra;        ///< `input:<col>`
  bool drift = false;                    ///< `drift`
  /// `unexplained:<against>`: generic effects (their fixed shapes) of time, row or a column.
  std::vector<GenericForm> generic;

  bool empty() const {
    return !(lagAll > 0.0) && lagCol.empty() && extra.empty() && !drift && generic.empty();
  }
};

/// One column a model fits on (see the header comment).
struct ThermalRegressor {
  std::string name;     ///< the closed loop's name: the input ("T2"), "input:<col>", "drift",
                        ///< "unexplained:<against>#<j>" (1-based basis column)
  std::string channel;  ///< column name in withThermalEffects' log: "T2", "lag:T2", "input:<col>", "drift"
  std::string unit;     ///< the source column's unit; "min" for drift
  double lagMin = 0.0;  ///< tau of a lagged input, else 0
  std::vector<double> values;  ///< one per row
};

/// The columns of the declared `inputs` with the effects, in the order inputs, `input:<col>`,
/// `drift`, the generic effects' basis columns. The columns must exist in `log` (ValidationError naming the
/// log and column otherwise).
std::vector<ThermalRegressor> thermalRegressors(const ThermalLog& log, const std::vector<std::string>& inputs,
                                                const ThermalEffectSet& effects);

/// An applied list read and checked (see the header comment).
struct AppliedThermalEffects {
  ThermalEffectSet effects;
  std::vector<std::string> labels;  ///< per applied entry: "lag:T2 (15.5 min)", "input:spindle_rpm", "drift"

  bool empty() const { return effects.empty(); }
  /// The labels joined with ", " (empty when none).
  std::string text() const;
};

/// Reads an applied list and checks it against the log, the model's target and inputs.
/// `input:<col>` of a column that already is an input adds nothing. `field` names the list in errors.
AppliedThermalEffects appliedThermalEffects(const nlohmann::json& applied, const ThermalLog& log,
                                            const std::string& target, const std::vector<std::string>& inputs,
                                            const std::string& field = kThermalAppliedField);

/// A log with the effects' columns (ThermalRegressor::channel) added, and the model's inputs: the
/// declared inputs (lagged ones replaced by their "lag:<col>" column), then "input:<col>", "drift".
struct ThermalLogWithEffects {
  ThermalLog log;
  std::vector<std::string> inputs;
};
ThermalLogWithEffects withThermalEffects(const ThermalLog& log, const std::vector<std::string>& inputs,
                                         const ThermalEffectSet& effects);

/// One model fitted twice, on the declared inputs and on the inputs with the applied effects, with the
/// same options and seed. An effect must never make the held-out error worse: the variant
/// with the lower held-out RMSE is kept, the declared one on a tie or when the effects' RMSE is not
/// finite. (GNNMCI(1,N) and GMC(1,N) are first-order lags of their inputs themselves: on the demo a
/// `lag:T2` makes their held-out error rise, so they keep the declared inputs.)
struct ThermalVariantFit {
  thermal::ThermalEvaluation declared;     ///< fitted on the declared inputs
  thermal::ThermalEvaluation withEffects;  ///< fitted with the applied effects (not run when cancelled)
  bool usesEffects = false;                ///< withEffects is the kept variant
  bool cancelled = false;                  ///< the observer stopped one of the fits
  const thermal::ThermalEvaluation& kept() const { return usesEffects ? withEffects : declared; }
};

/// True when a fit with held-out RMSE `withEffectsRmse` is kept over one with `declaredRmse`.
bool keepsAppliedEffects(double declaredRmse, double withEffectsRmse);

/// thermal::fitAndEvaluate on `declared` and on `withEffects` (both with `options`, so the same
/// seed), the kept variant chosen with keepsAppliedEffects. The two fits run at once (the second on a
/// thread of its own) with the results of running them one after the other, bit for bit, and
/// `observer` sees what it saw then, one call at a time: the declared fit's iterations, then the
/// with-effects fit's. When it stops the declared fit, the second one is stopped and not reported.
ThermalVariantFit fitDeclaredAndWithEffects(const thermal::ThermalSeries& declared,
                                            const thermal::ThermalSeries& withEffects, double trainFraction,
                                            const thermal::ThermalFitOptions& options,
                                            Observer* observer = nullptr);

/// The applied thermal effects of a project that apply to the thermal log `datasetId`: the list
/// studies.diagnosis.thermal.applied when the log is the one the thermal diagnosis ran on
/// (studies.diagnosis.thermal.dataset; the effects and their parameters were estimated on it, so the
/// thermal study includes them when it fits that log); an empty array otherwise or when nothing is
/// applied. Never throws: appliedThermalEffects checks the list.
nlohmann::json projectThermalApplied(const Project& project, const std::string& datasetId);

}  // namespace metrofit::diagnose
