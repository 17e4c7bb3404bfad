#include "app/gui/studysettingbinding.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>
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
  const auto shown = [spin, effective] {
    return static_cast<int>(std::clamp<qint64>(effective(), spin->minimum(), spin->maximum()));
  };
  QObject::connect(spin, &QSpinBox::valueChanged, spin,
                   [document, study, key, shown, writeUnsigned, undoText, syncing](int value) {
                     if (*syncing || value == shown()) return;
                     // Typing merges into one undo step until editingFinished.
                     const nlohmann::json json = writeUnsigned && value >= 0
                                                     ? nlohmann::json(static_cast<std::uint64_t>(value))
                                                     : nlohmann::json(static_cast<std::int64_t>(value));
                     document->setStudyValue(study, key, json, undoText);
                   });
  QObject::connect(spin, &QSpinBox::editingFinished, document, &ProjectDocument::endEditSequence);
  QObject::connect(document, &ProjectDocument::changed, spin, [spin, shown, syncing] {
    const int value = shown();
    if (value == spin->value()) return;
    *syncing = true;
    spin->setValue(value);
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

void bindStudySetting(ProjectDocument* document, QDoubleSpinBox* spin, const QString& study,
                      const QString& key, std::function<double()> effective, const QString& undoText) {
  auto syncing = std::make_shared<bool>(false);
  const auto shown = [spin, effective] {
    const double v = effective();
    return std::isfinite(v) ? std::clamp(v, spin->minimum(), spin->maximum()) : spin->minimum();
  };
  // Equal as the box shows them (its decimals): showing a value is never an edit.
  const auto same = [spin](double a, double b) {
    return std::abs(a - b) < 0.5 * std::pow(10.0, -spin->decimals());
  };
  QObject::connect(spin, &QDoubleSpinBox::valueChanged, spin,
                   [document, study, key, shown, same, undoText, syncing](double value) {
                     if (*syncing || same(value, shown())) return;
                     document->setStudyValue(study, key, value, undoText);  // typing: one undo step
                   });
  QObject::connect(spin, &QDoubleSpinBox::editingFinished, document, &ProjectDocument::endEditSequence);
  QObject::connect(document, &ProjectDocument::changed, spin, [spin, shown, same, syncing] {
    const double value = shown();
    if (same(value, spin->value())) return;
    *syncing = true;
    spin->setValue(value);
    *syncing = false;
  });
}

}  // namespace metrofit
