#pragma once
// A thermal log (docs/file-formats.md#thermal-log): a time column (time_s, time_min or time_h), then
// sensor columns and the target column(s). Time is kept in minutes internally. A log without a
// time column is read when the sampling interval is given (CsvReadOptions::sampleIntervalMin, the
// CLI's --sample-interval 15s): row i is at i times the interval.
//
// An MTConnect log (an SHDR adapter log or a Streams document, recognised by content: core/io/mtconnect.h)
// is read as its sample table: time_min from the first sample and one channel per numeric SAMPLE key,
// resampled every `sampleIntervalMin` (0: kMtconnectDefaultIntervalS) by holding the last observation at
// or before each grid time, with the Devices.xml beside the file when there is one. A cell without a value
// (before a key's first observation, while UNAVAILABLE) is NaN there (ThermalLog::gaps);
// selectThermalSeries leaves out the rows with a gap in a column it uses and counts them.
#include <string>
#include <string_view>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {
class CsvTable;
struct MtcSampleTable;

/// The grid of an MTConnect log read as a thermal log when no interval is given: one second (decision:
/// fine enough for any thermal time constant and for the spindle speed changes SHDR reports; a longer
/// one is a choice of the user: --sample-interval 10s).
inline constexpr double kMtconnectDefaultIntervalS = 1.0;
/// The grid step in seconds of an MTConnect log read with `sampleIntervalMin` (CsvReadOptions).
inline double mtconnectIntervalS(double sampleIntervalMin) {
  return sampleIntervalMin > 0.0 ? sampleIntervalMin * 60.0 : kMtconnectDefaultIntervalS;
}

struct ThermalChannel {
  std::string name;            ///< column name as in the file, e.g. "T1", "disp_z_um"
  std::string unit;            ///< from the name suffix ("_um", "_degC", "_rpm") or a trailing bracket
                               ///< ("[µm]", "[°C]", "[1/min]"; a displacement in "[mm]" or "[nm]" is
                               ///< read in µm: unit "um", values converted), else ""
  std::vector<double> values;  ///< one per row
};

/// True when the channel has a gap (NaN: no value in an MTConnect log, ThermalLog::gaps).
bool hasGaps(const ThermalChannel& c);

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
  /// True for a log whose channels may hold NaN for "no value" (an MTConnect log: before a key's first
  /// observation, while UNAVAILABLE); a CSV log never does.
  bool gaps = false;
  /// How the log was resampled, in words (an MTConnect log; empty for a CSV log).
  std::string resampling;

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
/// The thermal log of an MTConnect sample table (time_min from its grid, empty cells NaN, gaps true);
/// at least `minRows` rows.
ThermalLog thermalLogFromMtconnect(const MtcSampleTable& table, std::size_t minRows = 3);
/// Reads and validates a thermal log file: CSV, or an MTConnect log by content (see above).
ThermalLog readThermalLog(const std::string& path, std::size_t minRows = 3, const CsvReadOptions& csv = {});
/// Parses a sampling interval "<value><unit>" (unit s, min or h; blanks allowed between them,
/// e.g. "15s", "0.5 min", "1h") into minutes; an OptionsError naming `option` when it is not a
/// positive finite number with one of those units.
double parseSampleInterval(std::string_view text, const std::string& option = "--sample-interval");
/// Serialises a thermal log as CSV (time column as in `timeColumn`, 6 significant decimals; a gap is an
/// empty cell).
std::string thermalLogToCsv(const ThermalLog& log);

}  // namespace metrofit
