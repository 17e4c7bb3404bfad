#pragma once
// Numbers in files, independent of the process locale (issue 27).
//
// A control reads `G10 L2 P1 Z0.013`; under a German or Polish locale printf's "%f" writes
// `Z0,013`, which a control rejects or reads as `Z0` (notes/gui-run.md F1). QApplication calls
// setlocale(LC_ALL, "") on Unix, so every printf-family and strtod call in a Qt process follows
// the user's desktop. Core therefore never formats or parses a number in a file with them:
//   * cformat / c_snprintf: printf's formats under an explicit C locale (uselocale, per thread);
//   * fixed / general / toString: std::to_chars (locale independent by definition);
//   * parseDouble / strtodC: std::from_chars / strtod_l with the C locale.
// Tests keep it so: tests/core/locale_lint.sh refuses std::snprintf, strtod, atof and std::stod in
// core, widgets and app outside numformat.cpp; tests/core/locale_to_string_check.cmake refuses
// std::to_string of a floating value; tests/core/common/locale_matrix_test.cpp runs every writer and
// reader under C.UTF-8, de_DE.UTF-8 and pl_PL.UTF-8.
#include <cstdarg>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace metrofit {

/// std::snprintf with the C locale's '.' whatever setlocale says (same return value).
int c_snprintf(char* buf, std::size_t size, const char* format, ...) __attribute__((format(printf, 3, 4)));
/// The same as vsnprintf.
int c_vsnprintf(char* buf, std::size_t size, const char* format, std::va_list args);
/// printf's format under the C locale, as a string of any length.
std::string cformat(const char* format, ...) __attribute__((format(printf, 1, 2)));

namespace num {

/// printf("%.*f", decimals, v) in the C locale: "0.013", "-1.7300"; "nan" / "inf" / "-inf".
std::string fixed(double v, int decimals);
/// printf("%+.*f"): "+0.013", "-0.021" (a "+" before values >= 0, also +0.000).
std::string fixedSigned(double v, int decimals);
/// printf("%.*g", significant, v) in the C locale.
std::string general(double v, int significant = 6);
/// The shortest text that reads back to exactly v ("0.1", "1e-07").
std::string shortest(double v);
/// What std::to_string(double) gives in the C locale ("%f": "0.050000").
std::string toString(double v);

/// The whole of `text` as a C-locale number ('.' decimal mark, optional sign and exponent, "inf",
/// "nan"); leading/trailing blanks are not accepted. nullopt when it is not exactly one number.
std::optional<double> parseDouble(std::string_view text);
/// std::strtod with the C locale (leading blanks skipped, *end set as strtod does).
double strtodC(const char* text, char** end);

}  // namespace num
}  // namespace metrofit
