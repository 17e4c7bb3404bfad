#pragma once
// The user interface language: stored in QSettings under "ui/language" ("system", "en", "de",
// "pl") and applied at start-up by installing the translator ":/i18n/metrofit_<lang>.qm".
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace metrofit {

inline constexpr const char* kLanguageSettingsKey = "ui/language";
inline constexpr const char* kSystemLanguage = "system";

/// The language codes a user can choose: "system" then "en", "de", "pl".
QStringList languageChoices();
/// The stored choice ("system" when none or unknown).
QString languageSetting();
void setLanguageSetting(const QString& choice);
/// The language a choice means: "system" resolves to the system locale's language when Metrofit
/// has a translation for it, else "en".
QString effectiveLanguage(const QString& choice);
/// Installs Metrofit's (and, when present, Qt's own) translators for a language. Returns true when
/// Metrofit's translation was found (always true for "en", which needs none).
bool installTranslators(QCoreApplication& app, const QString& language);
/// The UI language for the run from the Preferences: its translators, and its numbers on screen
/// (QLocale's default): the system's own locale when it is of that language (a de_CH desktop keeps its
/// formats), else the language's (English UI on a German desktop: 0.013, not 0,013), so no page shows
/// "0.051" beside "3,969". Files never follow it (core/common/numformat.h). Returns installTranslators'.
bool useLanguage(QCoreApplication& app, const QString& language);
/// `metrofit --lang CODE`: for this run only, the language "en", "de" or "pl" (its translators and
/// its locale for the numbers shown). An unknown code is reported on stderr and returns false.
bool applyLanguageOption(QCoreApplication& app, const QString& code);
/// The language whose translators useLanguage() or applyLanguageOption() installed last ("en" before
/// either ran): Export report writes the PDF in it (`metrofit-cli report --lang`).
QString currentLanguage();

}  // namespace metrofit
