// Table 4's indices (Abdulshahed 2016, grey neural network thermal model) against values computed by hand.
#include "core/thermal/thermal_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "testsupport.h"

namespace metrofit::thermal {
namespace {

TEST(ThermalMetrics, HandComputedCase) {
  // y = 1 2 3 4, y^ = 1.5 2 2.5 4.5: residuals -0.5 0 0.5 -0.5.
  //   RMSE = sqrt(0.75 / 4) = 0.4330127..., band = 0.5,
  //   sum (y - 2.5)^2 = 5, E = 1 - 0.75 / 5 = 0.85,
  //   mean y^ = 2.625, sum dy dy^ = 4.75, sum dy^^2 = 5.1875, R = 4.75 / sqrt(5 * 5.1875).
  const std::vector<double> y{1, 2, 3, 4}, p{1.5, 2, 2.5, 4.5};
  const ThermalMetrics m = thermalMetrics(y, p);
  EXPECT_EQ(m.n, 4u);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(0.1875));
  EXPECT_DOUBLE_EQ(m.residualBand, 0.5);
  EXPECT_DOUBLE_EQ(m.e, 0.85);
  EXPECT_TRUE(test::near(m.r, 0.9326733, 1e-7));
  EXPECT_DOUBLE_EQ(m.r, 4.75 / std::sqrt(5.0 * 5.1875));
}

TEST(ThermalMetrics, PerfectAndMeanModels) {
  const std::vector<double> y{-3, 0, 2, 7};
  const ThermalMetrics perfect = thermalMetrics(y, y);
  EXPECT_EQ(perfect.rmse, 0.0);
  EXPECT_EQ(perfect.e, 1.0);
  EXPECT_DOUBLE_EQ(perfect.r, 1.0);
  // Predicting the mean gives E = 0 and an undefined R (constant prediction).
  const std::vector<double> mean(4, 1.5);
  const ThermalMetrics m = thermalMetrics(y, mean);
  EXPECT_DOUBLE_EQ(m.e, 0.0);
  EXPECT_TRUE(std::isnan(m.r));
  EXPECT_DOUBLE_EQ(m.residualBand, 5.5);
  // A constant measurement leaves E undefined; no rows leave everything undefined.
  EXPECT_TRUE(std::isnan(thermalMetrics(mean, y).e));
  EXPECT_TRUE(std::isnan(thermalMetrics(std::vector<double>{}, std::vector<double>{}).rmse));
}

}  // namespace
}  // namespace metrofit::thermal
