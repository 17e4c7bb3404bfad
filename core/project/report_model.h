#pragma once
// From a CMM report to a setup model (issue 28 item 3): the characteristics a report measures, as the
// setup model's dimensions would name them, and the model built from (or extended by) a chosen set of
// them. The GUI's "Create setup model from report…" / "Add report features to setup model…" dialog and
// its tests use these functions; nothing here needs Qt.
//
// How a dimension of the model names what the report measured (core/setup/report.h):
//   * CMM text reports (OGP step / summary reports, PC-DMIS text reports): the dimension's "label" is
//     "<feature>:<value>", the feature being the OGP Comment / summary step title (or "Step n" when
//     the label is empty or names two steps of one run), the PC-DMIS dimension name; the value being
//     the printed value's name ("Diameter", "Z Location", PC-DMIS axis "X", "D", ...).
//   * DMIS output files: the label is the DMIS label (F(label), FA(label), T(label), TA(label)).
//   * CSV report series: the report's `dimension` column names the model's dimension by its id, so the
//     dimension's id is the report's name and the label stays empty (ReportFeatures::byId).
// The label is the report mapping that the relation-graph editor edits (its "Report feature" column);
// it is the "label" key of the setup-model JSON (docs/file-formats.md#setup-model), so no new key is
// needed in the project or model files.
//
// Building the model (addReportCharacteristics): each chosen characteristic becomes one dimension
// (id "<feature> <value>", or the CSV name) with the report's nominal and tolerance limits, under one
// feature node per report feature (id: the feature's name), and, when `connectTo` names a setup
// datum, an arc datum -> feature (+1) and feature -> dimension (+1), so the model is valid at once and
// the user refines the arcs in the editor. Characteristics the report prints no tolerance for take
// ±defaultToleranceMm (a value the dialog shows and the user sets; 0 refuses them). Characteristics the
// model already reads (same label, compared as the reader compares it: case-insensitively; for CSV the
// same id) are skipped, so "Add report features" adds only what the model lacks.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/io/csv.h"
#include "core/project/project.h"
#include "core/setup/model.h"

namespace metrofit {

/// One measured characteristic of a report, as a dimension of a setup model would read it.
struct ReportCharacteristic {
  std::string feature;         ///< the report's feature ("oriball", "Step 7", "LOC1", DMIS label, CSV name)
  std::string characteristic;  ///< the value ("Diameter", "Z Location", "X", DMIS tolerance type); "" CSV
  std::string label;           ///< the dimension label that reads it ("" for CSV: the id reads it)
  std::string unit = "mm";     ///< "mm" or "deg"
  std::optional<double> nominal;
  std::optional<double> lower, upper;  ///< limits relative to the nominal; absent: none printed
  bool usable = true;                  ///< false: a setup model cannot read it (why says why)
  std::string why;
  long line = 0;  ///< first line of the report that prints it
};

struct ReportFeatures {
  std::string source;  ///< the file read
  std::string
      format;  ///< "OGP step report", "OGP summary report", "PC-DMIS text report", "DMIS output", "CSV"
  bool byId = false;                                  ///< CSV: the report names the model's dimensions by id
  std::vector<ReportCharacteristic> characteristics;  ///< in report order, each once
};

/// The characteristics of one report file (CSV report series, DMIS output or CMM text report, told
/// apart by content; `csv` is how a CSV report is read). InputError (naming file and line) when the
/// file cannot be read.
ReportFeatures readReportFeatures(const std::string& file, const CsvReadOptions& csv = {});
/// The same for the files of a project dataset (cmm_report or dmis); several files (a series) are
/// merged, each characteristic once.
ReportFeatures datasetReportFeatures(const std::string& projectPath, const DatasetRef& dataset);

/// The dimension of `model` that reads `c` (its label, case-insensitive; CSV: its id), or -1.
int modelDimensionFor(const setup::Model& model, const ReportFeatures& report, const ReportCharacteristic& c);

/// A new, empty model for a report: name, axis, one work offset "W1" (the datum the dimensions hang from
/// until the user draws the real graph).
setup::Model newReportModel(const std::string& name, const std::string& axis = "Z");

struct ReportModelOptions {
  std::string connectTo;            ///< setup datum the new features hang from ("" = no arcs)
  double defaultToleranceMm = 0.0;  ///< ± limits for characteristics printed without a tolerance
};

/// `model` with the characteristics `chosen` (indices into report.characteristics) added (see the
/// header comment); those the model reads already are skipped. ValidationError naming the
/// characteristic for an unusable one, one without a tolerance when defaultToleranceMm <= 0, an index out
/// of range, or a `connectTo` that is not a setup datum of the model.
setup::Model addReportCharacteristics(setup::Model model, const ReportFeatures& report,
                                      const std::vector<std::size_t>& chosen,
                                      const ReportModelOptions& options);

}  // namespace metrofit
