#pragma once
// "Create setup model from report…" / "Add report features to setup model…": the characteristics a CMM
// report measures (core/project/report_model.h: feature, characteristic, nominal, tolerance) in a table
// with check boxes; the checked ones become dimensions of a new model, or are added to an existing one
// (those it reads already are shown as such and cannot be checked again). Options: the new model's name
// and axis, the setup datum the new features hang from, and the ± tolerance of values the report prints
// none for. The dialog only builds the model value (resultModel); the Setup page applies it as one undo
// step. Tests drive it through its API without exec().
#include <QDialog>
#include <optional>
#include <vector>

#include "core/project/report_model.h"
#include "core/setup/model.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace metrofit {

class ReportModelDialog : public QDialog {
  Q_OBJECT
 public:
  /// `existing`: the model to extend (nullptr: a new model is created). `reportId` names the dataset.
  ReportModelDialog(const ReportFeatures& report, const QString& reportId, const setup::Model* existing,
                    QWidget* parent = nullptr);

  bool creates() const { return creates_; }
  QTableWidget* table() const { return table_; }
  /// Row k is characteristic k of the report.
  bool isChecked(int row) const;
  /// False when the row cannot be checked (unusable, or read by the model already).
  bool setChecked(int row, bool checked);
  void checkAll(bool checked);
  std::vector<std::size_t> checkedRows() const;
  void setModelName(const QString& name);
  void setAxis(const QString& axis);
  /// The setup datum the new features hang from ("" = none).
  void setConnectTo(const QString& datum);
  void setDefaultTolerance(double mm);

  /// The model with the checked characteristics (addReportCharacteristics); nullopt with the message in
  /// *error when nothing is checked or a checked one cannot be added.
  std::optional<setup::Model> resultModel(QString* error = nullptr) const;

  void accept() override;

 private:
  void updateSummary();

  ReportFeatures report_;
  setup::Model base_;
  bool creates_;
  QTableWidget* table_;
  QLineEdit* name_ = nullptr;
  QComboBox* axis_ = nullptr;
  QComboBox* connect_;
  QDoubleSpinBox* tolerance_;
  QLabel* summary_;
};

}  // namespace metrofit
