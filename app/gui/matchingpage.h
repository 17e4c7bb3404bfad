#pragma once
// The posture-matching study page: a combo of the project's probe point sets, the 3D point view of
// the chosen one (the first by default) and a table of the points with their deviation before
// matching (measured against nominal, along the normal where the set has normals).
#include <QWidget>
#include <vector>

#include "core/project/project.h"

class QComboBox;
class QLabel;
class QSplitter;
class QStackedWidget;
class QTableWidget;

namespace metrofit {
class PointSetView;
class ProjectDocument;

class MatchingPage : public QWidget {
  Q_OBJECT
 public:
  explicit MatchingPage(ProjectDocument* document, QWidget* parent = nullptr);

  /// Shows the probe point set with this dataset id (no effect for an unknown id).
  void selectDataset(const QString& id);
  QString currentDataset() const;
  PointSetView* pointView() const { return view_; }
  QTableWidget* pointTable() const { return table_; }
  QString errorMessage() const { return error_; }

 private:
  void refresh();
  void showPoints(int comboIndex);

  ProjectDocument* document_;
  QComboBox* combo_;
  QLabel* info_;
  QStackedWidget* stack_;
  QSplitter* content_;
  PointSetView* view_;
  QTableWidget* table_;
  QLabel* message_;
  QString error_;
  std::vector<DatasetRef> sets_;
  QString projectFile_;
};

}  // namespace metrofit
