// The round numbers of chart axes (core/common/axis_ticks.h), against values worked out by hand.
#include "core/common/axis_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace metrofit::ticks {
namespace {

TEST(AxisTicks, NiceFloorIsTheLargestOneTwoFiveBelow) {
  EXPECT_DOUBLE_EQ(niceFloor(7.3), 5.0);
  EXPECT_DOUBLE_EQ(niceFloor(0.0042), 0.002);
  EXPECT_DOUBLE_EQ(niceFloor(1999.0), 1000.0);
  EXPECT_DOUBLE_EQ(niceFloor(50.0), 50.0);  // exact values stay
  EXPECT_DOUBLE_EQ(niceFloor(2.0), 2.0);
}

TEST(AxisTicks, NiceCeilIsTheSmallestOneTwoFiveAbove) {
  EXPECT_DOUBLE_EQ(niceCeil(7.3), 10.0);
  EXPECT_DOUBLE_EQ(niceCeil(0.0042), 0.005);
  EXPECT_DOUBLE_EQ(niceCeil(1.01), 2.0);
  EXPECT_DOUBLE_EQ(niceCeil(5.0), 5.0);
  EXPECT_DOUBLE_EQ(niceCeil(0.1), 0.1);
}

TEST(AxisTicks, StepCoversTheSpanInAboutCountIntervals) {
  EXPECT_DOUBLE_EQ(niceStep(10.0, 2), 5.0);   // the polar plot's rings: 10 um in two rings
  EXPECT_DOUBLE_EQ(niceStep(37.0, 6), 10.0);  // 6.17 -> 10
  EXPECT_DOUBLE_EQ(niceStep(0.9, 8), 0.2);    // 0.1125 -> 0.2
  for (double span : {0.013, 1.0, 3.7, 250.0, 9.9e4})
    for (int n : {2, 5, 8}) EXPECT_GE(n * niceStep(span, n), span * (1 - 1e-12)) << span << " " << n;
}

TEST(AxisTicks, UnusableInputGivesOneNeverNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double x : {0.0, -3.0, nan, std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(niceFloor(x), 1.0);
    EXPECT_EQ(niceCeil(x), 1.0);
    EXPECT_EQ(niceStep(x, 5), 1.0);
  }
  EXPECT_EQ(niceStep(10.0, 0), 1.0);
}

TEST(AxisTicks, TickValuesAreTheMultiplesInsideTheRange) {
  const std::vector<double> t = tickValues(-0.37, 1.21, 5);  // step niceCeil(0.316) = 0.5
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[0], 0.0);
  EXPECT_DOUBLE_EQ(t[1], 0.5);
  EXPECT_DOUBLE_EQ(t[2], 1.0);
  EXPECT_TRUE(tickValues(2.0, 1.0, 5).empty());
}

}  // namespace
}  // namespace metrofit::ticks

namespace metrofit::ticks {
namespace {

TEST(AxisRange, IgnoresNonFiniteAndPadsByAFraction) {
  Range r;
  EXPECT_FALSE(r.valid());
  EXPECT_DOUBLE_EQ(r.padded().lo, 0.0);
  EXPECT_DOUBLE_EQ(r.padded().hi, 1.0);
  r.add(std::numeric_limits<double>::quiet_NaN());
  r.add(2.0);
  r.add(-std::numeric_limits<double>::infinity());
  r.add(4.0);
  EXPECT_TRUE(r.valid());
  EXPECT_DOUBLE_EQ(r.padded().lo, 1.9);  // 5 % of the span 2
  EXPECT_DOUBLE_EQ(r.padded(0.25).hi, 4.5);
  Range one;
  one.add(3.0);
  EXPECT_DOUBLE_EQ(one.padded().lo, 1.0);  // a single value: +-(0.5 |v| + 0.5)
  EXPECT_DOUBLE_EQ(one.padded().hi, 5.0);
}

}  // namespace
}  // namespace metrofit::ticks
