// The setup closed loop (core/diagnose/setup_diagnosis.h) on series from core/sim/effects_setup.h.
#include "core/diagnose/setup_diagnosis.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/setup/report.h"
#include "core/sim/effects_setup.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

setup::Model paperModel() {
  return setup::readModel((test::sourceDir() / "resources/demo/setup/paper_example.json").string());
}

/// Noise of the series: uniform in +-w2, sigma = w2 / sqrt(3).
constexpr double kW2 = 0.01;
const double kSigma = kW2 / std::sqrt(3.0);
constexpr int kParts = 10;

SetupEffectsSimOptions baseOptions(std::uint64_t seed) {
  SetupEffectsSimOptions o;
  o.base.w1 = 0.03;
  o.base.w2 = kW2;
  o.base.parts = kParts;
  o.base.minutesPerPart = 12.0;
  o.base.resolutionMm = 0.0001;
  o.base.seed = seed;
  return o;
}

Diagnosis run(const setup::Model& model, const SetupEffectsSimOptions& o) {
  const std::string csv = simulateSetupEffectsReport(model, o);
  const setup::Measurements m = setup::cmmReportFromCsv(parseCsv(csv, "sim.csv"), model);
  return diagnoseSetup(model, m);
}

const Candidate* find(const Diagnosis& d, const std::string& name) {
  for (const Candidate& c : d.effects)
    if (c.name == name) return &c;
  return nullptr;
}

double value(const Candidate& c) {
  return std::get<double>(c.parameters.front().value);
}

TEST(SetupDiagnosis, FindsToolWearAtEffectToNoiseFive) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(3);
  const double rate = 5.0 * kSigma / (kParts - 1);  // change over the series = 5 sigma
  o.toolWearMmPerPart = {{"T23", rate}};
  const Diagnosis d = run(model, o);
  ASSERT_EQ(d.accepted().size(), 1u);
  const Candidate& c = *d.accepted().front();
  EXPECT_EQ(c.name, "tool_wear:T23");
  EXPECT_NEAR(value(c), rate, 0.3 * rate);
  ASSERT_TRUE(c.parameters.front().standardError);
  EXPECT_GT(*c.parameters.front().standardError, 0.0);
  EXPECT_EQ(c.parameters.front().name, "mm_per_part");
  EXPECT_LT(d.final.rmse, d.baseline.rmse);
  EXPECT_NEAR(d.final.rmse, kSigma, 0.25 * kSigma);
  ASSERT_TRUE(c.plot);
  EXPECT_EQ(c.plot->xLabel, "part");
  EXPECT_EQ(c.plot->x.size(), static_cast<std::size_t>(kParts));
  // Every candidate appears once: 2 tool wear + 10 drift.
  EXPECT_EQ(d.effects.size(), 12u);
}

TEST(SetupDiagnosis, FindsDriftOfAWorkOffset) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(5);
  SetupEffectsTruth truth;
  (void)simulateSetupEffectsReport(model, o, &truth);
  const double span = truth.timeMin.back() - truth.timeMin.front();
  const double rate = 5.0 * kSigma / span;
  o.driftMmPerMin = {{"W3", rate}};
  const Diagnosis d = run(model, o);
  ASSERT_EQ(d.accepted().size(), 1u);
  const Candidate& c = *d.accepted().front();
  EXPECT_EQ(c.name, "drift:W3");
  EXPECT_EQ(c.parameters.front().name, "mm_per_min");
  EXPECT_NEAR(value(c), rate, 0.3 * rate);
  EXPECT_EQ(c.plot->xLabel, "time (min)");
}

TEST(SetupDiagnosis, CleanDataStayCleanOverSeeds) {
  const setup::Model model = paperModel();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Diagnosis d = run(model, baseOptions(seed));
    EXPECT_TRUE(d.accepted().empty())
        << "seed " << seed << ": " << d.accepted().front()->name << " " << d.accepted().front()->evidence;
    EXPECT_DOUBLE_EQ(d.final.rmse, d.baseline.rmse);
  }
}

TEST(SetupDiagnosis, FindsTwoEffectsBoth) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(11);
  SetupEffectsTruth truth;
  (void)simulateSetupEffectsReport(model, o, &truth);
  const double wear = 8.0 * kSigma / (kParts - 1);
  const double drift = 8.0 * kSigma / (truth.timeMin.back() - truth.timeMin.front());
  o.toolWearMmPerPart = {{"T5", wear}};
  o.driftMmPerMin = {{"W6", -drift}};
  const Diagnosis d = run(model, o);
  ASSERT_EQ(d.accepted().size(), 2u);
  const Candidate* w = find(d, "tool_wear:T5");
  const Candidate* r = find(d, "drift:W6");
  ASSERT_TRUE(w && r);
  EXPECT_TRUE(w->accepted);
  EXPECT_TRUE(r->accepted);
  EXPECT_NEAR(value(*w), wear, 0.3 * wear);
  EXPECT_NEAR(value(*r), -drift, 0.3 * drift);
  EXPECT_EQ(d.accepted()[1]->round, 1);
  EXPECT_NEAR(d.final.rmse, kSigma, 0.25 * kSigma);
}

TEST(SetupDiagnosis, JsonHasTheContractKeys) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(3);
  o.toolWearMmPerPart = {{"T23", 0.004}};
  const nlohmann::json j = toJson(run(model, o));
  EXPECT_EQ(j["domain"], "setup");
  EXPECT_TRUE(j["baseline"].contains("rmse"));
  EXPECT_TRUE(j["baseline"].contains("max_abs"));
  EXPECT_FALSE(j["baseline"].contains("heldout_rmse"));
  EXPECT_EQ(j["effects"][0]["name"], "tool_wear:T23");
  EXPECT_EQ(j["effects"][0]["accepted"], true);
  EXPECT_TRUE(j["effects"][0]["parameters"].contains("mm_per_part"));
  EXPECT_LT(j["final"]["rmse"].get<double>(), j["baseline"]["rmse"].get<double>());
}

TEST(SetupDiagnosis, SinglePartHasNothingIdentifiable) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(2);
  o.base.parts = 1;
  o.toolWearMmPerPart = {{"T23", 0.01}};
  const Diagnosis d = run(model, o);
  EXPECT_TRUE(d.accepted().empty());
  for (const Candidate& c : d.effects)
    EXPECT_NE(c.evidence.find("not identifiable"), std::string::npos) << c.name;
}

TEST(SetupDiagnosis, TimeProportionalToPartCannotTellWearFromDrift) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(4);
  o.timeJitter = 0.0;
  o.toolWearMmPerPart = {{"T23", 0.005}};
  const Diagnosis d = run(model, o);
  ASSERT_EQ(d.accepted().size(), 1u);
  EXPECT_EQ(d.accepted().front()->name, "tool_wear:T23");
  EXPECT_NE(d.accepted().front()->evidence.find("indistinguishable from drift:T23"), std::string::npos);
}

TEST(SetupDiagnosis, BadInputs) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(1);
  o.toolWearMmPerPart = {{"W1", 0.001}};  // not a tool
  EXPECT_THROW(simulateSetupEffectsReport(model, o), OptionsError);
  o.toolWearMmPerPart.clear();
  o.driftMmPerMin = {{"W99", 0.001}};
  EXPECT_THROW(simulateSetupEffectsReport(model, o), OptionsError);
  o.driftMmPerMin.clear();
  o.timeJitter = 1.5;
  EXPECT_THROW(simulateSetupEffectsReport(model, o), OptionsError);

  const setup::Measurements m =
      setup::cmmReportFromCsv(parseCsv(simulateSetupEffectsReport(model, baseOptions(1)), "s.csv"), model);
  SetupDiagnosisOptions bad;
  bad.acceptance.minRelativeReduction = 1.5;
  EXPECT_THROW(diagnoseSetup(model, m, bad), OptionsError);
  setup::Measurements empty;
  EXPECT_THROW(diagnoseSetup(model, empty), ValidationError);
}

TEST(SetupDiagnosis, ObserverCanCancel) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(11);
  o.toolWearMmPerPart = {{"T5", 0.01}};
  o.driftMmPerMin = {{"W6", 0.0005}};
  const setup::Measurements m =
      setup::cmmReportFromCsv(parseCsv(simulateSetupEffectsReport(model, o), "s.csv"), model);
  int calls = 0;
  FunctionObserver stop([&](const IterationSummary&) {
    ++calls;
    return ObserverDecision::Stop;
  });
  const Diagnosis d = diagnoseSetup(model, m, {}, &stop);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(d.accepted().size(), 1u);
}

TEST(SetupDiagnosis, SimulatorIsDeterministicBySeed) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o = baseOptions(9);
  o.toolWearMmPerPart = {{"T23", 0.002}};
  EXPECT_EQ(simulateSetupEffectsReport(model, o), simulateSetupEffectsReport(model, o));
  SetupEffectsSimOptions o2 = o;
  o2.base.seed = 10;
  EXPECT_NE(simulateSetupEffectsReport(model, o), simulateSetupEffectsReport(model, o2));
}

/// The demo's setup data with one undeclared effect (resources/demo/README.md): the paper model,
/// 12 parts, tool T23 wearing by 0.002 mm per part, seed 8. METROFIT_WRITE_DEMO=1 rewrites the file.
TEST(SetupDiagnosis, DemoReportIsTheDocumentedSimulationWithToolWear) {
  const setup::Model model = paperModel();
  SetupEffectsSimOptions o;
  o.base.w1 = 0.03;
  o.base.w2 = 0.01;
  o.base.parts = 12;
  o.base.minutesPerPart = 12.0;
  o.base.resolutionMm = 0.001;
  o.base.seed = 8;
  o.timeJitter = 0.5;
  o.toolWearMmPerPart = {{"T23", 0.002}};
  const std::string text = simulateSetupEffectsReport(model, o);
  const std::string path = (test::sourceDir() / "resources/demo/data/diagnose_setup_report.csv").string();
  if (test::env("METROFIT_WRITE_DEMO") == "1") test::writeText(path, text);
  EXPECT_EQ(test::readText(path), text);
  const Diagnosis d = diagnoseSetup(model, setup::readCmmReport(path, model));
  ASSERT_EQ(d.accepted().size(), 1u);
  EXPECT_EQ(d.accepted().front()->name, "tool_wear:T23");
  EXPECT_NEAR(value(*d.accepted().front()), 0.002, 0.0006);
}

}  // namespace
}  // namespace metrofit::diagnose
