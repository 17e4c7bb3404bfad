#pragma once
// Preferences: the user interface language (applied at the next start) and the autosave interval.
#include <QDialog>

class QComboBox;
class QSpinBox;

namespace metrofit {

class PreferencesDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PreferencesDialog(QWidget* parent = nullptr);

  /// The chosen language code ("system", "en", "de", "pl").
  QString language() const;
  QComboBox* languageCombo() const { return language_; }
  /// Minutes between autosaves (0: off).
  QSpinBox* autosaveSpin() const { return autosave_; }

  /// Stores the choices in QSettings; returns true when the language differs from the stored one.
  bool apply();

 private:
  QComboBox* language_;
  QSpinBox* autosave_;
};

}  // namespace metrofit
