#pragma once
// The diagnosis study page (the closed loop): a domain selector (thermal, kinematic, setup,
// matching), the data and settings of the project's studies.diagnosis.<domain>
// (core/study/diagnosis_study.h), Run (Ctrl+R) in a worker thread with progress and Cancel,
// then the residual plot of each accepted effect, the candidate table (effect, parameters ±
// standard error, rmse before -> after, evidence, accepted; Ctrl+C copies) and the before / after
// error bars. A second tab, "Residual check" (widgets/diagnose/residualcheckview.h), shows what the
// final residual still depends on: the verdict, the structure, the outliers, every test and the
// residual against the variable of the strongest structure with the generic fit. Generic effects
// (`unexplained:<against>`) are listed with the named ones, their form in the parameters column.
// Apply (Ctrl+Shift+A) writes the accepted effects its study can include (canApplyEffect: the generic
// ones in thermal, kinematic and matching; the button's tooltip says which are left out and why) to
// studies.diagnosis.<domain>.applied as one undoable edit of the project document.
//
// The settings of each domain (studies.diagnosis.<domain>: core/study/study_settings.h
// DiagnosisDomainSettings owns the keys and defaults) are edited in the row below the title: the data,
// thermal's train fraction, kinematic's feed, setup's model, matching's tolerance, each bound through
// app/gui/studysettingbinding.h (undoable; undo moves the control back). A bad value in the project
// file (train_fraction = 2) is refused: the page names the field and nothing runs until it is
// corrected; no default is put in its place.
//
// A completed run is stored in the project (core/project/stored_results.h) under
// results.diagnosis.<dataset id>: the diagnose-result JSON (core/diagnose/diagnosis.h toJson) with the
// settings it ran with (the domain's block without "applied" and "notes", plus "domain"; setup also the
// model file's hash). A dataset serves one domain only (each domain reads its own dataset kind), so the
// dataset id alone is the key; "domain" in the settings makes a mismatch read as out of date. A reopened
// project shows it as "From the saved project (computed ...)" or as out of date.
#include <QWidget>
#include <memory>
#include <optional>

#include "core/diagnose/diagnosis.h"
#include "core/study/diagnosis_study.h"
#include "widgets/common/backgroundrun.h"

class QComboBox;
class QDoubleSpinBox;
class QMenu;
class QToolButton;
class QLabel;
class QProgressBar;
class QPushButton;
class QSplitter;
class QStackedWidget;
class QTabWidget;
class QTableWidget;

namespace metrofit {
class ErrorBarsView;
class ProjectDocument;
class ResidualCheckView;
class ResidualPlotView;

class DiagnosisPage : public QWidget {
  Q_OBJECT
 public:
  explicit DiagnosisPage(ProjectDocument* document, QWidget* parent = nullptr);
  ~DiagnosisPage() override;

  void setDomain(DiagnosisDomain domain);
  DiagnosisDomain domain() const;
  /// The text shown instead of the results when the settings or data are unusable ("" otherwise).
  QString message() const;
  QString statusText() const;
  /// The diagnosis' notes as shown (the declared model's fit; translated, one per line).
  QString notesText() const;
  const std::optional<diagnose::Diagnosis>& result() const { return result_; }
  bool isRunning() const;

  QTableWidget* candidateTable() const { return table_; }
  ResidualPlotView* residualPlot() const { return plot_; }
  ErrorBarsView* errorBars() const { return bars_; }
  QPushButton* applyButton() const { return applyButton_; }
  ResidualCheckView* residualCheckView() const { return check_; }
  /// The result tabs: 0 the effects (plots and candidate table), 1 the residual check.
  QTabWidget* resultTabs() const { return tabs_; }
  QPushButton* runButton() const { return runButton_; }
  /// The settings controls: the data of each domain (items carry the dataset id), thermal's train
  /// fraction, kinematic's feed (mm/min), setup's model (a setup_model dataset id), matching's
  /// tolerance (mm).
  QComboBox* datasetCombo(DiagnosisDomain domain) const;
  QDoubleSpinBox* trainFractionBox() const { return trainFraction_; }
  QDoubleSpinBox* feedBox() const { return feed_; }
  QComboBox* setupModelCombo() const { return setupModel_; }
  QDoubleSpinBox* toleranceBox() const { return tolerance_; }
  /// Thermal's target (the log's columns; items carry the name) and declared inputs (a menu of
  /// checkable actions, one per column, their data the name).
  QComboBox* thermalTargetCombo() const { return thermalTarget_; }
  QToolButton* thermalInputsButton() const { return thermalInputs_; }
  /// Chooses the thermal diagnosis data as the Data box does (one undo step): the dataset, and a target
  /// and inputs the log has (kept when the study's are columns of it, else the thermal study's when it
  /// is on the same log, else the defaults of core/study/thermal_comparison.h).
  void chooseThermalData(const QString& datasetId);
  /// Why the current domain's settings are refused ("" when they are usable or not configured).
  QString settingsError() const { return settingsError_; }

  /// Shows a result computed elsewhere as if the current settings had produced it (tests with a
  /// hand-built diagnosis); it is dropped like a computed one when the settings change.
  void setResult(diagnose::Diagnosis result);
  /// Runs the loop synchronously (tests, screenshots); false with message()/statusText() on error.
  bool runNow();
  /// Runs it in a worker thread (the Run button); finished() when done.
  void startRun();
  void cancelRun();
  /// Adds the accepted effects to the study (one undoable edit); false when there is nothing to add.
  bool applyAccepted();

  /// "diagnosis" (or a domain name): runs the first configured domain whose data load, in the order
  /// thermal, setup, matching, kinematic (or the named one), and shows its result; "residual" shows
  /// the residual check tab of the first of them whose result has a residual check.
  Q_INVOKABLE void showView(const QString& view);

 signals:
  void finished();

 private:
  void refresh();
  void showResult();
  void fillTable();
  void showPlot(int index);
  void setRunning(bool running);
  void copySelection();
  void showMessage(const QString& text);
  void updateApplyButton();
  void buildControls();
  void fillControls();
  /// Target and inputs of the thermal controls from the study and the chosen log's columns.
  void fillThermalColumns();
  /// Writes the checked inputs of the menu to the study (one undo step).
  void writeThermalInputs();
  /// The channel names of a thermal_log dataset (read once per file state; empty when unreadable).
  std::vector<std::string> thermalColumns(const std::string& datasetId);
  /// The settings a result is stored with (see the header comment); null when the settings are unusable.
  nlohmann::json storedSettings() const;
  void storeResult(const std::string& datasetId, const nlohmann::json& settings);
  /// The stored result of the current settings as the status line shows it ("" when none).
  QString storedResultText() const;

  ProjectDocument* document_;
  QComboBox* domainCombo_;
  QLabel* info_;
  QLabel* status_;
  QLabel* notes_;
  QPushButton* runButton_;
  QPushButton* cancelButton_;
  QPushButton* applyButton_;
  QProgressBar* progress_;
  QStackedWidget* stack_;
  QSplitter* content_;
  QLabel* message_;
  QComboBox* plotCombo_;
  ResidualPlotView* plot_;
  ErrorBarsView* bars_;
  QTableWidget* table_;
  QTabWidget* tabs_;
  ResidualCheckView* check_;
  QStackedWidget* controls_;
  QComboBox* datasetCombos_[4] = {};  ///< per domain, in the order of kDiagnosisDomains
  QDoubleSpinBox* trainFraction_;
  QDoubleSpinBox* feed_;
  QComboBox* setupModel_;
  QDoubleSpinBox* tolerance_;
  QComboBox* thermalTarget_;
  QToolButton* thermalInputs_;
  QMenu* thermalInputsMenu_;
  std::string columnsKey_;                 ///< the file state thermalColumns_ were read from
  std::vector<std::string> columnsCache_;  ///< its channel names
  QString settingsError_;
  nlohmann::json runSettings_;  ///< the stored settings of the run in the worker
  std::string runDatasetId_;

  std::optional<DiagnosisSettings> settings_;
  std::string settingsKey_;  ///< the settings the shown result was computed with
  quint64 generation_ = 0;   ///< the document's generation the page shows
  std::optional<diagnose::Diagnosis> result_;
  BackgroundRun<diagnose::Diagnosis>* run_;
};

}  // namespace metrofit
