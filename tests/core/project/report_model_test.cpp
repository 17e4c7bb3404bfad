// From a CMM report to a setup model (core/project/report_model.h) and the project's DMIS series ("paths",
// core/project/project.h), without Qt. The model built from a report is checked the independent way: the
// setup report reader (core/setup/report.h) reads it back against the same file, and its deviations are
// the report's actual - nominal (OGP, PC-DMIS) or the DMIS file's FA - F and TA values, numbers copied
// here from the files by hand.
//
// OGP: the REAL step report ../shared/data/real/cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt
// (skipped when absent). PC-DMIS: the documented example of tests/core/setup/cmm_text_report_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/common/error.h"
#include "core/project/datasets.h"
#include "core/project/project.h"
#include "core/project/report_model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "testsupport.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;

int rowOf(const ReportFeatures& r, const std::string& label) {
  for (std::size_t k = 0; k < r.characteristics.size(); ++k)
    if (r.characteristics[k].label == label) return static_cast<int>(k);
  return -1;
}

std::string dmisPart(const std::string& serial, const std::string& z, const std::string& d2) {
  return "DMISMN/'series test',05.0\nPARTSN/'" + serial +
         "'\nUNITS/MM,ANGDEG\nF(POS_D1)=FEAT/PLANE,CART,10,20,42.000,0,0,1\nFA(POS_D1)=FEAT/"
         "PLANE,CART,10,20," +
         z + ",0,0,1\nT(D2)=TOL/DISTB,NOMINL,18.5,-0.05,0.03,ZAXIS\nTA(D2)=TOL/DISTB," + d2 + "\nENDFIL\n";
}

TEST(ReportModel, OgpStepReportCharacteristicsBecomeAModelTheReaderReads) {
  const fs::path ogp = test::realData("cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt");
  METROFIT_REQUIRE_PATH(ogp);
  const ReportFeatures f = readReportFeatures(ogp.string());
  EXPECT_EQ(f.format, "OGP step report");
  EXPECT_FALSE(f.byId);
  const int oriZ = rowOf(f, "oriball:Z Location");
  const int axiD = rowOf(f, "axiball:Diameter");
  ASSERT_GE(oriZ, 0);
  ASSERT_GE(axiD, 0);
  // sed -n 39p: "Z Location  -032.03676  -032.04627 +00.00000 -00.00000": no tolerance printed (both 0).
  EXPECT_DOUBLE_EQ(*f.characteristics[static_cast<std::size_t>(oriZ)].nominal, -32.04627);
  EXPECT_FALSE(f.characteristics[static_cast<std::size_t>(oriZ)].lower);
  // Angles and values without a nominal cannot be dimensions.
  const int angle = rowOf(f, "Step 4:XY Angle");
  ASSERT_GE(angle, 0);
  EXPECT_FALSE(f.characteristics[static_cast<std::size_t>(angle)].usable);
  EXPECT_FALSE(f.characteristics[static_cast<std::size_t>(rowOf(f, "oriball:True Position"))].usable);

  ReportModelOptions options;
  options.connectTo = "W1";
  const std::vector<std::size_t> chosen{static_cast<std::size_t>(oriZ), static_cast<std::size_t>(axiD)};
  try {
    (void)addReportCharacteristics(newReportModel("m"), f, chosen, options);
    FAIL() << "no tolerance and none given";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("oriball:Z Location"), std::string::npos) << e.what();
  }
  options.defaultToleranceMm = 0.05;
  const setup::Model m = addReportCharacteristics(newReportModel("m"), f, chosen, options);
  setup::validateModel(m);
  ASSERT_EQ(m.dimensions.size(), 2u);
  EXPECT_EQ(m.dimensions[0].label, "oriball:Z Location");
  EXPECT_EQ(m.dimensions[0].lower, -0.05);
  const setup::Measurements meas = setup::readMeasurements({ogp.string()}, m);
  EXPECT_TRUE(test::near(meas.deviationMm[0], -32.03676 + 32.04627, 1e-9));
  EXPECT_TRUE(test::near(meas.deviationMm[1], 6.35505 - 6.34291, 1e-9));

  // Adding again adds nothing; every usable length characteristic gives a model the reader reads.
  EXPECT_EQ(setup::modelToJson(addReportCharacteristics(m, f, chosen, options)), setup::modelToJson(m));
  std::vector<std::size_t> all;
  for (std::size_t k = 0; k < f.characteristics.size(); ++k)
    if (f.characteristics[k].usable) all.push_back(k);
  const setup::Model big = addReportCharacteristics(m, f, all, options);
  setup::validateModel(big);
  EXPECT_EQ(big.dimensions.size(), all.size());
  EXPECT_EQ(setup::readMeasurements({ogp.string()}, big).rows.size(), all.size());
}

TEST(ReportModel, DmisSeriesDatasetListsEveryFileAndReadsAsOneSeries) {
  test::TempDir tmp;
  const std::string a = tmp.file("part_1.dmo"), b = tmp.file("part_2.dmo");
  test::writeText(a, dmisPart("S1", "42.013", "-0.021"));
  test::writeText(b, dmisPart("S2", "42.007", "0.004"));
  Project project;
  AddDatasetRequest request;
  request.kind = "cmm-report";
  request.file = a;
  request.moreFiles = {b};
  const std::string projectPath = tmp.file("p.metrofit");
  const DatasetRef d = addDataset(project, projectPath, request);
  EXPECT_EQ(d.path, "part_1.dmo");
  EXPECT_EQ(d.paths, (std::vector<std::string>{"part_1.dmo", "part_2.dmo"}));
  const Project back = Project::fromJson(project.toJson(), "p.metrofit");
  EXPECT_EQ(back, project);
  EXPECT_EQ(summarizeDataset(projectPath, back.datasets[0]).rows, 4) << "two measured labels per file";

  const ReportFeatures f = datasetReportFeatures(projectPath, back.datasets[0]);
  EXPECT_EQ(f.format, "DMIS output");
  ASSERT_EQ(f.characteristics.size(), 2u);
  EXPECT_EQ(f.characteristics[0].label, "POS_D1");
  EXPECT_EQ(f.characteristics[1].label, "D2");
  EXPECT_EQ(*f.characteristics[1].lower, -0.05);
  EXPECT_EQ(*f.characteristics[1].upper, 0.03);
  ReportModelOptions options;
  options.connectTo = "W1";
  options.defaultToleranceMm = 0.02;
  const setup::Model m = addReportCharacteristics(newReportModel("m"), f, {0, 1}, options);
  const setup::Measurements meas =
      setup::readMeasurements(resolveDatasetPaths(projectPath, back.datasets[0]), m);
  EXPECT_EQ(meas.parts, (std::vector<std::string>{"S1", "S2"}));
  EXPECT_TRUE(test::near(meas.deviationMm[0], (0.013 + 0.007) / 2, 1e-9));
  EXPECT_TRUE(test::near(meas.deviationMm[1], (-0.021 + 0.004) / 2, 1e-9));

  // A series is made of DMIS files only, and not embedded.
  test::writeText(tmp.file("not_dmis.csv"), "a,b\n1,2\n");
  request.moreFiles = {tmp.file("not_dmis.csv")};
  EXPECT_THROW((void)addDataset(project, projectPath, request), ValidationError);
  request.moreFiles = {b};
  request.embed = true;
  EXPECT_THROW((void)addDataset(project, projectPath, request), ValidationError);
}

TEST(ReportModel, PathsKeyIsOptionalAndChecked) {
  nlohmann::json j = {{"format", "metrofit-project"},
                      {"version", 1},
                      {"name", "p"},
                      {"datasets", {{{"id", "r"}, {"kind", "dmis"}, {"path", "a.dmo"}}}}};
  EXPECT_TRUE(Project::fromJson(j, "p.metrofit").datasets[0].paths.empty()) << "no key: one file as before";
  EXPECT_FALSE(Project::fromJson(j, "p.metrofit").toJson()["datasets"][0].contains("paths"));
  j["datasets"][0]["paths"] = {"a.dmo", "b.dmo"};
  const Project p = Project::fromJson(j, "p.metrofit");
  EXPECT_EQ(p.datasets[0].paths, (std::vector<std::string>{"a.dmo", "b.dmo"}));
  EXPECT_EQ(p.toJson()["datasets"][0]["paths"], j["datasets"][0]["paths"]);
  EXPECT_EQ(resolveDatasetPaths("/x/p.metrofit", p.datasets[0]),
            (std::vector<std::string>{"/x/a.dmo", "/x/b.dmo"}));
  j["datasets"][0]["paths"] = {"b.dmo", "a.dmo"};
  try {
    (void)Project::fromJson(j, "p.metrofit");
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("paths[0]"), std::string::npos) << e.what();
  }
  j["datasets"][0]["paths"] = {"a.dmo", "b.dmo"};
  j["datasets"][0]["kind"] = "thermal_log";
  EXPECT_THROW((void)Project::fromJson(j, "p.metrofit"), ValidationError);
}

// A Q-DAS DFQ file (issue 29), written here from the AQDEF field list, as the report a setup model is
// made from (issue 28 item 3): its characteristics with nominal and limits become dimensions the setup
// reader reads, with the deviations of the valid values (the removed one, attribute 255, left out).
TEST(ReportModel, DfqCharacteristicsBecomeAModelTheReaderReads) {
  test::TempDir tmp;
  const std::string file = tmp.file("w.dfq");
  test::writeText(
      file,
      "K0100 2\r\n"
      "K1001/1 4711-A\r\n"
      "K2001/1 1\r\nK2002/1 Durchmesser 12,5\r\nK2101/1 12.5\r\nK2110/1 12.48\r\nK2111/1 12.52\r\n"
      "K2001/2 2\r\nK2002/2 Laenge\r\nK2101/2 40\r\nK2110/2 39.9\r\nK2111/2 40.1\r\n"
      "K0001/1 12.506\r\nK0001/2 40.02\r\nK0014/0 SN-1\r\n"
      "K0001/1 12.504\r\nK0001/2 40.90\r\nK0002/2 255\r\nK0014/0 SN-2\r\n");
  const ReportFeatures f = readReportFeatures(file);
  ASSERT_EQ(f.characteristics.size(), 2u) << f.format;
  for (const ReportCharacteristic& c : f.characteristics) EXPECT_TRUE(c.usable) << c.label << ": " << c.why;
  ASSERT_TRUE(f.characteristics[0].nominal.has_value());
  EXPECT_DOUBLE_EQ(*f.characteristics[0].nominal, 12.5);
  ASSERT_TRUE(f.characteristics[0].lower.has_value());
  EXPECT_NEAR(*f.characteristics[0].lower, -0.02, 1e-12);
  EXPECT_NEAR(*f.characteristics[0].upper, 0.02, 1e-12);
  ReportModelOptions options;
  options.connectTo = "W1";
  const setup::Model m = addReportCharacteristics(newReportModel("shaft"), f, {0, 1}, options);
  setup::validateModel(m);
  ASSERT_EQ(m.dimensions.size(), 2u);
  const setup::Measurements meas = setup::readMeasurements({file}, m);
  // The mean deviation of the valid values: (0.006 + 0.004) / 2; and 0.02 (the 40.90 was removed).
  EXPECT_NEAR(meas.deviationMm[0], 0.005, 1e-9);
  EXPECT_NEAR(meas.deviationMm[1], 0.02, 1e-9);
}

}  // namespace
}  // namespace metrofit
