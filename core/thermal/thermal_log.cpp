#include "core/thermal/thermal_log.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/common/error.h"
#include "core/io/csv.h"

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
  if (n.starts_with("fbg") || n.starts_with("strain")) return ChannelKind::Strain;
  if (n.starts_with("t") || n.find("temp") != std::string::npos) return ChannelKind::Temperature;
  if (n.find("rpm") != std::string::npos || n.find("speed") != std::string::npos) return ChannelKind::Speed;
  return ChannelKind::Other;
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
    log.channels.push_back(std::move(ch));
  }
  return log;
}

ThermalLog readThermalLog(const std::string& path, std::size_t minRows, const CsvReadOptions& csv) {
  return thermalLogFromCsv(readCsvFile(path, csv), minRows, csv.sampleIntervalMin);
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
      row[c + 1] = CsvWriter::formatNumber(std::round(log.channels[c].values[r] * 1e6) / 1e6);
    }
    w.row(row);
  }
  return w.text();
}

}  // namespace metrofit
