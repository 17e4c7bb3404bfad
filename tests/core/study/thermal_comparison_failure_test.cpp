// One model's failure marks that model only (core/study/thermal_comparison.h): on a noise-free log whose
// target is exactly linear in its one input, GMC(1,N)'s least-squares system is rank deficient; the
// comparison records that for GMC(1,N) with its reason and fits the other models, the static linear
// model exactly (closed form: the target is 3.25 um/K times the temperature's change, written to the
// file with every decimal it has). Bad input that every model refuses still throws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
namespace {

constexpr double kSlope = 3.25;  // um/K

/// Heating of a spindle, 120 rows every 30 s: T1 rounded to the 4 decimals the file carries, so that
/// the displacement (6 decimals) is exactly 3.25 (T1 - 21) - 0.8 in the file.
std::string linearLogCsv(bool constantTarget = false) {
  std::string csv = "time_s,T1,disp_z_um\n";
  for (int r = 0; r < 120; ++r) {
    const double t = 30.0 * r;
    const double temperature = std::round((21.0 + 9.0 * (1.0 - std::exp(-t / 1500.0))) * 1e4) / 1e4;
    const double disp = constantTarget ? 1.5 : kSlope * (temperature - 21.0) - 0.8;
    char line[96];
    std::snprintf(line, sizeof line, "%d,%.4f,%.6f\n", static_cast<int>(t), temperature, disp);
    csv += line;
  }
  return csv;
}

ThermalLog linearLog(bool constantTarget = false) {
  return thermalLogFromCsv(parseCsv(linearLogCsv(constantTarget), "linear.csv"));
}

std::size_t indexOf(thermal::ThermalModelKind kind) {
  for (std::size_t i = 0; i < kThermalModelCount; ++i)
    if (kThermalModelOrder[i] == kind) return i;
  return kThermalModelCount;
}

TEST(ThermalComparisonFailure, ARankDeficientGmcIsMarkedAndTheLinearModelFitsExactly) {
  const ThermalLog log = linearLog();
  ThermalModelSettings s;
  s.target = "disp_z_um";
  s.inputs = {"T1"};
  s.trainFraction = 0.5;
  ThermalComparison c;
  ASSERT_NO_THROW(c = compareThermalModels(log, s));
  EXPECT_FALSE(c.cancelled);
  EXPECT_EQ(c.fitRows, 60u);
  EXPECT_EQ(c.heldoutRows, 60u);

  const std::size_t gmc = indexOf(thermal::ThermalModelKind::Gmc);
  const std::size_t linear = indexOf(thermal::ThermalModelKind::Linear);
  EXPECT_FALSE(c.fitted(gmc));
  EXPECT_NE(c.failed[gmc].find("rank deficient"), std::string::npos) << c.failed[gmc];
  EXPECT_EQ(c.failed[gmc].find('\n'), std::string::npos);
  EXPECT_TRUE(c.models[gmc].predicted.empty());

  ASSERT_TRUE(c.fitted(linear)) << c.failed[linear];
  EXPECT_LT(c.models[linear].heldout.rmse, 1e-9);
  // The closed form on every row: 3.25 (T1 - 21) - 0.8.
  const std::vector<double>& t1 = log.channel("T1").values;
  for (std::size_t k = 0; k < log.rows(); ++k)
    EXPECT_NEAR(c.models[linear].predicted[k], kSlope * (t1[k] - 21.0) - 0.8, 1e-9) << k;
  // Every model that fitted has finite figures; the failed one none (no NaN to show).
  for (std::size_t i = 0; i < kThermalModelCount; ++i) {
    if (!c.fitted(i)) continue;
    EXPECT_TRUE(c.failed[i].empty());
    EXPECT_TRUE(std::isfinite(c.models[i].fit.rmse)) << i;
    EXPECT_EQ(c.models[i].predicted.size(), log.rows());
  }
}

TEST(ThermalComparisonFailure, BadInputThatEveryModelRefusesStillThrows) {
  ThermalModelSettings s;
  s.target = "disp_z_um";
  s.inputs = {"T1"};
  // A constant target: no model can learn anything; the core's ValidationError, as before.
  EXPECT_THROW(compareThermalModels(linearLog(true), s), ValidationError);
  // A column the log does not have.
  s.inputs = {"T9"};
  EXPECT_THROW(compareThermalModels(linearLog(), s), InputError);
  // A train fraction out of range: the OptionsError at once.
  s.inputs = {"T1"};
  s.trainFraction = 1.5;
  EXPECT_THROW(compareThermalModels(linearLog(), s), OptionsError);
  // Too few held-out rows for every model.
  s.trainFraction = 0.99;
  EXPECT_THROW(compareThermalModels(linearLog(), s), ValidationError);
}

// The modular case likewise: fitted on two such logs together, GMC(1,N) is rank deficient and marked;
// the linear model predicts a third log (the same heating, 1 K cooler at the start) exactly.
TEST(ThermalComparisonFailure, TheModularCaseMarksTheModelThatCannotBeFitted) {
  const ThermalLog a = linearLog(), b = linearLog();
  std::string shifted = "time_s,T1,disp_z_um\n";
  for (std::size_t k = 0; k < a.rows(); ++k) {
    const double t1 = a.channel("T1").values[k] - 1.0;
    char line[96];
    std::snprintf(line, sizeof line, "%d,%.4f,%.6f\n", static_cast<int>(30 * k), t1,
                  kSlope * (t1 - 21.0) - 0.8);
    shifted += line;
  }
  const ThermalLog test = thermalLogFromCsv(parseCsv(shifted, "test.csv"));
  ModularComparison m;
  ASSERT_NO_THROW(m = compareModularModels({&a, &b}, test, "disp_z_um", {"T1"}, 1));
  const std::size_t gmc = indexOf(thermal::ThermalModelKind::Gmc);
  const std::size_t linear = indexOf(thermal::ThermalModelKind::Linear);
  EXPECT_FALSE(m.fitted(gmc));
  EXPECT_NE(m.failed[gmc].find("rank deficient"), std::string::npos) << m.failed[gmc];
  ASSERT_TRUE(m.fitted(linear)) << m.failed[linear];
  EXPECT_LT(m.models[linear].test.rmse, 1e-9);
  // Both tests move T1 alike: no module has a channel of its own (said, not thrown).
  EXPECT_FALSE(m.modules.evaluation.has_value());
  EXPECT_FALSE(m.modules.why.empty());
}

}  // namespace
}  // namespace metrofit
