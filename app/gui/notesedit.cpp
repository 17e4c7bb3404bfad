#include "app/gui/notesedit.h"

#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

NotesEdit::NotesEdit(ProjectDocument* document, const QString& study, QWidget* parent)
    : QPlainTextEdit(parent), document_(document), study_(study) {
  setPlaceholderText(tr("Notes on the %1 study (saved with the project)").arg(studyTitle(study)));
  setTabChangesFocus(true);
  // A strip below the study's views on every page (one height for all pages).
  setMaximumHeight(56);
  connect(this, &QPlainTextEdit::textChanged, this, [this] {
    if (!updating_) document_->setValue(ProjectField::studyNotes(study_), toPlainText());
  });
  connect(document_, &ProjectDocument::changed, this, &NotesEdit::refresh);
  refresh();
}

void NotesEdit::focusOutEvent(QFocusEvent* event) {
  document_->endEditSequence();
  QPlainTextEdit::focusOutEvent(event);
}

void NotesEdit::refresh() {
  const QString notes = document_->value(ProjectField::studyNotes(study_));
  if (notes == toPlainText()) return;
  updating_ = true;
  setPlainText(notes);
  updating_ = false;
}

}  // namespace metrofit
