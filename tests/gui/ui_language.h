// The GUI in one of its languages for the length of a scope: Metrofit's translation installed and
// (optionally) the default QLocale of that language, both undone when the object dies, also when an
// ASSERT leaves the test early. "en" installs nothing (the source texts). Shared by the tests that
// walk the GUI in English, German and Polish (clipping_test, page_layout_test, mainwindow_test,
// mainwindow_shell_test).
#pragma once

#include <QCoreApplication>
#include <QLocale>
#include <QString>
#include <QTranslator>

namespace metrofit::test {

class ScopedUiLanguage {
 public:
  enum class Locale { Follow, Keep };

  explicit ScopedUiLanguage(const QString& language, Locale locale = Locale::Follow) : language_(language) {
    if (language != QLatin1String("en")) {
      loaded_ = translator_.load(QStringLiteral(METROFIT_QM_DIR "/metrofit_") + language);
      if (loaded_) installed_ = QCoreApplication::installTranslator(&translator_);
    }
    if (locale == Locale::Follow) {
      setLocale_ = true;
      QLocale::setDefault(QLocale(language));
    }
  }
  ~ScopedUiLanguage() {
    if (setLocale_) QLocale::setDefault(previous_);
    if (installed_) QCoreApplication::removeTranslator(&translator_);
  }
  ScopedUiLanguage(const ScopedUiLanguage&) = delete;
  ScopedUiLanguage& operator=(const ScopedUiLanguage&) = delete;

  /// True for "en" and when metrofit_<language>.qm was found and installed.
  bool ok() const { return language_ == QLatin1String("en") || (loaded_ && installed_); }
  /// What ok() == false means, for the assertion's message.
  std::string why() const {
    return ("metrofit_" + language_ + ".qm not loaded from " METROFIT_QM_DIR).toStdString();
  }

 private:
  QString language_;
  QTranslator translator_;
  QLocale previous_;
  bool loaded_ = false;
  bool installed_ = false;
  bool setLocale_ = false;
};

}  // namespace metrofit::test
