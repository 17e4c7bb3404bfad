// CMM text reports as project datasets (core/project/datasets.h) and as probe points
// (core/matching/hole_table.h, probePointsFromCmmReport).
//
// PC-DMIS: no real file is available; the report below is written from the PC-DMIS help
// (Hexagon, "Dimension Command Format", PC-DMIS 2019 R1: "dimension_name = TYPE OF DIMENSION,
// feat_1 UNITS=...,$", the AX / NOM / +TOL / -TOL / MEAS / DEV / OUT-TOL columns, "END OF DIMENSION";
// "To Dimension a Feature Using the LOCATION Option", 2021.2: a circle's default axes are X, Y, D),
// not from a Metrofit writer. OGP: the real files of ../shared/data/real/cmm-ogp-hps-svt (GPL-3.0),
// read in place; those checks skip when the folder is not there.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/matching/hole_table.h"
#include "core/project/datasets.h"
#include "testsupport.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;

// Three bores of a plate, LOCATION dimensions with X, Y and D.
const char* kPlate =
    "PART NAME  : PLATE-7\n"
    "\n"
    "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "X      10.000      0.050      0.050     10.012      0.012      0.000 ----#----\n"
    "Y      20.000      0.050      0.050     19.991     -0.009      0.000 ----#----\n"
    "D       6.000      0.020      0.020      6.011      0.011      0.000 -----#---\n"
    "END OF DIMENSION LOC1\n"
    "DIM LOC2= LOCATION OF CIRCLE CIR2  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "X      60.000      0.050      0.050     60.021      0.021      0.000 ----#----\n"
    "Y      20.000      0.050      0.050     20.004      0.004      0.000 ----#----\n"
    "D       6.000      0.020      0.020      5.996     -0.004      0.000 ---#-----\n"
    "END OF DIMENSION LOC2\n"
    "DIM LOC3= LOCATION OF CIRCLE CIR3  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "X      35.000      0.050      0.050     34.987     -0.013      0.000 ---#-----\n"
    "Y      50.000      0.050      0.050     50.016      0.016      0.000 -----#---\n"
    "D      10.000      0.020      0.020     10.005      0.005      0.000 ----#----\n"
    "END OF DIMENSION LOC3\n";

TEST(CmmTextDataset, PcDmisLocationsAreProbePoints) {
  const std::string path = (test::outDir() / "pcdmis_plate.txt").string();
  test::writeText(path, kPlate);
  const ProbePointSet set = readProbePointsAnyFormat(path);
  ASSERT_EQ(set.points.size(), 3u);
  EXPECT_TRUE(set.planar);
  EXPECT_FALSE(set.hasNormals);
  EXPECT_EQ(set.points[0].id, "LOC1");
  EXPECT_EQ(set.points[0].surface, "circle D6");
  EXPECT_EQ(set.points[2].surface, "circle D10");
  EXPECT_DOUBLE_EQ(set.points[1].nominal.x(), 60.0);
  EXPECT_DOUBLE_EQ(set.points[1].measured.x(), 60.021);
  EXPECT_DOUBLE_EQ(set.points[2].measured.y(), 50.016);
  // The "before" deviation of a position-only point is its distance: |(0.012, -0.009)| = 0.015.
  EXPECT_NEAR(set.deviations()[0], 0.015, 1e-12);

  // One of them with a Z and the others without: an error naming that line.
  std::string mixed = kPlate;
  mixed.replace(mixed.find("D      10.000"), 1, "Z");
  test::writeText(path, mixed);
  try {
    (void)readProbePointsAnyFormat(path);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("pcdmis_plate.txt:3:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("all planar or all 3-D"), std::string::npos) << e.what();
  }
  // A bad row: one line, the file and its line.
  std::string bad = kPlate;
  bad.replace(bad.find("20.004      0.004"), 17, "20.004      0.014");
  test::writeText(path, bad);
  try {
    (void)readProbePointsAnyFormat(path);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("pcdmis_plate.txt:14:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is not MEAS - NOMINAL"), std::string::npos) << e.what();
  }
}

fs::path ogp(const std::string& rel) {
  return test::realData("cmm-ogp-hps-svt/survey_data/" + rel);
}

TEST(CmmTextDataset, ReportsAreAddedAsTheirKindsWithoutOptions) {
  const fs::path summary = ogp("L123_fixture_sho.txt");
  const fs::path rtf = ogp("meas1/L1_axial_top_module3_1.txt");
  METROFIT_REQUIRE_PATH(summary);
  const std::string projectPath = (test::outDir() / "cmm_text" / "P.metrofit").string();
  fs::create_directories(fs::path(projectPath).parent_path());
  Project project;
  DatasetRef series =
      addDataset(project, projectPath, {"feature-series", summary.string(), "fixture", {}, ""});
  DatasetRef report = addDataset(project, projectPath, {"cmm-report", rtf.string(), "", {}, ""});
  EXPECT_EQ(report.id, "L1_axial_top_module3_1");
  const DatasetSummary s = summarizeDataset(projectPath, series);
  EXPECT_EQ(s.rows, 13);  // 13 runs
  EXPECT_EQ(s.columns.at(0), "run");
  const CsvTable t = readDatasetTable(projectPath, series);
  EXPECT_EQ(t.rowCount(), 13u);
  EXPECT_DOUBLE_EQ(t.numericColumn("step16.x_location.dev")[0], 252.856 - 252.829);
  // The step report: its values with a nominal (every value under "Actual Nominal Upper Lower").
  const DatasetSummary r = summarizeDataset(projectPath, report);
  EXPECT_GT(r.rows, 0);
  // A truncated copy is refused when added, with the file and the line.
  const std::string raw = test::readText(rtf.string());
  const std::string cut = (test::outDir() / "cmm_text" / "cut.txt").string();
  test::writeText(cut, raw.substr(0, raw.size() * 2 / 3));
  try {
    (void)addDataset(project, projectPath, {"cmm-report", cut, "", {}, ""});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.txt:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  EXPECT_EQ(project.datasets.size(), 2u);
}

}  // namespace
}  // namespace metrofit
