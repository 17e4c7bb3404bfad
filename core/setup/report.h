#pragma once
// Measurement reports for the setup correction: what the CMM says about the model's dimensions.
//
// 1. CMM report series, CSV (CONTRACT.md):
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
//    * F(label)=FEAT/type,CART,x,y,z,...    nominal feature (type: POINT, PLANE, CIRCLE,
//      SPHERE, CYLNDR, ...; any type whose first three numbers after CART are the position);
//    * FA(label)=FEAT/type,CART,x,y,z,...   feature actual;
//    * T(label)=TOL/DISTB|DISTWRT|DIAM|RAD|WIDTH,NOMINL,nominal,lotol,uptol,...   tolerance
//      definition (NOMINL,nominal is optional; T(label)=TOL/CORTOL,ZAXIS,lotol,uptol too): when
//      present, the nominal (if the model has one) and the limits are checked against the model
//      like the CSV's;
//    * TA(label)=TOL/DISTB|DISTWRT|DIAM|RAD|WIDTH,dev,...   tolerance actual: DMIS output reports
//      the actual DEVIATION from the nominal as the first value (a following INTOL / OUTOL is
//      ignored); TA(label)=TOL/CORTOL,XAXIS|YAXIS|ZAXIS,dev,... gives the deviation along the
//      named axis, which must be the model's axis.
//    A dimension is found by its DMIS label (Dimension::dmisLabel(): the "label" of the model,
//    default the id; compared case-insensitively): its deviation is the TA(label) value when the
//    file has one, otherwise FA(label) - F(label) along the model's axis (X, Y or Z coordinate).
//    Labels that name no dimension are skipped (DMIS files carry datums and other features); a
//    dimension found in neither form is an error. POL coordinates are an error.
//
// Errors are ParseError / ValidationError naming file, line and field.
#include <string>
#include <string_view>
#include <vector>

#include "core/setup/model.h"

namespace metrofit {
class CsvTable;
}

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
Measurements readCmmReport(const std::string& path, const Model& model);

/// Reads one DMIS output file (text) against the model; `source` names it in errors.
Measurements dmisReportFromText(std::string_view text, const std::string& source, const Model& model);
Measurements readDmisReport(const std::string& path, const Model& model);

/// True when the text looks like DMIS (its first statement is DMISMN or DMISMD).
bool looksLikeDmis(std::string_view text);

/// Reads one or more report files (CSV or DMIS, told apart by content) and merges them: the deviation of each
/// dimension is the mean over all rows of all files. The same (part, dimension) in two files is an error
/// naming the second file and line.
Measurements readMeasurements(const std::vector<std::string>& paths, const Model& model);
/// Merges measurement sets (same rules as readMeasurements).
Measurements mergeMeasurements(const std::vector<Measurements>& sets, const Model& model);

}  // namespace metrofit::setup
