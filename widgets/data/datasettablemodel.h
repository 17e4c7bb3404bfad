#pragma once
// The table model over a dataset's content (core/project/dataset_content.h), for the "Show data"
// view (widgets/data/datasetview.h). The cells are read from the core data when they are drawn
// (nothing is copied into items: a thermal log can have 100 000 rows); the numbers of each column are
// parsed once, when the content is set, for sorting and plotting.
//   * Columns (a log, a series, a point set): one column per column of the table, headed by its name
//     as the readers see it (a mapped column by its role) and its unit in brackets ("disp_z_um [µm]");
//     the tooltip names the file's own column. The vertical header is the data row (1-based).
//   * Features (a CMM report): [Part,] Feature, Characteristic, [Unit,] Nominal, Actual, Deviation,
//     Lower tol., Upper tol., Status; when every row has the same unit it goes into the headers
//     ("Nominal [mm]") instead of a Unit column. A row out of tolerance has a light red background,
//     the status text "out of tolerance" and a warning icon (not the colour alone).
// Numbers are shown in the default QLocale (the UI language: decimal comma in German and Polish),
// without group separators, with the shortest digits that read back to the value. SortRole gives
// numbers as doubles (cells that are no number sort last) and text otherwise.
#include <QAbstractTableModel>
#include <QStringList>
#include <memory>
#include <vector>

namespace metrofit {
struct DatasetContent;

class DatasetTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Roles { SortRole = Qt::UserRole + 1, OutOfToleranceRole };

  explicit DatasetTableModel(QObject* parent = nullptr);
  ~DatasetTableModel() override;

  /// Shows `content` (nullptr: an empty table).
  void setContent(std::shared_ptr<const DatasetContent> content);
  const DatasetContent* content() const { return content_.get(); }
  bool isFeatureTable() const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

  /// The column's name without the unit, and its unit ("" when none or when it varies by row).
  QString columnName(int column) const;
  QString columnUnit(int column) const;
  /// True when most non-empty cells of the column are numbers (the columns a plot can show).
  bool isNumeric(int column) const;
  /// The cell as a number; NaN when it is none.
  double number(int row, int column) const;
  /// The first time column (role time_s / time_min / time_h, or a column in s / min / h), or -1.
  int timeColumn() const;
  /// Whether a row of a feature table is out of tolerance (false for other tables).
  bool outOfTolerance(int row) const;
  /// Whether a cell of the row contains `text` (case-insensitive): the text shown for a feature
  /// table; the file's own text for other tables (fast on 100 000 rows), a number also with the
  /// other decimal mark, so "20,75" typed in a German UI finds "20.75" in the file.
  bool rowContains(int row, const QString& text) const;

 private:
  enum class Field { Part, Feature, Characteristic, Unit, Nominal, Actual, Deviation, Lower, Upper, Status };
  QString featureText(int row, Field field) const;
  QString numberText(double value) const;

  std::shared_ptr<const DatasetContent> content_;
  std::vector<Field> fields_;                 ///< Features: the columns shown
  QString commonUnit_;                        ///< Features: the unit of every row, else ""
  std::vector<std::vector<double>> numbers_;  ///< per column, per row (NaN: no number)
  std::vector<bool> numeric_;
};

}  // namespace metrofit
