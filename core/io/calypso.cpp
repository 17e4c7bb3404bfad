#include "core/io/calypso.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/common/error.h"
#include "core/io/file_io.h"
#include "core/io/text_encoding.h"

namespace metrofit {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '"')) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string o(trimmed(s));
  for (char& c : o) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return o;
}

struct Table {
  std::string source;
  std::vector<std::string> header;  // lower case
  std::vector<std::vector<std::string>> rows;
  std::vector<long> lines;

  int column(std::string_view name) const {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return static_cast<int>(k);
    return -1;
  }
};

std::vector<std::string> splitCells(std::string_view line, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto at = line.find(sep, start);
    out.emplace_back(
        trimmed(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return out;
}

/// The first non-blank line's cell names (lower case); the separator it uses.
std::vector<std::string> headerNames(std::string_view text, char* sep = nullptr) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string_view line =
        text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    if (trimmed(line).empty()) continue;
    const char s = line.find('\t') != std::string_view::npos ? '\t' : ';';
    if (sep) *sep = s;
    auto names = splitCells(line, s);
    for (auto& n : names) n = lower(n);
    return names;
  }
  return {};
}

bool has(const std::vector<std::string>& names, std::string_view n) {
  return std::find(names.begin(), names.end(), n) != names.end();
}

Table readTable(std::string_view raw, const std::string& source) {
  if (raw.substr(0, 2) == "\xFF\xFE" || raw.substr(0, 2) == "\xFE\xFF")
    throw ParseError(ErrorContext{source, 1, 0, {}}, "is UTF-16; save the Calypso table as UTF-8 or ANSI");
  if (raw.find('\0') != std::string_view::npos)
    throw ParseError(ErrorContext{source, 1, 0, {}}, "is a binary file (NUL bytes), not a Calypso table");
  const std::string text = textAsUtf8(raw);
  Table t;
  t.source = source;
  char sep = '\t';
  std::size_t pos = 0;
  long line = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string_view l(text.data() + pos, (nl == std::string::npos ? text.size() : nl) - pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    ++line;
    if (trimmed(l).empty()) continue;
    if (t.header.empty()) {
      sep = l.find('\t') != std::string_view::npos ? '\t' : ';';
      t.header = splitCells(l, sep);
      for (auto& n : t.header) n = lower(n);
      continue;
    }
    auto cells = splitCells(l, sep);
    if (cells.size() > t.header.size()) {
      // Trailing empty cells (a tab at the end of a row) are no extra columns.
      while (cells.size() > t.header.size() && cells.back().empty()) cells.pop_back();
      if (cells.size() > t.header.size())
        throw ParseError(ErrorContext{source, line, static_cast<long>(t.header.size()) + 1, {}},
                         "the row has " + std::to_string(cells.size()) + " cells, the header " +
                             std::to_string(t.header.size()));
    }
    cells.resize(t.header.size());
    t.rows.push_back(std::move(cells));
    t.lines.push_back(line);
  }
  return t;
}

/// A number with a decimal point or a decimal comma; `digits` = the written decimals.
std::optional<double> number(const Table& t, std::size_t row, int col, bool required, int* digits = nullptr) {
  const std::string& name = t.header[static_cast<std::size_t>(col)];
  std::string s(trimmed(t.rows[row][static_cast<std::size_t>(col)]));
  if (s.empty()) {
    if (!required) return std::nullopt;
    throw ParseError(ErrorContext{t.source, t.lines[row], col + 1, name}, "a number is missing");
  }
  std::string p = s;
  const bool comma = p.find(',') != std::string::npos;
  if (comma && (p.find('.') != std::string::npos || std::count(p.begin(), p.end(), ',') > 1))
    throw ParseError(ErrorContext{t.source, t.lines[row], col + 1, name}, "'" + s + "' is not a number");
  if (comma) std::replace(p.begin(), p.end(), ',', '.');
  const char* first = p.data();
  const char* last = p.data() + p.size();
  if (*first == '+') ++first;
  double v = 0.0;
  const auto res = std::from_chars(first, last, v);
  if (res.ec != std::errc() || res.ptr != last || !std::isfinite(v))
    throw ParseError(ErrorContext{t.source, t.lines[row], col + 1, name}, "'" + s + "' is not a number");
  if (digits) {
    const auto dot = p.find('.');
    const auto e = p.find_first_of("eE");
    *digits =
        dot == std::string::npos ? 0 : static_cast<int>((e == std::string::npos ? p.size() : e) - dot - 1);
  }
  return v;
}

std::string cell(const Table& t, std::size_t row, int col) {
  return col < 0 ? std::string() : t.rows[row][static_cast<std::size_t>(col)];
}

int require(const Table& t, std::string_view name) {
  const int c = t.column(name);
  if (c < 0) {
    std::string names;
    for (const auto& h : t.header) names += (names.empty() ? "" : ", ") + h;
    throw ValidationError(ErrorContext{t.source, 1, 0, std::string(name)},
                          "missing column '" + std::string(name) + "' (the file has: " + names + ")");
  }
  return c;
}

std::string fmt(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

bool looksLikeCalypsoCharacteristics(std::string_view text) {
  const auto n = headerNames(text.substr(0, 64 * 1024));
  return has(n, "id") && has(n, "actual") && has(n, "nominal") && (has(n, "planid") || has(n, "partnb"));
}

bool looksLikeCalypsoFeatures(std::string_view text) {
  const auto n = headerNames(text.substr(0, 64 * 1024));
  return has(n, "x") && has(n, "y") && has(n, "z") && has(n, "x_nom") && has(n, "y_nom") && has(n, "z_nom");
}

bool looksLikeCalypsoHeader(std::string_view text) {
  const auto n = headerNames(text.substr(0, 64 * 1024));
  return has(n, "planid") && has(n, "partnb") && has(n, "date") && !has(n, "actual");
}

CalypsoCharacteristics calypsoCharacteristicsFromText(std::string_view text, const std::string& source) {
  const Table t = readTable(text, source);
  if (t.header.empty()) throw ParseError(ErrorContext{source, 1, 0, {}}, "is empty");
  const int cId = require(t, "id"), cActual = require(t, "actual"), cNominal = require(t, "nominal");
  const int cPlan = t.column("planid"), cPart = t.column("partnb"), cType = t.column("type"),
            cSymbol = t.column("idsymbol"), cUpper = t.column("uppertol"), cLower = t.column("lowertol"),
            cDev = t.column("deviation");
  CalypsoCharacteristics out;
  out.source = source;
  if (t.rows.empty()) throw ValidationError(ErrorContext{source, 2, 0, {}}, "has no characteristic rows");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CalypsoCharacteristic c;
    c.line = t.lines[r];
    c.planId = cell(t, r, cPlan);
    c.part = cell(t, r, cPart);
    c.id = cell(t, r, cId);
    c.type = cell(t, r, cType);
    c.idSymbol = cell(t, r, cSymbol);
    if (c.id.empty())
      throw ParseError(ErrorContext{source, c.line, cId + 1, "id"}, "the characteristic has no id");
    int digits = 0;
    c.actual = *number(t, r, cActual, true, &digits);
    c.rounding = 0.5 * std::pow(10.0, -digits);
    c.nominal = number(t, r, cNominal, false);
    int devDigits = 0;
    if (cUpper >= 0) c.upperTol = number(t, r, cUpper, false);
    if (cLower >= 0) c.lowerTol = number(t, r, cLower, false);
    if (cDev >= 0) c.deviation = number(t, r, cDev, false, &devDigits);
    if (c.upperTol && c.lowerTol && *c.lowerTol > *c.upperTol)
      throw ValidationError(ErrorContext{source, c.line, cLower + 1, "lowertol"},
                            "lower tolerance " + fmt(*c.lowerTol) + " is above the upper tolerance " +
                                fmt(*c.upperTol) + " of '" + c.id + "'");
    if (c.deviation && c.nominal) {
      const double slack = c.rounding + 0.5 * std::pow(10.0, -devDigits) + 1e-9;
      if (std::abs(*c.deviation - (c.actual - *c.nominal)) > slack + 1e-12 * std::abs(c.actual))
        throw ValidationError(
            ErrorContext{source, c.line, cDev + 1, "deviation"},
            "deviation " + fmt(*c.deviation) + " of '" + c.id +
                "' is not actual - nominal = " + fmt(std::round((c.actual - *c.nominal) * 1e9) / 1e9));
    }
    if (std::find(out.parts.begin(), out.parts.end(), c.part) == out.parts.end()) out.parts.push_back(c.part);
    out.rows.push_back(std::move(c));
  }
  out.dates.assign(out.parts.size(), std::string());
  return out;
}

std::vector<std::pair<std::string, std::string>> calypsoHeaderDates(std::string_view text,
                                                                    const std::string& source) {
  const Table t = readTable(text, source);
  const int cPart = t.column("partnb"), cDate = t.column("date"), cTime = t.column("time");
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    std::string d = cell(t, r, cDate);
    const std::string time = cell(t, r, cTime);
    if (!time.empty()) d += (d.empty() ? "" : " ") + time;
    out.emplace_back(cell(t, r, cPart), d);
  }
  return out;
}

CalypsoCharacteristics readCalypsoCharacteristics(const std::string& path) {
  CalypsoCharacteristics c = calypsoCharacteristicsFromText(readFile(path, 256u << 20), displayPath(path));
  namespace fs = std::filesystem;
  const std::string name = fs::path(path).filename().string();
  const std::string suffix = "_chr.txt";
  if (path != "-" && name.size() > suffix.size() &&
      lower(name.substr(name.size() - suffix.size())) == suffix) {
    const fs::path hdr =
        fs::path(path).parent_path() / (name.substr(0, name.size() - suffix.size()) + "_hdr.txt");
    std::error_code ec;
    if (fs::is_regular_file(hdr, ec)) {
      const std::string text = readFile(hdr.string(), 16u << 20);
      if (looksLikeCalypsoHeader(text)) {
        for (const auto& [part, date] : calypsoHeaderDates(text, displayPath(hdr.string()))) {
          for (std::size_t k = 0; k < c.parts.size(); ++k)
            if (c.parts[k] == part || (c.parts.size() == 1 && c.dates[k].empty())) c.dates[k] = date;
        }
      }
    }
  }
  return c;
}

CsvTable calypsoFeaturesProbeTable(std::string_view text, const std::string& source) {
  const Table t = readTable(text, source);
  const int cx = require(t, "x"), cy = require(t, "y"), cz = require(t, "z");
  const int qx = require(t, "x_nom"), qy = require(t, "y_nom"), qz = require(t, "z_nom");
  const int nx = t.column("nx"), ny = t.column("ny"), nz = t.column("nz");
  const int cId = t.column("id"), cType = t.column("type"), cPart = t.column("partnb");
  std::vector<std::size_t> rows;
  std::string firstPart;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string part = cell(t, r, cPart);
    if (rows.empty()) firstPart = part;
    if (part != firstPart)
      throw ValidationError(ErrorContext{source, t.lines[r], cPart + 1, "partnb"},
                            "the file has several measured parts ('" + firstPart + "', '" + part +
                                "'); probe points for a matching come from one part");
    rows.push_back(r);
  }
  bool normals = nx >= 0 && ny >= 0 && nz >= 0;
  std::vector<std::array<double, 3>> n(rows.size());
  if (normals) {
    for (std::size_t k = 0; k < rows.size() && normals; ++k) {
      const auto a = number(t, rows[k], nx, false), b = number(t, rows[k], ny, false),
                 c = number(t, rows[k], nz, false);
      if (!a || !b || !c) {
        normals = false;
        break;
      }
      const double len = std::sqrt(*a * *a + *b * *b + *c * *c);
      if (len < 1e-9) {
        normals = false;
        break;
      }
      n[k] = {*a / len, *b / len, *c / len};
    }
  }
  std::vector<std::string> header{"id", "surface", "qx", "qy", "qz"};
  if (normals) header.insert(header.end(), {"nx", "ny", "nz"});
  header.insert(header.end(), {"px", "py", "pz"});
  std::vector<std::vector<std::string>> cells;
  std::vector<long> lines;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t r = rows[k];
    std::string id = cell(t, r, cId);
    if (id.empty()) id = std::to_string(k + 1);
    std::vector<std::string> row{id, cell(t, r, cType)};
    for (int c : {qx, qy, qz}) row.push_back(fmt(*number(t, r, c, true)));
    if (normals)
      for (double v : n[k]) row.push_back(fmt(v));
    for (int c : {cx, cy, cz}) row.push_back(fmt(*number(t, r, c, true)));
    cells.push_back(std::move(row));
    lines.push_back(t.lines[r]);
  }
  return CsvTable::fromCells(source, std::move(header), std::move(cells), std::move(lines));
}

}  // namespace metrofit
