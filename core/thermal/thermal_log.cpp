#include "core/thermal/thermal_log.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/mtconnect.h"

namespace metrofit {
namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string unitOf(const std::string& name) {
  const auto us = name.rfind('_');
  if (us == std::string::npos || us + 1 >= name.size()) return {};
  const std::string u = lower(name.substr(us + 1));
  static const char* known[] = {"um",          "mm", "nm",       "degc", "c", "k",   "rpm", "ue",
                                "microstrain", "pm", "nm_per_m", "w",    "s", "min", "h"};
  for (const char* k : known) {
    if (u == k) return name.substr(us + 1);
  }
  return {};
}

/// The unit a column names in brackets at its end, as German and Polish spreadsheets and data loggers
/// write it ("Verlagerung K3 [µm]", "Temperatur T1 [°C]", "Drehzahl [1/min]", "Temperatura (°C)"):
/// the unit as core spells it and the factor to that unit ("[mm]" of a displacement: "um", 1000;
/// "[nm]": "um", 0.001). Empty when the name ends in no bracket or an unknown unit.
struct BracketUnit {
  std::string unit;
  double factor = 1.0;
};

bool isDisplacementName(const std::string& lowerName) {
  for (const char* w : {"disp", "verlagerung", "verschiebung", "auslenkung", "przemieszczenie", "przesuni",
                        "odkszta", "deformation", "delta", "ch"})
    if (lowerName.starts_with(w) || (std::string(w).size() > 3 && lowerName.find(w) != std::string::npos))
      return true;
  return false;
}

BracketUnit bracketUnit(const std::string& name) {
  std::string n = name;
  while (!n.empty() && std::isspace(static_cast<unsigned char>(n.back()))) n.pop_back();
  if (n.empty() || (n.back() != ']' && n.back() != ')')) return {};
  const char open = n.back() == ']' ? '[' : '(';
  const auto at = n.rfind(open);
  if (at == std::string::npos) return {};
  std::string u = n.substr(at + 1, n.size() - at - 2);
  u.erase(std::remove_if(u.begin(), u.end(), [](unsigned char c) { return std::isspace(c); }), u.end());
  const std::string l = lower(u);
  if (l == "\xc2\xb5m" || l == "\xce\xbcm" || l == "um" || l == "mym" || l == "mikron") return {"um", 1.0};
  if (l == "mm")
    return isDisplacementName(lower(n.substr(0, at))) ? BracketUnit{"um", 1000.0} : BracketUnit{"mm", 1.0};
  if (l == "nm") return {"um", 0.001};
  if (l == "\xc2\xb0"
           "c" ||
      l == "degc" || l == "grad" || l == "\xc2\xb0" || l == "c")
    return {"degC", 1.0};
  if (l == "k") return {"K", 1.0};
  if (l == "1/min" || l == "u/min" || l == "rpm" || l == "min-1" || l == "min^-1" || l == "obr/min" ||
      l == "min\xe2\x81\xbb\xc2\xb9")
    return {"rpm", 1.0};
  if (l == "\xc2\xb5\xce\xb5" || l == "ue" || l == "microstrain") return {"ue", 1.0};
  if (l == "w") return {"W", 1.0};
  return {};
}

}  // namespace

ChannelKind channelKind(const ThermalChannel& c) {
  const std::string u = lower(c.unit);
  const std::string n = lower(c.name);
  if (u == "degc" || u == "c" || u == "k") return ChannelKind::Temperature;
  if (u == "um" || u == "mm" || u == "nm") return ChannelKind::Displacement;
  if (u == "ue" || u == "microstrain" || u == "pm") return ChannelKind::Strain;
  if (u == "rpm") return ChannelKind::Speed;
  if (n.starts_with("disp") || n.starts_with("delta") || n.starts_with("ch"))
    return ChannelKind::Displacement;
  if (n.starts_with("fbg") || n.starts_with("strain") || n.starts_with("dehnung") || n.starts_with("odkszta"))
    return ChannelKind::Strain;
  // German and Polish names (Drehzahl / Prędkość obrotowa, Verlagerung / Przemieszczenie, Temperatur /
  // Temperatura), before the "t..." rule that would take "Drehzahl"'s neighbours for temperatures.
  if (n.find("drehzahl") != std::string::npos ||
      n.find("pr\xc4\x99"
             "dko\xc5\x9b\xc4\x87") != std::string::npos ||
      n.find("predkosc") != std::string::npos || n.find("obroty") != std::string::npos)
    return ChannelKind::Speed;
  if (isDisplacementName(n)) return ChannelKind::Displacement;
  if (n.starts_with("t") || n.find("temp") != std::string::npos) return ChannelKind::Temperature;
  if (n.find("rpm") != std::string::npos || n.find("speed") != std::string::npos) return ChannelKind::Speed;
  return ChannelKind::Other;
}

bool hasGaps(const ThermalChannel& c) {
  return std::any_of(c.values.begin(), c.values.end(), [](double v) { return std::isnan(v); });
}

int ThermalLog::indexOf(const std::string& name) const {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (channels[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const ThermalChannel& ThermalLog::channel(const std::string& name) const {
  const int i = indexOf(name);
  if (i < 0) {
    std::string have;
    for (const auto& c : channels) have += (have.empty() ? "" : ", ") + c.name;
    throw ValidationError(ErrorContext{source, 0, 0, name},
                          "no such column in the thermal log (it has: " + have + ")");
  }
  return channels[static_cast<std::size_t>(i)];
}

double parseSampleInterval(std::string_view text, const std::string& option) {
  std::string t(text);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
  std::size_t unitAt = t.size();
  while (unitAt > 0 && std::isalpha(static_cast<unsigned char>(t[unitAt - 1]))) --unitAt;
  const std::string unit = lower(t.substr(unitAt));
  std::string number = t.substr(0, unitAt);
  while (!number.empty() && std::isspace(static_cast<unsigned char>(number.back()))) number.pop_back();
  double value = 0.0;
  double toMin = 0.0;
  if (unit == "s") toMin = 1.0 / 60.0;
  if (unit == "min") toMin = 1.0;
  if (unit == "h") toMin = 60.0;
  if (toMin == 0.0 || !parseNumber(number, &value) || !std::isfinite(value) || value <= 0.0) {
    throw OptionsError(
        ErrorContext{{}, 0, 0, option},
        "'" + std::string(text) +
            "' is not a sampling interval: a positive number with a unit s, min or h, e.g. 15s");
  }
  return value * toMin;
}

ThermalLog thermalLogFromCsv(const CsvTable& table, std::size_t minRows, double sampleIntervalMin) {
  ThermalLog log;
  log.source = table.source();
  double scale = 0.0;
  int timeCol = -1;
  for (const auto& [name, s] :
       {std::pair<const char*, double>{"time_s", 1.0 / 60.0}, {"time_min", 1.0}, {"time_h", 60.0}}) {
    const int c = table.columnIndex(name);
    if (c < 0) continue;
    if (timeCol >= 0) {
      throw ValidationError(ErrorContext{table.source(), 0, 0, name},
                            "more than one time column; keep one of time_s, time_min, time_h");
    }
    timeCol = c;
    scale = s;
    log.timeColumn = name;
  }
  if (timeCol >= 0 && sampleIntervalMin > 0.0) {
    throw ValidationError(ErrorContext{table.source(), 0, 0, log.timeColumn},
                          "has a time column and a sampling interval was given (--sample-interval); "
                          "leave out one of them");
  }
  if (timeCol < 0 && !(sampleIntervalMin > 0.0)) {
    throw ValidationError(
        ErrorContext{table.source(), 0, 0, "time_s|time_min|time_h"},
        "no time column; the first column of a thermal log must be time_s, time_min or time_h, or give the "
        "sampling interval (--sample-interval 15s)");
  }
  if (table.columnCount() < (timeCol >= 0 ? 2u : 1u)) {
    throw ValidationError(ErrorContext{table.source(), 0, 0, {}},
                          "a thermal log needs sensor columns besides time");
  }
  table.requireRows(minRows);
  const std::size_t n = table.rowCount();
  log.timeMin.resize(n);
  if (timeCol < 0) {
    log.timeColumn = "time_min";
    log.sampleIntervalMin = sampleIntervalMin;
    for (std::size_t r = 0; r < n; ++r) log.timeMin[r] = static_cast<double>(r) * sampleIntervalMin;
  }
  for (std::size_t r = 0; timeCol >= 0 && r < n; ++r) {
    log.timeMin[r] = table.number(r, static_cast<std::size_t>(timeCol)) * scale;
    if (r > 0 && !(log.timeMin[r] > log.timeMin[r - 1])) {
      table.failAt(r, static_cast<std::size_t>(timeCol),
                   "time does not increase (" + table.cell(r, static_cast<std::size_t>(timeCol)) + " after " +
                       table.cell(r - 1, static_cast<std::size_t>(timeCol)) +
                       "); rows must be in strictly increasing time");
    }
  }
  for (std::size_t c = 0; c < table.columnCount(); ++c) {
    if (static_cast<int>(c) == timeCol) continue;
    ThermalChannel ch;
    ch.name = table.header()[c];
    ch.unit = unitOf(ch.name);
    ch.values = table.numericColumn(c);
    if (ch.unit.empty()) {
      // "Verlagerung K3 [mm]": read in µm like every displacement of the log (one axis, one unit).
      const BracketUnit b = bracketUnit(ch.name);
      ch.unit = b.unit;
      if (b.factor != 1.0)
        for (double& v : ch.values) v *= b.factor;
    }
    log.channels.push_back(std::move(ch));
  }
  return log;
}

ThermalLog thermalLogFromMtconnect(const MtcSampleTable& t, std::size_t minRows) {
  const CsvTable& table = t.table;
  ThermalLog log;
  log.source = table.source();
  log.timeColumn = "time_min";
  log.gaps = true;
  log.resampling = "zero-order hold, " + t.rule;
  table.requireRows(minRows);
  const std::size_t n = table.rowCount();
  log.timeMin.resize(n);
  // The grid itself, not its printed minutes (exactly r * interval).
  for (std::size_t r = 0; r < n; ++r) log.timeMin[r] = static_cast<double>(r) * t.intervalS / 60.0;
  for (std::size_t c = 1; c < table.columnCount(); ++c) {
    ThermalChannel ch;
    ch.name = table.header()[c];
    ch.unit = unitOf(ch.name);
    ch.values.resize(n);
    for (std::size_t r = 0; r < n; ++r) {
      const std::string& cell = table.cell(r, c);
      const auto v = cell.empty() ? std::nullopt : num::parseDouble(cell);
      ch.values[r] = v && std::isfinite(*v) ? *v : std::numeric_limits<double>::quiet_NaN();
    }
    log.channels.push_back(std::move(ch));
  }
  return log;
}

ThermalLog readThermalLog(const std::string& path, std::size_t minRows, const CsvReadOptions& csv) {
  const std::string text = readFile(path);
  if (looksLikeMtconnectLog(text))
    return thermalLogFromMtconnect(readMtconnectSampleTable(path, mtconnectIntervalS(csv.sampleIntervalMin)),
                                   minRows);
  return thermalLogFromCsv(parseCsv(text, displayPath(path), csv), minRows, csv.sampleIntervalMin);
}

std::string thermalLogToCsv(const ThermalLog& log) {
  CsvWriter w;
  std::vector<std::string> header{log.timeColumn.empty() ? "time_min" : log.timeColumn};
  for (const auto& c : log.channels) header.push_back(c.name);
  w.row(header);
  const double toCol = header[0] == "time_s" ? 60.0 : header[0] == "time_h" ? 1.0 / 60.0 : 1.0;
  std::vector<std::string> row(header.size());
  for (std::size_t r = 0; r < log.rows(); ++r) {
    row[0] = CsvWriter::formatNumber(std::round(log.timeMin[r] * toCol * 1e6) / 1e6);
    for (std::size_t c = 0; c < log.channels.size(); ++c) {
      const double v = log.channels[c].values[r];
      row[c + 1] = std::isfinite(v) ? CsvWriter::formatNumber(std::round(v * 1e6) / 1e6) : std::string();
    }
    w.row(row);
  }
  return w.text();
}

}  // namespace metrofit
