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
#include <string_view>
#include <utility>
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
  bool operator==(const DfqCharacteristic&) const = default;
};

struct DfqPart {
  std::string number;       ///< K1001
  std::string description;  ///< K1002
  std::vector<DfqCharacteristic> characteristics;
  bool operator==(const DfqPart&) const = default;
};

/// The DFQ text. ValidationError (field "dfq") without characteristics, for a characteristic without
/// values, a non-finite value or limit, lower limit not below upper, or times not one per value.
std::string writeDfq(const DfqPart& part);

/// An ISO 8601 date-time "YYYY-MM-DDTHH:MM:SS" (or with a space for T; seconds optional) as Q-DAS writes
/// it, "DD.MM.YYYY/HH:MM:SS"; nullopt when `iso` is not such a date-time.
std::optional<std::string> qdasDateTime(const std::string& iso);

/// A date-time as Q-DAS (K0004, "DD.MM.YYYY/HH:MM:SS") or Calypso's _hdr ("DD.MM.YYYY HH:MM:SS") write
/// it, seconds optional, as minutes since 1970-01-01 00:00 (the time zone as written); nullopt for
/// anything else.
std::optional<double> qdasMinutes(const std::string& dateTime);

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

// ---- Reading (the AQDEF K-field and value-line forms) -----------------------------------------------
//
// dfqFromText reads a Q-DAS DFQ file (description and values in one file, AQDEF V12 "ASCII transfer
// format"), as CMM and SPC software write it:
//
//   * Lines end in CR LF or LF; empty lines are skipped. A line "Kxxxx[/i] value" is a field: the key
//     K and four digits, optionally "/" and an index, then one space (or tab) and the value (the rest
//     of the line, trailing blanks removed). Without an index a field is index 1 (AQDEF allows that
//     for files with one part / one characteristic).
//   * K0100 is the number of characteristics in the file. K1xxx/i are fields of part i: K1001 part
//     number, K1002 part description. K2xxx/i are fields of characteristic i (1-based, through the
//     whole file): K2001 number (as written, a text), K2002 description, K2101 nominal, K2110 lower and
//     K2111 upper specification limit (absolute values), K2022 decimals, K2142 unit. A characteristic
//     belongs to the part whose K1xxx fields came last before its first K2xxx field (part 1 when none
//     did): several parts per file.
//   * Index 0 ("K2142/0 mm", "K2022/0 3", "K0004/0 ...") means "for all": a K2xxx/0 field is the value
//     of every characteristic that does not give the field itself (before or after the /0 line); a
//     K1xxx/0 field that of every part; a K0xxx/0 field applies to the values of the measured part
//     read last (every characteristic's value in that value set).
//   * Values, K-field form: K0001/i a value of characteristic i, K0002/i its attribute, K0004/i its
//     date/time ("DD.MM.YYYY/HH:MM:SS", kept as written), K0014/i the part ident (serial number). The
//     n-th K0001/i is characteristic i's value of measured part n.
//   * Values, value-line form (the DFX lines; any line that does not start with a K field): one line
//     per measured part, the characteristics 1..K0100 in order separated by 0x14 ("¶", also written as
//     U+00B6 by converters to UTF-8), within one characteristic the fields value, attribute,
//     date/time, events, batch, nest, operator, machine, process parameter, gage separated by 0x0F
//     ("¤", U+00A4). Fields after the date/time are ignored; K0xxx fields after a value line
//     (e.g. "K0014/0 SN4711") apply to that line's values. An empty value field: not measured.
//   * Attribute rule (K0002): 0 (or none) is a valid value, and so is every attribute below 255 (the
//     lower attributes flag events such as an adjusted machine but keep the value). An attribute of
//     255 or more marks a value that is NOT valid (255: value disabled/removed, 256 and above: deleted
//     or otherwise invalidated): it is kept in `values` as read, with valid() false, and every series
//     Metrofit makes from the file (SPC, the setup report, the feature table) leaves it out.
//   * Numbers: '.' is the decimal mark (AQDEF); as AQDEF numbers have no digit grouping, a number with
//     a single ',' and no '.' ("12,5", as German Windows exporters write it) is read with ',' as the
//     decimal mark. Texts (K1002, K2002 ...) are never read as numbers: "Durchmesser 12,5" stays text.
//   * Encoding: UTF-8 (a BOM is accepted) when the file is valid UTF-8, else 8-bit Windows-1252 (which
//     includes ISO-8859-1's letters), converted to UTF-8; `eightBit` says which.
// Unknown K fields are skipped. Errors (ParseError / ValidationError) name the file, the line and the
// field: a field index above K0100, a value line with more characteristics than K0100, a number that
// is not one (or not finite), an attribute that is not an integer, K2110 not below K2111, a file
// without any characteristic, binary (NUL bytes) or UTF-16 content.

struct DfqReadValue {
  std::optional<double> value;  ///< K0001; empty: not measured (an empty field)
  int attribute = 0;            ///< K0002 (0 when absent)
  std::string time;             ///< K0004 as written ("DD.MM.YYYY/HH:MM:SS"), may be empty
  std::string partId;           ///< K0014, may be empty
  long line = 0;
  /// A value that counts: measured and its attribute below 255 (see the attribute rule above).
  bool valid() const { return value.has_value() && attribute < 255; }
};

struct DfqReadCharacteristic {
  int index = 0;            ///< i of K2xxx/i
  int part = 1;             ///< index of its part (K1xxx/part)
  std::string number;       ///< K2001 as written (the index when the file gives none)
  std::string description;  ///< K2002
  std::optional<double> nominal, lowerLimit, upperLimit;  ///< K2101, K2110, K2111 (absolute)
  std::optional<int> decimals;                            ///< K2022
  std::string unit;                                       ///< K2142
  std::vector<DfqReadValue> values;  ///< per measured part, in file order (invalid ones included)
  long line = 0;                     ///< the line of its first K2xxx field (0: none)
  /// "K2001 number" with the description in parentheses when it has one: `3 (Durchmesser 12,5)`.
  std::string title() const;
};

struct DfqReadPart {
  int index = 0;
  std::string number;       ///< K1001
  std::string description;  ///< K1002
  long line = 0;
};

struct DfqFile {
  std::string source;
  bool eightBit = false;  ///< read as Windows-1252 (else UTF-8)
  std::vector<DfqReadPart> parts;
  std::vector<DfqReadCharacteristic> characteristics;  ///< index 1..K0100 in order
  /// The number of measured parts (the longest value list).
  std::size_t measuredParts() const;
};

/// True when the text's first non-empty line is a K field ("K0100 3", "K1001/1 ...").
bool looksLikeDfq(std::string_view text);
/// Reads a DFQ file (see above); `source` names it in errors.
DfqFile dfqFromText(std::string_view text, const std::string& source);
DfqFile readDfqFile(const std::string& path);

/// The file's parts in the writer's form (writeDfq): per part its characteristics with their valid
/// values (and times, when every valid value has one). writeDfq(p) read back gives p again.
std::vector<DfqPart> dfqParts(const DfqFile& file);

/// The characteristic `choice` names (metrofit-cli --characteristic N|NAME): N is the number K2001 as
/// written, NAME the description K2002. A number is tried first, then a description (exactly, then
/// ignoring case and surrounding blanks). ValidationError naming `field` and `source` when it names
/// none (listing the characteristics) or several (listing the candidates); an empty choice is only
/// accepted when the file has one characteristic.
std::size_t chooseCharacteristic(const std::vector<std::pair<std::string, std::string>>& numberAndName,
                                 const std::string& choice, const std::string& source,
                                 const std::string& field = "--characteristic");

}  // namespace metrofit
