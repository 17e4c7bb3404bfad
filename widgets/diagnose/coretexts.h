#pragma once
// Core's texts in the GUI, translated (core/common/text.h): core records its evidence, notes and
// axis titles as Phrases (English templates with %1 ... placeholders and typed arguments) next to
// the English strings the files and the CLI keep. Here a phrase is shown with its template
// translated in the context "metrofit::core" (QCoreApplication::translate) and its numbers
// formatted with the user's QLocale (',' decimals in German and Polish); names stay as they are,
// units too except "um", which is shown as "µm".
//
// lupdate does not read core: every template core produces is listed in coretexts.cpp with
// QT_TRANSLATE_NOOP, and diagnosis_locale_test runs the diagnoses and fails on a template that is
// missing from that list (coreTextSources()), so a new core sentence cannot silently stay English.
// When a template is added in core, add it to the list (and to the .ts files via lupdate).
//
// Also here: display names of the diagnosis parameters (keys of docs/file-formats.md#effect-catalogue:
// "tau_min", "x_mm", ...) and the text of a run's termination reason (core/common/run.h toString:
// "converged", ...).
#include <QLocale>
#include <QString>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/common/text.h"

namespace metrofit {

/// The translation context of core's texts.
inline constexpr char kCoreTextContext[] = "metrofit::core";

/// Every template core produces (the QT_TRANSLATE_NOOP list).
const std::vector<const char*>& coreTextSources();
/// True when `format` is in coreTextSources().
bool isCoreTextSource(const std::string& format);

/// One phrase / a text, translated, numbers in `locale`.
QString coreText(const Phrase& phrase, const QLocale& locale = QLocale());
QString coreText(const Phrases& text, const QLocale& locale = QLocale());
/// `text` translated when it has phrases, else `english` as it is (e.g. a result without phrases).
QString coreText(const Phrases& text, const std::string& english, const QLocale& locale = QLocale());

/// A number as the GUI shows it: `precision` significant digits ('g') or decimals ('f') in
/// `locale`; "n/a" (translated) when it is not finite.
QString localNumber(double value, int precision = 4, char style = 'g', const QLocale& locale = QLocale());

/// Units for display: "um" -> "µm" (as a word, e.g. "um/min" -> "µm/min"); others unchanged.
QString displayUnit(const QString& units);

/// Core's ASCII symbols as the GUI shows them: "+-" -> "±", "->" -> "→", "um" -> "µm" (every
/// template and English text of core passes through it, whatever the language).
QString displaySymbols(const QString& text);

/// The display name of a diagnosis parameter key (docs/file-formats.md#effect-catalogue, e.g. "tau_min" ->
/// "time constant"), translated; unknown keys as they are.
QString parameterDisplayName(const std::string& key);
/// True when `key` has a display name (a translatable one).
bool hasParameterDisplayName(const std::string& key);

/// The termination reason of a run ("converged", "iteration limit", ...), translated.
QString terminationText(Termination termination);

}  // namespace metrofit
