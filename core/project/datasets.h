#pragma once
// Own data in a project (docs/file-formats.md#own-data-in-a-project): adding a file to a project as
// a dataset of a kind, reading a dataset the way the project says (CSV dialect and column mapping
// saved with it), and the summary `project list` prints. The CLI's `project new|add|list` and a GUI
// import dialog share these functions.
//
// Kinds, as the command line spells them (the project file writes '_' for '-'):
//   thermal-log    CSV, read as a thermal log (time column, strictly increasing time)
//   probe-points   CSV of contact-probed points, a PC-DMIS hole-table report or a CMM text report
//   circular-test  CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm
//   cmm-report     CSV part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm, a
//                  DMIS output file or a CMM text report (OGP step / summary report, PC-DMIS text
//                  report; core/io/cmm_text_report.h), told apart by content (the setup study reads
//                  it against its model); rows: the values with a nominal
//   setup-model    JSON relation graph (no CSV options)
//   feature-series CSV of measured feature values in production order (SPC), or a CMM text report
//                  (one row per run, cmmReportFeatureTable)
//   dmis           DMIS output file (no CSV options)
//   hole-table     PC-DMIS hole-table report (no CSV options)
//   dfq            Q-DAS DFQ / AQDEF file (core/io/dfq.h; no CSV options): characteristics with their
//                  values per measured part; a setup report series, a feature series per characteristic
//                  (SPC); rows: the measured parts, columns: the characteristics ("number (description)")
//   calypso        Zeiss Calypso table file (core/io/calypso.h; no CSV options), told apart by content: a
//                  _chr table (characteristics per measured part: a setup report series or a feature
//                  series; rows: its rows, columns: the characteristic ids) or a _fet table (features as
//                  probe points; rows: the points)
// A dataset is checked when it is added: the file is read as its kind says, so a wrong delimiter or
// a missing mapped column is an error then (InputError naming file, line and field), not later.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/project/project.h"

namespace metrofit {

/// The kinds as the command line spells them: "thermal-log", ..., "hole-table".
const std::vector<std::string>& datasetKindNames();
/// "thermal-log" (or "thermal_log") -> dataset_kind::kThermalLog, ...; ValidationError naming
/// `field` for an unknown kind.
std::string datasetKindFromName(const std::string& name, const std::string& field = "KIND");
/// True for the kinds read as CSV (they take a dialect and a column mapping).
bool datasetKindIsCsv(const std::string& kind);

/// What `project list` prints of one dataset.
struct DatasetSummary {
  std::string id;
  std::string kind;
  std::string path;                    ///< as stored in the project (relative to its folder)
  long rows = 0;                       ///< data rows, points, holes, dimensions or measured features
  std::vector<std::string> columns;    ///< the columns as the readers see them (after the mapping)
  bool dmis = false;                   ///< read as a DMIS output file
  std::vector<CsvRowProblem> skipped;  ///< rows left out (CsvReadOptions::skipBadRows)
};

/// The kinds (project spelling) a study setting that asks for a `wanted` dataset may name: `wanted`
/// itself, and for a CMM report (dataset_kind::kCmmReport) every report of measured dimensions: DMIS
/// output, a Q-DAS DFQ file, a Calypso _chr table, a QIF Results file; for a thermal log
/// (dataset_kind::kThermalLog) an MTConnect log (read as its resampled table). One list for the studies,
/// the settings check and the GUI.
std::vector<std::string> datasetKindsServing(const std::string& wanted);
/// True when a dataset of `kind` serves where a `wanted` one is asked for (datasetKindsServing).
bool datasetKindServes(const std::string& wanted, const std::string& kind);

/// Reads a dataset as its kind says, with its dialect and mapping; InputError when it cannot be read.
DatasetSummary summarizeDataset(const std::string& projectPath, const DatasetRef& dataset);
/// `project list`: [{"id", "kind", "path", "rows", "columns"}] in project order; a dataset that skips
/// unreadable rows also has "skipped_rows" (their count).
nlohmann::json datasetListJson(const Project& project, const std::string& projectPath);

/// A dfq or calypso dataset's text (kind: dataset_kind::kDfq or kCalypso) as a report of characteristics
/// (dfqCmmReport / calypsoCmmReport); nullopt for a Calypso _fet table (probe points:
/// calypsoFeaturesProbeTable). ParseError naming `shown` when the text is not of the kind.
std::optional<CmmTextReport> characteristicTableReport(std::string_view text, const std::string& shown,
                                                       const std::string& kind);

/// The CSV table of a CSV dataset, read with the dataset's dialect and mapping; for a dfq or calypso
/// dataset the feature table of its characteristics (cmmReportFeatureTable) or a _fet's probe points.
CsvTable readDatasetTable(const std::string& projectPath, const DatasetRef& dataset);

struct AddDatasetRequest {
  std::string kind;  ///< command-line or project spelling
  std::string file;  ///< path as the user gave it (relative to the working folder), or "-"
  std::string id;    ///< empty: the file's base name without extension (made unique)
  CsvReadOptions csv;
  std::string description;
  setup::DmisOptions dmis = {};  ///< DMIS files only (a DMIS dataset or a cmm-report that is a DMIS file)
  /// Copy the file into the project's folder as data/<id>.<ext> (embedDataset) instead of referencing it.
  bool embed = false;
  /// A CSV dataset without a column mapping (csv.columnMap empty) takes the roles suggestColumnRoles
  /// (core/project/import_guess.h) finds in its header ("Zeit [min]" -> time_min, "Soll X [µm]" -> qx,
  /// read in mm), as the import dialog does; the applied mapping is the dataset's csv.columnMap.
  bool guessRoles = false;
  /// Further DMIS output files of the same series, one per workpiece (`file` is the first): the dataset
  /// then lists them all in "paths" (core/project/project.h). Each must be a DMIS file; a series is
  /// referenced where it is, not embedded and not read from standard input.
  std::vector<std::string> moreFiles;
  /// A probe-point file of measured points only: where its nominals come from (core/project/nominals.h);
  /// checked (the element fits, the reference pairs) before the dataset is added.
  NominalSource nominals = {};
  /// A QIF file of several measured parts added as probe points: the part (1-based; DatasetRef::part).
  int part = 0;
};

/// The kind `project add` takes to mean "guess it from the file" (guessDatasetKind).
inline constexpr const char* kGuessKind = "auto";

/// Where an embedded copy of `file` goes, relative to the project's folder: "data/<id>.<ext>" with
/// the file's own extension (lower case), or the kind's usual one when the file has none.
std::string embeddedDatasetPath(const std::string& id, const std::string& file, const std::string& kind);
/// Copies `file` to embeddedDatasetPath(...) in the folder of `projectPath` (creating data/) and
/// points dataset.path to the copy. ValidationError naming the copy when it exists already (an
/// embedded file is never overwritten); FileError when it cannot be written.
void embedDataset(const std::string& projectPath, const std::string& file, DatasetRef& dataset);

/// Adds a dataset to `project` (saved at `projectPath`); request.kind kGuessKind: the kind the file's
/// name and content say (guessDatasetKind, read with request.csv). The file is referenced relative to the
/// project's folder (absolute when it is on another root), or, for "-" (standard input), copied into
/// the project's folder as "<id>.<ext>" (an --id is then required). The file is read and checked as
/// its kind says before anything is changed. ValidationError for a duplicate id, CSV options on a
/// kind that is not CSV, DMIS options on a file that is not DMIS, an unknown kind, an embedded copy
/// that exists already. With `embed`, the file is copied (embedDataset). Returns the new dataset
/// (also appended to the project).
DatasetRef addDataset(Project& project, const std::string& projectPath, const AddDatasetRequest& request);

}  // namespace metrofit
