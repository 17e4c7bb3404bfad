#pragma once
// From the SPC regression offset angle to actuator errors and a compensation: the chain of the
// kinematic-compensation paper (IEEE Access, kinematic compensation algorithm) from Section IV.A (Fig. 9-10,
// Tables 2-3) to Section IV (Eq. 9, 15). Lengths in mm, angles in degrees at the API.
//
// The paper measures linear features of the part that each axis made (Dx, Dy); a linear regression
// through the measurement results of a feature (Fig. 10) gives "a slight incline calculated to
// determine the offset angle ... the displacement angle concerning an axis of the machine"
// (Table 2), and the systematic error E = V - Xbar (Eq. 20) its position error; together they are
// the "errors in position and orientation of the actuators" (Table 3) that the inverse kinematics
// (Eq. 15) compensates. The text gives no formula for the step from the line to the actuator; here
// it is derived from Eq. 9 (P = o + ir Pr_x + jr Pr_y, ir = (cos a, sin a), jr = (-sin b, cos b),
// the parametrisation of cartesian_model.h):
//
// X feature: a straight edge machined along X at the nominal cross coordinate y0 (commands
// (x, y0)); measured at positions u_k = measured x, with deviation d_k = measured y - y0:
//   u = o_x + x cos a - y0 sin b,  d = o_y + x sin a + y0 (cos b - 1)
//   => d = c_X + s_X u,  s_X = tan a,
//      c_X = o_y - tan a o_x + y0 (cos b - 1) + tan a y0 sin b
// so the offset angle of the regression line atan(s_X) IS the X actuator's orientation error a.
// Y feature: an edge along Y at the nominal x0 (commands (x0, y)); u = measured y,
// d = measured x - x0:
//   d = c_Y + s_Y u,  s_Y = -tan b,
//      c_Y = o_x + tan b o_y + x0 (cos a - 1) + tan b x0 sin a
// so b = -atan(s_Y) (a Y axis leaning towards +x has a negative angle, CCW positive as everywhere).
// With a and b known the two intercepts are a 2x2 linear system in the origin (det = -(1 + tan a
// tan b), never 0 within +-45 deg):
//   [-tan a  1     ] [o_x]   [c_X - y0 (cos b - 1) - tan a y0 sin b]
//   [ 1      tan b ] [o_y] = [c_Y - x0 (cos a - 1) - tan b x0 sin a]
// The relations are exact (no small-angle step), so the paper's 10 deg / 15 deg errors come back
// exactly from noise-free data.
//
// SPC gate (as spc.h's for the systematic error): a slope or an intercept is taken only when it
// is beyond its interval +-k se (k the coverage factor, se from the regression: se(s) =
// sqrt(SSE / (N - 2) / Sxx), se(c) = sqrt(SSE / (N - 2) (1 / N + ubar^2 / Sxx))); otherwise it is
// random scatter and set to 0. The residuals about each line are charted (X-bar/R in subgroups of
// n consecutive points, control_chart.h): when a chart is out of control the errors are still
// reported but the compensation is not applied (special causes first). With 3-sigma limits a series
// in control still raises a false alarm now and then (10 subgroups of 5 on both charts: about 7 % per
// feature), as any Shewhart chart does; the result says which feature it was. Residuals with a sigma
// below 1e-9 mm (noise-free simulated edges) are not charted: their limits would be rounding noise. The
// systematic error of Eq. 20 (0 - mean deviation) is reported per feature beside the line.
//
// Compensation: the derived errors as a CartesianMachine2 (Oxr = Oyr = o), the references of a
// nominal path by Eq. 15 (compensatePath).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/kinematics/cartesian_model.h"
#include "core/spc/control_chart.h"
#include "core/spc/spc.h"

namespace metrofit {

/// One feature series: measured position along the axis and the deviation across it (mm).
struct AxisFeatureSeries {
  std::string source;  ///< file name for messages
  std::vector<double> positionMm, deviationMm;
  std::vector<long> lines;      ///< physical line of each row (empty when not from a file)
  double nominalCrossMm = 0.0;  ///< y0 of the X feature, x0 of the Y feature
};

/// Reads columns `positionColumn` and `deviationColumn` (ValidationError naming the file and the
/// missing column; ParseError naming line and field for a bad cell).
AxisFeatureSeries axisFeatureFromCsv(const CsvTable& table, const std::string& positionColumn,
                                     const std::string& deviationColumn);

struct SpcActuatorOptions {
  int subgroupSize = 5;         ///< of the residual X-bar/R chart
  double coverageFactor = 2.0;  ///< k of the intervals +-k se

  bool isValid(std::string* why) const;
};

/// The regression of one feature (Fig. 10) and what it says about its axis.
struct AxisFeatureFit {
  std::string source;
  LineFit line;                       ///< d = intercept + slope u (spc.h fitLine), angleDeg = atan(slope)
  double interceptStdErr = 0.0;       ///< se(c)
  bool slopeSignificant = false;      ///< |s| > k se(s)
  bool interceptSignificant = false;  ///< |c| > k se(c)
  double systematicErrorMm = 0.0;     ///< Eq. 20 with V = 0: -mean deviation
  double residualSigmaMm = 0.0;       ///< sqrt(SSE / (N - 2))
  std::optional<XbarRChart> residualChart;  ///< empty when the series has fewer than 2 subgroups
  std::string chartNote;                    ///< why there is no chart (empty when there is)
};

struct SpcActuatorResult {
  SpcActuatorOptions options;
  AxisFeatureFit x, y;
  ActuatorErrors2 errors;  ///< derived from the gated slopes and intercepts
  bool apply = false;      ///< compensate (both residual charts in control, or not charted)
  std::string reason;      ///< one line: why (not) applied
};

/// The derivation of the header comment. ValidationError naming the feature's file when a series
/// has fewer than 3 points, non-finite values, all positions equal, or an offset angle beyond
/// +-45 deg; OptionsError for invalid options.
SpcActuatorResult actuatorErrorsFromSpc(const AxisFeatureSeries& xFeature, const AxisFeatureSeries& yFeature,
                                        const SpcActuatorOptions& options = {});

/// JSON: origin_mm, x_axis_angle_deg, y_axis_angle_deg, squareness_deg (the keys of identify, so
/// `kinematic compensate --errors` reads it), features {x, y: source, slope, intercept, r2,
/// slope_std_err, intercept_std_err, offset_angle_deg, slope_significant, intercept_significant,
/// systematic_error_mm, residual_sigma_mm, points, residual_chart {in_control, subgroups} or
/// chart_note, nominal_cross_mm}, coverage_factor, subgroup_size, compensation {apply, reason}, model.
nlohmann::json spcActuatorResultToJson(const SpcActuatorResult& result, const AxisFeatureSeries& xFeature,
                                       const AxisFeatureSeries& yFeature);

/// The two edges' deviations as a Q-DAS DFQ file (core/io/dfq.h): part "from-spc" described as "Edges
/// machined along X (<xName>) and along Y (<yName>)", two characteristics "X edge <deviationColumn>" and
/// "Y edge <deviationColumn>" (nominal 0, unit mm), the values in series order. What `metrofit-cli
/// kinematic from-spc --dfq` and the kinematics page's Save DFQ write.
std::string edgesDfq(const AxisFeatureSeries& xFeature, const AxisFeatureSeries& yFeature,
                     const std::string& deviationColumn, const std::string& xName, const std::string& yName);

}  // namespace metrofit
