#pragma once
// Measurement reports for the setup correction: what the CMM says about the model's dimensions.
//
// 1. CMM report series, CSV (docs/file-formats.md#cmm-report-series):
//      part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm
//    one row per dimension per measured part (one or many parts). `dimension` names a dimension of
//    the model (an unknown name is an error naming line and field); `lower_tol_mm` /
//    `upper_tol_mm` are the tolerance limits relative to the nominal, as in the model, and must
//    equal the model's limits (within 1e-6 mm), as must `nominal_mm` when the model gives a
//    nominal. A (part, dimension) pair may occur once. The deviation of a row is
//    measured_mm - nominal_mm; the deviation e_q of dimension q used by the objective is the MEAN
//    over all rows of q (all parts given). Every dimension of the model needs at least one row.
//
// 2. DMIS output files (ISO 22093 / DMIS 5), one file per measured part. The subset read here:
//    * one statement per line; a line ending in '@' continues on the next; "$$" starts a
//      comment; major and minor words are case-insensitive; blank lines are skipped; every
//      other statement (DMISMN, MODE, SNSET, MEAS, GOTO, OUTPUT, ...) is skipped;
//    * UNITS/MM|CM|INCH|FEET,...   the length unit of the following numbers (converted to mm);
//    * FILNAM/'name'               names the part (default: the file name);
//    * PARTSN/'serial'             the workpiece's serial number; names the part (before FILNAM);
//    * F(label)=FEAT/type,[INNER|OUTER,]CART,x,y,z,...    nominal feature (type: POINT, PLANE,
//      CIRCLE, SPHERE, CYLNDR, ...; any type whose first three numbers after CART are the position;
//      CIRCLE and CYLNDR carry the diameter as the 7th number after CART, SPHERE as the 4th);
//    * FA(label)=FEAT/type,[INNER|OUTER,]CART,x,y,z,...   feature actual;
//    * T(label)=TOL/DISTB|DISTWRT|DIAM|RAD|WIDTH,NOMINL,nominal,lotol,uptol,...   tolerance
//      definition (NOMINL,nominal is optional; T(label)=TOL/CORTOL,ZAXIS,lotol,uptol too): when
//      present, the nominal (if the model has one) and the limits are checked against the model
//      like the CSV's;
//    * TA(label)=TOL/DISTB|DISTWRT|DIAM|RAD|WIDTH|PROFP,value,[INTOL|OUTOL|OUTTOL]   tolerance
//      actual; TA(label)=TOL/CORTOL,XAXIS|YAXIS|ZAXIS,value,... along the named axis, which must be
//      the model's axis. Writers differ on the value (shared/data/real/README.md): CMM output gives
//      the deviation (actual - nominal) for CORTOL / PROFP, the QIF-to-DMIS converter the actual
//      diameter for TOL/DIAM, some flip the sign for negative nominals; DmisOptions says which.
//    A dimension is found by its DMIS label (Dimension::dmisLabel(): the "label" of the model,
//    default the id; compared case-insensitively). Its deviation is, in this order:
//      1. FA(label) - F(label) when the file has both: the diameters for a DIAM tolerance (half of
//         them for RAD) when both features have one, else the coordinate along the model's axis;
//      2. the TA(label) value read as DmisOptions says: Deviation (value, times sign(nominal) with
//         signFollowsNominal), Actual (value - nominal; the nominal from T's NOMINL, F's diameter or
//         the model), Auto (Actual when the value is nearer the nominal than zero, else
//         Deviation). Plausibility:
//         when the statement says INTOL / OUTOL / OUTTOL, the deviation must be inside / outside the
//         tolerance (T's limits, else the model's), else a ValidationError names the line; without
//         such a word the deviation must not lie more than 10 tolerance widths outside the band
//         (else a ValidationError naming TA(label) says which reading to try instead).
//    Labels that name no dimension are skipped (DMIS files carry datums and other features); a
//    dimension found in neither form is an error (dmisReportFromText, or a single file given to
//    readMeasurements). POL coordinates are an error.
//    Several DMIS files, one per measured workpiece, are a series of parts like the CSV's
//    (readMeasurements): each file is a part, named by its PARTSN, else its FILNAM, else its file name;
//    files without PARTSN whose FILNAM repeats (the program's name, the same in every file) are named
//    by their file name (the path when base names repeat); files with the same PARTSN are one part, as
//    the CSV's rows with the same part. Like a part of a CSV series, each file may measure any of the
//    model's dimensions (on a multi-part fixture, only those of its workpiece), at least one; a
//    dimension measured by no file of the series is an error naming the dimension and the files read,
//    and a dimension measured twice within one file (or one part) is an error naming the file. The
//    deviation of a dimension is the mean over the files that measure it, as over the rows of a CSV
//    series, so the DMIS files and the CSV series with the same rows give the same result.
//
// 3. CMM text reports (core/io/cmm_text_report.h, docs/file-formats.md#cmm-text-reports): OGP step
//    reports (.RTN printouts, plain or RTF), OGP summary reports (one part per run) and PC-DMIS
//    standard text reports. A dimension's label (Dimension::dmisLabel()) names a feature and,
//    after a ':', one of its values: "oriball" or "oriball:Diameter", "Step 7:Diameter",
//    "LOC1:D". The feature is found by its label (OGP Comment or summary step title, PC-DMIS
//    dimension name), as "Step n" / "step<n>" (OGP) or by the dimensioned feature's name (PC-DMIS
//    CIR1); case-insensitively. Without a value name the location along the model's axis is taken
//    (OGP "Z Location", PC-DMIS axis Z), or the feature's only value with a nominal. For OGP, "X" /
//    "Y" / "Z" stand for "X Location" etc. The deviation is actual - nominal with its plain sign
//    (OGP PRINTS sign(nominal) * (actual - nominal) for locations; the reader has checked the
//    printed values against that rule), nominal 0 for form values. Tolerance limits printed in the
//    report (not both 0) and a printed nominal are checked against the model within the printed
//    rounding. A label that names two features of one run, a missing value or a value without a
//    nominal is a ValidationError naming the line. Parts: the file's base name for a single-run
//    report, "<base> run <k>" for the k-th run of an OGP summary.
//    Q-DAS DFQ files and Zeiss Calypso _chr tables are read the same way (cmm_text_report.h 4.): a label
//    names a characteristic by its description (DFQ K2002, Calypso id) or its number (DFQ K2001); DFQ
//    values that are not valid (attribute 255 or more) are left out; parts are the workpieces' serials
//    (K0014, partnb) when every run has its own, and time_min counts from the first run's date-time
//    (K0004; the _hdr's date and time) when every run has one (else 0).
//
// Errors are ParseError / ValidationError naming file, line and field.
#include <string>
#include <string_view>
#include <vector>

#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/setup/dmis_options.h"
#include "core/setup/model.h"

namespace metrofit::setup {

struct Measurements {
  struct Row {
    std::string part;
    double timeMin = 0.0;       ///< CSV time_min (0 for DMIS)
    std::size_t dimension = 0;  ///< index into Model::dimensions
    double deviationMm = 0.0;   ///< measured - nominal
    std::string source;
    long line = 0;
  };
  std::vector<std::string> sources;  ///< files read
  std::vector<std::string> parts;    ///< distinct parts, in order of appearance
  std::vector<Row> rows;
  std::vector<double> deviationMm;  ///< e_q: per model dimension, mean deviation over its rows
  std::vector<int> samples;         ///< rows per model dimension
};

/// Reads a CMM report series (CSV) against the model.
Measurements cmmReportFromCsv(const CsvTable& table, const Model& model);
Measurements readCmmReport(const std::string& path, const Model& model, const CsvReadOptions& csv = {});

/// Reads one DMIS output file (text) against the model; `source` names it in errors.
Measurements dmisReportFromText(std::string_view text, const std::string& source, const Model& model,
                                const DmisOptions& options = {});
Measurements readDmisReport(const std::string& path, const Model& model, const DmisOptions& options = {});

/// True when the text looks like DMIS (its first statement is DMISMN, DMISMD or FILNAM).
bool looksLikeDmis(std::string_view text);

/// Reads a CMM text report (OGP step or summary report, PC-DMIS text report) against the model (3. above).
Measurements cmmTextReportMeasurements(const CmmTextReport& report, const Model& model);

/// Reads one or more report files (CSV, DMIS or a CMM text report, told apart by content) and merges them:
/// the deviation of each dimension is the mean over all rows of all files. The same (part, dimension) in two
/// files is an error naming the second file and line.
/// `dmis`: how a DMIS file's TA(label) values without F/FA are read (metrofit-cli setup --ta-meaning,
/// --ta-sign).
Measurements readMeasurements(const std::vector<std::string>& paths, const Model& model,
                              const CsvReadOptions& csv = {}, const DmisOptions& dmis = {});
/// Merges measurement sets (same rules as readMeasurements).
Measurements mergeMeasurements(const std::vector<Measurements>& sets, const Model& model);

}  // namespace metrofit::setup
