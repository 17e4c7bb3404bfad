// SPC (IEEE Access, kinematic compensation algorithm, Section IV.A): chart constants against the published
// table, X-bar/R limits, Cp/Cpk/Pp/Ppk, natural tolerance (Eq. 17), systematic error (Eq. 20), regression
// line and offset angle (Fig. 10), the SPC gate, and bad input; the published limits of Montgomery's
// piston rings (Example 6.1), phase I / phase II limits, individuals and moving range, and the rules
// in the JSON (the rules themselves: nelson_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/spc/control_chart.h"
#include "core/spc/spc.h"
#include "testsupport.h"

namespace metrofit {
namespace {

// The standard table of factors for X-bar and R charts (Montgomery, Introduction to Statistical
// Quality Control, Appendix VI; ASTM Manual on Presentation of Data and Control Chart Analysis).
struct TableRow {
  int n;
  double A2, D3, D4, d2;
};
const TableRow kTable[] = {
    {2, 1.880, 0.000, 3.267, 1.128},  {3, 1.023, 0.000, 2.574, 1.693},  {4, 0.729, 0.000, 2.282, 2.059},
    {5, 0.577, 0.000, 2.114, 2.326},  {6, 0.483, 0.000, 2.004, 2.534},  {7, 0.419, 0.076, 1.924, 2.704},
    {8, 0.373, 0.136, 1.864, 2.847},  {9, 0.337, 0.184, 1.816, 2.970},  {10, 0.308, 0.223, 1.777, 3.078},
    {11, 0.285, 0.256, 1.744, 3.173}, {12, 0.266, 0.283, 1.717, 3.258}, {13, 0.249, 0.307, 1.693, 3.336},
    {14, 0.235, 0.328, 1.672, 3.407}, {15, 0.223, 0.347, 1.653, 3.472}, {16, 0.212, 0.363, 1.637, 3.532},
    {17, 0.203, 0.378, 1.622, 3.588}, {18, 0.194, 0.391, 1.608, 3.640}, {19, 0.187, 0.403, 1.597, 3.689},
    {20, 0.180, 0.415, 1.585, 3.735}, {21, 0.173, 0.425, 1.575, 3.778}, {22, 0.167, 0.434, 1.566, 3.819},
    {23, 0.162, 0.443, 1.557, 3.858}, {24, 0.157, 0.451, 1.548, 3.895}, {25, 0.153, 0.459, 1.541, 3.931},
};

TEST(ControlChartConstants, MatchThePublishedTable) {
  for (const TableRow& row : kTable) {
    const ControlChartConstants& c = controlChartConstants(row.n);
    EXPECT_EQ(c.n, row.n);
    // A2 and d2 agree to the table's last digit (rounding: 0.0005).
    EXPECT_NEAR(c.A2, row.A2, 0.0005 + 1e-9) << "A2, n = " << row.n;
    EXPECT_NEAR(c.d2, row.d2, 0.0005 + 1e-9) << "d2, n = " << row.n;
    // D3 and D4: the printed table rounds 3 d3 / d2 from rounded d3 and d2, so at n = 18, 19, 22
    // and 24 its last digit is one off the exact value (there D3 + D4 != 2 in print, e.g.
    // 0.391 + 1.608 at n = 18); allow one unit in the last place.
    EXPECT_NEAR(c.D3, row.D3, 0.0011) << "D3, n = " << row.n;
    EXPECT_NEAR(c.D4, row.D4, 0.0011) << "D4, n = " << row.n;
    EXPECT_NEAR(c.D3 + c.D4, row.D3 > 0.0 ? 2.0 : c.D4, 1e-12) << row.n;
  }
  // Where the table is consistent, agreement is to rounding.
  for (const int n : {2, 5, 7, 10, 15, 20, 25}) {
    const ControlChartConstants& c = controlChartConstants(n);
    const TableRow& row = kTable[n - 2];
    EXPECT_NEAR(c.D3, row.D3, 0.0005 + 1e-9) << n;
    EXPECT_NEAR(c.D4, row.D4, 0.0005 + 1e-9) << n;
  }
  // Known closed forms: d2(2) = 2 / sqrt(pi), d3(2) = sqrt(2 - 4 / pi).
  EXPECT_NEAR(controlChartConstants(2).d2, 2.0 / std::sqrt(std::numbers::pi), 1e-7);
  EXPECT_NEAR(controlChartConstants(2).d3, std::sqrt(2.0 - 4.0 / std::numbers::pi), 1e-7);
}

TEST(ControlChartConstants, SubgroupSizeOutsideTheTableIsAnOptionsError) {
  EXPECT_THROW(controlChartConstants(1), OptionsError);
  EXPECT_THROW(controlChartConstants(26), OptionsError);
  try {
    controlChartConstants(30);
  } catch (const OptionsError& e) {
    EXPECT_EQ(std::string(e.what()),
              "field 'subgroup size': must be between 2 and 25 (the range of the A2/D3/D4 table), got 30");
  }
}

// Three subgroups of 5, hand-computed with the table (d2 = 2.326, A2 = 0.577, D4 = 2.114):
//   means 10.0, 10.1, 9.9 -> xbarbar = 10.0; ranges 0.4, 0.4, 0.4 -> Rbar = 0.4
//   UCL = 10 + 0.577 * 0.4 = 10.2308, LCL = 9.7692; R chart UCL = 0.8456, LCL = 0
//   sigma_within = 0.4 / 2.326 = 0.171969
//   LSL 9.4, USL 10.8: Cp = 1.4 / (6 * 0.171969) = 1.35683, Cpk = 0.6 / (3 * 0.171969) = 1.16300
//   sum of squares about 10.0 = 0.40 -> s = sqrt(0.40 / 14) = 0.169031
//   Pp = 1.4 / (6 s) = 1.38042, Ppk = 0.6 / (3 s) = 1.18322
const std::vector<double> kData = {10.0, 10.2, 9.9, 10.1, 9.8, 10.1, 10.3, 10.0,
                                   10.2, 9.9,  9.9, 10.1, 9.8, 10.0, 9.7};

SpcOptions withSpec() {
  SpcOptions o;
  o.subgroupSize = 5;
  o.lsl = 9.4;
  o.usl = 10.8;
  return o;
}

TEST(Spc, ChartLimitsAndCapabilityOnHandComputedData) {
  const SpcResult r = analyseSpc(kData, withSpec());
  ASSERT_EQ(r.chart.subgroups(), 3u);
  EXPECT_NEAR(r.chart.means[0], 10.0, 1e-12);
  EXPECT_NEAR(r.chart.means[1], 10.1, 1e-12);
  EXPECT_NEAR(r.chart.means[2], 9.9, 1e-12);
  EXPECT_NEAR(r.chart.grandMean, 10.0, 1e-12);
  EXPECT_NEAR(r.chart.meanRange, 0.4, 1e-12);
  EXPECT_NEAR(r.chart.xbarUcl, 10.2308, 2e-4);
  EXPECT_NEAR(r.chart.xbarLcl, 9.7692, 2e-4);
  EXPECT_NEAR(r.chart.rUcl, 0.8456, 2e-4);
  EXPECT_EQ(r.chart.rLcl, 0.0);
  EXPECT_TRUE(r.chart.inControl());
  EXPECT_NEAR(r.capability.sigmaWithin, 0.171969, 1e-5);
  EXPECT_NEAR(*r.capability.cp, 1.35683, 1e-3);
  EXPECT_NEAR(*r.capability.cpk, 1.16300, 1e-3);
  EXPECT_NEAR(r.capability.sigmaOverall, 0.169031, 1e-6);
  EXPECT_NEAR(*r.capability.pp, 1.38042, 1e-5);
  EXPECT_NEAR(*r.capability.ppk, 1.18322, 1e-5);
  // Eq. 17: (UCL - LCL) sqrt(n) is 6 sigma_within.
  EXPECT_NEAR(r.capability.naturalTolerance, 6.0 * r.capability.sigmaWithin, 1e-12);
  EXPECT_NEAR(r.capability.naturalTolerance, 1.032, 1e-3);
  EXPECT_EQ(r.valuesUsed, 15u);
  EXPECT_EQ(r.valuesIgnored, 0u);
  EXPECT_FALSE(r.systematic.has_value());
  EXPECT_FALSE(r.decision.apply);
  EXPECT_EQ(r.decision.reason, "no nominal value given: nothing to compensate against");
}

TEST(Spc, CpkUsesTheNearerLimit) {
  SpcOptions o = withSpec();
  o.lsl = 9.0;
  o.usl = 10.5;  // mean 10.0 is 0.5 from USL, 1.0 from LSL
  const SpcResult r = analyseSpc(kData, o);
  EXPECT_NEAR(*r.capability.cpk, 0.5 / (3.0 * r.capability.sigmaWithin), 1e-12);
  EXPECT_NEAR(*r.capability.cp, 1.5 / (6.0 * r.capability.sigmaWithin), 1e-12);
}

TEST(Spc, SystematicErrorIsNominalMinusMeanAndGatesCompensation) {
  SpcOptions o = withSpec();
  // Eq. 20 with V = 10.05: E = 0.05; standard error 0.171969 / sqrt(15) = 0.044402; k = 2 ->
  // +-0.088804: not significant.
  o.nominal = 10.05;
  SpcResult r = analyseSpc(kData, o);
  ASSERT_TRUE(r.systematic.has_value());
  EXPECT_NEAR(r.systematic->error, 0.05, 1e-12);
  EXPECT_NEAR(r.systematic->standardError, 0.044402, 1e-5);
  EXPECT_NEAR(r.systematic->halfWidth, 0.088804, 2e-5);
  EXPECT_FALSE(r.systematic->significant);
  EXPECT_FALSE(r.decision.apply);
  EXPECT_EQ(r.decision.correction, 0.0);
  EXPECT_EQ(
      r.decision.reason.rfind("not compensated: the systematic error +0.05 is within its interval +-0.08", 0),
      0u)
      << r.decision.reason;

  o.nominal = 10.2;  // E = +0.2, beyond +-0.0888, process in control: compensate +0.2
  r = analyseSpc(kData, o);
  EXPECT_TRUE(r.systematic->significant);
  EXPECT_TRUE(r.decision.apply);
  EXPECT_NEAR(r.decision.correction, 0.2, 1e-12);
  EXPECT_EQ(
      r.decision.reason.rfind("compensate +0.2: the systematic error (nominal - mean, Eq. 20) is beyond", 0),
      0u)
      << r.decision.reason;
  EXPECT_NE(r.decision.reason.find("in control (3 subgroups of 5)"), std::string::npos) << r.decision.reason;

  o.minCorrection = 0.5;  // the machine cannot apply 0.2
  r = analyseSpc(kData, o);
  EXPECT_FALSE(r.decision.apply);
  EXPECT_NE(r.decision.reason.find("below the smallest correction 0.5"), std::string::npos)
      << r.decision.reason;

  o.minCorrection = 0.0;
  o.coverageFactor = 5.0;  // +-0.222: 0.2 is no longer significant
  r = analyseSpc(kData, o);
  EXPECT_FALSE(r.decision.apply);
}

TEST(Spc, OutOfControlProcessIsNotCompensated) {
  std::vector<double> data = kData;
  for (const double v : {10.35, 10.45, 10.25, 10.35, 10.35}) data.push_back(v);  // subgroup 4: a shift
  SpcOptions o = withSpec();
  o.nominal = 10.3;
  const SpcResult r = analyseSpc(data, o);
  // xbarbar = 10.0875, Rbar = 0.35, limits 10.0875 -+ 0.577 * 0.35 = 9.8856 .. 10.2895: subgroup 4
  // (10.35) is above, subgroup 3 (9.9) just inside.
  EXPECT_NEAR(r.chart.grandMean, 10.0875, 1e-12);
  EXPECT_NEAR(r.chart.xbarUcl, 10.2895, 2e-4);
  EXPECT_NEAR(r.chart.meanRange, 0.35, 1e-12);
  EXPECT_EQ(r.chart.xbarOutOfControl, std::vector<std::size_t>{3});
  EXPECT_TRUE(r.chart.rOutOfControl.empty());
  EXPECT_FALSE(r.chart.inControl());
  EXPECT_TRUE(r.systematic->significant);
  EXPECT_FALSE(r.decision.apply);
  EXPECT_EQ(r.decision.reason,
            "not compensated: the process is out of control (subgroup 4 beyond the X-bar limits); remove the "
            "special "
            "causes first, a correction would chase them");
}

TEST(Spc, RangeBeyondItsLimitIsOutOfControl) {
  // n = 2: D4 = 3.267. Ranges 0.1 x 9 and 2.0 -> Rbar = 0.29, UCL_R = 0.947 < 2.0.
  std::vector<double> data;
  for (int g = 0; g < 9; ++g) {
    data.push_back(5.0);
    data.push_back(5.1);
  }
  data.push_back(4.0);
  data.push_back(6.0);
  SpcOptions o;
  o.subgroupSize = 2;
  const SpcResult r = analyseSpc(data, o);
  EXPECT_EQ(r.chart.rOutOfControl, std::vector<std::size_t>{9});
  EXPECT_NEAR(r.chart.rUcl, 3.26653 * 0.29, 1e-4);
}

TEST(Spc, RegressionLineAndOffsetAngle) {
  // y = 2 x + 1 exactly.
  LineFit f = fitLine({0, 1, 2, 3}, {1, 3, 5, 7});
  EXPECT_NEAR(f.slope, 2.0, 1e-12);
  EXPECT_NEAR(f.intercept, 1.0, 1e-12);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  EXPECT_NEAR(f.slopeStdErr, 0.0, 1e-12);
  EXPECT_NEAR(f.angleDeg, std::atan(2.0) * 180.0 / std::numbers::pi, 1e-12);
  // Hand-computed: x 1..4, y 1, 3, 2, 4: Sxx = 5, Sxy = 4, Syy = 5 -> slope 0.8, intercept 0.5,
  // SSE = 5 - 0.8 * 4 = 1.8, r^2 = 0.64, se(slope) = sqrt(1.8 / 2 / 5) = 0.424264, angle 38.6598 deg.
  f = fitLine({1, 2, 3, 4}, {1, 3, 2, 4});
  EXPECT_NEAR(f.slope, 0.8, 1e-12);
  EXPECT_NEAR(f.intercept, 0.5, 1e-12);
  EXPECT_NEAR(f.r2, 0.64, 1e-12);
  EXPECT_NEAR(f.slopeStdErr, 0.424264, 1e-6);
  EXPECT_NEAR(f.angleDeg, 38.6598, 1e-4);
  EXPECT_EQ(f.points, 4u);
  // A feature series drifting 1 um per part over 20 parts: the trend of analyseSpc sees it.
  std::vector<double> drift;
  for (int i = 1; i <= 20; ++i) drift.push_back(50.0 + 0.001 * i + (i % 2 ? 0.0005 : -0.0005));
  SpcOptions o;
  o.subgroupSize = 4;
  const SpcResult r = analyseSpc(drift, o);
  EXPECT_NEAR(r.trend.slope, 0.001, 1e-4);
  EXPECT_EQ(r.trend.points, 20u);

  EXPECT_THROW(fitLine({1}, {1}), ValidationError);
  EXPECT_THROW(fitLine({1, 1, 1}, {1, 2, 3}), ValidationError);
  EXPECT_THROW(fitLine({1, 2}, {1}), ValidationError);
  EXPECT_THROW(fitLine({1, NAN}, {1, 2}), ValidationError);
}

TEST(Spc, BadInputAndOptions) {
  const ErrorContext where{"f.csv", 0, 0, "d_mm"};
  SpcOptions o;
  o.subgroupSize = 5;
  try {
    analyseSpc({1, 2, 3, 4, 5, 6, 7}, o, where);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "f.csv: field 'd_mm': has 7 values: at least 2 subgroups of 5 (10 values) are needed");
  }
  try {
    analyseSpc(std::vector<double>(10, 3.0), o, where);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv: field 'd_mm': every subgroup has a range of 0"),
              std::string::npos);
  }
  std::vector<double> withNan(10, 1.0);
  withNan[3] = NAN;
  EXPECT_THROW(analyseSpc(withNan, o, where), ValidationError);

  std::string why;
  SpcOptions bad = withSpec();
  bad.lsl = 11.0;
  EXPECT_FALSE(bad.isValid(&why));
  EXPECT_EQ(why, "LSL 11 must be below USL 10.8");
  EXPECT_THROW(analyseSpc(kData, bad), OptionsError);
  bad = withSpec();
  bad.usl.reset();
  EXPECT_FALSE(bad.isValid(&why));
  EXPECT_EQ(why, "give both specification limits (LSL and USL) or neither");
  bad = {};
  bad.subgroupSize = 26;
  EXPECT_FALSE(bad.isValid(&why));
  bad = {};
  bad.coverageFactor = 0.0;
  EXPECT_FALSE(bad.isValid(&why));
  bad = {};
  bad.minCorrection = -1.0;
  EXPECT_FALSE(bad.isValid(&why));

  // A trailing incomplete subgroup is left out and reported.
  std::vector<double> twelve(kData.begin(), kData.begin() + 12);
  const SpcResult r = analyseSpc(twelve, withSpec());
  EXPECT_EQ(r.valuesUsed, 10u);
  EXPECT_EQ(r.valuesIgnored, 2u);
}

TEST(Spc, JsonCarriesLimitsAndIndices) {
  SpcOptions o = withSpec();
  o.nominal = 10.2;
  const nlohmann::json j = spcResultToJson(analyseSpc(kData, o));
  EXPECT_EQ(j["subgroup_size"], 5);
  EXPECT_EQ(j["subgroups"], 3);
  EXPECT_NEAR(j["xbar_chart"]["ucl"].get<double>(), 10.2308, 2e-4);
  EXPECT_NEAR(j["r_chart"]["ucl"].get<double>(), 0.8456, 2e-4);
  EXPECT_EQ(j["xbar_chart"]["points"].size(), 3u);
  EXPECT_NEAR(j["cp"].get<double>(), 1.35683, 1e-3);
  EXPECT_NEAR(j["cpk"].get<double>(), 1.16300, 1e-3);
  EXPECT_NEAR(j["constants"]["A2"].get<double>(), 0.577, 5e-4);
  EXPECT_TRUE(j["in_control"].get<bool>());
  EXPECT_NEAR(j["systematic_error"]["value"].get<double>(), 0.2, 1e-12);
  EXPECT_TRUE(j["compensation"]["apply"].get<bool>());
  for (const char* key :
       {"natural_tolerance", "sigma_within", "sigma_overall", "trend", "pp", "ppk", "nominal"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
}

// Montgomery, Introduction to Statistical Quality Control (Wiley; 6th and 7th editions), Example 6.1 and
// Table 6.3: inside diameters (mm) of forged automobile-engine piston rings, 25 preliminary samples of
// 5. The book prints the subgroup means and ranges, sum xbar_i = 1850.028 (of the means rounded to 3
// decimals), sum R_i = 0.581, and
//   xbarbar = 74.001, Rbar = 0.023, UCL = 74.014, LCL = 73.988 (A2 = 0.577), UCL_R = 0.049 (D4 = 2.114),
//   LCL_R = 0, and every sample in control on both charts.
// The book rounds xbarbar and Rbar to 3 decimals before it computes the limits (74.001 + 0.577 x 0.023
// = 74.01427); from the unrounded 74.001176 and 0.02324 the upper limit is 74.01458, which is 74.015
// to 3 decimals. So the limits are checked to one unit of the book's last digit, and to 1e-5 against
// the same formula with the unrounded centre lines and the table's A2.
const double kPistonRings[25][5] = {
    {74.030, 74.002, 74.019, 73.992, 74.008}, {73.995, 73.992, 74.001, 74.011, 74.004},
    {73.988, 74.024, 74.021, 74.005, 74.002}, {74.002, 73.996, 73.993, 74.015, 74.009},
    {73.992, 74.007, 74.015, 73.989, 74.014}, {74.009, 73.994, 73.997, 73.985, 73.993},
    {73.995, 74.006, 73.994, 74.000, 74.005}, {73.985, 74.003, 73.993, 74.015, 73.988},
    {74.008, 73.995, 74.009, 74.005, 74.004}, {73.998, 74.000, 73.990, 74.007, 73.995},
    {73.994, 73.998, 73.994, 73.995, 73.990}, {74.004, 74.000, 74.007, 74.000, 73.996},
    {73.983, 74.002, 73.998, 73.997, 74.012}, {74.006, 73.967, 73.994, 74.000, 73.984},
    {74.012, 74.014, 73.998, 73.999, 74.007}, {74.000, 73.984, 74.005, 73.998, 73.996},
    {73.994, 74.012, 73.986, 74.005, 74.007}, {74.006, 74.010, 74.018, 74.003, 74.000},
    {73.984, 74.002, 74.003, 74.005, 73.997}, {74.000, 74.010, 74.013, 74.020, 74.003},
    {73.982, 74.001, 74.015, 74.005, 73.996}, {74.004, 73.999, 73.990, 74.006, 74.009},
    {74.010, 73.989, 73.990, 74.009, 74.014}, {74.015, 74.008, 73.993, 74.000, 74.010},
    {73.982, 73.984, 73.995, 74.017, 74.013},
};
// Table 6.3's printed subgroup means and ranges.
const double kPistonMeans[25] = {74.010, 74.001, 74.008, 74.003, 74.003, 73.996, 74.000, 73.997, 74.004,
                                 73.998, 73.994, 74.001, 73.998, 73.990, 74.006, 73.997, 74.001, 74.007,
                                 73.998, 74.009, 74.000, 74.002, 74.002, 74.005, 73.998};
const double kPistonRanges[25] = {0.038, 0.019, 0.036, 0.022, 0.026, 0.024, 0.012, 0.030, 0.014,
                                  0.017, 0.008, 0.011, 0.029, 0.039, 0.016, 0.021, 0.026, 0.018,
                                  0.021, 0.020, 0.033, 0.019, 0.025, 0.022, 0.035};

TEST(Spc, MontgomeryPistonRingsGiveThePublishedLimits) {
  std::vector<double> values;
  for (const auto& sample : kPistonRings) values.insert(values.end(), sample, sample + 5);
  const SpcResult r = analyseSpc(values, SpcOptions{});  // n = 5, every subgroup is the base
  const XbarRChart& c = r.chart;
  ASSERT_EQ(c.subgroups(), 25u);
  double sumRounded = 0.0, sumR = 0.0;
  for (std::size_t i = 0; i < 25; ++i) {
    EXPECT_NEAR(c.means[i], kPistonMeans[i], 0.0005 + 1e-12) << "sample " << i + 1;
    EXPECT_NEAR(c.ranges[i], kPistonRanges[i], 1e-9) << "sample " << i + 1;
    sumRounded += std::round(c.means[i] * 1000.0) / 1000.0;
    sumR += c.ranges[i];
  }
  EXPECT_NEAR(sumRounded, 1850.028, 1e-9);
  EXPECT_NEAR(sumR, 0.581, 1e-9);
  // The published centre lines, to their 3 decimals.
  EXPECT_NEAR(c.grandMean, 74.001, 0.0005);
  EXPECT_NEAR(c.meanRange, 0.023, 0.0005);
  EXPECT_NEAR(c.meanRange, 0.581 / 25.0, 1e-12);
  // The published limits, to one unit of their last digit (the book rounds the centre lines first).
  EXPECT_NEAR(c.xbarUcl, 74.014, 0.001);
  EXPECT_NEAR(c.xbarLcl, 73.988, 0.0005);
  EXPECT_NEAR(c.rUcl, 0.049, 0.0005);
  EXPECT_EQ(c.rLcl, 0.0);
  // The book's arithmetic on its rounded centre lines gives its printed limits.
  EXPECT_NEAR(74.001 + 0.577 * 0.023, 74.014, 0.0005);
  EXPECT_NEAR(74.001 - 0.577 * 0.023, 73.988, 0.0005);
  EXPECT_NEAR(2.114 * 0.023, 0.049, 0.0005);
  // The same formulas on the unrounded centre lines with the table's A2 and D4 (3 decimals: they
  // differ from the exact constants by up to 0.0005, times Rbar 1.2e-5).
  const double xbb = 1850.0294 / 25.0, rbar = 0.02324;
  EXPECT_NEAR(c.grandMean, xbb, 1e-9);
  EXPECT_NEAR(c.xbarUcl, xbb + 0.577 * rbar, 1.2e-5);
  EXPECT_NEAR(c.xbarLcl, xbb - 0.577 * rbar, 1.2e-5);
  EXPECT_NEAR(c.rUcl, 2.114 * rbar, 1.2e-5);
  // "All the points are inside the limits": in control, and no Nelson rule either.
  EXPECT_TRUE(c.inControl());
  EXPECT_TRUE(r.rules.empty());
  EXPECT_EQ(c.baseSubgroups, 25u);
  EXPECT_EQ(c.type, ChartType::XbarR);
}

// Phase I / phase II: subgroups of 4 (table: A2 = 0.729, D3 = 0, D4 = 2.282). The first four
// subgroups are the base:
//   means 10.05, 10.05, 9.95, 9.975 -> xbarbar = 40.025 / 4 = 10.00625
//   ranges 0.3, 0.3, 0.3, 0.4       -> Rbar = 1.3 / 4 = 0.325
//   UCL = 10.00625 + 0.729 x 0.325 = 10.243175, LCL = 9.769325, UCL_R = 2.282 x 0.325 = 0.74165
// Subgroup 5 (mean 10.0, range 0.2) is inside; subgroup 6 has shifted (mean 10.4, range 0.2): beyond
// the UCL, so Nelson rule 1 at subgroup 6 on the X-bar chart and nothing else.
const std::vector<double> kPhases = {10.0, 10.2, 9.9,  10.1, 10.1, 9.9,  10.0, 10.2, 9.8,  10.0, 10.1, 9.9,
                                     10.0, 9.8,  10.2, 9.9,  10.1, 10.0, 9.9,  10.0, 10.4, 10.3, 10.5, 10.4};

TEST(Spc, PhaseTwoIsJudgedAgainstTheLimitsOfTheBase) {
  SpcOptions o;
  o.subgroupSize = 4;
  o.baseSubgroups = 4;
  const SpcResult r = analyseSpc(kPhases, o);
  const XbarRChart& c = r.chart;
  ASSERT_EQ(c.subgroups(), 6u);
  EXPECT_EQ(c.baseSubgroups, 4u);
  EXPECT_NEAR(c.grandMean, 10.00625, 1e-12);
  EXPECT_NEAR(c.meanRange, 0.325, 1e-12);
  // The table's constants have 3 decimals: 0.0005 x 0.325 is the most they can differ by.
  EXPECT_NEAR(c.xbarUcl, 10.243175, 2e-4);
  EXPECT_NEAR(c.xbarLcl, 9.769325, 2e-4);
  EXPECT_NEAR(c.rUcl, 0.74165, 2e-4);
  EXPECT_EQ(c.rLcl, 0.0);
  EXPECT_EQ(c.xbarOutOfControl, std::vector<std::size_t>{5});
  EXPECT_TRUE(c.rOutOfControl.empty());
  ASSERT_EQ(r.rules.size(), 1u);
  EXPECT_EQ(r.rules[0].chart, RuleChart::Mean);
  EXPECT_EQ(r.rules[0].rule, 1);
  EXPECT_EQ(r.rules[0].subgroups, std::vector<std::size_t>{5});
  // The mean of every value (60.425 / 6) is what Cpk, Ppk and the systematic error use.
  EXPECT_NEAR(c.meanOfAll, 60.425 / 6.0, 1e-12);
  const nlohmann::json j = spcResultToJson(r);
  EXPECT_EQ(j["base_subgroups"], 4);
  EXPECT_EQ(j["chart_type"], "xbar-r");
  EXPECT_EQ(j["rules"], nlohmann::json::parse(R"([{"chart": "xbar", "rule": "nelson1", "subgroups": [6]}])"));
  EXPECT_EQ(j["xbar_chart"]["out_of_control"], nlohmann::json::parse("[6]"));
  EXPECT_NEAR(j["mean"].get<double>(), 60.425 / 6.0, 1e-12);
  EXPECT_NEAR(j["xbar_chart"]["center"].get<double>(), 10.00625, 1e-12);

  // With every subgroup as the base the limits are those of all six (xbarbar 10.0708, Rbar 0.28333).
  o.baseSubgroups = 0;
  const SpcResult all = analyseSpc(kPhases, o);
  EXPECT_NEAR(all.chart.grandMean, 60.425 / 6.0, 1e-12);
  EXPECT_NEAR(all.chart.meanRange, 1.7 / 6.0, 1e-12);
  EXPECT_EQ(all.chart.baseSubgroups, 6u);
  // ... and a base of all six subgroups is the default, to the byte.
  o.baseSubgroups = 6;
  EXPECT_EQ(spcResultToJson(analyseSpc(kPhases, o)).dump(), spcResultToJson(all).dump());
}

TEST(Spc, BaseMustBeTwoToTheNumberOfSubgroups) {
  SpcOptions o;
  o.subgroupSize = 4;
  o.baseSubgroups = 1;
  std::string why;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_EQ(why, "the base of the control limits must be 2 or more subgroups, got 1");
  EXPECT_THROW(analyseSpc(kPhases, o), OptionsError);
  o.baseSubgroups = 7;
  try {
    analyseSpc(kPhases, o, ErrorContext{"p.csv", 0, 0, "d_mm"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "p.csv: field 'd_mm': has 6 complete subgroups of 4, fewer than the base of 7 to set control "
              "limits from");
  }
  // A base without variation, although later subgroups vary.
  std::vector<double> flat(8, 10.0);
  flat.insert(flat.end(), {10.0, 10.1, 10.2, 10.3});
  o.baseSubgroups = 2;
  try {
    analyseSpc(flat, o);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("every subgroup of the first 2 has a range of 0"), std::string::npos)
        << e.what();
  }
}

// Individuals and moving range: x = 10.0, 10.2, 10.1, 10.4, 10.2, 10.3, 10.1, 10.2 (the base, K = 8),
// then 11.0 and 10.2.
//   mean of the base = 81.5 / 8 = 10.1875
//   moving ranges 0.2, 0.1, 0.3, 0.2, 0.1, 0.2, 0.1 (subgroups 2..8) -> MRbar = 1.2 / 7 = 0.171429
//   X chart     UCL/LCL = 10.1875 +- 2.66 x 0.171429 = 10.6435 / 9.7315 (published E2 = 2.66; exactly
//               3 / d2(2) = 3 sqrt(pi) / 2 = 2.65868: 10.643274 / 9.731726)
//   MR chart    UCL = 3.267 x 0.171429 = 0.56006 (exactly D4(2) = 1 + 1.5 sqrt(2 pi - 4) = 3.26653:
//               0.559977), LCL = 0; sigma_within = MRbar / d2(2) = 0.171429 / 1.128379 = 0.151924
// Phase II: 11.0 (subgroup 9) is beyond the X chart's UCL (rule 1 on xbar at 9); its moving ranges
// 0.8 (subgroups 9 and 10) are beyond the MR chart's UCL (rule 1 on r at 9, 10), and two of three
// beyond the MR chart's 2 sigma above, 0.171429 + 2 (0.559977 - 0.171429) / 3 = 0.43046 (rule 5 on r
// at 10). Nothing else: the X chart's runs on one side are at most 3 long, and the MR chart's 1-sigma
// excursions below (0.1 < 0.171429 - 0.171429 / 3 = 0.114286) are never four of five.
const std::vector<double> kIndividuals = {10.0, 10.2, 10.1, 10.4, 10.2, 10.3, 10.1, 10.2, 11.0, 10.2};

TEST(Spc, IndividualsAndMovingRange) {
  SpcOptions o;
  o.subgroupSize = 1;
  o.baseSubgroups = 8;
  ASSERT_TRUE(o.isValid(nullptr));
  const SpcResult r = analyseSpc(kIndividuals, o);
  const XbarRChart& c = r.chart;
  EXPECT_EQ(c.type, ChartType::IndividualsMR);
  ASSERT_EQ(c.subgroups(), 10u);
  ASSERT_EQ(c.ranges.size(), 9u);
  EXPECT_NEAR(c.ranges[0], 0.2, 1e-12);  // MR of subgroup 2
  EXPECT_NEAR(c.grandMean, 10.1875, 1e-12);
  const double mrbar = 1.2 / 7.0;
  EXPECT_NEAR(c.meanRange, mrbar, 1e-12);
  // Published constants (3 significant digits) ...
  EXPECT_NEAR(c.xbarUcl, 10.1875 + 2.66 * mrbar, 3e-4);
  EXPECT_NEAR(c.xbarLcl, 10.1875 - 2.66 * mrbar, 3e-4);
  EXPECT_NEAR(c.rUcl, 3.267 * mrbar, 1e-4);
  // ... and their closed forms for a range of two: d2 = 2 / sqrt(pi), D4 = 1 + 1.5 sqrt(2 pi - 4).
  const double d2 = 2.0 / std::sqrt(std::numbers::pi);
  EXPECT_NEAR(c.xbarUcl, 10.1875 + 3.0 / d2 * mrbar, 1e-6);
  EXPECT_NEAR(c.xbarLcl, 10.1875 - 3.0 / d2 * mrbar, 1e-6);
  EXPECT_NEAR(c.rUcl, (1.0 + 1.5 * std::sqrt(2.0 * std::numbers::pi - 4.0)) * mrbar, 1e-6);
  EXPECT_EQ(c.rLcl, 0.0);
  EXPECT_NEAR(r.capability.sigmaWithin, mrbar / d2, 1e-6);
  EXPECT_EQ(r.constants.n, 2);  // the constants of the moving range's span
  EXPECT_NEAR(r.constants.E2, 3.0 / d2, 1e-6);
  EXPECT_EQ(r.valuesUsed, 10u);
  EXPECT_EQ(r.valuesIgnored, 0u);
  EXPECT_EQ(c.xbarOutOfControl, std::vector<std::size_t>{8});
  EXPECT_EQ(c.rOutOfControl, (std::vector<std::size_t>{8, 9}));

  const nlohmann::json j = spcResultToJson(r);
  EXPECT_EQ(j["chart_type"], "x-mr");
  EXPECT_EQ(j["subgroup_size"], 1);
  EXPECT_EQ(j["base_subgroups"], 8);
  EXPECT_EQ(j["r_chart"]["first_subgroup"], 2);
  EXPECT_EQ(j["r_chart"]["points"].size(), 9u);
  EXPECT_EQ(j["xbar_chart"]["points"].size(), 10u);
  EXPECT_NEAR(j["constants"]["E2"].get<double>(), 2.66, 0.0015);  // printed 3 / 1.128; exactly 2.65868
  EXPECT_EQ(j["rules"], nlohmann::json::parse(R"([
      {"chart": "xbar", "rule": "nelson1", "subgroups": [9]},
      {"chart": "r", "rule": "nelson1", "subgroups": [9, 10]},
      {"chart": "r", "rule": "nelson5", "subgroups": [10]}])"));
  EXPECT_EQ(j["r_chart"]["out_of_control"], nlohmann::json::parse("[9, 10]"));

  // Too few values, and no variation between consecutive values.
  o.baseSubgroups = 0;
  try {
    analyseSpc({5.0}, o, ErrorContext{"i.csv", 0, 0, "x"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "i.csv: field 'x': has 1 value: at least 2 are needed for a moving range");
  }
  try {
    analyseSpc({5.0, 5.0, 5.0}, o);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("every moving range is 0"), std::string::npos) << e.what();
  }
  // n = 0 stays invalid.
  o.subgroupSize = 0;
  EXPECT_FALSE(o.isValid(nullptr));
}

TEST(Spc, JsonListsRulesAlwaysAndKeepsItsKeys) {
  const nlohmann::json j = spcResultToJson(analyseSpc(kData, withSpec()));
  ASSERT_TRUE(j.contains("rules"));
  EXPECT_TRUE(j["rules"].is_array());
  EXPECT_TRUE(j["rules"].empty());
  EXPECT_EQ(j["chart_type"], "xbar-r");
  EXPECT_EQ(j["base_subgroups"], 3);
  EXPECT_EQ(j["r_chart"]["first_subgroup"], 1);
  EXPECT_FALSE(j["constants"].contains("E2"));
  for (const char* key : {"subgroup_size",
                          "subgroups",
                          "values_used",
                          "values_ignored",
                          "constants",
                          "xbar_chart",
                          "r_chart",
                          "in_control",
                          "mean",
                          "sigma_within",
                          "sigma_overall",
                          "natural_tolerance",
                          "lsl",
                          "usl",
                          "cp",
                          "cpk",
                          "pp",
                          "ppk",
                          "trend",
                          "compensation"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["mean"].get<double>(), 10.0, 1e-12);
}

}  // namespace
}  // namespace metrofit
