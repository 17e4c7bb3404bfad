#pragma once
// The paper's statistical validation in the GUI (core/study/setup_validation.h, Fig. 18): N simulated
// measurement sets (Eq. 12-13, weights w1 and w2) x M trials per chosen method, run in a worker
// thread with a progress bar and Cancel, then the sorted-results chart and a summary
// (core/study/setup_validation.h summarizeValidation): the range of f1 before correction and the paper's
// range checked against the simulator, per method the mean gap to the exact optimum and the trials
// within one grid step of it, and the estimated share of the setup data in the dimension error.
// Defaults: the paper's 100 sets x 10 trials of CRIPSO at 5000 solutions, w1 = 0.03, w2 = 0.02 mm.
#include <QWidget>
#include <memory>

#include "core/setup/model.h"
#include "core/setup/report.h"

class QProgressBar;
class QPushButton;

namespace metrofit {
namespace setup {
struct ValidationResult;
}

class SetupValidationView : public QWidget {
  Q_OBJECT
 public:
  explicit SetupValidationView(QWidget* parent = nullptr);
  ~SetupValidationView() override;

  /// The model the validation simulates (a new model clears the result).
  void setModel(const setup::Model& model);
  /// The project's measurements, read against `measModel`: the summary adds the setup share
  /// estimated in them (validation.h partDeviationSets, estimateSetupShare) while the view's model
  /// has the same dimensions. nullptr clears them.
  void setMeasurements(const setup::Model& measModel, const setup::Measurements* measurements);
  void setSets(int sets);
  void setTrials(int trials);
  void setBudget(long budget);
  int sets() const;
  int trials() const;

  /// Starts the validation in the worker thread (false when one runs or there is no valid model).
  bool start();
  void cancel();
  bool isRunning() const;
  /// Blocks until the running validation has finished and its result is shown (tests).
  void waitForFinished();
  /// Drops the result shown: no result, an empty chart and the introductory text (another project).
  /// A running validation is cancelled first.
  void clearResult();
  /// The last result (nullptr before the first one).
  const setup::ValidationResult* result() const;
  QString summaryText() const;
  QProgressBar* progressBar() const;

 signals:
  void finished();

 private:
  struct Impl;
  std::unique_ptr<Impl> d;
  /// The run ended; error is empty for a finished or cancelled run.
  void onFinished(const QString& error);
};

}  // namespace metrofit
