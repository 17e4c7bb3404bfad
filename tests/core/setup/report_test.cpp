// Measurement reports of the setup correction (core/setup/report.h): the CMM CSV and DMIS output.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/setup/report.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

const char* kHeader = "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n";

Measurements csv(const std::string& body) {
  return cmmReportFromCsv(parseCsv(std::string(kHeader) + body, "r.csv"), test::smallModel());
}

std::string csvError(const std::string& body) {
  try {
    (void)csv(body);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string dmisError(const std::string& text) {
  try {
    (void)dmisReportFromText(text, "p.dmo", test::smallModel());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SetupReport, CsvMeanDeviationOverParts) {
  const Measurements m =
      csv("1,10,D1,42,42.010,-0.02,0.02\n"
          "1,10,D2,18.5,18.49,-0.05,0.03\n"
          "2,20,D1,42,42.004,-0.02,0.02\n"
          "2,20,D2,18.5,18.5,-0.05,0.03\n"
          "3,30,D1,42,41.999,-0.02,0.02\n");
  EXPECT_EQ(m.parts, (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(m.samples, (std::vector<int>{3, 2}));
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[0], (0.010 + 0.004 - 0.001) / 3.0, 1e-12));
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[1], -0.005, 1e-12));
  EXPECT_EQ(m.rows.size(), 5u);
  EXPECT_EQ(m.rows[4].line, 6);
  EXPECT_DOUBLE_EQ(m.rows[4].timeMin, 30.0);
}

TEST(SetupReport, CsvErrorsNameLineAndField) {
  EXPECT_EQ(csvError("1,10,D9,42,42.010,-0.02,0.02\n"),
            "r.csv:2:3: field 'dimension': unknown dimension 'D9' (not in the model m.json)");
  EXPECT_EQ(csvError("1,10,D1,42,42.010,-0.03,0.02\n"),
            "r.csv:2:6: field 'lower_tol_mm': -0.03 differs from the model's lower limit -0.02 of 'D1'");
  EXPECT_EQ(csvError("1,10,D1,42,42.010,-0.02,0.025\n"),
            "r.csv:2:7: field 'upper_tol_mm': 0.025 differs from the model's upper limit 0.02 of 'D1'");
  EXPECT_EQ(csvError("1,10,D1,42.1,42.010,-0.02,0.02\n"),
            "r.csv:2:4: field 'nominal_mm': 42.1 differs from the model's nominal 42 of 'D1'");
  EXPECT_EQ(csvError("1,10,D1,42,42.010,0.02,0.02\n"),
            "r.csv:2:6: field 'lower_tol_mm': lower limit 0.02 is not below upper limit 0.02");
  EXPECT_EQ(csvError("1,10,D1,42,abc,-0.02,0.02\n"), "r.csv:2:5: field 'measured_mm': 'abc' is not a number");
  EXPECT_EQ(
      csvError("1,10,D1,42,42.01,-0.02,0.02\n2,10,D2,18.5,18.5,-0.05,0.03\n1,11,D1,42,42.01,-0.02,0.02\n"),
      "r.csv:4:3: field 'dimension': duplicate row for part '1' and dimension 'D1' (first on line 2)");
  EXPECT_EQ(
      csvError("1,10,D1,42,42.01,-0.02,0.02\n"),
      "r.csv: field 'dimension': the report has no measurement of dimension 'D2' of the model (m.json)");
  try {
    (void)cmmReportFromCsv(parseCsv("part,dimension,measured_mm\n1,D1,3\n", "short.csv"), test::smallModel());
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("short.csv: field 'time_min': missing column", 0), 0u) << e.what();
  }
}

TEST(SetupReport, DmisTestFile) {
  const std::string path = (metrofit::test::sourceDir() / "tests/core/setup/data/part_17.dmo").string();
  const Measurements m = readDmisReport(path, test::smallModel());
  EXPECT_EQ(m.parts, std::vector<std::string>{"PART-17"});
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[0], 0.013, 1e-12));   // FA(POS_D1) - F(POS_D1) along Z
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[1], -0.021, 1e-12));  // TA(D2)
  EXPECT_EQ(m.rows[0].line, 11);                                       // FA(pos_d1), continued on 12
  EXPECT_EQ(m.rows[1].line, 15);
  EXPECT_TRUE(looksLikeDmis(metrofit::test::readText(path)));
  EXPECT_FALSE(looksLikeDmis(kHeader));
}

TEST(SetupReport, DmisUnitsCortolAndPriority) {
  // INCH: values convert to mm; CORTOL along the model's axis; F and FA win over TA for the same label
  // (shared/data/real/README.md: where F and FA are present, the deviation is computed from them).
  const std::string text =
      "DMISMN/'x',05.0\n"
      "UNITS/INCH,ANGDEG\n"
      "F(POS_D1)=FEAT/POINT,CART,0,0,1.0\n"
      "FA(POS_D1)=FEAT/POINT,CART,0,0,1.001\n"
      "TA(POS_D1)=TOL/CORTOL,ZAXIS,0.0002,INTOL\n"
      "T(D2)=TOL/CORTOL,ZAXIS,-0.05,0.03\n"  // inch limits: differ from the model's mm limits
      "TA(D2)=TOL/CORTOL,ZAXIS,-0.0004\n";
  EXPECT_EQ(
      dmisError(text),
      "p.dmo:6: field 'T(D2)': tolerance -1.27 / 0.762 differs from the model's limits -0.05 / 0.03 of 'D2'");
  const std::string inchLimits = "T(D2)=TOL/CORTOL,ZAXIS,-0.05,0.03";
  std::string ok = text;
  ok.replace(ok.find(inchLimits), inchLimits.size(), "T(D2)=TOL/CORTOL,ZAXIS,-0.0019685,0.0011811");
  const Measurements m = dmisReportFromText(ok, "p.dmo", test::smallModel());
  EXPECT_EQ(m.parts, std::vector<std::string>{"p.dmo"});
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[0], 0.001 * 25.4, 1e-12));
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[1], -0.0004 * 25.4, 1e-12));
}

TEST(SetupReport, DmisErrors) {
  const std::string head = "DMISMN/'x',05.0\nTA(D2)=TOL/DISTB,-0.01,INTOL\n";
  EXPECT_EQ(dmisError(head + "FA(POS_D1)=FEAT/PLANE,POL,1,2,3\n"),
            "p.dmo:3: field 'FA(POS_D1)': polar (POL) coordinates are not supported; use CART");
  EXPECT_EQ(dmisError(head + "TA(POS_D1)=TOL/DISTB,abc,INTOL\n"),
            "p.dmo:3: field 'TA(POS_D1)': deviation: 'abc' is not a number");
  EXPECT_EQ(dmisError(head + "TA(POS_D1)=TOL/FLAT,0.01\n"),
            "p.dmo:3: field 'TA(POS_D1)': tolerance type 'FLAT' is not supported for a dimension (use DISTB, "
            "DISTWRT, DIAM, RAD, WIDTH, CORTOL or PROFP)");
  EXPECT_EQ(dmisError(head + "TA(POS_D1)=TOL/CORTOL,XAXIS,0.01\n"),
            "p.dmo:3: field 'TA(POS_D1)': CORTOL along 'XAXIS' but the model's axis is Z");
  EXPECT_EQ(
      dmisError(head + "FA(POS_D1)=FEAT/PLANE,CART,1,2,3,0,0,1\n"),
      "p.dmo:3: field 'FA(POS_D1)': feature actual without its nominal F(POS_D1) and without a tolerance "
      "actual TA(POS_D1)");
  EXPECT_EQ(dmisError(head + "TA(D2)=TOL/DISTB,-0.02,INTOL\n"),
            "p.dmo:3: field 'TA(D2)': duplicate TA statement for 'D2' (first on line 2)");
  EXPECT_EQ(dmisError(head),
            "p.dmo: field 'dimension': the report has no measurement of dimension 'D1' (label "
            "'POS_D1') of the model (m.json)");
  EXPECT_EQ(dmisError(head + "UNITS/FURLONG\n"), "p.dmo:3: field 'UNITS': unknown length unit 'FURLONG'");
  EXPECT_EQ(dmisError(head + "TA(POS_D1)=TOL/DISTB,0.01,@\n"),
            "p.dmo:3: the last statement ends in '@' (continuation) but the file ends");
}

TEST(SetupReport, MergeCsvAndDmis) {
  metrofit::test::TempDir tmp;
  const std::string dmo = (metrofit::test::sourceDir() / "tests/core/setup/data/part_17.dmo").string();
  metrofit::test::writeText(tmp.file("r.csv"), std::string(kHeader) +
                                                   "1,10,D1,42,42.010,-0.02,0.02\n"
                                                   "1,10,D2,18.5,18.49,-0.05,0.03\n");
  const Measurements m = readMeasurements({tmp.file("r.csv"), dmo}, test::smallModel());
  EXPECT_EQ(m.parts, (std::vector<std::string>{"1", "PART-17"}));
  EXPECT_EQ(m.sources.size(), 2u);
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[0], (0.010 + 0.013) / 2.0, 1e-12));
  EXPECT_TRUE(metrofit::test::near(m.deviationMm[1], (-0.010 - 0.021) / 2.0, 1e-12));
  try {
    (void)readMeasurements({dmo, dmo}, test::smallModel());
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              dmo + ":11: field 'part': part 'PART-17', dimension 'D1' is measured twice (first in " + dmo +
                  " line 11)");
  }
}

}  // namespace
}  // namespace metrofit::setup
