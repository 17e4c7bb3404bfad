#include "core/io/dfq.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/text_encoding.h"

namespace metrofit {
namespace {

std::string number(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string text(std::string s) {
  for (char& c : s) {
    if (c == '\r' || c == '\n' || c == '\t') c = ' ';
  }
  if (s.size() > 255) s.resize(255);
  return s;
}

[[noreturn]] void fail(const std::string& what) {
  throw ValidationError(ErrorContext{{}, 0, 0, "dfq"}, what);
}

}  // namespace

std::optional<std::string> qdasDateTime(const std::string& iso) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0;
  char sep = 0;
  int used = 0;
  const int n = std::sscanf(iso.c_str(), "%4d-%2d-%2d%c%2d:%2d%n", &y, &mo, &d, &sep, &h, &mi, &used);
  if (n != 6 || (sep != 'T' && sep != ' ')) return std::nullopt;
  std::size_t pos = static_cast<std::size_t>(used);
  if (pos < iso.size() && iso[pos] == ':') {
    int more = 0;
    if (std::sscanf(iso.c_str() + pos, ":%2d%n", &s, &more) != 1) return std::nullopt;
    pos += static_cast<std::size_t>(more);
  }
  if (pos != iso.size()) return std::nullopt;
  if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || s > 60 || h < 0 || mi < 0 || s < 0)
    return std::nullopt;
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, "%02d.%02d.%04d/%02d:%02d:%02d", d, mo, y, h, mi, s);
  return std::string(buf);
}

std::optional<double> qdasMinutes(const std::string& text) {
  // DD.MM.YYYY, then '/' or blanks, then HH:MM[:SS]; digits parsed by hand (locale free).
  std::string_view t(text);
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t' || t.back() == '\r')) t.remove_suffix(1);
  std::size_t pos = 0;
  const auto digits = [&](std::size_t most, int* out) {
    std::size_t n = 0;
    int v = 0;
    while (pos < t.size() && n < most && std::isdigit(static_cast<unsigned char>(t[pos]))) {
      v = v * 10 + (t[pos] - '0');
      ++pos;
      ++n;
    }
    *out = v;
    return n > 0;
  };
  const auto expect = [&](char c) {
    if (pos < t.size() && t[pos] == c) {
      ++pos;
      return true;
    }
    return false;
  };
  int d = 0, mo = 0, y = 0, h = 0, mi = 0, sec = 0;
  if (!digits(2, &d) || !expect('.') || !digits(2, &mo) || !expect('.') || !digits(4, &y))
    return std::nullopt;
  if (!expect('/') && !expect(' ')) return std::nullopt;
  while (pos < t.size() && t[pos] == ' ') ++pos;
  if (!digits(2, &h) || !expect(':') || !digits(2, &mi)) return std::nullopt;
  if (expect(':') && !digits(2, &sec)) return std::nullopt;
  if (pos != t.size() || mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec > 60 || y < 1900)
    return std::nullopt;
  // Days from the civil date (H. Hinnant's days_from_civil).
  const int yy = mo <= 2 ? y - 1 : y;
  const int era = yy / 400;
  const int yoe = yy - era * 400;
  const int doy = (153 * (mo + (mo > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const long days = static_cast<long>(era) * 146097 + doe - 719468;
  return static_cast<double>(days) * 1440.0 + h * 60.0 + mi + sec / 60.0;
}

std::string writeDfq(const DfqPart& part) {
  const auto& cs = part.characteristics;
  if (cs.empty()) fail("a DFQ file needs at least one characteristic");
  std::size_t most = 0;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const DfqCharacteristic& c = cs[i];
    const std::string which = "characteristic " + std::to_string(i + 1) + " (" + c.number + ")";
    if (c.values.empty()) fail(which + " has no values");
    for (const double v : c.values) {
      if (!std::isfinite(v)) fail(which + " has a value that is not a finite number");
    }
    for (const auto& v : {c.nominal, c.lowerLimit, c.upperLimit}) {
      if (v && !std::isfinite(*v)) fail(which + ": nominal and limits must be finite");
    }
    if (c.lowerLimit && c.upperLimit && !(*c.lowerLimit < *c.upperLimit))
      fail(which + ": the lower limit must be below the upper limit");
    if (!c.times.empty() && c.times.size() != c.values.size())
      fail(which + ": give one time per value or none");
    most = std::max(most, c.values.size());
  }
  std::string out;
  auto line = [&out](const std::string& key, const std::string& value) {
    out += key;
    out += ' ';
    out += value;
    out += "\r\n";
  };
  line("K0100", std::to_string(cs.size()));
  line("K1001/1", text(part.number));
  line("K1002/1", text(part.description));
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const DfqCharacteristic& c = cs[i];
    const std::string k = "/" + std::to_string(i + 1);
    line("K2001" + k, text(c.number));
    line("K2002" + k, text(c.description));
    if (c.nominal) line("K2101" + k, number(*c.nominal));
    if (c.lowerLimit) line("K2110" + k, number(*c.lowerLimit));
    if (c.upperLimit) line("K2111" + k, number(*c.upperLimit));
    if (!c.unit.empty()) line("K2142" + k, text(c.unit));
  }
  for (std::size_t row = 0; row < most; ++row) {
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const DfqCharacteristic& c = cs[i];
      if (row >= c.values.size()) continue;
      const std::string k = "/" + std::to_string(i + 1);
      line("K0001" + k, number(c.values[row]));
      if (!c.times.empty()) line("K0004" + k, c.times[row]);
    }
  }
  return out;
}

std::string dfqColumnUnit(const std::string& column) {
  const auto pos = column.rfind('_');
  if (pos == std::string::npos) return {};
  const std::string u = column.substr(pos + 1);
  for (const char* known : {"mm", "um", "deg", "s", "min", "h", "ppm"}) {
    if (u == known) return u;
  }
  return {};
}

DfqPart seriesDfqPart(const CsvTable& table, const std::string& column, const std::vector<double>& values,
                      std::optional<double> nominal, std::optional<double> lowerLimit,
                      std::optional<double> upperLimit, const std::string& dataPath,
                      const std::string& partNumber, const std::string& source) {
  DfqPart part;
  const std::string file = std::filesystem::path(dataPath).filename().string();
  part.number = partNumber.empty() ? std::filesystem::path(dataPath).stem().string() : partNumber;
  part.description = "Metrofit SPC series " + column + " of " + file;
  DfqCharacteristic c;
  c.number = column;
  c.description = column + " (" + file + ")";
  c.nominal = nominal;
  c.lowerLimit = lowerLimit;
  c.upperLimit = upperLimit;
  c.unit = dfqColumnUnit(column);
  c.values = values;
  if (const int t = table.columnIndex("timestamp"); t >= 0) {
    for (std::size_t r = 0; r < table.rowCount(); ++r) {
      const std::string& cell = table.cell(r, static_cast<std::size_t>(t));
      const std::optional<std::string> q = qdasDateTime(cell);
      if (!q) {
        throw ParseError(ErrorContext{source, table.lineOf(r), t + 1, "timestamp"},
                         "'" + cell + "' is not a date-time YYYY-MM-DDTHH:MM[:SS]");
      }
      c.times.push_back(*q);
    }
  }
  part.characteristics.push_back(std::move(c));
  return part;
}

// ---- Reading -------------------------------------------------------------------------------------

namespace {

/// The value-line separators: 0x0F / U+00A4 between the fields of a characteristic, 0x14 / U+00B6
/// between characteristics (after the text was made UTF-8).
constexpr std::string_view kFieldSep8 = "\x0F", kFieldSepU = "\xC2\xA4";
constexpr std::string_view kCharSep8 = "\x14", kCharSepU = "\xC2\xB6";

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// Splits at either spelling of a separator.
std::vector<std::string_view> splitAt(std::string_view s, std::string_view a, std::string_view b) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size();) {
    if (s.compare(i, a.size(), a) == 0) {
      out.push_back(s.substr(start, i - start));
      i += a.size();
      start = i;
    } else if (s.compare(i, b.size(), b) == 0) {
      out.push_back(s.substr(start, i - start));
      i += b.size();
      start = i;
    } else {
      ++i;
    }
  }
  out.push_back(s.substr(start));
  return out;
}

struct Reader {
  std::string source;
  DfqFile file;
  long line = 0;
  std::optional<int> count;  // K0100
  int currentPart = 1;
  // Fields given for all (index 0): key -> (value, line).
  std::map<std::string, std::pair<std::string, long>> allCharacteristics, allParts;
  // Per characteristic: the keys it gave itself.
  std::map<int, std::set<std::string>> ownKeys;
  std::map<int, DfqReadCharacteristic> chars;
  std::map<int, long> lowerLimitLine;  // the line of K2110/i (for the limits check)
  std::map<int, DfqReadPart> parts;
  // The value set read last: (characteristic index, position in its values).
  std::vector<std::pair<int, std::size_t>> lastSet;

  [[noreturn]] void parseFail(const std::string& field, const std::string& what) const {
    throw ParseError(ErrorContext{source, line, 0, field}, what);
  }

  double number(std::string_view text, const std::string& field) const {
    std::string t(trimmed(text));
    if (t.empty()) parseFail(field, "a number is missing");
    std::string parsed = t;
    if (parsed.find('.') == std::string::npos && std::count(parsed.begin(), parsed.end(), ',') == 1)
      std::replace(parsed.begin(), parsed.end(), ',', '.');
    const char* first = parsed.data();
    const char* last = parsed.data() + parsed.size();
    if (*first == '+') ++first;
    double v = 0.0;
    const auto res = std::from_chars(first, last, v);
    if (res.ec != std::errc() || res.ptr != last || !std::isfinite(v))
      parseFail(field, "'" + t + "' is not a number");
    return v;
  }

  int integer(std::string_view text, const std::string& field) const {
    const std::string t(trimmed(text));
    int v = 0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || res.ec != std::errc() || res.ptr != t.data() + t.size())
      parseFail(field, "'" + t + "' is not a whole number");
    return v;
  }

  DfqReadCharacteristic& characteristic(int i, const std::string& field) {
    if (i < 1) parseFail(field, "characteristic index " + std::to_string(i) + " (1 or more, or 0 for all)");
    if (count && i > *count)
      parseFail(field, "characteristic " + std::to_string(i) + " beyond K0100 = " + std::to_string(*count) +
                           " (the number of characteristics in the file)");
    if (i > 100000) parseFail(field, "characteristic index " + std::to_string(i) + " is too large");
    auto [it, added] = chars.try_emplace(i);
    if (added) {
      it->second.index = i;
      it->second.part = currentPart;
    }
    return it->second;
  }

  /// Sets a characteristic field (K2xxx) on `c`.
  void setCharacteristicField(DfqReadCharacteristic& c, const std::string& key, std::string_view value,
                              const std::string& field) {
    if (key == "K2001") {
      c.number = std::string(trimmed(value));
    } else if (key == "K2002") {
      c.description = std::string(trimmed(value));
    } else if (key == "K2101") {
      c.nominal = number(value, field);
    } else if (key == "K2110") {
      c.lowerLimit = number(value, field);
      lowerLimitLine[c.index] = line;
    } else if (key == "K2111") {
      c.upperLimit = number(value, field);
    } else if (key == "K2022") {
      c.decimals = integer(value, field);
      if (*c.decimals < 0 || *c.decimals > 15) parseFail(field, "decimals must be 0 to 15");
    } else if (key == "K2142") {
      c.unit = std::string(trimmed(value));
    }
  }

  bool knownCharacteristicKey(const std::string& key) const {
    return key == "K2001" || key == "K2002" || key == "K2101" || key == "K2110" || key == "K2111" ||
           key == "K2022" || key == "K2142";
  }

  /// Sets a value field (K0002, K0004, K0014) of one value.
  void setValueField(DfqReadValue& v, const std::string& key, std::string_view value,
                     const std::string& field) {
    if (key == "K0002") {
      v.attribute = integer(value, field);
      if (v.attribute < 0) parseFail(field, "an attribute is 0 or more");
    } else if (key == "K0004") {
      v.time = std::string(trimmed(value));
    } else if (key == "K0014") {
      v.partId = std::string(trimmed(value));
    }
  }

  void field(std::string_view text) {
    // "Kxxxx[/i] value"
    std::size_t p = 5;
    std::string key(text.substr(0, 5));
    std::optional<int> index;
    if (p < text.size() && text[p] == '/') {
      std::size_t q = p + 1;
      while (q < text.size() && std::isdigit(static_cast<unsigned char>(text[q]))) ++q;
      if (q == p + 1) parseFail(key, "'/' must be followed by the index (" + key + "/1)");
      index = integer(text.substr(p + 1, q - p - 1), key);
      p = q;
    }
    if (p < text.size() && text[p] != ' ' && text[p] != '\t')
      parseFail(key, "a field is 'Kxxxx[/index] value' (one space before the value)");
    const std::string_view value = p < text.size() ? text.substr(p + 1) : std::string_view();
    const std::string field = key + (index ? "/" + std::to_string(*index) : std::string());
    const int i = index.value_or(1);
    const char group = key[1];
    if (key == "K0100") {
      const int n = integer(value, field);
      if (n < 1 || n > 100000) parseFail(field, "the number of characteristics must be 1 or more");
      if (!chars.empty() && chars.rbegin()->first > n)
        parseFail(field, "K0100 = " + std::to_string(n) + " but characteristic " +
                             std::to_string(chars.rbegin()->first) + " came before");
      count = n;
    } else if (group == '1') {
      if (i == 0) {
        allParts[key] = {std::string(trimmed(value)), line};
        return;
      }
      if (i < 1 || i > 100000) parseFail(field, "part index must be 1 or more");
      auto [it, added] = parts.try_emplace(i);
      if (added) {
        it->second.index = i;
        it->second.line = line;
      }
      currentPart = i;
      if (key == "K1001") it->second.number = std::string(trimmed(value));
      if (key == "K1002") it->second.description = std::string(trimmed(value));
    } else if (group == '2') {
      if (i == 0) {
        if (knownCharacteristicKey(key)) {
          DfqReadCharacteristic probe;  // checks the value now, names this line
          setCharacteristicField(probe, key, value, field);
          allCharacteristics[key] = {std::string(value), line};
        }
        return;
      }
      DfqReadCharacteristic& c = characteristic(i, field);
      if (c.line == 0) c.line = line;
      setCharacteristicField(c, key, value, field);
      ownKeys[i].insert(key);
    } else if (group == '0') {
      if (key == "K0001") {
        if (i == 0) parseFail(field, "a value belongs to one characteristic (K0001/1, K0001/2, ...)");
        DfqReadCharacteristic& c = characteristic(i, field);
        DfqReadValue v;
        v.line = line;
        if (!trimmed(value).empty()) v.value = number(value, field);
        c.values.push_back(std::move(v));
        const std::pair<int, std::size_t> at{i, c.values.size() - 1};
        // A new value set starts when this characteristic already has a value in the current one.
        bool again = false;
        for (const auto& s : lastSet) again = again || s.first == i;
        if (again) lastSet.clear();
        lastSet.push_back(at);
      } else if (key == "K0002" || key == "K0004" || key == "K0014") {
        if (i == 0) {
          if (lastSet.empty()) parseFail(field, "comes before any value");
          for (const auto& [ci, pos] : lastSet) setValueField(chars[ci].values[pos], key, value, field);
          return;
        }
        DfqReadCharacteristic& c = characteristic(i, field);
        if (c.values.empty())
          parseFail(field, "comes before the characteristic's first value (K0001/" + std::to_string(i) + ")");
        setValueField(c.values.back(), key, value, field);
      }
    }
  }

  void valueLine(std::string_view text) {
    const auto groups = splitAt(text, kCharSep8, kCharSepU);
    const int n = count.value_or(chars.empty() ? 0 : chars.rbegin()->first);
    if (n == 0)
      parseFail({},
                "a value line before K0100 or any characteristic; the file does not start like a DFQ file");
    if (static_cast<int>(groups.size()) > n)
      parseFail({}, "the value line has " + std::to_string(groups.size()) + " characteristics, the file " +
                        std::to_string(n) + " (K0100)");
    lastSet.clear();
    for (int i = 1; i <= n; ++i) {
      const std::string field = "K0001/" + std::to_string(i);
      DfqReadCharacteristic& c = characteristic(i, field);
      DfqReadValue v;
      v.line = line;
      if (i <= static_cast<int>(groups.size())) {
        const auto parts = splitAt(groups[static_cast<std::size_t>(i - 1)], kFieldSep8, kFieldSepU);
        if (!trimmed(parts[0]).empty()) v.value = number(parts[0], field);
        if (parts.size() > 1 && !trimmed(parts[1]).empty())
          setValueField(v, "K0002", parts[1], "K0002/" + std::to_string(i));
        if (parts.size() > 2) v.time = std::string(trimmed(parts[2]));
      }
      c.values.push_back(std::move(v));
      lastSet.emplace_back(i, c.values.size() - 1);
    }
  }

  void finish() {
    if (!count && chars.empty())
      throw ParseError(ErrorContext{source, 0, 0, "K2001"},
                       "has no characteristic (no K0100 and no K2xxx field)");
    const int n = count.value_or(chars.rbegin()->first);
    for (int i = 1; i <= n; ++i) {
      DfqReadCharacteristic& c = chars.try_emplace(i).first->second;
      c.index = i;
      for (const auto& [key, v] : allCharacteristics) {
        if (ownKeys[i].count(key)) continue;
        line = v.second;
        setCharacteristicField(c, key, v.first, key + "/0");
      }
      if (c.number.empty()) c.number = std::to_string(i);
      if (c.lowerLimit && c.upperLimit && !(*c.lowerLimit < *c.upperLimit)) {
        const auto at = lowerLimitLine.find(i);
        throw ValidationError(ErrorContext{source, at != lowerLimitLine.end() ? at->second : c.line, 0,
                                           "K2110/" + std::to_string(i)},
                              "lower limit " + metrofit::number(*c.lowerLimit) +
                                  " is not below the upper limit (K2111) " + metrofit::number(*c.upperLimit));
      }
      if (!parts.count(c.part)) {
        DfqReadPart& p = parts[c.part];
        p.index = c.part;
      }
      file.characteristics.push_back(std::move(c));
    }
    for (auto& [i, p] : parts) {
      if (p.number.empty() && allParts.count("K1001"))
        p.number = std::string(trimmed(allParts["K1001"].first));
      if (p.description.empty() && allParts.count("K1002"))
        p.description = std::string(trimmed(allParts["K1002"].first));
      file.parts.push_back(p);
    }
  }
};

bool isFieldLine(std::string_view t) {
  if (t.size() < 5 || t[0] != 'K') return false;
  for (std::size_t k = 1; k < 5; ++k)
    if (!std::isdigit(static_cast<unsigned char>(t[k]))) return false;
  return t.size() == 5 || t[5] == '/' || t[5] == ' ' || t[5] == '\t';
}

}  // namespace

std::string DfqReadCharacteristic::title() const {
  return description.empty() ? number : number + " (" + description + ")";
}

std::size_t DfqFile::measuredParts() const {
  std::size_t n = 0;
  for (const auto& c : characteristics) n = std::max(n, c.values.size());
  return n;
}

bool looksLikeDfq(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string_view t =
        trimmed(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    if (!t.empty()) return isFieldLine(t);
    if (nl == std::string_view::npos) break;
    pos = nl + 1;
  }
  return false;
}

DfqFile dfqFromText(std::string_view raw, const std::string& source) {
  if (raw.substr(0, 2) == "\xFF\xFE" || raw.substr(0, 2) == "\xFE\xFF")
    throw ParseError(ErrorContext{source, 1, 0, {}},
                     "is UTF-16; save the DFQ file as UTF-8 or ANSI (Windows-1252)");
  if (raw.find('\0') != std::string_view::npos)
    throw ParseError(ErrorContext{source, 1, 0, {}}, "is a binary file (NUL bytes), not a DFQ text file");
  Reader r;
  r.source = source;
  r.file.source = source;
  const std::string text = textAsUtf8(raw, &r.file.eightBit);
  std::size_t pos = 0;
  bool any = false;
  while (pos <= text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view t(text.data() + pos, (nl == std::string::npos ? text.size() : nl) - pos);
    pos = nl == std::string::npos ? text.size() + 1 : nl + 1;
    ++r.line;
    while (!t.empty() && t.back() == '\r') t.remove_suffix(1);
    if (trimmed(t).empty()) continue;
    if (isFieldLine(t)) {
      r.field(t);
      any = true;
    } else {
      if (!any) r.parseFail({}, "does not start with a K field (e.g. K0100); not a DFQ file");
      r.valueLine(t);
    }
  }
  r.finish();
  return std::move(r.file);
}

DfqFile readDfqFile(const std::string& path) {
  return dfqFromText(readFile(path, 256u << 20), displayPath(path));
}

std::vector<DfqPart> dfqParts(const DfqFile& file) {
  std::vector<DfqPart> out;
  for (const DfqReadPart& p : file.parts) {
    DfqPart part;
    part.number = p.number;
    part.description = p.description;
    for (const DfqReadCharacteristic& c : file.characteristics) {
      if (c.part != p.index) continue;
      DfqCharacteristic d;
      d.number = c.number;
      d.description = c.description;
      d.nominal = c.nominal;
      d.lowerLimit = c.lowerLimit;
      d.upperLimit = c.upperLimit;
      d.unit = c.unit;
      bool allTimes = true;
      for (const DfqReadValue& v : c.values) {
        if (!v.valid()) continue;
        d.values.push_back(*v.value);
        d.times.push_back(v.time);
        allTimes = allTimes && !v.time.empty();
      }
      if (!allTimes) d.times.clear();
      part.characteristics.push_back(std::move(d));
    }
    out.push_back(std::move(part));
  }
  return out;
}

std::size_t chooseCharacteristic(const std::vector<std::pair<std::string, std::string>>& list,
                                 const std::string& choice, const std::string& source,
                                 const std::string& field) {
  const auto title = [&list](std::size_t k) {
    const auto& [n, d] = list[k];
    // Without a description of its own, its place in the file tells equal numbers apart.
    return "'" + n + "'" +
           (d.empty() || d == n ? " (no. " + std::to_string(k + 1) + " in the file)" : " (" + d + ")");
  };
  const auto all = [&](const std::vector<std::size_t>& which) {
    std::string out;
    for (std::size_t k : which) out += (out.empty() ? "" : ", ") + title(k);
    return out;
  };
  std::vector<std::size_t> every(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) every[k] = k;
  if (list.empty())
    throw ValidationError(ErrorContext{source, 0, 0, field}, "the file has no characteristic");
  const std::string want(trimmed(choice));
  if (want.empty()) {
    if (list.size() == 1) return 0;
    throw ValidationError(ErrorContext{source, 0, 0, field},
                          "is required: the file has " + std::to_string(list.size()) +
                              " characteristics; choose one by number or name: " + all(every));
  }
  const auto lower = [](std::string_view s) {
    std::string o(trimmed(s));
    for (char& ch : o) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return o;
  };
  std::vector<std::size_t> found;
  const auto pick = [&](int which, bool folded) {
    found.clear();
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string& s = which == 0 ? list[k].first : list[k].second;
      if (folded ? lower(s) == lower(want) : s == want) found.push_back(k);
    }
    return !found.empty();
  };
  const bool byNumber = pick(0, false);
  if (byNumber || pick(1, false) || pick(1, true)) {
    if (found.size() == 1) return found.front();
    throw ValidationError(ErrorContext{source, 0, 0, field},
                          "'" + want + "' is ambiguous: it names " + std::to_string(found.size()) +
                              " characteristics: " + all(found) +
                              (byNumber ? "; choose one by its description" : "; choose one by its number"));
  }
  throw ValidationError(ErrorContext{source, 0, 0, field},
                        "no characteristic '" + want + "' (by number or name); the file has: " + all(every));
}

}  // namespace metrofit
