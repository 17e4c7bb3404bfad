#include "core/setup/report.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/io/calypso.h"
#include "core/io/csv.h"
#include "core/io/dfq.h"
#include "core/io/dmis.h"
#include "core/io/file_io.h"

namespace metrofit::setup {
namespace {

constexpr double kLimitTolMm = 1e-6;  ///< report limits / nominals must match the model this closely
/// A DMIS tolerance actual more than this many tolerance widths outside its band is implausible.
constexpr double kImplausibleWidths = 10.0;

std::string fmt(double v) {
  return num::general(v, 12);
}  // as an ostream's precision(12), C locale

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// Fills deviationMm / samples from rows; every dimension needs a row unless `requireEvery` is false
/// (one file of a DMIS series: the series as a whole must measure every dimension, readMeasurements).
void finish(Measurements& m, const Model& model, const std::string& source, bool requireEvery = true) {
  const std::size_t n = model.dimensions.size();
  m.deviationMm.assign(n, 0.0);
  m.samples.assign(n, 0);
  for (const auto& r : m.rows) {
    m.deviationMm[r.dimension] += r.deviationMm;
    ++m.samples[r.dimension];
  }
  for (std::size_t q = 0; q < n; ++q) {
    if (m.samples[q] == 0 && !requireEvery) continue;
    if (m.samples[q] == 0) {
      const Dimension& d = model.dimensions[q];
      const std::string name =
          "'" + d.id + "'" + (d.dmisLabel() != d.id ? " (label '" + d.dmisLabel() + "')" : std::string());
      throw ValidationError(ErrorContext{source, 0, 0, "dimension"},
                            "the report has no measurement of dimension " + name + " of the model" +
                                (model.source.empty() ? std::string() : " (" + model.source + ")"));
    }
    m.deviationMm[q] /= m.samples[q];
  }
}

void addPart(Measurements& m, const std::string& part) {
  if (std::find(m.parts.begin(), m.parts.end(), part) == m.parts.end()) m.parts.push_back(part);
}

// ---- DMIS -------------------------------------------------------------------------------------

int axisIndex(const std::string& axis) {
  return axis == "X" ? 0 : axis == "Y" ? 1 : 2;
}

}  // namespace

Measurements cmmReportFromCsv(const CsvTable& t, const Model& model) {
  const std::size_t cPart = t.requireColumn("part"), cTime = t.requireColumn("time_min"),
                    cDim = t.requireColumn("dimension"), cNom = t.requireColumn("nominal_mm"),
                    cMeas = t.requireColumn("measured_mm"), cLo = t.requireColumn("lower_tol_mm"),
                    cUp = t.requireColumn("upper_tol_mm");
  t.requireRows(1);
  Measurements m;
  m.sources.push_back(t.source());
  std::map<std::pair<std::string, std::size_t>, long> seen;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const std::string part = trim(t.cell(r, cPart));
    if (part.empty()) t.failAt(r, cPart, "empty part name");
    const double time = t.number(r, cTime);
    const std::string dim = trim(t.cell(r, cDim));
    const int q = model.dimensionIndex(dim);
    if (q < 0) {
      t.failAt(r, cDim,
               "unknown dimension '" + dim + "' (not in the model" +
                   (model.source.empty() ? std::string() : " " + model.source) + ")");
    }
    const Dimension& d = model.dimensions[static_cast<std::size_t>(q)];
    const double nominal = t.number(r, cNom), measured = t.number(r, cMeas);
    const double lo = t.number(r, cLo), up = t.number(r, cUp);
    if (lo >= up) t.failAt(r, cLo, "lower limit " + fmt(lo) + " is not below upper limit " + fmt(up));
    if (std::abs(lo - d.lower) > kLimitTolMm)
      t.failAt(r, cLo,
               fmt(lo) + " differs from the model's lower limit " + fmt(d.lower) + " of '" + dim + "'");
    if (std::abs(up - d.upper) > kLimitTolMm)
      t.failAt(r, cUp,
               fmt(up) + " differs from the model's upper limit " + fmt(d.upper) + " of '" + dim + "'");
    if (d.nominal && std::abs(nominal - *d.nominal) > kLimitTolMm)
      t.failAt(r, cNom,
               fmt(nominal) + " differs from the model's nominal " + fmt(*d.nominal) + " of '" + dim + "'");
    const auto key = std::make_pair(part, static_cast<std::size_t>(q));
    const auto it = seen.find(key);
    if (it != seen.end()) {
      t.failAt(r, cDim,
               "duplicate row for part '" + part + "' and dimension '" + dim + "' (first on line " +
                   std::to_string(it->second) + ")");
    }
    seen.emplace(key, t.lineOf(r));
    addPart(m, part);
    m.rows.push_back({part, time, static_cast<std::size_t>(q), measured - nominal, t.source(), t.lineOf(r)});
  }
  finish(m, model, t.source());
  return m;
}

Measurements readCmmReport(const std::string& path, const Model& model, const CsvReadOptions& csv) {
  return cmmReportFromCsv(readCsvFile(path, csv), model);
}

bool looksLikeDmis(std::string_view text) {
  return looksLikeDmisText(text);
}

DmisTaMeaning parseDmisTaMeaning(const std::string& text, const std::string& option) {
  if (text == "auto") return DmisTaMeaning::Auto;
  if (text == "deviation") return DmisTaMeaning::Deviation;
  if (text == "actual") return DmisTaMeaning::Actual;
  throw OptionsError(ErrorContext{{}, 0, 0, option}, "'" + text + "' is not auto, deviation or actual");
}

std::string dmisTaMeaningName(DmisTaMeaning meaning) {
  switch (meaning) {
    case DmisTaMeaning::Deviation:
      return "deviation";
    case DmisTaMeaning::Actual:
      return "actual";
    case DmisTaMeaning::Auto:
      break;
  }
  return "auto";
}

bool parseDmisTaSign(const std::string& text, const std::string& option) {
  if (text == "plain") return false;
  if (text == "nominal") return true;
  throw OptionsError(ErrorContext{{}, 0, 0, option}, "'" + text + "' is not plain or nominal");
}

namespace {

/// A feature statement F(label) / FA(label): its position and, for round features, its diameter.
struct DmisFeature {
  std::array<double, 3> position{};
  std::optional<double> diameter;
  long line = 0;
};

/// A tolerance statement T(label) / TA(label).
struct DmisTolerance {
  std::string type;                             ///< DISTB, DIAM, CORTOL, ...
  double value = 0.0;                           ///< TA: the first value (mm)
  std::optional<double> nominal, lower, upper;  ///< T: NOMINL and limits (mm)
  std::string status;  ///< TA: INTOL, OUTOL or OUTTOL (upper case), empty when absent
  long line = 0;
};

/// Position of the numbers after CART in FEAT/type,[INNER|OUTER,]CART,x,y,z,...; ParseError otherwise.
std::size_t cartIndex(const DmisStatement& s, const std::string& source, const std::string& field) {
  std::size_t k = 1;
  if (k < s.minor.size() && (upper(s.minor[k]) == "INNER" || upper(s.minor[k]) == "OUTER")) ++k;
  const std::string coords = k < s.minor.size() ? upper(s.minor[k]) : std::string();
  if (coords == "POL")
    throw ParseError(ErrorContext{source, s.line, 0, field},
                     "polar (POL) coordinates are not supported; use CART");
  if (coords != "CART")
    throw ParseError(ErrorContext{source, s.line, 0, field},
                     "expected CART after the feature type" + std::string(k == 2 ? " and INNER/OUTER" : "") +
                         ", found '" + (k < s.minor.size() ? s.minor[k] : std::string()) + "'");
  return k + 1;
}

bool isDiameterType(const std::string& type) {
  return type == "DIAM" || type == "RAD";
}

}  // namespace

namespace {

/// dmisReportFromText; *bySerial tells whether PARTSN named the part (else FILNAM or the file name).
/// `requireEvery`: the file must measure every dimension of the model (a single file); one file of a
/// series may measure any of them, but at least one.
Measurements dmisMeasurements(std::string_view text, const std::string& source, const Model& model,
                              const DmisOptions& options, bool* bySerial, bool requireEvery) {
  const auto statements = dmisStatements(text, source);
  // Dimensions by upper-case DMIS label.
  std::map<std::string, std::size_t> byLabel;
  for (std::size_t q = 0; q < model.dimensions.size(); ++q)
    byLabel[upper(model.dimensions[q].dmisLabel())] = q;

  double unit = 1.0;  // mm per file unit
  std::string part = baseName(source);
  std::string serial;  // PARTSN/'serial': the workpiece's serial number, the best part name
  std::map<std::size_t, DmisTolerance> tol, ta;  // T(label), TA(label)
  std::map<std::size_t, DmisFeature> nominalF, actualF;
  std::map<std::pair<std::string, std::size_t>, long> firstLine;
  const int ax = axisIndex(model.axis);

  for (const DmisStatement& s : statements) {
    const std::string field = s.kind.empty() ? s.major : s.kind + "(" + s.label + ")";
    if (s.kind.empty()) {
      if (s.major == "UNITS") {
        unit = dmisUnitMm(s, source);
      } else if ((s.major == "FILNAM" || s.major == "PARTSN") && !s.minor.empty()) {
        std::string name = s.minor[0];
        if (name.size() >= 2 && name.front() == '\'' && name.back() == '\'')
          name = name.substr(1, name.size() - 2);
        if (!name.empty()) (s.major == "PARTSN" ? serial : part) = name;
      }
      continue;
    }
    const auto lab = byLabel.find(upper(s.label));
    if (lab == byLabel.end()) continue;  // a datum or another feature: not a dimension of the model
    const std::size_t q = lab->second;
    const Dimension& d = model.dimensions[q];
    const auto dupKey = std::make_pair(s.kind, q);
    if (const auto it = firstLine.find(dupKey); it != firstLine.end()) {
      throw ValidationError(ErrorContext{source, s.line, 0, field},
                            "duplicate " + s.kind + " statement for '" + s.label + "' (first on line " +
                                std::to_string(it->second) + ")");
    }
    if (s.kind == "F" || s.kind == "FA") {
      if (s.major != "FEAT") continue;
      if (s.minor.size() < 2)
        throw ParseError(ErrorContext{source, s.line, 0, field}, "expected FEAT/type,CART,x,y,z,...");
      const std::size_t c = cartIndex(s, source, field);
      DmisFeature f;
      f.line = s.line;
      for (std::size_t k = 0; k < 3; ++k)
        f.position[k] = unit * dmisNumber(s, c + k, source, std::string(1, "xyz"[k]) + " coordinate");
      if (const auto di = dmisDiameterIndex(upper(s.minor[0])); di && c + *di < s.minor.size())
        f.diameter = unit * dmisNumber(s, c + *di, source, "diameter");
      firstLine.emplace(dupKey, s.line);
      (s.kind == "F" ? nominalF : actualF)[q] = f;
    } else if (s.kind == "T" || s.kind == "TA") {
      if (s.major != "TOL") continue;
      if (s.minor.empty()) throw ParseError(ErrorContext{source, s.line, 0, field}, "expected TOL/type,...");
      DmisTolerance t;
      t.line = s.line;
      t.type = upper(s.minor[0]);
      const bool cortol = t.type == "CORTOL";
      const bool profile = t.type == "PROFP" || t.type == "PROFL" || t.type == "PROFS";
      if (!cortol && !profile && t.type != "DISTB" && t.type != "DISTWRT" && t.type != "DIAM" &&
          t.type != "RAD" && t.type != "WIDTH") {
        throw ParseError(ErrorContext{source, s.line, 0, field},
                         "tolerance type '" + s.minor[0] +
                             "' is not supported for a dimension (use DISTB, DISTWRT, "
                             "DIAM, RAD, WIDTH, CORTOL or PROFP)");
      }
      std::size_t first = 1;
      if (cortol) {
        const std::string axisWord = s.minor.size() > 1 ? upper(s.minor[1]) : std::string();
        if (axisWord != model.axis + "AXIS") {
          throw ValidationError(ErrorContext{source, s.line, 0, field},
                                "CORTOL along '" + (s.minor.size() > 1 ? s.minor[1] : std::string()) +
                                    "' but the model's axis is " + model.axis);
        }
        first = 2;
      }
      firstLine.emplace(dupKey, s.line);
      if (s.kind == "TA") {
        t.value = unit * dmisNumber(s, first, source, "deviation");
        for (std::size_t k = first + 1; k < s.minor.size(); ++k) {
          const std::string w = upper(s.minor[k]);
          if (w == "INTOL" || w == "OUTOL" || w == "OUTTOL") t.status = w;
        }
        ta[q] = t;
        continue;
      }
      // Tolerance definition: check against the model.
      if (!cortol && first < s.minor.size() && upper(s.minor[first]) == "NOMINL") {
        t.nominal = unit * dmisNumber(s, first + 1, source, "nominal");
        first += 2;
      }
      const double lo = unit * dmisNumber(s, first, source, "lower tolerance");
      const double up = unit * dmisNumber(s, first + 1, source, "upper tolerance");
      if (std::abs(lo - d.lower) > kLimitTolMm || std::abs(up - d.upper) > kLimitTolMm) {
        throw ValidationError(ErrorContext{source, s.line, 0, field},
                              "tolerance " + fmt(lo) + " / " + fmt(up) + " differs from the model's limits " +
                                  fmt(d.lower) + " / " + fmt(d.upper) + " of '" + d.id + "'");
      }
      if (t.nominal && d.nominal && std::abs(*t.nominal - *d.nominal) > kLimitTolMm) {
        throw ValidationError(ErrorContext{source, s.line, 0, field},
                              "nominal " + fmt(*t.nominal) + " differs from the model's nominal " +
                                  fmt(*d.nominal) + " of '" + d.id + "'");
      }
      t.lower = lo;
      t.upper = up;
      tol[q] = t;
    }
  }

  if (!serial.empty()) part = serial;
  if (bySerial != nullptr) *bySerial = !serial.empty();
  Measurements m;
  m.sources.push_back(source);
  addPart(m, part);
  for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
    const Dimension& d = model.dimensions[q];
    const auto a = actualF.find(q);
    const auto n = nominalF.find(q);
    const auto t = ta.find(q);
    const auto def = tol.find(q);
    // 1. Nominal and actual feature: the deviation from them (a diameter for DIAM / RAD tolerances).
    if (a != actualF.end() && n != nominalF.end()) {
      const std::string type = t != ta.end()      ? t->second.type
                               : def != tol.end() ? def->second.type
                                                  : std::string();
      double dev =
          a->second.position[static_cast<std::size_t>(ax)] - n->second.position[static_cast<std::size_t>(ax)];
      if (isDiameterType(type) && a->second.diameter && n->second.diameter)
        dev = (*a->second.diameter - *n->second.diameter) * (type == "RAD" ? 0.5 : 1.0);
      m.rows.push_back({part, 0.0, q, dev, source, a->second.line});
      continue;
    }
    // 2. The tolerance actual: a deviation or the actual value, as the options say (auto: the one that
    //    agrees with INTOL / OUTOL, else the one nearer the nominal's scale).
    if (t != ta.end()) {
      const DmisTolerance& v = t->second;
      const std::string field = "TA(" + d.dmisLabel() + ")";
      std::optional<double> nominal =
          def != tol.end() && def->second.nominal ? def->second.nominal : d.nominal;
      if (n != nominalF.end() && isDiameterType(v.type) && n->second.diameter)
        nominal = *n->second.diameter * (v.type == "RAD" ? 0.5 : 1.0);
      const double lo = def != tol.end() ? *def->second.lower : d.lower;
      const double up = def != tol.end() ? *def->second.upper : d.upper;
      const double sign = options.signFollowsNominal && nominal && *nominal < 0.0 ? -1.0 : 1.0;
      auto asDeviation = [&] { return sign * v.value; };
      auto asActual = [&] {
        if (!nominal)
          throw ValidationError(
              ErrorContext{source, v.line, 0, field},
              "the tolerance actual is read as the actual value, but neither the file (T with "
              "NOMINL, or F) nor the model gives a nominal");
        return v.value - *nominal;
      };
      auto inTolerance = [&](double dev) { return dev >= lo - 1e-9 && dev <= up + 1e-9; };
      const bool saysIn = v.status == "INTOL";
      const bool hasStatus = !v.status.empty();
      double dev = 0.0;
      if (options.taMeaning == DmisTaMeaning::Deviation) {
        dev = asDeviation();
      } else if (options.taMeaning == DmisTaMeaning::Actual) {
        dev = asActual();
      } else {
        // Auto: an actual value lies near the nominal, a deviation near zero.
        const bool nearNominal = nominal && std::abs(v.value - *nominal) < std::abs(v.value);
        dev = nearNominal ? asActual() : asDeviation();
      }
      if (hasStatus && inTolerance(dev) != saysIn) {
        throw ValidationError(
            ErrorContext{source, v.line, 0, field},
            "the deviation " + fmt(dev) + " mm is " + (inTolerance(dev) ? "inside" : "outside") +
                " the tolerance " + fmt(lo) + " / " + fmt(up) + " but the file says " + v.status +
                "; read the tolerance actual as " +
                (options.taMeaning == DmisTaMeaning::Actual ? "a deviation" : "the actual value") +
                " or with the other sign convention");
      }
      // Without INTOL / OUTOL the band itself is the check: a tolerance actual that lands more than
      // kImplausibleWidths tolerance widths outside it was read in the wrong meaning (an actual
      // diameter taken as a deviation, say), not measured on a part worth correcting.
      const double width = up - lo;
      if (!hasStatus && width > 0.0 &&
          (dev < lo - kImplausibleWidths * width || dev > up + kImplausibleWidths * width)) {
        const bool asActualValue = options.taMeaning == DmisTaMeaning::Actual ||
                                   (options.taMeaning == DmisTaMeaning::Auto && nominal &&
                                    std::abs(v.value - *nominal) < std::abs(v.value));
        throw ValidationError(
            ErrorContext{source, v.line, 0, field},
            "the tolerance actual " + fmt(v.value) + " read as " +
                (asActualValue ? "the actual value" : "a deviation") + " gives the deviation " + fmt(dev) +
                " mm, more than " + fmt(kImplausibleWidths) + " tolerance widths outside the tolerance " +
                fmt(lo) + " / " + fmt(up) + " of '" + d.id + "'; read it as " +
                (asActualValue ? "a deviation" : "the actual value") + " or with the other sign convention");
      }
      m.rows.push_back({part, 0.0, q, dev, source, v.line});
      continue;
    }
    if (a == actualF.end()) continue;  // finish() reports the missing dimension
    throw ValidationError(ErrorContext{source, a->second.line, 0, "FA(" + d.dmisLabel() + ")"},
                          "feature actual without its nominal F(" + d.dmisLabel() +
                              ") and without a tolerance actual TA(" + d.dmisLabel() + ")");
  }
  if (!requireEvery && m.rows.empty()) {
    throw ValidationError(ErrorContext{source, 0, 0, "dimension"},
                          "the file measures no dimension of the model" +
                              (model.source.empty() ? std::string() : " (" + model.source + ")") +
                              " (no F/FA or TA statement whose label is a dimension's label)");
  }
  finish(m, model, source, requireEvery);
  return m;
}

}  // namespace

Measurements dmisReportFromText(std::string_view text, const std::string& source, const Model& model,
                                const DmisOptions& options) {
  return dmisMeasurements(text, source, model, options, nullptr, true);
}

Measurements readDmisReport(const std::string& path, const Model& model, const DmisOptions& options) {
  return dmisReportFromText(readFile(path, 256u << 20), displayPath(path), model, options);
}

namespace {

/// "oriball:Diameter" -> {"oriball", "Diameter"}; "oriball" -> {"oriball", ""}.
std::pair<std::string, std::string> splitReportLabel(const std::string& label) {
  const auto colon = label.rfind(':');
  if (colon == std::string::npos) return {trim(label), {}};
  return {trim(std::string_view(label).substr(0, colon)), trim(std::string_view(label).substr(colon + 1))};
}

std::string collapse(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '\t') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool featureNamed(const CmmFeature& f, const std::string& name, CmmReportFormat format) {
  const std::string u = upper(name);
  if (!f.label.empty() && upper(f.label) == u) return true;
  if (format == CmmReportFormat::PcDmis || isCharacteristicTable(format))
    return !f.featureName.empty() && upper(f.featureName) == u;
  return collapse(name) == "STEP" + std::to_string(f.step);
}

const CmmValue* reportValue(const CmmFeature& f, const std::string& value, const std::string& axis,
                            CmmReportFormat format) {
  const bool ogp = format != CmmReportFormat::PcDmis;
  if (!value.empty()) {
    if (const CmmValue* v = f.value(value)) return v;
    const std::string u = upper(value);
    if (ogp && (u == "X" || u == "Y" || u == "Z")) return f.value(u + " Location");
    return nullptr;
  }
  if (const CmmValue* v = f.value(ogp ? axis + " Location" : axis)) return v;
  const CmmValue* only = nullptr;
  int withNominal = 0;
  for (const CmmValue& v : f.values) {
    if (v.nominal) {
      only = &v;
      ++withNominal;
    }
  }
  return withNominal == 1 ? only : nullptr;
}

std::string valueNames(const CmmFeature& f) {
  std::string out;
  for (const CmmValue& v : f.values) out += (out.empty() ? "" : ", ") + v.name;
  return out.empty() ? std::string("none") : out;
}

std::string featureTitle(const CmmFeature& f, CmmReportFormat format) {
  if (format == CmmReportFormat::PcDmis) return "dimension '" + f.label + "'";
  if (isCharacteristicTable(format))
    return "characteristic " + f.featureName +
           (f.label != f.featureName ? " '" + f.label + "'" : std::string());
  return "step " + std::to_string(f.step) + (f.label.empty() ? std::string() : " '" + f.label + "'");
}

}  // namespace

Measurements cmmTextReportMeasurements(const CmmTextReport& report, const Model& model) {
  Measurements m;
  m.sources.push_back(report.source);
  const std::string base = baseName(report.source);
  // DFQ and Calypso date each measured part (K0004; the _hdr's date and time): time_min from the first
  // one, when every run has a date-time that reads (else 0, as for the other reports).
  std::vector<double> times;
  if (isCharacteristicTable(report.format)) {
    for (const CmmRun& r : report.runs) {
      const auto t = qdasMinutes(r.dateTime);
      if (!t) {
        times.clear();
        break;
      }
      times.push_back(*t);
    }
    if (!times.empty()) {
      const double t0 = *std::min_element(times.begin(), times.end());
      for (double& t : times) t -= t0;
    }
  }
  for (std::size_t k = 0; k < report.runs.size(); ++k) {
    const CmmRun& run = report.runs[k];
    // DFQ and Calypso name the measured workpiece (K0014, partnb): the part, when every run has its own.
    std::set<std::string> serials;
    for (const CmmRun& r : report.runs)
      if (!r.serial.empty()) serials.insert(r.serial);
    const bool bySerial = serials.size() == report.runs.size();
    const std::string part = bySerial                  ? run.serial
                             : report.runs.size() == 1 ? base
                                                       : base + " run " + std::to_string(k + 1);
    addPart(m, part);
    for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
      const Dimension& d = model.dimensions[q];
      const auto [featureName, valueName] = splitReportLabel(d.dmisLabel());
      const CmmFeature* found = nullptr;
      for (const CmmFeature& f : run.features) {
        if (!featureNamed(f, featureName, report.format)) continue;
        if (found) {
          throw ValidationError(ErrorContext{report.source, f.line, 0, d.id},
                                "the label '" + featureName + "' of dimension '" + d.id + "' names " +
                                    featureTitle(*found, report.format) + " (line " +
                                    std::to_string(found->line) + ") and " + featureTitle(f, report.format) +
                                    (report.format == CmmReportFormat::PcDmis ? std::string()
                                     : isCharacteristicTable(report.format)
                                         ? "; name one by its number '" + f.featureName + "'"
                                         : "; name one as 'Step " + std::to_string(f.step) + "'"));
        }
        found = &f;
      }
      if (!found) continue;  // finish() reports a dimension measured in no run
      const CmmValue* v = reportValue(*found, valueName, model.axis, report.format);
      if (!v) {
        throw ValidationError(
            ErrorContext{report.source, found->line, 0, d.id},
            featureTitle(*found, report.format) + " has no value '" +
                (valueName.empty()
                     ? (report.format == CmmReportFormat::PcDmis ? model.axis : model.axis + " Location")
                     : valueName) +
                "' for dimension '" + d.id + "' (it has: " + valueNames(*found) +
                "); name one in the label as '" + featureName + ":<value>'");
      }
      if (!v->nominal && !v->printedDeviation) {
        throw ValidationError(ErrorContext{report.source, v->line, 0, v->name},
                              "the report prints no nominal for this value of " +
                                  featureTitle(*found, report.format) + ", so dimension '" + d.id +
                                  "' has no deviation");
      }
      const double tol = v->rounding + 1e-9;
      if (v->upper && v->lower && (*v->upper != 0.0 || *v->lower != 0.0) &&
          (std::abs(*v->lower - d.lower) > tol || std::abs(*v->upper - d.upper) > tol)) {
        throw ValidationError(ErrorContext{report.source, v->line, 0, v->name},
                              "tolerance " + fmt(*v->lower) + " / " + fmt(*v->upper) +
                                  " differs from the model's limits " + fmt(d.lower) + " / " + fmt(d.upper) +
                                  " of '" + d.id + "'");
      }
      if (v->nominal && d.nominal && std::abs(*v->nominal - *d.nominal) > tol) {
        throw ValidationError(ErrorContext{report.source, v->line, 0, v->name},
                              "nominal " + fmt(*v->nominal) + " differs from the model's nominal " +
                                  fmt(*d.nominal) + " of '" + d.id + "'");
      }
      m.rows.push_back({part, times.empty() ? 0.0 : times[k], q, plainDeviation(*v), report.source, v->line});
    }
  }
  finish(m, model, report.source);
  return m;
}

Measurements mergeMeasurements(const std::vector<Measurements>& sets, const Model& model) {
  if (sets.empty()) throw ValidationError(ErrorContext{}, "no measurement report given");
  if (sets.size() == 1) return sets.front();
  Measurements out;
  std::map<std::pair<std::string, std::size_t>, const Measurements::Row*> seen;
  for (const auto& s : sets) {
    out.sources.insert(out.sources.end(), s.sources.begin(), s.sources.end());
    for (const auto& r : s.rows) {
      const auto key = std::make_pair(r.part, r.dimension);
      if (const auto it = seen.find(key); it != seen.end()) {
        throw ValidationError(ErrorContext{r.source, r.line, 0, "part"},
                              "part '" + r.part + "', dimension '" + model.dimensions[r.dimension].id +
                                  "' is measured twice (first in " + it->second->source + " line " +
                                  std::to_string(it->second->line) + ")");
      }
      seen.emplace(key, &r);
      addPart(out, r.part);
      out.rows.push_back(r);
    }
  }
  finish(out, model, out.sources.front());
  return out;
}

namespace {

/// A series of DMIS files, one part each: FILNAM usually names the inspection program, the same in
/// every file of the series. The files without PARTSN that name the same part are named by their file
/// instead (the base name, the path when base names repeat): part k = file k. The same file given
/// twice keeps its name, and mergeMeasurements reports the part measured twice.
void nameDmisSeriesParts(std::vector<Measurements>& sets, const std::vector<std::size_t>& unnamed) {
  std::map<std::string, int> count, baseCount;
  std::map<std::string, int> sourceCount;
  for (std::size_t i : unnamed) {
    ++count[sets[i].parts.front()];
    ++baseCount[baseName(sets[i].sources.front())];
    ++sourceCount[sets[i].sources.front()];
  }
  for (std::size_t i : unnamed) {
    Measurements& m = sets[i];
    const std::string& source = m.sources.front();
    if (count[m.parts.front()] < 2 || sourceCount[source] > 1) continue;
    const std::string part = baseCount[baseName(source)] > 1 ? source : baseName(source);
    m.parts.assign(1, part);
    for (auto& r : m.rows) r.part = part;
  }
}

}  // namespace

Measurements readMeasurements(const std::vector<std::string>& paths, const Model& model,
                              const CsvReadOptions& csv, const DmisOptions& dmis) {
  std::vector<Measurements> sets;
  // DMIS files named by FILNAM or their file name (not by PARTSN), by index into sets.
  std::vector<std::size_t> unnamedDmis;
  // One DMIS file alone must measure every dimension; in a series each file may measure any of them.
  const bool series = paths.size() > 1;
  for (const auto& p : paths) {
    const std::string text = readFile(p, 256u << 20);
    bool bySerial = false;
    if (looksLikeDmis(text)) {
      sets.push_back(dmisMeasurements(text, displayPath(p), model, dmis, &bySerial, !series));
      if (!bySerial) unnamedDmis.push_back(sets.size() - 1);
    } else if (p != "-" && looksLikeCalypsoCharacteristics(text) && !looksLikeDfq(text)) {
      // A Calypso _chr file read by its path: with the dates of the _hdr file beside it.
      sets.push_back(cmmTextReportMeasurements(readCmmTextReport(p), model));
    } else if (looksLikeCmmTextReport(text))
      sets.push_back(cmmTextReportMeasurements(cmmTextReportFromText(text, displayPath(p)), model));
    else
      sets.push_back(cmmReportFromCsv(parseCsv(text, displayPath(p), csv), model));
  }
  nameDmisSeriesParts(sets, unnamedDmis);
  // Coverage over the whole series, as in a CSV series: a dimension that no file measures is the
  // error, naming the dimension and the files read (the other readers require every dimension of
  // each file, so only a series of DMIS files can miss one here).
  if (series) {
    std::vector<bool> measured(model.dimensions.size(), false);
    for (const auto& s : sets)
      for (const auto& r : s.rows) measured[r.dimension] = true;
    for (std::size_t q = 0; q < measured.size(); ++q) {
      if (measured[q]) continue;
      const Dimension& d = model.dimensions[q];
      std::string files;
      for (const auto& p : paths) files += (files.empty() ? "" : ", ") + displayPath(p);
      throw ValidationError(
          ErrorContext{{}, 0, 0, "dimension"},
          "no file of the series measures dimension '" + d.id + "'" +
              (d.dmisLabel() != d.id ? " (label '" + d.dmisLabel() + "')" : std::string()) + " of the model" +
              (model.source.empty() ? std::string() : " (" + model.source + ")") + "; files read: " + files);
    }
  }
  return mergeMeasurements(sets, model);
}

}  // namespace metrofit::setup
