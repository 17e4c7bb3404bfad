#include "core/setup/export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/common/run.h"
#include "core/io/csv.h"

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
  std::snprintf(buf, sizeof buf, plus ? "%+.*f" : "%.*f", decimals, r);
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
  if (programNumber < 1 || programNumber > 9999) return no("the Fanuc program number must be in 1..9999");
  if (cuttingEdge < 1 || cuttingEdge > 12) return no("the cutting edge (D number) must be in 1..12");
  return true;
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

}  // namespace metrofit::setup
