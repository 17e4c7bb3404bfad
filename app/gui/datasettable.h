#pragma once
// A read-only table of a project's datasets: id, kind, path (red when the file is missing) and
// licence, with the description as tooltip.
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
};

}  // namespace metrofit
