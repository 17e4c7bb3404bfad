#pragma once
// A thermal log (docs/file-formats.md#thermal-log): a time column (time_s, time_min or time_h), then
// sensor columns and the target column(s). Time is kept in minutes internally. A log without a
// time column is read when the sampling interval is given (CsvReadOptions::sampleIntervalMin, the
// CLI's --sample-interval 15s): row i is at i times the interval.
#include <string>
#include <string_view>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {
class CsvTable;

struct ThermalChannel {
  std::string name;            ///< column name as in the file, e.g. "T1", "disp_z_um"
  std::string unit;            ///< from the name suffix ("_um", "_degC", "_rpm") or a trailing bracket
                               ///< ("[µm]", "[°C]", "[1/min]"; a displacement in "[mm]" or "[nm]" is
                               ///< read in µm: unit "um", values converted), else ""
  std::vector<double> values;  ///< one per row
};

/// What a channel measures, guessed from its name and unit (for chart axes and defaults).
enum class ChannelKind { Temperature, Displacement, Strain, Speed, Other };
ChannelKind channelKind(const ThermalChannel& c);

struct ThermalLog {
  std::string source;              ///< file name for messages
  std::string timeColumn;          ///< "time_s", "time_min" or "time_h" as in the file ("time_min"
                                   ///< when the time comes from a sampling interval)
  double sampleIntervalMin = 0.0;  ///< > 0: the file had no time column, rows this far apart
  std::vector<double> timeMin;     ///< time in minutes, strictly increasing
  std::vector<ThermalChannel> channels;

  std::size_t rows() const { return timeMin.size(); }
  /// Index of a channel by name, or -1.
  int indexOf(const std::string& name) const;
  /// The channel or a ValidationError naming the log and the missing column.
  const ThermalChannel& channel(const std::string& name) const;
};

/// Reads a thermal log from a parsed CSV table: finds the time column, requires strictly
/// increasing time, at least `minRows` rows, finite numbers everywhere (errors name file, line, column).
/// Without a time column the rows are `sampleIntervalMin` apart (> 0), else that is an error; a
/// time column together with an interval is an error too (which one is meant is not clear).
ThermalLog thermalLogFromCsv(const CsvTable& table, std::size_t minRows = 3, double sampleIntervalMin = 0.0);
/// Reads and validates a thermal log file.
ThermalLog readThermalLog(const std::string& path, std::size_t minRows = 3, const CsvReadOptions& csv = {});
/// Parses a sampling interval "<value><unit>" (unit s, min or h; blanks allowed between them,
/// e.g. "15s", "0.5 min", "1h") into minutes; an OptionsError naming `option` when it is not a
/// positive finite number with one of those units.
double parseSampleInterval(std::string_view text, const std::string& option = "--sample-interval");
/// Serialises a thermal log as CSV (time column as in `timeColumn`, 6 significant decimals).
std::string thermalLogToCsv(const ThermalLog& log);

}  // namespace metrofit
