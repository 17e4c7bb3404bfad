#pragma once
// ISO 230-4 results of a circular test (circular tests for numerically controlled machine tools, two
// linear axes interpolating a circle), for each direction of travel, from either form of the test
// (docs/file-formats.md#circular-test): the x/y form (commanded and measured points) or the
// radial-only form a ballbar exports (angle, radial deviation).
//
// Sources: the scope of ISO 230-4:2005 (UNI ISO 230-4:2010, store.uni.com/uni-iso-230-4-2010: "the
// bidirectional circular deviation, the bidirectional mean radial deviation and the circular and radial
// deviations of circular paths produced by the simultaneous movement of two linear axes"), the NIST/
// SEMATECH e-Handbook 2.3.4.4 "Roundness measurements" (itl.nist.gov/div898/handbook/mpc/section3/
// mpc344.htm: a least-squares circle fitted to the trace defines the out-of-roundness P - R), and the
// way ballbar evaluations report them (mts-nw.com/analyzing.html: circularity = max minus min radial
// deviation of a trace, minimum/maximum radial deviation from the programmed radius). The definitions
// used here, for a path traced once counter-clockwise (CCW) and once clockwise (CW):
//
//   LSQ circle of a set of points p_k: centre c and radius r minimising sum_k (|p_k - c| - r)^2
//     (Gauss-Newton from the algebraic Kasa fit; converged when the step is below 1e-12 mm).
//   Circular deviation G (per direction): the radial range of that direction's path about its own LSQ
//     centre, G = max_k |p_k - c| - min_k |p_k - c| (the minimum radial separation of two circles about
//     the LSQ centre that enclose the path).
//   Circular hysteresis H: both directions about ONE LSQ centre c_both (fitted to the points of both
//     directions); H = max over angles theta of |r_CW(theta) - r_CCW(theta)|, where the other direction's
//     radius at theta is interpolated linearly in angle between its two neighbouring points (an angle is
//     compared only where those neighbours are at most twice the direction's median angular spacing apart,
//     so a partial arc is not interpolated across its gap). Absent unless both directions are present.
//   Radial deviation F (per direction): the largest and the smallest deviation of the path from the
//     nominal radius about the NOMINAL centre, F_max = max_k (|p_k - c_nom| - R_nom), F_min = min_k (...).
//     The nominal centre and radius are those of the commanded points (their mean, and the mean distance
//     from it) in the x/y form; in the radial form the file's deviations are already about the ballbar's
//     centre pivot and nominal length, so F is their range.
//
// The radial form gives the angle theta_k and the deviation d_k = |p_k - c_nom| - R_nom. With a nominal
// radius R_nom (column radius_mm) the points p_k = (R_nom + d_k)(cos theta_k, sin theta_k) are evaluated as
// above. Without one, the LSQ circle is its small-deviation limit (R_nom >> |d|, |c|), the limacon
// d_k ~ dr + cx cos theta_k + cy sin theta_k fitted by linear least squares (Eigen ColPivHouseholderQR),
// and the radius about the LSQ centre is R_nom + d_k - cx cos theta_k - cy sin theta_k; the centre is then
// given relative to the nominal centre and the LSQ radius as its difference dr from the nominal radius.
//
// Directions: in the x/y form a point is CCW when the command turns counter-clockwise about the nominal
// centre from it to the next point (the last point takes its predecessor's direction); in the radial form
// the file's direction column when it has one, else the same rule on the angles (a step of the angle,
// wrapped into (-180, 180], that is >= 0 is CCW).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/kinematics/measured_path.h"

namespace metrofit {

/// A circular test as the ISO 230-4 evaluation reads it: polar samples about the nominal centre.
struct CircularTrace {
  std::string source;       ///< file name for messages
  bool radialOnly = false;  ///< read from the radial form (no x/y: not identifiable)
  Eigen::Vector2d nominalCentreMm = Eigen::Vector2d::Zero();  ///< (0, 0) for the radial form
  std::optional<double> nominalRadiusMm;                      ///< unknown for a radial file without radius_mm
  std::vector<double> angleDeg;                               ///< angle about the nominal centre, [0, 360)
  std::vector<double> deviationMm;                            ///< |p - c_nom| - R_nom
  std::vector<bool> counterClockwise;                         ///< direction of travel of each point
  std::vector<long> run;    ///< run number of each point (radial form with a run column)
  std::vector<long> lines;  ///< physical line of each row (empty when not from a file)

  std::size_t size() const { return angleDeg.size(); }
};

/// The trace of an x/y circular test (nominal centre and radius of the commanded points). ValidationError
/// (field x_cmd_mm) for fewer than 3 points or commands without a radius.
CircularTrace circularTraceOf(const MeasuredPath& path);

/// True when the table has the radial form's columns (angle_deg and deviation_um or deviation_mm) and not
/// the x/y form's x_cmd_mm.
bool isRadialCircularTest(const CsvTable& table);
/// The radial form: angle_deg, deviation_um or deviation_mm; optional direction (ccw / cw, also
/// counterclockwise, anticlockwise, clockwise, +1 / -1), run, radius_mm. ValidationError / ParseError
/// naming file, line and field of a bad cell; at least 3 rows.
CircularTrace radialTraceFromCsv(const CsvTable& table);
/// Either form of a circular test file.
CircularTrace circularTraceFromCsv(const CsvTable& table);
CircularTrace readCircularTrace(const std::string& path, const CsvReadOptions& csv);

struct LsqCircle {
  Eigen::Vector2d centreMm = Eigen::Vector2d::Zero();
  double radiusMm = 0.0;
  double rmsMm = 0.0;  ///< RMS of |p - c| - r
};

/// Geometric least-squares circle (see the header comment). ValidationError naming `source` for fewer
/// than 3 points or points on a line.
LsqCircle fitLsqCircle(const std::vector<Eigen::Vector2d>& points, const std::string& source = {});

struct Iso230Direction {
  bool counterClockwise = true;
  std::size_t points = 0;
  Eigen::Vector2d lsqCentreMm = Eigen::Vector2d::Zero();  ///< relative to the nominal centre when no radius
  std::optional<double> lsqRadiusMm;                      ///< absent when the nominal radius is unknown
  double lsqRadiusDeviationMm = 0.0;                      ///< LSQ radius - nominal radius
  double circularDeviationMm = 0.0;                       ///< G
  double radialDeviationMaxMm = 0.0, radialDeviationMinMm = 0.0;  ///< F max / F min
};

struct Iso230Result {
  Eigen::Vector2d nominalCentreMm = Eigen::Vector2d::Zero();
  std::optional<double> nominalRadiusMm;
  bool linearised = false;                     ///< the limacon fit (radial form without radius_mm)
  std::vector<Iso230Direction> directions;     ///< CCW first, then CW; only the directions present
  std::optional<double> circularHysteresisMm;  ///< H, when both directions are present and overlap
  Eigen::Vector2d hysteresisCentreMm = Eigen::Vector2d::Zero();  ///< c_both

  const Iso230Direction* direction(bool counterClockwise) const;
};

/// ValidationError naming the trace's source when a direction has fewer than 3 points or its points
/// do not determine a circle.
Iso230Result evaluateIso230_4(const CircularTrace& trace);

/// The "iso230_4" object of the CLI results (docs/file-formats.md#iso-230-4-results): deviations in um,
/// positions in mm; "ccw" / "cw" null when that direction is absent, "circular_hysteresis_h_um" null
/// without both directions.
nlohmann::json iso230ResultToJson(const Iso230Result& result);

}  // namespace metrofit
