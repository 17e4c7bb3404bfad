#pragma once
// PC-DMIS hole-table text reports, as in the CMM reports of drilled plates, e.g.
//
//   Plug Plate: 8131
//   Date: 2014-10-14
//
//       Meas X    Meas Y     Nom X     Nom Y     Err X     Err Y  Meas D   Nom D   Round
//       11.610   -10.090    11.650   -10.184    -0.039     0.094   3.265   2.845   0.006
//
// Before the column header: "Key: value" lines (kept as metadata), blank lines and '#' comments.
// The header names the columns; they are separated by two or more spaces (names contain one space).
// Required: "Meas X", "Meas Y", "Nom X", "Nom Y" (mm). Optional and checked when present:
// "Err X", "Err Y" (= Meas - Nom, as printed: must agree within 0.0015 mm, the rounding of three
// values printed to 0.001 mm), "Meas D", "Nom D" (hole diameters, > 0), "Round" (>= 0). Other
// columns are ignored. Rows: one whitespace-separated number per column; blank and '#' lines are
// skipped; CRLF or LF line ends.
//
// The result is a planar, position-only probe point set (docs/file-formats.md#contact-probed-points,
// the lighter form without normals and without z): q = (Nom X, Nom Y), p = (Meas X, Meas Y), ids
// "H001", "H002", ... in row order, surface "hole D<Nom D>" (so holes of different nominal size are
// evaluated as separate groups), or "hole" without a Nom D column.
//
// Errors (ParseError / ValidationError) name the file and line: no header, a missing required
// column, a row with the wrong number of values, a value that is not a finite number, Err X/Y that
// disagree with Meas - Nom, a non-positive diameter, two holes at the same nominal position, fewer
// holes than `minPoints`.
#include <map>
#include <string>

#include "core/io/cmm_text_report.h"
#include "core/matching/probe_points.h"

namespace metrofit {

struct HoleTable {
  ProbePointSet points;
  std::map<std::string, std::string> metadata;  ///< "Plug Plate" -> "8131", "Date" -> "2014-10-14"
  std::vector<double> measuredDiameterMm;       ///< per hole, empty without a "Meas D" column
  std::vector<double> nominalDiameterMm;        ///< per hole, empty without a "Nom D" column
};

/// True when `text` looks like a hole-table report: a line with both "Meas X" and "Nom X" among the
/// first 50 non-blank lines, before any line that looks like a CSV header with an "id" column.
bool looksLikeHoleTable(const std::string& text);

/// Parses a hole-table report; `source` names the file in errors.
HoleTable holeTableFromText(const std::string& text, const std::string& source, std::size_t minPoints = 3);
HoleTable readHoleTable(const std::string& path, std::size_t minPoints = 3);

/// Probe points from a CMM text report of one run (core/io/cmm_text_report.h): one point per
/// feature that prints a nominal and an actual X and Y location (PC-DMIS: the X / Y / Z rows of a
/// LOCATION dimension; OGP: X / Y / Z Location), q = the nominals, p = the actuals, in mm; planar
/// (z = 0) when no feature has a Z, an error naming the line when only some have one. Ids: the
/// PC-DMIS dimension name (LOC1) or the OGP label ("step<n>" without one); surface: the feature
/// type in lower case ("circle", "sphere"), with " D<nominal>" when a diameter (D / Diameter) has a
/// nominal, so features of different nominal size are separate groups. Position-only (no normals).
/// ValidationError for several runs or fewer than `minPoints` points.
ProbePointSet probePointsFromCmmReport(const CmmTextReport& report, std::size_t minPoints = 3);

/// Probe points from a file in any accepted form, detected by content: a PC-DMIS hole table
/// (looksLikeHoleTable), a Zeiss Calypso _fet table (core/io/calypso.h: calypsoFeaturesProbeTable), a QIF 3
/// Results file (core/matching/qif_points.h: every measured feature of part `part`, 1-based, 0 for a file
/// of one part), a CMM text report (looksLikeCmmTextReport: probePointsFromCmmReport) or the CSV of
/// docs/file-formats.md#contact-probed-points in the dialect `csv` (probePointsFromCsv). The file is read
/// once, so "-" (standard input) works.
ProbePointSet readProbePointsAnyFormat(const std::string& path, std::size_t minPoints = 3,
                                       const CsvReadOptions& csv = {}, int part = 0);

}  // namespace metrofit
