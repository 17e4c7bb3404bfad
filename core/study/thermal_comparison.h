#pragma once
// Qt-free runs behind the thermal model views and the report (Abdulshahed 2016, grey neural network thermal
// model, Section 4 and Table 4): the three models of core/thermal (GNNMCI(1,N) by PSO, GMC(1,N) by least
// squares, the MLP by Levenberg-Marquardt) fitted on the first part of one log with the same settings and
// compared on the rest, the modular case of Section 4.3 (Z + C heating tests -> the combined test),
// hysteresis runs for the charts and the decimation the report uses for long logs.
//
// One train fraction for all three models (the CLI's `thermal fit` defaults differ by model: 0.5 for
// the grey models, 0.7 for the MLP); the comparison needs the same held-out rows for all. Each model
// is fitted exactly as `metrofit-cli thermal fit --model M --train-fraction F --seed S` does
// (thermal::fitAndEvaluate with the default options and the seed), so the numbers agree bit for bit.
// A model that cannot be fitted on a log (GMC(1,N) on a noise-free log whose target is exactly linear
// in an input) is marked failed with its reason; the others are fitted and compared.
//
// Project keys of the thermal study read here (`studies.thermal`): "dataset", "target", "inputs",
// "train_fraction", "seed" (defaultThermalModelSettings) and "modules": {MODULE: {"dataset": ID}}, the
// test a module of the modular case is identified on when it is not the module's own first test (the
// Modular tab's "Identify again…", one undoable edit; studyModuleTests, identifyModulesOnStudyTests).
#include <array>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/thermal/hysteresis.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"

namespace metrofit {

/// What a comparison is run with.
struct ThermalModelSettings {
  std::string target;
  std::vector<std::string> inputs;
  double trainFraction = thermal::kDefaultTrainFraction;
  std::uint64_t seed = 1;
  /// Effects added to the model with Apply on the diagnosis page (studies.diagnosis.thermal.applied,
  /// core/diagnose/thermal_applied.h: lagged inputs, extra input columns, a drift term): every model
  /// is also fitted with them and keeps them where they lower its held-out error; an empty array: the
  /// declared inputs only.
  nlohmann::json applied = nlohmann::json::array();
  bool operator==(const ThermalModelSettings&) const = default;
};

/// Settings for a log: the project's thermal study (`studies.thermal`: "dataset", "target",
/// "inputs", optional "train_fraction", "seed"; ThermalSettings of core/study/study_settings.h) when it
/// names this dataset: its values are used as they are, and a bad one (a fraction outside (0, 1), a
/// target or input the log does not have) is a ValidationError naming the field, never replaced by a
/// default. Otherwise (another log, or a study without target and inputs) the first displacement
/// channel as target and, as inputs, the strain channels plus T2 when the log has strain sensors (the
/// paper's choice, Section 4.3: FBG-1..4 and the ram temperature), else every non-ambient temperature
/// (at most 8).
ThermalModelSettings defaultThermalModelSettings(const ThermalLog& log, const nlohmann::json& thermalStudy,
                                                 const std::string& datasetId);

/// The models in the order they are trained and shown: the paper's three, then the regression models
/// of real thermal logs (static linear, first-order lag per sensor, distributed lag).
inline constexpr std::array<thermal::ThermalModelKind, 6> kThermalModelOrder = {
    thermal::ThermalModelKind::Gnnmci, thermal::ThermalModelKind::Gmc,
    thermal::ThermalModelKind::Mlp,    thermal::ThermalModelKind::Linear,
    thermal::ThermalModelKind::Lag,    thermal::ThermalModelKind::DistributedLag};
inline constexpr std::size_t kThermalModelCount = kThermalModelOrder.size();

/// Progress of a comparison: which model (index into kThermalModelOrder) and its iteration.
using ThermalComparisonObserver = std::function<ObserverDecision(int model, const IterationSummary& summary)>;

struct ThermalComparison {
  ThermalModelSettings settings;
  thermal::ThermalSeries series;         ///< the declared inputs
  thermal::ThermalSeries appliedSeries;  ///< with the applied effects' columns as inputs (no rows: none)
  std::string appliedText;  ///< the applied effects, e.g. "lag:T2 (15.5 min)"; empty: none applied
  /// With applied effects every model is fitted on `series` and on `appliedSeries` and keeps the
  /// variant with the lower held-out RMSE (ties: declared; core/diagnose/thermal_applied.h
  /// fitDeclaredAndWithEffects): `models` holds the kept fits, `usesApplied` which one each is, and
  /// the held-out RMSE of both variants (NaN where not fitted).
  std::array<thermal::ThermalEvaluation, kThermalModelCount>
      models;                                          ///< in kThermalModelOrder, the kept variants
  std::array<bool, kThermalModelCount> usesApplied{};  ///< the model keeps the applied-effect inputs
  std::array<double, kThermalModelCount> declaredHeldoutRmse{};  ///< held-out RMSE with the declared inputs
  std::array<double, kThermalModelCount> appliedHeldoutRmse{};   ///< held-out RMSE with the applied effects
  std::array<double, kThermalModelCount> seconds{};              ///< wall time of each model's fit(s)
  /// Per model, why it could not be fitted (empty: fitted, or not run after a cancel): a failure of
  /// that model alone (GMC(1,N)'s least squares is rank deficient on a noise-free log whose target is
  /// exactly linear in an input; too few rows for its parameters) as a one-line reason. The other
  /// models are fitted and shown; a failed model has no prediction, no figures (its `models` entry is
  /// empty) and is never the best model.
  std::array<std::string, kThermalModelCount> failed;
  std::size_t fitRows = 0, heldoutRows = 0;  ///< the rows every model is fitted on / tested on
  bool cancelled = false;                    ///< an observer stopped a training
  /// Model i was fitted (not failed, not skipped after a cancel): its prediction covers every row.
  bool fitted(std::size_t i) const {
    return failed[i].empty() && !series.timeMin.empty() && models[i].predicted.size() == series.rows();
  }
};

/// Fits and evaluates the three models (see above); with applied effects in the settings each model
/// is fitted with and without them and keeps the better variant on the held-out rows (when one variant
/// cannot be fitted, the other).
/// Throws the core's InputError / OptionsError for bad columns or settings (a bad applied entry: a
/// ValidationError naming studies.diagnosis.thermal.applied[i]...; a bad train fraction, too few
/// held-out rows, a constant target or input: every model refuses the log, and the first model's error
/// is thrown). A model that fails alone is recorded in `failed`. `cancelled` is set (and the remaining
/// models skipped) when the observer stops.
ThermalComparison compareThermalModels(const ThermalLog& log, const ThermalModelSettings& settings,
                                       const ThermalComparisonObserver& observer = {});

/// The modular case as separate modules (each identified on its own test, the combined test predicted as
/// their sum): module i takes the temperature and strain channels that its own test moves at least
/// twice as much as every other training test does (the sensors its own heating reaches), and is
/// identified with the distributed-lag model on its test.
struct ModularModules {
  std::vector<std::string> names;                ///< one per training test
  std::vector<std::vector<std::string>> inputs;  ///< per module
  /// Per module, the test it was identified on: its training test's name (the module's name) or, after
  /// identifyModuleAgain, the name given there.
  std::vector<std::string> tests;
  /// The modules as fitted (one per name when `evaluation` is set): saveThermalModules writes them,
  /// identifyModuleAgain keeps all but one of them as they are.
  std::vector<thermal::ThermalModule> fitted;
  std::optional<thermal::ModulesEvaluation> evaluation;
  std::string why;  ///< why there is no evaluation (a module without inputs, a failed fit)
};
/// The channels of the rule above, per training test (same order).
std::vector<std::vector<std::string>> moduleInputs(const std::vector<const ThermalLog*>& trainingTests,
                                                   const ThermalLog& test, const std::string& target);

struct ModularComparison {
  std::string target;
  std::vector<std::string> inputs;
  thermal::ThermalSeries test;                                        ///< the combined test
  std::array<thermal::ModularEvaluation, kThermalModelCount> models;  ///< in kThermalModelOrder
  /// Per model, why it could not be fitted on the training tests (empty: fitted), as
  /// ThermalComparison::failed: a failed model has no prediction and no figures.
  std::array<std::string, kThermalModelCount> failed;
  ModularModules modules;  ///< the same case module by module
  bool cancelled = false;
  /// Model i was fitted and predicts every row of the test.
  bool fitted(std::size_t i) const {
    return failed[i].empty() && !test.timeMin.empty() && models[i].predicted.size() == test.rows() &&
           models[i].training.run.termination != Termination::Cancelled;
  }
};

/// Section 4.3: each model fitted on the training tests together, predicting `test`.
/// `moduleNames` name the training tests' modules (default: their sources). Bad columns throw the
/// core's InputError; a model that cannot be fitted on these tests (a rank-deficient GMC(1,N)) is
/// recorded in `failed` and the others are fitted.
ModularComparison compareModularModels(const std::vector<const ThermalLog*>& trainingTests,
                                       const ThermalLog& test, const std::string& target,
                                       const std::vector<std::string>& inputs, std::uint64_t seed,
                                       const ThermalComparisonObserver& observer = {},
                                       const std::vector<std::string>& moduleNames = {});

/// Identifies module `index` of `modules` again on another test of its drive (`moduleTest`, named
/// `testName` in `tests`, e.g. a new C-heating test after new bearings), as compareModularModels identifies
/// it: its own inputs, the distributed-lag model, `seed`. Every other module keeps its fitted model as it
/// is (the same coefficients, not fitted again) and the combined test (`combined`, the log the modules
/// were evaluated on) is predicted again as their sum. Needs every module fitted (`modules.evaluation`);
/// InputError naming the log and column when `moduleTest` lacks the target or one of the module's inputs
/// or the module cannot be fitted on it: `modules` is then unchanged. Returns false (and changes nothing)
/// when the observer stops the fit.
bool identifyModuleAgain(ModularModules& modules, std::size_t index, const ThermalLog& moduleTest,
                         const std::string& testName, const ThermalLog& combined, const std::string& target,
                         std::uint64_t seed, Observer* observer = nullptr);

/// The tests named for the modules in the project's thermal study: `studies.thermal.modules`, an object
/// {MODULE: {"dataset": ID}} (MODULE: the module's name, which in a project is the dataset id of its
/// first test, kModularZId / kModularCId; ID: the thermal_log dataset the module is identified on instead).
/// Per entry of `names`, the dataset id, or the name itself when the study names none.
std::vector<std::string> studyModuleTests(const nlohmann::json& thermalStudy,
                                          const std::vector<std::string>& names);

/// Every module of `modules` whose test in the thermal study (studyModuleTests) is not the one it was
/// identified on, identified again on that test (identifyModuleAgain; `logOf(id)` gives the thermal log
/// of the project's dataset `id`, nullptr when the project has none): the modular case as the project
/// declares it. Nothing happens without an evaluation (a module not identified). ValidationError naming
/// studies.thermal.modules.MODULE.dataset when the project has no such thermal log; identifyModuleAgain's
/// errors. Returns false when the observer stopped a fit.
bool identifyModulesOnStudyTests(ModularModules& modules, const nlohmann::json& thermalStudy,
                                 const std::function<const ThermalLog*(const std::string&)>& logOf,
                                 const ThermalLog& combined, const std::string& target, std::uint64_t seed,
                                 Observer* observer = nullptr);

/// Dataset ids of the modular case in a project (the demo's): the Z-heating, the C-heating and the
/// combined (helical) test.
inline constexpr const char* kModularZId = "thermal_modular_z";
inline constexpr const char* kModularCId = "thermal_modular_c";
inline constexpr const char* kModularCombinedId = "thermal_modular_combined";

/// The inputs of the modular case: FBG strain channels and T2 when present (the paper's), else the
/// defaults of defaultThermalModelSettings.
std::vector<std::string> modularInputs(const ThermalLog& log);

/// A contiguous run of rows of one phase (+1 heating, -1 cooling) of a hysteresis analysis.
struct PhaseRun {
  int phase = 1;
  std::size_t first = 0, last = 0;  ///< rows, inclusive
};
/// The runs of `phase` in row order.
std::vector<PhaseRun> phaseRuns(const std::vector<int>& phase);

/// Every `stride`-th row of a log (the first and the last always), for fitting long logs in reports.
ThermalLog decimateThermalLog(const ThermalLog& log, std::size_t stride);

}  // namespace metrofit
