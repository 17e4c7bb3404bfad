#pragma once
// The results of a setup correction: a summary line (f1 before -> after, bonus, |x|, gap to the
// exact optimum), the corrections per setup datum (mm, 3 decimals, with the controller register),
// the per-dimension margins before / after inside the tolerance zones (setupmargins.h), the parts
// of the report in tolerance before / after (parts rescued) and the export buttons (Fanuc,
// Heidenhain, Siemens, CSV: core/setup/export.h, written atomically).
#include <QWidget>
#include <optional>

#include "core/setup/export.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/study/setup_study.h"

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

 private:
  void exportDialog(setup::ControllerFormat format);

  QLabel* summary_;
  QTableWidget* table_;
  SetupMarginsWidget* margins_;
  QLabel* parts_;
  QList<QPushButton*> exportButtons_;
  setup::Model model_;
  std::optional<SetupRunOutcome> result_;
};

}  // namespace metrofit
