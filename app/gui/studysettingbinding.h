#pragma once
// Binds a page's input widget to one value of a study, through the document's undo stack
// (ProjectDocument::setStudyValue): a user edit becomes an undoable command (typing in a spin box is
// one undo step, ended by editingFinished), and undo / redo / load put the widget back to the value
// the project holds. `effective` returns the value the page uses for the current project (the
// study's value, or the default when the study has none); the widget is only written to the project
// when it differs from that, so showing or reloading a project is never an edit. A value the study
// refuses (the page names the field and runs nothing) is never shown as a default: the widget stays
// as it is, and an edit of it writes its value (which corrects the study).
#include <QString>
#include <QtGlobal>
#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace metrofit {

class ProjectDocument;

/// A combo box whose items carry the value as their data (a string).
void bindStudySetting(ProjectDocument* document, QComboBox* combo, const QString& study, const QString& key,
                      std::function<QString()> effective, const QString& undoText);
/// A spin box holding an integer; `writeUnsigned` writes a JSON unsigned number (seeds). An `effective`
/// value outside the spin box's range (a refused or missing value) leaves the spin box as it is, and
/// any edit writes its value.
void bindStudySetting(ProjectDocument* document, QSpinBox* spin, const QString& study, const QString& key,
                      std::function<qint64()> effective, bool writeUnsigned, const QString& undoText);

/// A dataset chooser: a combo box whose items carry a dataset id as their data, "" for none. Choosing
/// none removes the key (a study names no dataset rather than an empty one); `effective` gives the id
/// the study names ("" when none). The items may change with the project (the page fills them); the
/// binding only writes a choice that differs from the study's.
void bindStudyDatasetSetting(ProjectDocument* document, QComboBox* combo, const QString& study,
                             const QString& key, std::function<QString()> effective, const QString& undoText);

/// A spin box holding a decimal number (written as a JSON number). `effective` returns nullopt for a
/// refused value; values equal to the spin box's decimals count as equal. Typing merges into one
/// undo step until editingFinished.
void bindStudySetting(ProjectDocument* document, QDoubleSpinBox* spin, const QString& study,
                      const QString& key, std::function<std::optional<double>()> effective,
                      const QString& undoText);
/// A check box (written as true / false). `effective` returns nullopt for a refused value.
void bindStudySetting(ProjectDocument* document, QCheckBox* box, const QString& study, const QString& key,
                      std::function<std::optional<bool>()> effective, const QString& undoText);
/// A line edit holding a text (written as a JSON string; an empty text removes the key when
/// `emptyRemoves`). Typing merges into one undo step until editingFinished. `effective` returns
/// nullopt for a refused value.
void bindStudySetting(ProjectDocument* document, QLineEdit* edit, const QString& study, const QString& key,
                      std::function<std::optional<QString>()> effective, bool emptyRemoves,
                      const QString& undoText);

}  // namespace metrofit
