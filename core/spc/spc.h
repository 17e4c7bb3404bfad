#pragma once
// Statistical process control of a measured feature (kinematic-compensation paper, IEEE Access, kinematic
// compensation algorithm, Section IV.A) and the SPC gate in front of compensation. Values are in the
// feature's own unit.
//
// From the X-bar/R chart (control_chart.h; n values per subgroup, N = k n values used):
//   sigma_within   = Rbar / d2                             (the process's short-term sigma)
//   sigma_overall  = sample standard deviation of the N values (n - 1 denominator)
//   Cp   = (USL - LSL) / (6 sigma_within)                  (Eq. 16, printed "USL - LSL/6 sigma")
//   Cpk  = min(USL - xbarbar, xbarbar - LSL) / (3 sigma_within)
//   Pp, Ppk: the same with sigma_overall
//   natural tolerance = (UCL_xbar - LCL_xbar) sqrt(n)       (Eq. 17; = 6 sigma_within since
//                                                            A2 = 3 / (d2 sqrt(n)))
//   systematic error  E = V - xbarbar                       (Eq. 20: desired value V minus mean)
// The systematic error is significant when |E| > k sigma_within / sqrt(N): outside the interval
// (coverage factor k, default 2, about 95 %) that the mean of N values scatters in by chance.
//
// Trend (Fig. 10): the least-squares line y = slope x + intercept of a feature series against
// x (the sample number, or a position along an axis), with r^2, the slope's standard error and the
// offset angle atan(slope) in degrees. The angle is a geometric angle only when x and y share a
// unit (e.g. deviation in mm against position in mm); against the sample number it is the paper's
// incline of the regression line and says how fast the feature drifts.
//
// SPC gate: compensate only what is systematic and significant, in a process in control:
//   no nominal                      -> no (nothing to compensate against)
//   a subgroup beyond its limits    -> no (special causes first: a correction would chase them)
//   |E| within its interval         -> no (random scatter, not a systematic error)
//   |E| below the smallest step     -> no (the machine cannot apply it)
//   otherwise                       -> yes, correction = E (add it to the reference)
//
// With individuals (n = 1, control_chart.h) sigma_within = MRbar / d2(2) and Eq. 17 holds with n = 1.
//
// Phase I / phase II (SpcOptions::baseSubgroups = K): the chart's limits, its centre lines and
// sigma_within come from the first K subgroups (what the limits stand for), the mean in Cpk, Ppk and
// E and sigma_overall from every used value (the process as measured). With K = all subgroups (the
// default) the two means are the same number, bit for bit.
//
// Nelson rules (nelson.h): which subgroups break each of the eight tests on the X-bar (X) and on
// the R (MR) chart; listed in the result, they do not change `in_control` or the gate above, which
// look at the control limits only (rule 1).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/common/error.h"
#include "core/common/text.h"
#include "core/spc/control_chart.h"
#include "core/spc/nelson.h"

namespace metrofit {

struct SpcOptions {
  int subgroupSize = 5;            ///< n: 2..25 for X-bar/R, 1 for individuals and moving range
  std::size_t baseSubgroups = 0;   ///< K >= 2: limits from the first K subgroups (phase I); 0 = all
  std::optional<double> lsl, usl;  ///< specification limits (both or neither)
  std::optional<double> nominal;   ///< desired value V of Eq. 20
  double coverageFactor = 2.0;     ///< k of the interval of the mean
  double minCorrection = 0.0;      ///< smallest correction the machine can apply (>= 0)

  bool isValid(std::string* why) const;
};

struct Capability {
  double sigmaWithin = 0.0;
  double sigmaOverall = 0.0;
  double naturalTolerance = 0.0;  ///< Eq. 17
  std::optional<double> cp, cpk, pp, ppk;
};

struct SystematicError {
  double nominal = 0.0;
  double mean = 0.0;
  double error = 0.0;          ///< nominal - mean (Eq. 20)
  double standardError = 0.0;  ///< sigma_within / sqrt(N)
  double halfWidth = 0.0;      ///< k standardError
  bool significant = false;    ///< |error| > halfWidth
};

struct LineFit {
  std::size_t points = 0;
  double slope = 0.0, intercept = 0.0;
  double r2 = 0.0;           ///< coefficient of determination (0 when y is constant)
  double slopeStdErr = 0.0;  ///< 0 with two points
  double angleDeg = 0.0;     ///< atan(slope)
};

struct CompensationDecision {
  bool apply = false;
  double correction = 0.0;  ///< add to the reference (0 when not applied)
  std::string reason;       ///< one line a person can read (= english(reasonParts))
  Phrases reasonParts;      ///< the same line as translatable phrases (core/common/text.h)
};

struct SpcResult {
  SpcOptions options;
  std::size_t valuesUsed = 0;
  std::size_t valuesIgnored = 0;  ///< a trailing incomplete subgroup
  ControlChartConstants constants;
  XbarRChart chart;
  Capability capability;
  std::optional<SystematicError> systematic;
  LineFit trend;  ///< of the used values against the sample number 1..N
  CompensationDecision decision;
  std::vector<RuleBreak> rules;  ///< Nelson rules broken (nelson.h)
};

/// Least-squares line through (x_i, y_i); ValidationError at `where` with fewer than 2 points,
/// different lengths, non-finite values or all x equal.
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y, const ErrorContext& where = {});

Capability capability(const XbarRChart& chart, const std::vector<double>& usedValues,
                      const SpcOptions& options);
SystematicError systematicError(const XbarRChart& chart, double sigmaWithin, std::size_t valuesUsed,
                                double nominal, double coverageFactor);
/// The SPC gate (see the header comment). `systematic` is empty when there is no nominal.
CompensationDecision gateCompensation(const XbarRChart& chart,
                                      const std::optional<SystematicError>& systematic,
                                      const SpcOptions& options);

/// The whole analysis of a feature series in sample order. OptionsError for invalid options,
/// ValidationError at `where` for data that cannot be charted (see xbarRChart).
SpcResult analyseSpc(const std::vector<double>& values, const SpcOptions& options,
                     const ErrorContext& where = {});

/// JSON of the analysis: subgroup_size, subgroups, values_used, values_ignored, chart_type ("xbar-r" or
/// "x-mr"), base_subgroups (K), constants {A2, D3, D4, d2, d3, and E2 for x-mr: the constants of the
/// range's span}, xbar_chart {center, ucl, lcl, points, out_of_control}, r_chart {the same, and
/// first_subgroup: the 1-based subgroup of its first point, 2 for moving ranges}, rules [{chart
/// "xbar"|"r", rule "nelson1".."nelson8", subgroups [1-based]}] (always present, empty when no rule is
/// broken), in_control, mean, sigma_within, sigma_overall, natural_tolerance, and when given
/// lsl, usl, cp, cpk, pp, ppk; nominal, systematic_error {value, standard_error, half_width,
/// coverage_factor, significant}; trend {slope, intercept, r2, slope_std_err, angle_deg};
/// compensation {apply, correction, reason}.
nlohmann::json spcResultToJson(const SpcResult& result);

}  // namespace metrofit
