#include "core/thermal/control_export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/run.h"
#include "core/io/csv.h"

namespace metrofit::thermal {
namespace {

// ---- numbers and names -------------------------------------------------------------------------

/// The shortest text that reads back to v, as an IEC 61131-3 REAL literal (a '.' in the mantissa,
/// 'E' for the exponent): "0.5", "3.0", "1.0E-07", "-2.5E+20".
std::string stReal(double v) {
  std::string s = num::shortest(v + 0.0);
  std::string mantissa = s, exponent;
  if (const auto e = s.find('e'); e != std::string::npos) {
    mantissa = s.substr(0, e);
    exponent = "E" + s.substr(e + 1);
  }
  if (mantissa.find('.') == std::string::npos) mantissa += ".0";
  return mantissa + exponent;
}

/// Shortest round-trip text (plain "1e-07" form) for the vendor formulas and the headers' code lines.
std::string exact(double v) {
  return num::shortest(v + 0.0);
}

/// Six significant digits, for prose in headers.
std::string g6(double v) {
  return num::general(v + 0.0, 6);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// The unit a column name states ("_um", "_degC", "_rpm", "_mm", "_K" suffixes or a bracket), else "".
std::string unitOfName(const std::string& name) {
  const std::string l = lower(name);
  for (const char* u : {"um", "degc", "rpm", "mm", "k", "nm"}) {
    const std::string suffix = std::string("_") + u;
    if (l.size() > suffix.size() && l.ends_with(suffix)) return name.substr(name.size() - suffix.size() + 1);
  }
  const auto open = name.rfind('[');
  if (open != std::string::npos && name.back() == ']') return name.substr(open + 1, name.size() - open - 2);
  return "";
}

/// Text for a comment: no comment delimiters of any of the forms inside.
std::string commentSafe(std::string s) {
  for (std::size_t at = s.find("*)"); at != std::string::npos; at = s.find("*)")) s.replace(at, 2, "* )");
  for (std::size_t at = s.find("(*"); at != std::string::npos; at = s.find("(*")) s.replace(at, 2, "( *");
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

const std::set<std::string>& stKeywords() {
  static const std::set<std::string> k = {
      "ABS",    "AND",    "ARRAY", "AT",    "BOOL",   "BY",     "BYTE", "CASE", "CONSTANT", "DATE",
      "DINT",   "DO",     "DWORD", "ELSE",  "ELSIF",  "END",    "EXP",  "EXIT", "FALSE",    "FOR",
      "IF",     "INT",    "LN",    "LOG",   "LREAL",  "MOD",    "NOT",  "OF",   "OR",       "REAL",
      "REPEAT", "RETURN", "SINT",  "SQRT",  "STRING", "STRUCT", "THEN", "TIME", "TO",       "TRUE",
      "TYPE",   "UDINT",  "UINT",  "UNTIL", "VAR",    "WHILE",  "WORD", "XOR",  "RETAIN",   "TASK"};
  return k;
}

/// An IEC 61131-3 identifier from a column name (letters, digits, single underscores, no leading digit).
std::string stIdentifier(const std::string& name) {
  std::string id;
  for (char c : name) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 128;
    if (ok)
      id += c;
    else if (!id.empty() && id.back() != '_')
      id += '_';
  }
  while (!id.empty() && id.back() == '_') id.pop_back();
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id.front())) || stKeywords().count(upper(id)))
    id = "in_" + id;
  while (id.back() == '_') id.pop_back();
  return id;
}

// ---- the model as terms ------------------------------------------------------------------------

/// One regressor of a regression model with its PLC / ST names.
struct Term {
  std::size_t input = 0;
  double tauMin = 0.0;
  double coef = 0.0;
  std::string column;  ///< csv column / grid axis name
  std::string stVar;   ///< ST variable that holds u_t (the input itself or its filter)
};

std::string tauText(double tauMin) {
  return g6(tauMin) + " min";
}

/// The names the ST block and the PLC formulas use; inputs first (stInputNames), then the internal ones.
struct Names {
  std::vector<std::string> input, ref;
  std::vector<Term> terms;
};

Names names(const ThermalModel& m) {
  Names n;
  n.input = stInputNames(m);
  std::set<std::string> used;
  for (const auto& s : n.input) used.insert(upper(s));
  for (const char* r : {"dt_s", "reset", "error_um", "comp_um", "limited", "started", "z", "yn"})
    used.insert(upper(r));
  auto unique = [&](std::string base) {
    std::string s = base;
    for (int k = 2; used.count(upper(s)); ++k) s = base + "_" + std::to_string(k);
    used.insert(upper(s));
    return s;
  };
  for (const auto& s : n.input) n.ref.push_back(unique("ref_" + s));
  if (isRegression(m.kind)) {
    for (std::size_t t = 0; t < m.regression.terms.size(); ++t) {
      Term term;
      term.input = m.regression.terms[t].input;
      term.tauMin = m.regression.terms[t].tauMin;
      term.coef = m.regression.coef[t];
      const std::string& col = m.inputs[term.input];
      if (term.tauMin > 0.0) {
        term.column = "delta_lag" + exact(term.tauMin) + "min_" + col;
        term.stVar = unique("lag_" + n.input[term.input]);
      } else {
        term.column = "delta_" + col;
        term.stVar = n.input[term.input];
      }
      n.terms.push_back(std::move(term));
    }
  }
  return n;
}

bool hasLag(const Names& n) {
  return std::any_of(n.terms.begin(), n.terms.end(), [](const Term& t) { return t.tauMin > 0.0; });
}

struct Units {
  std::string target;      ///< "um" or what the name says
  double toMm = 0.001;     ///< target unit -> mm (um assumed when the name does not say)
  std::string assumption;  ///< a header line when the unit is assumed
};

Units targetUnits(const ThermalModel& m) {
  Units u;
  const std::string t = unitOfName(m.target);
  if (lower(t) == "mm") {
    u.target = "mm";
    u.toMm = 1.0;
  } else if (lower(t) == "nm") {
    u.target = "nm";
    u.toMm = 1e-6;
  } else {
    u.target = "um";
    if (lower(t) != "um")
      u.assumption = "The target column '" + m.target + "' does not state its unit: um is assumed.";
  }
  return u;
}

std::string inputUnit(const std::string& column) {
  const std::string u = unitOfName(column);
  return u.empty() ? "its unit" : u;
}

double samplePeriodS(const ThermalModel& m, const ControlExportOptions& o) {
  return o.samplePeriodS > 0.0 ? o.samplePeriodS : m.timeUnitMin * 60.0;
}

// ---- the header every form shares ----------------------------------------------------------------

std::vector<std::string> modelLines(const ThermalModel& m, ControlFormat f, const ControlExportOptions& o,
                                    const Names& n) {
  const Units u = targetUnits(m);
  const std::string file = std::filesystem::path(o.source).filename().string();
  std::vector<std::string> l;
  l.push_back("Metrofit thermal compensation, form '" + std::string(toString(f)) +
              "' (metrofit-cli thermal export).");
  l.push_back("Model: " + std::string(toString(m.kind)) + " from " + file + ", target " + m.target + " [" +
              u.target + "].");
  if (!u.assumption.empty()) l.push_back(u.assumption);
  std::string in = "Inputs:";
  for (std::size_t j = 0; j < m.inputs.size(); ++j)
    in += std::string(j ? ", " : " ") + m.inputs[j] + " [" + inputUnit(m.inputs[j]) + "]";
  l.push_back(in + ".");
  l.push_back("Reference: the model predicts the change of " + m.target +
              " since a reference sample (it was fitted on changes since the first row of its log):");
  l.push_back(
      "  r_j = the inputs at the first sample after a reset (power-on, or the machine at its reference "
      "state).");
  if (isRegression(m.kind)) {
    std::string eq = "Model: e = " + g6(m.regression.intercept);
    for (const Term& t : n.terms) {
      eq += (t.coef < 0 ? " - " : " + ") + g6(std::abs(t.coef)) + " * (" +
            (t.tauMin > 0.0 ? "L[" + m.inputs[t.input] + ", " + tauText(t.tauMin) + "]" : m.inputs[t.input]) +
            " - r)";
    }
    l.push_back(eq + "   [" + u.target + "]");
    l.push_back("  (6 significant digits here; the code below has the exact coefficients).");
    if (hasLag(n)) {
      const double ts = samplePeriodS(m, o);
      l.push_back(
          "Lag L[x, tau]: first-order, discretised by exact zero-order hold with the input held at its "
          "new value:");
      l.push_back("  s(k) = s(k-1) + (1 - exp(-dt / tau)) * (x(k) - s(k-1)),  s = x at the reference;");
      l.push_back("  the continuous lag's step response 1 - exp(-t / tau) at every sample, for any dt.");
      for (const Term& t : n.terms) {
        if (!(t.tauMin > 0.0)) continue;
        l.push_back("  " + m.inputs[t.input] + ": tau = " + tauText(t.tauMin) + " = " +
                    exact(t.tauMin * 60.0) + " s; for dt = " + g6(ts) +
                    " s, 1 - exp(-dt / tau) = " + exact(-std::expm1(-ts / (t.tauMin * 60.0))));
      }
    }
  } else if (m.kind == ThermalModelKind::Mlp) {
    l.push_back("Model: N-" + std::to_string(m.mlp.hidden()) +
                "-1 MLP (logistic hidden layer, linear output) on the input changes x_j - r_j, inputs and "
                "output scaled by their training ranges (mapminmax).");
  }
  l.push_back("Sample period: the model's log was sampled every " + g6(m.timeUnitMin * 60.0) +
              " s (mean step of the fitting rows).");
  l.push_back("Sign: e is the predicted thermal error (the drift of " + m.target +
              " as measured); the compensation is -e. Check the sign on the machine with one warm-up: the "
              "compensated drift must shrink, not double.");
  if (m.kind == ThermalModelKind::Mlp) {
    std::string r = "Limits: the network was trained on input changes";
    for (std::size_t j = 0; j < m.inputs.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      r += std::string(j ? "," : "") + " " + m.inputs[j] + " " + g6(m.mlp.inMin(i)) + ".." +
           g6(m.mlp.inMax(i));
    }
    l.push_back(r + "; outside them it extrapolates.");
  } else {
    l.push_back(
        "Limits: the model is linear in its regressors and extrapolates; the model file does not store "
        "the fitted log's range: keep the inputs within the range of the log it was fitted on.");
  }
  return l;
}

[[noreturn]] void refuse(const ThermalModel& m, ControlFormat f, const ControlExportOptions& o,
                         const std::string& why) {
  throw ValidationError(
      ErrorContext{o.source, 0, 0, "model"},
      "the " + std::string(toString(m.kind)) + " model cannot be exported as " + toString(f) + ": " + why);
}

// ---- st ------------------------------------------------------------------------------------------------

std::string stHeader(const std::vector<std::string>& lines) {
  std::string out = "(*\n";
  for (const auto& l : lines) out += "   " + commentSafe(l) + "\n";
  out += "*)\n";
  return out;
}

std::string exportSt(const ThermalModel& m, const ControlExportOptions& o, const Names& n) {
  const Units u = targetUnits(m);
  std::vector<std::string> h = modelLines(m, ControlFormat::St, o, n);
  h.push_back(
      "IEC 61131-3 Structured Text, REAL (32-bit) arithmetic. Call the block once per sample with "
      "dt_s = seconds since the previous call (dt_s > 0; " +
      std::string(hasLag(n) ? "the lag filters use it" : "unused by this static model") + ").");
  h.push_back(
      "reset = TRUE (or the first call) takes the present inputs as the reference r_j and starts the "
      "filters there.");
  if (hasLag(n))
    h.push_back(
        "The filters hold L[x] - r (0 at the reference): filtering the change keeps REAL's 24-bit "
        "mantissa for the change, not for the absolute value.");
  h.push_back("Outputs: error_um = e, comp_um = -e limited to +-" + g6(o.limitUm) +
              " um (limited = TRUE while it is). Units: " + u.target +
              " as the target (error_um / comp_um "
              "carry the target's unit).");
  h.push_back(
      "A sensor fault (open circuit, out of range) is the PLC's to detect: hold or reset the block then.");

  std::string s = stHeader(h);
  s += "FUNCTION_BLOCK FB_METROFIT_THERMAL_" + stIdentifier(m.target) + "\n";
  s += "VAR_INPUT\n";
  for (std::size_t j = 0; j < m.inputs.size(); ++j)
    s += "    " + n.input[j] + " : REAL; (* " + commentSafe(m.inputs[j]) + " [" +
         commentSafe(inputUnit(m.inputs[j])) + "] *)\n";
  s += "    dt_s : REAL; (* seconds since the previous call: the sample period *)\n";
  s += "    reset : BOOL; (* TRUE: the present inputs become the reference *)\n";
  s += "END_VAR\n";
  s += "VAR_OUTPUT\n";
  s += "    error_um : REAL; (* predicted thermal error of " + commentSafe(m.target) +
       " since the reference *)\n";
  s += "    comp_um : REAL; (* compensation = -error_um, limited *)\n";
  s += "    limited : BOOL; (* TRUE while comp_um is limited *)\n";
  s += "END_VAR\n";
  s += "VAR\n";
  s += "    started : BOOL := FALSE;\n";
  for (std::size_t j = 0; j < m.inputs.size(); ++j) s += "    " + n.ref[j] + " : REAL;\n";
  for (const Term& t : n.terms)
    if (t.tauMin > 0.0)
      s += "    " + t.stVar + " : REAL; (* " + commentSafe(m.inputs[t.input]) + " through a " +
           tauText(t.tauMin) + " lag, minus its reference *)\n";
  if (m.kind == ThermalModelKind::Mlp) {
    for (std::size_t j = 0; j < m.inputs.size(); ++j) s += "    n_" + n.input[j] + " : REAL;\n";
    s += "    z : REAL;\n    yn : REAL;\n";
  }
  s += "END_VAR\n";
  s += "IF reset OR NOT started THEN\n";
  for (std::size_t j = 0; j < m.inputs.size(); ++j) s += "    " + n.ref[j] + " := " + n.input[j] + ";\n";
  for (const Term& t : n.terms)
    if (t.tauMin > 0.0) s += "    " + t.stVar + " := 0.0;\n";
  s += "    started := TRUE;\n";
  if (hasLag(n)) {
    s += "ELSE\n";
    for (const Term& t : n.terms) {
      if (!(t.tauMin > 0.0)) continue;
      const std::string& x = n.input[t.input];
      s += "    " + t.stVar + " := " + t.stVar + " + (1.0 - EXP(-dt_s / " + stReal(t.tauMin * 60.0) +
           ")) * (" + x + " - " + n.ref[t.input] + " - " + t.stVar + ");\n";
    }
  }
  s += "END_IF;\n";
  if (isRegression(m.kind)) {
    s += "error_um := " + stReal(m.regression.intercept);
    for (const Term& t : n.terms) {
      s += "\n    " + std::string(t.coef < 0 ? "- " : "+ ") + stReal(std::abs(t.coef)) + " * " +
           (t.tauMin > 0.0 ? t.stVar : "(" + t.stVar + " - " + n.ref[t.input] + ")");
    }
    s += ";\n";
  } else {
    const Mlp& net = m.mlp;
    for (std::size_t j = 0; j < m.inputs.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      const double lo = net.inMin(i), scale = 2.0 / (net.inMax(i) - net.inMin(i));
      s += "n_" + n.input[j] + " := (" + n.input[j] + " - " + n.ref[j] + " - " + stReal(lo) + ") * " +
           stReal(scale) + " - 1.0;\n";
    }
    s += "yn := " + stReal(net.v0) + ";\n";
    for (Eigen::Index h2 = 0; h2 < net.w.rows(); ++h2) {
      s += "z := " + stReal(net.c(h2));
      for (std::size_t j = 0; j < m.inputs.size(); ++j) {
        const double w = net.w(h2, static_cast<Eigen::Index>(j));
        s += std::string(w < 0 ? " - " : " + ") + stReal(std::abs(w)) + " * n_" + n.input[j];
      }
      s += ";\n";
      s += "IF z < -80.0 THEN\n    z := -80.0;\nEND_IF;\n";
      s += "yn := yn + " + stReal(net.v(h2)) + " / (1.0 + EXP(-z));\n";
    }
    s += "error_um := " + stReal(net.outMin) + " + (yn + 1.0) * " + stReal(0.5 * (net.outMax - net.outMin)) +
         ";\n";
  }
  const std::string lim = stReal(o.limitUm);
  s += "comp_um := -error_um;\n";
  s += "limited := FALSE;\n";
  s += "IF comp_um > " + lim + " THEN\n    comp_um := " + lim + ";\n    limited := TRUE;\n";
  s += "ELSIF comp_um < -" + lim + " THEN\n    comp_um := -" + lim + ";\n    limited := TRUE;\n";
  s += "END_IF;\n";
  s += "END_FUNCTION_BLOCK\n";
  return s;
}

// ---- the vendor forms: the PLC computes e, the control applies it --------------------------------------

/// Comment lines with `prefix` ("; ", "# ").
std::string commentBlock(const std::vector<std::string>& lines, const std::string& prefix) {
  std::string out;
  for (const auto& l : lines) out += prefix + commentSafe(l) + "\n";
  return out;
}

/// The PLC's part, in the vendor forms' headers: the filters and e with the exact coefficients.
std::vector<std::string> plcLines(const ThermalModel& m, const ControlExportOptions& o, const Names& n,
                                  double scale, const std::string& unit) {
  std::vector<std::string> l;
  const double ts = samplePeriodS(m, o);
  l.push_back("The PLC's part (every sample period T, here T = " + g6(ts) + " s):");
  l.push_back("  at a reset: ref_x := x for every input, and every filter := its input;");
  for (const Term& t : n.terms) {
    if (!(t.tauMin > 0.0)) continue;
    l.push_back("  " + t.stVar + " := " + t.stVar + " + " + exact(-std::expm1(-ts / (t.tauMin * 60.0))) +
                " * (" + n.input[t.input] + " - " + t.stVar + ")   (1 - exp(-T / " + exact(t.tauMin * 60.0) +
                " s); another T: recompute)");
  }
  std::string e = "  e := " + exact(m.regression.intercept * scale);
  for (const Term& t : n.terms)
    e += std::string(t.coef < 0 ? " - " : " + ") + exact(std::abs(t.coef) * scale) + " * (" + t.stVar +
         " - " + n.ref[t.input] + ")";
  l.push_back(e + "   [" + unit + "]");
  std::string vars;
  for (std::size_t j = 0; j < m.inputs.size(); ++j)
    if (n.input[j] != m.inputs[j])
      vars += std::string(vars.empty() ? "" : ",") + " " + n.input[j] + " = " + m.inputs[j];
  if (!vars.empty()) l.push_back("  where" + vars + ".");
  l.push_back("  The inputs in their units, as the model's columns.");
  return l;
}

int axisNumber(char axis) {
  const std::string order = "XYZABCUVW";
  return static_cast<int>(order.find(axis)) + 1;
}

std::string exportSiemens(const ThermalModel& m, const ControlExportOptions& o, const Names& n) {
  const Units u = targetUnits(m);
  const std::string ax = std::string(1, o.axis) + "1";
  std::vector<std::string> h = modelLines(m, ControlFormat::Siemens, o, n);
  h.push_back(
      "Form: SINUMERIK temperature compensation (function manual Extended Functions, K3): the error "
      "line dK = K0 + tan(beta) * (P - P0) per axis,");
  h.push_back(
      "  K0 = SD43900 $SA_TEMP_COMP_ABS_VALUE (mm, position-independent), tan(beta) = SD43910 "
      "$SA_TEMP_COMP_SLOPE, P0 = SD43920 $SA_TEMP_COMP_REF_POSITION (mm).");
  h.push_back(
      "Assumptions: the model has no position term, so only the position-independent part is used "
      "(MD32750 $MA_TEMP_COMP_TYPE bit 0; slope 0, reference position 0);");
  h.push_back(
      "  K0 is the error value of the line (the predicted error e in mm), which the control corrects; "
      "axis " +
      ax + " is the compensated one.");
  h.push_back(
      "  MD32760 $MA_COMP_ADD_VELO_FACTOR limits how fast a change of K0 is traversed: keep its default "
      "or set it for your axis.");
  h.push_back(
      "The PLC computes K0 from the temperatures every cycle and writes SD43900 (e.g. PUT, FB3, or a "
      "synchronous action): the NC does not filter or reference the sensors.");
  const auto plc = plcLines(m, o, n, u.toMm, "mm");
  h.insert(h.end(), plc.begin(), plc.end());
  h.push_back("  SD43900 $SA_TEMP_COMP_ABS_VALUE[" + ax + "] := e");
  std::string s = commentBlock(h, "; ");
  s += "$MA_TEMP_COMP_TYPE[" + ax + "]=1\n";
  s += "$SA_TEMP_COMP_SLOPE[" + ax + "]=0\n";
  s += "$SA_TEMP_COMP_REF_POSITION[" + ax + "]=0\n";
  s += "$SA_TEMP_COMP_ABS_VALUE[" + ax + "]=" + exact(m.regression.intercept * u.toMm) +
       " ; e at the reference; the PLC overwrites it\n";
  s += "M17\n";
  return s;
}

std::string exportHeidenhain(const ThermalModel& m, const ControlExportOptions& o, const Names& n) {
  const Units u = targetUnits(m);
  // PLC words: the sensors, their reference values, the filtered sensors (placeholders to renumber).
  std::vector<std::string> wordOf(m.inputs.size()), refWord(m.inputs.size());
  for (std::size_t j = 0; j < m.inputs.size(); ++j) {
    wordOf[j] = "W" + std::to_string(1000 + 2 * j);
    refWord[j] = "W" + std::to_string(1100 + 2 * j);
  }
  std::vector<std::string> termWord;
  int filters = 0;
  for (const Term& t : n.terms)
    termWord.push_back(t.tauMin > 0.0 ? "W" + std::to_string(1200 + 2 * filters++) : wordOf[t.input]);
  std::vector<std::string> h = modelLines(m, ControlFormat::Heidenhain, o, n);
  h.push_back(
      "Form: the TEMPCOMP column of the kinematics description table (TNC 426/430 and iTNC 530 "
      "technical manuals, 'Permanently effective temperature compensation'):");
  h.push_back(
      "  a formula over PLC words giving the transformation's length, e.g. TEMPCOMP = 300 + 3.45e-3 * "
      "(W486 - 20).");
  h.push_back(
      "Assumptions: the formula below is the thermal change in mm (the predicted error e): enter "
      "NOMINAL + formula in the TEMPCOMP column of the");
  h.push_back("  transformation along " + std::string(1, o.axis) +
              " that carries the drift (NOMINAL: that line's value); a growth in +" + std::string(1, o.axis) +
              " must be a drift in +" + std::string(1, o.axis) + " of " + m.target + ".");
  std::string words = "PLC words (placeholders: renumber to your PLC):";
  for (std::size_t j = 0; j < m.inputs.size(); ++j)
    words += " " + wordOf[j] + " = " + m.inputs[j] + ", " + refWord[j] + " = its reference;";
  for (std::size_t t = 0; t < n.terms.size(); ++t)
    if (n.terms[t].tauMin > 0.0)
      words += " " + termWord[t] + " = " + m.inputs[n.terms[t].input] + " through the " +
               tauText(n.terms[t].tauMin) + " lag;";
  h.push_back(words);
  h.push_back(
      "The PLC's part: scale each sensor into its word in the model's units (a word holding 0.1 degC "
      "needs the coefficient / 10), capture the references at a reset,");
  h.push_back(
      "  and run the filters (below). The TNC evaluates the formula; it does not filter or reference.");
  const auto plc = plcLines(m, o, n, u.toMm, "mm");
  h.insert(h.end(), plc.begin(), plc.end());
  std::string s = commentBlock(h, "; ");
  std::string f = "TEMPCOMP = " + exact(m.regression.intercept * u.toMm);
  for (std::size_t t = 0; t < n.terms.size(); ++t) {
    const Term& term = n.terms[t];
    f += std::string(term.coef < 0 ? " - " : " + ") + exact(std::abs(term.coef) * u.toMm) + " * (" +
         termWord[t] + " - " + refWord[term.input] + ")";
  }
  s += f + "\n";
  return s;
}

std::string exportIsg(const ThermalModel& m, const ControlExportOptions& o, const Names& n) {
  const Units u = targetUnits(m);
  const int axisNo = axisNumber(o.axis);
  std::vector<std::string> h = modelLines(m, ControlFormat::Isg, o, n);
  h.push_back(
      "Form: ISG kernel / Beckhoff TwinCAT CNC temperature compensation (axis parameters P-AXIS-00271 "
      "to 00274): ds(T, s) = offset(T) + coefficient(T) * (s - s0),");
  h.push_back(
      "  temp_comp_offset_0 [0.1 um] the deviation at the reference position s0 = temp_comp_position_0 "
      "[0.1 um], temp_comp_coefficient [um/m].");
  h.push_back(
      "Assumptions: the model has no position term: coefficient 0 and s0 = 0; the offset is the "
      "predicted error e, which the control corrects;");
  h.push_back("  kopf.achs_nr " + std::to_string(axisNo) + " is axis " + std::string(1, o.axis) +
              " in the order X Y Z A B C U V W: set your logical axis number.");
  h.push_back(
      "The PLC computes e from the temperatures every cycle and writes temp_comp_offset_0 (ADS write to "
      "the GEO task, or a parameter download): offset_0 := round(e * 10) in 0.1 um.");
  const auto plc = plcLines(m, o, n, u.toMm * 1000.0, "um");
  h.insert(h.end(), plc.begin(), plc.end());
  std::string s = commentBlock(h, "# ");
  s += "kopf.achs_nr " + std::to_string(axisNo) + "\n";
  s += "#\n";
  s += "# temperature compensation on, position-independent\n";
  s += "lr_param.temp_comp 1\n";
  s += "lr_param.temp_comp_position_0 0\n";
  s += "lr_param.temp_comp_offset_0 " + std::to_string(std::lround(m.regression.intercept * u.toMm * 1e4)) +
       "\n";
  s += "lr_param.temp_comp_coefficient 0\n";
  return s;
}

// ---- csv ----------------------------------------------------------------------------------------------

struct Axis {
  std::string column;
  std::vector<double> values;
};

std::vector<double> gridValues(const ControlGridAxis& g) {
  std::vector<double> v;
  const double n = std::floor((g.to - g.from) / g.step + 1e-9);
  for (long k = 0; k <= static_cast<long>(n); ++k) v.push_back(g.from + static_cast<double>(k) * g.step);
  return v;
}

std::string exportCsv(const ThermalModel& m, const ControlExportOptions& o, const Names& n) {
  const Units u = targetUnits(m);
  std::vector<Axis> axes;
  std::vector<std::string> inputOfAxis;
  if (isRegression(m.kind)) {
    for (const Term& t : n.terms) {
      axes.push_back({t.column, {}});
      inputOfAxis.push_back(m.inputs[t.input]);
    }
  } else {
    for (const auto& in : m.inputs) {
      axes.push_back({"delta_" + in, {}});
      inputOfAxis.push_back(in);
    }
  }
  for (const ControlGridAxis& g : o.grid) {
    bool found = false;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      if (g.input == axes[a].column || g.input == inputOfAxis[a]) {
        axes[a].values = gridValues(g);
        found = true;
      }
    }
    if (!found) {
      std::string have;
      for (std::size_t a = 0; a < axes.size(); ++a) have += (a ? ", " : "") + axes[a].column;
      throw OptionsError(
          ErrorContext{{}, 0, 0, "--grid"},
          "'" + g.input + "' is not an input or a table column of the model (it has: " + have + ")");
    }
  }
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (!axes[a].values.empty()) continue;
    ControlGridAxis g{inputOfAxis[a], 0.0, 10.0, 10.0 / (kDefaultGridPoints - 1)};
    if (m.kind == ThermalModelKind::Mlp) {
      const auto i = static_cast<Eigen::Index>(a);
      g.from = m.mlp.inMin(i);
      g.to = m.mlp.inMax(i);
      g.step = (g.to - g.from) / (kDefaultGridPoints - 1);
    }
    axes[a].values = gridValues(g);
    axes[a].values.resize(kDefaultGridPoints, g.to);  // the last point exactly at `to`
    axes[a].values.back() = g.to;
  }
  double rows = 1.0;
  for (const Axis& a : axes) rows *= static_cast<double>(a.values.size());
  if (rows > static_cast<double>(o.maxTableRows)) {
    throw OptionsError(ErrorContext{{}, 0, 0, "--grid"},
                       "the table would have " + g6(rows) + " rows (at most " +
                           std::to_string(o.maxTableRows) + "): give coarser grids");
  }

  std::vector<std::string> h = modelLines(m, ControlFormat::Csv, o, n);
  h.push_back(
      "Form: a table of e and the compensation -e on a grid of the regressors (every combination; "
      "the last column varies fastest), for controls that take tables.");
  if (isRegression(m.kind)) {
    h.push_back(
        "Columns delta_<input>: the input's change since the reference; delta_lag<tau>min_<input>: the "
        "input through the lag, minus the reference (the PLC runs the filter).");
    h.push_back("The model is linear in these columns: interpolating the table linearly is exact inside it.");
  } else {
    h.push_back(
        "Columns delta_<input>: the input's change since the reference. The network is nonlinear: the "
        "table is exact at its points only; interpolate on a fine enough grid.");
  }
  h.push_back(
      "Default grid: " + std::string(m.kind == ThermalModelKind::Mlp ? "the training range" : "0..10") +
      " in " + std::to_string(kDefaultGridPoints) +
      " points per axis (in the input's unit); --grid sets others. Values: 6 decimals, " + u.target + ".");
  CsvWriter w;
  for (const auto& l : h) w.comment(commentSafe(l));
  std::vector<std::string> head;
  for (const Axis& a : axes) head.push_back(a.column);
  head.push_back("error_" + u.target);
  head.push_back("compensation_" + u.target);
  w.row(head);
  std::vector<std::size_t> idx(axes.size(), 0);
  std::vector<double> x(axes.size());
  for (;;) {
    for (std::size_t a = 0; a < axes.size(); ++a) x[a] = axes[a].values[idx[a]];
    double e = 0.0;
    if (isRegression(m.kind)) {
      e = m.regression.intercept;
      for (std::size_t t = 0; t < n.terms.size(); ++t) e += n.terms[t].coef * x[t];
    } else {
      e = m.mlp.predict(x);
    }
    std::vector<std::string> row;
    for (double v : x) row.push_back(exact(v));
    row.push_back(num::fixed(e + 0.0, 6));
    row.push_back(num::fixed(-e + 0.0, 6));
    w.row(row);
    std::size_t a = axes.size();
    while (a > 0) {
      --a;
      if (++idx[a] < axes[a].values.size()) break;
      idx[a] = 0;
      if (a == 0) return w.text();
    }
    if (axes.empty()) return w.text();
  }
}

}  // namespace

const char* toString(ControlFormat f) {
  switch (f) {
    case ControlFormat::St:
      return "st";
    case ControlFormat::Siemens:
      return "siemens";
    case ControlFormat::Heidenhain:
      return "heidenhain";
    case ControlFormat::Isg:
      return "isg";
    case ControlFormat::Csv:
      return "csv";
  }
  return "?";
}

ControlFormat controlFormat(const std::string& name, const std::string& field) {
  for (ControlFormat f : kAllControlFormats)
    if (name == toString(f)) return f;
  throw OptionsError(ErrorContext{{}, 0, 0, field},
                     "'" + name + "' is not a control form (st, siemens, heidenhain, isg, csv)");
}

bool ControlExportOptions::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (std::string("XYZABCUVW").find(axis) == std::string::npos || axis == 0)
    return no(std::string("axis must be one of X, Y, Z, A, B, C, U, V, W, got '") + axis + "'");
  if (!(samplePeriodS >= 0.0) || !std::isfinite(samplePeriodS))
    return no("the sample period must be a positive number of seconds, got " + num::shortest(samplePeriodS));
  if (!(limitUm > 0.0) || !std::isfinite(limitUm))
    return no("the limit must be a positive number of um, got " + num::shortest(limitUm));
  for (const ControlGridAxis& g : grid) {
    if (!std::isfinite(g.from) || !std::isfinite(g.to) || !(g.to > g.from) || !(g.step > 0.0) ||
        !std::isfinite(g.step))
      return no("the grid of '" + g.input + "' must run from a number to a larger one by a positive step");
  }
  if (maxTableRows == 0) return no("maxTableRows must be positive");
  return true;
}

std::vector<std::string> stInputNames(const ThermalModel& m) {
  std::vector<std::string> out;
  std::set<std::string> used;
  for (const char* r : {"dt_s", "reset", "error_um", "comp_um", "limited", "started", "z", "yn"})
    used.insert(upper(r));
  for (const auto& in : m.inputs) {
    const std::string base = stIdentifier(in);
    std::string s = base;
    for (int k = 2; used.count(upper(s)); ++k) s = base + "_" + std::to_string(k);
    used.insert(upper(s));
    out.push_back(s);
  }
  return out;
}

std::string controlExportRefusal(const ThermalModel& m, ControlFormat f) {
  if (isGrey(m.kind)) {
    return std::string("its prediction (GMC(1,N) Eq. 2.2") +
           (m.kind == ThermalModelKind::Gnnmci ? ", which the GNNMCI network reproduces" : "") +
           ") is the inverse accumulation of a convolution over the whole log from its first row with a "
           "start transient, which no control form here holds; fit linear, lag or dlag (thermal fit --model "
           "lag) "
           "for a control";
  }
  if (m.kind == ThermalModelKind::Mlp && f != ControlFormat::St && f != ControlFormat::Csv) {
    return "the MLP is nonlinear in the temperatures (" + std::to_string(m.mlp.hidden()) +
           " logistic neurons) and the " + toString(f) +
           " form is an offset the PLC writes from a formula linear in its values; export it as st (a "
           "function "
           "block) or csv (a table)";
  }
  return {};
}

std::string exportControl(const ThermalModel& m, ControlFormat f, const ControlExportOptions& o) {
  requireValid(o, "thermal export options");
  if (const std::string why = controlExportRefusal(m, f); !why.empty()) refuse(m, f, o, why);
  if (isRegression(m.kind)) {
    if (m.regression.coef.size() != m.regression.terms.size())
      throw ValidationError(ErrorContext{o.source, 0, 0, "regression"},
                            "terms and coefficients differ in number");
    if (!std::isfinite(m.regression.intercept))
      throw ValidationError(ErrorContext{o.source, 0, 0, "intercept"}, "must be a finite number");
    for (double c : m.regression.coef)
      if (!std::isfinite(c))
        throw ValidationError(ErrorContext{o.source, 0, 0, "coefficient"}, "must be a finite number");
  }
  const Names n = names(m);
  switch (f) {
    case ControlFormat::St:
      return exportSt(m, o, n);
    case ControlFormat::Siemens:
      return exportSiemens(m, o, n);
    case ControlFormat::Heidenhain:
      return exportHeidenhain(m, o, n);
    case ControlFormat::Isg:
      return exportIsg(m, o, n);
    case ControlFormat::Csv:
      return exportCsv(m, o, n);
  }
  return {};
}

}  // namespace metrofit::thermal
