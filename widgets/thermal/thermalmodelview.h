#pragma once
// Model comparison view of a thermal log (Abdulshahed 2016, grey neural network thermal model, Fig. 10-14 and
// Table 4): settings (target, inputs, train fraction, seed), training of GNNMCI(1,N), GMC(1,N) and the MLP in
// a worker thread with live PSO progress (best fitness against iteration, a progress bar, Cancel), then
// measured against the three models over time with the fit / held-out boundary, the residuals, the Table 4
// metrics (R, RMSE, E, residual band on the fitted and the held-out rows) and, when the project has
// the three modular tests, the combined test predicted from the Z and C tests (Section 4.3).
// Applied effects in the settings (ThermalModelSettings::applied) are named under the inputs; each
// model is fitted with and without them and keeps the lower held-out error, and the line says which
// ("Applied effects lag:T2 (15.5 min): not used by GNNMCI(1,N), GMC(1,N), MLP (held-out error would
// rise: 0.39 → 0.46 µm, ...)"), or why they cannot be used. A model that could not be fitted on the
// log has one row "not fitted: <reason>" and a legend entry without a curve, and is never the best.
// The modular tab lists the modules (each identified on its own test) with "Identify again…" per
// module and "Save module models…"; the page runs them (app/gui/thermalpage.h). Qt Charts stays behind
// the pimpl.
#include <QWidget>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace metrofit {
struct ThermalLog;
struct ThermalModelSettings;
struct ThermalComparison;
struct ModularComparison;

class ThermalModelView : public QWidget {
  Q_OBJECT
 public:
  explicit ThermalModelView(QWidget* parent = nullptr);
  ~ThermalModelView() override;

  /// Shows a log with these settings; clears the results (cancels a running training).
  void setLog(const ThermalLog& log, const ThermalModelSettings& settings);
  /// The settings in the controls.
  ThermalModelSettings settings() const;
  /// Puts settings into the controls (no training).
  void setSettings(const ThermalModelSettings& settings);

  /// Starts training the three models in a worker thread (no effect while one runs).
  void train();
  /// Trains on the calling thread and shows the result; false (message shown) on bad settings.
  bool trainNow();
  /// Asks a running training to stop; trainingFinished(false) follows.
  void cancel();
  bool isRunning() const;
  /// The results shown, nullptr when none.
  const ThermalComparison* comparison() const;
  /// Status line under the progress bar (last error, timing, cancellation).
  QString statusText() const;
  /// Replaces the status line (the page's note on a stored result while nothing is trained).
  void setStatusText(const QString& text);
  /// PSO iterations received live during the last training.
  int liveIterations() const;

  /// The modular case (nullptr hides the group); `testLog` is the combined test's log.
  void setModular(std::shared_ptr<const ModularComparison> modular, const ThermalLog* testLog,
                  const QString& description);

  QProgressBar* progressBar() const;
  QPushButton* trainButton() const;
  QPushButton* cancelButton() const;
  QTableWidget* metricsTable() const;
  QTableWidget* modularTable() const;
  /// The modules line of the modular case (each module's inputs and contribution).
  QLabel* modularModulesLabel() const;

  /// The modules of the modular case, one row each: the module, the test it is identified on, its
  /// inputs, its contribution and an "Identify again…" button (identifyModuleRequested(row)).
  QTableWidget* modulesTable() const;
  /// "Save module models…": saveModulesRequested().
  QPushButton* saveModulesButton() const;
  /// Cancel of a module run: modulesCancelRequested().
  QPushButton* modulesCancelButton() const;
  QProgressBar* modulesProgressBar() const;
  /// A module run is going on (identifying a module again): the actions are disabled, Cancel and the
  /// progress bar shown.
  void setModulesRunning(bool running);
  void setModulesProgress(double fraction, const QString& text);
  /// The line under the modules (the last run's outcome, where the models were saved).
  void setModulesMessage(const QString& text);
  QString modulesMessage() const;

 signals:
  /// A training ended (train() or trainNow()): completed true, or false when cancelled or failed.
  void trainingFinished(bool completed);
  /// The user changed a setting in the controls.
  void settingsEdited();
  /// "Identify again…" of module `module` (a row of modulesTable()).
  void identifyModuleRequested(int module);
  /// "Save module models…".
  void saveModulesRequested();
  /// Cancel of the module run.
  void modulesCancelRequested();

 private:
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
