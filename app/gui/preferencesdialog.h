#pragma once
// Preferences: the user interface language (applied at the next start).
#include <QDialog>

class QComboBox;

namespace metrofit {

class PreferencesDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PreferencesDialog(QWidget* parent = nullptr);

  /// The chosen language code ("system", "en", "de", "pl").
  QString language() const;
  QComboBox* languageCombo() const { return language_; }

  /// Stores the choice in QSettings; returns true when it differs from the stored one.
  bool apply();

 private:
  QComboBox* language_;
};

}  // namespace metrofit
