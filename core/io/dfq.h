#pragma once
// Q-DAS DFQ export (the AQDEF "ASCII transfer format" that SPC packages such as Q-DAS qs-STAT, and the
// open readers aqdefreader and qdas-parser on PyPI, import): one part with N characteristics and their
// measured values, in the K-field form, one field per line, "Kxxxx[/i] value" (the characteristic index
// i after a slash, 1-based; a single space before the value):
//
//   K0100 N                 number of characteristics in the file
//   K1001/1 part number     K1002/1 part description
//   K2001/i characteristic number      K2002/i characteristic description
//   K2101/i nominal   K2110/i lower specification limit   K2111/i upper specification limit
//   K2142/i unit (text, e.g. mm)
//   K0001/i value           K0004/i date/time of the value, DD.MM.YYYY/HH:MM:SS
//
// The description fields come first, then the values of measured part 1 (K0001/1, K0004/1, K0001/2, ...),
// part 2, ...; a characteristic with fewer values than another is left out of the later parts. Numbers
// are written with '.' and the shortest digits that read back to the same double. Text fields have no
// line breaks (replaced by spaces) and are cut to 255 bytes. Lines end in CR LF, as Windows SPC software
// writes them (readers also accept LF). Limits and nominal are optional (left out when unknown); K0004
// only when the values have times.
#include <optional>
#include <string>
#include <vector>

namespace metrofit {

class CsvTable;

struct DfqCharacteristic {
  std::string number;                                     ///< K2001
  std::string description;                                ///< K2002
  std::optional<double> nominal, lowerLimit, upperLimit;  ///< K2101, K2110, K2111
  std::string unit;                                       ///< K2142 (left out when empty)
  std::vector<double> values;                             ///< K0001
  std::vector<std::string> times;  ///< K0004, DD.MM.YYYY/HH:MM:SS; empty or one per value
};

struct DfqPart {
  std::string number;       ///< K1001
  std::string description;  ///< K1002
  std::vector<DfqCharacteristic> characteristics;
};

/// The DFQ text. ValidationError (field "dfq") without characteristics, for a characteristic without
/// values, a non-finite value or limit, lower limit not below upper, or times not one per value.
std::string writeDfq(const DfqPart& part);

/// An ISO 8601 date-time "YYYY-MM-DDTHH:MM:SS" (or with a space for T; seconds optional) as Q-DAS writes
/// it, "DD.MM.YYYY/HH:MM:SS"; nullopt when `iso` is not such a date-time.
std::optional<std::string> qdasDateTime(const std::string& iso);

/// The unit of a column from its name's suffix ("diameter_mm" -> "mm"; one of mm, um, deg, s, min, h,
/// ppm), ASCII; empty when the name has none.
std::string dfqColumnUnit(const std::string& column);

/// One measured feature series as a DFQ part, as `spc --dfq` writes it: one characteristic `column`
/// with `nominal`, the limits and the unit of its name (dfqColumnUnit), `values` in row order, and the
/// times from the table's `timestamp` column when it has one. `dataPath` is the file the table was read
/// from (its name goes into the descriptions), `partNumber` K1001 (empty: the file's name without its
/// extension). ParseError naming `source`, the line and "timestamp" for a time that is not a date-time.
DfqPart seriesDfqPart(const CsvTable& table, const std::string& column, const std::vector<double>& values,
                      std::optional<double> nominal, std::optional<double> lowerLimit,
                      std::optional<double> upperLimit, const std::string& dataPath,
                      const std::string& partNumber = {}, const std::string& source = {});

}  // namespace metrofit
