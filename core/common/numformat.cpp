#include "core/common/numformat.h"

#include <locale.h>  // newlocale, uselocale, strtod_l (POSIX / glibc)
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace metrofit {
namespace {

/// The C locale as a locale object (never freed: it lives as long as the process).
locale_t cLocale() {
  static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  return c;
}

/// Makes the C locale the calling thread's locale for the lifetime of the object.
class CLocaleScope {
 public:
  CLocaleScope() : previous_(cLocale() != nullptr ? uselocale(cLocale()) : nullptr) {}
  ~CLocaleScope() {
    if (previous_ != nullptr) uselocale(previous_);
  }
  CLocaleScope(const CLocaleScope&) = delete;
  CLocaleScope& operator=(const CLocaleScope&) = delete;

 private:
  locale_t previous_;
};

std::string chars(double v, std::chars_format format, int precision) {
  char buf[512];  // %.*f of 1e308 with 12 decimals fits
  const auto res = std::to_chars(buf, buf + sizeof buf, v, format, precision);
  if (res.ec != std::errc()) return cformat("%.*g", precision, v);  // not reached for sane precisions
  return std::string(buf, res.ptr);
}

}  // namespace

int c_vsnprintf(char* buf, std::size_t size, const char* format, std::va_list args) {
  CLocaleScope c;
  return std::vsnprintf(buf, size, format, args);
}

int c_snprintf(char* buf, std::size_t size, const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  const int n = c_vsnprintf(buf, size, format, args);
  va_end(args);
  return n;
}

std::string cformat(const char* format, ...) {
  char small[256];
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int n = c_vsnprintf(small, sizeof small, format, args);
  va_end(args);
  std::string out;
  if (n < 0) {
    out.clear();
  } else if (static_cast<std::size_t>(n) < sizeof small) {
    out.assign(small, static_cast<std::size_t>(n));
  } else {
    std::vector<char> big(static_cast<std::size_t>(n) + 1);
    c_vsnprintf(big.data(), big.size(), format, again);
    out.assign(big.data(), static_cast<std::size_t>(n));
  }
  va_end(again);
  return out;
}

namespace num {

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  return chars(v, std::chars_format::fixed, decimals);
}

std::string fixedSigned(double v, int decimals) {
  const std::string s = fixed(v, decimals);
  return s.empty() || s[0] == '-' || std::isnan(v) ? s : "+" + s;
}

std::string general(double v, int significant) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  return chars(v, std::chars_format::general, significant);
}

std::string shortest(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string toString(double v) {
  return fixed(v, 6);
}

std::optional<double> parseDouble(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;  // from_chars does not take a leading '+'
  if (first == last || *first == '+') return std::nullopt;
  double v = 0.0;
  const auto res = std::from_chars(first, last, v);
  if (res.ec == std::errc::result_out_of_range) {
    // Overflow / underflow: what strtod gives (inf or a denormal/zero), so "1e400" is inf.
    const std::string copy(text);
    char* end = nullptr;
    v = strtodC(copy.c_str(), &end);
    return end == copy.c_str() + copy.size() ? std::optional<double>(v) : std::nullopt;
  }
  if (res.ec != std::errc() || res.ptr != last) return std::nullopt;
  return v;
}

double strtodC(const char* text, char** end) {
  if (cLocale() == nullptr) {
    CLocaleScope c;
    return std::strtod(text, end);
  }
  return strtod_l(text, end, cLocale());
}

}  // namespace num
}  // namespace metrofit
