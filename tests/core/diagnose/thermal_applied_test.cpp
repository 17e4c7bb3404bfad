// Applied thermal effects (core/diagnose/thermal_applied.h): the columns the closed loop adds are the
// ones the thermal models fit with once an effect is applied. On simulator data with one undeclared
// effect (input:spindle_rpm) the three models fitted without the applied effect leave the held-out
// error E0, with it E1: a few percent of E0, and GNNMCI's close to the diagnosis' own error after the
// effect. On the demo's diagnosis log (lag:T2) the grey models' own first-order dynamics already hold
// the lag (documented below), so the thermal study (fitDeclaredAndWithEffects) keeps the declared
// inputs wherever the effect would raise the held-out error, and the effect for all three models on
// the simulator data. Bad applied entries are ValidationErrors naming the field.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>

#include "core/common/error.h"
#include "core/diagnose/thermal_applied.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/io/csv.h"
#include "core/sim/effects_thermal.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_model.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

const std::vector<std::string> kDeclared{"T2", "T4", "T_amb"};

ThermalLog demoLog() {
  return readThermalLog((test::sourceDir() / "resources/demo/data/diagnose_thermal.csv").string());
}

/// The applied list as the diagnosis page's Apply stores it (widgets/diagnose appliedEffects).
nlohmann::json appliedOf(const Diagnosis& d) {
  nlohmann::json out = nlohmann::json::array();
  for (const Candidate* c : d.accepted()) {
    nlohmann::json params = nlohmann::json::object();
    for (const Parameter& p : c->parameters)
      if (const double* v = std::get_if<double>(&p.value)) params[p.name] = *v;
    out.push_back({{"name", c->name}, {"parameters", params}});
  }
  return out;
}

std::string fieldOf(const nlohmann::json& applied, const ThermalLog& log) {
  try {
    (void)appliedThermalEffects(applied, log, "disp_z_um", kDeclared);
  } catch (const ValidationError& e) {
    return e.context().field;
  }
  return "(no error)";
}

TEST(ThermalApplied, RegressorsAreTheDiagnosisColumns) {
  const ThermalLog log = demoLog();
  ThermalEffectSet fx;
  fx.lagCol["T2"] = 15.0;
  fx.extra = {"spindle_rpm"};
  fx.drift = true;
  const std::vector<ThermalRegressor> r = thermalRegressors(log, kDeclared, fx);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0].name, "T2");
  EXPECT_EQ(r[0].channel, "lag:T2");
  EXPECT_DOUBLE_EQ(r[0].lagMin, 15.0);
  EXPECT_EQ(r[0].values, firstOrderLag(log.channel("T2").values, log.timeMin, 15.0));
  EXPECT_EQ(r[1].channel, "T4");
  EXPECT_EQ(r[1].values, log.channel("T4").values);
  EXPECT_EQ(r[3].name, "input:spindle_rpm");
  EXPECT_DOUBLE_EQ(r[3].values[0], 0.0);
  EXPECT_EQ(r[4].name, "drift");
  EXPECT_EQ(r[4].unit, "min");
  EXPECT_DOUBLE_EQ(r[4].values.back(), log.timeMin.back() - log.timeMin.front());

  const ThermalLogWithEffects with = withThermalEffects(log, kDeclared, fx);
  EXPECT_EQ(with.inputs, (std::vector<std::string>{"lag:T2", "T4", "T_amb", "input:spindle_rpm", "drift"}));
  EXPECT_EQ(with.log.channels.size(), log.channels.size() + 3);
  EXPECT_EQ(with.log.channel("lag:T2").values, r[0].values);
}

/// Held-out rmse of each model (GNNMCI, GMC, MLP; seed 1, train fraction 0.5) on a series.
std::array<thermal::ThermalEvaluation, 3> fitAll(const thermal::ThermalSeries& s) {
  std::array<thermal::ThermalEvaluation, 3> out;
  const thermal::ThermalModelKind kinds[3] = {thermal::ThermalModelKind::Gnnmci,
                                              thermal::ThermalModelKind::Gmc, thermal::ThermalModelKind::Mlp};
  for (int i = 0; i < 3; ++i) {
    thermal::ThermalFitOptions fo;
    fo.model = kinds[i];
    fo.setSeed(1);
    out[static_cast<std::size_t>(i)] = thermal::fitAndEvaluate(s, 0.5, fo);
  }
  return out;
}

/// Each model (GNNMCI, GMC, MLP; seed 1, train fraction 0.5) fitted as the thermal study does with
/// applied effects: on the declared inputs and with the effects, the lower held-out RMSE kept.
std::array<ThermalVariantFit, 3> fitBoth(const thermal::ThermalSeries& declared,
                                         const thermal::ThermalSeries& withEffects) {
  std::array<ThermalVariantFit, 3> out;
  const thermal::ThermalModelKind kinds[3] = {thermal::ThermalModelKind::Gnnmci,
                                              thermal::ThermalModelKind::Gmc, thermal::ThermalModelKind::Mlp};
  for (int i = 0; i < 3; ++i) {
    thermal::ThermalFitOptions fo;
    fo.model = kinds[i];
    fo.setSeed(1);
    out[static_cast<std::size_t>(i)] = fitDeclaredAndWithEffects(declared, withEffects, 0.5, fo);
  }
  return out;
}

TEST(ThermalApplied, KeepsTheEffectsOnlyWhenTheHeldOutErrorFalls) {
  EXPECT_TRUE(keepsAppliedEffects(0.5, 0.4));
  EXPECT_FALSE(keepsAppliedEffects(0.4, 0.5));
  EXPECT_FALSE(keepsAppliedEffects(0.4, 0.4));  // ties: declared
  EXPECT_FALSE(keepsAppliedEffects(0.4, std::nan("")));
  EXPECT_FALSE(keepsAppliedEffects(0.4, HUGE_VAL));
  EXPECT_TRUE(keepsAppliedEffects(std::nan(""), 0.4));
}

TEST(ThermalApplied, UndeclaredInputAppliedToTheModelsGivesTheDiagnosisAfterError) {
  // Simulator data with one undeclared effect: the displacement also follows the spindle speed
  // (0.002 um/rpm), which the declared inputs T2, T4, T_amb omit.
  ThermalEffectsOptions so;
  so.seed = 7;
  so.extraInputs = {{"spindle_rpm", 0.002}};
  const ThermalLog log = simulateThermalEffects(so);
  ThermalDiagnosisOptions o;
  o.target = so.target;
  o.inputs = so.declaredInputs;
  const Diagnosis d = diagnoseThermal(log, o);
  ASSERT_EQ(d.accepted().size(), 1u) << toJson(d).dump(1);
  ASSERT_EQ(d.accepted()[0]->name, "input:spindle_rpm");
  const nlohmann::json applied = appliedOf(d);
  const double before = *d.baseline.heldoutRmse, after = *d.final.heldoutRmse;

  const AppliedThermalEffects a = appliedThermalEffects(applied, log, o.target, o.inputs);
  EXPECT_EQ(a.text(), "input:spindle_rpm");
  const ThermalLogWithEffects with = withThermalEffects(log, o.inputs, a.effects);
  EXPECT_EQ(with.inputs, (std::vector<std::string>{"T2", "T4", "T_amb", "input:spindle_rpm"}));
  const auto e0 = fitAll(thermal::selectThermalSeries(log, o.target, o.inputs));
  const auto e1 = fitAll(thermal::selectThermalSeries(with.log, o.target, with.inputs));
  std::cout << "held-out rmse (um) GNNMCI / GMC / MLP: declared " << e0[0].heldout.rmse << " / "
            << e0[1].heldout.rmse << " / " << e0[2].heldout.rmse << ", with input:spindle_rpm "
            << e1[0].heldout.rmse << " / " << e1[1].heldout.rmse << " / " << e1[2].heldout.rmse
            << "; diagnosis " << before << " -> " << after << "\n";
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_GT(e0[m].heldout.rmse, 2.0 * before) << m;  // the undeclared input is missed
    EXPECT_LT(e1[m].heldout.rmse, 0.05 * e0[m].heldout.rmse) << m;
    EXPECT_LT(e1[m].heldout.rmse, 8.0 * after) << m;
  }
  // GNNMCI, the paper's model, comes close to the diagnosis' error after the effect.
  EXPECT_NEAR(e1[0].heldout.rmse, after, 0.5 * after);
  // The thermal study fits both variants: the effect helps every model, so every model keeps it.
  const auto v = fitBoth(thermal::selectThermalSeries(log, o.target, o.inputs),
                         thermal::selectThermalSeries(with.log, o.target, with.inputs));
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_TRUE(v[m].usesEffects) << m;
    EXPECT_DOUBLE_EQ(v[m].kept().heldout.rmse, e1[m].heldout.rmse) << m;
    EXPECT_DOUBLE_EQ(v[m].declared.heldout.rmse, e0[m].heldout.rmse) << m;
  }
}

TEST(ThermalApplied, DemoLagIsAlreadyTheGreyModelsOwnDynamics) {
  // The demo's diagnosis log: T2 seen through a further 15 min lag. The closed loop's declared model
  // is static, so it finds lag:T2; the grey models GNNMCI(1,N) and GMC(1,N) are first-order lags of
  // their inputs themselves (time constant 1 / b1) and fit the declared inputs close to the
  // diagnosis' error after the lag. Applying the lag to them lags T2 twice: worse, not better
  // (measured and stated in the report: the user can undo the Apply).
  const ThermalLog log = demoLog();
  ThermalDiagnosisOptions o;
  o.target = "disp_z_um";
  o.inputs = kDeclared;
  const Diagnosis d = diagnoseThermal(log, o);
  ASSERT_EQ(d.accepted().size(), 1u);
  ASSERT_EQ(d.accepted()[0]->name, "lag:T2");
  const nlohmann::json applied = appliedOf(d);
  const double tau = applied[0]["parameters"]["tau_min"].get<double>();
  EXPECT_NEAR(tau, 15.0, 3.0);
  const double after = *d.final.heldoutRmse;
  const AppliedThermalEffects a = appliedThermalEffects(applied, log, o.target, o.inputs);
  EXPECT_EQ(a.text(), "lag:T2 (" + CsvWriter::formatNumber(tau, 3) + " min)");
  const ThermalLogWithEffects with = withThermalEffects(log, o.inputs, a.effects);
  const auto e0 = fitAll(thermal::selectThermalSeries(log, o.target, o.inputs));
  const auto e1 = fitAll(thermal::selectThermalSeries(with.log, o.target, with.inputs));
  std::cout << "demo held-out rmse (um) GNNMCI / GMC / MLP: declared " << e0[0].heldout.rmse << " / "
            << e0[1].heldout.rmse << " / " << e0[2].heldout.rmse << ", with " << a.text() << " "
            << e1[0].heldout.rmse << " / " << e1[1].heldout.rmse << " / " << e1[2].heldout.rmse
            << "; diagnosis " << *d.baseline.heldoutRmse << " -> " << after << "; GNNMCI 1/b1 "
            << 1.0 / e0[0].training.model.grey.b1 << " min\n";
  for (std::size_t m = 0; m < 2; ++m) {
    EXPECT_LT(e0[m].heldout.rmse, 2.0 * after) << m;
    EXPECT_NEAR(1.0 / e0[m].training.model.grey.b1, tau, 0.2 * tau) << m;
    EXPECT_GT(e1[m].heldout.rmse, e0[m].heldout.rmse) << m;
  }
  // The thermal study therefore fits both variants and keeps the declared one wherever the lag
  // would make the held-out error rise: with Apply no model is worse on the held-out rows.
  const auto v = fitBoth(thermal::selectThermalSeries(log, o.target, o.inputs),
                         thermal::selectThermalSeries(with.log, o.target, with.inputs));
  std::cout << "demo kept held-out rmse (um) GNNMCI / GMC / MLP: " << v[0].kept().heldout.rmse << " / "
            << v[1].kept().heldout.rmse << " / " << v[2].kept().heldout.rmse << "; uses " << a.text() << ": "
            << v[0].usesEffects << " / " << v[1].usesEffects << " / " << v[2].usesEffects << "\n";
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_DOUBLE_EQ(v[m].declared.heldout.rmse, e0[m].heldout.rmse) << m;  // same seed, same fit
    EXPECT_DOUBLE_EQ(v[m].withEffects.heldout.rmse, e1[m].heldout.rmse) << m;
    EXPECT_EQ(v[m].usesEffects, e1[m].heldout.rmse < e0[m].heldout.rmse) << m;
    EXPECT_LE(v[m].kept().heldout.rmse, e0[m].heldout.rmse) << m;
  }
  EXPECT_FALSE(v[0].usesEffects);
  EXPECT_FALSE(v[1].usesEffects);
  EXPECT_NEAR(v[0].kept().heldout.rmse, 0.387, 0.02);  // declared GNNMCI(1,N), not 0.458 with the lag
  EXPECT_NEAR(v[1].kept().heldout.rmse, 0.479, 0.02);  // declared GMC(1,N), not 17.5 with the lag
  EXPECT_NEAR(v[2].kept().heldout.rmse, 2.90, 0.15);   // MLP: 3.84 with the lag
}

TEST(ThermalApplied, BadEntriesNameTheField) {
  const ThermalLog log = demoLog();
  using J = nlohmann::json;
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "warp", "parameters": {}}])"), log),
            "studies.diagnosis.thermal.applied[0].name");
  EXPECT_EQ(
      fieldOf(J::parse(R"([{"name": "drift"}, {"name": "lag:T9", "parameters": {"tau_min": 5}}])"), log),
      "studies.diagnosis.thermal.applied[1].name");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "lag:T1", "parameters": {"tau_min": 5}}])"), log),
            "studies.diagnosis.thermal.applied[0].name");  // a column, but not an input
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "input:nope"}])"), log),
            "studies.diagnosis.thermal.applied[0].name");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "input:disp_z_um"}])"), log),
            "studies.diagnosis.thermal.applied[0].name");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "lag", "parameters": {"tau_min": -1}}])"), log),
            "studies.diagnosis.thermal.applied[0].parameters.tau_min");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "lag:T2"}])"), log),
            "studies.diagnosis.thermal.applied[0].parameters.tau_min");
  EXPECT_EQ(fieldOf(J::parse(R"([{"name": "drift"}, {"name": "drift"}])"), log),
            "studies.diagnosis.thermal.applied[1].name");
  EXPECT_EQ(fieldOf(J::parse(R"([42])"), log), "studies.diagnosis.thermal.applied[0]");
  EXPECT_EQ(fieldOf(J::parse(R"([{"parameters": {}}])"), log), "studies.diagnosis.thermal.applied[0].name");
  EXPECT_EQ(fieldOf(J::parse(R"({"name": "drift"})"), log), "studies.diagnosis.thermal.applied");
  try {
    (void)appliedThermalEffects(J::parse(R"([{"name": "warp"}])"), log, "disp_z_um", kDeclared);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()),
              "field 'studies.diagnosis.thermal.applied[0].name': unknown thermal effect 'warp' (known: lag, "
              "lag:<column>, input:<column>, drift)");
  }
  // Nothing applied; an input column that already is an input adds nothing.
  EXPECT_TRUE(appliedThermalEffects(J::array(), log, "disp_z_um", kDeclared).empty());
  EXPECT_TRUE(appliedThermalEffects(J(), log, "disp_z_um", kDeclared).empty());
  EXPECT_TRUE(appliedThermalEffects(J::parse(R"([{"name": "input:T4"}])"), log, "disp_z_um", kDeclared)
                  .effects.extra.empty());
}

}  // namespace
}  // namespace metrofit::diagnose
