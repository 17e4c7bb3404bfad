// One owner per study's settings (core/study/study_settings.h): each type reads its study block, writes
// it back (only what differs from the defaults), refuses a bad value naming the field, and the project
// validator (core/study/study_check.h) knows exactly the keys of the types.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/project/project.h"
#include "core/study/diagnosis_study.h"
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

// ---- studies.diagnosis.<domain> -------------------------------------------------------------------------

TEST(DiagnosisDomainSettings, DefaultsAreTheClosedLoopsOptions) {
  const DiagnosisDomainSettings d;
  EXPECT_EQ(d.trainFraction, diagnose::ThermalDiagnosisOptions{}.trainFraction);
  EXPECT_EQ(d.feedMmPerMin, diagnose::KinematicDiagnosisOptions{}.feedMmPerMin);
  EXPECT_EQ(d.toleranceMm, diagnose::MatchingDiagnosisOptions{}.toleranceMm);
  EXPECT_EQ(DiagnosisSettings{}.trainFraction, d.trainFraction);
  EXPECT_EQ(DiagnosisSettings{}.feedMmPerMin, d.feedMmPerMin);
  EXPECT_EQ(DiagnosisSettings{}.toleranceMm, d.toleranceMm);
  // Only the required keys: everything else takes the defaults, and toJson writes them back alone.
  const nlohmann::json thermal = {{"dataset", "log"}, {"target", "disp_z_um"}, {"inputs", {"T1"}}};
  const DiagnosisDomainSettings t = DiagnosisDomainSettings::fromJson(thermal, "thermal");
  EXPECT_EQ(t.trainFraction, d.trainFraction);
  EXPECT_EQ(t.toJson(), thermal);
  const nlohmann::json kin = {{"dataset", "circ"}};
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(kin, "kinematic").toJson(), kin);
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(kin, "kinematic").feedMmPerMin, d.feedMmPerMin);
  const nlohmann::json match = {{"dataset", "pts"}};
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(match, "matching").toleranceMm, d.toleranceMm);
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(match, "matching").toJson(), match);
}

TEST(DiagnosisDomainSettings, EveryKeyRoundTrips) {
  DiagnosisDomainSettings t;
  t.domain = "thermal";
  t.dataset = "log";
  t.target = "disp_z_um";
  t.inputs = {"T1", "T2"};
  t.trainFraction = 0.6;
  t.applied = nlohmann::json::array({{{"name", "lag:T1"}, {"parameters", {{"tau_min", 12.0}}}}});
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(t.toJson(), "thermal"), t);
  DiagnosisDomainSettings k;
  k.domain = "kinematic";
  k.dataset = "circ";
  k.feedMmPerMin = 2500.0;
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(k.toJson(), "kinematic"), k);
  EXPECT_EQ(k.toJson().at("feed_mm_per_min"), 2500.0);
  DiagnosisDomainSettings s;
  s.domain = "setup";
  s.dataset = "report";
  s.model = "graph";
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(s.toJson(), "setup"), s);
  DiagnosisDomainSettings m;
  m.domain = "matching";
  m.dataset = "pts";
  m.toleranceMm = 0.02;
  EXPECT_EQ(DiagnosisDomainSettings::fromJson(m.toJson(), "matching"), m);
  std::string field, why;
  for (const auto* x : {&t, &k, &s, &m}) EXPECT_TRUE(x->isValid(&field, &why)) << field << ": " << why;
}

TEST(DiagnosisDomainSettings, BadValuesAreRefusedNamingTheField) {
  const nlohmann::json thermal = {{"dataset", "log"}, {"target", "disp_z_um"}, {"inputs", {"T1"}}};
  const auto with = [](nlohmann::json j, const char* key, nlohmann::json v) {
    j[key] = std::move(v);
    return j;
  };
  const auto refused = [](const nlohmann::json& j, const char* domain) {
    return refusedField([&] { DiagnosisDomainSettings::fromJson(j, domain, "p.metrofit"); });
  };
  EXPECT_EQ(refused(with(thermal, "train_fraction", 2), "thermal"),
            "studies.diagnosis.thermal.train_fraction");
  EXPECT_EQ(refused(with(thermal, "train_fraction", 0.01), "thermal"),
            "studies.diagnosis.thermal.train_fraction");
  EXPECT_EQ(refused(with(thermal, "train_fraction", "half"), "thermal"),
            "studies.diagnosis.thermal.train_fraction");
  EXPECT_EQ(refused(with(thermal, "target", ""), "thermal"), "studies.diagnosis.thermal.target");
  EXPECT_EQ(refused(with(thermal, "inputs", "T1"), "thermal"), "studies.diagnosis.thermal.inputs");
  EXPECT_EQ(refused(with(thermal, "applied", 3), "thermal"), "studies.diagnosis.thermal.applied");
  EXPECT_EQ(refused(with(thermal, "lag", 3), "thermal"), "studies.diagnosis.thermal.lag");
  EXPECT_EQ(refused(with(thermal, "dataset", 7), "thermal"), "studies.diagnosis.thermal.dataset");
  EXPECT_EQ(refused({{"dataset", "log"}, {"inputs", {"T1"}}}, "thermal"), "studies.diagnosis.thermal.target");
  EXPECT_EQ(refused({{"dataset", "log"}, {"target", "d"}}, "thermal"), "studies.diagnosis.thermal.inputs");
  EXPECT_EQ(refused({{"target", "d"}, {"inputs", {"T1"}}}, "thermal"), "studies.diagnosis.thermal.dataset");
  EXPECT_EQ(refused({{"dataset", "c"}, {"feed_mm_per_min", 0}}, "kinematic"),
            "studies.diagnosis.kinematic.feed_mm_per_min");
  EXPECT_EQ(refused({{"dataset", "c"}, {"tolerance_mm", 0.1}}, "kinematic"),
            "studies.diagnosis.kinematic.tolerance_mm");
  EXPECT_EQ(refused({{"dataset", "p"}, {"tolerance_mm", -0.1}}, "matching"),
            "studies.diagnosis.matching.tolerance_mm");
  EXPECT_EQ(refused({{"dataset", "r"}}, "setup"), "studies.diagnosis.setup.model");
  EXPECT_EQ(refused(nlohmann::json::array(), "setup"), "studies.diagnosis.setup");
  EXPECT_EQ(refused({{"dataset", "x"}}, "thermo"), "studies.diagnosis.thermo");
  // The message says what is wrong, with the file named.
  try {
    DiagnosisDomainSettings::fromJson(with(thermal, "train_fraction", 2), "thermal", "p.metrofit");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("p.metrofit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("between 0.05 and 0.95"), std::string::npos) << e.what();
  }

  std::string field, why;
  DiagnosisDomainSettings t = DiagnosisDomainSettings::fromJson(thermal, "thermal");
  t.trainFraction = 2.0;
  EXPECT_FALSE(t.isValid(&field, &why));
  EXPECT_EQ(field, "studies.diagnosis.thermal.train_fraction");
  DiagnosisDomainSettings k;
  k.domain = "kinematic";
  k.dataset = "c";
  k.feedMmPerMin = -1.0;
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.diagnosis.kinematic.feed_mm_per_min");
  DiagnosisDomainSettings m;
  m.domain = "matching";
  m.dataset = "p";
  m.toleranceMm = 0.0;
  EXPECT_FALSE(m.isValid(&field, &why));
  EXPECT_EQ(field, "studies.diagnosis.matching.tolerance_mm");
  DiagnosisDomainSettings s;
  s.domain = "setup";
  s.dataset = "r";
  EXPECT_FALSE(s.isValid(&field, &why));
  EXPECT_EQ(field, "studies.diagnosis.setup.model");
}

// The project validator refuses the same values (it iterates the same fields).
TEST(DiagnosisDomainSettings, TheValidatorUsesTheSameChecks) {
  Project p;
  p.datasets.push_back({"log", dataset_kind::kThermalLog, "l.csv", "", "", {}});
  p.datasets.push_back({"pts", dataset_kind::kProbePoints, "p.csv", "", "", {}});
  DiagnosisDomainSettings t;
  t.dataset = "log";
  t.target = "disp_z_um";
  t.inputs = {"T1"};
  t.trainFraction = 0.7;
  DiagnosisDomainSettings m;
  m.domain = "matching";
  m.dataset = "pts";
  m.toleranceMm = 0.01;
  p.studies["diagnosis"] = {{"thermal", t.toJson()}, {"matching", m.toJson()}};
  EXPECT_TRUE(checkStudies(p).empty()) << checkStudies(p).front().field;
  p.studies["diagnosis"]["thermal"]["train_fraction"] = 2;
  p.studies["diagnosis"]["matching"]["tolerance_mm"] = 0;
  const auto issues = checkStudies(p);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "studies.diagnosis.matching.tolerance_mm");
  EXPECT_EQ(issues[1].field, "studies.diagnosis.thermal.train_fraction");
}

}  // namespace
}  // namespace metrofit
