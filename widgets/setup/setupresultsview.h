#pragma once
// The results of a setup correction: a summary line (f1 before -> after, bonus, |x|, gap to the
// exact optimum), the corrections per setup datum (mm, 3 decimals, with the controller register),
// the per-dimension margins before / after inside the tolerance zones (setupmargins.h), the parts
// of the report in tolerance before / after (parts rescued) and the export buttons (Fanuc,
// Heidenhain, Siemens, CSV: core/setup/export.h, written atomically), "Update HEIDENHAIN table…" (the
// control's current preset table *.PR or tool table *.T with the corrections added to its cells:
// updateHeidenhainTable, as `metrofit-cli setup --export heidenhain-table`; the rows are the model's
// registers, the tool register wear DL or geometry L as chosen next to the buttons), and "Export Q-DAS
// DFQ…" of the measured features (core/setup/measurements_dfq.h, as `setup --dfq`).
#include <QWidget>
#include <optional>

#include "core/setup/export.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/study/setup_study.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace metrofit {
class SetupMarginsWidget;

class SetupResultsView : public QWidget {
  Q_OBJECT
 public:
  explicit SetupResultsView(QWidget* parent = nullptr);

  /// Shows a run's result on `instance` (of `model`); `exact` gives the gap.
  void setResult(const setup::Model& model, const setup::SetupInstance& instance,
                 const SetupRunOutcome& outcome, const std::optional<setup::SetupScore>& exact,
                 const SetupPartsSummary& parts);
  /// No result: the message instead.
  void clear(const QString& message);
  bool hasResult() const { return result_.has_value(); }
  const std::optional<SetupRunOutcome>& result() const { return result_; }

  QTableWidget* correctionsTable() const { return table_; }
  SetupMarginsWidget* margins() const { return margins_; }
  QString summaryText() const;
  QString partsText() const;

  /// Writes the shown corrections in a controller format to `path` (atomically). False with a
  /// readable message in *error on failure (also when there is no result).
  bool exportTo(setup::ControllerFormat format, const QString& path, QString* error = nullptr) const;

  /// The tool register of the exports (combo next to the buttons; default wear).
  setup::ToolOffset toolOffset() const;
  void setToolOffset(setup::ToolOffset offset);
  /// Writes the HEIDENHAIN table `tablePath` (saved from the control: *.PR or *.T) with the shown
  /// corrections added to its cells to `outPath` (atomically; never onto `tablePath`). False with a
  /// readable message in *error (no result, the same file, or core's message); *update gets what was
  /// and was not written.
  bool updateHeidenhainTable(const QString& tablePath, const QString& outPath, QString* error = nullptr,
                             setup::TableUpdate* update = nullptr) const;

  /// The measured features for "Export Q-DAS DFQ…": the report read against `model` (the model file),
  /// `modelFile` names the part (K1001: its name without extension). nullptr: none (button disabled).
  void setMeasurements(const setup::Model& model, const setup::Measurements* measurements,
                       const QString& modelFile);
  bool hasMeasurements() const { return measurements_.has_value(); }
  /// Writes the measured features as a Q-DAS DFQ file (atomically), as `setup --dfq`. False with *error.
  bool exportDfq(const QString& path, QString* error = nullptr) const;

 private:
  /// The corrections table is never narrower than its columns need (header and cells, in any
  /// language), so the splitter cannot hide the correction column (gui-run F3).
  void fitTableWidth();
  void exportDialog(setup::ControllerFormat format);
  void tableDialog();
  void dfqDialog();

  QLabel* summary_;
  QTableWidget* table_;
  SetupMarginsWidget* margins_;
  QLabel* parts_;
  QList<QPushButton*> exportButtons_;
  QComboBox* toolOffset_;
  QPushButton* dfqButton_;
  setup::Model measModel_;
  std::optional<setup::Measurements> measurements_;
  QString modelFile_;
  setup::Model model_;
  std::optional<SetupRunOutcome> result_;
};

}  // namespace metrofit
