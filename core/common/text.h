#pragma once
// Texts core writes for people (the diagnosis evidence, notes and residual-plot axis titles) in a
// form the GUI can translate, without core depending on Qt.
//
// Core keeps building the English string every file, the CLI and the report carry (docs/file-formats.md:
// the JSON stays exactly as it is); next to it, it records the same text as a list of Phrases, and
// the English string is made *from* that list (english()), so the two cannot differ.
//
// A Phrase is an English template with Qt-style placeholders %1 to %99 (the source text a
// translator sees; a '%' not followed by a digit is literal, e.g. "%1 %" is a percentage) and its
// arguments:
//   * numbers: printf's %.<p>g (significant digits) or %.<p>f (decimals), optionally with a '+'
//     before values >= 0 and "n/a" for NaN / infinity. The English text uses the C locale
//     (std::to_chars: independent of setlocale); the GUI formats them with the user's QLocale;
//   * names (columns, effects, setup data, surfaces): verbatim, never translated;
//   * units ("mm", " um", "ppm"): verbatim, never translated (the GUI shows "um" as "µm");
//   * nested texts (a list of phrases, e.g. a choice between two sentences): translated in turn.
// A text is a list of phrases whose English forms are concatenated; separators ("; ", ", ") belong
// to the templates, so a translation may change them.
//
// The GUI translates a template with QCoreApplication::translate("metrofit::core", format)
// (widgets/diagnose/coretexts.h); lupdate does not read core, so every template core produces is
// listed there, and a test runs the diagnoses and fails on a template missing from that list.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace metrofit {

struct Phrase;
/// A text: phrases whose English forms are concatenated.
using Phrases = std::vector<Phrase>;

/// One argument of a Phrase (see the header comment).
struct PhraseArg {
  enum class Kind { Number, Name, Unit, Text };
  Kind kind = Kind::Name;
  double value = 0.0;
  char style = 'g';       ///< 'g': `precision` significant digits; 'f': `precision` decimals; 'd': integer
  int precision = 6;      ///< as printf's precision (%g: 6)
  bool plusSign = false;  ///< "+" before values >= 0 (percent changes)
  bool naIfNotFinite = false;  ///< "n/a" for NaN and infinity (else "nan", "inf")
  std::string verbatim;        ///< Name, Unit
  Phrases nested;              ///< Text

  /// %.<significant>g (to_chars general); "nan" / "inf" when not finite.
  static PhraseArg number(double value, int significant = 6);
  /// The same with "n/a" when the value is not finite.
  static PhraseArg numberOrNa(double value, int significant = 6);
  /// An integer (counts, rounds).
  static PhraseArg integer(long long value);
  /// %.<decimals>f.
  static PhraseArg fixed(double value, int decimals);
  /// "+" before values >= 0, then %.<significant>g.
  static PhraseArg signedNumber(double value, int significant);
  static PhraseArg name(std::string name);
  static PhraseArg unit(std::string unit);
  static PhraseArg text(Phrases phrases);

  /// The argument as it appears in the English text.
  std::string english() const;
};

/// An English template with placeholders %1 to %99 and its arguments.
struct Phrase {
  std::string format;
  std::vector<PhraseArg> args;

  Phrase() = default;
  explicit Phrase(std::string format, std::vector<PhraseArg> args = {})
      : format(std::move(format)), args(std::move(args)) {}

  /// The template with its arguments substituted (C locale).
  std::string english() const;
};

/// The English forms of `text` concatenated.
std::string english(const Phrases& text);

/// Replaces %1 to %99 in `format` by args[0] to args[98] in one pass (a replacement is never scanned
/// again); a '%' not followed by a digit, or with a number beyond args, is kept as it is.
std::string substitutePlaceholders(std::string_view format, const std::vector<std::string>& args);

/// Every template of `text`, nested texts included (for the translation coverage test).
void collectFormats(const Phrases& text, std::vector<std::string>& out);

}  // namespace metrofit
