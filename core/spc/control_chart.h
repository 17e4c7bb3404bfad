#pragma once
// X-bar and R control charts (Shewhart), as used in Section IV.A of the kinematic-compensation
// paper (IEEE Access, kinematic compensation algorithm, Eq. 18-19), with the chart constants of the standard
// table for subgroup sizes n = 2..25.
//
// Constants (e.g. Montgomery, Introduction to Statistical Quality Control, Appendix VI; ASTM
// STP 15D). For n independent N(0, 1) values with range R:
//   d2 = E[R],  d3 = sd[R],  A2 = 3 / (d2 sqrt(n)),  D3 = max(0, 1 - 3 d3 / d2),  D4 = 1 + 3 d3 / d2.
// They are computed here, not typed in, from the distribution of the range (Tippett 1925):
//   G(w) = P(R <= w) = n int phi(x) [Phi(x + w) - Phi(x)]^(n-1) dx
//   d2 = int_0^inf (1 - G(w)) dw,   E[R^2] = int_0^inf 2 w (1 - G(w)) dw,   d3^2 = E[R^2] - d2^2,
// by the trapezoidal rule in x over [-9, 9] and Simpson's rule in w over [0, 16], step 0.05
// (error below 1e-6, well inside the table's 3 decimals; tests compare with the published table).
//
// Charts, from k subgroups of n consecutive values (subgroup means xbar_i, ranges R_i):
//   centre lines  xbarbar = mean of xbar_i,  Rbar = mean of R_i
//   X-bar chart   UCL = xbarbar + A2 Rbar (Eq. 18),  LCL = xbarbar - A2 Rbar (Eq. 19)
//   R chart       UCL = D4 Rbar,  LCL = D3 Rbar
// A subgroup is out of control when its mean or its range lies outside the limits.
//
// Individuals and moving range (n = 1; Montgomery, Chapter 6, control charts for individual measurements):
// the values x_1..x_k themselves are the X chart's points, the moving ranges MR_i = |x_i - x_(i-1)|, i
// = 2..k, the MR chart's (a range of span 2, so the constants are those of n = 2: d2 = 1.128, D3 = 0, D4
// = 3.267, E2 = 3 / d2 = 2.66):
//   X chart    CL = xbar,   UCL/LCL = xbar +- E2 MRbar      (sigma = MRbar / d2)
//   MR chart   CL = MRbar,  UCL = D4 MRbar,  LCL = D3 MRbar = 0
// MR_i belongs to subgroup i (the later value of its pair): the MR chart starts at subgroup 2.
//
// Phase I / phase II (Montgomery, Chapters 5-6: trial limits from preliminary samples, then monitoring): the
// limits above are computed from the first K subgroups only (the base, "phase I"; K = k by default), and
// every subgroup, the later ones
// ("phase II") included, is judged against them. With individuals the base is the first K values
// and its K - 1 moving ranges.
#include <cstddef>
#include <string>
#include <vector>

#include "core/common/error.h"

namespace metrofit {

inline constexpr int kMinSubgroupSize = 2;
inline constexpr int kMaxSubgroupSize = 25;

struct ControlChartConstants {
  int n = 0;
  double d2 = 0.0, d3 = 0.0;
  double A2 = 0.0, D3 = 0.0, D4 = 0.0;
  double E2 = 0.0;  ///< 3 / d2: the individuals chart's factor on the mean moving range (used with n = 2)
};

/// The constants for subgroup size n in [2, 25]; OptionsError (field 'subgroup size') otherwise.
/// Computed on first use of each n, then cached (thread-safe).
const ControlChartConstants& controlChartConstants(int n);

enum class ChartType {
  XbarR,         ///< X-bar and R, subgroups of 2..25
  IndividualsMR  ///< individuals (X) and moving range (MR), n = 1
};

/// "xbar-r" or "x-mr" (the `chart_type` of the spc result).
const char* chartTypeName(ChartType type);

struct XbarRChart {
  int subgroupSize = 0;  ///< n; 1 for individuals
  ChartType type = ChartType::XbarR;
  std::vector<double> means;      ///< xbar_i (individuals: the values x_i)
  std::vector<double> ranges;     ///< R_i (individuals: the moving ranges MR_2..MR_k, one fewer than means)
  std::size_t baseSubgroups = 0;  ///< K: the limits come from subgroups 0..K-1 (= subgroups() by default)
  double grandMean = 0.0;         ///< xbarbar of the base (centre line of the X-bar chart)
  double meanRange = 0.0;         ///< Rbar of the base (centre line of the R chart)
  double meanOfAll = 0.0;         ///< mean of every xbar_i (= grandMean when the base is every subgroup)
  double xbarUcl = 0.0, xbarLcl = 0.0;
  double rUcl = 0.0, rLcl = 0.0;
  std::vector<std::size_t> xbarOutOfControl;  ///< 0-based subgroup indices beyond the X-bar limits
  std::vector<std::size_t> rOutOfControl;     ///< 0-based subgroup indices beyond the R (MR) limits

  std::size_t subgroups() const { return means.size(); }
  bool inControl() const { return xbarOutOfControl.empty() && rOutOfControl.empty(); }
  /// The 0-based subgroup of ranges[j]: j, or j + 1 for moving ranges.
  std::size_t rangeSubgroup(std::size_t j) const { return type == ChartType::IndividualsMR ? j + 1 : j; }
  /// The number of values a range spans: n, or 2 for moving ranges (the constants are those of it).
  int rangeSpan() const { return type == ChartType::IndividualsMR ? 2 : subgroupSize; }
};

/// Builds the charts from consecutive subgroups of n values; a trailing incomplete subgroup is left
/// out (the caller reports it). ValidationError at `where` when there are fewer than 2 complete
/// subgroups, a value is not finite, or every range is 0 (no within-subgroup variation to set
/// limits from). OptionsError when n is outside [2, 25].
XbarRChart xbarRChart(const std::vector<double>& values, int n, const ErrorContext& where = {});

/// The charts with limits from the first `baseSubgroups` subgroups (0: all; phase I / phase II in
/// the header comment); n = 1 gives individuals and moving range, n = 2..25 X-bar and R.
/// ValidationError at `where` as xbarRChart, also when the base is 1 subgroup or more subgroups
/// than the series has, or every range (moving range) of the base is 0. OptionsError when n is
/// outside [1, 25].
XbarRChart controlChart(const std::vector<double>& values, int n, std::size_t baseSubgroups,
                        const ErrorContext& where = {});

}  // namespace metrofit
