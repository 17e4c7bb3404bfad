#pragma once
// The thermal study page: a combo of the project's thermal logs and three tabs for the chosen one
// (the first by default):
//  * Trend: the sensor trend chart (widgets/thermal/thermaltrendview.h);
//  * Hysteresis: displacement against each sensor over heating and cooling, loop areas and lags;
//  * Models: GNNMCI(1,N), GMC(1,N) and the MLP fitted on the first part and compared on the rest
//    (Table 4), trained in a worker thread with live PSO progress; when the project has the three
//    modular tests (datasets kModularZId, kModularCId, kModularCombinedId of thermal_comparison.h), the
//    combined test predicted from models fitted on the Z and C tests (Section 4.3), and the same case
//    module by module: each module identified on its own test; "Identify again…" re-fits one module on
//    another test of its drive (a thermal log of the project) while the others keep their models,
//    stored as studies.thermal.modules.<module>.dataset (undoable); "Save module models…" writes the
//    modules' models as `thermal modular --save-modules` does.
// A log that cannot be read shows its one-line error instead. The model settings start from the
// project's thermal study (studies.thermal: dataset, target, inputs) and are kept per log for the
// session; they do not edit the project, so they are not on the undo stack. Effects applied on the
// diagnosis page (studies.diagnosis.thermal.applied) are part of the model of the log the diagnosis
// ran on (core/diagnose/thermal_applied.h): for that log the Models tab fits with them and says so,
// other logs say where they apply; Apply and its undo change the settings (Train again to update).
#include <QHash>
#include <QWidget>
#include <functional>
#include <memory>
#include <vector>

#include "core/project/project.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_log.h"
#include "widgets/common/backgroundrun.h"

class QComboBox;
class QLabel;
class QStackedWidget;
class QTabWidget;

namespace metrofit {
class ProjectDocument;
class ThermalTrendView;
class ThermalHysteresisView;
class ThermalModelView;

class ThermalPage : public QWidget {
  Q_OBJECT
 public:
  explicit ThermalPage(ProjectDocument* document, QWidget* parent = nullptr);
  ~ThermalPage() override;

  /// Shows the thermal log with this dataset id (no effect for an unknown id).
  void selectDataset(const QString& id);
  /// Id of the log shown; empty when the project has none.
  QString currentDataset() const;
  QComboBox* datasetCombo() const { return combo_; }
  QTabWidget* tabs() const { return tabs_; }
  ThermalTrendView* trendView() const { return trend_; }
  ThermalHysteresisView* hysteresisView() const { return hysteresis_; }
  ThermalModelView* modelView() const { return models_; }
  /// The error of the last read, empty when the log was read.
  QString errorMessage() const { return error_; }
  /// What the project stores of the log shown (results.thermal.<log>, core/project/stored_results.h)
  /// for the page, or "" when nothing is stored: the stored figures marked "From the saved project,
  /// computed <when>" when the settings and the data are those they came from, else "out of date"
  /// with why. Shown in the Models tab's status line until the models are trained.
  QString storedResultText() const;

  /// Switches to "trend", "hysteresis" or "models" with results on it: the hysteresis analysis and,
  /// for "models", the three models (trained synchronously with the settings shown when none are)
  /// and the modular case when the project has it.
  Q_INVOKABLE void showView(const QString& view);

  /// The modular case shown (nullptr when there is none yet).
  const ModularComparison* modularComparison() const { return modularResult_.get(); }
  /// The run of the modular case and of its module runs (progress, cancel).
  BackgroundRunBase* modularRun() const { return modular_; }
  /// Identifies module `module` (a row of the Modular tab's modules table) again on the project's
  /// thermal log `datasetId` (a new test of its drive) on the modular run (synchronously when `now`):
  /// the other modules keep their fitted models as they are, the combined test is predicted again and,
  /// when that worked, studies.thermal.modules.<module>.dataset = datasetId is written (one undoable
  /// step; undo identifies the module on its previous test again). False when it cannot start (no
  /// modular case, a run going on, an unknown module or dataset).
  bool identifyModuleAgain(int module, const QString& datasetId, bool now = false);
  /// Writes each module's fitted model to `folder` as NAME.json (the files of `metrofit-cli thermal
  /// modular --save-modules`, thermal::saveThermalModules); false with the message shown on an error.
  bool saveModuleModels(const QString& folder);

 private:
  void refresh();
  void showLog(int comboIndex);
  /// Shows why the study's settings were refused (the field named) instead of the log.
  void showSettingsError(const QString& message);
  /// The field the model view cannot show as the study holds it (a train fraction it would round or
  /// clamp, a seed beyond its range), named with why; empty when the view shows `s` exactly.
  QString unshownSetting(const ThermalModelSettings& s) const;
  /// The log shown (logs_, paths resolved), or nullptr.
  const DatasetRef* currentLogRef() const;
  /// Keeps the trained comparison in the project (results.thermal.<log>) with its settings and the
  /// data's hash; the next save writes it.
  void storeResult();
  /// The stored result's text in the Models tab while it shows no trained models.
  void showStoredResult();
  void onTabChanged(int index);
  /// Starts the hysteresis analysis of the log and settings shown on a worker (the view shows it
  /// when ready); nothing when the view already has them.
  void updateHysteresis();
  /// Starts the modular case in a worker (or runs it now when `now`); no effect without the datasets.
  void updateModular(bool now);
  /// Writes the view's model settings to studies.thermal through the shared binding (writeSettings_):
  /// the settings of the study's dataset (and the dataset, when the study names none yet) in one undo
  /// step; nothing for another log.
  void writeStudySettings();
  /// Puts studies.thermal's settings into the controls after undo / redo (signals blocked).
  void syncSettingsFromStudy();
  /// The log's description plus, when effects applied on the diagnosis page belong to another log,
  /// a line that says so.
  void updateInfo();

  ProjectDocument* document_;
  QComboBox* combo_;
  QLabel* info_;
  QStackedWidget* stack_;
  QTabWidget* tabs_;
  ThermalTrendView* trend_;
  ThermalHysteresisView* hysteresis_;
  ThermalModelView* models_;
  QLabel* message_;
  QString error_;
  std::vector<DatasetRef> logs_;
  QString projectFile_;
  quint64 generation_ = 0;  ///< the document's generation the page shows (ProjectDocument::generation)
  ThermalLog log_;
  QString logId_;
  QString infoBase_;       ///< the log's description (info_ without the applied-effects line)
  QString hysteresisKey_;  ///< what the hysteresis view shows (dataset, target, inputs)
  QHash<QString, ThermalModelSettings> settings_;  ///< per dataset id, this session
  bool settingsInvalid_ = false;         ///< the study's settings were refused (message_ names the field)
  bool writingStudy_ = false;            ///< the page's own edit of the document
  std::function<void()> writeSettings_;  ///< bindStudySettings' write (app/gui/studysettingbinding.h)

  struct ModularRun {
    std::shared_ptr<ModularComparison> result;
    QString error;
    std::shared_ptr<ThermalLog> testLog;
    QString moduleError;     ///< the study's module tests could not be used (the modules as first fitted)
    bool moduleRun = false;  ///< a run of the modules only (identify again, undo / redo of one)
    QString storeModule, storeDataset;  ///< written to studies.thermal.modules when the run worked
  };
  BackgroundRun<ModularRun>* modular_;
  QString modularKey_;  ///< project file the modular result belongs to
  bool modularDone_ = false;
  bool moduleRunActive_ = false;  ///< the modular run is a run of the modules only
  std::shared_ptr<const ModularComparison> modularResult_;
  std::shared_ptr<ThermalLog> modularTestLog_;
  void applyModular(const ModularRun& run);
  /// The modules identified again on the tests `thermalStudy` names for them (a module run); on success
  /// `storeModule`'s test `storeDataset` is written to the study.
  bool startModulesRun(const nlohmann::json& thermalStudy, const QString& storeModule,
                       const QString& storeDataset, bool now);
  /// After undo / redo of a module's test: the modules shown follow studies.thermal.modules.
  void syncModulesFromStudy();
  /// "Identify again…" of a module: asks for the test (a thermal log of the project).
  void askIdentifyModuleAgain(int module);
  /// "Save module models…": asks for the folder.
  void askSaveModuleModels();
  /// The modular tab's description of the comparison.
  QString modularDescription(const ModularComparison& m) const;
};

}  // namespace metrofit
