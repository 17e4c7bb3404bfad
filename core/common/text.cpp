#include "core/common/text.h"

#include <charconv>
#include <cmath>

namespace metrofit {
namespace {

std::string formatDouble(double value, char style, int precision) {
  char buf[400];
  const auto res =
      std::to_chars(buf, buf + sizeof buf, value,
                    style == 'f' ? std::chars_format::fixed : std::chars_format::general, precision);
  if (res.ec != std::errc()) return "n/a";
  return std::string(buf, res.ptr);
}

}  // namespace

PhraseArg PhraseArg::number(double value, int significant) {
  PhraseArg a;
  a.kind = Kind::Number;
  a.value = value;
  a.style = 'g';
  a.precision = significant;
  return a;
}

PhraseArg PhraseArg::numberOrNa(double value, int significant) {
  PhraseArg a = number(value, significant);
  a.naIfNotFinite = true;
  return a;
}

PhraseArg PhraseArg::integer(long long value) {
  PhraseArg a = number(static_cast<double>(value), 0);
  a.style = 'd';
  return a;
}

PhraseArg PhraseArg::fixed(double value, int decimals) {
  PhraseArg a = number(value, decimals);
  a.style = 'f';
  return a;
}

PhraseArg PhraseArg::signedNumber(double value, int significant) {
  PhraseArg a = number(value, significant);
  a.plusSign = true;
  return a;
}

PhraseArg PhraseArg::name(std::string name) {
  PhraseArg a;
  a.kind = Kind::Name;
  a.verbatim = std::move(name);
  return a;
}

PhraseArg PhraseArg::unit(std::string unit) {
  PhraseArg a;
  a.kind = Kind::Unit;
  a.verbatim = std::move(unit);
  return a;
}

PhraseArg PhraseArg::text(Phrases phrases) {
  PhraseArg a;
  a.kind = Kind::Text;
  a.nested = std::move(phrases);
  return a;
}

std::string PhraseArg::english() const {
  switch (kind) {
    case Kind::Number: {
      if (naIfNotFinite && !std::isfinite(value)) return "n/a";
      if (style == 'd') return std::to_string(static_cast<long long>(value));
      const std::string s = formatDouble(value, style, precision);
      return plusSign && value >= 0.0 ? "+" + s : s;
    }
    case Kind::Name:
    case Kind::Unit:
      return verbatim;
    case Kind::Text:
      return metrofit::english(nested);
  }
  return {};
}

std::string Phrase::english() const {
  std::vector<std::string> values;
  values.reserve(args.size());
  for (const PhraseArg& a : args) values.push_back(a.english());
  return substitutePlaceholders(format, values);
}

std::string english(const Phrases& text) {
  std::string out;
  for (const Phrase& p : text) out += p.english();
  return out;
}

std::string substitutePlaceholders(std::string_view format, const std::vector<std::string>& args) {
  std::string out;
  out.reserve(format.size() + 16 * args.size());
  for (std::size_t i = 0; i < format.size(); ++i) {
    const char c = format[i];
    if (c == '%' && i + 1 < format.size() && format[i + 1] >= '1' && format[i + 1] <= '9') {
      std::size_t n = static_cast<std::size_t>(format[i + 1] - '0');
      std::size_t len = 2;
      if (i + 2 < format.size() && format[i + 2] >= '0' && format[i + 2] <= '9') {
        n = 10 * n + static_cast<std::size_t>(format[i + 2] - '0');
        len = 3;
      }
      if (n <= args.size()) {
        out += args[n - 1];
        i += len - 1;
        continue;
      }
    }
    out += c;
  }
  return out;
}

void collectFormats(const Phrases& text, std::vector<std::string>& out) {
  for (const Phrase& p : text) {
    out.push_back(p.format);
    for (const PhraseArg& a : p.args)
      if (a.kind == PhraseArg::Kind::Text) collectFormats(a.nested, out);
  }
}

}  // namespace metrofit
