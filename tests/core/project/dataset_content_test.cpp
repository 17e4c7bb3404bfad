// core/project/dataset_content.h: a dataset read for the "Show data" table. Files written here (a
// PC-DMIS report in inches, DMIS in inches with OUTOL, a hole table, units in column names), the
// demo's setup model and report series (resources/demo), and the REAL OGP summary report of 13 runs
// ../shared/data/real/cmm-ogp-hps-svt/survey_data/L123_fixture_sho.txt (GPL-3.0, read in place as
// cmm_text_dataset_test.cpp does; skipped when it is not there).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/common/error.h"
#include "core/project/dataset_content.h"
#include "testsupport.h"

namespace metrofit {
namespace {

DatasetRef datasetOf(const char* kind, const std::string& path) {
  DatasetRef d;
  d.id = "d";
  d.kind = kind;
  d.path = path;
  return d;
}

TEST(DatasetContent, ColumnUnitsFromRoleSuffixesAndBrackets) {
  EXPECT_EQ(columnDisplayUnit("disp_z_um"), "µm");
  EXPECT_EQ(columnDisplayUnit("t1_degC"), "°C");
  EXPECT_EQ(columnDisplayUnit("spindle_rpm"), "1/min");
  EXPECT_EQ(columnDisplayUnit("angle_deg"), "°");
  EXPECT_EQ(columnDisplayUnit("time_min"), "min");
  EXPECT_EQ(columnDisplayUnit("x_cmd_mm"), "mm");
  EXPECT_EQ(columnDisplayUnit("Zeit [min]"), "min");
  EXPECT_EQ(columnDisplayUnit("Temperatur T1 [°C]"), "°C");
  EXPECT_EQ(columnDisplayUnit("Verlagerung K3 [µm]"), "µm");
  EXPECT_EQ(columnDisplayUnit("Drehzahl [1/min]"), "1/min");
  EXPECT_EQ(columnDisplayUnit("Kraft [N]"), "N");  // a unit the import does not know, as written
  EXPECT_EQ(columnDisplayUnit("qx"), "mm");
  EXPECT_EQ(columnDisplayUnit("T1"), "");
  EXPECT_EQ(columnDisplayUnit("surface"), "");
}

TEST(DatasetContent, OutsideToleranceWithMissingLimitsAndSlack) {
  EXPECT_TRUE(outsideTolerance(0.031, -0.03, 0.03));
  EXPECT_FALSE(outsideTolerance(0.030, -0.03, 0.03));
  EXPECT_FALSE(outsideTolerance(0.0305, -0.03, 0.03, 0.0005));
  EXPECT_TRUE(outsideTolerance(-0.05, -0.03, std::nullopt));
  EXPECT_FALSE(outsideTolerance(5.0, std::nullopt, std::nullopt));
}

TEST(DatasetContent, PcDmisInInchesIsConvertedAndOuttolMarksTheRow) {
  test::TempDir dir;
  const std::string file = dir.file("inch.txt");
  test::writeText(file,
                  "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=IN ,$\n"
                  "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
                  "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
                  "X      1.0000     0.0020     0.0020     1.0030     0.0030     0.0010 --------->\n"
                  "END OF DIMENSION LOC1\n");
  const DatasetContent c = readDatasetContentFile(file, datasetOf(dataset_kind::kCmmReport, file));
  ASSERT_EQ(c.shape, DatasetContent::Shape::Features);
  EXPECT_EQ(c.format, "PC-DMIS text report");
  ASSERT_EQ(c.features.size(), 1u);
  const FeatureTableRow& r = c.features[0];
  EXPECT_EQ(r.feature, "LOC1");
  EXPECT_EQ(r.characteristic, "X");
  EXPECT_EQ(r.unit, "mm");
  EXPECT_NEAR(*r.nominal, 25.4, 1e-9);
  EXPECT_NEAR(*r.actual, 1.003 * 25.4, 1e-9);
  EXPECT_NEAR(*r.deviation, 0.003 * 25.4, 1e-9);
  EXPECT_NEAR(*r.upper, 0.002 * 25.4, 1e-9);
  EXPECT_NEAR(*r.lower, -0.002 * 25.4, 1e-9);
  EXPECT_TRUE(r.outOfTolerance);
  EXPECT_EQ(r.line, 4);
}

TEST(DatasetContent, DmisInchesAndOutolWord) {
  test::TempDir dir;
  const std::string file = dir.file("p.dmo");
  test::writeText(file,
                  "DMISMN/'t',05.0\n"
                  "UNITS/INCH,ANGDEG\n"
                  "F(C1)=FEAT/CIRCLE,INNER,CART,1,2,0,0,0,1,0.5\n"
                  "FA(C1)=FEAT/CIRCLE,INNER,CART,1.001,2,0,0,0,1,0.502\n"
                  "T(W)=TOL/WIDTH,NOMINL,4,-0.001,0.001\n"
                  "TA(W)=TOL/WIDTH,4.01,OUTOL\n"
                  "ENDFIL\n");
  const DatasetContent c = readDatasetContentFile(file, datasetOf(dataset_kind::kDmis, file));
  ASSERT_EQ(c.shape, DatasetContent::Shape::Features);
  ASSERT_EQ(c.features.size(), 5u);  // C1 X, Y, Z, D; W
  EXPECT_EQ(c.features[0].characteristic, "X");
  EXPECT_NEAR(*c.features[0].deviation, 0.001 * 25.4, 1e-9);
  EXPECT_EQ(c.features[3].characteristic, "D");
  EXPECT_NEAR(*c.features[3].nominal, 0.5 * 25.4, 1e-9);
  EXPECT_NEAR(*c.features[3].actual, 0.502 * 25.4, 1e-9);
  const FeatureTableRow& w = c.features[4];
  EXPECT_EQ(w.feature, "W");
  EXPECT_EQ(w.characteristic, "WIDTH");
  EXPECT_NEAR(*w.actual, 4.01 * 25.4, 1e-9);  // nearer the nominal than zero: the actual
  EXPECT_NEAR(*w.deviation, 0.01 * 25.4, 1e-9);
  EXPECT_TRUE(w.outOfTolerance);
  EXPECT_EQ(w.line, 6);
}

TEST(DatasetContent, HoleTableIsAPointTableInMm) {
  test::TempDir dir;
  const std::string file = dir.file("holes.txt");
  test::writeText(
      file, "Meas X    Meas Y    Nom X    Nom Y\n1.001  2.000  1.000  2.000\n5.000  0.002  5.000  0.000\n");
  const DatasetContent c = readDatasetContentFile(file, datasetOf(dataset_kind::kHoleTable, file));
  ASSERT_EQ(c.shape, DatasetContent::Shape::Columns);
  EXPECT_EQ(c.format, "hole table");
  EXPECT_EQ(c.table.header(), (std::vector<std::string>{"id", "surface", "qx", "qy", "px", "py"}));
  EXPECT_EQ(c.units, (std::vector<std::string>{"", "", "mm", "mm", "mm", "mm"}));
  ASSERT_EQ(c.table.rowCount(), 2u);
  EXPECT_EQ(c.table.cell(0, 4), "1.001");
}

TEST(DatasetContent, MappedCsvKeepsTheFilesColumnNames) {
  test::TempDir dir;
  const std::string file = dir.file("log.csv");
  test::writeText(file, "Zeit [s];Temp;Verlagerung Z [mm]\n0;20,5;0,001\n30;21;0,002\n");
  DatasetRef d = datasetOf(dataset_kind::kThermalLog, file);
  d.csv.columnMap = {{"time_s", "Zeit [s]"}, {"T1", "Temp"}};
  const DatasetContent c = readDatasetContentFile(file, d);
  ASSERT_EQ(c.shape, DatasetContent::Shape::Columns);
  EXPECT_EQ(c.table.header(), (std::vector<std::string>{"time_s", "T1", "Verlagerung Z [mm]"}));
  EXPECT_EQ(c.fileColumns, (std::vector<std::string>{"Zeit [s]", "Temp", "Verlagerung Z [mm]"}));
  // The values as the file writes them: a displacement in mm stays in mm here.
  EXPECT_EQ(c.units, (std::vector<std::string>{"s", "", "mm"}));
  EXPECT_EQ(c.table.cell(1, 2), "0,002");
}

TEST(DatasetContent, DemoSetupModelAndReportSeries) {
  const std::string model = (test::sourceDir() / "resources/demo/setup/paper_example.json").string();
  const DatasetContent m = readDatasetContentFile(model, datasetOf(dataset_kind::kSetupModel, model));
  ASSERT_EQ(m.shape, DatasetContent::Shape::Columns);
  EXPECT_EQ(m.table.header(),
            (std::vector<std::string>{"dimension", "label", "nominal_mm", "lower_tol_mm", "upper_tol_mm"}));
  ASSERT_GT(m.table.rowCount(), 3u);
  EXPECT_EQ(m.table.cell(2, 0), "P1.D3");
  EXPECT_EQ(m.table.cell(2, 2), "18");
  EXPECT_EQ(m.table.cell(2, 3), "-0.12");
  EXPECT_EQ(m.table.cell(2, 4), "0.08");
  EXPECT_EQ(m.units[2], "mm");

  const std::string series = (test::sourceDir() / "resources/demo/data/diagnose_setup_report.csv").string();
  const DatasetContent s = readDatasetContentFile(series, datasetOf(dataset_kind::kCmmReport, series));
  ASSERT_EQ(s.shape, DatasetContent::Shape::Features);
  ASSERT_GT(s.features.size(), 3u);
  // 1,16.54,P1.D1,12,11.947,-0.1,0.1
  EXPECT_EQ(s.features[0].part, "1");
  EXPECT_EQ(s.features[0].feature, "P1.D1");
  EXPECT_DOUBLE_EQ(*s.features[0].deviation, -0.053);
  EXPECT_FALSE(s.features[0].outOfTolerance);
  for (const FeatureTableRow& r : s.features)
    EXPECT_EQ(r.outOfTolerance, *r.deviation < *r.lower || *r.deviation > *r.upper) << r.line;
}

TEST(DatasetContent, MissingFileNamesIt) {
  try {
    (void)readDatasetContentFile("/nonexistent/x.csv", datasetOf(dataset_kind::kThermalLog, "x.csv"));
    FAIL() << "read a missing file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.csv"), std::string::npos) << e.what();
  }
}

TEST(DatasetContent, RealOgpSummaryHasOnePartPerRun) {
  const std::filesystem::path real = test::realData("cmm-ogp-hps-svt/survey_data/L123_fixture_sho.txt");
  METROFIT_REQUIRE_PATH(real);
  const DatasetContent c =
      readDatasetContentFile(real.string(), datasetOf(dataset_kind::kCmmReport, real.string()));
  ASSERT_EQ(c.shape, DatasetContent::Shape::Features);
  EXPECT_EQ(c.format, "OGP summary report");
  std::set<std::string> parts;
  for (const FeatureTableRow& r : c.features) parts.insert(r.part);
  EXPECT_EQ(parts.size(), 13u);  // SOURCE.md: a summary of 13 runs
  EXPECT_EQ(c.features.front().part, "run 1 (#4, Wed Oct 01 17:29:15 2014)");
  EXPECT_EQ(c.features.front().feature, "Datum plane, focus");
  EXPECT_EQ(c.features.front().characteristic, "X Location");
  EXPECT_DOUBLE_EQ(*c.features.front().actual, 23.608);
  EXPECT_FALSE(c.features.front().nominal.has_value());
  // Step 5, X Location: nominal +00020.262, actual +00020.264: deviation 0.002.
  const auto step5 = std::find_if(c.features.begin(), c.features.end(), [](const FeatureTableRow& r) {
    return r.nominal.has_value() && r.characteristic == "X Location";
  });
  ASSERT_NE(step5, c.features.end());
  EXPECT_DOUBLE_EQ(*step5->nominal, 20.262);
  EXPECT_DOUBLE_EQ(*step5->actual, 20.264);
  EXPECT_DOUBLE_EQ(*step5->deviation, 0.002);
}

}  // namespace
}  // namespace metrofit
