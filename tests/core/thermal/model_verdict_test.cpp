// The usability thresholds of a thermal model (core/thermal/model_verdict.h) on metrics computed
// by thermalMetrics from hand-made predictions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/thermal/model_verdict.h"

namespace metrofit::thermal {
namespace {

std::vector<double> wave(double scale, double shift, double noise) {
  std::vector<double> v;
  for (int i = 0; i < 200; ++i) v.push_back(scale * std::sin(i / 20.0) + shift + noise * std::sin(i * 2.7));
  return v;
}

TEST(ModelVerdict, UsableNegativeEfficiencyLowCorrelationDiverging) {
  const std::vector<double> measured = wave(10.0, 0.0, 0.0);
  const double scale = targetScale(measured);
  EXPECT_EQ(judgeThermalModel(thermalMetrics(measured, wave(10.0, 0.0, 0.5)), scale), ModelVerdict::Usable);
  // Follows the shape (R near 1) but 15 off: worse than the mean, E < 0.
  EXPECT_EQ(judgeThermalModel(thermalMetrics(measured, wave(10.0, 15.0, 0.0)), scale),
            ModelVerdict::NegativeEfficiency);
  // A flat small prediction: E about 0 or slightly above, R low.
  ThermalMetrics low;
  low.r = 0.3;
  low.e = 0.05;
  low.rmse = 9.0;
  EXPECT_EQ(judgeThermalModel(low, scale), ModelVerdict::LowCorrelation);
  ThermalMetrics runaway = low;
  runaway.rmse = 1e68;
  EXPECT_EQ(judgeThermalModel(runaway, scale), ModelVerdict::Diverges);
  runaway.rmse = std::nan("");
  EXPECT_EQ(judgeThermalModel(runaway, scale), ModelVerdict::Diverges);
  // Thresholds are inclusive at the limit.
  ThermalMetrics edge{10, kMinCorrelation, 1.0, kMinEfficiency, 1.0};
  EXPECT_EQ(judgeThermalModel(edge, scale), ModelVerdict::Usable);
}

// The tables' "diverges" and the verdict are one rule: RMSE not finite or above 100 x the scale.
TEST(ModelVerdict, DivergesIsTheVerdictsRule) {
  ThermalMetrics m{10, 0.9, 1.0, 0.9, 1.0};
  m.rmse = 2.16e305;
  EXPECT_TRUE(diverges(m, 87.2));
  m.rmse = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(diverges(m, 87.2));
  m.rmse = 8000.0;  // exactly 100 x: not yet
  EXPECT_FALSE(diverges(m, 80.0));
  m.rmse = 8001.0;
  EXPECT_TRUE(diverges(m, 80.0));
  EXPECT_EQ(judgeThermalModel(m, 80.0), ModelVerdict::Diverges);
}

}  // namespace
}  // namespace metrofit::thermal
