// Study settings are checked, never quietly replaced (core/study/study_check.h): every bad
// setting is one issue naming the study and the field; the demo project has none.
#include <gtest/gtest.h>

#include <map>

#include "core/common/error.h"
#include "core/project/project.h"
#include "core/study/study_check.h"
#include "testsupport.h"

namespace metrofit {
namespace {

Project twoDatasets() {
  Project p;
  p.datasets.push_back({"log", dataset_kind::kThermalLog, "log.csv", "", "", {}});
  p.datasets.push_back({"pts", dataset_kind::kProbePoints, "pts.csv", "", "", {}});
  return p;
}

std::vector<std::string> fields(const std::vector<StudyIssue>& issues) {
  std::vector<std::string> f;
  for (const auto& i : issues) f.push_back(i.field);
  return f;
}

TEST(StudyCheck, TheDemoProjectIsClean) {
  const Project demo = loadProject((test::sourceDir() / "resources/demo/demo.metrofit").string());
  EXPECT_TRUE(checkStudies(demo).empty()) << checkStudies(demo).front().field;
}

TEST(StudyCheck, UnknownStudyAndSettingAreNamed) {
  Project p = twoDatasets();
  p.studies["thermals"] = nlohmann::json::object();
  p.studies["thermal"] = {{"dataset", "log"}, {"targt", "disp_z_um"}, {"notes", "fine"}};
  const auto issues = checkStudies(p);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(fields(issues), (std::vector<std::string>{"studies.thermal.targt", "studies.thermals"}));
  EXPECT_NE(issues[0].message.find("not a setting"), std::string::npos);
  EXPECT_NE(issues[1].message.find("not a study"), std::string::npos);
}

TEST(StudyCheck, DatasetOfTheWrongKindOrMissing) {
  Project p = twoDatasets();
  p.studies["thermal"] = {{"dataset", "pts"}};
  p.studies["matching"] = {{"dataset", "nope"}};
  const auto issues = checkStudies(p);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "studies.matching.dataset");
  EXPECT_NE(issues[0].message.find("'nope'"), std::string::npos);
  EXPECT_EQ(issues[1].field, "studies.thermal.dataset");
  EXPECT_NE(issues[1].message.find("probe_points"), std::string::npos);
}

// studies.thermal.modules: per module the thermal log it is identified on (core/study/thermal_comparison.h).
TEST(StudyCheck, ThermalModulesNameThermalLogs) {
  Project p = twoDatasets();
  p.studies["thermal"] = {{"modules", {{"thermal_modular_c", {{"dataset", "log"}}}}}};
  EXPECT_TRUE(checkStudies(p).empty()) << checkStudies(p).front().field;
  p.studies["thermal"] = {{"modules",
                           {{"thermal_modular_c", {{"dataset", "pts"}}},
                            {"thermal_modular_z", {{"datset", "log"}}},
                            {"x", {{"dataset", "gone"}}}}}};
  const auto issues = checkStudies(p);
  EXPECT_EQ(fields(issues), (std::vector<std::string>{"studies.thermal.modules.thermal_modular_c.dataset",
                                                      "studies.thermal.modules.thermal_modular_z.datset",
                                                      "studies.thermal.modules.x.dataset"}));
  p.studies["thermal"] = {{"modules", {"log"}}};
  EXPECT_EQ(fields(checkStudies(p)), (std::vector<std::string>{"studies.thermal.modules"}));
}

// studies.matching.frame / .frame_decimals: the matching page's Controller frame tab writes them (F2 of the
// GUI run: they were unknown keys, so the report refused a project after a control was chosen).
TEST(StudyCheck, MatchingFrameIsASetting) {
  Project p = twoDatasets();
  for (const char* control : {"heidenhain", "siemens", "fanuc"}) {
    p.studies["matching"] = {{"dataset", "pts"}, {"frame", control}, {"frame_decimals", 3}};
    EXPECT_TRUE(checkStudies(p).empty()) << control << ": " << checkStudies(p).front().message;
  }
  p.studies["matching"] = {{"frame", "okuma"}, {"frame_decimals", 13}};
  auto issues = checkStudies(p);
  EXPECT_EQ(fields(issues),
            (std::vector<std::string>{"studies.matching.frame", "studies.matching.frame_decimals"}));
  EXPECT_NE(issues[0].message.find("heidenhain, siemens, fanuc"), std::string::npos);
  EXPECT_NE(issues[1].message.find("0..12"), std::string::npos);
  p.studies["matching"] = {{"frame", 1}, {"frame_decimals", 2.5}};
  EXPECT_EQ(fields(checkStudies(p)),
            (std::vector<std::string>{"studies.matching.frame", "studies.matching.frame_decimals"}));
}

TEST(StudyCheck, MisspelledDatasetKind) {
  Project p = twoDatasets();
  p.datasets.push_back({"x", "thermal-log", "x.csv", "", "", {}});
  const auto issues = checkStudies(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "datasets[2].kind");
  EXPECT_NE(issues[0].message.find("'thermal-log'"), std::string::npos);
}

TEST(StudyCheck, BadValuesAndDiagnosisDomains) {
  Project p = twoDatasets();
  p.studies["thermal"] = {{"dataset", "log"}, {"train_fraction", 1.5}, {"inputs", nlohmann::json::array()}};
  p.studies["diagnosis"] = {{"thermo", nlohmann::json::object()},
                            {"thermal", {{"dataset", "log"}, {"lag", 3}}}};
  const auto f = fields(checkStudies(p));
  EXPECT_EQ(f, (std::vector<std::string>{"studies.diagnosis.thermal.lag", "studies.diagnosis.thermo",
                                         "studies.thermal.inputs", "studies.thermal.train_fraction"}));
}

TEST(StudyCheck, ColumnsTheDataLacks) {
  Project p = twoDatasets();
  p.studies["thermal"] = {{"dataset", "log"}, {"target", "disp_x_um"}, {"inputs", {"T1", "T9"}}};
  const std::vector<std::string> cols = {"time_min", "T1", "T2", "disp_z_um"};
  const DatasetColumns columns = [&](const std::string& id) { return id == "log" ? &cols : nullptr; };
  const auto issues = checkStudyColumns(p, columns);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "studies.thermal.target");
  EXPECT_NE(issues[0].message.find("'disp_x_um'"), std::string::npos);
  EXPECT_NE(issues[0].message.find("disp_z_um"), std::string::npos);  // says what it has
  EXPECT_EQ(issues[1].field, "studies.thermal.inputs");
  try {
    validateStudies(p, "cell.metrofit", columns);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.context().field, "studies.thermal.target");
    EXPECT_NE(std::string(e.what()).find("cell.metrofit"), std::string::npos) << e.what();
  }
}

TEST(StudyCheck, KinematicsFromSpcAndPlanesNameTheirDatasets) {
  Project p = twoDatasets();
  p.studies["kinematics"] = {{"from_spc", {{"x_dataset", "log"}, {"y_dataset", "nope"}, {"coverag", 2}}},
                             {"planes", {{"xy", "pts"}, {"yz", "log"}, {"zx", ""}}}};
  const auto f = fields(checkStudies(p));
  const std::vector<std::string> expected = {"studies.kinematics.from_spc.coverag",
                                             "studies.kinematics.from_spc.y_dataset",
                                             "studies.kinematics.planes.zx"};
  EXPECT_EQ(f, expected);
}

}  // namespace
}  // namespace metrofit
