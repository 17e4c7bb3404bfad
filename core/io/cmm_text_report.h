#pragma once
// CMM text reports as measuring software prints them (docs/file-formats.md#cmm-text-reports), read
// into one structure: runs (a part measured once) of features (a step or a dimension) of values
// (a characteristic with nominal, actual, tolerances and the deviation as printed).
//
// 1. OGP step printouts (`.RTN` routine reports): "Step:" blocks, plain text or wrapped in RTF
//    (Msftedit: the text lines with their CRLF between an opening "{\rtf1..." with the font and
//    colour tables and a closing "}", often a NUL byte after it). Per step: the step number and the
//    unit ("MM"; "INCH" values are converted to mm, angles stay in degrees) from the "Step:" line,
//    the label from the line after "Comment:", the feature type from the first line after
//    "Prompt:", then value rows "name actual nominal upper lower" under an "Actual Nominal Upper
//    Lower" header, "name actual tolerance [mod]" under an "Actual Tolerance" header and
//    "name actual" without a header (datum settings); "Points: n" (Measure) or "Features: n"
//    (Construct) closes the step. There is no Deviation column; "True Position" is printed as the
//    diametral value 2 |actual - nominal| of the location.
// 2. OGP summary reports ("Machine Serial Number: ... Page: n", "Routine Name  Run #  Date & Time",
//    "Feature  Unit  Nominal  Actual  Tolerances  Deviation  Exceeded"): one run per "Routine
//    Name" header, "Step n - title" starting a feature, value rows in fixed columns (name 0-14,
//    nominal from column 15, actual from column 26, the deviation after column 36; rows without a
//    nominal print the actual only, form rows actual and deviation). The printed deviation
//    follows OGP's sign rule (ogpPrintedDeviation): sign(nominal) * (actual - nominal) for X / Y / Z
//    Location, actual - nominal for everything else (nominal 0 for form rows); the reader checks
//    every printed deviation against it within the rounding of the printed digits.
// 3. PC-DMIS standard text reports: dimension blocks
//      DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$
//      GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO
//      AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL
//      X      10.000      0.050      0.050     10.012      0.012      0.000 ----#----
//      END OF DIMENSION LOC1
//    ("DIM" is optional, as in the Edit window; UNITS=MM or IN, inch values converted to mm). The
//    column header names the columns in the order printed (NOMINAL / NOM, +TOL, -TOL, MEAS, MAX,
//    MIN, BONUS, DEV, OUTTOL / OUT-TOL); rows are the axis (X, Y, Z, D, R, M, TP, ...) and one number
//    per column, "-" for an empty cell, then the deviation graphic. The vector row V is skipped.
//    +TOL is the upper limit, -TOL the lower limit below the nominal (lower = -(-TOL)); DEV must
//    equal MEAS - NOMINAL within the rounding of the printed digits. "PART NAME :" names the part.
//
// 4. Q-DAS DFQ files (core/io/dfq.h) and Zeiss Calypso characteristic tables (*_chr.txt,
//    core/io/calypso.h) are read into the same structure: one run per measured part (DFQ: per part
//    number K1001 and value set, with the part ident K0014 as `serial`; Calypso: per partnb), one
//    feature per characteristic (step = DFQ characteristic index / Calypso row within the part, label =
//    K2002 description (the number when it has none) / Calypso id, featureName = K2001 number / Calypso
//    id) with one value "actual": the nominal, the limits relative to it (DFQ K2110 - K2101, K2111 -
//    K2101; Calypso lowertol, uppertol), the written deviation (Calypso) and the rounding of the written
//    digits (DFQ K2022; Calypso the actual's decimals). DFQ values that are not valid (attribute 255 or
//    more, or not measured) are left out; a value set without a valid value makes no run.
//
// Every error is a ParseError / ValidationError naming the file and the physical line (and the
// column of a bad number): an RTF document that is not closed (a truncated file), a step that ends
// without its "Points:" / "Features:" line, a value row with a missing or non-numeric value, a
// printed deviation that disagrees with the actual and nominal, binary content.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {

enum class CmmReportFormat { OgpSteps, OgpSummary, PcDmis, Dfq, Calypso, Qif };
/// "OGP step report", "OGP summary report", "PC-DMIS text report", "Q-DAS DFQ file", "Calypso table",
/// "QIF results file".
const char* toString(CmmReportFormat format);

struct CmmValue {
  std::string name;  ///< "X Location", "Diameter", "True Position"; PC-DMIS axis "X", "D", "TP", "M"
  std::optional<double> nominal;
  double actual = 0.0;
  std::optional<double> upper;  ///< upper limit relative to the nominal (OGP Upper or Tolerance, +TOL)
  std::optional<double> lower;  ///< lower limit relative to the nominal (OGP Lower, -(-TOL))
  std::optional<double> printedDeviation;  ///< as printed (OGP summary Deviation, PC-DMIS DEV), mm / deg
  std::optional<double> outTol;            ///< PC-DMIS OUTTOL
  bool angle = false;                      ///< degrees (XY Angle, Elevation, Angle ...), else mm
  double rounding = 0.0;  ///< half a unit of the last printed digit of the actual (mm or deg)
  long line = 0;
};

struct CmmFeature {
  int step = 0;             ///< OGP step number; PC-DMIS: the dimension's 1-based order in the file
  std::string label;        ///< OGP Comment (step report) or step title (summary); PC-DMIS dimension name
  std::string type;         ///< OGP "Sphere", "Plane Best Fit"; PC-DMIS "LOCATION OF CIRCLE CIR1"
  std::string featureName;  ///< PC-DMIS: the dimensioned feature (CIR1); empty for OGP
  std::string featureType;  ///< PC-DMIS: its type word (CIRCLE, POINT, ...); OGP: the type's first word(s)
  int points = 0;           ///< OGP "Points: n" of a Measure step (0 for Construct)
  std::vector<CmmValue> values;
  long line = 0;

  /// The value named `name` (case-insensitive), or nullptr.
  const CmmValue* value(std::string_view name) const;
};

struct CmmRun {
  std::string routine;   ///< OGP routine (the .RTN), PC-DMIS PART NAME
  int number = 0;        ///< OGP "Run #" (summary), else 0
  std::string dateTime;  ///< as printed, may be empty
  std::string serial;    ///< the measured workpiece: DFQ K0014 part ident, Calypso partnb; may be empty
  std::vector<CmmFeature> features;
  long line = 0;
};

struct CmmTextReport {
  CmmReportFormat format = CmmReportFormat::OgpSteps;
  std::string source;
  bool rtf = false;  ///< the file was an RTF document
  std::vector<CmmRun> runs;
};

/// The deviation OGP prints for a value: sign(nominal) * (actual - nominal) for "X Location",
/// "Y Location" and "Z Location" (sign of the printed nominal, so "-0.000" counts as negative), and
/// actual - nominal for every other value; a value without a nominal counts as nominal 0.
double ogpPrintedDeviation(const CmmValue& value);
/// actual - nominal, the geometric deviation (nominal 0 when the value has none).
double plainDeviation(const CmmValue& value);

/// The text of an RTF document with the control words and the font / colour / info groups removed
/// and the line breaks kept (so line numbers stay those of the file); ParseError when the document
/// is not closed (truncated) or has text after its end.
std::string rtfToText(std::string_view rtf, const std::string& source);

/// The report format of `text` (its first 200 lines), or nothing when it is none of them.
std::optional<CmmReportFormat> detectCmmTextReport(std::string_view text);
inline bool looksLikeCmmTextReport(std::string_view text) {
  return detectCmmTextReport(text).has_value();
}

struct DfqFile;
struct CalypsoCharacteristics;
struct QifFile;
/// A DFQ file / a Calypso _chr table as a report (4. above); a QIF Results file likewise (below).
CmmTextReport dfqCmmReport(const DfqFile& file);
CmmTextReport calypsoCmmReport(const CalypsoCharacteristics& table);
/// A QIF 3 Results file (core/io/qif.h) as a report, implemented in qif.cpp: one run per
/// MeasurementResults (serial = the ActualComponent's SerialNumber, number = its 1-based order), one
/// feature per characteristic measurement with a Value (step = the characteristic's 1-based order,
/// label = its Name, type = its type ("Diameter", "Position"), featureType = the measured feature's type)
/// with one value "actual": the nominal and the limits relative to it of QifCharacteristic
/// (nominalValue, lowerLimit, upperLimit). featureName, the column key, is the Name, with "#<item id>"
/// when several characteristics share the Name and "@FEAT1+FEAT2" (the measured FeatureNames) when one
/// characteristic is measured on several sets of features (a pattern). A repeated measurement of the same
/// key in one part (point profiles: the deviation, then 0) is left out: the first one counts.
CmmTextReport qifCmmReport(const QifFile& file);
/// True for the formats whose features are characteristics named by number and description (DFQ,
/// Calypso, QIF), not steps or dimensions.
inline bool isCharacteristicTable(CmmReportFormat format) {
  return format == CmmReportFormat::Dfq || format == CmmReportFormat::Calypso ||
         format == CmmReportFormat::Qif;
}

/// Parses a report in the detected format; ParseError when the text is none of them.
CmmTextReport cmmTextReportFromText(std::string_view text, const std::string& source);
CmmTextReport readCmmTextReport(const std::string& path);

/// A report as a feature series table (docs/file-formats.md#cmm-text-reports): one row per run, in
/// file order; columns "run", "date", then per feature and value, in order of first appearance,
/// "<key>.<value>" (the actual) and, for values with a nominal or a printed deviation,
/// "<key>.<value>.dev" (actual - nominal, plain sign). <key> is "step<n>" for OGP and the dimension
/// name for PC-DMIS; <value> is the value name in lower case with '_' for blanks and punctuation
/// ("step5.x_location", "LOC1.x"). A run without a feature leaves its cells empty.
CsvTable cmmReportFeatureTable(const CmmTextReport& report);
/// A feature series file: a CMM text report (cmmReportFeatureTable) or a CSV file read with `csv`.
/// The file is read once, so "-" works.
CsvTable readFeatureTable(const std::string& path, const CsvReadOptions& csv = {});

}  // namespace metrofit
