#pragma once
// The setup-correction study page: the study's model and CMM report (studies.setup.model
// and .dataset, else the first setup_model / cmm_report datasets of the project) in four tabs:
//  * Graph: the relation-graph editor (its own undo stack); "Save model" writes the edited model
//    back to the dataset file atomically, "Revert" reads it again as one undo step (Ctrl+Z brings
//    the edits back). Unsaved edits are autosaved with the project (app/gui/autosave.h
//    AutosaveExtras, key "setup_model") and recovered as unsaved edits.
//  * Run: method (exact, CRIPSO, PSO, GA, COA), budget, seed, Run (Ctrl+R) / Cancel with a progress
//    bar shown while a run goes on; the run works in a worker thread and feeds the live convergence
//    chart, where earlier runs stay overlaid and the exact optimum is the reference line.
//  * Results: the last run's corrections, margins, parts rescued and exports.
//  * Validation: the paper's statistical validation (Fig. 18).
// The runs use the EDITED model (tolerance edits can be tried before saving); the measured
// deviations come from the report read against the model file, matched by dimension id.
// From a CMM report (issue 28 item 3): "Create setup model from report…" / "Add report features to setup
// model…" (the page's "From report…" button, the report's context menu in the navigator) list the report's
// characteristics (ReportModelDialog); the checked ones become a new model (written as data/<id>.json
// beside the project, added as a setup_model dataset and made the study's model and report: one undo step
// of the project) or are added to the edited model (one undo step of the graph editor). The graph
// editor's "Report feature" column offers the study's report's features as each dimension's label; a
// changed mapping is read against the report at once (before the model is saved).
// Effects added with the diagnosis page's Apply (studies.diagnosis.setup.applied: tool wear, datum
// drift) are part of the study's model: the deviations are then those predicted for the next part
// (core/study/setup_study.h applyStudyEffects); the info line says so, and undoing Apply brings
// the declared model back.
#include <QWidget>
#include <memory>
#include <optional>

#include "core/diagnose/applied_setup_matching.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace metrofit {
class ProjectDocument;
class SetupConvergenceView;
class SetupGraphEditor;
class SetupModelEditor;
class SetupResultsView;
class SetupValidationView;
class ReportModelDialog;
struct SetupRunOutcome;
struct ReportFeatures;

class SetupPage : public QWidget {
  Q_OBJECT
 public:
  explicit SetupPage(ProjectDocument* document, QWidget* parent = nullptr);
  ~SetupPage() override;

  /// "graph", "convergence" (runs exact, CRIPSO and PSO synchronously when nothing ran yet),
  /// "results" (the exact result when nothing ran yet), "validation".
  Q_INVOKABLE void showView(const QString& view);

  SetupModelEditor* modelEditor() const { return editor_; }
  SetupGraphEditor* graphEditor() const { return graph_; }
  SetupConvergenceView* convergenceView() const { return convergence_; }
  SetupResultsView* resultsView() const { return results_; }
  SetupValidationView* validationView() const { return validation_; }
  QTabWidget* tabs() const { return tabs_; }
  QComboBox* methodCombo() const { return method_; }
  QSpinBox* budgetSpin() const { return budget_; }
  QSpinBox* seedSpin() const { return seed_; }
  QPushButton* runButton() const { return run_; }
  QPushButton* cancelButton() const { return cancel_; }
  QProgressBar* progressBar() const { return progress_; }
  /// Why the study cannot run (unreadable model or report, invalid edited model); empty when it can.
  QString errorMessage() const { return error_; }
  /// Why the study's run settings (studies.setup.method, budget, seed) are refused, the field named
  /// ("studies.setup.budget: must be a number > 0 (solutions)"); empty when they are good. A refused
  /// setting is never replaced by a default: Run stays disabled until it is corrected (an edit of the
  /// control, Undo, or the project file).
  QString settingsError() const { return settingsError_; }
  /// What the project stores of the setup run for the study's report (results.setup.<report>,
  /// core/project/stored_results.h), or "" when nothing is stored: "From the saved project (computed
  /// <when>) ..." with the figures when the settings, the model and the data are those they came
  /// from, else "out of date" with why. Shown on the Results tab until a run is made.
  QString storedResultText() const;
  /// The info text (model, report, applied effects).
  QString infoText() const;
  /// The effects of studies.diagnosis.setup.applied in use (empty: the declared model).
  const std::vector<diagnose::AppliedSetupEffect>& appliedEffects() const;
  /// Figures of the study's model (with the applied effects) and of the declared model, when the
  /// report was read.
  std::optional<diagnose::SetupPrediction> prediction() const;
  std::optional<diagnose::SetupPrediction> declaredPrediction() const;
  /// The instance the runs use (edited model, deviations of the study's model), when valid.
  const setup::SetupInstance* instance() const;

  /// Starts a run in the worker thread with the panel's settings (false when one runs or the
  /// study cannot run; errorMessage() says why).
  bool startRun();
  /// Runs a method to the end on the calling thread (no progress), shows it like a finished run.
  bool runSynchronously(const QString& method, long budget, unsigned long long seed);
  void cancelRun();
  bool isRunning() const;
  /// Waits until the running run has finished and its result is shown (tests).
  void waitForRun();

  /// The report datasets (cmm_report, dmis) the page can build a model from.
  QStringList reportDatasets() const;
  /// The dialog for the report dataset `reportId` (the study's report when empty): "Create setup model
  /// from report…" when the study has no model, else "Add report features…" for the edited model. nullptr
  /// with the message in *error when the report cannot be read. Not shown: the caller exec()s it (or a
  /// test drives it) and passes it to applyReportDialog.
  ReportModelDialog* makeReportDialog(const QString& reportId, QString* error = nullptr);
  /// Applies an accepted dialog for `reportId` (see the header comment); false with the message in *error.
  bool applyReportDialog(const ReportModelDialog& dialog, const QString& reportId, QString* error = nullptr);
  /// makeReportDialog, exec, applyReportDialog, with message boxes for errors.
  void openReportDialog(const QString& reportId = {});
  QPushButton* fromReportButton() const { return fromReport_; }

  /// Writes the edited model to its dataset file (atomically); false with the message in *error.
  bool saveModel(QString* error = nullptr);
  /// Reloads the model and the report from the files (drops the edits and their undo history).
  void reload();
  /// Revert: reads the model file (and the report) again and goes back to it as one undo step of
  /// the graph editor, so undo brings the edits back. False with the message in *error (the edits
  /// stay) when the file cannot be read.
  bool revertModel(QString* error = nullptr);

 signals:
  /// A run finished (also cancelled ones) and its result is on the Results tab.
  void runFinished();

 private:
  void refresh();
  void onModelEdited();
  void flushTrace();
  void onRunFinished(const QString& error);
  void showOutcome(const SetupRunOutcome& outcome);
  /// Reads studies.setup's run settings (SetupSettings::fromJson / isValid): settingsError_ names
  /// the field of a refused one.
  void readSettings();
  /// The settings a stored result is compared with: the study's run settings (SetupSettings::toJson),
  /// a hash of the model the run used (edits included) and the effects applied on the diagnosis page.
  nlohmann::json storedSettingsJson() const;
  /// Keeps a finished run of the study's settings in the project (results.setup.<report>).
  void storeResult(const SetupRunOutcome& outcome);
  /// Without a run shown: the Results tab says what is stored (storedResultText).
  void showStoredResult();
  void updateInfo();
  /// d->measurements from the raw report and studies.diagnosis.setup.applied.
  void applyEffects();
  void updateControls();
  /// The instance of the edited model with the report's deviations; nullopt (and error_) if not possible.
  bool ensureExact();
  /// Reads the report against `model` (d->rawMeasurements, d->measurements; d->dataError on failure).
  void readReport(const setup::Model& model);
  /// The study's report's characteristics for the graph editor's "Report feature" column.
  void readReportFeatures();
  /// Autosave recovery: the edited model of the side file ({"dataset", "model"}) as one undo step.
  void restoreUnsavedModel(const nlohmann::json& unsaved);

  struct Impl;
  std::unique_ptr<Impl> d;
  ProjectDocument* document_;
  SetupModelEditor* editor_;
  QLabel* info_;
  QTabWidget* tabs_;
  SetupGraphEditor* graph_;
  QPushButton* saveModel_;
  QPushButton* revertModel_;
  QPushButton* fromReport_ = nullptr;
  QComboBox* method_;
  QSpinBox* budget_;
  QSpinBox* seed_;
  QPushButton* run_;
  QPushButton* cancel_;
  QPushButton* clearRuns_;
  QProgressBar* progress_;
  QLabel* runStatus_;
  SetupConvergenceView* convergence_;
  SetupResultsView* results_;
  SetupValidationView* validation_;
  QString error_;
  QString settingsError_;
};

}  // namespace metrofit
