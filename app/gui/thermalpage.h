#pragma once
// The thermal study page: a combo of the project's thermal logs and the sensor trend chart of the
// chosen one (the first by default). A log that cannot be read shows its one-line error instead.
#include <QWidget>
#include <vector>

#include "core/project/project.h"

class QComboBox;
class QLabel;
class QStackedWidget;

namespace metrofit {
class ProjectDocument;
class ThermalTrendView;

class ThermalPage : public QWidget {
  Q_OBJECT
 public:
  explicit ThermalPage(ProjectDocument* document, QWidget* parent = nullptr);

  /// Shows the thermal log with this dataset id (no effect for an unknown id).
  void selectDataset(const QString& id);
  /// Id of the log shown; empty when the project has none.
  QString currentDataset() const;
  QComboBox* datasetCombo() const { return combo_; }
  ThermalTrendView* trendView() const { return trend_; }
  /// The error of the last read, empty when the log was read.
  QString errorMessage() const { return error_; }

 private:
  void refresh();
  void showLog(int comboIndex);

  ProjectDocument* document_;
  QComboBox* combo_;
  QLabel* info_;
  QStackedWidget* stack_;
  ThermalTrendView* trend_;
  QLabel* message_;
  QString error_;
  std::vector<DatasetRef> logs_;
  QString projectFile_;
};

}  // namespace metrofit
