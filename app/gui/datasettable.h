#pragma once
// A table of a project's datasets: id, kind, path (red when the file is missing) and licence, with
// the description as tooltip. With enableEditing, a double click shows a dataset's data and its
// context menu shows the data, renames, re-links and removes datasets (app/gui/datasetactions.h,
// through the document's undo stack).
#include <QTableWidget>
#include <vector>

namespace metrofit {
class ProjectDocument;
struct DatasetRef;

class DatasetTable : public QTableWidget {
  Q_OBJECT
 public:
  explicit DatasetTable(QWidget* parent = nullptr);

  /// Shows these datasets of the document (paths checked against the document's folder).
  void setDatasets(const ProjectDocument& document, const std::vector<DatasetRef>& datasets);
  /// Gives the table a context menu that shows and edits the document's datasets, and "Show data" on
  /// a double click.
  void enableEditing(ProjectDocument* document);
  /// The id of the dataset in a row ("" when there is none).
  QString datasetId(int row) const;
};

}  // namespace metrofit
