#pragma once
// "Show data": one dataset of a project as a table with a plot below it (issue 28, item 2).
//   * the table (DatasetTableModel through a QSortFilterProxyModel): a CMM report as a feature table
//     with the rows out of tolerance marked, any other dataset with its columns and their units;
//     a click on a header sorts (numbers as numbers), the filter line keeps the rows with a cell
//     that contains its text (any column, case-insensitive), Ctrl+C copies the selection
//     tab-separated with the header (widgets/common/tablecopy.h);
//   * the plot (Qt Charts, in the .cpp only): the chosen numeric column against the row number, the
//     time column (the default when there is one) or another numeric column, all rows in file order (not the
//     filtered / sorted view), cells that are no number left out;
//   * a file that cannot be read: one line naming the file and what is wrong, instead of the table.
// Testable without a main window: app/gui opens it in a window of its own (datasetactions.h).
#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "core/project/project.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPointF;
class QSortFilterProxyModel;
class QSplitter;
class QTableView;

namespace metrofit {
struct DatasetContent;
class DatasetTableModel;

class DatasetView : public QWidget {
  Q_OBJECT
 public:
  explicit DatasetView(QWidget* parent = nullptr);
  ~DatasetView() override;

  /// Reads `file` as `dataset` says (its kind, dialect and mapping) and shows it; an error line when
  /// it cannot be read. Returns false on an error.
  /// `reference`: probe points whose nominals are a second measurement's points (core/project/nominals.h),
  /// that dataset with its path resolved.
  bool showDataset(const QString& file, const DatasetRef& dataset,
                   const std::optional<DatasetRef>& reference = std::nullopt);
  /// The same, read off the GUI thread (BackgroundRun, widgets/common/backgroundrun.h): the summary line
  /// says "Reading <file>…" until the content (or the error line) is shown and datasetShown() is
  /// emitted. A call while a read is going on is done after it (the last one wins).
  void showDatasetInBackground(const QString& file, const DatasetRef& dataset,
                               const std::optional<DatasetRef>& reference = std::nullopt);
  /// True while a background read is going on.
  bool isReading() const;
  /// Shows content already read.
  void setContent(std::shared_ptr<const DatasetContent> content);
  /// Shows the one-line error "Cannot show <file>: <message>" instead of the table.
  void showError(const QString& file, const QString& message);

  /// The error line's text; empty when the table is shown.
  QString errorText() const;
  /// The summary line above the table ("OGP step report, 160 rows, 3 out of tolerance").
  QString summaryText() const;

  QTableView* table() const { return table_; }
  DatasetTableModel* model() const { return model_; }
  QSortFilterProxyModel* proxy() const { return proxy_; }
  QLineEdit* filterEdit() const { return filter_; }
  QComboBox* plotColumnBox() const { return plotColumn_; }
  QComboBox* plotAxisBox() const { return plotAxis_; }
  /// The chart view (a QChartView) below the table.
  QWidget* chartView() const { return chartView_; }

  /// Plots a model column (-1: none) against `xColumn` (-1: the row number).
  void setPlot(int column, int xColumn = -1);
  /// The points of the plotted series (x, y), in file order.
  std::vector<QPointF> plottedPoints() const;

 signals:
  /// A background read ended: the content is shown (true) or the error line (false).
  void datasetShown(bool ok);

 private:
  void updatePlot();
  void updateSummary();
  void readingEnded(bool ok, const QString& message);

  DatasetTableModel* model_;
  QSortFilterProxyModel* proxy_;
  QLabel* summary_;
  QLabel* error_;
  QLineEdit* filter_;
  QComboBox* plotColumn_;
  QComboBox* plotAxis_;
  QSplitter* splitter_;
  QTableView* table_;
  QWidget* chartView_;
  struct Chart;
  std::unique_ptr<Chart> chart_;
  struct Reading;
  std::unique_ptr<Reading> reading_;
};

}  // namespace metrofit
