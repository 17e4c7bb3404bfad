// The shared preamble of the applied-effects parsers (core/diagnose/applied_entries.h): the list,
// object and name checks of studies.diagnosis.<domain>.applied[i] in the thermal, kinematic, setup
// and matching parsers. The messages are the ones the parsers gave before they shared the helper,
// byte for byte (the bad-input catalogue and the GUI show them).
#include "core/diagnose/applied_entries.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/diagnose/applied_kinematic.h"
#include "core/diagnose/applied_setup_matching.h"
#include "core/diagnose/thermal_applied.h"
#include "core/setup/model.h"

namespace metrofit::diagnose {
namespace {

using J = nlohmann::json;

/// what() of the ValidationError `f` throws ("no error" / "other error" otherwise).
std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ValidationError& e) {
    return e.what();
  } catch (...) {
    return "other error";
  }
  return "no error";
}

ThermalLog thermalLog() {
  ThermalLog log;
  log.source = "log.csv";
  log.timeColumn = "time_min";
  log.timeMin = {0.0, 1.0, 2.0};
  log.channels.push_back(ThermalChannel{"T2", "degC", {20.0, 21.0, 22.0}});
  log.channels.push_back(ThermalChannel{"disp_z_um", "um", {0.0, 1.0, 2.0}});
  return log;
}

std::string thermal(const J& applied) {
  const ThermalLog log = thermalLog();
  return messageOf([&] { (void)appliedThermalEffects(applied, log, "disp_z_um", {"T2"}); });
}
std::string kinematic(const J& applied, double feed = 1000.0) {
  return messageOf([&] { (void)axisEffectsFromApplied(applied, feed); });
}
std::string setupEffects(const J& applied) {
  const setup::Model model;
  return messageOf([&] { (void)parseAppliedSetupEffects(applied, model, "demo.metrofit"); });
}
std::string matching(const J& applied) {
  return messageOf([&] { (void)parseAppliedMatchingEffects(applied, "demo.metrofit"); });
}

TEST(AppliedEntries, ThermalPreambleMessages) {
  EXPECT_EQ(thermal(J::parse(R"({"name": "drift"})")),
            "field 'studies.diagnosis.thermal.applied': must be a list of {\"name\", \"parameters\"}");
  EXPECT_EQ(thermal(J::parse(R"([{"name": "drift"}, 42])")),
            "field 'studies.diagnosis.thermal.applied[1]': must be an object {\"name\", \"parameters\"}");
  EXPECT_EQ(
      thermal(J::parse(R"([{"parameters": {}}])")),
      "field 'studies.diagnosis.thermal.applied[0].name': must be the effect's name (lag, lag:<column>, "
      "input:<column>, drift, unexplained:<variable>)");
  EXPECT_EQ(
      thermal(J::parse(R"([{"name": 7}])")),
      "field 'studies.diagnosis.thermal.applied[0].name': must be the effect's name (lag, lag:<column>, "
      "input:<column>, drift, unexplained:<variable>)");
  EXPECT_EQ(thermal(J::parse(R"([{"name": ""}])")),
            "field 'studies.diagnosis.thermal.applied[0].name': unknown thermal effect '' (known: lag, "
            "lag:<column>, input:<column>, drift, unexplained:<variable>)");
  EXPECT_EQ(thermal(J::parse(R"([{"name": "drift"}, {"name": "drift"}])")),
            "field 'studies.diagnosis.thermal.applied[1].name': the effect 'drift' is applied twice");
  EXPECT_EQ(thermal(J()), "no error");
  EXPECT_EQ(thermal(J::array()), "no error");
}

TEST(AppliedEntries, KinematicPreambleMessages) {
  EXPECT_EQ(kinematic(J::parse(R"("backlash")")),
            "field 'studies.diagnosis.kinematic.applied': must be a list of {\"name\", \"parameters\"}");
  // The feed is checked after the list, before the entries (also for an empty list).
  EXPECT_EQ(kinematic(J::parse(R"("backlash")"), -1.0),
            "field 'studies.diagnosis.kinematic.applied': must be a list of {\"name\", \"parameters\"}");
  EXPECT_EQ(kinematic(J::array(), -1.0),
            "field 'studies.diagnosis.kinematic.feed_mm_per_min': must be a positive feed (mm/min)");
  EXPECT_EQ(kinematic(J::parse(R"([42])"), -1.0),
            "field 'studies.diagnosis.kinematic.feed_mm_per_min': must be a positive feed (mm/min)");
  EXPECT_EQ(kinematic(J::parse(R"([[1]])")),
            "field 'studies.diagnosis.kinematic.applied[0]': must be an object {\"name\", \"parameters\"}");
  EXPECT_EQ(
      kinematic(J::parse(R"([{"name": null}])")),
      "field 'studies.diagnosis.kinematic.applied[0].name': must be the effect's name (backlash, scale, "
      "cyclic, servo_lag, unexplained:<variable>)");
  EXPECT_EQ(
      kinematic(J::parse(R"([{"parameters": {"x_mm": 1}}])")),
      "field 'studies.diagnosis.kinematic.applied[0].name': must be the effect's name (backlash, scale, "
      "cyclic, servo_lag, unexplained:<variable>)");
  EXPECT_EQ(kinematic(J::parse(R"([{"name": ""}])")),
            "field 'studies.diagnosis.kinematic.applied[0].name': unknown kinematic effect '' (known: "
            "backlash, scale, cyclic, servo_lag, unexplained:<variable>)");
  EXPECT_EQ(kinematic(J::parse(R"([{"name": "scale", "parameters": {"x_ppm": 1, "y_ppm": 2}},
                                   {"name": "scale", "parameters": {"x_ppm": 1, "y_ppm": 2}}])")),
            "field 'studies.diagnosis.kinematic.applied[1].name': the effect 'scale' is applied twice");
  EXPECT_EQ(kinematic(J()), "no error");
  EXPECT_EQ(kinematic(J(), -1.0), "no error");
}

TEST(AppliedEntries, SetupPreambleMessages) {
  EXPECT_EQ(setupEffects(J::object()),
            "demo.metrofit: field 'studies.diagnosis.setup.applied': must be a list of effects");
  EXPECT_EQ(setupEffects(J::parse(R"(["tool_wear:T1"])")),
            "demo.metrofit: field 'studies.diagnosis.setup.applied[0]': must be an object {\"name\": ..., "
            "\"parameters\": {...}}");
  EXPECT_EQ(setupEffects(J::parse(R"([{"parameters": {}}])")),
            "demo.metrofit: field 'studies.diagnosis.setup.applied[0].name': is missing");
  EXPECT_EQ(setupEffects(J::parse(R"([{"name": 3}])")),
            "demo.metrofit: field 'studies.diagnosis.setup.applied[0].name': must be the name of an effect "
            "(text)");
  EXPECT_EQ(setupEffects(J::parse(R"([{"name": ""}])")),
            "demo.metrofit: field 'studies.diagnosis.setup.applied[0].name': must be the name of an effect "
            "(text)");
  EXPECT_EQ(setupEffects(J::parse(R"([{"name": "wobble"}])")),
            "demo.metrofit: field 'studies.diagnosis.setup.applied[0].name': 'wobble' is not a setup effect "
            "(tool_wear:<tool>, drift:<setup datum> or unexplained:<variable>)");
  EXPECT_EQ(setupEffects(J()), "no error");
}

TEST(AppliedEntries, MatchingPreambleMessages) {
  EXPECT_EQ(matching(J(1.5)),
            "demo.metrofit: field 'studies.diagnosis.matching.applied': must be a list of effects");
  EXPECT_EQ(matching(J::parse(R"([{"name": "scale", "parameters": {"ppm": 3}}, null])")),
            "demo.metrofit: field 'studies.diagnosis.matching.applied[1]': must be an object {\"name\": ..., "
            "\"parameters\": {...}}");
  EXPECT_EQ(matching(J::parse(R"([{}])")),
            "demo.metrofit: field 'studies.diagnosis.matching.applied[0].name': is missing");
  EXPECT_EQ(
      matching(J::parse(R"([{"name": ["scale"]}])")),
      "demo.metrofit: field 'studies.diagnosis.matching.applied[0].name': must be the name of an effect "
      "(text)");
  EXPECT_EQ(matching(J::parse(R"([{"name": "scale", "parameters": {"ppm": 3}},
                                  {"name": "scale", "parameters": {"ppm": 3}}])")),
            "demo.metrofit: field 'studies.diagnosis.matching.applied[1].name': 'scale' is applied twice");
  EXPECT_EQ(matching(J::parse(R"([{"name": "scale"}])")),
            "demo.metrofit: field 'studies.diagnosis.matching.applied[0].parameters': is missing");
  EXPECT_EQ(matching(J::array()), "no error");
}

TEST(AppliedEntries, HelperVisitsEveryEntryInOrder) {
  std::vector<std::string> seen;
  forEachAppliedEntry(J::parse(R"([{"name": "a", "parameters": {"x": 1}}, {"name": ""}])"), "f",
                      appliedMessagesKnown("a, b"), [&](const AppliedEntry& e) {
                        seen.push_back(std::to_string(e.index) + " " + e.name + " " + e.field + " " +
                                       e.at("parameters.x") + " " + e.json.dump());
                      });
  EXPECT_EQ(seen,
            (std::vector<std::string>{"0 a f[0] f[0].parameters.x {\"name\":\"a\",\"parameters\":{\"x\":1}}",
                                      "1  f[1] f[1].parameters.x {\"name\":\"\"}"}));
  int calls = 0;
  forEachAppliedEntry(J(), "f", appliedMessagesOf("p.metrofit"), [&](const AppliedEntry&) { ++calls; });
  EXPECT_EQ(calls, 0);
  // Entries before a bad one are visited; the bad one stops the walk.
  EXPECT_EQ(messageOf([&] {
              forEachAppliedEntry(J::parse(R"([{"name": "a"}, {"name": ""}])"), "f",
                                  appliedMessagesOf("p.metrofit"), [&](const AppliedEntry&) { ++calls; });
            }),
            "p.metrofit: field 'f[1].name': must be the name of an effect (text)");
  EXPECT_EQ(calls, 1);
  EXPECT_FALSE(isAppliedList(J(), "f", appliedMessagesOf("p")));
  EXPECT_TRUE(isAppliedList(J::array(), "f", appliedMessagesOf("p")));
  EXPECT_EQ(appliedEntryField("f", 3), "f[3]");
  EXPECT_EQ(appliedEntryField("f", 3, "name"), "f[3].name");
}

}  // namespace
}  // namespace metrofit::diagnose
