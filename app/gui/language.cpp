#include "app/gui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>
#include <cstdio>

namespace metrofit {

QStringList languageChoices() {
  return {QString::fromLatin1(kSystemLanguage), QStringLiteral("en"), QStringLiteral("de"),
          QStringLiteral("pl")};
}

QString languageSetting() {
  const QString value = QSettings().value(QString::fromLatin1(kLanguageSettingsKey)).toString();
  return languageChoices().contains(value) ? value : QString::fromLatin1(kSystemLanguage);
}

void setLanguageSetting(const QString& choice) {
  QSettings().setValue(QString::fromLatin1(kLanguageSettingsKey), choice);
}

QString effectiveLanguage(const QString& choice) {
  if (choice != QLatin1String(kSystemLanguage)) return choice;
  for (const QString& ui : QLocale::system().uiLanguages()) {
    const QString language = ui.left(2).toLower();
    if (languageChoices().contains(language)) return language;
  }
  return QStringLiteral("en");
}

namespace {
QString& installedLanguage() {
  static QString language = QStringLiteral("en");
  return language;
}
}  // namespace

QString currentLanguage() {
  return installedLanguage();
}

bool installTranslators(QCoreApplication& app, const QString& language) {
  if (language == QLatin1String("en")) {
    installedLanguage() = language;
    return true;
  }
  auto* qt = new QTranslator(&app);
  if (qt->load(QStringLiteral("qtbase_") + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
    QCoreApplication::installTranslator(qt);
  } else {
    delete qt;
  }
  auto* own = new QTranslator(&app);
  if (!own->load(QStringLiteral(":/i18n/metrofit_") + language)) {
    delete own;
    return false;
  }
  QCoreApplication::installTranslator(own);
  installedLanguage() = language;
  return true;
}

bool useLanguage(QCoreApplication& app, const QString& language) {
  const QLocale system = QLocale::system();
  const bool keepSystem = system.name().left(2).toLower() == language ||
                          (language == QLatin1String("en") && system.language() == QLocale::C);
  QLocale::setDefault(keepSystem ? system : QLocale(language));
  return installTranslators(app, language);
}

bool applyLanguageOption(QCoreApplication& app, const QString& code) {
  const QString language = code.trimmed().toLower();
  if (language == QLatin1String(kSystemLanguage) || !languageChoices().contains(language)) {
    std::fprintf(stderr, "metrofit: --lang takes en, de or pl, not '%s'\n", qPrintable(code));
    return false;
  }
  QLocale::setDefault(QLocale(language));
  if (!installTranslators(app, language)) {
    std::fprintf(stderr, "metrofit: no translation for '%s' is built in\n", qPrintable(language));
    return false;
  }
  return true;
}

}  // namespace metrofit
