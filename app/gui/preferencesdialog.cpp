#include "app/gui/preferencesdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>

#include "app/gui/autosave.h"
#include "app/gui/language.h"

namespace metrofit {

PreferencesDialog::PreferencesDialog(QWidget* parent)
    : QDialog(parent), language_(new QComboBox(this)), autosave_(new QSpinBox(this)) {
  setWindowTitle(tr("Preferences"));
  language_->setObjectName(QStringLiteral("languageCombo"));
  // Language names are shown in their own language, so a user can find theirs in any UI language.
  language_->addItem(tr("System"), QString::fromLatin1(kSystemLanguage));
  language_->addItem(QStringLiteral("English"), QStringLiteral("en"));
  language_->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
  language_->addItem(QStringLiteral("Polski"), QStringLiteral("pl"));
  language_->setCurrentIndex(std::max(0, language_->findData(languageSetting())));

  autosave_->setObjectName(QStringLiteral("autosaveSpin"));
  autosave_->setRange(0, Autosave::kMaxIntervalMinutes);
  autosave_->setSuffix(tr(" min"));
  autosave_->setSpecialValueText(tr("Off"));
  autosave_->setValue(Autosave::intervalSetting());
  autosave_->setToolTip(
      tr("While the project has unsaved changes, a copy is written next to it this often, and offered "
         "for recovery after a crash (0: off)"));

  auto* note = new QLabel(tr("The language is applied at the next start of Metrofit."), this);
  note->setWordWrap(true);

  auto* form = new QFormLayout;
  form->addRow(tr("&Language:"), language_);
  form->addRow(tr("&Autosave every:"), autosave_);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("OK"));
  buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(note);
  layout->addStretch(1);
  layout->addWidget(buttons);
}

QString PreferencesDialog::language() const {
  return language_->currentData().toString();
}

bool PreferencesDialog::apply() {
  const bool changed = language() != languageSetting();
  setLanguageSetting(language());
  Autosave::setIntervalSetting(autosave_->value());
  return changed;
}

}  // namespace metrofit
