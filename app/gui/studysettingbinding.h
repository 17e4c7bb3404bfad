#pragma once
// Binds a page's input widget to one value of a study, through the document's undo stack
// (ProjectDocument::setStudyValue): a user edit becomes an undoable command (typing in a spin box is
// one undo step, ended by editingFinished), and undo / redo / load put the widget back to the value
// the project holds. `effective` returns the value the page uses for the current project (the
// study's value, or the default when the study has none); the widget is only written to the project
// when it differs from that, so showing or reloading a project is never an edit. A value the study
// refuses (the page names the field and runs nothing) is never shown as a default: the widget stays
// as it is, and an edit of it writes its value (which corrects the study).
#include <QList>
#include <QString>
#include <QStringList>
#include <QtGlobal>
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QObject;
class QSpinBox;
class QVariant;

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

/// A combo box whose items carry data that the study spells as a text through `text` (an enum as an
/// int, written as its name). `effective` returns the study's text ("" when refused: the combo stays
/// as it is and any choice writes its value).
void bindStudySetting(ProjectDocument* document, QComboBox* combo, const QString& study, const QString& key,
                      std::function<QString()> effective, const QString& undoText,
                      std::function<QString(const QVariant&)> text);

/// Check boxes that together give one value (matching's locks "rz,z"): `value` is the JSON the boxes
/// give (null removes the key), `effective` the states the study's value gives the boxes, in their
/// order (nullopt for a refused value: the boxes stay, and a click writes their value). A click is one
/// undo step.
void bindStudySetting(ProjectDocument* document, const QList<QCheckBox*>& boxes, const QString& study,
                      const QString& key, std::function<nlohmann::json()> value,
                      std::function<std::optional<QList<bool>>()> effective, const QString& undoText);

/// One value of a study written together with others (bindStudySettings).
struct StudyEdit {
  QString key;
  nlohmann::json value;  ///< null removes the key
  QString undoText;
};

/// A view whose own controls edit several keys of a study at once (ThermalModelView: target, inputs,
/// train fraction, seed) and that puts the study's values back itself. Returns the write, to call when
/// the view says it was edited: `edits` gives the view's values key by key and any extra edit the
/// values need in the same undo step (declaring the study's dataset); nullopt writes nothing. The
/// edits whose value differs from the study's are written as one undo step (a macro named `macroText`
/// when more than one); a single edit of one of `typingKeys` merges with the previous one (typing in
/// a spin box) until endEditSequence. On every document change that the write did not make (undo,
/// redo, load, another page) `show` puts the study's values into the view; an empty `show`: the page
/// does that in its own reaction to the change (ThermalPage::refresh, which also re-reads the log when
/// the datasets change).
std::function<void()> bindStudySettings(ProjectDocument* document, QObject* view, const QString& study,
                                        std::function<std::optional<std::vector<StudyEdit>>()> edits,
                                        const QStringList& typingKeys, std::function<void()> show,
                                        const QString& macroText);

}  // namespace metrofit
