#pragma once
// Measured points from a table: the columns the point readers share (fit-element, raw probe points
// whose nominals come from an element or a second measurement, core/project/nominals.h).
//   x_mm,y_mm,z_mm   in mm
//   px,py,pz         in mm (the measured point of a probe-point file, or raw points mapped to it)
//   x,y,z            in the caller's unit (bareFactorMm: mm per unit)
// in this order of preference; an optional `id` column (any case: `ID`) names the points. ValidationError
// naming the file and line for a non-finite coordinate or a duplicate id, InputError for missing columns.
#include "core/geometry/element_fit.h"

#include "core/io/csv.h"

namespace metrofit::geometry {

struct PointTableColumns {
  std::string x, y, z;  ///< the columns read
  bool bare = false;    ///< x,y,z (in the caller's unit)
};

/// The columns pointsFromTable reads from `table` (InputError naming the file when none of the forms is
/// there).
PointTableColumns pointTableColumns(const CsvTable& table);
PointSet pointsFromTable(const CsvTable& table, double bareFactorMm = 1.0);
/// pointsFromTable of the CSV file `path` read with `csv`.
PointSet readPointTable(const std::string& path, const CsvReadOptions& csv = {}, double bareFactorMm = 1.0);

}  // namespace metrofit::geometry
