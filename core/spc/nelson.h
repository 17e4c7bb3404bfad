#pragma once
// Nelson's tests for special causes on a Shewhart chart (L. S. Nelson, "The Shewhart Control Chart -
// Tests for Special Causes", Journal of Quality Technology 16(4), 1984, pp. 237-239; the same eight
// tests as the Western Electric zone rules, numbered as Minitab and Q-DAS number them).
//
// Zones. sigma is a third of the distance from the centre line CL to a control limit, measured on
// each side separately:
//   above CL   sigma_up   = (UCL - CL) / 3
//   below CL   sigma_down = (CL - LCL) / 3
// On the X-bar and X charts the limits are symmetric, so both are A2 Rbar / 3 (E2 MRbar / 3). On the
// R (MR) chart they are not: UCL = D4 Rbar, LCL = D3 Rbar (0 for n <= 6), so the zones above CL are
// (D4 - 1) Rbar / 3 wide and those below (1 - D3) Rbar / 3. "Beyond k sigma" is strictly beyond
// CL + k sigma_up or CL - k sigma_down; for k = 3 the limits themselves are used, so rule 1 lists
// exactly the subgroups beyond the control limits.
//
//   1  one point beyond 3 sigma (outside the control limits)
//   2  nine points in a row on the same side of CL (a point on CL ends the run)
//   3  six points in a row steadily increasing or steadily decreasing (equal neighbours end it)
//   4  fourteen points in a row alternating up and down
//   5  two out of three points in a row beyond 2 sigma on the same side
//   6  four out of five points in a row beyond 1 sigma on the same side
//   7  fifteen points in a row within 1 sigma on either side (|x - CL| <= sigma)
//   8  eight points in a row beyond 1 sigma on either side (none within 1 sigma)
//
// Which point is reported: the point at which the pattern is completed, i.e. the last point of the
// run or window. A run longer than the rule's length reports every point from the one that completes
// the first window onwards (a run of 10 on one side gives points 9 and 10 for rule 2). For rules 5
// and 6 the reported point is itself beyond the zone and completes the count among the last three
// (five) points, counting from the start of the series when fewer came before it. Runs span phase I
// and phase II alike: every point is judged against the same limits.
#include <cstddef>
#include <string>
#include <vector>

#include "core/spc/control_chart.h"

namespace metrofit {

inline constexpr int kNelsonRules = 8;

/// 0-based indices of `points` at which Nelson rule `rule` (1..8) is completed (see the header
/// comment), for a chart with centre line `cl` and limits `lcl` < `cl` < `ucl`. std::invalid_argument
/// for a rule outside 1..8.
std::vector<std::size_t> nelsonRule(int rule, const std::vector<double>& points, double cl, double ucl,
                                    double lcl);

enum class RuleChart {
  Mean,  ///< the X-bar (X) chart, "xbar" in the JSON
  Range  ///< the R (MR) chart, "r" in the JSON
};

/// A rule broken on one chart: the 0-based subgroups at which it is completed (never empty).
struct RuleBreak {
  RuleChart chart = RuleChart::Mean;
  int rule = 1;  ///< 1..8
  std::vector<std::size_t> subgroups;
};

/// "xbar" or "r".
const char* ruleChartName(RuleChart chart);
/// "nelson1" ... "nelson8".
std::string ruleName(int rule);

/// Every rule broken on the X-bar (X) chart, then on the R (MR) chart, each in rule order; a moving
/// range is reported at its later subgroup (XbarRChart::rangeSubgroup).
std::vector<RuleBreak> nelsonRules(const XbarRChart& chart);

}  // namespace metrofit
