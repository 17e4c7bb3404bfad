#pragma once
// The setup-correction study of a project as the GUI page and the report section use it, without
// Qt widgets: which datasets it reads (studies.setup.model / .dataset, else the first setup_model
// and cmm_report datasets), the model and measurements read from them, and one run of a method
// (core/setup/methods.h, exact.h) reduced to what the views show: the corrections, the scores and
// the convergence trace (best f1, f2, f against the number of solutions evaluated).
//
// Edited models: the measurements are read against the model FILE (report.h checks the report's
// tolerance limits against it); a model edited in the graph editor gets the deviations of its
// dimensions by id (measurementsFor), so tolerance edits can be tried before the model is saved.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/diagnose/applied_setup_matching.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"

namespace metrofit {
class Project;

/// Paths and ids of the study's datasets.
struct SetupStudyFiles {
  std::string modelId, reportId;         ///< dataset ids (empty when the project has none)
  std::string modelPath, reportPath;     ///< resolved paths (empty when the project has none)
  std::vector<std::string> reportPaths;  ///< every file of the report (a DMIS series: one per workpiece)
  CsvReadOptions reportCsv;              ///< how the report is read (a CSV report's dialect and mapping)
  setup::DmisOptions reportDmis;         ///< how a DMIS report's TA(label) values are read (its "dmis" key)
  std::string method = "exact";          ///< studies.setup.method, when set
  long budget = setup::kPaperBudget;     ///< studies.setup.budget, when set
  std::uint64_t seed = 1;                ///< studies.setup.seed, when set
};

/// The study's datasets (see above); `projectPath` resolves relative dataset paths.
SetupStudyFiles setupStudyFiles(const Project& project, const std::string& projectPath);

/// The effects added to the setup model with the diagnosis page's Apply
/// (studies.diagnosis.setup.applied, core/diagnose/applied_setup_matching.h), read against the
/// model the measurements belong to, when the diagnosis ran on the report `reportId` the
/// measurements were read from (studies.diagnosis.setup.dataset; another report keeps the
/// declared model). With effects, measurements.deviationMm becomes the predicted
/// deviation of the next part (tool wear x part number, drift x time), so the runs, the corrections
/// and their exports include them; without, nothing changes. `prediction` (optional) receives the
/// figures of the model with the effects, `declared` those of the declared model (without them).
/// ValidationError naming `source` and the field (studies.diagnosis.setup.applied[i].name, ...).
std::vector<diagnose::AppliedSetupEffect> applyStudyEffects(const Project& project, const std::string& source,
                                                            const std::string& reportId,
                                                            const setup::Model& model,
                                                            setup::Measurements& measurements,
                                                            diagnose::SetupPrediction* prediction = nullptr,
                                                            diagnose::SetupPrediction* declared = nullptr);

/// Deviations of the dimensions of `model` (by id) from measurements read against `fileModel`.
/// ValidationError naming the dimension when the report has no rows for one.
std::vector<double> deviationsFor(const setup::Model& model, const setup::Model& fileModel,
                                  const setup::Measurements& measurements);

/// One point of a convergence trace: the best solution after `evaluations` solutions.
struct SetupTracePoint {
  long evaluations = 0;
  double f1 = 0.0, f2 = 0.0, f = 0.0;  ///< mm
};

/// What a run of one method produced.
struct SetupRunOutcome {
  std::string method;  ///< "exact", "cripso", ...
  std::uint64_t seed = 0;
  long budget = 0;
  std::vector<double> x;  ///< corrections, mm, one per setup datum
  setup::SetupScore score;
  double f1Before = 0.0;
  long evaluations = 0;  ///< solutions evaluated (exact: solver calls)
  std::vector<SetupTracePoint> trace;
  Termination termination = Termination::Converged;
  double seconds = 0.0;                       ///< wall time of the run
  bool f1Optimal = false, f2Optimal = false;  ///< exact: the certificate
};

/// Runs a method ("exact" or a metaheuristic of setupMetaheuristicNames()) on the instance. The
/// observer sees every iteration (metaheuristics) and may stop the run (Termination::Cancelled).
/// Throws OptionsError for an unknown method or a bad budget.
SetupRunOutcome runSetupMethod(const setup::SetupInstance& instance, const std::string& method, long budget,
                               std::uint64_t seed, Observer* observer = nullptr);

/// Trace point of an iteration summary with components f1, f2, f (as SetupProblem reports them).
SetupTracePoint tracePoint(const IterationSummary& summary);

/// Per measured part: in tolerance before and after the correction x (every row of the part within
/// its dimension's limits, deviation + (G x)_q after). Parts counted by name, in report order.
struct SetupPartsSummary {
  int parts = 0;
  int inToleranceBefore = 0;
  int inToleranceAfter = 0;
  int rescued = 0;  ///< out of tolerance before, in tolerance after
  int lost = 0;     ///< in tolerance before, out after
};
/// `measurements` as read against `fileModel`; rows are mapped to the instance's dimensions by id.
SetupPartsSummary partsSummary(const setup::SetupInstance& instance, const setup::Model& fileModel,
                               const setup::Measurements& measurements, const std::vector<double>& x);

}  // namespace metrofit
