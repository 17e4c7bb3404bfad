#pragma once
// The project navigator: the project as root, its studies below it and each study's datasets as
// children. Selecting an item asks for its page (and dataset); a double click on a dataset item shows
// its data, its context menu shows the data, renames, re-links and removes the dataset
// (app/gui/datasetactions.h).
#include <QTreeWidget>
#include <vector>

#include "app/gui/pageid.h"
#include "core/project/project.h"

namespace metrofit {
class ProjectDocument;

class ProjectNavigator : public QTreeWidget {
  Q_OBJECT
 public:
  enum Role { PageRole = Qt::UserRole + 1, DatasetRole };

  explicit ProjectNavigator(ProjectDocument* document, QWidget* parent = nullptr);

  /// The item of a page (the root for the overview).
  QTreeWidgetItem* itemForPage(Page page) const;
  /// Selects a page's item without emitting pageActivated.
  void selectPage(Page page);

 signals:
  /// An item was selected: its page and, for a dataset item, the dataset id (else empty).
  void pageActivated(metrofit::Page page, const QString& datasetId);
  /// "Create setup model from report…" / "Add report features to setup model…" was chosen in the
  /// context menu of the CMM report (or DMIS) dataset `datasetId`.
  void setupModelFromReportRequested(const QString& datasetId);

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void refresh();
  void rebuild();
  /// The column is the viewport's width, or wider when a word (a dataset id) needs more; rows are
  /// laid out again so that wrapped names get their height.
  void fitColumn();

  ProjectDocument* document_;
  QTreeWidgetItem* root_ = nullptr;
  std::vector<DatasetRef> shown_;
};

}  // namespace metrofit
