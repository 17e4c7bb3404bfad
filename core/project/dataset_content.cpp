#include "core/project/dataset_content.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>

#include "core/common/error.h"
#include "core/io/calypso.h"
#include "core/io/dmis.h"
#include "core/io/file_io.h"
#include "core/io/mtconnect.h"
#include "core/io/qif.h"
#include "core/matching/hole_table.h"
#include "core/matching/probe_points.h"
#include "core/matching/qif_points.h"
#include "core/project/datasets.h"
#include "core/project/import_guess.h"
#include "core/project/nominals.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
namespace {

std::string trimmed(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return std::string(s.substr(b, e - b + 1));
}

std::string upperCase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

/// a - b rounded to 1e-9 (mm or deg), below every printed digit, so that 42.035 - 42 reads 0.035 and
/// not 0.034999999999996589.
double difference(double a, double b) {
  return std::round((a - b) * 1e9) / 1e9;
}

/// Limits printed as 0 (both, or the one printed) are OGP's (and many exports') "no tolerance".
void setLimits(FeatureTableRow& row, std::optional<double> lower, std::optional<double> upper) {
  if ((!lower || *lower == 0.0) && (!upper || *upper == 0.0)) return;
  row.lower = lower;
  row.upper = upper;
}

void finish(FeatureTableRow& row, double slack) {
  if (row.nominal && row.actual) row.deviation = difference(*row.actual, *row.nominal);
  if (row.deviation && outsideTolerance(*row.deviation, row.lower, row.upper, slack))
    row.outOfTolerance = true;
}

/// The file's own name of each column of a table read with `columnMap` (role -> file column).
std::vector<std::string> fileColumnNames(const CsvTable& table,
                                         const std::vector<std::pair<std::string, std::string>>& columnMap) {
  std::vector<std::string> names = table.header();
  for (std::string& n : names)
    for (const auto& [role, column] : columnMap)
      if (n == role) n = column;
  return names;
}

DatasetContent columnsContent(CsvTable table, std::string format, const std::string& file,
                              const std::vector<std::pair<std::string, std::string>>& columnMap = {}) {
  DatasetContent c;
  c.shape = DatasetContent::Shape::Columns;
  c.format = std::move(format);
  c.file = file;
  c.fileColumns = fileColumnNames(table, columnMap);
  for (std::size_t i = 0; i < table.columnCount(); ++i) {
    std::string unit = columnDisplayUnit(c.fileColumns[i]);
    if (unit.empty()) unit = columnDisplayUnit(table.header()[i]);
    c.units.push_back(unit);
  }
  c.table = std::move(table);
  return c;
}

DatasetContent featuresContent(std::vector<FeatureTableRow> rows, std::string format,
                               const std::string& file) {
  DatasetContent c;
  c.shape = DatasetContent::Shape::Features;
  c.format = std::move(format);
  c.file = file;
  c.features = std::move(rows);
  return c;
}

// ---- DMIS ------------------------------------------------------------------------------------

/// Position (and diameter) of a FEAT statement: the numbers after CART.
struct DmisFeat {
  double xyz[3] = {0, 0, 0};
  std::optional<double> diameter;
  long line = 0;
};

std::optional<DmisFeat> dmisFeat(const DmisStatement& s, double scale, const std::string& source) {
  if (s.major != "FEAT" || s.minor.empty()) return std::nullopt;
  const auto cart = std::find_if(s.minor.begin(), s.minor.end(),
                                 [](const std::string& w) { return upperCase(w) == "CART"; });
  if (cart == s.minor.end()) return std::nullopt;
  const auto at = static_cast<std::size_t>(cart - s.minor.begin()) + 1;
  DmisFeat f;
  f.line = s.line;
  for (std::size_t k = 0; k < 3; ++k)
    f.xyz[k] = dmisNumber(s, at + k, source, std::string(1, "xyz"[k]) + " coordinate") * scale;
  if (const auto d = dmisDiameterIndex(upperCase(s.minor.front())); d && at + *d < s.minor.size())
    f.diameter = dmisNumber(s, at + *d, source, "diameter") * scale;
  return f;
}

}  // namespace

bool outsideTolerance(double deviation, std::optional<double> lower, std::optional<double> upper,
                      double slack) {
  return (lower && deviation < *lower - slack) || (upper && deviation > *upper + slack);
}

std::vector<FeatureTableRow> cmmReportFeatureRows(const CmmTextReport& report) {
  std::vector<FeatureTableRow> rows;
  for (std::size_t k = 0; k < report.runs.size(); ++k) {
    const CmmRun& run = report.runs[k];
    std::string part;
    // Run numbers repeat in a summary of several days (run # 1-4 each day): the k-th run in the
    // file, with its printed number and date.
    if (isCharacteristicTable(report.format)) {
      // DFQ / Calypso: the measured workpiece (K0014, partnb), else the part number and the value set.
      part = !run.serial.empty()   ? run.serial
             : run.routine.empty() ? "part " + std::to_string(run.number)
                                   : run.routine + " #" + std::to_string(run.number);
      if (!run.dateTime.empty()) part += " (" + run.dateTime + ")";
    } else if (report.runs.size() > 1) {
      part = "run " + std::to_string(k + 1);
      std::string printed = run.number > 0 ? "#" + std::to_string(run.number) : std::string();
      if (!run.dateTime.empty()) printed += (printed.empty() ? "" : ", ") + run.dateTime;
      if (!printed.empty()) part += " (" + printed + ")";
    }
    for (const CmmFeature& f : run.features) {
      const std::string feature =
          !f.label.empty() ? f.label
          : report.format == CmmReportFormat::PcDmis || isCharacteristicTable(report.format)
              ? f.featureName
              : "Step " + std::to_string(f.step);
      for (const CmmValue& v : f.values) {
        FeatureTableRow row;
        row.part = part;
        row.feature = feature;
        row.characteristic = v.name;
        row.unit = v.angle ? "deg" : "mm";
        row.nominal = v.nominal;
        row.actual = v.actual;
        row.line = v.line;
        setLimits(row, v.lower, v.upper);
        if (!v.nominal && v.printedDeviation) row.deviation = v.printedDeviation;
        finish(row, v.rounding);
        if (v.outTol && *v.outTol != 0.0) row.outOfTolerance = true;
        rows.push_back(std::move(row));
      }
    }
  }
  return rows;
}

std::vector<FeatureTableRow> cmmCsvFeatureRows(const CsvTable& t) {
  const std::size_t cPart = t.requireColumn("part"), cDim = t.requireColumn("dimension"),
                    cNom = t.requireColumn("nominal_mm"), cMeas = t.requireColumn("measured_mm"),
                    cLo = t.requireColumn("lower_tol_mm"), cUp = t.requireColumn("upper_tol_mm");
  std::vector<FeatureTableRow> rows;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    FeatureTableRow row;
    row.part = trimmed(t.cell(r, cPart));
    row.feature = trimmed(t.cell(r, cDim));
    row.unit = "mm";
    row.nominal = t.number(r, cNom);
    row.actual = t.number(r, cMeas);
    setLimits(row, t.number(r, cLo), t.number(r, cUp));
    row.line = t.lineOf(r);
    finish(row, 1e-12);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<FeatureTableRow> dmisFeatureRows(std::string_view text, const std::string& source) {
  const std::vector<DmisStatement> statements = dmisStatements(text, source);
  std::vector<std::string> order;  // labels (upper case) in order of first appearance
  std::map<std::string, std::string> shown;
  std::map<std::string, DmisFeat> nominal, actual;
  std::map<std::string, const DmisStatement*> tol, tolActual;
  std::map<std::string, double> tolScale;
  double scale = 1.0;
  for (const DmisStatement& s : statements) {
    if (s.kind.empty()) {
      if (s.major == "UNITS" && !s.minor.empty()) {
        scale = dmisUnitMm(s, source);
      }
      continue;
    }
    const std::string key = upperCase(s.label);
    if (s.kind != "F" && s.kind != "FA" && s.kind != "T" && s.kind != "TA") continue;
    if (!shown.count(key)) {
      shown[key] = s.label;
      order.push_back(key);
    }
    if (s.kind == "F" || s.kind == "FA") {
      if (const auto f = dmisFeat(s, scale, source)) (s.kind == "F" ? nominal : actual)[key] = *f;
    } else {
      (s.kind == "T" ? tol : tolActual)[key] = &s;
      tolScale[key] = scale;
    }
  }
  std::vector<FeatureTableRow> rows;
  for (const std::string& key : order) {
    const std::string& label = shown[key];
    const auto n = nominal.find(key);
    const auto a = actual.find(key);
    if (a != actual.end()) {
      const char* axes[] = {"X", "Y", "Z"};
      for (int k = 0; k < 3; ++k) {
        FeatureTableRow row;
        row.feature = label;
        row.characteristic = axes[k];
        row.unit = "mm";
        row.actual = a->second.xyz[k];
        if (n != nominal.end()) row.nominal = n->second.xyz[k];
        row.line = a->second.line;
        finish(row, 0.0);
        rows.push_back(std::move(row));
      }
      if (a->second.diameter) {
        FeatureTableRow row;
        row.feature = label;
        row.characteristic = "D";
        row.unit = "mm";
        row.actual = a->second.diameter;
        if (n != nominal.end() && n->second.diameter) row.nominal = n->second.diameter;
        row.line = a->second.line;
        finish(row, 0.0);
        rows.push_back(std::move(row));
      }
    }
    const auto t = tol.find(key);
    const auto ta = tolActual.find(key);
    if (ta == tolActual.end() && t == tol.end()) continue;
    FeatureTableRow row;
    row.feature = label;
    row.unit = "mm";
    const DmisStatement* def = t != tol.end() ? t->second : nullptr;
    const DmisStatement* act = ta != tolActual.end() ? ta->second : nullptr;
    const DmisStatement& any = act ? *act : *def;
    row.characteristic = any.minor.empty() ? "TOL" : upperCase(any.minor.front());
    const bool cortol = row.characteristic == "CORTOL";
    if (cortol && any.minor.size() > 1) row.characteristic += " " + upperCase(any.minor[1]);
    row.line = any.line;
    const double sc = tolScale[key];
    if (def) {
      std::size_t i = cortol ? 2 : 1;
      if (i < def->minor.size() && upperCase(def->minor[i]) == "NOMINL") {
        row.nominal = dmisNumber(*def, i + 1, source, "nominal") * sc;
        i += 2;
      }
      if (i + 1 < def->minor.size())
        setLimits(row, dmisNumber(*def, i, source, "lower tolerance") * sc,
                  dmisNumber(*def, i + 1, source, "upper tolerance") * sc);
    }
    if (act) {
      const std::size_t i = cortol ? 2 : 1;
      const double value = dmisNumber(*act, i, source, "value") * sc;
      // The value is the actual when it is nearer the nominal than zero, else the deviation
      // (core/setup/report.h: DmisTaMeaning::Auto).
      if (row.nominal && std::abs(value - *row.nominal) < std::abs(value)) {
        row.actual = value;
      } else {
        row.deviation = value;
        if (row.nominal) row.actual = difference(*row.nominal, -value);
      }
      for (std::size_t w = i + 1; w < act->minor.size(); ++w) {
        const std::string word = upperCase(act->minor[w]);
        if (word == "OUTOL" || word == "OUTTOL") row.outOfTolerance = true;
      }
    }
    if (row.actual && row.nominal) row.deviation = difference(*row.actual, *row.nominal);
    if (row.deviation && outsideTolerance(*row.deviation, row.lower, row.upper)) row.outOfTolerance = true;
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string columnDisplayUnit(const std::string& name) {
  const ColumnName split = splitColumnName(name);
  if (!split.unit.empty()) {
    const std::string& u = split.unit;
    if (u == "um") return "µm";
    if (u == "degC") return "°C";
    if (u == "rpm") return "1/min";
    if (u == "deg") return "°";
    return u;
  }
  // A bracket the import does not know: shown as written ("Kraft [N]").
  const std::string t = trimmed(name);
  if (!t.empty() && (t.back() == ']' || t.back() == ')')) {
    const auto open = t.rfind(t.back() == ']' ? '[' : '(');
    if (open != std::string::npos && open + 2 < t.size())
      return trimmed(t.substr(open + 1, t.size() - open - 2));
  }
  const auto pos = name.rfind('_');
  if (pos != std::string::npos) {
    const std::string u = name.substr(pos + 1);
    if (u == "um") return "µm";
    if (u == "degC") return "°C";
    if (u == "deg") return "°";
    if (u == "rpm") return "1/min";
    if (u == "mm" || u == "nm" || u == "s" || u == "min" || u == "h" || u == "ppm") return u;
  }
  static const char* const kPointRoles[] = {"qx", "qy", "qz", "px", "py", "pz"};
  for (const char* r : kPointRoles)
    if (name == r) return "mm";
  return {};
}

DatasetContent readDatasetContent(const std::string& projectPath, const DatasetRef& dataset,
                                  const Project* project) {
  std::optional<DatasetRef> reference;
  if (project) {
    if (const DatasetRef* r = nominalReference(*project, dataset)) {
      reference = *r;
      reference->path = resolveDatasetPath(projectPath, *r);
    }
  }
  return readDatasetContentFile(resolveDatasetPath(projectPath, dataset), dataset,
                                reference ? &*reference : nullptr);
}

DatasetContent readDatasetContentFile(const std::string& file, const DatasetRef& dataset,
                                      const DatasetRef* reference) {
  const std::string& kind = dataset.kind;
  if (kind == dataset_kind::kProbePoints && !dataset.nominals.empty()) {
    // Measured points whose nominals come from an element or a second measurement: the points as the
    // studies read them, with each point's deviation before any matching (along the normal, or the
    // distance for position-only points).
    DatasetRef d = dataset;
    d.path = file;
    const ProbePointSet set = readProbePointDataset(d, reference, 1);
    CsvTable points = parseCsv(probePointsToCsv(set), file);
    std::vector<std::string> header = points.header();
    header.push_back("d_mm");
    std::vector<std::vector<std::string>> cells;
    std::vector<long> lines;
    for (std::size_t r = 0; r < points.rowCount(); ++r) {
      std::vector<std::string> row;
      for (std::size_t c = 0; c < points.columnCount(); ++c) row.push_back(points.cell(r, c));
      const ProbePoint& p = set.points[r];
      row.push_back(CsvWriter::formatNumber(std::round(set.deviation(r, p.nominal, p.normal) * 1e7) / 1e7));
      cells.push_back(std::move(row));
      lines.push_back(0);
    }
    const NominalSource& n = dataset.nominals;
    const std::string format = n.from == "element" ? "measured points, nominals on the fitted " + n.element
                                                   : "measured points, nominals from '" + n.reference + "'";
    return columnsContent(CsvTable::fromCells(file, std::move(header), std::move(cells), std::move(lines)),
                          format, file);
  }
  if (kind == dataset_kind::kSetupModel) {
    const setup::Model model = setup::readModel(file);
    std::vector<std::vector<std::string>> cells;
    std::vector<long> lines;
    const auto num = [](const std::optional<double>& v) {
      return v ? CsvWriter::formatNumber(*v) : std::string();
    };
    for (const setup::Dimension& d : model.dimensions) {
      cells.push_back({d.id, d.dmisLabel(), num(d.nominal), num(d.lower), num(d.upper)});
      lines.push_back(0);
    }
    CsvTable t =
        CsvTable::fromCells(file, {"dimension", "label", "nominal_mm", "lower_tol_mm", "upper_tol_mm"},
                            std::move(cells), std::move(lines));
    return columnsContent(std::move(t), "setup model", file);
  }
  const std::string text = readFile(file, 256u << 20);
  if (kind == dataset_kind::kMtconnect ||
      (kind == dataset_kind::kThermalLog && looksLikeMtconnectLog(text))) {
    // An MTConnect log: the table it is read as, resampled to the dataset's grid (thermal_log.h).
    const MtcSampleTable t =
        readMtconnectSampleTable(file, mtconnectIntervalS(dataset.csv.sampleIntervalMin));
    return columnsContent(t.table, looksLikeMtconnectStreams(text) ? "MTConnect Streams" : "MTConnect SHDR",
                          file);
  }
  if (kind == dataset_kind::kProbePoints && looksLikeQif(text)) {
    // One measured part of a QIF file as probe points: nominal and actual locations (and normals).
    const QifFile qif = qifFromText(text, file);
    const ProbePointSet set = qifProbePoints(qif, qifPartIndex(qif, dataset.part, "part"));
    return columnsContent(parseCsv(probePointsToCsv(set), file), "QIF features", file);
  }
  if (kind == dataset_kind::kDfq || kind == dataset_kind::kCalypso || kind == dataset_kind::kQif ||
      (kind == dataset_kind::kProbePoints && looksLikeCalypsoFeatures(text))) {
    if (const auto report = characteristicTableReport(text, file, kind))
      return featuresContent(cmmReportFeatureRows(*report), toString(report->format), file);
    return columnsContent(calypsoFeaturesProbeTable(text, file), "Calypso features", file);
  }
  if (kind == dataset_kind::kDmis || (kind == dataset_kind::kCmmReport && setup::looksLikeDmis(text))) {
    if (!setup::looksLikeDmis(text))
      throw ParseError(ErrorContext{file, 1, 0, {}}, "not a DMIS file (its first statement is not DMISMN)");
    return featuresContent(dmisFeatureRows(text, file), "DMIS output", file);
  }
  if ((kind == dataset_kind::kCmmReport || kind == dataset_kind::kFeatureSeries ||
       kind == dataset_kind::kProbePoints) &&
      looksLikeCmmTextReport(text)) {
    const CmmTextReport report = cmmTextReportFromText(text, file);
    const std::string format = toString(report.format);
    if (kind == dataset_kind::kFeatureSeries)
      return columnsContent(cmmReportFeatureTable(report), format, file);
    if (kind == dataset_kind::kProbePoints)
      return columnsContent(parseCsv(probePointsToCsv(probePointsFromCmmReport(report, 1)), file), format,
                            file);
    return featuresContent(cmmReportFeatureRows(report), format, file);
  }
  if (kind == dataset_kind::kHoleTable || (kind == dataset_kind::kProbePoints && looksLikeHoleTable(text))) {
    const HoleTable t = holeTableFromText(text, file, 1);
    return columnsContent(parseCsv(probePointsToCsv(t.points), file), "hole table", file);
  }
  CsvTable table = parseCsv(text, file, dataset.csv);
  if (kind == dataset_kind::kCmmReport) return featuresContent(cmmCsvFeatureRows(table), "CSV", file);
  return columnsContent(std::move(table), "CSV", file, dataset.csv.columnMap);
}

}  // namespace metrofit
