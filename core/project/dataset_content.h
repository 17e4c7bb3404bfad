#pragma once
// A dataset's content as a table, the way the GUI's "Show data" view (widgets/data/datasetview.h)
// shows it. Two shapes:
//   * Features: a CMM report (a CMM text report: OGP step / summary report, PC-DMIS text report; or
//     the CSV form part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm) as one
//     row per measured characteristic: part, feature, characteristic, unit, nominal, actual,
//     deviation = actual - nominal (plain sign; OGP PRINTS sign(nominal) * (actual - nominal) for
//     locations, core/io/cmm_text_report.h), the tolerance limits relative to the nominal and whether
//     the deviation lies outside them. Limits printed as 0 (OGP's "no tolerance": Upper and Lower 0,
//     or a Tolerance of 0) count as none.
//     PC-DMIS: OUTTOL != 0 marks a value out of tolerance as well.
//   * Columns: every other dataset as the readers see it (the dataset's dialect and column mapping
//     applied), each column with the file's own name and its unit: a thermal log, a feature series
//     (a CMM text report read as one: one row per run), probe points (a CSV; a hole table or a CMM
//     text report as the points the matching reads), a circular test, a setup model's dimensions.
// A DMIS file (a dmis dataset or a cmm-report that is one) is read as a table of its statements'
// features (F / FA / T / TA labels; dmisFeatureRows).
// Errors are those of the readers (FileError, ParseError, ValidationError naming the file).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/project/project.h"

namespace metrofit {

/// One characteristic of a measured feature: a row of the feature table.
struct FeatureTableRow {
  std::string part;     ///< part or run ("" when the report has one run)
  std::string feature;  ///< OGP label (else "Step n"), PC-DMIS dimension name, CSV dimension, DMIS label
  std::string
      characteristic;  ///< "Diameter", "X Location", PC-DMIS axis "X", DMIS tolerance type; "" for CSV
  std::string unit;    ///< "mm" or "deg"
  std::optional<double> nominal;
  std::optional<double> actual;     ///< absent when a DMIS TA gives the deviation only
  std::optional<double> deviation;  ///< actual - nominal rounded to 1e-9 (absent without a nominal)
  std::optional<double> lower;      ///< lower limit relative to the nominal (absent: no tolerance)
  std::optional<double> upper;      ///< upper limit relative to the nominal (absent: no tolerance)
  bool outOfTolerance = false;
  long line = 0;  ///< physical line of the file
};

/// Whether a deviation lies outside the limits (each absent limit is no limit): below lower or above
/// upper by more than `slack` (the rounding of the printed digits).
bool outsideTolerance(double deviation, std::optional<double> lower, std::optional<double> upper,
                      double slack = 0.0);

/// The feature rows of a CMM text report, in file order (part "" for a single run, else "run <k>
/// (#<run number>, <date>)" for the k-th run of the file: run numbers repeat from day to day). DFQ and
/// Calypso tables: the workpiece's serial (K0014, partnb), else "<part number> #<value set>", with the
/// date in parentheses when the file gives one.
std::vector<FeatureTableRow> cmmReportFeatureRows(const CmmTextReport& report);
/// The feature rows of a CMM report series CSV (columns as core/setup/report.h names them, mapped).
std::vector<FeatureTableRow> cmmCsvFeatureRows(const CsvTable& table);
/// The feature rows of a DMIS output file: per label, the nominal of F(label) and the actual of
/// FA(label) (diameter when both have one, else the three coordinates), and the T(label) / TA(label)
/// tolerance (lower / upper limits, the TA value as actual when no FA gives one; TA's OUTOL / OUTTOL
/// marks the row). ParseError naming the line for a statement that cannot be read.
std::vector<FeatureTableRow> dmisFeatureRows(std::string_view text, const std::string& source);

/// The unit a column name states: a role suffix ("_um" -> "µm", "_mm", "_degC" -> "°C", "_deg" -> "°",
/// "_s", "_min", "_h", "_rpm" -> "1/min", "_ppm", "_nm") or a trailing bracket as shops write it
/// ("[µm]", "(°C)", "[1/min]"); the probe-point roles qx..pz are in mm. "" when the name states none.
std::string columnDisplayUnit(const std::string& name);

struct DatasetContent {
  enum class Shape { Columns, Features };
  Shape shape = Shape::Columns;
  std::string format;  ///< "CSV", "OGP step report", "DMIS output", "setup model", "hole table", ...
  std::string file;    ///< the resolved path that was read
  /// Columns: the table as the readers see it (header after the mapping).
  CsvTable table;
  /// Columns: per column of `table`, the file's own name (the same as the header when not mapped).
  std::vector<std::string> fileColumns;
  /// Columns: per column, its unit (columnDisplayUnit of the file's name, else of the role); "" none.
  std::vector<std::string> units;
  /// Features: the rows.
  std::vector<FeatureTableRow> features;
};

/// Reads a dataset of the project saved at `projectPath` for display (see the header comment). Probe
/// points whose nominals come from elsewhere (core/project/nominals.h) are shown as the studies read
/// them, with each point's deviation before matching (`d_mm`); a second measurement's reference is
/// looked up in `project`.
DatasetContent readDatasetContent(const std::string& projectPath, const DatasetRef& dataset,
                                  const Project* project = nullptr);
/// The same for a file already resolved (`file`), read as `dataset` says; `reference`: the resolved
/// dataset of a second measurement the nominals come from (nullptr when there is none).
DatasetContent readDatasetContentFile(const std::string& file, const DatasetRef& dataset,
                                      const DatasetRef* reference = nullptr);

}  // namespace metrofit
