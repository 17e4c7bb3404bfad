#pragma once
// The columns a thermal model works on, picked out of a thermal log (docs/file-formats.md#thermal-log) and
// validated with errors that name the file and the column (STYLE.md §9):
//  * the target and every input must be columns of the log (the error lists the columns it has),
//  * inputs must be distinct and must not be the target,
//  * every value must be finite (the CSV reader already names file, line and column for text; logs
//    built in code are checked here and name the row); in a log with gaps (ThermalLog::gaps, an
//    MTConnect log) a row with a gap (NaN) in the target or an input is left out instead and counted
//    (ThermalSeries::rowsWithGapsLeftOut); gaps in the columns not used leave every row in,
//  * at least 2 rows.
// Model-specific checks (constant inputs on the fitting rows, too few rows for the model) are in
// thermal_model.h, where the fitting rows are known.
//
// Every model of this module works on changes since the first row of a log: Abdulshahed 2016's Table 1 starts
// every series (inputs and displacement) at zero, and the GMC(1,N) response has no static offset (its
// output is a lag of sum_j (b_j / b_1) x_j plus a decaying start term; grey.h), so a log that starts
// warm is referred to its own first row. `change()` gives x(k) - x(1).
#include <cstddef>
#include <string>
#include <vector>

#include "core/thermal/thermal_log.h"

namespace metrofit::thermal {

struct ThermalSeries {
  std::string source;      ///< the log's file name, for messages
  std::string timeColumn;  ///< "time_s", "time_min" or "time_h" as in the log
  std::vector<double> timeMin;
  std::string targetName;
  std::vector<double> target;  ///< empty when the log has no target column (prediction only)
  std::vector<std::string> inputNames;
  std::vector<std::vector<double>> inputs;  ///< [input][row]
  /// Rows of the log left out for a gap (NaN) in the target or an input (a log with gaps only).
  std::size_t rowsWithGapsLeftOut = 0;

  std::size_t rows() const { return timeMin.size(); }
  bool hasTarget() const { return !target.empty(); }
  /// The first `n` rows (n <= rows()).
  ThermalSeries head(std::size_t n) const;
};

/// Picks the target and the inputs out of `log` and validates them (see above). With
/// `requireTarget` false a log without the target column is accepted (compensation of new data).
ThermalSeries selectThermalSeries(const ThermalLog& log, const std::string& target,
                                  const std::vector<std::string>& inputs, bool requireTarget = true);

/// The rows of a log with gaps (ThermalLog::gaps) that have a value in every column of `used` (columns
/// the log lacks are ignored), and only the channels without a gap left in those rows: what a
/// computation that looks at every channel (the diagnosis) may read. `leftOut` (may be null) receives
/// the number of rows left out. A log without gaps is returned as it is.
ThermalLog thermalLogWithoutGaps(const ThermalLog& log, const std::vector<std::string>& used,
                                 std::size_t* leftOut = nullptr);

/// x(k) - x(0) for every k.
std::vector<double> change(const std::vector<double>& x);

}  // namespace metrofit::thermal
