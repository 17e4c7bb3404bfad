#pragma once
// MTConnect data (ANSI/MTC1.4, www.mtconnect.org): the observations of an SHDR adapter log or an
// MTConnectStreams document, and the MTConnectDevices document that declares their data items, as a
// table of samples on a regular time grid (a thermal log, docs/file-formats.md#mtconnect-logs).
//
// SHDR (the Adapter Agent Protocol, cppagent README "Adapter Agent Protocol Version 2.0"):
//   timestamp|key|value|key|value...          one or more key/value pairs per line
//   timestamp|key|level|native_code|native_severity|qualifier|message   a condition
//   timestamp|key|native_code|text            a MESSAGE data item
//   timestamp|key|count|rate|v1 v2 ...         a TIME_SERIES data item
//   timestamp|@ASSET@|id|type|--multiline--ABCD ... --multiline--ABCD   an asset (skipped)
//   timestamp|@REMOVE_ASSET@|id, @REMOVE_ALL_ASSETS@|type              (skipped)
//   * command: value                          agent commands (skipped)
// A key is a DataItem's id, name or Source. Which form a line has is decided by the declared data item
// where a Devices document is given; without one, a pair whose value is a condition level (NORMAL,
// WARNING, FAULT) followed by four more fields is a condition, and so is UNAVAILABLE followed by four empty
// fields (`key|UNAVAILABLE||||`; `key|UNAVAILABLE|key2|value2|...` is an unavailable sample among pairs).
// Timestamps are ISO 8601 UTC
// (`2022-08-08T13:51:34.7167146Z`, any number of fractional digits; an offset +hh:mm is applied); they
// need not be in time order (logs of several adapter sessions overlap): observations are ordered by time,
// equal times in file order.
//
// Streams: every element under a ComponentStream's Samples, Events or Condition is an observation of
// its dataItemId (the key) at its timestamp; Samples are SAMPLE data items, Condition children
// (Normal, Warning, Fault, Unavailable) conditions.
//
// The sample table (mtconnectSampleTable): one column per key that is a SAMPLE with scalar numbers (with
// a Devices document: its category is SAMPLE; without one: every value that is not UNAVAILABLE or empty
// reads as one number; conditions are never columns, so a TEMPERATURE condition is not a temperature),
// named by the key as the log writes it. Rows lie on the grid t0, t0 + dt, ... up to the last sample
// observation, t0 the first one; the first column `time_min` is minutes from t0. The rule is a
// zero-order hold: a cell is the last observation of its key at or before the row's time; empty before
// the key's first observation and while its last observation is UNAVAILABLE (or empty).
//
// Errors are one line naming the file and line: a timestamp that is not one, a log without any sample
// observation, a multiline block that is not closed, XML that is not well formed.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {

struct MtcDataItem {
  std::string id, name, source;  ///< what an SHDR key may be
  std::string category;          ///< SAMPLE, EVENT or CONDITION
  std::string type, subType, units, representation;
  std::string component;  ///< the element name of the component that holds it (Linear, Rotary, ...)
  std::string device;     ///< the name of its Device
};

struct MtcDevices {
  std::string source;
  std::vector<MtcDataItem> items;
  /// The item whose id, name or Source is `key` (ids first), or nullptr.
  const MtcDataItem* find(std::string_view key) const;
};

/// True when the text is XML whose root element is MTConnectDevices / MTConnectStreams.
bool looksLikeMtconnectDevices(std::string_view text);
bool looksLikeMtconnectStreams(std::string_view text);
/// True when the first line that is not blank or a command (`*`) starts with an ISO 8601 date-time and a
/// `|`: an SHDR log.
bool looksLikeShdr(std::string_view text);
inline bool looksLikeMtconnectLog(std::string_view text) {
  return looksLikeShdr(text) || looksLikeMtconnectStreams(text);
}

MtcDevices mtconnectDevicesFromText(std::string_view text, const std::string& source);
MtcDevices readMtconnectDevices(const std::string& path);
/// The Devices document beside a log: a file named Devices.xml (any case) in the log's folder, when
/// there is one that reads as an MTConnectDevices document.
std::optional<std::string> devicesFileBeside(const std::string& logPath);

struct MtcObservation {
  double timeS = 0.0;  ///< seconds since 1970-01-01T00:00:00Z
  std::string key;
  std::string value;       ///< as written (trimmed); a condition: its level
  bool condition = false;  ///< a condition (never a column)
  bool sample = false;     ///< a Streams Samples element (category known from the document)
  long line = 0;
};

struct MtcLog {
  std::string source;
  std::vector<MtcObservation> observations;  ///< in file order
  std::size_t commands = 0, assets = 0;      ///< lines skipped: agent commands, asset blocks and removals
  bool streams = false;                      ///< read from a Streams document (categories known)
};

/// Parses ISO 8601 `YYYY-MM-DDThh:mm:ss[.f...][Z|+hh:mm|-hh:mm]` into seconds since the epoch (UTC).
std::optional<double> parseIsoTimestamp(std::string_view text);

/// `devices` (may be null) decides the form of each SHDR line's fields (see above).
MtcLog shdrFromText(std::string_view text, const std::string& source, const MtcDevices* devices = nullptr);
MtcLog mtconnectStreamsFromText(std::string_view text, const std::string& source);

struct MtcSampleTable {
  CsvTable table;                    ///< time_min, then one column per sample key (empty cells: no value)
  double startS = 0.0;               ///< t0, seconds since the epoch
  double intervalS = 0.0;            ///< the grid step
  std::vector<std::string> skipped;  ///< keys that are not scalar samples ("key: why")
  std::string rule;                  ///< the resampling rule in words, for results and reports
};

/// The samples of `log` on a grid `intervalS` apart (> 0), as above. `devices` may be null.
MtcSampleTable mtconnectSampleTable(const MtcLog& log, double intervalS, const MtcDevices* devices = nullptr);

/// Reads an SHDR log or a Streams document (by content) with the Devices.xml beside it (when there is
/// one) and resamples it: the thermal-log table of the file.
MtcSampleTable readMtconnectSampleTable(const std::string& path, double intervalS);

}  // namespace metrofit
