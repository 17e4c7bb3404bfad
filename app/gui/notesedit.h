#pragma once
// Editor of a study's notes (studies[<study>]["notes"]): every edit goes through the document's
// undo stack; consecutive typing is one undo step until the editor loses focus.
#include <QPlainTextEdit>

namespace metrofit {
class ProjectDocument;
struct ProjectField;

class NotesEdit : public QPlainTextEdit {
  Q_OBJECT
 public:
  NotesEdit(ProjectDocument* document, const QString& study, QWidget* parent = nullptr);

 protected:
  void focusOutEvent(QFocusEvent* event) override;

 private:
  void refresh();

  ProjectDocument* document_;
  QString study_;
  bool updating_ = false;
};

}  // namespace metrofit
