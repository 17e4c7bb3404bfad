#include "app/gui/studysettingbinding.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QUndoStack>
#include <QVariant>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "widgets/document/projectdocument.h"

namespace metrofit {

void bindStudySetting(ProjectDocument* document, QComboBox* combo, const QString& study, const QString& key,
                      std::function<QString()> effective, const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(combo, &QComboBox::currentIndexChanged, combo,
                   [document, combo, study, key, effective, undoText, syncing] {
                     if (*syncing || combo->currentIndex() < 0) return;
                     const QString value = combo->currentData().toString();
                     if (value == effective()) return;
                     document->endEditSequence();
                     document->setStudyValue(study, key, value.toStdString(), undoText);
                     document->endEditSequence();
                   });
  QObject::connect(document, &ProjectDocument::changed, combo, [combo, effective, syncing] {
    const int index = combo->findData(effective());
    if (index < 0 || index == combo->currentIndex()) return;
    *syncing = true;
    combo->setCurrentIndex(index);  // the page's own reactions to the change still run
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, QSpinBox* spin, const QString& study, const QString& key,
                      std::function<qint64()> effective, bool writeUnsigned, const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(spin, &QSpinBox::valueChanged, spin,
                   [document, study, key, effective, writeUnsigned, undoText, syncing](int value) {
                     // A value the spin box cannot show (refused by the page, never clamped) is
                     // replaced by any edit.
                     if (*syncing || value == effective()) return;
                     // Typing merges into one undo step until editingFinished.
                     const nlohmann::json json = writeUnsigned && value >= 0
                                                     ? nlohmann::json(static_cast<std::uint64_t>(value))
                                                     : nlohmann::json(static_cast<std::int64_t>(value));
                     document->setStudyValue(study, key, json, undoText);
                   });
  QObject::connect(spin, &QSpinBox::editingFinished, document, &ProjectDocument::endEditSequence);
  QObject::connect(document, &ProjectDocument::changed, spin, [spin, effective, syncing] {
    const qint64 value = effective();
    if (value < spin->minimum() || value > spin->maximum() || value == spin->value()) return;
    *syncing = true;
    spin->setValue(static_cast<int>(value));
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, QDoubleSpinBox* spin, const QString& study,
                      const QString& key, std::function<std::optional<double>()> effective,
                      const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  // Equal as the spin box shows them (its decimals): a project value with more digits is no edit.
  const auto same = [spin](double a, double b) {
    return std::abs(a - b) <= 0.5 * std::pow(10.0, -spin->decimals());
  };
  QObject::connect(spin, &QDoubleSpinBox::valueChanged, spin,
                   [document, study, key, effective, same, undoText, syncing](double value) {
                     if (*syncing) return;
                     if (const std::optional<double> v = effective(); v && same(*v, value)) return;
                     document->setStudyValue(study, key, value, undoText);
                   });
  QObject::connect(spin, &QDoubleSpinBox::editingFinished, document, &ProjectDocument::endEditSequence);
  QObject::connect(document, &ProjectDocument::changed, spin, [spin, effective, same, syncing] {
    const std::optional<double> value = effective();
    if (!value || !std::isfinite(*value) || *value < spin->minimum() || *value > spin->maximum() ||
        same(*value, spin->value()))
      return;
    *syncing = true;
    spin->setValue(*value);
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, QCheckBox* box, const QString& study, const QString& key,
                      std::function<std::optional<bool>()> effective, const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(box, &QCheckBox::toggled, box,
                   [document, study, key, effective, undoText, syncing](bool on) {
                     if (*syncing) return;
                     if (const std::optional<bool> v = effective(); v && *v == on) return;
                     document->endEditSequence();
                     document->setStudyValue(study, key, on, undoText);
                     document->endEditSequence();
                   });
  QObject::connect(document, &ProjectDocument::changed, box, [box, effective, syncing] {
    const std::optional<bool> value = effective();
    if (!value || *value == box->isChecked()) return;
    *syncing = true;
    box->setChecked(*value);  // the page's own reactions to the change still run
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, QLineEdit* edit, const QString& study, const QString& key,
                      std::function<std::optional<QString>()> effective, bool emptyRemoves,
                      const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(edit, &QLineEdit::textChanged, edit,
                   [document, study, key, effective, emptyRemoves, undoText, syncing](const QString& text) {
                     if (*syncing) return;
                     if (const std::optional<QString> v = effective(); v && *v == text) return;
                     const nlohmann::json json = text.isEmpty() && emptyRemoves
                                                     ? nlohmann::json()
                                                     : nlohmann::json(text.toStdString());
                     document->setStudyValue(study, key, json, undoText);
                   });
  QObject::connect(edit, &QLineEdit::editingFinished, document, &ProjectDocument::endEditSequence);
  QObject::connect(document, &ProjectDocument::changed, edit, [edit, effective, syncing] {
    const std::optional<QString> value = effective();
    if (!value || *value == edit->text()) return;
    *syncing = true;
    edit->setText(*value);
    *syncing = false;
  });
}

void bindStudyDatasetSetting(ProjectDocument* document, QComboBox* combo, const QString& study,
                             const QString& key, std::function<QString()> effective,
                             const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(combo, &QComboBox::currentIndexChanged, combo,
                   [document, combo, study, key, effective, undoText, syncing] {
                     if (*syncing || combo->currentIndex() < 0) return;
                     const QString value = combo->currentData().toString();
                     if (value == effective()) return;
                     document->endEditSequence();
                     document->setStudyValue(
                         study, key, value.isEmpty() ? nlohmann::json() : nlohmann::json(value.toStdString()),
                         undoText);
                     document->endEditSequence();
                   });
  QObject::connect(document, &ProjectDocument::changed, combo, [combo, effective, syncing] {
    const int index = combo->findData(effective());
    if (index < 0 || index == combo->currentIndex()) return;
    *syncing = true;
    combo->setCurrentIndex(index);
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, QComboBox* combo, const QString& study, const QString& key,
                      std::function<QString()> effective, const QString& undoText,
                      std::function<QString(const QVariant&)> text) {
  auto syncing = std::make_shared<bool>(false);
  QObject::connect(combo, &QComboBox::currentIndexChanged, combo,
                   [document, combo, study, key, effective, undoText, text, syncing] {
                     if (*syncing || combo->currentIndex() < 0) return;
                     const QString value = text(combo->currentData());
                     if (value == effective()) return;
                     document->endEditSequence();
                     document->setStudyValue(study, key, value.toStdString(), undoText);
                     document->endEditSequence();
                   });
  QObject::connect(document, &ProjectDocument::changed, combo, [combo, effective, text, syncing] {
    const QString value = effective();
    int index = -1;
    for (int i = 0; i < combo->count() && index < 0; ++i)
      if (text(combo->itemData(i)) == value) index = i;
    if (index < 0 || index == combo->currentIndex()) return;
    *syncing = true;
    combo->setCurrentIndex(index);  // the page's own reactions to the change still run
    *syncing = false;
  });
}

void bindStudySetting(ProjectDocument* document, const QList<QCheckBox*>& boxes, const QString& study,
                      const QString& key, std::function<nlohmann::json()> value,
                      std::function<std::optional<QList<bool>>()> effective, const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  const auto states = [boxes] {
    QList<bool> on;
    for (const QCheckBox* box : boxes) on << box->isChecked();
    return on;
  };
  for (QCheckBox* box : boxes) {
    QObject::connect(box, &QCheckBox::toggled, box,
                     [document, study, key, value, effective, states, undoText, syncing] {
                       if (*syncing) return;
                       if (const std::optional<QList<bool>> v = effective(); v && *v == states()) return;
                       document->endEditSequence();
                       document->setStudyValue(study, key, value(), undoText);
                       document->endEditSequence();
                     });
  }
  if (boxes.isEmpty()) return;
  QObject::connect(document, &ProjectDocument::changed, boxes.front(), [boxes, effective, states, syncing] {
    const std::optional<QList<bool>> value = effective();
    if (!value || value->size() != boxes.size() || *value == states()) return;
    *syncing = true;
    for (qsizetype k = 0; k < boxes.size(); ++k) boxes[k]->setChecked((*value)[k]);  // reactions still run
    *syncing = false;
  });
}

std::function<void()> bindStudySettings(ProjectDocument* document, QObject* view, const QString& study,
                                        std::function<std::optional<std::vector<StudyEdit>>()> edits,
                                        const QStringList& typingKeys, std::function<void()> show,
                                        const QString& macroText) {
  auto writing = std::make_shared<bool>(false);
  if (show) {
    QObject::connect(document, &ProjectDocument::changed, view, [show, writing] {
      if (!*writing) show();
    });
  }
  return [document, study, edits, typingKeys, macroText, writing] {
    if (*writing) return;
    const std::optional<std::vector<StudyEdit>> all = edits();
    if (!all) return;
    std::vector<StudyEdit> changed;
    for (const StudyEdit& e : *all)
      if (document->studyValue(study, e.key) != e.value) changed.push_back(e);
    if (changed.empty()) return;
    const bool typing = changed.size() == 1 && typingKeys.contains(changed.front().key);
    *writing = true;
    if (!typing) document->endEditSequence();
    if (changed.size() > 1) document->undoStack()->beginMacro(macroText);
    for (const StudyEdit& e : changed) document->setStudyValue(study, e.key, e.value, e.undoText);
    if (changed.size() > 1) document->undoStack()->endMacro();
    if (!typing) document->endEditSequence();
    *writing = false;
  };
}

}  // namespace metrofit
