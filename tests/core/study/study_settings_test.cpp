// One owner per study's settings (core/study/study_settings.h): each type reads its study block, writes
// it back (only what differs from the defaults), refuses a bad value naming the field, and the project
// validator (core/study/study_check.h) knows exactly the keys of the types.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/project/project.h"
#include "core/study/study_check.h"
#include "core/study/study_settings.h"

namespace metrofit {
namespace {

/// The field of the ValidationError `fn` throws ("" when it does not throw).
template <class Fn>
std::string refusedField(Fn fn) {
  try {
    fn();
  } catch (const ValidationError& e) {
    return e.context().field;
  }
  return {};
}

TEST(StudySettings, DefaultsWriteNothingAndReadBack) {
  EXPECT_EQ(SetupSettings{}.toJson(), nlohmann::json::object());
  EXPECT_EQ(MatchingSettings{}.toJson(), nlohmann::json::object());
  EXPECT_EQ(ThermalSettings{}.toJson(), nlohmann::json::object());
  EXPECT_EQ(SetupSettings::fromJson(nlohmann::json::object()), SetupSettings{});
  EXPECT_EQ(MatchingSettings::fromJson(nlohmann::json()), MatchingSettings{});
  EXPECT_EQ(ThermalSettings::fromJson(nlohmann::json::object()), ThermalSettings{});
}

TEST(StudySettings, EveryKeyRoundTrips) {
  SetupSettings setup;
  setup.model = "graph";
  setup.dataset = "report";
  setup.method = "cripso";
  setup.budget = 1234;
  setup.seed = 7;
  EXPECT_EQ(SetupSettings::fromJson(setup.toJson()), setup);

  MatchingSettings m;
  m.dataset = "pts";
  m.toleranceMm = 0.02;
  m.method = matching::MatchMethod::Minimax;
  m.allowScale = true;
  m.seed = 9;
  m.locks = "rz,z";
  m.frame = machine::FrameFormat::Fanuc;
  m.frameDecimals = 3;
  EXPECT_EQ(MatchingSettings::fromJson(m.toJson()), m);
  EXPECT_EQ(m.toJson().at("frame"), "fanuc");

  ThermalSettings t;
  t.dataset = "log";
  t.target = "disp_z_um";
  t.inputs = {"T1", "T2"};
  t.trainFraction = 0.6;
  t.seed = 4;
  t.modules = {{"thermal_modular_c", "log2"}};
  EXPECT_EQ(ThermalSettings::fromJson(t.toJson()), t);
}

TEST(StudySettings, BadValuesAreRefusedNamingTheField) {
  EXPECT_EQ(refusedField([] { SetupSettings::fromJson({{"method", "newton"}}); }), "studies.setup.method");
  EXPECT_EQ(refusedField([] { SetupSettings::fromJson({{"budget", 0}}); }), "studies.setup.budget");
  EXPECT_EQ(refusedField([] { MatchingSettings::fromJson({{"frame", "okuma"}}); }), "studies.matching.frame");
  EXPECT_EQ(refusedField([] {
              MatchingSettings::fromJson({{"frame_decimals", 13}});
            }),
            "studies.matching.frame_decimals");
  EXPECT_EQ(refusedField([] {
              MatchingSettings::fromJson({{"tolerance_mm", -1}});
            }),
            "studies.matching.tolerance_mm");
  EXPECT_EQ(refusedField([] {
              ThermalSettings::fromJson({{"train_fraction", 1.5}});
            }),
            "studies.thermal.train_fraction");
  EXPECT_EQ(refusedField([] { ThermalSettings::fromJson({{"targt", "x"}}); }), "studies.thermal.targt");

  std::string field, why;
  SetupSettings setup;
  setup.budget = -1;
  EXPECT_FALSE(setup.isValid(&field, &why));
  EXPECT_EQ(field, "studies.setup.budget");
  MatchingSettings m;
  m.frameDecimals = 20;
  EXPECT_FALSE(m.isValid(&field, &why));
  EXPECT_EQ(field, "studies.matching.frame_decimals");
  ThermalSettings t;
  t.trainFraction = 0.0;
  EXPECT_FALSE(t.isValid(&field, &why));
  EXPECT_EQ(field, "studies.thermal.train_fraction");
  EXPECT_TRUE(SetupSettings{}.isValid(&field, &why));
  EXPECT_TRUE(MatchingSettings{}.isValid(&field, &why));
  EXPECT_TRUE(ThermalSettings{}.isValid(&field, &why));
}

// What a type writes, the validator accepts: the validator iterates the same types.
TEST(StudySettings, TheValidatorAcceptsWhatTheTypesWrite) {
  Project p;
  p.datasets.push_back({"graph", dataset_kind::kSetupModel, "g.json", "", "", {}});
  p.datasets.push_back({"report", dataset_kind::kCmmReport, "r.csv", "", "", {}});
  p.datasets.push_back({"pts", dataset_kind::kProbePoints, "p.csv", "", "", {}});
  p.datasets.push_back({"log", dataset_kind::kThermalLog, "l.csv", "", "", {}});
  SetupSettings setup;
  setup.model = "graph";
  setup.dataset = "report";
  setup.method = "pso";
  setup.budget = 100;
  MatchingSettings m;
  m.dataset = "pts";
  m.frame = machine::FrameFormat::Siemens;
  m.frameDecimals = 2;
  m.locks = "x";
  m.method = matching::MatchMethod::ClosedForm;
  ThermalSettings t;
  t.dataset = "log";
  t.target = "disp_z_um";
  t.inputs = {"T1"};
  t.trainFraction = 0.7;
  t.modules = {{"thermal_modular_z", "log"}};
  p.studies["setup"] = setup.toJson();
  p.studies["matching"] = m.toJson();
  p.studies["thermal"] = t.toJson();
  EXPECT_TRUE(checkStudies(p).empty())
      << checkStudies(p).front().field << ": " << checkStudies(p).front().message;
  ASSERT_EQ(studyTypes().size(), std::size(study::kAll));
  for (std::size_t i = 0; i < studyTypes().size(); ++i) EXPECT_STREQ(studyTypes()[i].name, study::kAll[i]);
}

}  // namespace
}  // namespace metrofit
