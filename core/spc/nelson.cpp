#include "core/spc/nelson.h"

#include <stdexcept>

namespace metrofit {
namespace {

/// Zone of a point relative to CL in units of the side's sigma, as the rules need it.
struct Zones {
  double cl, ucl, lcl, up, down;  // up/down: sigma above and below CL

  /// +1 beyond k sigma above CL, -1 beyond k sigma below, 0 otherwise (k = 3: the limits themselves).
  int beyond(double x, int k) const {
    if (k == 3) return x > ucl ? 1 : (x < lcl ? -1 : 0);
    if (x > cl + k * up) return 1;
    if (x < cl - k * down) return -1;
    return 0;
  }
  static int side(double x, double cl) { return x > cl ? 1 : (x < cl ? -1 : 0); }
};

/// Points i (>= length - 1) where `ok(j)` holds for every j in i - length + 1 .. i.
template <class Ok>
std::vector<std::size_t> runs(std::size_t count, std::size_t length, Ok ok) {
  std::vector<std::size_t> out;
  std::size_t run = 0;
  for (std::size_t i = 0; i < count; ++i) {
    run = ok(i) ? run + 1 : 0;
    if (run >= length) out.push_back(i);
  }
  return out;
}

/// Points i beyond k sigma on a side s with at least `need` of points max(0, i - window + 1) .. i
/// beyond k sigma on side s (rules 5 and 6).
std::vector<std::size_t> countInWindow(const std::vector<double>& x, const Zones& z, int k,
                                       std::size_t window, std::size_t need) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int s = z.beyond(x[i], k);
    if (s == 0) continue;
    std::size_t count = 0;
    for (std::size_t j = i + 1 >= window ? i + 1 - window : 0; j <= i; ++j) count += z.beyond(x[j], k) == s;
    if (count >= need) out.push_back(i);
  }
  return out;
}

}  // namespace

std::vector<std::size_t> nelsonRule(int rule, const std::vector<double>& x, double cl, double ucl,
                                    double lcl) {
  const Zones z{cl, ucl, lcl, (ucl - cl) / 3.0, (cl - lcl) / 3.0};
  const std::size_t n = x.size();
  switch (rule) {
    case 1:
      return runs(n, 1, [&](std::size_t i) { return z.beyond(x[i], 3) != 0; });
    case 2: {
      // Two run counters, one per side: a point on the other side (or on CL) resets a side's run.
      std::vector<std::size_t> out;
      std::size_t above = 0, below = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const int s = Zones::side(x[i], cl);
        above = s > 0 ? above + 1 : 0;
        below = s < 0 ? below + 1 : 0;
        if (above >= 9 || below >= 9) out.push_back(i);
      }
      return out;
    }
    case 3: {
      // Six points: five consecutive differences of one sign.
      std::vector<std::size_t> out;
      std::size_t up = 0, down = 0;
      for (std::size_t i = 1; i < n; ++i) {
        up = x[i] > x[i - 1] ? up + 1 : 0;
        down = x[i] < x[i - 1] ? down + 1 : 0;
        if (up >= 5 || down >= 5) out.push_back(i);
      }
      return out;
    }
    case 4: {
      // Fourteen points: thirteen consecutive non-zero differences, each of the other sign than the last.
      std::vector<std::size_t> out;
      std::size_t alternating = 0;
      int last = 0;
      for (std::size_t i = 1; i < n; ++i) {
        const int s = Zones::side(x[i], x[i - 1]);
        alternating = s == 0 ? 0 : (last != 0 && s == -last ? alternating + 1 : 1);
        last = s;
        if (alternating >= 13) out.push_back(i);
      }
      return out;
    }
    case 5:
      return countInWindow(x, z, 2, 3, 2);
    case 6:
      return countInWindow(x, z, 1, 5, 4);
    case 7:
      return runs(n, 15, [&](std::size_t i) { return z.beyond(x[i], 1) == 0; });
    case 8:
      return runs(n, 8, [&](std::size_t i) { return z.beyond(x[i], 1) != 0; });
    default:
      throw std::invalid_argument("Nelson rule " + std::to_string(rule) + " is not one of 1..8");
  }
}

const char* ruleChartName(RuleChart chart) {
  return chart == RuleChart::Mean ? "xbar" : "r";
}

std::string ruleName(int rule) {
  return "nelson" + std::to_string(rule);
}

std::vector<RuleBreak> nelsonRules(const XbarRChart& c) {
  std::vector<RuleBreak> out;
  for (int rule = 1; rule <= kNelsonRules; ++rule) {
    std::vector<std::size_t> at = nelsonRule(rule, c.means, c.grandMean, c.xbarUcl, c.xbarLcl);
    if (!at.empty()) out.push_back({RuleChart::Mean, rule, std::move(at)});
  }
  for (int rule = 1; rule <= kNelsonRules; ++rule) {
    std::vector<std::size_t> at = nelsonRule(rule, c.ranges, c.meanRange, c.rUcl, c.rLcl);
    for (std::size_t& j : at) j = c.rangeSubgroup(j);
    if (!at.empty()) out.push_back({RuleChart::Range, rule, std::move(at)});
  }
  return out;
}

}  // namespace metrofit
