#include "core/io/cmm_text_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/calypso.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/io/qif.h"

namespace metrofit {
namespace {

constexpr double kInchMm = 25.4;

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && s.substr(0, prefix.size()) == prefix;
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && upper(a) == upper(b);
}

/// "Plane         Best Fit" -> "Plane Best Fit".
std::string collapseBlanks(std::string_view s) {
  std::string out;
  bool blank = false;
  for (char c : trim(s)) {
    if (c == ' ' || c == '\t') {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += c;
  }
  return out;
}

struct Token {
  std::string text;
  std::size_t column = 0;  ///< 0-based start
};

std::vector<Token> tokens(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    if (i >= s.size()) break;
    const std::size_t b = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    out.push_back({std::string(s.substr(b, i - b)), b});
  }
  return out;
}

/// A token meant as a number: starts with a sign, a digit or a decimal point.
bool numberLike(std::string_view t) {
  if (t.empty()) return false;
  const char c = t[0];
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return true;
  return (c == '+' || c == '-') && t.size() > 1 &&
         (std::isdigit(static_cast<unsigned char>(t[1])) || t[1] == '.');
}

/// An OGP value: OGP prints every number with its sign (names may start with a digit: "3D Straightness").
bool signedNumberLike(std::string_view t) {
  return t.size() > 1 && (t[0] == '+' || t[0] == '-') &&
         (std::isdigit(static_cast<unsigned char>(t[1])) || t[1] == '.');
}

/// Half a unit of the last printed digit of a number token.
double halfUnit(std::string_view t) {
  const auto dot = t.find('.');
  if (dot == std::string_view::npos) return 0.5;
  std::size_t digits = 0;
  for (std::size_t i = dot + 1; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) ++digits;
  return 0.5 * std::pow(10.0, -static_cast<double>(digits));
}

struct Line {
  long number = 0;
  std::string text;  ///< without the line end
};

/// Splits into lines (LF or CRLF); a control byte other than tab is binary content (ParseError).
std::vector<Line> splitLines(std::string_view text, const std::string& source) {
  std::vector<Line> out;
  std::size_t pos = 0;
  long n = 0;
  if (startsWith(text, "\xEF\xBB\xBF")) pos = 3;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view raw = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++n;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const auto u = static_cast<unsigned char>(raw[i]);
      if ((u < 0x20 && u != '\t') || u == 0x7f) {
        throw ParseError(ErrorContext{source, n, static_cast<long>(i + 1), {}},
                         std::string("binary data (control byte 0x") + "0123456789ABCDEF"[u >> 4] +
                             "0123456789ABCDEF"[u & 15] + "); this is not a text report");
      }
    }
    out.push_back({n, std::string(raw)});
  }
  return out;
}

double number(const Token& t, const std::string& source, long line, const std::string& what) {
  double v = 0.0;
  if (!parseNumber(t.text, &v)) {
    throw ParseError(ErrorContext{source, line, static_cast<long>(t.column + 1), what},
                     "'" + t.text + "' is not a number");
  }
  return v;
}

bool isAngleName(std::string_view name) {
  const std::string u = upper(name);
  return u.find("ANGLE") != std::string::npos || u == "ELEVATION";
}

std::string fmt(double v) {
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// The printed deviation must be `expected` within the rounding of the three printed numbers.
void checkDeviation(const CmmValue& v, double expected, double tolerance, const std::string& rule,
                    const std::string& source) {
  if (std::abs(*v.printedDeviation - expected) > tolerance + 1e-9) {
    throw ValidationError(ErrorContext{source, v.line, 0, v.name},
                          "the printed deviation " + fmt(*v.printedDeviation) + " is not " + rule + " = " +
                              fmt(expected) + " (within the rounding " + fmt(tolerance) +
                              "); the row is garbled");
  }
}

// ---- OGP step reports --------------------------------------------------------------------------

std::string routineFromPath(const std::string& line) {
  std::string t = trim(line);
  const auto cut = t.find_last_of("\\/");
  if (cut != std::string::npos) t = t.substr(cut + 1);
  return t;
}

CmmTextReport parseOgpSteps(const std::vector<Line>& lines, const std::string& source) {
  CmmTextReport report;
  report.format = CmmReportFormat::OgpSteps;
  report.source = source;
  CmmRun run;
  enum class Section { Comment, Label, Type, Body, Done };
  enum class Table { None, Nominal, Tolerance };
  Section section = Section::Done;
  Table table = Table::None;
  bool inStep = false, closed = false;
  double unit = 1.0;
  CmmFeature f;
  long lastLine = 0;

  auto finishStep = [&](long at) {
    if (!inStep) return;
    if (!closed) {
      throw ParseError(
          ErrorContext{source, at, 0, {}},
          "step " + std::to_string(f.step) + " (line " + std::to_string(f.line) +
              ") ends without its 'Points:' or 'Features:' line; the file is truncated or garbled");
    }
    run.features.push_back(std::move(f));
    f = CmmFeature{};
    inStep = false;
  };

  for (const Line& ln : lines) {
    lastLine = ln.number;
    const std::string t = trim(ln.text);
    if (startsWith(t, "Step:")) {
      finishStep(ln.number);
      const auto tk = tokens(t);
      f = CmmFeature{};
      f.line = ln.number;
      double step = 0.0;
      if (tk.size() < 3 || !parseNumber(tk[1].text, &step) || step < 0 || step != std::floor(step))
        throw ParseError(ErrorContext{source, ln.number, 0, "Step"},
                         "expected 'Step: <number> <unit> ...', found '" + t + "'");
      f.step = static_cast<int>(step);
      const std::string u = upper(tk[2].text);
      if (u == "MM")
        unit = 1.0;
      else if (u == "INCH" || u == "IN")
        unit = kInchMm;
      else
        throw ParseError(ErrorContext{source, ln.number, 0, "Step"},
                         "unknown unit '" + tk[2].text + "' (MM or INCH)");
      inStep = true;
      closed = false;
      section = Section::Comment;
      table = Table::None;
      continue;
    }
    if (!inStep) {
      // Before the first step: the routine's path, "Header:", "Setup:" and rules.
      if (run.routine.empty() && upper(t).find(".RTN") != std::string::npos) run.routine = routineFromPath(t);
      if (section == Section::Done && closed && !t.empty() && !startsWith(t, "---") &&
          !startsWith(t, "===")) {
        throw ParseError(ErrorContext{source, ln.number, 0, {}},
                         "unexpected text after step " + std::to_string(run.features.back().step) + ": '" +
                             t.substr(0, 40) + "'");
      }
      continue;
    }
    switch (section) {
      case Section::Comment:
        if (!startsWith(t, "Comment:"))
          throw ParseError(ErrorContext{source, ln.number, 0, {}},
                           "expected 'Comment:' after the 'Step:' line, found '" + t.substr(0, 40) + "'");
        f.label = trim(std::string_view(t).substr(8));
        section = Section::Label;
        continue;
      case Section::Label:
        if (startsWith(t, "Prompt:")) {
          section = Section::Type;
        } else if (!t.empty()) {
          f.label += (f.label.empty() ? "" : " ") + t;
        }
        continue;
      case Section::Type:
        if (t.empty()) continue;
        f.type = collapseBlanks(t);
        {
          // The type's first part: "Plane         Best Fit" -> "Plane", "Datum Plane    Align" -> "Datum
          // Plane".
          const auto gap = t.find("  ");
          f.featureType = gap == std::string::npos ? t : trim(std::string_view(t).substr(0, gap));
        }
        section = Section::Body;
        continue;
      case Section::Done:
        if (!t.empty() && !startsWith(t, "---") && !startsWith(t, "==="))
          throw ParseError(
              ErrorContext{source, ln.number, 0, {}},
              "unexpected text after step " + std::to_string(f.step) + ": '" + t.substr(0, 40) + "'");
        continue;
      case Section::Body:
        break;
    }
    // Body of a step.
    if (t.empty()) {
      table = Table::None;
      continue;
    }
    if (startsWith(t, "---")) {
      if (!closed)
        throw ParseError(ErrorContext{source, ln.number, 0, {}},
                         "step " + std::to_string(f.step) + " (line " + std::to_string(f.line) +
                             ") ends without its 'Points:' or 'Features:' line");
      finishStep(ln.number);
      section = Section::Done;
      continue;
    }
    if (t.find("Actual") != std::string::npos && (t.find("Nominal") != std::string::npos)) {
      table = Table::Nominal;
      continue;
    }
    if (t.find("Actual") != std::string::npos && t.find("Tolerance") != std::string::npos) {
      table = Table::Tolerance;
      continue;
    }
    if (startsWith(t, "Points:") || startsWith(t, "Features:")) {
      const auto tk = tokens(t);
      double n = 0.0;
      if (tk.size() < 2 || !parseNumber(tk[1].text, &n) || n < 0 || n != std::floor(n))
        throw ParseError(ErrorContext{source, ln.number, 0, tk[0].text},
                         "expected a count after '" + tk[0].text + "'");
      if (startsWith(t, "Points:")) f.points = static_cast<int>(n);
      closed = true;
      continue;
    }
    if (startsWith(t, "Skip:") || startsWith(t, "Reference Feature") || startsWith(t, "DSM") ||
        startsWith(t, "Composite"))
      continue;
    if (closed) continue;  // sensor lines after "Points:" ("Lens: 1x", tips)
    // A value row: name, then the numbers.
    auto tk = tokens(ln.text);
    if (!tk.empty() && tk[0].text == "v" && tk.size() > 1 && !signedNumberLike(tk[1].text))
      tk.erase(tk.begin());  // the "v" flag of datum settings
    std::size_t k = 0;
    std::string name;
    while (k < tk.size() && !signedNumberLike(tk[k].text)) name += (name.empty() ? "" : " ") + tk[k++].text;
    if (name.empty() || k == tk.size())
      throw ParseError(ErrorContext{source, ln.number, 0, {}},
                       "expected a value row (name and numbers) in step " + std::to_string(f.step) +
                           ", found '" + t.substr(0, 40) + "'");
    std::vector<double> nums;
    std::vector<std::string> texts;
    for (; k < tk.size(); ++k) {
      if (!signedNumberLike(tk[k].text)) break;
      nums.push_back(number(tk[k], source, ln.number, name));
      texts.push_back(tk[k].text);
    }
    const std::size_t trailing = tk.size() - k;
    const std::size_t expected = table == Table::Nominal ? 4 : table == Table::Tolerance ? 2 : 1;
    if (nums.size() != expected || (trailing > 0 && table != Table::Tolerance)) {
      const char* cols = table == Table::Nominal     ? "Actual, Nominal, Upper and Lower"
                         : table == Table::Tolerance ? "Actual and Tolerance"
                                                     : "a value";
      throw ParseError(ErrorContext{source, ln.number, 0, name},
                       std::string("expected ") + cols + " (" + std::to_string(expected) + " number" +
                           (expected > 1 ? "s" : "") + "), found " + std::to_string(nums.size()) +
                           (trailing > 0 ? " and '" + tk[k].text + "'" : std::string()));
    }
    CmmValue v;
    v.name = name;
    v.angle = isAngleName(name);
    const double s = v.angle ? 1.0 : unit;
    v.line = ln.number;
    v.actual = s * nums[0];
    v.rounding = s * halfUnit(texts[0]);
    if (table == Table::Nominal) {
      v.nominal = s * nums[1];
      v.upper = s * nums[2];
      v.lower = s * nums[3];
    } else if (table == Table::Tolerance) {
      v.upper = s * nums[1];
    }
    f.values.push_back(std::move(v));
  }
  if (inStep) {
    if (!closed || section != Section::Body)
      throw ParseError(ErrorContext{source, lastLine, 0, {}},
                       "the file ends inside step " + std::to_string(f.step) + " (line " +
                           std::to_string(f.line) + "); it is truncated");
    finishStep(lastLine);
  }
  if (run.features.empty())
    throw ParseError(ErrorContext{source, lastLine, 0, {}}, "an OGP step report without any 'Step:' block");
  run.line = run.features.front().line;
  report.runs.push_back(std::move(run));
  return report;
}

// ---- OGP summary reports ----------------------------------------------------------------------

constexpr std::size_t kSummaryActualColumn = 26;     ///< first column of the Actual field
constexpr std::size_t kSummaryDeviationColumn = 36;  ///< the Deviation field starts after this
constexpr std::size_t kSummaryExceededColumn = 56;   ///< text after this is the Exceeded flag

CmmTextReport parseOgpSummary(const std::vector<Line>& lines, const std::string& source) {
  CmmTextReport report;
  report.format = CmmReportFormat::OgpSummary;
  report.source = source;
  bool expectRunLine = false;
  long lastLine = 0;
  for (const Line& ln : lines) {
    lastLine = ln.number;
    const std::string t = trim(ln.text);
    if (t.empty() || startsWith(t, "===") || startsWith(t, "Machine Serial Number")) continue;
    if (startsWith(t, "Routine Name")) {
      expectRunLine = true;
      continue;
    }
    if (expectRunLine) {
      // "L123_fixture.RTN           4 Wed Oct 01 17:29:15 2014"
      const auto tk = tokens(t);
      double n = 0.0;
      if (tk.size() < 2 || !parseNumber(tk[1].text, &n) || n != std::floor(n))
        throw ParseError(ErrorContext{source, ln.number, 0, "Run #"},
                         "expected '<routine> <run #> <date & time>' after 'Routine Name', found '" +
                             t.substr(0, 40) + "'");
      CmmRun run;
      run.routine = tk[0].text;
      run.number = static_cast<int>(n);
      run.dateTime = tk.size() > 2 ? collapseBlanks(std::string_view(t).substr(tk[2].column)) : std::string();
      run.line = ln.number;
      report.runs.push_back(std::move(run));
      expectRunLine = false;
      continue;
    }
    if (startsWith(t, "Feature") && t.find("Nominal") != std::string::npos) continue;  // column header
    if (startsWith(t, "Step ")) {
      if (report.runs.empty())
        throw ParseError(ErrorContext{source, ln.number, 0, {}},
                         "a step before the first 'Routine Name' header");
      const auto dash = t.find(" - ");
      double n = 0.0;
      if (dash == std::string::npos || !parseNumber(trim(std::string_view(t).substr(5, dash - 5)), &n) ||
          n != std::floor(n))
        throw ParseError(ErrorContext{source, ln.number, 0, "Step"},
                         "expected 'Step <number> - <title>', found '" + t.substr(0, 40) + "'");
      CmmFeature f;
      f.step = static_cast<int>(n);
      f.label = trim(std::string_view(t).substr(dash + 3));
      f.line = ln.number;
      report.runs.back().features.push_back(std::move(f));
      continue;
    }
    // A value row in fixed columns.
    if (report.runs.empty() || report.runs.back().features.empty())
      throw ParseError(
          ErrorContext{source, ln.number, 0, {}},
          "expected a 'Routine Name' header or 'Step n - title', found '" + t.substr(0, 40) + "'");
    CmmFeature& f = report.runs.back().features.back();
    const auto tk = tokens(ln.text);
    std::size_t k = 0;
    std::string name;
    while (k < tk.size() && !signedNumberLike(tk[k].text)) name += (name.empty() ? "" : " ") + tk[k++].text;
    if (name.empty() || k == tk.size())
      throw ParseError(ErrorContext{source, ln.number, 0, {}},
                       "expected a value row (name, nominal, actual, deviation) in step " +
                           std::to_string(f.step) + ", found '" + t.substr(0, 40) + "'");
    CmmValue v;
    v.name = name;
    v.angle = isAngleName(name);
    v.line = ln.number;
    std::optional<double> nominal, actual, deviation;
    double rounding = 0.0;
    for (; k < tk.size(); ++k) {
      const Token& tok = tk[k];
      if (!signedNumberLike(tok.text)) {
        if (tok.column >= kSummaryExceededColumn) break;  // the Exceeded flag
        throw ParseError(ErrorContext{source, ln.number, static_cast<long>(tok.column + 1), name},
                         "'" + tok.text + "' is not a number");
      }
      const double x = number(tok, source, ln.number, name);
      auto& slot = tok.column < kSummaryActualColumn      ? nominal
                   : tok.column < kSummaryDeviationColumn ? actual
                                                          : deviation;
      if (slot)
        throw ParseError(ErrorContext{source, ln.number, static_cast<long>(tok.column + 1), name},
                         "two numbers in one column ('" + tok.text + "'); the row is garbled");
      slot = x;
      rounding += halfUnit(tok.text);
      if (&slot == &actual) v.rounding = halfUnit(tok.text);
    }
    if (!actual)
      throw ParseError(ErrorContext{source, ln.number, 0, name},
                       "no Actual value (columns " + std::to_string(kSummaryActualColumn + 1) + " to " +
                           std::to_string(kSummaryDeviationColumn) + ")");
    v.nominal = nominal;
    v.actual = *actual;
    v.printedDeviation = deviation;
    if (deviation) {
      const bool location =
          iequals(name, "X Location") || iequals(name, "Y Location") || iequals(name, "Z Location");
      checkDeviation(v, ogpPrintedDeviation(v), rounding,
                     !nominal   ? std::string("the actual (a form value, nominal 0)")
                     : location ? std::string("sign(nominal) * (actual - nominal)")
                                : std::string("actual - nominal"),
                     source);
    }
    f.values.push_back(std::move(v));
  }
  if (report.runs.empty())
    throw ParseError(ErrorContext{source, lastLine, 0, {}}, "an OGP summary report without any run");
  if (expectRunLine)
    throw ParseError(ErrorContext{source, lastLine, 0, {}},
                     "the file ends after a 'Routine Name' header; it is truncated");
  return report;
}

// ---- PC-DMIS text reports ---------------------------------------------------------------------

/// "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$" (or without DIM): name, description, unit.
struct DimHeader {
  std::string name, description, unit;
};

std::optional<DimHeader> dimHeader(const std::string& t) {
  const std::string u = upper(t);
  const auto units = u.find("UNITS");
  const auto eq = t.find('=');
  if (units == std::string::npos || eq == std::string::npos || eq >= units) return std::nullopt;
  std::string name = trim(std::string_view(t).substr(0, eq));
  if (startsWith(upper(name), "DIM ")) name = trim(std::string_view(name).substr(4));
  if (name.empty() || name.find(' ') != std::string::npos) return std::nullopt;
  std::size_t k = units + 5;
  while (k < t.size() && t[k] == ' ') ++k;
  if (k >= t.size() || t[k] != '=') return std::nullopt;
  ++k;
  while (k < t.size() && t[k] == ' ') ++k;
  std::size_t e = k;
  while (e < t.size() && std::isalpha(static_cast<unsigned char>(t[e]))) ++e;
  DimHeader h;
  h.name = name;
  h.description = collapseBlanks(std::string_view(t).substr(eq + 1, units - eq - 1));
  while (!h.description.empty() && (h.description.back() == ',' || h.description.back() == ' '))
    h.description.pop_back();
  h.unit = upper(t.substr(k, e - k));
  return h;
}

enum class PcCol { Nominal, PlusTol, MinusTol, Meas, Max, Min, Bonus, Dev, OutTol };

std::optional<PcCol> pcColumn(const std::string& word) {
  const std::string w = upper(word);
  if (w == "NOMINAL" || w == "NOM") return PcCol::Nominal;
  if (w == "+TOL") return PcCol::PlusTol;
  if (w == "-TOL") return PcCol::MinusTol;
  if (w == "MEAS" || w == "MEASURED") return PcCol::Meas;
  if (w == "MAX") return PcCol::Max;
  if (w == "MIN") return PcCol::Min;
  if (w == "BONUS") return PcCol::Bonus;
  if (w == "DEV") return PcCol::Dev;
  if (w == "OUTTOL" || w == "OUT-TOL") return PcCol::OutTol;
  return std::nullopt;
}

bool graphicToken(std::string_view t) {
  return t.size() >= 3 && t.find_first_not_of("-#<>+|") == std::string_view::npos;
}

/// An axis word of a dimension row: letters only, at most 3 (X, Y, Z, D, R, M, TP, PR, PA, ...).
bool axisWord(std::string_view t) {
  if (t.empty() || t.size() > 3) return false;
  return std::all_of(t.begin(), t.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
}

CmmTextReport parsePcDmis(const std::vector<Line>& lines, const std::string& source) {
  CmmTextReport report;
  report.format = CmmReportFormat::PcDmis;
  report.source = source;
  CmmRun run;
  std::string serial;
  bool inDim = false;
  double unit = 1.0;
  std::vector<PcCol> columns;
  std::map<std::string, long> names;
  long lastLine = 0;
  for (const Line& ln : lines) {
    lastLine = ln.number;
    const std::string t = trim(ln.text);
    const std::string u = upper(t);
    if (startsWith(u, "PART NAME") && t.find(':') != std::string::npos) {
      run.routine = trim(std::string_view(t).substr(t.find(':') + 1));
      continue;
    }
    if (startsWith(u, "SER NUMBER") && t.find(':') != std::string::npos) {
      serial = trim(std::string_view(t).substr(t.find(':') + 1));
      continue;
    }
    if (const auto h = dimHeader(t)) {
      if (h->unit == "MM")
        unit = 1.0;
      else if (h->unit == "IN" || h->unit == "INCH")
        unit = kInchMm;
      else
        throw ParseError(ErrorContext{source, ln.number, 0, "UNITS"},
                         "unknown unit '" + h->unit + "' (MM or IN)");
      if (const auto it = names.find(h->name); it != names.end())
        throw ValidationError(
            ErrorContext{source, ln.number, 0, h->name},
            "dimension '" + h->name + "' appears twice (first on line " + std::to_string(it->second) + ")");
      names.emplace(h->name, ln.number);
      CmmFeature f;
      f.step = static_cast<int>(run.features.size()) + 1;
      f.label = h->name;
      f.type = h->description;
      f.line = ln.number;
      // "LOCATION OF CIRCLE CIR1": the feature is the last word, its type the one before.
      const auto of = upper(h->description).rfind(" OF ");
      if (of != std::string::npos) {
        const auto words = tokens(std::string_view(h->description).substr(of + 4));
        if (!words.empty()) f.featureName = words.back().text;
        if (words.size() >= 2) f.featureType = upper(words[words.size() - 2].text);
      }
      run.features.push_back(std::move(f));
      inDim = true;
      columns.clear();
      continue;
    }
    if (!inDim) continue;
    const auto tk = tokens(t);
    if (tk.empty()) continue;
    if (startsWith(u, "GRAPH=") || startsWith(u, "GRAPH ")) continue;
    if (startsWith(u, "END OF DIMENSION")) {
      inDim = false;
      continue;
    }
    if (upper(tk[0].text) == "AX") {
      columns.clear();
      for (std::size_t k = 1; k < tk.size(); ++k) {
        const auto c = pcColumn(tk[k].text);
        if (!c)
          throw ParseError(ErrorContext{source, ln.number, static_cast<long>(tk[k].column + 1), "AX"},
                           "unknown column '" + tk[k].text +
                               "' (NOMINAL, +TOL, -TOL, MEAS, MAX, MIN, BONUS, DEV, OUTTOL)");
        columns.push_back(*c);
      }
      if (std::find(columns.begin(), columns.end(), PcCol::Meas) == columns.end())
        throw ParseError(ErrorContext{source, ln.number, 0, "AX"}, "the column header has no MEAS column");
      continue;
    }
    // A value row: an axis word, then numbers ("-" for an empty cell); other text ends the block
    // (dimensions printed without END OF DIMENSION).
    bool row = axisWord(tk[0].text) && tk.size() >= 2;
    if (row) {
      row = false;
      for (std::size_t k = 1; k < tk.size(); ++k) row = row || numberLike(tk[k].text) || tk[k].text == "-";
    }
    if (!row) {
      inDim = false;
      continue;
    }
    CmmFeature& f = run.features.back();
    const std::string axis = upper(tk[0].text);
    if (axis == "V") continue;  // the vector row of a location
    if (columns.empty())
      throw ParseError(
          ErrorContext{source, ln.number, 0, axis},
          "a value row before the column header (AX NOMINAL +TOL -TOL MEAS DEV OUTTOL) of dimension '" +
              f.label + "'");
    std::map<PcCol, double> cell;
    std::map<PcCol, std::string> text;
    std::size_t k = 1;
    // A material condition after the axis (true position: "TP  RFS ...") is not a column.
    if (k < tk.size() &&
        (upper(tk[k].text) == "RFS" || upper(tk[k].text) == "MMC" || upper(tk[k].text) == "LMC"))
      ++k;
    const std::size_t first = k;
    for (const PcCol c : columns) {
      if (k >= tk.size() || graphicToken(tk[k].text))
        throw ParseError(
            ErrorContext{source, ln.number, 0, axis},
            "expected " + std::to_string(columns.size()) + " values after the axis, found " +
                std::to_string(k - first) +
                " (every column printed, '-' for an empty cell); the row is truncated or garbled");
      if (tk[k].text != "-") {
        cell[c] = number(tk[k], source, ln.number, axis);
        text[c] = tk[k].text;
      }
      ++k;
    }
    for (; k < tk.size(); ++k) {
      if (!graphicToken(tk[k].text))
        throw ParseError(ErrorContext{source, ln.number, static_cast<long>(tk[k].column + 1), axis},
                         "unexpected '" + tk[k].text + "' after the " + std::to_string(columns.size()) +
                             " values of the row");
    }
    if (!cell.count(PcCol::Meas))
      throw ParseError(ErrorContext{source, ln.number, 0, axis}, "the MEAS cell is empty");
    CmmValue v;
    v.name = axis;
    v.angle = axis == "A" || axis == "PA" || isAngleName(f.type);
    const double s = v.angle ? 1.0 : unit;
    v.line = ln.number;
    v.actual = s * cell[PcCol::Meas];
    v.rounding = s * halfUnit(text[PcCol::Meas]);
    if (cell.count(PcCol::Nominal)) v.nominal = s * cell[PcCol::Nominal];
    if (cell.count(PcCol::PlusTol)) v.upper = s * cell[PcCol::PlusTol];
    if (cell.count(PcCol::MinusTol)) v.lower = -s * cell[PcCol::MinusTol];
    if (cell.count(PcCol::OutTol)) v.outTol = s * cell[PcCol::OutTol];
    if (cell.count(PcCol::Dev)) {
      v.printedDeviation = s * cell[PcCol::Dev];
      const double tol = s * (halfUnit(text[PcCol::Meas]) + halfUnit(text[PcCol::Dev]) +
                              (cell.count(PcCol::Nominal) ? halfUnit(text[PcCol::Nominal]) : 0.0));
      checkDeviation(v, plainDeviation(v), tol, "MEAS - NOMINAL", source);
    }
    if (const CmmValue* dup = f.value(v.name))
      throw ValidationError(ErrorContext{source, ln.number, 0, axis},
                            "axis " + axis + " of dimension '" + f.label + "' appears twice (first on line " +
                                std::to_string(dup->line) + ")");
    f.values.push_back(std::move(v));
  }
  if (run.features.empty())
    throw ParseError(ErrorContext{source, lastLine, 0, {}}, "a PC-DMIS report without any dimension");
  for (const CmmFeature& f : run.features)
    if (f.values.empty())
      throw ParseError(ErrorContext{source, f.line, 0, f.label},
                       "dimension '" + f.label + "' has no value rows; the file is truncated or garbled");
  if (!serial.empty()) run.routine += (run.routine.empty() ? "" : " ") + serial;
  run.line = run.features.front().line;
  report.runs.push_back(std::move(run));
  return report;
}

/// "X Location" -> "x_location", "3-D Distance" -> "3_d_distance".
std::string columnName(std::string_view name) {
  std::string out;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) {
      out += static_cast<char>(std::tolower(u));
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace

const char* toString(CmmReportFormat format) {
  switch (format) {
    case CmmReportFormat::OgpSteps:
      return "OGP step report";
    case CmmReportFormat::OgpSummary:
      return "OGP summary report";
    case CmmReportFormat::PcDmis:
      return "PC-DMIS text report";
    case CmmReportFormat::Dfq:
      return "Q-DAS DFQ file";
    case CmmReportFormat::Calypso:
      return "Calypso table";
    case CmmReportFormat::Qif:
      return "QIF results file";
  }
  return "?";
}

const CmmValue* CmmFeature::value(std::string_view name) const {
  for (const CmmValue& v : values)
    if (iequals(v.name, name)) return &v;
  return nullptr;
}

double ogpPrintedDeviation(const CmmValue& v) {
  const double nominal = v.nominal.value_or(0.0);
  const double d = v.actual - nominal;
  const bool location =
      iequals(v.name, "X Location") || iequals(v.name, "Y Location") || iequals(v.name, "Z Location");
  return location && std::signbit(nominal) ? -d : d;
}

double plainDeviation(const CmmValue& v) {
  return v.actual - v.nominal.value_or(0.0);
}

namespace {

/// rtfToText; `head`: the first part of a document (no error when it is not closed, nothing read
/// after its end).
std::string rtfText(std::string_view rtf, const std::string& source, bool head) {
  std::string out;
  out.reserve(rtf.size());
  // One entry per open group: true when its content is not text (font table, colours, \* groups).
  std::vector<bool> skip;
  long line = 1;
  bool ended = false;
  std::size_t i = 0;
  auto latin1 = [&out](unsigned char b) {
    if (b < 0x80) {
      out += static_cast<char>(b);
    } else {
      out += static_cast<char>(0xC0 | (b >> 6));
      out += static_cast<char>(0x80 | (b & 0x3F));
    }
  };
  while (i < rtf.size()) {
    const char c = rtf[i];
    if (c == '\n') {
      out += '\n';
      ++line;
      ++i;
      continue;
    }
    if (c == '\r') {
      ++i;
      continue;
    }
    if (ended) {
      if (head) break;
      if (c == ' ' || c == '\t' || c == '\0') {
        ++i;
        continue;
      }
      throw ParseError(ErrorContext{source, line, 0, {}}, "text after the end of the RTF document");
    }
    const bool text = !skip.empty() && !skip.back();
    if (c == '{') {
      bool s = !skip.empty() && skip.back();
      // A destination group: "{\*..." or one of the tables that hold no text.
      std::size_t j = i + 1;
      if (j < rtf.size() && rtf[j] == '\\') {
        std::size_t e = j + 1;
        while (e < rtf.size() && std::isalpha(static_cast<unsigned char>(rtf[e]))) ++e;
        const std::string word(rtf.substr(j + 1, e - j - 1));
        static const char* const kDest[] = {"fonttbl", "colortbl", "stylesheet", "info",      "pict",
                                            "header",  "footer",   "object",     "themedata", "listtable"};
        if (rtf.substr(j, 2) == "\\*" ||
            std::find(std::begin(kDest), std::end(kDest), word) != std::end(kDest))
          s = true;
      }
      skip.push_back(s);
      ++i;
      continue;
    }
    if (c == '}') {
      if (skip.empty())
        throw ParseError(ErrorContext{source, line, 0, {}}, "unbalanced '}' in the RTF document");
      skip.pop_back();
      if (skip.empty()) ended = true;
      ++i;
      continue;
    }
    if (skip.empty())
      throw ParseError(ErrorContext{source, line, 0, {}}, "text before the RTF document starts");
    if (c == '\\') {
      if (i + 1 >= rtf.size()) break;
      const char n = rtf[i + 1];
      if (n == '\\' || n == '{' || n == '}') {
        if (text) out += n;
        i += 2;
        continue;
      }
      if (n == '\'') {
        unsigned v = 0;
        bool ok = i + 3 < rtf.size();
        for (std::size_t k = i + 2; ok && k < i + 4; ++k) {
          const char h = static_cast<char>(std::tolower(static_cast<unsigned char>(rtf[k])));
          if (h >= '0' && h <= '9')
            v = v * 16 + static_cast<unsigned>(h - '0');
          else if (h >= 'a' && h <= 'f')
            v = v * 16 + static_cast<unsigned>(h - 'a' + 10);
          else
            ok = false;
        }
        if (!ok) throw ParseError(ErrorContext{source, line, 0, {}}, "a \\' escape without two hex digits");
        if (text) latin1(static_cast<unsigned char>(v));
        i += 4;
        continue;
      }
      if (std::isalpha(static_cast<unsigned char>(n))) {
        std::size_t e = i + 1;
        while (e < rtf.size() && std::isalpha(static_cast<unsigned char>(rtf[e]))) ++e;
        const std::string word(rtf.substr(i + 1, e - i - 1));
        if (e < rtf.size() && (rtf[e] == '-' || std::isdigit(static_cast<unsigned char>(rtf[e])))) {
          ++e;
          while (e < rtf.size() && std::isdigit(static_cast<unsigned char>(rtf[e]))) ++e;
        }
        if (e < rtf.size() && rtf[e] == ' ') ++e;  // the delimiter belongs to the control word
        if (text) {
          if (word == "tab") out += '\t';
          // A paragraph break is a line end, unless the file breaks the line itself right after it.
          if ((word == "par" || word == "line") && !(e < rtf.size() && (rtf[e] == '\r' || rtf[e] == '\n')))
            out += '\n';
        }
        i = e;
        continue;
      }
      i += 2;  // a control symbol (\~, \-, \*, ...)
      continue;
    }
    if (c == '\0')
      throw ParseError(ErrorContext{source, line, 0, {}}, "binary data (a NUL byte) inside the RTF document");
    if (text) out += c;
    ++i;
  }
  if (!ended && !head)
    throw ParseError(ErrorContext{source, line, 0, {}},
                     "the RTF document is not closed (its final '}' is missing); the file is truncated");
  return out;
}

}  // namespace

std::string rtfToText(std::string_view rtf, const std::string& source) {
  return rtfText(rtf, source, false);
}

std::optional<CmmReportFormat> detectCmmTextReport(std::string_view text) {
  if (looksLikeQif(text)) return CmmReportFormat::Qif;
  if (looksLikeDfq(text)) return CmmReportFormat::Dfq;
  if (looksLikeCalypsoCharacteristics(text)) return CmmReportFormat::Calypso;
  std::size_t pos = startsWith(text, "\xEF\xBB\xBF") ? 3 : 0;
  std::string head;
  if (startsWith(text.substr(pos), "{\\rtf")) {
    // The first lines of the document's text (without the RTF groups).
    try {
      const auto cut = text.find('\n', std::min(text.size(), std::size_t{8000}));
      head = rtfText(text.substr(pos, cut == std::string_view::npos ? std::string_view::npos : cut - pos), {},
                     true);
    } catch (const InputError&) {
      return std::nullopt;
    }
    text = head;
    pos = 0;
  }
  bool summaryHeader = false, step = false, dim = false;
  for (int n = 0; n < 200 && pos < text.size(); ++n) {
    const auto nl = text.find('\n', pos);
    const std::string t =
        trim(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    if (startsWith(t, "Machine Serial Number:")) summaryHeader = true;
    if (summaryHeader && startsWith(t, "Routine Name")) return CmmReportFormat::OgpSummary;
    if (startsWith(t, "Step:")) step = true;
    if (step && startsWith(t, "Comment:")) return CmmReportFormat::OgpSteps;
    if (dimHeader(t)) dim = true;
    if (dim) {
      const auto tk = tokens(t);
      if (!tk.empty() && upper(tk[0].text) == "AX" && upper(t).find("MEAS") != std::string::npos)
        return CmmReportFormat::PcDmis;
    }
  }
  return std::nullopt;
}

CmmTextReport cmmTextReportFromText(std::string_view text, const std::string& source) {
  const auto format = detectCmmTextReport(text);
  if (!format)
    throw ParseError(ErrorContext{source, 1, 0, {}},
                     "not an OGP step or summary report nor a PC-DMIS text report");
  if (*format == CmmReportFormat::Qif) return qifCmmReport(qifFromText(text, source));
  if (*format == CmmReportFormat::Dfq) return dfqCmmReport(dfqFromText(text, source));
  if (*format == CmmReportFormat::Calypso)
    return calypsoCmmReport(calypsoCharacteristicsFromText(text, source));
  std::string plain;
  bool rtf = false;
  std::string_view body = text;
  if (startsWith(body, "\xEF\xBB\xBF")) body.remove_prefix(3);
  if (startsWith(body, "{\\rtf")) {
    plain = rtfToText(body, source);
    body = plain;
    rtf = true;
  }
  const auto lines = splitLines(body, source);
  CmmTextReport r = *format == CmmReportFormat::OgpSteps     ? parseOgpSteps(lines, source)
                    : *format == CmmReportFormat::OgpSummary ? parseOgpSummary(lines, source)
                                                             : parsePcDmis(lines, source);
  r.rtf = rtf;
  return r;
}

CmmTextReport readCmmTextReport(const std::string& path) {
  const std::string text = readFile(path, 256u << 20);
  // A Calypso _chr file read by its path also takes the dates of the _hdr file beside it.
  if (!looksLikeDfq(text) && looksLikeCalypsoCharacteristics(text))
    return calypsoCmmReport(readCalypsoCharacteristics(path));
  return cmmTextReportFromText(text, displayPath(path));
}

CmmTextReport dfqCmmReport(const DfqFile& file) {
  CmmTextReport r;
  r.format = CmmReportFormat::Dfq;
  r.source = file.source;
  for (const DfqReadPart& p : file.parts) {
    std::size_t sets = 0;
    for (const DfqReadCharacteristic& c : file.characteristics)
      if (c.part == p.index) sets = std::max(sets, c.values.size());
    for (std::size_t k = 0; k < sets; ++k) {
      CmmRun run;
      run.routine = p.number;
      run.number = static_cast<int>(k + 1);
      for (const DfqReadCharacteristic& c : file.characteristics) {
        if (c.part != p.index || k >= c.values.size()) continue;
        const DfqReadValue& v = c.values[k];
        if (run.line == 0) run.line = v.line;
        if (run.dateTime.empty()) run.dateTime = v.time;
        if (run.serial.empty()) run.serial = v.partId;
        if (!v.valid()) continue;
        CmmFeature f;
        f.step = c.index;
        f.label = c.description.empty() ? c.number : c.description;
        f.featureName = c.number;
        f.type = "characteristic";
        f.line = c.line != 0 ? c.line : v.line;
        CmmValue value;
        value.name = "actual";
        value.nominal = c.nominal;
        value.actual = *v.value;
        if (c.nominal && c.lowerLimit) value.lower = *c.lowerLimit - *c.nominal;
        if (c.nominal && c.upperLimit) value.upper = *c.upperLimit - *c.nominal;
        value.rounding = c.decimals ? 0.5 * std::pow(10.0, -*c.decimals) : 0.0;
        value.angle = c.unit == "°" || c.unit == "deg" || c.unit == "Grad";
        value.line = v.line;
        f.values.push_back(std::move(value));
        run.features.push_back(std::move(f));
      }
      if (!run.features.empty()) r.runs.push_back(std::move(run));
    }
  }
  return r;
}

CmmTextReport calypsoCmmReport(const CalypsoCharacteristics& table) {
  CmmTextReport r;
  r.format = CmmReportFormat::Calypso;
  r.source = table.source;
  for (std::size_t k = 0; k < table.parts.size(); ++k) {
    CmmRun run;
    run.serial = table.parts[k];
    run.dateTime = k < table.dates.size() ? table.dates[k] : std::string();
    run.number = static_cast<int>(k + 1);
    for (const CalypsoCharacteristic& c : table.rows) {
      if (c.part != table.parts[k]) continue;
      if (run.line == 0) {
        run.line = c.line;
        run.routine = c.planId;
      }
      CmmFeature f;
      f.step = static_cast<int>(run.features.size() + 1);
      f.label = c.id;
      f.featureName = c.id;
      f.type = c.type;
      f.line = c.line;
      CmmValue v;
      v.name = "actual";
      v.nominal = c.nominal;
      v.actual = c.actual;
      v.lower = c.lowerTol;
      v.upper = c.upperTol;
      v.printedDeviation = c.deviation;
      v.rounding = c.rounding;
      v.line = c.line;
      f.values.push_back(std::move(v));
      run.features.push_back(std::move(f));
    }
    r.runs.push_back(std::move(run));
  }
  return r;
}

CsvTable cmmReportFeatureTable(const CmmTextReport& report) {
  std::vector<std::string> header{"run", "date"};
  std::map<std::string, std::size_t> index;
  std::vector<std::vector<std::string>> rows;
  std::vector<long> lines;
  // Column keys in order of first appearance.
  for (const CmmRun& run : report.runs) {
    for (const CmmFeature& f : run.features) {
      const std::string key = report.format == CmmReportFormat::PcDmis ? f.label
                              : isCharacteristicTable(report.format)   ? f.featureName
                                                                       : "step" + std::to_string(f.step);
      for (const CmmValue& v : f.values) {
        const std::string col = key + "." + columnName(v.name);
        if (index.emplace(col, header.size()).second) header.push_back(col);
        if (v.nominal || v.printedDeviation) {
          if (index.emplace(col + ".dev", header.size()).second) header.push_back(col + ".dev");
        }
      }
    }
  }
  for (std::size_t r = 0; r < report.runs.size(); ++r) {
    const CmmRun& run = report.runs[r];
    std::vector<std::string> row(header.size());
    row[0] = std::to_string(r + 1);
    row[1] = run.dateTime;
    for (const CmmFeature& f : run.features) {
      const std::string key = report.format == CmmReportFormat::PcDmis ? f.label
                              : isCharacteristicTable(report.format)   ? f.featureName
                                                                       : "step" + std::to_string(f.step);
      for (const CmmValue& v : f.values) {
        const std::string col = key + "." + columnName(v.name);
        std::string& cell = row[index.at(col)];
        if (!cell.empty())
          throw ValidationError(ErrorContext{report.source, v.line, 0, v.name},
                                "run " + std::to_string(r + 1) + " has two values for column '" + col + "'");
        cell = CsvWriter::formatNumber(v.actual);
        if (v.nominal || v.printedDeviation)
          row[index.at(col + ".dev")] = CsvWriter::formatNumber(plainDeviation(v));
      }
    }
    rows.push_back(std::move(row));
    lines.push_back(run.line);
  }
  return CsvTable::fromCells(report.source, std::move(header), std::move(rows), std::move(lines));
}

CsvTable readFeatureTable(const std::string& path, const CsvReadOptions& csv) {
  const std::string text = readFile(path, 256u << 20);
  if (looksLikeCmmTextReport(text))
    return cmmReportFeatureTable(cmmTextReportFromText(text, displayPath(path)));
  return parseCsv(text, displayPath(path), csv);
}

}  // namespace metrofit
