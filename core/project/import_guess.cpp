#include "core/project/import_guess.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <set>

#include "core/io/calypso.h"
#include "core/io/cmm_text_report.h"
#include "core/io/dfq.h"
#include "core/io/mtconnect.h"
#include "core/io/qif.h"
#include "core/io/units.h"
#include "core/matching/hole_table.h"
#include "core/setup/report.h"

namespace metrofit {
namespace {

/// Lower case and without diacritics (the German and Polish letters; "ß" -> "ss"), so that
/// "Prędkość", "PREDKOSC" and "predkosc" compare equal. Other bytes are kept.
std::string fold(std::string_view s) {
  static const std::pair<const char*, const char*> letters[] = {
      {"\xC3\x84", "a"}, {"\xC3\xA4", "a"},  {"\xC3\x96", "o"}, {"\xC3\xB6", "o"}, {"\xC3\x9C", "u"},
      {"\xC3\xBC", "u"}, {"\xC3\x9F", "ss"}, {"\xC4\x84", "a"}, {"\xC4\x85", "a"}, {"\xC4\x86", "c"},
      {"\xC4\x87", "c"}, {"\xC4\x98", "e"},  {"\xC4\x99", "e"}, {"\xC5\x81", "l"}, {"\xC5\x82", "l"},
      {"\xC5\x83", "n"}, {"\xC5\x84", "n"},  {"\xC3\x93", "o"}, {"\xC3\xB3", "o"}, {"\xC5\x9A", "s"},
      {"\xC5\x9B", "s"}, {"\xC5\xB9", "z"},  {"\xC5\xBA", "z"}, {"\xC5\xBB", "z"}, {"\xC5\xBC", "z"}};
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    bool replaced = false;
    for (const auto& [from, to] : letters) {
      const std::string_view f(from);
      if (s.substr(i, f.size()) == f) {
        out += to;
        i += f.size();
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(s[i])));
    ++i;
  }
  return out;
}

std::string normalUnit(std::string u) {
  u.erase(std::remove_if(u.begin(), u.end(), [](unsigned char c) { return std::isspace(c); }), u.end());
  const std::string l = fold(u);
  if (l == "\xC2\xB5m" || l == "\xCE\xBCm" || l == "um" || l == "mym" || l == "mikron" || l == "micron")
    return "um";
  if (l == "mm" || l == "nm") return l;
  if (l == "\xC2\xB0"
           "c" ||
      l == "degc" || l == "c")
    return "degC";
  if (l == "s" || l == "sec" || l == "sek") return "s";
  if (l == "min") return "min";
  if (l == "h" || l == "std") return "h";
  if (l == "1/min" || l == "u/min" || l == "rpm" || l == "min-1" || l == "min^-1" || l == "obr/min" ||
      l == "min\xE2\x81\xBB\xC2\xB9")
    return "rpm";
  if (l == "\xC2\xB0" || l == "deg") return "deg";
  return {};
}

bool hasWord(const ColumnName& c, std::initializer_list<const char*> words) {
  for (const std::string& w : c.words)
    for (const char* x : words)
      if (w == x) return true;
  return false;
}

bool onlyWords(const ColumnName& c, std::initializer_list<const char*> words) {
  if (c.words.empty()) return false;
  for (const std::string& w : c.words) {
    bool known = false;
    for (const char* x : words) known = known || w == x;
    if (!known) return false;
  }
  return true;
}

bool isTime(const ColumnName& c) {
  return hasWord(c, {"time", "zeit", "czas", "uhrzeit"});
}
bool isNominal(const ColumnName& c) {
  return hasWord(c, {"nominal", "nom", "soll", "sollwert", "nennmass", "nennwert", "nominalna", "nominalny",
                     "nominalne", "nominalnie", "wartosc_nominalna", "nenn"});
}
bool isActual(const ColumnName& c) {
  return hasWord(c, {"measured", "meas", "actual", "act", "ist", "istwert", "aktuell", "gemessen",
                     "zmierzona", "zmierzony", "zmierzone", "rzeczywista", "rzeczywisty", "rzeczywiste"});
}
bool isTolerance(const ColumnName& c) {
  return hasWord(c, {"tol", "toleranz", "tolerance", "tolerancja", "tolerancji"});
}
bool isLowerTol(const ColumnName& c) {
  return (isTolerance(c) && hasWord(c, {"lower", "low", "untere", "unten", "dolna", "min", "minus"})) ||
         hasWord(c, {"ut", "utol", "lt", "tol-", "-tol", "lsl", "ugw", "ltol"});
}
bool isUpperTol(const ColumnName& c) {
  return (isTolerance(c) && hasWord(c, {"upper", "up", "obere", "oben", "gorna", "max", "plus"})) ||
         hasWord(c, {"ot", "otol", "tol+", "+tol", "usl", "ogw"});
}
/// The axis letter a column names ("Soll X", "x_ist", "X"), 0 when none or more than one.
char axisOf(const ColumnName& c) {
  char axis = 0;
  for (const std::string& w : c.words) {
    if (w == "x" || w == "y" || w == "z") {
      if (axis) return 0;
      axis = w[0];
    }
  }
  return axis;
}
/// Unit allowed for a role in mm: none, or a length (read in mm: CsvTable::mapColumns converts).
bool mmOrNone(const ColumnName& c) {
  return c.unit.empty() || unitFactor(c.unit, "mm").has_value();
}

std::vector<std::string> rolesOf(const std::string& kind) {
  if (kind == "thermal-log") return {"time_s", "time_min", "time_h", "spindle_rpm"};
  if (kind == "probe-points") return {"id", "surface", "qx", "qy", "qz", "px", "py", "pz", "nx", "ny", "nz"};
  if (kind == "circular-test")
    return {"x_cmd_mm",     "y_cmd_mm",     "x_meas_mm", "y_meas_mm", "angle_deg",
            "deviation_um", "deviation_mm", "direction", "run",       "radius_mm"};
  if (kind == "cmm-report")
    return {"part", "time_min", "dimension", "nominal_mm", "measured_mm", "lower_tol_mm", "upper_tol_mm"};
  return {};
}

/// The role a column is, for `kind`; "" when none.
std::string roleFor(const std::string& kind, const std::string& column, bool rawPoints) {
  const ColumnName c = splitColumnName(column);
  const std::string folded = fold(column);
  for (const std::string& r : rolesOf(kind))
    if (folded == r) return r;  // "ID" -> "id", "QX" -> "qx"
  if (kind == "thermal-log") {
    if (isTime(c) && (c.unit == "s" || c.unit == "min" || c.unit == "h")) return "time_" + c.unit;
    // Words that mean the spindle's speed only ("Prędkość" alone may be a feed: with "obrotowa" or
    // "wrzeciona"), or any column in 1/min.
    const bool speedWord = hasWord(c, {"drehzahl", "spindeldrehzahl", "obroty"}) ||
                           (hasWord(c, {"predkosc"}) && hasWord(c, {"obrotowa", "wrzeciona"}));
    if ((speedWord && (c.unit.empty() || c.unit == "rpm")) || (c.unit == "rpm" && !isTime(c)))
      return "spindle_rpm";
    return {};
  }
  if (kind == "cmm-report") {
    if (isTime(c)) return unitFactor(c.unit, "min") ? "time_min" : "";
    if (isLowerTol(c) && mmOrNone(c)) return "lower_tol_mm";
    if (isUpperTol(c) && mmOrNone(c)) return "upper_tol_mm";
    if (isNominal(c) && mmOrNone(c)) return "nominal_mm";
    if (isActual(c) && mmOrNone(c)) return "measured_mm";
    if (hasWord(c, {"part", "teil", "bauteil", "werkstuck", "werkstueck", "czesc", "detal", "przedmiot"}))
      return "part";
    if (hasWord(c, {"dimension", "dim", "feature", "characteristic", "merkmal", "mass", "wymiar", "cecha",
                    "charakterystyka"}))
      return "dimension";
    return {};
  }
  if (kind == "probe-points") {
    const char axis = axisOf(c);
    if (axis && mmOrNone(c)) {
      const std::string a(1, axis);
      if (isNominal(c)) return "q" + a;
      if (isActual(c)) return "p" + a;
      if (hasWord(c, {"normal", "normale", "n", "wektor", "vektor", "vector"})) return "n" + a;
      if (rawPoints && c.words.size() == 1) return "p" + a;  // raw points: x, y, z are the measured point
      return {};
    }
    if (onlyWords(c, {"i"})) return "nx";
    if (onlyWords(c, {"j"})) return "ny";
    if (onlyWords(c, {"k"})) return "nz";
    if (hasWord(c, {"surface", "flache", "flaeche", "powierzchnia", "face"})) return "surface";
    if (onlyWords(c,
                  {"id", "nr", "no", "punkt", "point", "pkt", "number", "nummer", "numer", "punktnr", "pt"}))
      return "id";
    return {};
  }
  if (kind == "circular-test") {
    if (hasWord(c, {"angle", "winkel", "kat"}) && (c.unit.empty() || unitFactor(c.unit, "deg")))
      return "angle_deg";
    if (hasWord(c, {"deviation", "dev", "abweichung", "abw", "odchylka", "odchylenie"}) &&
        unitFactor(c.unit, "um"))
      return c.unit == "mm" ? "deviation_mm" : "deviation_um";
    if (hasWord(c, {"radius", "promien"}) && mmOrNone(c)) return "radius_mm";
    if (onlyWords(c, {"direction", "richtung", "kierunek", "drehrichtung"})) return "direction";
    if (onlyWords(c, {"run", "lauf", "przebieg"})) return "run";
    return {};
  }
  return {};
}

/// The header of the file as read with `options` (title lines detected), or the first line's fields.
std::vector<std::string> headerOf(std::string_view text, const std::string& name,
                                  const CsvReadOptions& options) {
  CsvReadOptions o = options;
  o.columnMap.clear();
  o.skipBadRows = true;
  try {
    return parseCsv(text, name, o).header();
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace

ColumnName splitColumnName(const std::string& name) {
  ColumnName c;
  std::string base = name;
  while (!base.empty() && std::isspace(static_cast<unsigned char>(base.back()))) base.pop_back();
  if (!base.empty() && (base.back() == ']' || base.back() == ')')) {
    const char open = base.back() == ']' ? '[' : '(';
    const auto at = base.rfind(open);
    if (at != std::string::npos) {
      c.unit = normalUnitName(base.substr(at + 1, base.size() - at - 2));
      base.erase(at);
    }
  }
  std::string f = fold(base);
  // '-' between letters separates words ("Soll-X"); a trailing one belongs to the word ("tol-").
  for (std::size_t i = 0; i + 1 < f.size(); ++i)
    if (f[i] == '-' && std::isalpha(static_cast<unsigned char>(f[i + 1]))) f[i] = ' ';
  std::string word;
  const auto flush = [&] {
    if (!word.empty()) c.words.push_back(word);
    word.clear();
  };
  for (char ch : f) {
    if (std::isspace(static_cast<unsigned char>(ch)) || ch == '_' || ch == '.' || ch == ':' || ch == '/')
      flush();
    else
      word += ch;
  }
  flush();
  // A unit written as the last word ("dev_um", "Zeit min") when the name has other words.
  if (c.unit.empty() && c.words.size() > 1) {
    const std::string u = normalUnit(c.words.back());
    if (!u.empty() && u != "degC") {
      c.unit = u;
      c.words.pop_back();
    }
  }
  return c;
}

std::vector<std::pair<std::string, std::string>> suggestColumnRoles(const std::string& kind,
                                                                    const std::vector<std::string>& header) {
  const std::vector<std::string> roles = rolesOf(kind);
  std::set<std::string> taken;
  for (const std::string& h : header)
    if (std::find(roles.begin(), roles.end(), h) != roles.end()) taken.insert(h);
  // Raw measured points: coordinate columns and none of them names a nominal or actual value.
  bool rawPoints = kind == "probe-points";
  for (const std::string& h : header) {
    const ColumnName c = splitColumnName(h);
    if (h == "qx" || h == "px" || (axisOf(c) && (isNominal(c) || isActual(c)))) rawPoints = false;
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& h : header) {
    if (taken.count(h)) continue;
    const std::string role = roleFor(kind, h, rawPoints);
    if (role.empty() || role == h || taken.count(role)) continue;
    taken.insert(role);
    out.emplace_back(role, h);
  }
  return out;
}

std::string guessDatasetKind(const std::string& fileName, std::string_view text,
                             const CsvReadOptions& options) {
  std::string suffix;
  const auto slash = fileName.find_last_of("/\\");
  const auto dot = fileName.rfind('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
    suffix = fold(fileName.substr(dot + 1));
  if (suffix == "json") return "setup-model";
  if (suffix == "stl") return "cad-model";
  const std::string head(text.substr(0, 64 * 1024));
  // An ASCII STL ("solid" ... "facet normal"); a binary one without the extension is not guessed.
  {
    std::string start = head.substr(0, 512);
    for (char& c : start) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (start.rfind("solid", 0) == 0 && start.find("facet") != std::string::npos) return "cad-model";
  }
  if (suffix == "dmi" || suffix == "dms" || suffix == "dmis" || setup::looksLikeDmis(head)) return "dmis";
  // Q-DAS DFQ (K fields) and Zeiss Calypso tables (_chr / _fet column names), by content.
  if (looksLikeQif(head)) return "qif";                 // XML whose root is QIFDocument
  if (looksLikeMtconnectLog(head)) return "mtconnect";  // SHDR lines or an MTConnectStreams document
  if (looksLikeDfq(head)) return "dfq";
  if (looksLikeCalypso(head)) return "calypso";
  if (looksLikeCmmTextReport(head)) return "cmm-report";
  if (looksLikeHoleTable(head)) return "hole-table";
  const std::vector<std::string> header = headerOf(head, fileName, options);
  if (header.empty()) return "feature-series";
  const auto has = [&](const std::string& kind, std::initializer_list<const char*> wanted) {
    std::set<std::string> roles(header.begin(), header.end());
    for (const auto& [role, column] : suggestColumnRoles(kind, header)) roles.insert(role);
    for (const char* w : wanted)
      if (!roles.count(w)) return false;
    return true;
  };
  std::string all;
  for (const std::string& h : header) all += fold(h) + " ";
  const auto contains = [&all](const char* s) { return all.find(s) != std::string::npos; };
  // Points before reports: "Soll X; Ist X" columns name nominal and actual values too.
  if (has("probe-points", {"qx", "px"}) || has("probe-points", {"px", "py", "pz"})) return "probe-points";
  if (has("cmm-report", {"nominal_mm", "measured_mm"})) return "cmm-report";
  if (contains("x_cmd") || contains("x_meas")) return "circular-test";
  if (has("circular-test", {"angle_deg"}) &&
      (has("circular-test", {"deviation_um"}) || has("circular-test", {"deviation_mm"})))
    return "circular-test";
  if ((contains("angle") || contains("winkel")) && (contains("dev") || contains("abw")))
    return "circular-test";
  bool thermal = false;
  for (const auto& [role, column] : suggestColumnRoles("thermal-log", header))
    thermal = thermal || role.starts_with("time_");
  for (const char* w : {"time", "zeit", "czas", "temp", "disp", "verlagerung", "przemieszczenie", "drehzahl"})
    thermal = thermal || contains(w);
  if (thermal) return "thermal-log";
  return "feature-series";
}

}  // namespace metrofit
