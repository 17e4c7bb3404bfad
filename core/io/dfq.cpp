#include "core/io/dfq.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"

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

}  // namespace metrofit
