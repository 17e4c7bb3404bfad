// Nelson's eight tests for special causes (core/spc/nelson.h): each on a short series built so that
// exactly that rule fires at a known point, a clean series where none fires, the asymmetric zones of
// the R chart, and the mapping of moving ranges to subgroups. Every expected index is worked out by
// hand in the comments (0-based here; the JSON writes them 1-based).
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <vector>

#include "core/spc/control_chart.h"
#include "core/spc/nelson.h"

namespace metrofit {
namespace {

using Indices = std::vector<std::size_t>;

/// Every rule on `x` against CL 0, UCL 3, LCL -3 (sigma 1 on both sides): rule -> indices, fired only.
std::map<int, Indices> fired(const std::vector<double>& x, double cl = 0.0, double ucl = 3.0,
                             double lcl = -3.0) {
  std::map<int, Indices> out;
  for (int rule = 1; rule <= kNelsonRules; ++rule) {
    Indices at = nelsonRule(rule, x, cl, ucl, lcl);
    if (!at.empty()) out[rule] = at;
  }
  return out;
}

TEST(Nelson, Rule1OnePointBeyondThreeSigma) {
  // 3.5 (index 2) above UCL 3, -3.2 (index 5) below LCL -3; nothing else is beyond 1 sigma.
  EXPECT_EQ(fired({0.5, -0.5, 3.5, 0.2, -0.3, -3.2}), (std::map<int, Indices>{{1, {2, 5}}}));
  // On the limit itself is not beyond it.
  EXPECT_TRUE(nelsonRule(1, {3.0, -3.0}, 0.0, 3.0, -3.0).empty());
}

TEST(Nelson, Rule2NineInARowOnOneSide) {
  // Indices 1..9 are above CL (all within 1 sigma, no six rising, 11 points: too few for rules 4, 7):
  // the ninth of them, index 9, completes the run.
  EXPECT_EQ(fired({-0.5, 0.2, 0.6, 0.3, 0.8, 0.4, 0.5, 0.1, 0.7, 0.2, -0.3}),
            (std::map<int, Indices>{{2, {9}}}));
  // A point on the centre line ends a run: eight above, 0, eight above.
  std::vector<double> x(8, 0.5);
  x.push_back(0.0);
  x.insert(x.end(), 8, 0.5);
  EXPECT_TRUE(nelsonRule(2, x, 0.0, 3.0, -3.0).empty());
  // Below the line too.
  EXPECT_EQ(nelsonRule(2, std::vector<double>(10, -0.5), 0.0, 3.0, -3.0), (Indices{8, 9}));
}

TEST(Nelson, Rule3SixInARowRisingOrFalling) {
  // -0.6 < -0.4 < -0.1 < 0.2 < 0.5 < 0.9 at indices 1..6: completed at 6.
  EXPECT_EQ(fired({0.1, -0.6, -0.4, -0.1, 0.2, 0.5, 0.9, 0.3}), (std::map<int, Indices>{{3, {6}}}));
  // The mirror image falls: the same index.
  EXPECT_EQ(fired({-0.1, 0.6, 0.4, 0.1, -0.2, -0.5, -0.9, -0.3}), (std::map<int, Indices>{{3, {6}}}));
  // Equal neighbours are not a rise: 1 2 3 3 4 5 6 has at most four rising steps in a row.
  EXPECT_TRUE(nelsonRule(3, {0.1, 0.2, 0.3, 0.3, 0.4, 0.5, 0.6}, 0.0, 3.0, -3.0).empty());
}

TEST(Nelson, Rule4FourteenAlternating) {
  // 1.5, 1.5, then -0.4, 0.4, ... : the steps alternate from index 1 -> 2 on (the step 0 -> 1 is 0).
  // Points 1..14 are fourteen alternating points: completed at 14. Only indices 0 and 1 are beyond
  // 1 sigma, so rule 7 has 13 points within 1 sigma (2..14), not 15.
  std::vector<double> x = {1.5, 1.5};
  for (int i = 0; i < 13; ++i) x.push_back(i % 2 == 0 ? -0.4 : 0.4);
  ASSERT_EQ(x.size(), 15u);
  EXPECT_EQ(fired(x), (std::map<int, Indices>{{4, {14}}}));
  // One more alternating point: the run goes on and index 15 completes a window too.
  x.push_back(0.4);
  EXPECT_EQ(nelsonRule(4, x, 0.0, 3.0, -3.0), (Indices{14, 15}));
}

TEST(Nelson, Rule5TwoOfThreeBeyondTwoSigma) {
  // 2.5 (index 1) and 2.2 (index 3) above 2 sigma, 0.5 between: two of the three points 1..3.
  EXPECT_EQ(fired({0.3, 2.5, 0.5, 2.2, -0.2, 0.1}), (std::map<int, Indices>{{5, {3}}}));
  // Below: -2.5, -2.1 at 1, 2 -> completed at 2; then 2.5 and -2.5 are on opposite sides: no more.
  EXPECT_EQ(fired({0.3, -2.5, -2.1, 0.4, 2.5, -2.5, 0.2}), (std::map<int, Indices>{{5, {2}}}));
}

TEST(Nelson, Rule6FourOfFiveBeyondOneSigma) {
  // Beyond 1 sigma above at 1, 2, 4, 5 (0.5 at 3 is not): four of the five points 1..5, at 5. At 4 only
  // three of 0..4.
  EXPECT_EQ(fired({0.2, 1.5, 1.2, 0.5, 1.8, 1.1, -0.3}), (std::map<int, Indices>{{6, {5}}}));
}

TEST(Nelson, Rule7FifteenWithinOneSigma) {
  // 1.5, then fifteen points within +-1 (indices 1..15) that neither stay on one side nine times nor
  // rise six times nor alternate fourteen times: completed at 15.
  EXPECT_EQ(fired({1.5, 0.5, -0.5, 0.3, 0.6, -0.2, -0.7, 0.4, 0.1, -0.3, 0.8, -0.6, -0.1, 0.2, 0.9, -0.4}),
            (std::map<int, Indices>{{7, {15}}}));
}

TEST(Nelson, Rule8EightBeyondOneSigmaEitherSide) {
  // Indices 1..8 beyond 1 sigma, alternating sides (never four of five on one side; ten alternating
  // points in all, fewer than fourteen): completed at 8.
  EXPECT_EQ(fired({0.2, 1.5, -1.5, 1.2, -1.8, 1.4, -1.1, 1.6, -1.3, 0.1}),
            (std::map<int, Indices>{{8, {8}}}));
}

TEST(Nelson, CleanSeriesBreaksNoRule) {
  // Twenty points: one beyond 2 sigma (2.5), scattered 1-sigma excursions on both sides, runs on one
  // side of at most 3, no six-point trend, the alternation broken by equal neighbours (0.3, 0.3).
  EXPECT_TRUE(fired({0.5,  -0.5, 1.5,  0.2, -1.2, 0.3,  0.3, -0.4, 2.5, 0.1,
                     -0.6, 0.7,  -1.5, 0.0, 0.4,  -0.2, 1.1, -0.3, 0.6, 0.6})
                  .empty());
  EXPECT_TRUE(fired({}).empty());
}

TEST(Nelson, RangeChartZonesAreMeasuredOnEachSide) {
  // R chart CL 1, UCL 2.5, LCL 0: sigma above (2.5 - 1) / 3 = 0.5, below (1 - 0) / 3 = 1/3.
  // 2 sigma below is 1 - 2/3 = 0.3333: 0.3 (index 1) and 0.2 (index 3) are beyond it, 0.34 is not;
  // 2 sigma above is 2.0: 1.9 and 1.95 are not beyond it. Rule 5 at 3 and nothing else. (With the
  // upper sigma on both sides, 2 sigma below would be 0 and nothing would fire.)
  EXPECT_EQ(fired({1.0, 0.3, 0.9, 0.2, 0.34, 1.9, 1.95}, 1.0, 2.5, 0.0), (std::map<int, Indices>{{5, {3}}}));
}

TEST(Nelson, RulesOfAChartNameTheirSubgroups) {
  XbarRChart c;
  c.type = ChartType::IndividualsMR;
  c.subgroupSize = 1;
  c.means = {0.5, -0.5, 3.5, 0.2};
  c.grandMean = 0.0;
  c.xbarUcl = 3.0;
  c.xbarLcl = -3.0;
  c.ranges = {1.0, 4.0, 3.3};  // the moving ranges of subgroups 1, 2, 3 (0-based)
  c.meanRange = 1.0;
  c.rUcl = 3.267;
  c.rLcl = 0.0;
  const std::vector<RuleBreak> rules = nelsonRules(c);
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0].chart, RuleChart::Mean);
  EXPECT_EQ(rules[0].rule, 1);
  EXPECT_EQ(rules[0].subgroups, (Indices{2}));
  // Moving ranges 4.0 and 3.3 (ranges[1], ranges[2]) are beyond 3.267: subgroups 2 and 3.
  EXPECT_EQ(rules[1].chart, RuleChart::Range);
  EXPECT_EQ(rules[1].rule, 1);
  EXPECT_EQ(rules[1].subgroups, (Indices{2, 3}));
  // They are also two of three beyond 2 sigma above (1 + 2 (3.267 - 1) / 3 = 2.511): rule 5 at the
  // second of them, subgroup 3.
  EXPECT_EQ(rules[2].chart, RuleChart::Range);
  EXPECT_EQ(rules[2].rule, 5);
  EXPECT_EQ(rules[2].subgroups, (Indices{3}));
  EXPECT_STREQ(ruleChartName(RuleChart::Mean), "xbar");
  EXPECT_STREQ(ruleChartName(RuleChart::Range), "r");
  EXPECT_EQ(ruleName(7), "nelson7");
  EXPECT_THROW(nelsonRule(0, {1.0}, 0.0, 3.0, -3.0), std::invalid_argument);
  EXPECT_THROW(nelsonRule(9, {1.0}, 0.0, 3.0, -3.0), std::invalid_argument);
}

}  // namespace
}  // namespace metrofit
