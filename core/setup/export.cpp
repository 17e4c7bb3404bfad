#include "core/setup/export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/run.h"
#include "core/io/csv.h"
#include "core/io/nc_program.h"

namespace metrofit::setup {
namespace {

int decimalsFor(double step) {
  return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 3, 6);
}

/// Fixed decimals; "-0.000" becomes "0.000"; `plus` adds '+' to non-negative values.
std::string number(double v, int decimals, bool plus) {
  const double scale = std::pow(10.0, decimals);
  double r = std::round(v * scale) / scale;
  if (r == 0.0) r = 0.0;
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, plus ? "%+.*f" : "%.*f", decimals, r);
  return buf;
}

std::string pad(const std::string& s, std::size_t width, bool right = false) {
  if (s.size() >= width) return s + " ";
  return right ? std::string(width - s.size(), ' ') + s : s + std::string(width - s.size(), ' ');
}

/// Fanuc comments: upper case, no parentheses inside.
std::string fanucComment(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '(')
      ch = '[';
    else if (ch == ')')
      ch = ']';
    else if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126)
      ch = ' ';
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  }
  return "(" + out + ")";
}

std::string oneLine(const std::string& text) {
  std::string out;
  for (char ch : text) out += (ch == '\n' || ch == '\r') ? ' ' : ch;
  return out;
}

}  // namespace

ControllerFormat parseControllerFormat(const std::string& name, const std::string& field) {
  if (name == "fanuc") return ControllerFormat::Fanuc;
  if (name == "heidenhain") return ControllerFormat::Heidenhain;
  if (name == "siemens") return ControllerFormat::Siemens;
  if (name == "csv") return ControllerFormat::Csv;
  throw OptionsError(ErrorContext{{}, 0, 0, field},
                     "unknown format '" + name + "' (one of fanuc, heidenhain, siemens, csv)");
}

const char* toString(ControllerFormat format) {
  switch (format) {
    case ControllerFormat::Fanuc:
      return "fanuc";
    case ControllerFormat::Heidenhain:
      return "heidenhain";
    case ControllerFormat::Siemens:
      return "siemens";
    case ControllerFormat::Csv:
      return "csv";
  }
  return "?";
}

bool ExportOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (cuttingEdge < 1 || cuttingEdge > 12) return no("the cutting edge (D number) must be in 1..12");
  return fanucProgramNumberOk(programNumber, why);
}

int registerOf(const Model& model, std::size_t i) {
  const SetupDatum& d = model.setup.at(i);
  if (d.registerNumber > 0) return d.registerNumber;
  std::size_t start = d.id.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(d.id[start - 1]))) --start;
  const std::string digits = d.id.substr(start);
  const ErrorContext ctx{model.source, 0, 0, "setup[" + std::to_string(i) + "].register"};
  if (digits.empty() || digits.size() > 6)
    throw ValidationError(ctx, "cannot derive a register number from id '" + d.id + "'; add \"register\"");
  const int reg = std::stoi(digits);
  if (reg == 0 && d.kind != DatumKind::Machine)
    throw ValidationError(
        ctx, "register 0 derived from id '" + d.id + "' is not a valid register; add \"register\"");
  return reg;
}

std::string exportCorrections(const Model& model, std::span<const double> x, ControllerFormat format,
                              const ExportOptions& options) {
  requireValid(options, "export options");
  if (x.size() != model.setup.size()) {
    throw ValidationError(ErrorContext{model.source, 0, 0, "setup"},
                          "got " + std::to_string(x.size()) + " corrections for " +
                              std::to_string(model.setup.size()) + " setup data");
  }
  const int dec = decimalsFor(model.stepMm);
  const std::string title = oneLine(options.title.empty() ? model.name : options.title);
  const bool wear = options.toolOffset == ToolOffset::Wear;
  std::string out;
  auto line = [&](const std::string& s) { out += s + "\n"; };

  switch (format) {
    case ControllerFormat::Fanuc: {
      line("%");
      line("O" +
           std::string(4 - std::min<std::size_t>(4, std::to_string(options.programNumber).size()), '0') +
           std::to_string(options.programNumber) + " " + fanucComment("METROFIT SETUP CORRECTIONS"));
      if (!title.empty()) line(fanucComment(title));
      line(fanucComment("G91: EACH VALUE IS ADDED TO THE OFFSET REGISTER, MM"));
      line(fanucComment("+ MOVES THE WORK ZERO / TOOL TIP TOWARDS +" + model.axis));
      line(fanucComment(std::string("TOOL ") + (wear ? "WEAR L11" : "GEOMETRY L10") +
                        ": OFFSET MEMORY C; ACTS AT THE NEXT G43 H"));
      line("G21 G91");
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        const SetupDatum& d = model.setup[i];
        const std::string v = number(x[i], dec, false);
        if (d.kind == DatumKind::Machine) {
          line("G10 L2 P0 " + model.axis + v + " " + fanucComment(d.id + " EXTERNAL WORK OFFSET"));
          continue;
        }
        const int reg = registerOf(model, i);
        if (d.kind == DatumKind::Wks) {
          if (reg <= 6) {
            line("G10 L2 P" + std::to_string(reg) + " " + model.axis + v + " " +
                 fanucComment(d.id + " G" + std::to_string(53 + reg)));
          } else if (reg - 6 <= 300) {
            line("G10 L20 P" + std::to_string(reg - 6) + " " + model.axis + v + " " +
                 fanucComment(d.id + " G54.1 P" + std::to_string(reg - 6)));
          } else {
            throw ValidationError(
                ErrorContext{model.source, 0, 0, "setup[" + std::to_string(i) + "].register"},
                "work offset register " + std::to_string(reg) + " is beyond Fanuc's G54.1 P300");
          }
        } else {
          line(std::string("G10 ") + (wear ? "L11" : "L10") + " P" + std::to_string(reg) + " R" + v + " " +
               fanucComment(d.id + (wear ? " LENGTH WEAR" : " LENGTH GEOMETRY")));
        }
      }
      line("G90");
      line("M30");
      line("%");
      break;
    }
    case ControllerFormat::Heidenhain: {
      line("; Metrofit setup corrections for HEIDENHAIN TNC" +
           (title.empty() ? std::string() : ": " + title));
      line(
          "; Every value is an INCREMENT in mm: + moves the preset / tool tip "
          "towards +" +
          model.axis + ".");
      line("; PRESET.PR: enter each value in column " + model.axis +
           " of row NR with \"Correct\" (incremental).");
      line("; Activate the preset again and call the tool again (TOOL CALL) for the values to act.");
      line("; A file the control imports instead: --export heidenhain-table with the current table.");
      std::string machine;
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        if (model.setup[i].kind == DatumKind::Machine)
          machine += "; " + model.setup[i].id + ": machine point " + number(x[i], dec, true) +
                     " mm has no register here; apply it to every preset by hand\n";
      }
      out += machine;
      line(pad("NR", 8) + pad("DOC", 17) + pad(model.axis, 12, true));
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        if (model.setup[i].kind != DatumKind::Wks) continue;
        line(pad(std::to_string(registerOf(model, i)), 8) + pad(model.setup[i].id.substr(0, 16), 17) +
             pad(number(x[i], dec, true), 12, true));
      }
      line(std::string("; TOOL.T: add each value to column ") + (wear ? "DL" : "L") + " of tool T.");
      line(pad("T", 8) + pad("NAME", 17) + pad(wear ? "DL" : "L", 12, true));
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        if (model.setup[i].kind != DatumKind::Tool) continue;
        line(pad(std::to_string(registerOf(model, i)), 8) + pad(model.setup[i].id.substr(0, 16), 17) +
             pad(number(x[i], dec, true), 12, true));
      }
      break;
    }
    case ControllerFormat::Siemens: {
      line("; Metrofit setup corrections for SINUMERIK" + (title.empty() ? std::string() : ": " + title));
      line(
          "; Every value is ADDED to the register, mm: + moves the work zero / "
          "tool tip towards +" +
          model.axis + ".");
      line(
          "; Reselect the settable frame (G54 ...) and the tool offset (D) for "
          "the values to take effect.");
      line(
          "; Needs MD18600 $MN_FRAME_FINE_TRANS = 1 (fine offset of settable frames; else alarm "
          "\"FRAME: fine offset not possible\").");
      int maxFrame = 0;
      for (std::size_t i = 0; i < model.setup.size(); ++i)
        if (model.setup[i].kind == DatumKind::Wks) maxFrame = std::max(maxFrame, registerOf(model, i));
      if (maxFrame >= 5) {
        line("; Frame " + std::to_string(maxFrame) +
             " (G505..G599) needs MD28080 $MC_MM_NUM_USER_FRAMES >= " + std::to_string(maxFrame + 1) +
             " (settable frames G500, G54..G57, G505..).");
      }
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        const SetupDatum& d = model.setup[i];
        const std::string v = number(x[i], dec, true);
        if (d.kind == DatumKind::Machine) {
          line("; " + d.id + ": machine point " + v +
               " mm has no register here; apply it to every frame by hand");
          continue;
        }
        const int reg = registerOf(model, i);
        if (d.kind == DatumKind::Wks) {
          if (reg > 99) {
            throw ValidationError(
                ErrorContext{model.source, 0, 0, "setup[" + std::to_string(i) + "].register"},
                "settable frame " + std::to_string(reg) + " is beyond SINUMERIK's G599 (99)");
          }
          const std::string f = "$P_UIFR[" + std::to_string(reg) + "," + model.axis + ",FI]";
          const std::string g = reg <= 4 ? "G5" + std::to_string(3 + reg)
                                         : "G5" + std::string(reg < 10 ? "0" : "") + std::to_string(reg);
          line(f + "=" + f + v + " ; " + d.id + " " + g + " fine offset");
        } else {
          const std::string t = std::string(wear ? "$TC_DP12[" : "$TC_DP3[") + std::to_string(reg) + "," +
                                std::to_string(options.cuttingEdge) + "]";
          line(t + "=" + t + v + " ; " + d.id + " D" + std::to_string(options.cuttingEdge) +
               (wear ? " wear length 1" : " geometry length 1"));
        }
      }
      line("M30");
      break;
    }
    case ControllerFormat::Csv: {
      CsvWriter w;
      w.comment(" Metrofit setup corrections" + (title.empty() ? std::string() : ": " + title));
      w.comment(
          " correction_mm is an increment to ADD to the register; + moves "
          "the work zero / tool tip towards +axis");
      w.row({"id", "kind", "register", "axis", "correction_mm"});
      for (std::size_t i = 0; i < model.setup.size(); ++i) {
        const SetupDatum& d = model.setup[i];
        std::string reg;
        if (d.registerNumber > 0) {
          reg = std::to_string(d.registerNumber);
        } else if (d.kind != DatumKind::Machine) {
          try {
            reg = std::to_string(registerOf(model, i));
          } catch (const ValidationError&) {
            reg.clear();  // the CSV does not need one
          }
        }
        w.row({d.id, toString(d.kind), reg, model.axis, number(x[i], dec, false)});
      }
      out = w.text();
      break;
    }
  }
  return out;
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

struct Column {
  std::string name;
  std::size_t start = 0, end = std::string::npos;  ///< [start, end); npos: to the end of the line
};

/// Columns of a TNC table's header line: each starts where its name starts and ends where the next begins.
std::vector<Column> tableColumns(const std::string& header) {
  std::vector<Column> cols;
  std::size_t i = 0;
  while (i < header.size()) {
    if (header[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t b = i;
    while (i < header.size() && header[i] != ' ') ++i;
    if (!cols.empty()) cols.back().end = b;
    cols.push_back(Column{header.substr(b, i - b), b, std::string::npos});
  }
  return cols;
}

}  // namespace

TableUpdate updateHeidenhainTable(const Model& model, std::span<const double> x, const std::string& table,
                                  const std::string& source, const ExportOptions& options) {
  requireValid(options, "export options");
  if (x.size() != model.setup.size()) {
    throw ValidationError(ErrorContext{model.source, 0, 0, "setup"},
                          "got " + std::to_string(x.size()) + " corrections for " +
                              std::to_string(model.setup.size()) + " setup data");
  }
  // Lines, keeping the file's line ending (TNC files are often CRLF).
  std::vector<std::string> lines;
  const bool crlf = table.find("\r\n") != std::string::npos;
  {
    std::size_t b = 0;
    while (b < table.size()) {
      std::size_t e = table.find('\n', b);
      if (e == std::string::npos) e = table.size();
      std::string l = table.substr(b, e - b);
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines.push_back(l);
      b = e + 1;
    }
  }
  auto fail = [&](std::size_t line, const std::string& what) -> void {
    throw ValidationError(ErrorContext{source, static_cast<int>(line), 0, {}}, what);
  };
  if (lines.empty() || lines[0].rfind("BEGIN ", 0) != 0)
    fail(1, "is not a HEIDENHAIN table: the first line must start with 'BEGIN <NAME>.<EXT>'");
  // "BEGIN NAME.EXT UNIT ..."
  std::string rest = lines[0].substr(6);
  const std::size_t sp = rest.find(' ');
  const std::string nameExt = rest.substr(0, sp);
  const std::string unit = sp == std::string::npos ? std::string() : trim(rest.substr(sp + 1)).substr(0, 4);
  const std::size_t dot = nameExt.rfind('.');
  std::string ext = dot == std::string::npos ? std::string() : nameExt.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const bool preset = ext == "PR";
  if (!preset && ext != "T")
    fail(1, "'" + nameExt + "' is neither a preset table (.PR) nor a tool table (.T)");
  double perMm = 1.0;
  if (unit.rfind("MM", 0) == 0 && (unit.size() == 2 || unit[2] == ' ')) {
    perMm = 1.0;
  } else if (unit == "INCH") {
    perMm = 1.0 / 25.4;
  } else {
    fail(1, "the BEGIN line names no unit (MM or INCH) after '" + nameExt + "'");
  }
  // Optional structure preamble (#STRUCTBEGIN ... #STRUCTEND) before the column names.
  std::size_t headerLine = 1;
  if (headerLine < lines.size() && lines[headerLine].rfind("#STRUCTBEGIN", 0) == 0) {
    while (headerLine < lines.size() && lines[headerLine].rfind("#STRUCTEND", 0) != 0) ++headerLine;
    ++headerLine;
  }
  if (headerLine >= lines.size()) fail(lines.size(), "has no line of column names");
  const std::vector<Column> cols = tableColumns(lines[headerLine]);
  auto column = [&](std::initializer_list<const char*> names) -> const Column* {
    for (const char* n : names)
      for (const Column& c : cols)
        if (c.name == n) return &c;
    return nullptr;
  };
  const bool wear = options.toolOffset == ToolOffset::Wear;
  const Column* key = preset ? column({"NO", "NR"}) : column({"T"});
  const std::string valueName = preset ? model.axis : (wear ? "DL" : "L");
  const Column* value = column({valueName.c_str()});
  if (!key) fail(headerLine + 1, std::string("has no column ") + (preset ? "NO (or NR)" : "T"));
  if (!value) fail(headerLine + 1, "has no column " + valueName);
  std::size_t endLine = headerLine + 1;
  while (endLine < lines.size() && trim(lines[endLine]) != "[END]") ++endLine;
  if (endLine >= lines.size()) fail(lines.size(), "has no '[END]' line");

  auto cell = [](const std::string& l, const Column& c) {
    if (c.start >= l.size()) return std::string();
    return trim(l.substr(c.start, c.end == std::string::npos ? std::string::npos : c.end - c.start));
  };
  TableUpdate u;
  u.table = nameExt;
  const int dec = decimalsFor(model.stepMm) + (perMm == 1.0 ? 0 : 1);
  for (std::size_t i = 0; i < model.setup.size(); ++i) {
    const SetupDatum& d = model.setup[i];
    const bool mine = preset ? d.kind == DatumKind::Wks : d.kind == DatumKind::Tool;
    if (!mine) {
      u.notWritten.push_back(d.id);
      continue;
    }
    const int reg = registerOf(model, i);
    std::size_t row = 0;
    for (std::size_t l = headerLine + 1; l < endLine && row == 0; ++l) {
      const std::string k = cell(lines[l], *key);
      if (!k.empty() && k.size() <= 9 && k.find_first_not_of("0123456789") == std::string::npos &&
          std::stol(k) == reg)
        row = l;
    }
    if (row == 0) {
      fail(headerLine + 1, "has no row " + key->name + " " + std::to_string(reg) + " for setup[" +
                               std::to_string(i) + "] '" + d.id + "'");
    }
    const std::string old = cell(lines[row], *value);
    double v = 0.0;
    if (!old.empty()) {
      char* end = nullptr;
      v = metrofit::num::strtodC(old.c_str(), &end);
      if (end == old.c_str() || *end != '\0' || !std::isfinite(v))
        fail(row + 1, "column " + valueName + ": '" + old + "' is not a number");
    }
    // Keep the precision the cell has (a preset often holds 4 or 5 decimals).
    const std::size_t dp = old.find('.');
    const int oldDec =
        dp == std::string::npos ? 0 : static_cast<int>(std::min<std::size_t>(old.size() - dp - 1, 9));
    const std::string nv = number(v + x[i] * perMm, std::max(dec, oldDec), true);
    std::string& l = lines[row];
    if (l.size() < value->start) l.resize(value->start, ' ');
    if (value->end == std::string::npos) {  // the last column runs to the end of the line
      l.replace(value->start, std::string::npos, nv);
    } else {
      const std::size_t width = value->end - value->start;
      if (nv.size() >= width)  // one blank at least keeps the cell apart from the next column
        fail(row + 1, "column " + valueName + ": the new value " + nv + " does not fit its " +
                          std::to_string(width) + " characters");
      if (l.size() < value->end) l.resize(value->end, ' ');
      l.replace(value->start, width, nv + std::string(width - nv.size(), ' '));
    }
    u.written.push_back(d.id);
  }
  for (const std::string& l : lines) u.text += l + (crlf ? "\r\n" : "\n");
  return u;
}

}  // namespace metrofit::setup
