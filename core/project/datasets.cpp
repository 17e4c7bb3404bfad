#include "core/project/datasets.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/geometry/point_table.h"
#include "core/geometry/stl.h"
#include "core/io/calypso.h"
#include "core/io/cmm_text_report.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/io/mtconnect.h"
#include "core/io/qif.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"
#include "core/matching/hole_table.h"
#include "core/matching/probe_points.h"
#include "core/matching/qif_points.h"
#include "core/project/import_guess.h"
#include "core/project/nominals.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;

const std::map<std::string, std::string>& kinds() {
  static const std::map<std::string, std::string> k{{"thermal-log", dataset_kind::kThermalLog},
                                                    {"probe-points", dataset_kind::kProbePoints},
                                                    {"circular-test", dataset_kind::kCircularTest},
                                                    {"cmm-report", dataset_kind::kCmmReport},
                                                    {"setup-model", dataset_kind::kSetupModel},
                                                    {"feature-series", dataset_kind::kFeatureSeries},
                                                    {"dmis", dataset_kind::kDmis},
                                                    {"hole-table", dataset_kind::kHoleTable},
                                                    {"dfq", dataset_kind::kDfq},
                                                    {"calypso", dataset_kind::kCalypso},
                                                    {"cad-model", dataset_kind::kCadModel},
                                                    {"qif", dataset_kind::kQif},
                                                    {"mtconnect", dataset_kind::kMtconnect}};
  return k;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

/// Measured features of a DMIS output file: FA(...) and TA(...) statements.
long dmisMeasuredCount(const std::string& text) {
  long n = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    line.erase(0, line.find_first_not_of(" \t"));
    std::string head = line.substr(0, 3);
    for (char& c : head) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    n += head == "FA(" || head == "TA(";
  }
  return n;
}

/// Reads `file` (shown as `shown` in messages) as `kind` says.
/// `measuredOnly`: a probe-point file of measured points only (its nominals come from elsewhere,
/// core/project/nominals.h).
/// `part`: a QIF file read as probe points, the measured part (1-based; 0: the file's only one).
DatasetSummary inspect(const std::string& file, const std::string& shown, const std::string& kind,
                       const CsvReadOptions& csv, bool measuredOnly = false, int part = 0) {
  DatasetSummary s;
  s.kind = kind;
  if (kind == dataset_kind::kSetupModel) {
    const setup::Model model = setup::readModel(file);
    s.rows = static_cast<long>(model.dimensions.size());
    return s;
  }
  if (kind == dataset_kind::kCadModel) {
    // An STL part: its triangles (the reader names the file and line or triangle of a problem).
    s.rows = static_cast<long>(geometry::readStl(file).triangles.size());
    return s;
  }
  const std::string text = readFile(file, 256u << 20);
  if (kind == dataset_kind::kMtconnect ||
      (kind == dataset_kind::kThermalLog && looksLikeMtconnectLog(text))) {
    // The resampled table a thermal study reads (time_min and one column per numeric sample).
    const ThermalLog log = readThermalLog(file, 3, csv);
    s.rows = static_cast<long>(log.rows());
    s.columns.push_back(log.timeColumn);
    for (const ThermalChannel& c : log.channels) s.columns.push_back(c.name);
    return s;
  }
  if (part > 0 && !looksLikeQif(text))
    throw ValidationError(ErrorContext{shown, 0, 0, "part"},
                          "applies to a QIF file added as probe points (one measured part of it)");
  if (kind == dataset_kind::kQif || (kind == dataset_kind::kProbePoints && looksLikeQif(text))) {
    if (kind == dataset_kind::kProbePoints) {
      const QifFile qif = qifFromText(text, shown);
      const ProbePointSet set = qifProbePoints(qif, qifPartIndex(qif, part, "part"));
      s.rows = static_cast<long>(set.points.size());
      s.columns = {"id", "surface", "qx", "qy", "qz"};
      if (set.hasNormals) s.columns.insert(s.columns.end(), {"nx", "ny", "nz"});
      s.columns.insert(s.columns.end(), {"px", "py", "pz"});
      return s;
    }
    // The parts (one row each) and the characteristics measured on them.
    const CmmTextReport report = *characteristicTableReport(text, shown, kind);
    s.rows = static_cast<long>(report.runs.size());
    std::set<std::string> seen;
    for (const CmmRun& run : report.runs)
      for (const CmmFeature& f : run.features)
        if (seen.insert(f.featureName).second) s.columns.push_back(f.featureName);
    return s;
  }
  if (kind == dataset_kind::kDfq || kind == dataset_kind::kCalypso ||
      (kind == dataset_kind::kProbePoints && looksLikeCalypsoFeatures(text))) {
    if (const auto table = characteristicTableReport(text, shown, kind)) {
      const CmmTextReport& report = *table;
      s.rows = static_cast<long>(report.format == CmmReportFormat::Dfq ? report.runs.size() : 0);
      std::set<std::string> seen;
      for (const CmmRun& run : report.runs) {
        for (const CmmFeature& f : run.features) {
          if (report.format == CmmReportFormat::Calypso) ++s.rows;
          const std::string title =
              f.label == f.featureName ? f.featureName : f.featureName + " (" + f.label + ")";
          if (seen.insert(title).second) s.columns.push_back(title);
        }
      }
    } else {
      const CsvTable points = calypsoFeaturesProbeTable(text, shown);
      (void)probePointsFromCsv(points, 1);
      s.rows = static_cast<long>(points.rowCount());
      s.columns = points.header();
    }
    return s;
  }
  if (kind == dataset_kind::kDmis || (kind == dataset_kind::kCmmReport && setup::looksLikeDmis(text))) {
    if (!setup::looksLikeDmis(text))
      throw ParseError(ErrorContext{shown, 1, 0, {}}, "not a DMIS file (its first statement is not DMISMN)");
    s.rows = dmisMeasuredCount(text);
    s.dmis = true;
    return s;
  }
  // CMM text reports (OGP step / summary reports, PC-DMIS text reports), recognised by content.
  if ((kind == dataset_kind::kCmmReport || kind == dataset_kind::kFeatureSeries ||
       kind == dataset_kind::kProbePoints) &&
      looksLikeCmmTextReport(text)) {
    const CmmTextReport report = cmmTextReportFromText(text, shown);
    if (kind == dataset_kind::kFeatureSeries) {
      const CsvTable table = cmmReportFeatureTable(report);
      s.rows = static_cast<long>(table.rowCount());
      s.columns = table.header();
    } else if (kind == dataset_kind::kProbePoints) {
      s.rows = static_cast<long>(probePointsFromCmmReport(report, 1).points.size());
      s.columns = {"id", "surface", "qx", "qy", "qz", "px", "py", "pz"};
    } else {
      // Values a setup model can name: those with a nominal (or a printed deviation).
      for (const CmmRun& run : report.runs)
        for (const CmmFeature& f : run.features)
          for (const CmmValue& v : f.values) s.rows += v.nominal || v.printedDeviation ? 1 : 0;
    }
    return s;
  }
  if (kind == dataset_kind::kHoleTable || (kind == dataset_kind::kProbePoints && looksLikeHoleTable(text))) {
    const HoleTable t = holeTableFromText(text, shown, 1);
    s.rows = static_cast<long>(t.points.points.size());
    s.columns = {"Meas X", "Meas Y", "Nom X", "Nom Y"};
    return s;
  }
  const CsvTable table = parseCsv(text, shown, csv);
  s.rows = static_cast<long>(table.rowCount());
  s.columns = table.header();
  s.skipped = table.skippedRows();
  if (kind == dataset_kind::kThermalLog) {
    (void)thermalLogFromCsv(table, 3, csv.sampleIntervalMin);
  } else if (kind == dataset_kind::kProbePoints && measuredOnly) {
    (void)geometry::pointsFromTable(table);
  } else if (kind == dataset_kind::kProbePoints) {
    (void)probePointsFromCsv(table, 1);
  } else if (kind == dataset_kind::kCircularTest) {
    (void)circularTraceFromCsv(table);  // the x/y or the radial-only form
  } else if (kind == dataset_kind::kCmmReport) {
    for (const char* c :
         {"part", "time_min", "dimension", "nominal_mm", "measured_mm", "lower_tol_mm", "upper_tol_mm"})
      (void)table.requireColumn(c);
    table.requireRows(1);
    for (const char* c : {"time_min", "nominal_mm", "measured_mm", "lower_tol_mm", "upper_tol_mm"})
      (void)table.numericColumn(c);
  } else if (kind == dataset_kind::kFeatureSeries) {
    table.requireRows(1);
  }
  return s;
}

std::string extensionFor(const std::string& kind) {
  if (kind == dataset_kind::kSetupModel) return ".json";
  if (kind == dataset_kind::kDfq) return ".dfq";
  if (kind == dataset_kind::kCalypso) return ".txt";
  if (kind == dataset_kind::kDmis) return ".dmi";
  if (kind == dataset_kind::kHoleTable) return ".txt";
  if (kind == dataset_kind::kCadModel) return ".stl";
  if (kind == dataset_kind::kQif) return ".qif";
  if (kind == dataset_kind::kMtconnect) return ".txt";
  return ".csv";
}

}  // namespace

std::optional<CmmTextReport> characteristicTableReport(std::string_view text, const std::string& shown,
                                                       const std::string& kind) {
  if (kind == dataset_kind::kQif) {
    if (!looksLikeQif(text))
      throw ParseError(ErrorContext{shown, 1, 0, {}},
                       "not a QIF 3 document (its root element is not QIFDocument)");
    return qifCmmReport(qifFromText(text, shown));
  }
  if (kind == dataset_kind::kDfq) {
    if (!looksLikeDfq(text))
      throw ParseError(ErrorContext{shown, 1, 0, {}},
                       "not a Q-DAS DFQ file (its first line is not a K field such as 'K0100 3')");
    return dfqCmmReport(dfqFromText(text, shown));
  }
  if (looksLikeCalypsoCharacteristics(text))
    return calypsoCmmReport(calypsoCharacteristicsFromText(text, shown));
  if (looksLikeCalypsoFeatures(text)) return std::nullopt;
  throw ParseError(
      ErrorContext{shown, 1, 0, {}},
      "not a Zeiss Calypso table: its first line names neither a _chr table's columns (id, actual, "
      "nominal, planid or partnb) nor a _fet table's (x, y, z, x_nom, y_nom, z_nom)");
}

const std::vector<std::string>& datasetKindNames() {
  static const std::vector<std::string> names{
      "thermal-log", "probe-points", "circular-test", "cmm-report", "setup-model", "feature-series", "dmis",
      "hole-table",  "dfq",          "calypso",       "cad-model",  "qif",         "mtconnect"};
  return names;
}

std::vector<std::string> datasetKindsServing(const std::string& wanted) {
  if (wanted == dataset_kind::kCmmReport)
    return {dataset_kind::kCmmReport, dataset_kind::kDmis, dataset_kind::kDfq, dataset_kind::kCalypso,
            dataset_kind::kQif};
  if (wanted == dataset_kind::kThermalLog) return {dataset_kind::kThermalLog, dataset_kind::kMtconnect};
  return {wanted};
}

bool datasetKindServes(const std::string& wanted, const std::string& kind) {
  const std::vector<std::string> kinds = datasetKindsServing(wanted);
  return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

std::string datasetKindFromName(const std::string& name, const std::string& field) {
  std::string hyphen = name;
  std::replace(hyphen.begin(), hyphen.end(), '_', '-');
  const auto it = kinds().find(hyphen);
  if (it == kinds().end())
    throw ValidationError(ErrorContext{{}, 0, 0, field},
                          "unknown dataset kind '" + name + "' (one of: " + joined(datasetKindNames()) + ")");
  return it->second;
}

bool datasetKindIsCsv(const std::string& kind) {
  return kind != dataset_kind::kSetupModel && kind != dataset_kind::kDmis &&
         kind != dataset_kind::kHoleTable && kind != dataset_kind::kDfq && kind != dataset_kind::kCalypso &&
         kind != dataset_kind::kCadModel && kind != dataset_kind::kQif && kind != dataset_kind::kMtconnect;
}

DatasetSummary summarizeDataset(const std::string& projectPath, const DatasetRef& dataset) {
  const std::string path = resolveDatasetPath(projectPath, dataset);
  DatasetSummary s = inspect(path, path, dataset.kind, dataset.csv, !dataset.nominals.empty(), dataset.part);
  if (!dataset.paths.empty()) {
    // A DMIS series: every file is a DMIS output file; the rows of all of them.
    const std::vector<std::string> files = resolveDatasetPaths(projectPath, dataset);
    for (std::size_t k = 0; k < files.size(); ++k) {
      const DatasetSummary one = k == 0 ? s : inspect(files[k], files[k], dataset.kind, dataset.csv);
      if (!one.dmis)
        throw ValidationError(ErrorContext{files[k], 0, 0, "paths[" + std::to_string(k) + "]"},
                              "a series of files must be DMIS output files (one per workpiece)");
      if (k > 0) s.rows += one.rows;
    }
  }
  s.id = dataset.id;
  s.path = dataset.path;
  return s;
}

nlohmann::json datasetListJson(const Project& project, const std::string& projectPath) {
  nlohmann::json out = nlohmann::json::array();
  for (const DatasetRef& d : project.datasets) {
    const DatasetSummary s = summarizeDataset(projectPath, d);
    nlohmann::json entry{
        {"id", s.id}, {"kind", s.kind}, {"path", s.path}, {"rows", s.rows}, {"columns", s.columns}};
    if (d.csv.skipBadRows) entry["skipped_rows"] = s.skipped.size();
    out.push_back(std::move(entry));
  }
  return out;
}

CsvTable readDatasetTable(const std::string& projectPath, const DatasetRef& dataset) {
  const std::string path = resolveDatasetPath(projectPath, dataset);
  // A feature series may be a CMM text report (one row per run); every other kind is CSV here.
  if (dataset.kind == dataset_kind::kFeatureSeries) return readFeatureTable(path, dataset.csv);
  // DFQ and Calypso _chr: the feature table (one row per measured part); Calypso _fet: the probe points.
  if (dataset.kind == dataset_kind::kDfq || dataset.kind == dataset_kind::kCalypso ||
      dataset.kind == dataset_kind::kQif) {
    const std::string text = readFile(path, 256u << 20);
    if (const auto report = characteristicTableReport(text, path, dataset.kind))
      return cmmReportFeatureTable(*report);
    return calypsoFeaturesProbeTable(text, path);
  }
  // An MTConnect log: its resampled table (what a thermal study reads).
  if (dataset.kind == dataset_kind::kMtconnect)
    return readMtconnectSampleTable(path, mtconnectIntervalS(dataset.csv.sampleIntervalMin)).table;
  return readCsvFile(path, dataset.csv);
}

std::string embeddedDatasetPath(const std::string& id, const std::string& file, const std::string& kind) {
  std::string ext = file == "-" ? std::string() : fs::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext.size() < 2) ext = extensionFor(kind);
  return "data/" + id + ext;
}

void embedDataset(const std::string& projectPath, const std::string& file, DatasetRef& dataset) {
  const std::string rel = embeddedDatasetPath(dataset.id, file, dataset.kind);
  const fs::path folder = fs::absolute(fs::path(parentFolder(projectPath))).lexically_normal();
  const fs::path target = folder / rel;
  std::error_code ec;
  if (fs::exists(target, ec))
    throw ValidationError(ErrorContext{target.string(), 0, 0, {}},
                          "already exists; an embedded copy never overwrites a file (choose another id, "
                          "or remove or rename the file)");
  const std::string content = readFile(file, 256u << 20);
  fs::create_directories(target.parent_path(), ec);
  if (ec)
    throw FileError(ErrorContext{target.parent_path().string(), 0, 0, {}},
                    "cannot create the folder (" + ec.message() + ")");
  writeFileAtomic(target.string(), content);
  dataset.path = rel;
}

DatasetRef addDataset(Project& project, const std::string& projectPath, const AddDatasetRequest& request) {
  DatasetRef ref;
  std::string kindName = request.kind;
  if (kindName == kGuessKind) {
    const std::string text = readFile(request.file, 256u << 20);
    kindName = guessDatasetKind(request.file, std::string_view(text).substr(0, 256 * 1024), request.csv);
  }
  ref.kind = datasetKindFromName(kindName);
  ref.csv = request.csv;
  ref.description = request.description;
  ref.dmis = request.dmis;
  if (!datasetKindIsCsv(ref.kind) &&
      (!(request.csv.dialect == CsvDialect{}) || !request.csv.columnMap.empty() ||
       request.csv.headerLines >= 0 || !request.csv.commentPrefix.empty() || request.csv.skipBadRows)) {
    throw ValidationError(
        ErrorContext{{}, 0, 0, "KIND"},
        "a " + ref.kind +
            " dataset is not a CSV file; --delimiter, --decimal, --map, --header-lines, --comment and "
            "--skip-bad-rows do not apply");
  }
  if (!datasetKindServes(dataset_kind::kThermalLog, ref.kind) && request.csv.sampleIntervalMin > 0.0) {
    throw ValidationError(ErrorContext{{}, 0, 0, "--sample-interval"},
                          "applies to thermal logs only, not to a " + ref.kind + " dataset");
  }
  const bool fromStdin = request.file == "-";
  ref.id = request.id;
  if (ref.id.empty()) {
    if (fromStdin)
      throw ValidationError(ErrorContext{{}, 0, 0, "--id"},
                            "is required when the data come from standard input");
    ref.id = fs::path(request.file).stem().string();
    const std::string base = ref.id;
    for (int k = 2; project.dataset(ref.id) != nullptr; ++k) ref.id = base + "-" + std::to_string(k);
  }
  if (ref.id.empty()) throw ValidationError(ErrorContext{{}, 0, 0, "--id"}, "must not be empty");
  if (project.dataset(ref.id) != nullptr)
    throw ValidationError(ErrorContext{projectPath, 0, 0, "--id"},
                          "the project already has a dataset '" + ref.id + "'");

  // Read and check the file before the project changes. A DMIS reading applies to DMIS files only: a
  // dmis dataset, or a cmm-report that turns out to be one.
  const auto notDmis = [&] {
    return ValidationError(ErrorContext{displayPath(request.file), 0, 0, "--ta-meaning"},
                           "is not a DMIS file; --ta-meaning and --ta-sign apply to DMIS output only");
  };
  if (request.guessRoles && datasetKindIsCsv(ref.kind) && ref.csv.columnMap.empty()) {
    CsvReadOptions o = ref.csv;
    o.skipBadRows = true;  // only the header is needed here; inspect() below judges the rows
    std::vector<std::string> header;
    try {
      header = parseCsv(readFile(request.file, 256u << 20), displayPath(request.file), o).header();
    } catch (const Error&) {
      // Unreadable as CSV: inspect() below says why, naming the file and line.
    }
    std::string kindSpelling = ref.kind;
    std::replace(kindSpelling.begin(), kindSpelling.end(), '_', '-');
    ref.csv.columnMap = suggestColumnRoles(kindSpelling, header);
  }
  const bool dmisReading = !(ref.dmis == setup::DmisOptions{});
  if (dmisReading && ref.kind != dataset_kind::kDmis && ref.kind != dataset_kind::kCmmReport) throw notDmis();
  if (!request.nominals.empty()) {
    if (ref.kind != dataset_kind::kProbePoints)
      throw ValidationError(
          ErrorContext{{}, 0, 0, "KIND"},
          "only probe points take their nominals from an element, a reference measurement or a CAD part");
    checkNominalSource(request.nominals);
    ref.nominals = request.nominals;
    (void)nominalReference(project, ref);  // another probe-point dataset, or a CAD part, of the project
  }
  if (request.part > 0) {
    if (ref.kind != dataset_kind::kProbePoints)
      throw ValidationError(ErrorContext{displayPath(request.file), 0, 0, "--part"},
                            "applies to a QIF file added as probe points (one measured part of it)");
    ref.part = request.part;
  }
  const DatasetSummary s =
      inspect(request.file, displayPath(request.file), ref.kind, ref.csv, !ref.nominals.empty(), ref.part);
  if (dmisReading && !s.dmis) throw notDmis();
  const fs::path folder = fs::absolute(fs::path(parentFolder(projectPath))).lexically_normal();
  const auto relativePath = [&folder](const std::string& given) {
    const fs::path file = fs::absolute(fs::path(given)).lexically_normal();
    const fs::path rel = file.lexically_relative(folder);
    return rel.empty() ? file.string() : rel.string();
  };
  if (!request.moreFiles.empty()) {
    // A DMIS series: every file a DMIS output file of the kind, referenced where it is.
    if (request.embed || fromStdin)
      throw ValidationError(ErrorContext{{}, 0, 0, "FILE"},
                            "a series of DMIS files is referenced where it is, not embedded or read from "
                            "standard input");
    if (ref.kind != dataset_kind::kCmmReport && ref.kind != dataset_kind::kDmis)
      throw ValidationError(ErrorContext{{}, 0, 0, "KIND"},
                            "several files make one dataset only as a DMIS series (cmm-report or dmis)");
    if (!s.dmis)
      throw ValidationError(ErrorContext{displayPath(request.file), 0, 0, {}},
                            "is not a DMIS file; only DMIS output files make a series");
    ref.path = relativePath(request.file);
    ref.paths.push_back(ref.path);
    for (const std::string& more : request.moreFiles) {
      // Not DMIS: say so first (read as the kind's CSV it would fail on something else).
      if (!setup::looksLikeDmis(readFile(more, 256u << 20)))
        throw ValidationError(ErrorContext{displayPath(more), 0, 0, {}},
                              "is not a DMIS file; only DMIS output files make a series");
      const DatasetSummary m = inspect(more, displayPath(more), ref.kind, ref.csv);
      if (!m.dmis)
        throw ValidationError(ErrorContext{displayPath(more), 0, 0, {}},
                              "is not a DMIS file; only DMIS output files make a series");
      ref.paths.push_back(relativePath(more));
    }
    project.datasets.push_back(ref);
    return ref;
  }
  if (request.embed) {
    embedDataset(projectPath, request.file, ref);
  } else if (fromStdin) {
    const std::string content = readFile("-", 256u << 20);
    ref.path = ref.id + (looksLikeCmmTextReport(content) ? std::string(".txt") : extensionFor(ref.kind));
    writeFileAtomic((folder / ref.path).string(), content);
  } else {
    const fs::path file = fs::absolute(fs::path(request.file)).lexically_normal();
    const fs::path rel = file.lexically_relative(folder);
    ref.path = rel.empty() ? file.string() : rel.string();
  }
  // Nominals made from an element or a reference: they must come out (the fit runs, the ids pair).
  if (!ref.nominals.empty()) (void)readProjectProbePoints(project, projectPath, ref);
  project.datasets.push_back(ref);
  return ref;
}

}  // namespace metrofit
