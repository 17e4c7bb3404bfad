#pragma once
// CSV reader and writer following CONTRACT.md "Input files":
// UTF-8 (a UTF-8 BOM is accepted), comma separated, one header row, `#` comment lines allowed
// before the header, `\n` or `\r\n` line ends, `.` as the decimal point, RFC 4180 quoting
// ("a ""quoted"", field" and line breaks inside quotes). Blank lines are skipped.
//
// Every malformed input gives a ParseError whose message names the file, the physical line and
// the field (column) and says what is wrong: UTF-16 / binary / invalid UTF-8 content, an
// unterminated quote, text after a closing quote, a stray quote, a ragged row, an empty or
// duplicate header name, a semicolon-separated file, a field longer than kMaxFieldBytes.
// Numbers are parsed strictly (whole field, finite, '.' decimal): number() names line and column.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace metrofit {

class CsvTable {
 public:
  static constexpr std::size_t kMaxFieldBytes = 64 * 1024;

  const std::string& source() const { return source_; }
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::string>& comments() const { return comments_; }  ///< '#' lines, without '#'
  std::size_t rowCount() const { return rows_.size(); }
  std::size_t columnCount() const { return header_.size(); }

  /// Column index by exact name, or -1.
  int columnIndex(std::string_view name) const;
  /// Column index, or ValidationError "file: missing column 'x' (the file has: a, b, c)".
  std::size_t requireColumn(std::string_view name) const;
  /// ValidationError unless there are at least n data rows.
  void requireRows(std::size_t n) const;

  const std::string& cell(std::size_t row, std::size_t col) const { return rows_[row][col]; }
  /// Physical line (1-based) where data row `row` starts.
  long lineOf(std::size_t row) const { return lines_[row]; }
  /// Strict finite number, or ParseError "file:line:col: field 'name': 'abc' is not a number".
  double number(std::size_t row, std::size_t col) const;
  std::vector<double> numericColumn(std::size_t col) const;
  std::vector<double> numericColumn(std::string_view name) const {
    return numericColumn(requireColumn(name));
  }

  /// Throws ParseError at a cell (for readers that validate cell content themselves).
  [[noreturn]] void failAt(std::size_t row, std::size_t col, const std::string& what) const;

 private:
  friend CsvTable parseCsv(std::string_view, const std::string&);
  std::string source_;
  std::vector<std::string> comments_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<long> lines_;
};

/// Parses CSV text; `source` names the file in error messages.
CsvTable parseCsv(std::string_view text, const std::string& source);
/// Reads and parses a CSV file (FileError if it cannot be read).
CsvTable readCsvFile(const std::string& path);

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
