// SPC (IEEE Access, kinematic compensation algorithm, Section IV.A): chart constants against the published
// table, X-bar/R limits, Cp/Cpk/Pp/Ppk, natural tolerance (Eq. 17), systematic error (Eq. 20), regression
// line and offset angle (Fig. 10), the SPC gate, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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

}  // namespace
}  // namespace metrofit
