#pragma once
// ISO 230-2:2014 evaluation of a bidirectional positioning test of one linear axis (accuracy and
// repeatability of positioning), and the pitch-error compensation table a control takes from it.
//
// Data: target positions P_i (i = 1..m), each approached n times from each direction j (cycles);
// x_ij = P_ij - P_i is the positional deviation (position reached minus target), ↑ the approach in the
// positive direction, ↓ in the negative one. Definitions (ISO 230-2:2014, clause 3):
//   mean unidirectional positional deviation   x̄i↑ = 1/n Σ_j x_ij↑,   x̄i↓ likewise
//   mean bidirectional positional deviation    x̄i = (x̄i↑ + x̄i↓) / 2
//   reversal value                             Bi = x̄i↑ - x̄i↓
//   axis reversal value                        B = max |Bi|;   mean reversal value B̄ = 1/m Σ_i Bi
//   estimator of the unidirectional repeatability standard uncertainty
//                                              si↑ = sqrt(1/(n-1) Σ_j (x_ij↑ - x̄i↑)^2),  si↓ likewise
//   unidirectional repeatability               Ri↑ = 4 si↑,  Ri↓ = 4 si↓
//   bidirectional repeatability at a position  Ri = max(2 si↑ + 2 si↓ + |Bi|;  Ri↑;  Ri↓)
//   axis repeatabilities                       R↑ = max Ri↑,  R↓ = max Ri↓,  R = max Ri
//   unidirectional systematic positional deviation  E↑ = max x̄i↑ - min x̄i↑,  E↓ likewise
//   bidirectional systematic positional deviation   E = max(x̄i↑; x̄i↓) - min(x̄i↑; x̄i↓)
//   range of the mean bidirectional positional deviation  M = max x̄i - min x̄i
//   unidirectional accuracy   A↑ = max(x̄i↑ + 2 si↑) - min(x̄i↑ - 2 si↑),  A↓ likewise
//   bidirectional accuracy    A = max(x̄i↑ + 2 si↑; x̄i↓ + 2 si↓) - min(x̄i↑ - 2 si↑; x̄i↓ - 2 si↓)
// All in mm. Every target needs at least 2 approaches from each direction (s uses n - 1); the standard
// asks for 5 cycles, fewer are evaluated as given.
//
// Input forms (docs/file-formats.md#positioning-test), recognised by content:
//   * CSV `target_mm,direction,cycle,deviation_mm` (or `measured_mm`: deviation = measured - target),
//     direction `+` (approach in the positive direction) or `-`; one row per approach.
//   * `KEY=value` lines (the form the ESS ecmccomgui ISO 230-2 tool writes): `UNIT` (mm or um),
//     `CYCLES`, `POSITIONS`, `TGT_DATA[i]`, `REF_DATA_FWD[i,j]` / `REF_DATA_BWD[i,j]` the reference
//     reading at target i in cycle j approached forwards (↑) / backwards (↓); deviation = reading -
//     target; other keys and `#` lines are ignored.
//
// Pitch-error compensation (pitchCompensationTable): the compensation at target i is c_i = -x̄i, minus
// the MEAN BIDIRECTIONAL deviation (not a unidirectional one): the reversal B is left to the control's
// backlash compensation. The table needs equally spaced points; targets that are not equally spaced
// (ISO 230-2 recommends irregular spacing) are interpolated linearly onto m points from the first to the
// last target. Forms (each as the control's documentation describes it):
//   * fanuc: the parameter and pitch-error data of a Fanuc punch file: N3620 reference point number,
//     N3621 / N3622 the most negative / most positive compensation point, N3623 magnification (1),
//     N3624 compensation interval (detection units), then N10000+k P<value> for point k, the values
//     INCREMENTAL in detection units (the change of the compensation over the interval ending at the
//     point, as seen from the negative end); the reference position is the first target (point
//     `fanucReferenceNumber`, compensation 0 there: the table is referred to it).
//   * siemens: a SINUMERIK leadscrew / encoder error compensation file %_N_AX_EEC_INI with
//     $AA_ENC_COMP[0,k,<axis>1] (absolute values, mm), _STEP, _MIN, _MAX, _IS_MODULO = 0, M17.
//   * heidenhain: a compensation-value table <axis>.COM (BEGIN ... [END], columns NR, AXISPOS and the
//     axis's own column with the compensation value, mm).
//   * csv: target_mm,compensation_mm (the targets themselves, no interpolation).
// Numbers are written with '.' whatever the locale (core/common/numformat.h).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/io/csv.h"

namespace metrofit {

/// One approach of a target.
struct PositioningSample {
  double targetMm = 0.0;
  bool up = true;            ///< approached in the positive direction
  long cycle = 0;            ///< 1-based
  double deviationMm = 0.0;  ///< position reached - target
  long line = 0;             ///< physical line in the file (0 when not from a file)
};

/// A bidirectional positioning test as read from a file.
struct PositioningTest {
  std::string source;  ///< file name for messages
  std::vector<PositioningSample> samples;
};

/// Per target results.
struct PositioningTarget {
  double targetMm = 0.0;
  std::size_t nUp = 0, nDown = 0;
  double meanUpMm = 0.0, meanDownMm = 0.0;                         ///< x̄i↑, x̄i↓
  double sUpMm = 0.0, sDownMm = 0.0;                               ///< si↑, si↓
  double reversalMm = 0.0;                                         ///< Bi
  double meanMm() const { return 0.5 * (meanUpMm + meanDownMm); }  ///< x̄i
};

/// The axis results of ISO 230-2:2014 (mm).
struct PositioningResult {
  std::string source;                      ///< the test's file, for messages
  std::vector<PositioningTarget> targets;  ///< ascending target
  double B = 0.0, Bmean = 0.0;
  double Eup = 0.0, Edown = 0.0, E = 0.0, M = 0.0;
  double Rup = 0.0, Rdown = 0.0, R = 0.0;
  double Aup = 0.0, Adown = 0.0, A = 0.0;
};

/// The CSV form. ParseError / ValidationError naming file, line and field of a bad cell or a repeated
/// (target, direction, cycle).
PositioningTest positioningTestFromCsv(const CsvTable& table);
/// The KEY=value form. ParseError / ValidationError naming file, line and key.
PositioningTest positioningTestFromKeyValue(std::string_view text, const std::string& source);
/// True when the first line that is not blank or a '#' comment is KEY=value (not a CSV header).
bool isKeyValuePositioningTest(std::string_view text);
/// Reads either form from a file ("-": standard input).
PositioningTest readPositioningTest(const std::string& path, const CsvReadOptions& csv = {});

/// The ISO 230-2 evaluation. ValidationError naming the file and the line of the target's first sample
/// when a target has fewer than 2 approaches from one direction, or when there is no sample at all.
PositioningResult evaluateIso230_2(const PositioningTest& test);

/// {"B_mm", "B_mean_mm", "E_up_mm", ..., "A_mm", "targets": [{"target_mm", "x_up_mm", "x_down_mm",
/// "s_up_mm", "s_down_mm", "B_mm"}]}.
nlohmann::json iso230_2ToJson(const PositioningResult& r);

enum class PitchTableFormat { Fanuc, Siemens, Heidenhain, Csv };
/// "fanuc", "siemens", "heidenhain", "csv"; OptionsError naming `option` otherwise.
PitchTableFormat parsePitchTableFormat(std::string_view text, const std::string& option = "--compensation");

struct PitchTableOptions {
  char axis = 'X';                      ///< X, Y, Z, U, V, W, A, B, C
  double fanucDetectionUnitMm = 0.001;  ///< Fanuc detection unit (IS-B: 1 um)
  long fanucReferenceNumber = 1;        ///< Fanuc compensation point number of the first target (0..1023)
  bool isValid(std::string* why) const;
};

/// The compensation value c_i = -x̄i at each target (mm).
std::vector<double> compensationMm(const PositioningResult& r);
/// The table text in the given form (see the header comment). ValidationError when the targets are fewer
/// than 2 (fanuc, siemens, heidenhain need an interval).
std::string pitchCompensationTable(const PositioningResult& r, PitchTableFormat format,
                                   const PitchTableOptions& options = {});

}  // namespace metrofit
