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
};

/// The constants for subgroup size n in [2, 25]; OptionsError (field 'subgroup size') otherwise.
/// Computed on first use of each n, then cached (thread-safe).
const ControlChartConstants& controlChartConstants(int n);

struct XbarRChart {
  int subgroupSize = 0;
  std::vector<double> means;   ///< xbar_i
  std::vector<double> ranges;  ///< R_i
  double grandMean = 0.0;      ///< xbarbar
  double meanRange = 0.0;      ///< Rbar (centre line of the R chart)
  double xbarUcl = 0.0, xbarLcl = 0.0;
  double rUcl = 0.0, rLcl = 0.0;
  std::vector<std::size_t> xbarOutOfControl;  ///< 0-based subgroup indices beyond the X-bar limits
  std::vector<std::size_t> rOutOfControl;     ///< 0-based subgroup indices beyond the R limits

  std::size_t subgroups() const { return means.size(); }
  bool inControl() const { return xbarOutOfControl.empty() && rOutOfControl.empty(); }
};

/// Builds the charts from consecutive subgroups of n values; a trailing incomplete subgroup is left
/// out (the caller reports it). ValidationError at `where` when there are fewer than 2 complete
/// subgroups, a value is not finite, or every range is 0 (no within-subgroup variation to set
/// limits from). OptionsError when n is outside [2, 25].
XbarRChart xbarRChart(const std::vector<double>& values, int n, const ErrorContext& where = {});

}  // namespace metrofit
