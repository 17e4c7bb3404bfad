#pragma once
// CSV reader and writer following docs/file-formats.md#input-files:
// UTF-8 (a UTF-8 BOM is accepted), comma separated, one header row, `#` comment lines allowed
// before the header, `\n` or `\r\n` line ends, `.` as the decimal point, RFC 4180 quoting
// ("a ""quoted"", field" and line breaks inside quotes). Blank lines are skipped.
//
// Dialects (docs/file-formats.md#csv-dialects-and-standard-input: every reader takes --delimiter /
// --decimal): the delimiter may be ',', ';' or a tab and the decimal separator '.' or ','. CsvDialect's zero
// members mean "detect" (the default):
//   * delimiter: the one of ',', ';', tab that occurs most often (outside quotes) in the header
//     line, ',' on a tie or when none occurs; so "time_min;T1;disp_z_um" is read as ';'-separated,
//     as German and Polish spreadsheets and CMM exports write it;
//   * decimal: '.' in a ','-separated file (a decimal comma would split the field); otherwise the
//     form most data cells use among those that are numbers in exactly one of the two forms
//     ("20,5" is ',' and "20.5" is '.'; "1.234,5" and "12" decide nothing), '.' when there is
//     none, and a ParseError naming a cell of each form on a tie.
// With decimal ',' a number must not contain '.' (no thousands separators); number() says so.
// CsvReadOptions::columnMap renames the file's own columns to the role names the readers look for
// (docs/file-formats.md#own-data-in-a-project), so every reader built on CsvTable takes mapped files.
//
// Every malformed input gives a ParseError whose message names the file, the physical line and
// the field (column) and says what is wrong: UTF-16 / binary / invalid UTF-8 content, an
// unterminated quote, text after a closing quote, a stray quote, a ragged row, an empty or
// duplicate header name, a semicolon-separated file, a field longer than kMaxFieldBytes.
// Numbers are parsed strictly (whole field, finite, '.' decimal): number() names line and column.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace metrofit {

/// Delimiter and decimal separator of a CSV file; 0 = detect (see the header comment).
struct CsvDialect {
  char delimiter = 0;  ///< ',', ';', '\t' or 0
  char decimal = 0;    ///< '.', ',' or 0
  bool operator==(const CsvDialect&) const = default;
};

/// "auto" -> 0, "," (or "comma"), ";" ("semicolon"), "tab" (or a tab character) -> the character.
/// OptionsError naming `option` for anything else.
char parseCsvDelimiter(std::string_view text, const std::string& option = "--delimiter");
/// "auto" -> 0, "." (or "point"), "," (or "comma") -> the character; OptionsError otherwise.
char parseCsvDecimal(std::string_view text, const std::string& option = "--decimal");
/// The option spelling of a delimiter / decimal character: "auto", ",", ";", "tab", ".".
std::string csvDelimiterName(char delimiter);
std::string csvDecimalName(char decimal);

/// How to read one CSV file: its dialect and the mapping of roles to the file's own columns.
struct CsvReadOptions {
  CsvDialect dialect;
  /// (role, column): the file's column `column` is read as `role` (e.g. {"time_min", "Zeit"}).
  std::vector<std::pair<std::string, std::string>> columnMap;
  /// Thermal logs without a time column: the rows are this many minutes apart, the first at 0
  /// (0: the log must have a time column). Other readers ignore it.
  double sampleIntervalMin = 0.0;
  /// Lines before the column-name row, skipped whatever they hold (an instrument's preamble);
  /// -1: detect: blank lines and comment lines before the header are skipped, and so are title lines
  /// above the header when the header is not the first row (detectCsvPreamble: the header is the
  /// first row whose fields are mostly names above a row of as many fields, mostly numbers).
  int headerLines = -1;
  /// What starts a comment line before the header; empty: "#".
  std::string commentPrefix;
  /// Rows that cannot be read (a wrong number of fields, or a cell that is not a number in a column
  /// whose other cells mostly are) are left out and listed in CsvTable::skippedRows() instead of
  /// being an error; false (the default): the first such row is an error.
  bool skipBadRows = false;
  bool operator==(const CsvReadOptions&) const = default;
};

/// One row that cannot be read: where and why.
struct CsvRowProblem {
  long line = 0;        ///< physical line (1-based)
  std::size_t row = 0;  ///< data row (1-based, counting every row after the header)
  std::string column;   ///< the file's column name (empty: the whole row)
  std::string why;      ///< e.g. "'abc' is not a number"
  bool operator==(const CsvRowProblem&) const = default;
};
/// "line 7 (row 5), column 'T1': 'abc' is not a number".
std::string describeRowProblem(const CsvRowProblem& problem);

/// Parses "ROLE=COLUMN" (split at the first '='); OptionsError naming `option` when either side is
/// empty.
std::pair<std::string, std::string> parseColumnMapping(std::string_view text,
                                                       const std::string& option = "--map");

class CsvTable {
 public:
  static constexpr std::size_t kMaxFieldBytes = 64 * 1024;

  /// A table built by another reader (a report turned into columns): numbers as '.'-decimal text,
  /// `lines[r]` the physical line of the file that row r comes from. Rows must have one cell per
  /// header name and the names must be unique (std::invalid_argument otherwise: a bug of the caller).
  static CsvTable fromCells(std::string source, std::vector<std::string> header,
                            std::vector<std::vector<std::string>> rows, std::vector<long> lines);

  const std::string& source() const { return source_; }
  const std::vector<std::string>& header() const { return header_; }
  /// '#' lines without '#', and the title lines a detected header skipped (CsvReadOptions::headerLines).
  const std::vector<std::string>& comments() const { return comments_; }
  std::size_t rowCount() const { return rows_.size(); }
  std::size_t columnCount() const { return header_.size(); }
  /// The dialect the file was read with (detection resolved: both members are set).
  const CsvDialect& dialect() const { return dialect_; }
  /// Physical line (1-based) of the column-name row.
  long headerLineNumber() const { return headerLine_; }
  /// Rows left out because CsvReadOptions::skipBadRows was set (empty otherwise).
  const std::vector<CsvRowProblem>& skippedRows() const { return skipped_; }

  /// Renames the file's column `column` to `role` for every (role, column) pair. ValidationError
  /// naming the file and the role when `column` is not in the header, or when `role` already names
  /// another column of the file (that column would be hidden), or two roles name one column.
  /// Units (core/io/units.h): when the column names a unit in a trailing bracket ("Soll [µm]",
  /// "Zeit [s]") and the role has another unit of the same quantity ("nominal_mm", "time_min"), the
  /// column's numbers are read in the role's unit (number() converts); a unit of another quantity
  /// ("T1 [°C]" as "nominal_mm") is a ValidationError naming both.
  void mapColumns(const std::vector<std::pair<std::string, std::string>>& columnMap);
  /// The factor number() applies to column `col` (1 unless mapColumns converts its unit).
  double unitScale(std::size_t col) const { return col < scale_.size() ? scale_[col] : 1.0; }

  /// Column index by exact name, or -1.
  int columnIndex(std::string_view name) const;
  /// Column index, or ValidationError "file: missing column 'x' (the file has: a, b, c)".
  std::size_t requireColumn(std::string_view name) const;
  /// ValidationError unless there are at least n data rows.
  void requireRows(std::size_t n) const;

  const std::string& cell(std::size_t row, std::size_t col) const { return rows_[row][col]; }
  /// Physical line (1-based) where data row `row` starts.
  long lineOf(std::size_t row) const { return lines_[row]; }
  /// Strict finite number in the file's decimal form, or ParseError
  /// "file:line:col: field 'name': 'abc' is not a number".
  /// In the unit of the role the column is mapped to (unitScale).
  double number(std::size_t row, std::size_t col) const;
  std::vector<double> numericColumn(std::size_t col) const;
  std::vector<double> numericColumn(std::string_view name) const {
    return numericColumn(requireColumn(name));
  }

  /// Throws ParseError at a cell (for readers that validate cell content themselves).
  [[noreturn]] void failAt(std::size_t row, std::size_t col, const std::string& what) const;

 private:
  friend CsvTable parseCsv(std::string_view, const std::string&, const CsvReadOptions&);
  char detectDecimal() const;
  /// CsvReadOptions::skipBadRows: moves the rows with a non-number in a numeric column to skipped_.
  void dropUnreadableRows(const std::vector<std::size_t>& rowNumbers);
  bool isNumber(std::size_t row, std::size_t col) const;
  double numberAsWritten(std::size_t row, std::size_t col) const;
  std::string source_;
  std::vector<double> scale_;  ///< per column; empty: all 1
  CsvDialect dialect_{',', '.'};
  std::vector<std::string> comments_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<long> lines_;
  long headerLine_ = 0;
  std::vector<CsvRowProblem> skipped_;
};

/// The lines before the header that CsvReadOptions::headerLines = -1 skips beyond comments and blank
/// lines: 0 when the first row that is not blank or a comment is the header, else the 0-based line of
/// the first row whose fields (split at the given delimiter, or the line's own most frequent of ',', ';',
/// tab) are at least two, mostly not numbers, and whose next row has as many fields, mostly numbers in
/// either decimal form. Only the first 60 such rows are looked at; none found: 0.
long detectCsvPreamble(std::string_view text, const CsvReadOptions& options);

/// Parses CSV text in the given dialect (detected where 0) and applies the column mapping;
/// `source` names the file in error messages.
CsvTable parseCsv(std::string_view text, const std::string& source, const CsvReadOptions& options = {});
/// Every row of the text that cannot be read (as CsvReadOptions::skipBadRows says), in file order;
/// errors that are not about a row (no header, a bad encoding) are thrown as by parseCsv.
std::vector<CsvRowProblem> csvRowProblems(std::string_view text, const std::string& source,
                                          const CsvReadOptions& options = {});
/// Reads and parses a CSV file (FileError if it cannot be read); "-" reads standard input
/// (readFile) and is named "<stdin>" in messages.
CsvTable readCsvFile(const std::string& path, const CsvReadOptions& options = {});

/// Parses a whole string as a finite double ('.' decimal, optional surrounding blanks).
/// Returns false for anything else (empty, trailing text, nan, inf, decimal comma).
bool parseNumber(std::string_view text, double* out);

/// Builds CSV text: quotes fields that need it, '\n' line ends.
class CsvWriter {
 public:
  void comment(std::string_view text);
  void row(const std::vector<std::string>& fields);
  /// Numbers with `precision` significant digits (shortest round-trip form when precision <= 0).
  static std::string formatNumber(double value, int precision = 0);
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace metrofit
