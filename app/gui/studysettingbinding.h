#pragma once
// Binds a page's input widget to one value of a study, through the document's undo stack
// (ProjectDocument::setStudyValue): a user edit becomes an undoable command (typing in a spin box is
// one undo step, ended by editingFinished), and undo / redo / load put the widget back to the value
// the project holds. `effective` returns the value the page uses for the current project (the
// study's value, or the page's default when the study has none or an invalid one); the widget is
// only written to the project when it differs from that, so showing or reloading a project is
// never an edit.
#include <QString>
#include <QtGlobal>
#include <functional>

class QComboBox;
class QSpinBox;
class QDoubleSpinBox;

namespace metrofit {

class ProjectDocument;

/// A combo box whose items carry the value as their data (a string).
void bindStudySetting(ProjectDocument* document, QComboBox* combo, const QString& study, const QString& key,
                      std::function<QString()> effective, const QString& undoText);
/// A spin box holding an integer; `writeUnsigned` writes a JSON unsigned number (seeds).
void bindStudySetting(ProjectDocument* document, QSpinBox* spin, const QString& study, const QString& key,
                      std::function<qint64()> effective, bool writeUnsigned, const QString& undoText);

/// A dataset chooser: a combo box whose items carry a dataset id as their data, "" for none. Choosing
/// none removes the key (a study names no dataset rather than an empty one); `effective` gives the id
/// the study names ("" when none). The items may change with the project (the page fills them); the
/// binding only writes a choice that differs from the study's.
void bindStudyDatasetSetting(ProjectDocument* document, QComboBox* combo, const QString& study,
                             const QString& key, std::function<QString()> effective, const QString& undoText);

/// A double spin box holding a number (written as a JSON number). Typing merges into one undo step
/// until editingFinished; a value equal to `effective` at the box's decimals is not written.
void bindStudySetting(ProjectDocument* document, QDoubleSpinBox* spin, const QString& study,
                      const QString& key, std::function<double()> effective, const QString& undoText);

}  // namespace metrofit
