// studies.kinematics has one owner (KinematicsSettings, core/study/study_settings.h): its defaults, a round
// trip of every key, every bad value refused naming its field (by fromJson and by the project validator
// alike), and the study's reader (kinematicStudySettings) taking its values from it.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/common/error.h"
#include "core/kinematics/spc_actuator.h"
#include "core/project/project.h"
#include "core/spc/spc.h"
#include "core/study/kinematic_study.h"
#include "core/study/study_check.h"
#include "core/study/study_settings.h"

namespace metrofit {
namespace {

using json = nlohmann::json;

/// The field of the ValidationError `fn` throws ("" when it does not throw).
std::string refusedField(const std::function<void()>& fn, std::string* message = nullptr) {
  try {
    fn();
  } catch (const ValidationError& e) {
    if (message) *message = e.detail();
    return e.context().field;
  }
  return {};
}

Project projectWith(const json& study) {
  Project p;
  p.datasets.push_back({"circle", dataset_kind::kCircularTest, "c.csv", "", "", {}});
  p.datasets.push_back({"bores", dataset_kind::kFeatureSeries, "b.csv", "", "", {}});
  p.datasets.push_back({"edge_x", dataset_kind::kFeatureSeries, "x.csv", "", "", {}});
  p.datasets.push_back({"edge_y", dataset_kind::kFeatureSeries, "y.csv", "", "", {}});
  p.studies["kinematics"] = study;
  return p;
}

KinematicsSettings everyKey() {
  KinematicsSettings k;
  k.dataset = "circle";
  k.simulatedMachine = KinematicsSettings::SimulatedMachine{0.01, -0.02, 0.003, -0.004};
  KinematicsSettings::Spc spc;
  spc.dataset = "bores";
  spc.column = "diameter_mm";
  spc.subgroup = 4;
  spc.lsl = 9.98;
  spc.usl = 10.02;
  spc.nominal = 10.0;
  spc.coverage = 3.0;
  k.spc = spc;
  KinematicsSettings::FromSpc f;
  f.xDataset = "edge_x";
  f.yDataset = "edge_y";
  f.positionColumn = "pos_mm";
  f.deviationColumn = "dev_mm";
  f.xNominalY = 5.0;
  f.yNominalX = -5.0;
  f.subgroup = 6;
  f.coverage = 2.5;
  k.fromSpc = f;
  k.planes = std::array<std::string, 3>{"circle", "edge_x", "edge_y"};
  return k;
}

TEST(KinematicsSettings, DefaultsAreTheMethodsOwnAndWriteNothing) {
  const KinematicsSettings d;
  EXPECT_EQ(d.toJson(), json::object());
  EXPECT_EQ(KinematicsSettings::fromJson(json()), d);
  EXPECT_EQ(KinematicsSettings::fromJson(json::object()), d);
  EXPECT_EQ(KinematicsSettings::Spc{}.subgroup, SpcOptions{}.subgroupSize);
  EXPECT_EQ(KinematicsSettings::Spc{}.coverage, SpcOptions{}.coverageFactor);
  EXPECT_EQ(KinematicsSettings::FromSpc{}.subgroup, SpcActuatorOptions{}.subgroupSize);
  EXPECT_EQ(KinematicsSettings::FromSpc{}.coverage, SpcActuatorOptions{}.coverageFactor);
  EXPECT_EQ(KinematicsSettings::FromSpc{}.positionColumn, "position_mm");
  EXPECT_EQ(KinematicsSettings::FromSpc{}.deviationColumn, "deviation_mm");
  // A block with only its required keys reads the defaults of the rest.
  const KinematicsSettings k = KinematicsSettings::fromJson(
      {{"spc", {{"dataset", "bores"}, {"column", "d_mm"}}}, {"from_spc", json::object()}});
  ASSERT_TRUE(k.spc && k.fromSpc);
  EXPECT_EQ(k.spc->subgroup, 5);
  EXPECT_EQ(k.spc->coverage, 2.0);
  EXPECT_FALSE(k.spc->lsl || k.spc->usl || k.spc->nominal);
  EXPECT_EQ(*k.fromSpc, KinematicsSettings::FromSpc{});
  EXPECT_EQ(k.toJson(),
            json({{"spc", {{"dataset", "bores"}, {"column", "d_mm"}}}, {"from_spc", json::object()}}));
  std::string field, why;
  EXPECT_TRUE(d.isValid(&field, &why)) << field << ": " << why;
}

TEST(KinematicsSettings, EveryKeyRoundTripsAndTheValidatorAcceptsIt) {
  const KinematicsSettings k = everyKey();
  const json j = k.toJson();
  EXPECT_EQ(KinematicsSettings::fromJson(j), k);
  EXPECT_EQ(j.at("spc").at("subgroup"), 4);
  EXPECT_EQ(j.at("from_spc").at("position_column"), "pos_mm");
  EXPECT_EQ(j.at("planes").at("zx"), "edge_y");
  std::string field, why;
  EXPECT_TRUE(k.isValid(&field, &why)) << field << ": " << why;
  const Project p = projectWith(j);
  const auto issues = checkStudies(p);
  EXPECT_TRUE(issues.empty()) << issues.front().field << ": " << issues.front().message;

  // The study's reader converts the same values.
  const KinematicStudySettings s = kinematicStudySettings(p);
  EXPECT_EQ(s.dataset, "circle");
  ASSERT_TRUE(s.simulatedMachine && s.spc && s.fromSpc && s.planes);
  EXPECT_DOUBLE_EQ(s.simulatedMachine->originMm.y(), -0.02);
  EXPECT_DOUBLE_EQ(s.simulatedMachine->yAxisAngleDeg, -0.004);
  EXPECT_EQ(s.spc->options.subgroupSize, 4);
  EXPECT_EQ(*s.spc->options.usl, 10.02);
  EXPECT_EQ(s.spc->options.coverageFactor, 3.0);
  EXPECT_EQ(s.fromSpc->positionColumn, "pos_mm");
  EXPECT_EQ(s.fromSpc->options.subgroupSize, 6);
  EXPECT_EQ(s.fromSpc->options.coverageFactor, 2.5);
  EXPECT_EQ((*s.planes)[2], "edge_y");
  // Without the study: the defaults (the same type's).
  const KinematicStudySettings none = kinematicStudySettings(Project{});
  EXPECT_FALSE(none.spc || none.fromSpc || none.planes || none.simulatedMachine);
}

struct BadValue {
  json study;
  std::string field;
};

TEST(KinematicsSettings, EveryBadValueIsRefusedNamingItsFieldByTheTypeAndTheValidator) {
  const json spc = {{"dataset", "bores"}, {"column", "diameter_mm"}};
  const auto withSpc = [&](const char* key, const json& v) {
    json b = spc;
    b[key] = v;
    return json{{"spc", b}};
  };
  const json machine = {{"origin_mm", {0.0, 0.0}}, {"x_axis_angle_deg", 0.0}, {"y_axis_angle_deg", 0.0}};
  const auto withMachine = [&](const char* key, const json& v) {
    json b = machine;
    if (v.is_discarded())
      b.erase(key);
    else
      b[key] = v;
    return json{{"simulated_machine", b}};
  };
  const std::vector<BadValue> bad = {
      {json(5), "studies.kinematics"},
      {{{"dataset", 5}}, "studies.kinematics.dataset"},
      {{{"datset", "circle"}}, "studies.kinematics.datset"},
      {withSpc("subgroup", 0), "studies.kinematics.spc.subgroup"},
      {withSpc("subgroup", 1), "studies.kinematics.spc.subgroup"},
      {withSpc("subgroup", 26), "studies.kinematics.spc.subgroup"},
      {withSpc("subgroup", "abc"), "studies.kinematics.spc.subgroup"},
      {withSpc("subgroup", 4.5), "studies.kinematics.spc.subgroup"},
      {withSpc("coverage", 0), "studies.kinematics.spc.coverage"},
      {withSpc("coverage", "two"), "studies.kinematics.spc.coverage"},
      {withSpc("nominal", "ten"), "studies.kinematics.spc.nominal"},
      {withSpc("lsl", 9.9), "studies.kinematics.spc.usl"},
      {withSpc("usl", 10.1), "studies.kinematics.spc.lsl"},
      {withSpc("column", ""), "studies.kinematics.spc.column"},
      {withSpc("dataset", 3), "studies.kinematics.spc.dataset"},
      {withSpc("chart", "xbar"), "studies.kinematics.spc.chart"},
      {{{"spc", {{"column", "d"}}}}, "studies.kinematics.spc.dataset"},
      {{{"spc", {{"dataset", "bores"}}}}, "studies.kinematics.spc.column"},
      {{{"spc", {{"dataset", "bores"}, {"column", "d"}, {"lsl", 2}, {"usl", 1}}}},
       "studies.kinematics.spc.lsl"},
      {{{"spc", "bores"}}, "studies.kinematics.spc"},
      {{{"from_spc", {{"subgroup", 0}}}}, "studies.kinematics.from_spc.subgroup"},
      {{{"from_spc", {{"subgroup", "abc"}}}}, "studies.kinematics.from_spc.subgroup"},
      {{{"from_spc", {{"coverage", -1}}}}, "studies.kinematics.from_spc.coverage"},
      {{{"from_spc", {{"x_nominal_y", "0"}}}}, "studies.kinematics.from_spc.x_nominal_y"},
      {{{"from_spc", {{"y_nominal_x", true}}}}, "studies.kinematics.from_spc.y_nominal_x"},
      {{{"from_spc", {{"position_column", ""}}}}, "studies.kinematics.from_spc.position_column"},
      {{{"from_spc", {{"deviation_column", 1}}}}, "studies.kinematics.from_spc.deviation_column"},
      {{{"from_spc", {{"x_dataset", ""}}}}, "studies.kinematics.from_spc.x_dataset"},
      {{{"from_spc", {{"y_dataset", 2}}}}, "studies.kinematics.from_spc.y_dataset"},
      {{{"planes", {{"yz", ""}}}}, "studies.kinematics.planes.yz"},
      {{{"planes", {{"xz", "circle"}}}}, "studies.kinematics.planes.xz"},
      {withMachine("origin_mm", {1.0}), "studies.kinematics.simulated_machine.origin_mm"},
      {withMachine("x_axis_angle_deg", 60.0), "studies.kinematics.simulated_machine.x_axis_angle_deg"},
      {withMachine("y_axis_angle_deg", "b"), "studies.kinematics.simulated_machine.y_axis_angle_deg"},
      {withMachine("y_axis_angle_deg", json(json::value_t::discarded)),
       "studies.kinematics.simulated_machine.y_axis_angle_deg"},
      {withMachine("z_axis_angle_deg", 0.0), "studies.kinematics.simulated_machine.z_axis_angle_deg"},
  };
  for (const BadValue& b : bad) {
    std::string message;
    EXPECT_EQ(refusedField([&] { KinematicsSettings::fromJson(b.study, "cell.metrofit"); }, &message),
              b.field)
        << b.study.dump();
    EXPECT_FALSE(message.empty());
    // The study's reader refuses it the same way (never a default in its place) ...
    const Project p = projectWith(b.study);
    EXPECT_EQ(refusedField([&] { kinematicStudySettings(p); }), b.field) << b.study.dump();
    // ... and so does the project validator, with the same message.
    const auto issues = checkStudies(p);
    ASSERT_FALSE(issues.empty()) << b.study.dump();
    EXPECT_EQ(issues.front().field, b.field) << b.study.dump();
    EXPECT_EQ(issues.front().message, message) << b.study.dump();
  }
}

TEST(KinematicsSettings, IsValidNamesTheFieldOfABadValue) {
  std::string field, why;
  KinematicsSettings k = everyKey();
  k.spc->subgroup = 0;
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.spc.subgroup");
  k = everyKey();
  k.spc->lsl = 11.0;
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.spc.lsl");
  k = everyKey();
  k.spc->usl.reset();
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.spc.usl");
  k = everyKey();
  k.fromSpc->coverage = 0.0;
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.from_spc.coverage");
  k = everyKey();
  k.simulatedMachine->yAxisAngleDeg = 90.0;
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.simulated_machine.y_axis_angle_deg");
  k = everyKey();
  k.spc->column.clear();
  EXPECT_FALSE(k.isValid(&field, &why));
  EXPECT_EQ(field, "studies.kinematics.spc.column");
}

// The applied effects the kinematics study includes are read through the diagnosis block's one owner
// (DiagnosisDomainSettings): its feed and its checks, no second parser in core/diagnose.
TEST(KinematicsSettings, AppliedEffectsAreReadThroughTheDiagnosisSettings) {
  Project p = projectWith(json::object());
  const json lag = json::parse(R"([{"name": "servo_lag", "parameters": {"tau_s": 0.002}}])");
  p.studies["diagnosis"] = {
      {"kinematic", {{"dataset", "circle"}, {"feed_mm_per_min", 2500.0}, {"applied", lag}}}};
  AxisEffects fx = projectAxisEffects(p, "circle");
  ASSERT_FALSE(fx.empty());
  EXPECT_DOUBLE_EQ(fx.base.servoLagS, 0.002);
  EXPECT_DOUBLE_EQ(fx.base.feedMmPerMin, 2500.0);
  EXPECT_TRUE(projectAxisEffects(p, "bores").empty());  // estimated on another test

  p.studies["diagnosis"]["kinematic"].erase("feed_mm_per_min");
  fx = projectAxisEffects(p, "circle");
  EXPECT_DOUBLE_EQ(fx.base.feedMmPerMin, DiagnosisDomainSettings{}.feedMmPerMin);

  // A bad value is refused with the field the settings type names, never replaced by the default.
  p.studies["diagnosis"]["kinematic"]["feed_mm_per_min"] = 0;
  EXPECT_EQ(refusedField([&] { projectAxisEffects(p, "circle", "p.metrofit"); }),
            "studies.diagnosis.kinematic.feed_mm_per_min");
  p.studies["diagnosis"]["kinematic"]["feed_mm_per_min"] = "fast";
  EXPECT_EQ(refusedField([&] { projectAxisEffects(p, "circle"); }),
            "studies.diagnosis.kinematic.feed_mm_per_min");
  p.studies["diagnosis"]["kinematic"]["feed_mm_per_min"] = 1500.0;
  p.studies["diagnosis"]["kinematic"]["tolerance_mm"] = 0.01;  // a matching key
  EXPECT_EQ(refusedField([&] { projectAxisEffects(p, "circle"); }),
            "studies.diagnosis.kinematic.tolerance_mm");

  // Nothing applied: the diagnosis's half-set controls do not concern the kinematics study.
  p.studies["diagnosis"] = {{"kinematic", {{"feed_mm_per_min", 0}}}};
  EXPECT_TRUE(projectAxisEffects(p, "circle").empty());
  EXPECT_EQ(kinematicStoredSettings(p, "circle").at("applied"), "");
}

}  // namespace
}  // namespace metrofit
