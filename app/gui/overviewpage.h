#pragma once
// The project overview: name and description (edited through the document's undo stack), the
// project file and the table of datasets.
#include <QWidget>
#include <vector>

#include "core/project/project.h"

class QFrame;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace metrofit {
class DatasetTable;
class ProjectDocument;

class OverviewPage : public QWidget {
  Q_OBJECT
 public:
  explicit OverviewPage(ProjectDocument* document, QWidget* parent = nullptr);

  QLineEdit* nameEdit() const { return name_; }
  QPlainTextEdit* descriptionEdit() const { return description_; }
  DatasetTable* datasetTable() const { return datasets_; }
  /// The first-run hint ("New here? Open the demo project…"): shown until dismissed or used
  /// (remembered in QSettings under kFirstRunHintKey), and only while no project file is open.
  QFrame* firstRunHint() const { return hint_; }
  /// The marked message listing the study settings no method can use (core/study/study_check.h);
  /// hidden when every setting is valid.
  QLabel* settingProblems() const { return problems_; }
  static constexpr const char* kFirstRunHintKey = "ui/firstRunHintDismissed";

 signals:
  /// The hint's "Open the demo project" button was pressed.
  void openDemoRequested();
  /// The "Import data…" button above the datasets was pressed.
  void importRequested();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void refresh();
  void dismissHint();

  ProjectDocument* document_;
  QLineEdit* name_;
  QPlainTextEdit* description_;
  QLabel* file_;
  DatasetTable* datasets_;
  QFrame* hint_;
  QLabel* problems_;
  bool updating_ = false;
  std::vector<DatasetRef> shownDatasets_;  ///< what the table shows (rebuilt only when it changes)
  QString shownFile_;
};

}  // namespace metrofit
