#include "core/matching/hole_table.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/calypso.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/qif.h"
#include "core/matching/qif_points.h"

namespace metrofit {
namespace {

/// Printed values have three decimals: Meas - Nom - Err may differ by three half units.
constexpr double kErrTolerance = 0.0015 + 1e-9;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  // A UTF-8 byte order mark is not part of the first line.
  if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

/// Header column names: separated by two or more blanks (a name holds single spaces).
std::vector<std::string> splitHeader(const std::string& line) {
  std::vector<std::string> names;
  std::string current;
  int blanks = 0;
  for (char c : line) {
    if (c == ' ' || c == '\t') {
      blanks += c == '\t' ? 2 : 1;
      continue;
    }
    if (blanks >= 2 && !current.empty()) {
      names.push_back(current);
      current.clear();
    } else if (blanks == 1 && !current.empty()) {
      current += ' ';
    }
    blanks = 0;
    current += c;
  }
  if (!current.empty()) names.push_back(current);
  return names;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  std::string f;
  while (in >> f) fields.push_back(f);
  return fields;
}

bool isHeaderLine(const std::string& line) {
  return line.find("Meas X") != std::string::npos && line.find("Nom X") != std::string::npos;
}

std::string formatDiameter(double d) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.3f", d);
  return buf;
}

std::string formatMm(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace

bool looksLikeHoleTable(const std::string& text) {
  int seen = 0;
  for (const std::string& raw : splitLines(text)) {
    const std::string line = trim(raw);
    if (line.empty()) continue;
    if (isHeaderLine(line)) return true;
    if (line.rfind("id,", 0) == 0) return false;  // a CSV header of probe points (file-formats.md)
    if (++seen >= 50) break;
  }
  return false;
}

HoleTable holeTableFromText(const std::string& text, const std::string& source, std::size_t minPoints) {
  HoleTable table;
  ProbePointSet& set = table.points;
  set.source = source;
  set.planar = true;
  set.hasNormals = false;

  const std::vector<std::string> lines = splitLines(text);
  auto fail = [&](std::size_t lineIndex, long column, const std::string& field, const std::string& what) {
    throw ValidationError(ErrorContext{source, static_cast<long>(lineIndex + 1), column, field}, what);
  };

  // Preamble up to the column header.
  std::size_t i = 0;
  std::vector<std::string> header;
  for (; i < lines.size(); ++i) {
    const std::string line = trim(lines[i]);
    if (line.empty() || line[0] == '#') continue;
    if (isHeaderLine(line)) {
      header = splitHeader(line);
      ++i;
      break;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos || colon == 0) {
      throw ParseError(ErrorContext{source, static_cast<long>(i + 1), 0, {}},
                       "not a hole-table report: expected 'Key: value' lines and then a column header "
                       "with Meas X, Meas Y, Nom X, Nom Y, found '" +
                           line.substr(0, 60) + "'");
    }
    table.metadata[trim(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }
  if (header.empty()) {
    throw ParseError(ErrorContext{source, 0, 0, {}},
                     "no hole-table header (a line with the columns Meas X, Meas Y, Nom X, Nom Y)");
  }
  const std::size_t headerLine = i - 1;
  auto column = [&](const char* name) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return c;
    return std::nullopt;
  };
  auto require = [&](const char* name) {
    const auto c = column(name);
    if (!c)
      fail(headerLine, 0, name, "missing column (the header has Meas X, Meas Y, Nom X, Nom Y at least)");
    return *c;
  };
  const std::size_t measX = require("Meas X"), measY = require("Meas Y");
  const std::size_t nomX = require("Nom X"), nomY = require("Nom Y");
  const auto errX = column("Err X"), errY = column("Err Y");
  const auto measD = column("Meas D"), nomD = column("Nom D"), round = column("Round");

  std::map<std::pair<double, double>, std::size_t> nominalSeen;
  for (; i < lines.size(); ++i) {
    const std::string line = trim(lines[i]);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() != header.size()) {
      fail(i, 0, {},
           "has " + std::to_string(fields.size()) + " values, the header has " +
               std::to_string(header.size()) + " columns");
    }
    std::vector<double> v(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const char* s = fields[c].c_str();
      char* end = nullptr;
      errno = 0;
      v[c] = metrofit::num::strtodC(s, &end);
      if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v[c])) {
        throw ParseError(ErrorContext{source, static_cast<long>(i + 1), static_cast<long>(c + 1), header[c]},
                         "'" + fields[c] + "' is not a finite number");
      }
    }
    const std::size_t row = set.points.size();
    ProbePoint p;
    char id[16];
    metrofit::c_snprintf(id, sizeof id, "H%03zu", row + 1);
    p.id = id;
    p.nominal = {v[nomX], v[nomY], 0.0};
    p.measured = {v[measX], v[measY], 0.0};
    for (const auto& [err, meas, nom] : {std::array<std::optional<std::size_t>, 3>{errX, measX, nomX},
                                         std::array<std::optional<std::size_t>, 3>{errY, measY, nomY}}) {
      if (!err) continue;
      const double expected = v[*meas] - v[*nom];
      if (std::abs(v[*err] - expected) > kErrTolerance) {
        fail(i, static_cast<long>(*err + 1), header[*err],
             fields[*err] + " disagrees with " + header[*meas] + " - " + header[*nom] + " = " +
                 formatMm(expected) + " mm (columns shifted?)");
      }
    }
    for (const auto& d : {measD, nomD}) {
      if (d && !(v[*d] > 0.0))
        fail(i, static_cast<long>(*d + 1), header[*d], "a hole diameter must be > 0 mm");
    }
    if (round && v[*round] < 0.0)
      fail(i, static_cast<long>(*round + 1), header[*round], "roundness must not be negative");
    if (auto [it, fresh] = nominalSeen.emplace(std::make_pair(v[nomX], v[nomY]), i); !fresh) {
      fail(i, static_cast<long>(nomX + 1), header[nomX],
           "two holes at the same nominal position (" + fields[nomX] + ", " + fields[nomY] +
               "), first on line " + std::to_string(it->second + 1));
    }
    p.surface = nomD ? "hole D" + formatDiameter(v[*nomD]) : std::string("hole");
    if (measD) table.measuredDiameterMm.push_back(v[*measD]);
    if (nomD) table.nominalDiameterMm.push_back(v[*nomD]);
    set.points.push_back(std::move(p));
  }
  if (set.points.size() < minPoints) {
    throw ValidationError(ErrorContext{source, 0, 0, {}}, "has " + std::to_string(set.points.size()) +
                                                              " holes, at least " +
                                                              std::to_string(minPoints) + " needed");
  }
  return table;
}

HoleTable readHoleTable(const std::string& path, std::size_t minPoints) {
  return holeTableFromText(readFile(path), displayPath(path), minPoints);
}

ProbePointSet probePointsFromCmmReport(const CmmTextReport& report, std::size_t minPoints) {
  if (report.runs.size() != 1) {
    throw ValidationError(
        ErrorContext{report.source, report.runs.size() > 1 ? report.runs[1].line : 0, 0, {}},
        "the report has " + std::to_string(report.runs.size()) +
            " runs; probe points are read from a report of one run");
  }
  const bool pcdmis = report.format == CmmReportFormat::PcDmis;
  ProbePointSet set;
  set.source = report.source;
  int withZ = 0;
  const CmmFeature* firstWithoutZ = nullptr;
  const CmmFeature* firstWithZ = nullptr;
  std::map<std::string, long> ids;
  for (const CmmFeature& f : report.runs.front().features) {
    if (pcdmis && f.type.rfind("LOCATION", 0) != 0) continue;
    const auto axis = [&](const char* a) {
      const CmmValue* v = f.value(pcdmis ? std::string(a) : std::string(a) + " Location");
      return v && v->nominal ? v : nullptr;
    };
    const CmmValue *x = axis("X"), *y = axis("Y"), *z = axis("Z");
    if (!x || !y) continue;
    ProbePoint p;
    p.id = pcdmis || !f.label.empty() ? f.label : "step" + std::to_string(f.step);
    if (const auto [it, fresh] = ids.emplace(p.id, f.line); !fresh) {
      if (pcdmis)
        throw ValidationError(
            ErrorContext{report.source, f.line, 0, p.id},
            "duplicate point id '" + p.id + "' (first on line " + std::to_string(it->second) + ")");
      p.id += "@step" + std::to_string(f.step);
      ids.emplace(p.id, f.line);
    }
    std::string type = f.featureType;
    for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    p.surface = type.empty() ? std::string("feature") : type;
    const CmmValue* d = f.value(pcdmis ? "D" : "Diameter");
    if (d && d->nominal) p.surface += " D" + CsvWriter::formatNumber(*d->nominal, 6);
    p.nominal = {*x->nominal, *y->nominal, z ? *z->nominal : 0.0};
    p.measured = {x->actual, y->actual, z ? z->actual : 0.0};
    if (z) {
      ++withZ;
      if (!firstWithZ) firstWithZ = &f;
    } else if (!firstWithoutZ) {
      firstWithoutZ = &f;
    }
    set.points.push_back(std::move(p));
  }
  if (withZ > 0 && firstWithoutZ) {
    throw ValidationError(ErrorContext{report.source, firstWithoutZ->line, 0, firstWithoutZ->label},
                          "this feature has no Z but others have one (first on line " +
                              std::to_string(firstWithZ->line) +
                              "); probe points are either all planar or all 3-D");
  }
  set.planar = withZ == 0;
  set.hasNormals = false;
  if (set.points.size() < minPoints) {
    throw ValidationError(ErrorContext{report.source, 0, 0, {}},
                          "has " + std::to_string(set.points.size()) +
                              " features with a nominal and actual X and Y location, at least " +
                              std::to_string(minPoints) + " needed");
  }
  return set;
}

ProbePointSet readProbePointsAnyFormat(const std::string& path, std::size_t minPoints,
                                       const CsvReadOptions& csv, int part) {
  const std::string text = readFile(path);
  if (looksLikeQif(text)) {
    const QifFile file = qifFromText(text, displayPath(path));
    const std::size_t index = qifPartIndex(file, part);
    ProbePointSet set = qifProbePoints(file, index);
    if (set.points.size() < minPoints)
      throw ValidationError(
          ErrorContext{set.source, 0, 0, {}},
          "part " + std::to_string(index + 1) + " has " + std::to_string(set.points.size()) +
              " measured features with a location, at least " + std::to_string(minPoints) + " needed");
    return set;
  }
  if (looksLikeHoleTable(text)) return holeTableFromText(text, displayPath(path), minPoints).points;
  if (looksLikeCalypsoFeatures(text))
    return probePointsFromCsv(calypsoFeaturesProbeTable(text, displayPath(path)), minPoints);
  if (looksLikeCmmTextReport(text))
    return probePointsFromCmmReport(cmmTextReportFromText(text, displayPath(path)), minPoints);
  return probePointsFromCsv(parseCsv(text, displayPath(path), csv), minPoints);
}

}  // namespace metrofit
