// Zeiss Calypso table files (core/io/calypso.h), written here as Calypso's table export lays them out
// (tab-separated, the column names planid, partnb, id, type, idsymbol, actual, nominal, uppertol, lowertol,
// deviation, ... for _chr; x y z, x_nom y_nom z_nom, nx ny nz for _fet; decimal commas as a German
// Windows writes them); the expected values are read off the texts by hand.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "core/io/calypso.h"
#include "core/io/cmm_text_report.h"
#include "testsupport.h"

namespace metrofit {
namespace {

const std::string kChr =
    "planid\tpartnb\tid\ttype\tidsymbol\tactual\tnominal\tuppertol\tlowertol\tdeviation\texceed\r\n"
    "Flansch\t1\tDurchmesser_B1\tDiameter\t\xC3\x98\t12,5030\t12,5000\t0,0200\t-0,0100\t0,0030\t0\r\n"
    "Flansch\t1\tAbstand_E1\tDistance\t\t40,0120\t40,0000\t0,0500\t-0,0500\t0,0120\t0\r\n"
    "Flansch\t1\tEbenheit_E1\tFlatness\t\t0,0042\t0,0000\t0,0100\t0,0000\t0,0042\t0\r\n"
    "Flansch\t2\tDurchmesser_B1\tDiameter\t\xC3\x98\t12,4990\t12,5000\t0,0200\t-0,0100\t-0,0010\t0\r\n"
    "Flansch\t2\tAbstand_E1\tDistance\t\t40,0080\t40,0000\t0,0500\t-0,0500\t0,0080\t0\r\n"
    "Flansch\t2\tEbenheit_E1\tFlatness\t\t0,0051\t0,0000\t0,0100\t0,0000\t0,0051\t0\r\n";

TEST(Calypso, CharacteristicsWithDecimalCommasAndTabs) {
  ASSERT_TRUE(looksLikeCalypsoCharacteristics(kChr));
  EXPECT_FALSE(looksLikeCalypsoFeatures(kChr));
  const CalypsoCharacteristics t = calypsoCharacteristicsFromText(kChr, "f_chr.txt");
  ASSERT_EQ(t.rows.size(), 6u);
  EXPECT_EQ(t.parts, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(t.rows[0].id, "Durchmesser_B1");
  EXPECT_EQ(t.rows[0].idSymbol, "\xC3\x98");
  EXPECT_EQ(t.rows[0].actual, 12.503);
  EXPECT_EQ(*t.rows[0].nominal, 12.5);
  EXPECT_EQ(*t.rows[0].upperTol, 0.02);
  EXPECT_EQ(*t.rows[0].lowerTol, -0.01);
  EXPECT_EQ(*t.rows[3].deviation, -0.001);
  EXPECT_EQ(t.rows[3].line, 5);
  EXPECT_DOUBLE_EQ(t.rows[0].rounding, 0.00005);
  // As a report: one run per partnb, one feature per characteristic.
  const CmmTextReport r = cmmTextReportFromText(kChr, "f_chr.txt");
  EXPECT_EQ(r.format, CmmReportFormat::Calypso);
  ASSERT_EQ(r.runs.size(), 2u);
  EXPECT_EQ(r.runs[1].serial, "2");
  EXPECT_EQ(r.runs[0].routine, "Flansch");
  ASSERT_EQ(r.runs[1].features.size(), 3u);
  EXPECT_EQ(r.runs[1].features[1].label, "Abstand_E1");
  EXPECT_EQ(r.runs[1].features[1].values[0].actual, 40.008);
  // The feature table: one row per part, a column per characteristic.
  const CsvTable ft = cmmReportFeatureTable(r);
  EXPECT_EQ(ft.numericColumn("Abstand_E1.actual"), (std::vector<double>{40.012, 40.008}));
}

TEST(Calypso, PointDecimalsAndSemicolonsToo) {
  const std::string text = "planid;partnb;id;actual;nominal\nP;7;L1;10.25;10.2\n";
  const CalypsoCharacteristics t = calypsoCharacteristicsFromText(text, "s_chr.txt");
  EXPECT_EQ(t.rows[0].actual, 10.25);
  EXPECT_EQ(*t.rows[0].nominal, 10.2);
  EXPECT_FALSE(t.rows[0].upperTol.has_value());
}

TEST(Calypso, HeaderFileBesideGivesTheDates) {
  test::TempDir dir;
  test::writeText(dir.file("flansch_chr.txt"), kChr);
  test::writeText(dir.file("flansch_hdr.txt"),
                  "planid\tpartnb\tdate\ttime\toperid\r\nFlansch\t1\t14.03.2024\t08:15:30\tmk\r\n"
                  "Flansch\t2\t14.03.2024\t08:21:05\tmk\r\n");
  const CalypsoCharacteristics t = readCalypsoCharacteristics(dir.file("flansch_chr.txt"));
  EXPECT_EQ(t.dates, (std::vector<std::string>{"14.03.2024 08:15:30", "14.03.2024 08:21:05"}));
  const CmmTextReport r = readCmmTextReport(dir.file("flansch_chr.txt"));
  EXPECT_EQ(r.runs[1].dateTime, "14.03.2024 08:21:05");
}

std::string errorOf(const std::string& text) {
  try {
    (void)calypsoCharacteristicsFromText(text, "b_chr.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Calypso, ErrorsNameFileLineAndColumn) {
  const std::string head = "planid\tpartnb\tid\tactual\tnominal\tdeviation\n";
  EXPECT_EQ(errorOf(head + "P\t1\tD1\t12,5x\t12\t0\n"),
            "b_chr.txt:2:4: field 'actual': '12,5x' is not a number");
  EXPECT_EQ(errorOf(head + "P\t1\tD1\t12,5\t12\t0,3\n"),
            "b_chr.txt:2:6: field 'deviation': deviation 0.3 of 'D1' is not actual - nominal = 0.5");
  EXPECT_EQ(errorOf(head + "P\t1\tD1\t1,2.5\t12\t0\n"),
            "b_chr.txt:2:4: field 'actual': '1,2.5' is not a number");
  EXPECT_EQ(errorOf(head + "P\t1\tD1\t\t12\t0\n"), "b_chr.txt:2:4: field 'actual': a number is missing");
  EXPECT_EQ(errorOf(head + "P\t1\tD1\t1\t1\t0\t9\t9\n"), "b_chr.txt:2:7: the row has 8 cells, the header 6");
  EXPECT_EQ(errorOf("planid\tpartnb\tid\tnominal\n"),
            "b_chr.txt:1: field 'actual': missing column 'actual' "
            "(the file has: planid, partnb, id, nominal)");
}

const std::string kFet =
    "planid\tpartnb\tid\ttype\tx\ty\tz\tx_nom\ty_nom\tz_nom\tnx\tny\tnz\r\n"
    "Flansch\t1\tPkt1\tPoint\t10,0030\t0,0000\t5,0000\t10,0000\t0,0000\t5,0000\t1,0000\t0,0000\t0,0000\r\n"
    "Flansch\t1\tPkt2\tPoint\t0,0000\t20,0021\t5,0000\t0,0000\t20,0000\t5,0000\t0,0000\t1,0000\t0,0000\r\n"
    "Flansch\t1\tPkt3\tPoint\t-10,0010\t0,0000\t5,0000\t-10,0000\t0,0000\t5,0000\t-1,0000\t0,0000\t0,0000\r\n"
    "Flansch\t1\tPkt4\tPoint\t5,0000\t5,0000\t10,0040\t5,0000\t5,0000\t10,0000\t0,0000\t0,0000\t0,9999\r\n";

TEST(Calypso, FeaturesAsProbePoints) {
  ASSERT_TRUE(looksLikeCalypsoFeatures(kFet));
  EXPECT_FALSE(looksLikeCalypsoCharacteristics(kFet));
  EXPECT_FALSE(looksLikeCmmTextReport(kFet));
  const CsvTable t = calypsoFeaturesProbeTable(kFet, "f_fet.txt");
  EXPECT_EQ(t.header(), (std::vector<std::string>{"id", "surface", "qx", "qy", "qz", "nx", "ny", "nz", "px",
                                                  "py", "pz"}));
  ASSERT_EQ(t.rowCount(), 4u);
  EXPECT_EQ(t.cell(0, 0), "Pkt1");
  EXPECT_EQ(t.cell(0, 1), "Point");
  EXPECT_EQ(t.numericColumn("px")[0], 10.003);
  EXPECT_EQ(t.numericColumn("qx")[2], -10.0);
  EXPECT_EQ(t.numericColumn("nz")[3], 1.0);  // 0.9999 made unit length
  EXPECT_EQ(t.lineOf(3), 5);
  // Several measured parts: refused, naming the line.
  const std::string two = kFet + "Flansch\t2\tPkt1\tPoint\t1\t0\t0\t1\t0\t0\t1\t0\t0\r\n";
  try {
    (void)calypsoFeaturesProbeTable(two, "f_fet.txt");
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("f_fet.txt:6:2: field 'partnb'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace metrofit
