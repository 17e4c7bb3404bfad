#include "core/io/csv.h"
#include "core/io/units.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_set>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/file_io.h"

namespace metrofit {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trimBlanks(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char buf[8];
      metrofit::c_snprintf(buf, sizeof buf, "\\x%02X", u);
      out += buf;
    } else {
      out += c;
    }
  }
  if (s.size() > 40) out += "...";
  return out;
}

/// Length of the valid UTF-8 sequence starting at s[i], or 0 if invalid.
std::size_t utf8Length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF)
    n = 2;
  else if (c >= 0xE0 && c <= 0xEF)
    n = 3;
  else if (c >= 0xF0 && c <= 0xF4)
    n = 4;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto cc = static_cast<unsigned char>(s[i + k]);
    if ((cc & 0xC0) != 0x80) return 0;
  }
  const auto c1 = static_cast<unsigned char>(s[i + 1]);
  if (c == 0xE0 && c1 < 0xA0) return 0;  // overlong
  if (c == 0xED && c1 > 0x9F) return 0;  // surrogates
  if (c == 0xF0 && c1 < 0x90) return 0;  // overlong
  if (c == 0xF4 && c1 > 0x8F) return 0;  // > U+10FFFF
  return n;
}

/// A record as split by the tokenizer: fields, the line it starts on, the line/column of each field.
struct Record {
  std::vector<std::string> fields;
  long line = 0;
  bool isComment = false;
  bool isBlank = false;
};

class Tokenizer {
 public:
  Tokenizer(std::string_view text, const std::string& source, char delimiter, std::string_view commentPrefix,
            std::size_t start, long firstLine)
      : t_(text),
        source_(source),
        delimiter_(delimiter),
        prefix_(commentPrefix),
        pos_(start),
        line_(firstLine) {}

  bool done() const { return pos_ >= t_.size(); }
  /// The last error was about the file (binary data, bad encoding), not about one row.
  bool fatal() const { return fatal_; }
  /// After a row-level error: continues at the next line.
  void skipRestOfLine() {
    if (pos_ >= t_.size()) return;
    const std::size_t nl = t_.find('\n', pos_);
    pos_ = nl == std::string_view::npos ? t_.size() : nl + 1;
    ++line_;
  }

  Record next() {
    Record rec;
    rec.line = line_;
    std::string field;
    bool quoted = false;      // this field started with a quote
    bool afterQuote = false;  // the closing quote of this field was seen
    bool anyContent = false;  // anything but blanks on this record
    long col = 1;             // 1-based field index
    long quoteLine = line_;
    auto fail = [&](const std::string& what) -> void {
      throw ParseError(ErrorContext{source_, line_, col, {}}, what);
    };
    auto failFile = [&](const std::string& what) -> void {
      fatal_ = true;
      throw ParseError(ErrorContext{source_, line_, col, {}}, what);
    };
    auto endField = [&]() {
      if (quoted) {
        rec.fields.push_back(std::move(field));
      } else {
        rec.fields.emplace_back(trimBlanks(field));
      }
      field.clear();
      quoted = false;
      afterQuote = false;
      ++col;
    };
    bool inQuotes = false;
    while (pos_ < t_.size()) {
      const char c = t_[pos_];
      const auto u = static_cast<unsigned char>(c);
      if (u == 0) failFile("binary data (a NUL byte); this is not a CSV text file");
      if (u >= 0x80) {
        const std::size_t n = utf8Length(t_, pos_);
        if (n == 0) {
          if (t_.find('\0') != std::string_view::npos)  // e.g. a PNG: 0x89 before the first NUL
            failFile("binary data (not UTF-8, NUL bytes in the file); this is not a CSV text file");
          char buf[64];
          metrofit::c_snprintf(buf, sizeof buf, "invalid UTF-8 byte 0x%02X; save the file as UTF-8", u);
          failFile(buf);
        }
        if (afterQuote) fail("text after the closing quote of a quoted field");
        field.append(t_.substr(pos_, n));
        anyContent = true;
        pos_ += n;
        continue;
      }
      if (inQuotes) {
        if (c == '"') {
          if (pos_ + 1 < t_.size() && t_[pos_ + 1] == '"') {
            field += '"';
            pos_ += 2;
            continue;
          }
          inQuotes = false;
          afterQuote = true;
          ++pos_;
          continue;
        }
        if (c == '\n') ++line_;
        if (c != '\r' || pos_ + 1 >= t_.size() || t_[pos_ + 1] != '\n') field += c;
        ++pos_;
        if (field.size() > CsvTable::kMaxFieldBytes) fail(tooLong());
        continue;
      }
      if (c == '\r' && pos_ + 1 < t_.size() && t_[pos_ + 1] == '\n') {
        ++pos_;
        continue;
      }
      if (c == '\n' || c == '\r') {
        ++pos_;
        ++line_;
        break;
      }
      if (!anyContent && rec.fields.empty() && field.empty() && !seenHeader_ &&
          t_.substr(pos_).starts_with(prefix_)) {
        // Comment line: up to the end of the line.
        const std::size_t end = t_.find('\n', pos_);
        const std::size_t from = pos_ + prefix_.size();
        std::string_view body = t_.substr(from, (end == std::string_view::npos ? t_.size() : end) - from);
        if (!body.empty() && body.back() == '\r') body.remove_suffix(1);
        for (std::size_t i = 0; i < body.size(); ++i) {
          const auto b = static_cast<unsigned char>(body[i]);
          if (b == 0) failFile("binary data (a NUL byte); this is not a CSV text file");
          if (b >= 0x80) {
            const std::size_t n = utf8Length(body, i);
            if (n == 0) failFile("invalid UTF-8 in a comment line; save the file as UTF-8");
            i += n - 1;
          }
        }
        rec.isComment = true;
        rec.fields.emplace_back(body);
        pos_ = end == std::string_view::npos ? t_.size() : end + 1;
        ++line_;
        return rec;
      }
      if (c == delimiter_) {
        endField();
        anyContent = true;
        ++pos_;
        continue;
      }
      if (c == '"') {
        if (afterQuote) fail("text after the closing quote of a quoted field");
        if (!trimBlanks(field).empty())
          fail("a quote inside an unquoted field; quote the whole field and double inner quotes");
        field.clear();
        quoted = true;
        inQuotes = true;
        quoteLine = line_;
        anyContent = true;
        ++pos_;
        continue;
      }
      if (afterQuote) {
        if (isBlank(c)) {
          ++pos_;
          continue;
        }
        fail("text after the closing quote of a quoted field");
      }
      if (!isBlank(c)) anyContent = true;
      field += c;
      if (field.size() > CsvTable::kMaxFieldBytes) fail(tooLong());
      ++pos_;
    }
    if (inQuotes) {
      throw ParseError(ErrorContext{source_, quoteLine, col, {}},
                       "unterminated quoted field (the closing quote is missing)");
    }
    if (!anyContent && rec.fields.empty()) {
      rec.isBlank = true;
      return rec;
    }
    endField();
    return rec;
  }

  void headerSeen() { seenHeader_ = true; }

 private:
  static std::string tooLong() {
    return "field longer than " + std::to_string(CsvTable::kMaxFieldBytes / 1024) +
           " KiB; is this a CSV file?";
  }
  std::string_view t_;
  const std::string& source_;
  char delimiter_;
  std::string_view prefix_;
  std::size_t pos_ = 0;
  long line_ = 1;
  bool seenHeader_ = false;
  bool fatal_ = false;
};

/// The first line that is neither blank nor a '#' comment (the header), without its line end.
std::string_view headerLine(std::string_view text, std::string_view commentPrefix) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    std::string_view line =
        text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? text.size() : end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view body = trimBlanks(line);
    if (body.empty() || body.starts_with(commentPrefix)) continue;
    return line;
  }
  return {};
}

/// The delimiter of the header line: the most frequent of ',', ';', tab outside quotes (',' wins
/// ties and is the answer when none occurs).
char detectDelimiter(std::string_view text, std::string_view commentPrefix) {
  const std::string_view header = headerLine(text, commentPrefix);
  std::size_t comma = 0, semicolon = 0, tab = 0;
  bool inQuotes = false;
  for (char c : header) {
    if (c == '"') inQuotes = !inQuotes;
    if (inQuotes) continue;
    comma += c == ',';
    semicolon += c == ';';
    tab += c == '\t';
  }
  if (semicolon > comma && semicolon >= tab) return ';';
  if (tab > comma && tab > semicolon) return '\t';
  return ',';
}

/// True when `s` is a number written with `sep` as its one decimal separator:
/// [+-] digits* sep digits+ [(e|E) [+-] digits+] with at least one digit before or after sep.
bool isDecimalForm(std::string_view s, char sep) {
  s = trimBlanks(s);
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t intStart = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  const bool intDigits = i > intStart;
  if (i >= s.size() || s[i] != sep) return false;
  ++i;
  const std::size_t fracStart = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  if (!intDigits && i == fracStart) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t expStart = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == expStart) return false;
  }
  return i == s.size();
}

/// A cell that reads as a number in either decimal form ("12", "-0.5", "3,25", "1e-3"): the test the
/// header detection uses to tell a row of values from a row of names.
bool looksNumeric(std::string_view s) {
  s = trimBlanks(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = trimBlanks(s.substr(1, s.size() - 2));
  if (s.empty()) return false;
  std::string t(s);
  if (t.find(',') != std::string::npos) {
    if (t.find('.') != std::string::npos || t.find(',') != t.rfind(',')) return false;
    t[t.find(',')] = '.';
  }
  double v = 0.0;
  const char* b = t.data();
  if (*b == '+') ++b;
  const auto [ptr, ec] = std::from_chars(b, t.data() + t.size(), v);
  return ec == std::errc() && ptr == t.data() + t.size();
}

/// The fields of one physical line split at `delimiter` outside double quotes (no unquoting: enough
/// to count fields and look at their form).
std::vector<std::string_view> splitLine(std::string_view line, char delimiter) {
  std::vector<std::string_view> fields;
  bool inQuotes = false;
  std::size_t from = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') inQuotes = !inQuotes;
    if (!inQuotes && line[i] == delimiter) {
      fields.push_back(line.substr(from, i - from));
      from = i + 1;
    }
  }
  fields.push_back(line.substr(from));
  return fields;
}

char lineDelimiter(std::string_view line) {
  std::size_t comma = 0, semicolon = 0, tab = 0;
  bool inQuotes = false;
  for (char c : line) {
    if (c == '"') inQuotes = !inQuotes;
    if (inQuotes) continue;
    comma += c == ',';
    semicolon += c == ';';
    tab += c == '\t';
  }
  if (semicolon > comma && semicolon >= tab) return ';';
  if (tab > comma && tab > semicolon) return '\t';
  return ',';
}

}  // namespace

long detectCsvPreamble(std::string_view text, const CsvReadOptions& options) {
  const std::string_view prefix =
      options.commentPrefix.empty() ? std::string_view("#") : options.commentPrefix;
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  struct Line {
    long index;  // 0-based physical line
    std::string_view text;
  };
  // The first lines that are neither blank nor comments (a header far down is not looked for).
  constexpr std::size_t kLookAhead = 60;
  std::vector<Line> lines;
  std::size_t pos = 0;
  long index = 0;
  while (pos < text.size() && lines.size() < kLookAhead) {
    const std::size_t end = text.find('\n', pos);
    std::string_view line =
        text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? text.size() : end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view body = trimBlanks(line);
    if (!body.empty() && !body.starts_with(prefix)) lines.push_back({index, line});
    ++index;
  }
  if (lines.size() < 2) return 0;
  // The header is the first row whose fields are names above rows of numbers: at least two fields,
  // most of them not numbers, and the next row has as many fields, most of them numbers.
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    const char d = options.dialect.delimiter ? options.dialect.delimiter : lineDelimiter(lines[i].text);
    const auto names = splitLine(lines[i].text, d);
    if (names.size() < 2) continue;
    std::size_t nameCount = 0;
    for (std::string_view f : names) nameCount += !looksNumeric(f) && !trimBlanks(f).empty();
    if (2 * nameCount <= names.size()) continue;
    const auto values = splitLine(lines[i + 1].text, d);
    if (values.size() != names.size()) continue;
    std::size_t numberCount = 0;
    for (std::string_view f : values) numberCount += looksNumeric(f);
    if (2 * numberCount <= values.size()) continue;
    // The first row of the file is the header: the reader's own rule (comments and blank lines
    // before it skipped) gives the same; otherwise skip every line above it.
    return i == 0 ? 0 : lines[i].index;
  }
  return 0;
}

char parseCsvDelimiter(std::string_view text, const std::string& option) {
  if (text == "auto") return 0;
  if (text == "," || text == "comma") return ',';
  if (text == ";" || text == "semicolon") return ';';
  if (text == "tab" || text == "\t" || text == "\\t") return '\t';
  throw OptionsError(ErrorContext{{}, 0, 0, option},
                     "'" + printable(text) + "' is not a delimiter (use auto, ',', ';' or tab)");
}

char parseCsvDecimal(std::string_view text, const std::string& option) {
  if (text == "auto") return 0;
  if (text == "." || text == "point") return '.';
  if (text == "," || text == "comma") return ',';
  throw OptionsError(ErrorContext{{}, 0, 0, option},
                     "'" + printable(text) + "' is not a decimal separator (use auto, '.' or ',')");
}

std::string csvDelimiterName(char delimiter) {
  if (delimiter == 0) return "auto";
  if (delimiter == '\t') return "tab";
  return std::string(1, delimiter);
}

std::string csvDecimalName(char decimal) {
  return decimal == 0 ? std::string("auto") : std::string(1, decimal);
}

std::pair<std::string, std::string> parseColumnMapping(std::string_view text, const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || trimBlanks(text.substr(0, eq)).empty() ||
      trimBlanks(text.substr(eq + 1)).empty()) {
    throw OptionsError(ErrorContext{{}, 0, 0, option},
                       "'" + printable(text) + "' is not ROLE=COLUMN (e.g. time_min=Zeit)");
  }
  return {std::string(trimBlanks(text.substr(0, eq))), std::string(trimBlanks(text.substr(eq + 1)))};
}

bool parseNumber(std::string_view text, double* out) {
  text = trimBlanks(text);
  if (text.empty()) return false;
  if (text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  double v = 0.0;
  const auto* first = text.data();
  const auto* last = text.data() + text.size();
  const auto res = std::from_chars(first, last, v, std::chars_format::general);
  if (res.ec != std::errc() || res.ptr != last) return false;
  if (!std::isfinite(v)) return false;
  *out = v;
  return true;
}

CsvTable parseCsv(std::string_view text, const std::string& source, const CsvReadOptions& options) {
  CsvTable table;
  table.source_ = source;
  if (text.size() >= 2 &&
      ((static_cast<unsigned char>(text[0]) == 0xFF && static_cast<unsigned char>(text[1]) == 0xFE) ||
       (static_cast<unsigned char>(text[0]) == 0xFE && static_cast<unsigned char>(text[1]) == 0xFF))) {
    throw ParseError(ErrorContext{source, 1, 0, {}},
                     "the file is UTF-16 encoded; save it as UTF-8 (comma separated)");
  }
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (trimBlanks(text).empty() || text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw ParseError(ErrorContext{source, 0, 0, {}},
                     "the file is empty (expected a header row and data rows)");
  }

  const std::string_view prefix =
      options.commentPrefix.empty() ? std::string_view("#") : options.commentPrefix;
  // A preamble of header_lines lines is skipped whatever it holds; detected (-1): the title lines
  // above the first row of names over a row of numbers (detectCsvPreamble), kept as comments.
  std::size_t start = 0;
  long firstLine = 1;
  const long preamble = options.headerLines >= 0 ? options.headerLines : detectCsvPreamble(text, options);
  for (long k = 0; k < preamble && start < text.size(); ++k, ++firstLine) {
    const std::size_t nl = text.find('\n', start);
    if (options.headerLines < 0) {
      std::string_view line =
          text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
      line = trimBlanks(line);
      if (line.starts_with(prefix)) line = trimBlanks(line.substr(prefix.size()));
      if (!line.empty()) table.comments_.emplace_back(line);
    }
    start = nl == std::string_view::npos ? text.size() : nl + 1;
  }
  if (text.substr(start).find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw ParseError(ErrorContext{source, firstLine, 0, {}},
                     "no header row after the " + std::to_string(options.headerLines) +
                         " header lines skipped (is the header line count right?)");
  }
  const char delimiter =
      options.dialect.delimiter ? options.dialect.delimiter : detectDelimiter(text.substr(start), prefix);
  table.dialect_.delimiter = delimiter;
  Tokenizer tok(text, source, delimiter, prefix, start, firstLine);
  bool haveHeader = false;
  long headerLine = 0;
  std::vector<std::size_t> rowNumbers;  // data row number (1-based) of each kept row
  std::size_t dataRow = 0;              // data rows seen after the header, readable or not
  while (!tok.done()) {
    Record rec;
    try {
      rec = tok.next();
    } catch (const ParseError& e) {
      if (!options.skipBadRows || !haveHeader || tok.fatal()) throw;
      const long col = e.context().column;
      table.skipped_.push_back({e.context().line, ++dataRow,
                                col >= 1 && col <= static_cast<long>(table.header_.size())
                                    ? table.header_[static_cast<std::size_t>(col - 1)]
                                    : std::string(),
                                e.detail()});
      tok.skipRestOfLine();
      continue;
    }
    if (rec.isBlank) continue;
    if (rec.isComment) {
      table.comments_.push_back(std::move(rec.fields.front()));
      continue;
    }
    if (!haveHeader) {
      haveHeader = true;
      headerLine = rec.line;
      tok.headerSeen();
      std::unordered_set<std::string> seen;
      for (std::size_t i = 0; i < rec.fields.size(); ++i) {
        const std::string& name = rec.fields[i];
        ErrorContext at{source, rec.line, static_cast<long>(i + 1), {}};
        if (name.empty()) throw ParseError(at, "empty column name in the header row");
        if (!seen.insert(name).second)
          throw ParseError(at, "duplicate column name '" + printable(name) + "' in the header row");
      }
      if (rec.fields.size() == 1 && delimiter != ';' && rec.fields[0].find(';') != std::string::npos) {
        throw ParseError(ErrorContext{source, rec.line, 1, {}},
                         "the header is separated by ';' but the delimiter is '" +
                             csvDelimiterName(delimiter) + "' (read it with delimiter ';' or auto)");
      }
      if (rec.fields.size() == 1 && delimiter != '\t' && rec.fields[0].find('\t') != std::string::npos) {
        throw ParseError(ErrorContext{source, rec.line, 1, {}},
                         "the header is separated by tabs but the delimiter is '" +
                             csvDelimiterName(delimiter) + "' (read it with delimiter tab or auto)");
      }
      table.header_ = std::move(rec.fields);
      table.headerLine_ = headerLine;
      continue;
    }
    ++dataRow;
    if (rec.fields.size() != table.header_.size()) {
      const long col = static_cast<long>(std::min(rec.fields.size(), table.header_.size()) + 1);
      const std::string why = "row has " + std::to_string(rec.fields.size()) + " fields, the header (line " +
                              std::to_string(headerLine) + ") has " + std::to_string(table.header_.size());
      if (!options.skipBadRows) throw ParseError(ErrorContext{source, rec.line, col, {}}, why);
      table.skipped_.push_back({rec.line, dataRow, {}, why});
      continue;
    }
    table.rows_.push_back(std::move(rec.fields));
    table.lines_.push_back(rec.line);
    rowNumbers.push_back(dataRow);
  }
  if (!haveHeader) {
    throw ParseError(ErrorContext{source, 0, 0, {}},
                     "no header row (the file has only comments or blank lines)");
  }
  table.dialect_.decimal = options.dialect.decimal ? options.dialect.decimal : table.detectDecimal();
  if (options.skipBadRows) table.dropUnreadableRows(rowNumbers);
  table.mapColumns(options.columnMap);
  return table;
}

std::vector<CsvRowProblem> csvRowProblems(std::string_view text, const std::string& source,
                                          const CsvReadOptions& options) {
  CsvReadOptions o = options;
  o.skipBadRows = true;
  o.columnMap.clear();  // the problems name the file's own columns
  return parseCsv(text, source, o).skippedRows();
}

std::string describeRowProblem(const CsvRowProblem& p) {
  std::string out = "line " + std::to_string(p.line) + " (row " + std::to_string(p.row) + ")";
  if (!p.column.empty()) out += ", column '" + p.column + "'";
  return out + ": " + p.why;
}

void CsvTable::dropUnreadableRows(const std::vector<std::size_t>& rowNumbers) {
  // A column is numeric when more than half of its cells are numbers in the file's decimal form; a
  // row with a cell of a numeric column that is not a number (or is empty) cannot be read.
  const std::size_t rows = rows_.size();
  std::vector<bool> numeric(header_.size(), false);
  for (std::size_t c = 0; c < header_.size(); ++c) {
    std::size_t numbers = 0;
    for (std::size_t r = 0; r < rows; ++r) numbers += isNumber(r, c) ? 1 : 0;
    numeric[c] = 2 * numbers > rows;
  }
  std::vector<std::vector<std::string>> keptRows;
  std::vector<long> keptLines;
  for (std::size_t r = 0; r < rows; ++r) {
    bool bad = false;
    for (std::size_t c = 0; c < header_.size() && !bad; ++c) {
      if (!numeric[c] || isNumber(r, c)) continue;
      try {
        (void)number(r, c);
      } catch (const ParseError& e) {
        skipped_.push_back({lines_[r], rowNumbers[r], header_[c], e.detail()});
        bad = true;
      }
    }
    if (bad) continue;
    keptRows.push_back(std::move(rows_[r]));
    keptLines.push_back(lines_[r]);
  }
  rows_ = std::move(keptRows);
  lines_ = std::move(keptLines);
  std::stable_sort(skipped_.begin(), skipped_.end(),
                   [](const CsvRowProblem& a, const CsvRowProblem& b) { return a.line < b.line; });
}

bool CsvTable::isNumber(std::size_t row, std::size_t col) const {
  try {
    (void)number(row, col);
    return true;
  } catch (const ParseError&) {
    return false;
  }
}

CsvTable readCsvFile(const std::string& path, const CsvReadOptions& options) {
  return parseCsv(readFile(path), displayPath(path), options);
}

char CsvTable::detectDecimal() const {
  if (dialect_.delimiter == ',') return '.';
  std::size_t count[2] = {0, 0};  // '.', ','
  std::size_t firstRow[2] = {0, 0}, firstCol[2] = {0, 0};
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    for (std::size_t c = 0; c < rows_[r].size(); ++c) {
      for (int k = 0; k < 2; ++k) {
        if (!isDecimalForm(rows_[r][c], k == 0 ? '.' : ',')) continue;
        if (count[k]++ == 0) {
          firstRow[k] = r;
          firstCol[k] = c;
        }
      }
    }
  }
  if (count[1] > count[0]) return ',';
  if (count[0] > count[1] || count[0] == 0) return '.';
  const std::size_t later =
      firstRow[0] > firstRow[1] || (firstRow[0] == firstRow[1] && firstCol[0] > firstCol[1]);
  const std::size_t other = 1 - later;
  failAt(firstRow[later], firstCol[later],
         "'" + printable(rows_[firstRow[later]][firstCol[later]]) + "' uses '" + (later ? "," : ".") +
             "' as the decimal separator but line " + std::to_string(lines_[firstRow[other]]) + " uses '" +
             (other ? "," : ".") + "' equally often; give the decimal separator (decimal '.' or ',')");
}

void CsvTable::mapColumns(const std::vector<std::pair<std::string, std::string>>& columnMap) {
  std::vector<std::string> renamed = header_;
  std::vector<bool> mapped(header_.size(), false);
  for (const auto& [role, column] : columnMap) {
    const int from = columnIndex(column);
    if (from < 0) {
      std::string have;
      for (const auto& h : header_) have += (have.empty() ? "" : ", ") + h;
      throw ValidationError(
          ErrorContext{source_, 0, 0, role},
          "mapped to column '" + column + "', which the file does not have (it has: " + have + ")");
    }
    if (mapped[static_cast<std::size_t>(from)]) {
      throw ValidationError(
          ErrorContext{source_, 0, 0, role},
          "column '" + column + "' is already mapped to '" + renamed[static_cast<std::size_t>(from)] + "'");
    }
    const int clash = columnIndex(role);
    if (clash >= 0 && clash != from && !mapped[static_cast<std::size_t>(clash)]) {
      bool remapped = false;  // the clashing column is itself mapped to another role: fine
      for (const auto& [r2, c2] : columnMap) remapped |= c2 == role && r2 != role;
      if (!remapped) {
        throw ValidationError(ErrorContext{source_, 0, 0, role},
                              "the file already has a column '" + role + "'; mapping '" + column +
                                  "' to it would hide that column (map or rename it too)");
      }
    }
    const std::string fromUnit = columnNameUnit(column), toUnit = roleUnit(role);
    if (!fromUnit.empty() && !toUnit.empty() && fromUnit != toUnit) {
      const std::optional<double> factor = unitFactor(fromUnit, toUnit);
      if (!factor) {
        throw ValidationError(ErrorContext{source_, 0, 0, role},
                              "column '" + column + "' is in " + fromUnit + ", which cannot be read as " +
                                  toUnit + " (map a column in " + toUnit + " or a unit convertible to it)");
      }
      if (scale_.empty()) scale_.assign(header_.size(), 1.0);
      scale_[static_cast<std::size_t>(from)] = *factor;
    }
    renamed[static_cast<std::size_t>(from)] = role;
    mapped[static_cast<std::size_t>(from)] = true;
  }
  std::unordered_set<std::string> seen;
  for (const auto& name : renamed) {
    if (!seen.insert(name).second)
      throw ValidationError(ErrorContext{source_, 0, 0, name}, "two columns are mapped to this role");
  }
  header_ = std::move(renamed);
}

int CsvTable::columnIndex(std::string_view name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::size_t CsvTable::requireColumn(std::string_view name) const {
  const int i = columnIndex(name);
  if (i >= 0) return static_cast<std::size_t>(i);
  std::string have;
  for (const auto& h : header_) have += (have.empty() ? "" : ", ") + h;
  throw ValidationError(ErrorContext{source_, 0, 0, std::string(name)},
                        "missing column (the file has: " + have + ")");
}

void CsvTable::requireRows(std::size_t n) const {
  if (rows_.size() < n) {
    throw ValidationError(ErrorContext{source_, 0, 0, {}}, "has " + std::to_string(rows_.size()) +
                                                               " data row" + (rows_.size() == 1 ? "" : "s") +
                                                               ", at least " + std::to_string(n) + " needed");
  }
}

void CsvTable::failAt(std::size_t row, std::size_t col, const std::string& what) const {
  throw ParseError(ErrorContext{source_, lines_[row], static_cast<long>(col + 1), header_[col]}, what);
}

CsvTable CsvTable::fromCells(std::string source, std::vector<std::string> header,
                             std::vector<std::vector<std::string>> rows, std::vector<long> lines) {
  if (rows.size() != lines.size()) throw std::invalid_argument("CsvTable::fromCells: one line per row");
  for (std::size_t i = 0; i < header.size(); ++i)
    for (std::size_t j = i + 1; j < header.size(); ++j)
      if (header[i] == header[j])
        throw std::invalid_argument("CsvTable::fromCells: duplicate column '" + header[i] + "'");
  for (const auto& r : rows)
    if (r.size() != header.size()) throw std::invalid_argument("CsvTable::fromCells: ragged row");
  CsvTable t;
  t.source_ = std::move(source);
  t.dialect_ = CsvDialect{',', '.'};
  t.header_ = std::move(header);
  t.rows_ = std::move(rows);
  t.lines_ = std::move(lines);
  return t;
}

double CsvTable::number(std::size_t row, std::size_t col) const {
  const double v = numberAsWritten(row, col);
  return col < scale_.size() ? v * scale_[col] : v;
}

double CsvTable::numberAsWritten(std::size_t row, std::size_t col) const {
  double v = 0.0;
  const std::string& s = rows_[row][col];
  if (dialect_.decimal == ',') {
    if (s.find('.') == std::string::npos) {
      std::string t = s;
      std::replace(t.begin(), t.end(), ',', '.');
      if (parseNumber(t, &v)) return v;
    } else if (isDecimalForm(s, '.') || parseNumber(s, &v)) {
      failAt(row, col,
             "'" + printable(s) +
                 "' is not a number in this file: its decimal separator is ',' (read it with "
                 "decimal '.' if the file uses '.')");
    }
  } else if (parseNumber(s, &v)) {
    return v;
  }
  if (trimBlanks(s).empty()) failAt(row, col, "empty value where a number is expected");
  std::string low;
  for (char c : trimBlanks(s)) low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (low == "nan" || low == "-nan" || low == "inf" || low == "-inf" || low == "+inf" || low == "infinity" ||
      low == "-infinity") {
    failAt(row, col, "'" + printable(s) + "' is not a finite number");
  }
  if (dialect_.decimal == '.' && dialect_.delimiter != ',' && isDecimalForm(s, ',')) {
    failAt(row, col,
           "'" + printable(s) +
               "' is not a number in this file: its decimal separator is '.' (read it with "
               "decimal ',' if the file uses ',')");
  }
  if (dialect_.decimal == '.' && (s.find(',') != std::string::npos ||
                                  (s.find('.') == std::string::npos && s.find(';') != std::string::npos))) {
    failAt(row, col, "'" + printable(s) + "' is not a number (use '.' as the decimal point)");
  }
  failAt(row, col, "'" + printable(s) + "' is not a number");
}

std::vector<double> CsvTable::numericColumn(std::size_t col) const {
  std::vector<double> out(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) out[r] = number(r, col);
  return out;
}

void CsvWriter::comment(std::string_view text) {
  text_ += '#';
  if (!text.empty() && text.front() != ' ') text_ += ' ';
  text_.append(text);
  text_ += '\n';
}

void CsvWriter::row(const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) text_ += ',';
    const std::string& f = fields[i];
    const bool needsQuotes = f.find_first_of(",\"\r\n") != std::string::npos ||
                             (!f.empty() && (isBlank(f.front()) || isBlank(f.back()))) ||
                             (i == 0 && !f.empty() && f.front() == '#');
    if (!needsQuotes) {
      text_ += f;
      continue;
    }
    text_ += '"';
    for (char c : f) {
      if (c == '"') text_ += '"';
      text_ += c;
    }
    text_ += '"';
  }
  text_ += '\n';
}

std::string CsvWriter::formatNumber(double value, int precision) {
  char buf[64];
  if (precision <= 0) {
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, res.ptr);
  }
  const auto res = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, precision);
  return std::string(buf, res.ptr);
}

}  // namespace metrofit
