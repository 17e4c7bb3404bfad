#pragma once
// The Metrofit project file (.metrofit): versioned JSON holding the studies' models, references to
// (or embedded) data, method settings and the last results. The GUI document wraps it with an undo
// stack; the CLI and the report read the same file.
//
// {
//   "format": "metrofit-project", "version": 1,
//   "name": "Demo cell", "description": "...",
//   "datasets": [ {"id": "thermal", "kind": "thermal_log", "path": "data/thermal_demo.csv",
//                  "description": "...",
//                  "delimiter": ";", "decimal": ",", "map": {"time_min": "Zeit"}} ],
//   "studies": { "setup": {...}, "matching": {...}, "kinematics": {...}, "thermal": {...},
//                "diagnosis": {...} },
//   "results": { ... }
// }
// Dataset paths are relative to the project file's folder (absolute paths are kept as they are).
// "delimiter" (",", ";", "tab"), "decimal" (".", ",") and "map" (role -> the file's column) say how a
// CSV dataset is read (core/io/csv.h); absent means auto-detection and no mapping, so projects written
// before them read as before. Optional, written only when not the default: "header_lines" (lines
// before the column-name row), "comment" (the comment prefix, default "#"), "skip_bad_rows" (true:
// unreadable rows are left out and counted) and, for a DMIS file, "dmis": {"ta_meaning":
// "auto|deviation|actual", "ta_sign": "plain|nominal"} (core/setup/dmis_options.h).
// A DMIS series (several DMIS output files, one per measured workpiece, read as one setup series;
// core/setup/report.h) is one dataset of kind "cmm_report" or "dmis" with the optional key "paths": every
// file of the series in order, each relative to the project's folder like "path"; "path" is then the first
// of them, so a reader that knows only "path" still finds a file of the series. Without "paths" (every
// project written before it) the dataset is the one file of "path".
// A probe-point dataset whose file has measured points only (raw CMM points: id,x,y,z) takes its
// nominals from "nominals" (core/project/nominals.h):
//   {"from": "element", "element": "sphere", "criterion": "ls"|"minimax", "radius_mm": 12.7 (optional:
//    a fixed radius), "robust": false, "inner": false}   nominal = the foot on the element fitted to the
//    points, normal = the element's normal there (reversed with "inner": true, a bore or a hole);
//   {"from": "reference", "reference": "DATASET_ID", "pair": "id"|"order", "element": "" | "sphere" ...,
//    "inner": false}   nominal = the same point of a second measurement of the part (another probe-point
//    dataset's measured points), paired by id or by order; normals from the element fitted to the
//    reference points ("element"), or none (position-only points) when "element" is absent;
//   {"from": "cad", "cad": "DATASET_ID"}   nominal = the closest point of the CAD part (a cad_model
//    dataset), normal = its outward surface normal there; the matching study re-projects the points
//    onto the part at each posture (core/matching/cad_match.h) until the posture stops changing.
// core/project/datasets.h adds and lists datasets.
// Study objects are owned by the method that uses them; unknown keys are preserved on save.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/csv.h"
#include "core/setup/dmis_options.h"

namespace metrofit::machine {
struct MachineDefinition;  // core/machine/machine.h
}

namespace metrofit {

/// Kinds of dataset a project may reference.
namespace dataset_kind {
inline constexpr const char* kThermalLog = "thermal_log";
inline constexpr const char* kProbePoints = "probe_points";
inline constexpr const char* kCircularTest = "circular_test";
inline constexpr const char* kCmmReport = "cmm_report";
inline constexpr const char* kSetupModel = "setup_model";
/// A CSV of measured feature values in production order (e.g. bore diameters), charted by SPC.
inline constexpr const char* kFeatureSeries = "feature_series";
/// A DMIS output file (measured features and tolerances).
inline constexpr const char* kDmis = "dmis";
/// A PC-DMIS hole-table report (core/matching/hole_table.h).
inline constexpr const char* kHoleTable = "hole_table";
/// A CAD part as a triangle mesh (STL, core/geometry/stl.h): the nominal of measured points.
inline constexpr const char* kCadModel = "cad_model";
/// A Q-DAS DFQ (AQDEF) file: characteristics with their measured values (core/io/dfq.h).
inline constexpr const char* kDfq = "dfq";
/// A Zeiss Calypso table file: characteristics (_chr) or features as probe points (_fet)
/// (core/io/calypso.h).
inline constexpr const char* kCalypso = "calypso";
/// A QIF 3 Results file (core/io/qif.h): measured parts with their characteristics (a CMM report series)
/// and features (probe points: nominal and actual locations, normals).
inline constexpr const char* kQif = "qif";
/// An MTConnect log (core/io/mtconnect.h): an SHDR adapter log or a Streams document, read as a thermal
/// log resampled to a grid (its interval: DatasetRef::csv.sampleIntervalMin; 0: one second).
inline constexpr const char* kMtconnect = "mtconnect";
}  // namespace dataset_kind

/// The studies of a project, in navigator order.
namespace study {
inline constexpr const char* kSetup = "setup";
inline constexpr const char* kMatching = "matching";
inline constexpr const char* kKinematics = "kinematics";
inline constexpr const char* kThermal = "thermal";
inline constexpr const char* kDiagnosis = "diagnosis";
inline constexpr const char* kAll[] = {kSetup, kMatching, kKinematics, kThermal, kDiagnosis};
}  // namespace study

/// Where a probe-point dataset's nominals come from (the "nominals" key above); `from` empty: the file's
/// own nominal columns.
struct NominalSource {
  std::string from;  ///< "", "element", "reference" or "cad"
  std::string
      element;  ///< element kind (core/geometry/element_fit.h spelling), or "" (reference: no normals)
  std::string criterion;    ///< "ls" (or "" = ls) or "minimax"
  double radiusMm = 0.0;    ///< > 0: the element's radius is fixed (sphere, circle, cylinder)
  bool robust = false;      ///< stray points left out of the fit (they keep their foot on the element)
  bool inner = false;       ///< the material is outside the element (a bore): normals point inwards
  std::string reference;    ///< "reference": the dataset id of the second measurement
  std::string pair = "id";  ///< "reference": "id" or "order"
  std::string cad;          ///< "cad": the dataset id of the CAD part (kind cad_model)
  bool empty() const { return from.empty(); }
  bool operator==(const NominalSource&) const = default;
};

struct DatasetRef {
  std::string id;    ///< unique within the project
  std::string kind;  ///< one of dataset_kind
  std::string path;  ///< relative to the project folder, or absolute (a series: its first file)
  std::string description;
  std::string licence;           ///< e.g. "MIT (CAIVIAC), see LICENSE-MIT.txt" for real data
  CsvReadOptions csv;            ///< how a CSV dataset is read: dialect (0 = detect) and column mapping
  setup::DmisOptions dmis = {};  ///< how a DMIS file's TA(label) values are read
  /// A series of DMIS files ("paths"): every file, paths[0] == path; empty for a single file. Last, so
  /// that positional initialisers of the fields before it stay valid.
  std::vector<std::string> paths = {};
  /// A probe-point dataset of measured points only: where its nominals come from (see above).
  NominalSource nominals = {};
  /// A file of several measured parts (QIF) read as probe points: the part to read, 1-based ("part");
  /// 0: the file must hold one part.
  int part = 0;
  bool operator==(const DatasetRef&) const = default;
};

class Project {
 public:
  static constexpr int kFormatVersion = 1;
  static constexpr const char* kFormatName = "metrofit-project";
  static constexpr const char* kFileSuffix = ".metrofit";

  std::string name = "Untitled";
  std::string description;
  std::vector<DatasetRef> datasets;
  nlohmann::json studies = nlohmann::json::object();  ///< study name -> settings object
  nlohmann::json results = nlohmann::json::object();  ///< study name -> last results

  /// The dataset with this id, or nullptr.
  const DatasetRef* dataset(const std::string& id) const;
  /// The first dataset of a kind, or nullptr.
  const DatasetRef* firstOfKind(const std::string& kind) const;

  nlohmann::json toJson() const;
  /// Validates format, version, field types, unique dataset ids. `source` names the file in errors.
  static Project fromJson(const nlohmann::json& j, const std::string& source);

  bool operator==(const Project&) const = default;
};

/// The machine of the matching study, studies.matching.machine:
///   {"topology": "xfyzba" | "ac-table" | "bc-table" | "head-table" (also "ac", "bc"), "LX_mm": ..,
///    "LY_mm": .., "LZ_mm": .., "LAB_mm": .., "tilt_axis_point_mm": [..], "rotary_axis_point_mm": [..],
///    "pivot_mm": .., "rotary_travel_deg": [[min, max], [min, max]], "linear_travel_mm": [[min, max] x 3]}
///    (machine::MachineDefinition::toJson; missing
/// keys take the topology's preset). Returns false (and leaves *out alone) when the study has none;
/// ValidationError naming `source` and the field "studies.matching.machine.<key>" when it is invalid.
/// Project::fromJson runs this check, so a loaded project's machine is valid.
bool matchingMachine(const Project& project, machine::MachineDefinition* out, const std::string& source = {});
/// Sets studies.matching.machine to the definition (canonical topology names).
void setMatchingMachine(Project& project, const machine::MachineDefinition& definition);

/// Reads and validates a project file (FileError / ParseError / ValidationError on bad input).
Project loadProject(const std::string& path);
/// Writes the project atomically (temporary file in the same folder, fsync, rename).
void saveProject(const Project& project, const std::string& path);
/// Resolves a dataset path against the folder of the project file (a series: its first file).
std::string resolveDatasetPath(const std::string& projectPath, const DatasetRef& dataset);
/// The dataset's files as stored: `paths` for a series, else {path}.
std::vector<std::string> datasetFiles(const DatasetRef& dataset);
/// Every file of the dataset resolved against the folder of the project file.
std::vector<std::string> resolveDatasetPaths(const std::string& projectPath, const DatasetRef& dataset);

}  // namespace metrofit
