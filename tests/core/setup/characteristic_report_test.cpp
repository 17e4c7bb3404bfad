// A Q-DAS DFQ file as the setup's CMM report series (core/setup/report.h 3., core/io/cmm_text_report.h
// 4.): the file is written here from the AQDEF field list; the expected deviations are the values minus
// the nominal, worked out by hand.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/setup/report.h"
#include "setup_fixtures.h"
#include "testsupport.h"

namespace metrofit::setup {
namespace {

using metrofit::test::near;

// D1 (label POS_D1: K2001 number), D2 (label "Bohrung 18,5": the K2002 description, with a decimal
// comma). Three workpieces named by K0014; the second D2 value removed (attribute 255).
const std::string kDfq =
    "K0100 2\r\nK1001/1 4711\r\nK2022/0 3\r\n"
    "K2001/1 POS_D1\r\nK2002/1 Position\r\nK2101/1 42\r\nK2110/1 41.98\r\nK2111/1 42.02\r\n"
    "K2001/2 7\r\nK2002/2 Bohrung 18,5\r\nK2101/2 18.5\r\nK2110/2 18.45\r\nK2111/2 18.53\r\n"
    "K0001/1 42.004\r\nK0001/2 18.51\r\nK0014/0 SN-1\r\n"
    "K0001/1 42.008\r\nK0001/2 18.60\r\nK0002/2 255\r\nK0014/0 SN-2\r\n"
    "K0001/1 42.000\r\nK0001/2 18.52\r\nK0014/0 SN-3\r\n";

Model model(const std::string& d2Label) {
  nlohmann::json j = test::smallModelJson();
  j["dimensions"][1]["label"] = d2Label;
  return modelFromJson(j, "m.json");
}

TEST(CharacteristicReport, DfqDimensionsByNumberOrDescriptionRemovedValuesLeftOut) {
  const CmmTextReport r = cmmTextReportFromText(kDfq, "s.dfq");
  for (const std::string label : {"Bohrung 18,5", "7", "bohrung 18,5"}) {
    const Measurements m = cmmTextReportMeasurements(r, model(label));
    EXPECT_EQ(m.parts, (std::vector<std::string>{"SN-1", "SN-2", "SN-3"})) << label;
    EXPECT_EQ(m.samples, (std::vector<int>{3, 2})) << label;
    EXPECT_TRUE(near(m.deviationMm[0], (0.004 + 0.008 + 0.000) / 3, 1e-12)) << label;
    EXPECT_TRUE(near(m.deviationMm[1], (0.01 + 0.02) / 2, 1e-12)) << label;  // 18.60 removed
  }
}

TEST(CharacteristicReport, DfqDatesGiveTimeMinFromTheFirstPart) {
  std::string text = kDfq;
  for (const auto& [serial, time] : {std::pair<std::string, std::string>{"SN-1", "14.03.2024/08:00:00"},
                                     {"SN-2", "14.03.2024/08:12:30"},
                                     {"SN-3", "14.03.2024/09:00:00"}}) {
    const std::string field = "K0014/0 " + serial + "\r\n";
    text.insert(text.find(field) + field.size(), "K0004/0 " + time + "\r\n");
  }
  const Measurements m = cmmTextReportMeasurements(cmmTextReportFromText(text, "s.dfq"), model("7"));
  ASSERT_EQ(m.rows.size(), 5u);
  EXPECT_EQ(m.rows[0].timeMin, 0.0);
  EXPECT_EQ(m.rows[2].timeMin, 12.5);  // SN-2, D1 (its D2 removed)
  EXPECT_EQ(m.rows[3].timeMin, 60.0);
}

TEST(CharacteristicReport, CalypsoChrWithTheHeaderFileBesideIt) {
  metrofit::test::TempDir tmp;
  metrofit::test::writeText(tmp.file("plan_chr.txt"),
                            "planid\tpartnb\tid\tactual\tnominal\tuppertol\tlowertol\r\n"
                            "plan\t11\tPOS_D1\t42,0040\t42,0000\t0,0200\t-0,0200\r\n"
                            "plan\t11\tD2\t18,5100\t18,5000\t0,0300\t-0,0500\r\n"
                            "plan\t12\tPOS_D1\t42,0080\t42,0000\t0,0200\t-0,0200\r\n"
                            "plan\t12\tD2\t18,5300\t18,5000\t0,0300\t-0,0500\r\n");
  metrofit::test::writeText(tmp.file("plan_hdr.txt"),
                            "planid\tpartnb\tdate\ttime\r\nplan\t11\t14.03.2024\t08:00:00\r\n"
                            "plan\t12\t14.03.2024\t08:45:00\r\n");
  const Measurements m = readMeasurements({tmp.file("plan_chr.txt")}, model("D2"));
  EXPECT_EQ(m.parts, (std::vector<std::string>{"11", "12"}));
  ASSERT_EQ(m.rows.size(), 4u);
  EXPECT_EQ(m.rows[0].timeMin, 0.0);
  EXPECT_EQ(m.rows[3].timeMin, 45.0);
  EXPECT_TRUE(near(m.deviationMm[0], 0.006, 1e-12));
  EXPECT_TRUE(near(m.deviationMm[1], 0.02, 1e-12));
}

TEST(CharacteristicReport, LimitsThatDisagreeWithTheModelAreNamedWithTheirLine) {
  std::string text = kDfq;
  text.replace(text.find("K2111/2 18.53"), 13, "K2111/2 18.54");
  try {
    (void)cmmTextReportMeasurements(cmmTextReportFromText(text, "s.dfq"), model("7"));
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("s.dfq:15"), std::string::npos) << e.what();  // the value's line
    EXPECT_NE(std::string(e.what()).find("differs from the model's limits"), std::string::npos) << e.what();
  }
  // Two characteristics with one description: the label must use the number.
  text = kDfq;
  text.replace(text.find("K2002/1 Position"), 16, "K2002/1 Bohrung 18,5");
  try {
    (void)cmmTextReportMeasurements(cmmTextReportFromText(text, "s.dfq"), model("Bohrung 18,5"));
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("name one by its number '7'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace metrofit::setup
