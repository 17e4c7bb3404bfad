#pragma once
// The page of a study whose views are not part of this build yet: it states what the study does,
// lists the project's datasets it will work on and keeps the study's notes. It shows no results.
#include <QWidget>
#include <vector>

#include "core/project/project.h"

class QLabel;

namespace metrofit {
class DatasetTable;
class ProjectDocument;

class StudyPage : public QWidget {
  Q_OBJECT
 public:
  StudyPage(ProjectDocument* document, const QString& study, QWidget* parent = nullptr);

  QString study() const { return study_; }
  /// The datasets of the project this study works on (by kind).
  std::vector<DatasetRef> studyDatasets() const;

 private:
  void refresh();

  ProjectDocument* document_;
  QString study_;
  QLabel* noData_;
  DatasetTable* datasets_;
  QWidget* filler_;
  std::vector<DatasetRef> shown_;
};

}  // namespace metrofit
