// The thermal models behind one interface (thermal_model.h): validation, Table 4 on fit / held-out
// parts, the modular models of Section 4.3, persistence and compensation values.
#include "core/thermal/thermal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/sim/thermal_modular_sim.h"
#include "core/sim/thermal_sim.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

ThermalSeries fromCsv(const std::string& text, const std::string& target,
                      const std::vector<std::string>& inputs) {
  return selectThermalSeries(thermalLogFromCsv(parseCsv(text, "log.csv")), target, inputs);
}

std::string fitError(const ThermalSeries& s, ThermalModelKind kind, double fraction = 0.5) {
  ThermalFitOptions o;
  o.model = kind;
  o.gnnmci.iterations = 2;
  try {
    (void)fitAndEvaluate(s, fraction, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// time_min, T1, T2, d_um with `rows` rows (T2 constant when asked).
std::string logText(int rows, bool constantT2 = false) {
  std::string t = "time_min,T1,T2,d_um\n";
  for (int k = 0; k < rows; ++k) {
    const double x = 20.0 + 0.1 * k + 0.01 * (k % 3);
    t += std::to_string(k) + "," + std::to_string(x) + "," +
         (constantT2 ? "21.5" : std::to_string(20.0 + 0.05 * k * k / rows)) + "," +
         std::to_string(-2.0 * (x - 20.0)) + "\n";
  }
  return t;
}

TEST(ThermalModel, ValidationErrorsNameFileAndColumn) {
  const ThermalLog log = thermalLogFromCsv(parseCsv(logText(10), "log.csv"));
  auto selectError = [&](const std::string& target, const std::vector<std::string>& inputs) -> std::string {
    try {
      (void)selectThermalSeries(log, target, inputs);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(selectError("d_um", {"T9"}),
            "log.csv: field 'T9': no such column in the thermal log (it has: T1, T2, d_um)");
  EXPECT_EQ(selectError("d_um", {"T1", "d_um"}), "field '--inputs': 'd_um' is also the --target");
  EXPECT_EQ(selectError("d_um", {"T1", "T1"}), "field '--inputs': 'T1' is named twice");
  EXPECT_EQ(selectError("disp", {"T1"}),
            "log.csv: field 'disp': no such column in the thermal log (it has: T1, T2, d_um)");
  ThermalLog bad = log;
  bad.channels[0].values[2] = std::nan("");
  try {
    (void)selectThermalSeries(bad, "d_um", {"T1"});
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "log.csv: field 'T1': row 3 is not a finite number");
  }

  EXPECT_EQ(
      fitError(fromCsv(logText(12, true), "d_um", {"T1", "T2"}), ThermalModelKind::Gmc),
      "log.csv: field 'T2': input is constant (21.5) on all 6 fitting rows; a model cannot learn from it "
      "(drop it from --inputs)");
  ThermalSeries flat = fromCsv(logText(12), "d_um", {"T1"});
  flat.target.assign(flat.rows(), 3.0);
  EXPECT_EQ(fitError(flat, ThermalModelKind::Gnnmci),
            "log.csv: field 'd_um': the target is constant on all 6 fitting rows; there is no thermal error "
            "to model");
  EXPECT_EQ(fitError(fromCsv(logText(8), "d_um", {"T1", "T2"}), ThermalModelKind::Gmc),
            "log.csv: 4 fitting rows are too few: GMC(1,N) with 2 inputs has 4 parameters and needs at least "
            "5 rows "
            "(use more rows or a larger --train-fraction)");
  EXPECT_EQ(fitError(fromCsv(logText(5), "d_um", {"T1"}), ThermalModelKind::Gnnmci, 0.4),
            "log.csv: 2 fitting rows are too few: GNNMCI(1,N) needs at least 3 per log (the first row is the "
            "initial condition)");
  EXPECT_EQ(
      fitError(fromCsv(logText(40), "d_um", {"T1", "T2"}), ThermalModelKind::Mlp),
      "log.csv: 20 fitting rows are too few: the MLP with 2 inputs and 10 hidden neurons has 41 weights and "
      "needs at least 42 rows (use more rows, a larger --train-fraction or fewer inputs)");
  EXPECT_EQ(
      fitError(fromCsv(logText(10), "d_um", {"T1"}), ThermalModelKind::Gmc, 0.9),
      "log.csv: field '--train-fraction': with 10 rows, train fraction 0.9 holds out 1 row; at least 2 are "
      "needed");
  EXPECT_EQ(fitError(fromCsv(logText(10), "d_um", {"T1"}), ThermalModelKind::Gmc, 1.0),
            "field '--train-fraction': 1 is not in (0, 1)");
  try {
    (void)thermalModelKind("ann");
    FAIL();
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(),
                 "field '--model': 'ann' is not a thermal model (gnnmci, gmc, mlp, linear, lag or dlag)");
  }
}

TEST(ThermalModel, DefaultsOfThePaper) {
  EXPECT_EQ(defaultTrainFraction(ThermalModelKind::Mlp), 0.7);  // Table 3: 70 / 30
  EXPECT_EQ(defaultTrainFraction(ThermalModelKind::Gnnmci), 0.5);
  EXPECT_EQ(fitRowCount(481, 0.5), 241u);
  EXPECT_EQ(fitRowCount(10, 0.7), 7u);
  const ThermalFitOptions o;
  EXPECT_EQ(o.model, ThermalModelKind::Gnnmci);
  EXPECT_EQ(o.gnnmci.particles, 90);
  EXPECT_EQ(o.mlp.hidden, 10);
}

TEST(ThermalModel, ThreeModelsOnTheSimulatedSpindleLog) {
  // thermal_sim.h, seed 1: 8 h, heating 10-250 min, T1..T4 in, disp_z_um out; fit on the first half
  // (heating), hold out the second (mostly cooling).
  const ThermalSeries s = selectThermalSeries(simulateThermalTest({}), "disp_z_um", {"T1", "T2", "T3", "T4"});
  ThermalEvaluation ev[3];
  const ThermalModelKind kinds[3] = {ThermalModelKind::Gnnmci, ThermalModelKind::Gmc, ThermalModelKind::Mlp};
  for (int i = 0; i < 3; ++i) {
    ThermalFitOptions o;
    o.model = kinds[i];
    ev[i] = fitAndEvaluate(s, 0.5, o);
    EXPECT_EQ(ev[i].fitRows, 241u);
    EXPECT_EQ(ev[i].heldoutRows, 240u);
    EXPECT_EQ(ev[i].predicted.size(), s.rows());
    std::printf(
        "[ figures  ] spindle log, %-6s fit RMSE %.4g um, held-out RMSE %.4g um, R %.4g, E %.4g, band %.4g "
        "um\n",
        toString(kinds[i]), ev[i].fit.rmse, ev[i].heldout.rmse, ev[i].heldout.r, ev[i].heldout.e,
        ev[i].heldout.residualBand);
  }
  // GNNMCI: accurate on the held-out cooling part, better than the MLP and than GMC(1,N).
  EXPECT_LT(ev[0].heldout.rmse, 1.5);
  EXPECT_GT(ev[0].heldout.e, 0.99);
  EXPECT_LT(ev[0].heldout.rmse, ev[2].heldout.rmse);
  EXPECT_LT(ev[0].heldout.rmse, ev[1].heldout.rmse);
  EXPECT_LE(ev[0].training.fitness, ev[1].training.fitness);
  // Least squares gives an unstable GMC(1,N) here (b1 < 0): the paper's "the least square solution
  // may not meet the expectation". It is reported as it is, and flagged.
  EXPECT_LT(ev[1].training.model.grey.b1, 0.0);
  EXPECT_EQ(thermalModelParameters(ev[1].training.model)["stable"], false);
  // The grey models start from the measured first value; the fit rows' metrics are Table 4's.
  EXPECT_EQ(ev[0].predicted[0], s.target[0]);
  const ThermalMetrics direct = thermalMetrics(std::span<const double>(s.target).subspan(241),
                                               std::span<const double>(ev[0].predicted).subspan(241));
  EXPECT_EQ(direct.rmse, ev[0].heldout.rmse);
}

TEST(ThermalModel, ModularModelsPredictTheCombinedTest) {
  // Section 4.3: fitted on the Z and C heating tests together, validated on the combined test.
  // Inputs as in the paper: FBG-1..4 and the ram temperature T2.
  const ModularSimOptions so;
  const std::vector<std::string> in{"FBG1_ue", "FBG2_ue", "FBG3_ue", "FBG4_ue", "T2"};
  const ThermalSeries z =
      selectThermalSeries(simulateModularTest(ModularTest::ZHeating, so), "disp_z_um", in);
  const ThermalSeries c =
      selectThermalSeries(simulateModularTest(ModularTest::CHeating, so), "disp_z_um", in);
  const ThermalSeries h =
      selectThermalSeries(simulateModularTest(ModularTest::Combined, so), "disp_z_um", in);
  ModularEvaluation m[3];
  const ThermalModelKind kinds[3] = {ThermalModelKind::Gnnmci, ThermalModelKind::Gmc, ThermalModelKind::Mlp};
  for (int i = 0; i < 3; ++i) {
    ThermalFitOptions o;
    o.model = kinds[i];
    m[i] = fitModular({z, c}, h, o);
    EXPECT_EQ(m[i].training.fitRows, z.rows() + c.rows());
    std::printf(
        "[ figures  ] modular, %-6s combined test error %.4g um -> +-%.4g um (%.1f %% less), RMSE %.4g um "
        "(%.1f %% less), R %.4f, E %.4f\n",
        toString(kinds[i]), m[i].errorPeak, m[i].residualPeak, 100.0 * m[i].reductionPeak, m[i].test.rmse,
        100.0 * m[i].reductionRms, m[i].test.r, m[i].test.e);
  }
  // The paper's headline: at least 85 % less thermal error on the combined test.
  EXPECT_GE(m[0].reductionPeak, 0.85);
  EXPECT_GT(m[0].test.e, 0.99);
  EXPECT_LT(m[0].test.rmse, m[1].test.rmse);
  EXPECT_LT(m[0].test.rmse, m[2].test.rmse);
  EXPECT_LE(m[0].training.fitness, m[1].training.fitness);
  EXPECT_TRUE(test::near(m[0].errorPeak, 87.6, 2.0)) << m[0].errorPeak;
}

// Separate modules (Section 4.3 as modules identified on their own tests): a two-drive plant written
// out here, independent of the simulator: the Z and C drive nodes are first-order lags of their drives
// (tau 20 and 15 min, exact for the sample-and-hold step), the ram growth is -5 um/K dTz - 3 um/K dTc
// plus 0.1 um noise. The Z module sees only Tz and the Z test, the C module only Tc and the C test;
// on the helical test (both drives at half) each module's contribution is its own closed-form term and
// their sum the growth. A new C test with the C gain changed re-identifies the C module alone: the Z
// module is kept bit for bit and the combined prediction follows the new machine.
namespace modules {

struct Plant {
  double kz = -5.0, kc = -3.0;
};

/// time_min,Tz,Tc,disp_um with drives z, c in [0, 1] for the first 120 of 240 min.
ThermalSeries plantTest(double z, double c, const Plant& p, std::uint32_t seed,
                        const std::vector<std::string>& in) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::string csv = "time_min,Tz,Tc,disp_um\n";
  double tz = 20.0, tc = 20.0;
  for (int k = 0; k <= 240; ++k) {
    const double dz = tz - 20.0, dc = tc - 20.0;
    csv += std::to_string(k) + "," + std::to_string(tz) + "," + std::to_string(tc) + "," +
           std::to_string(p.kz * dz + p.kc * dc + noise(rng)) + "\n";
    const double uz = k < 120 ? 8.0 * z : 0.0, uc = k < 120 ? 6.0 * c : 0.0;
    tz = 20.0 + uz + (tz - 20.0 - uz) * std::exp(-1.0 / 20.0);
    tc = 20.0 + uc + (tc - 20.0 - uc) * std::exp(-1.0 / 15.0);
  }
  return fromCsv(csv, "disp_um", in);
}

}  // namespace modules

TEST(ThermalModules, EachModuleOnItsOwnTestAndTheCombinedPredictionIsTheirSum) {
  using modules::plantTest;
  const modules::Plant plant;
  ThermalFitOptions o;
  o.model = ThermalModelKind::Linear;
  const ThermalModule z = fitThermalModule("z", plantTest(1, 0, plant, 1, {"Tz"}), o);
  const ThermalModule c = fitThermalModule("c", plantTest(0, 1, plant, 2, {"Tc"}), o);
  const ThermalSeries hz = plantTest(0.5, 0.5, plant, 3, {"Tz"}), hc = plantTest(0.5, 0.5, plant, 3, {"Tc"});
  const ModulesEvaluation m = evaluateModules({z, c}, {hz, hc});
  ASSERT_EQ(m.contributions.size(), 2u);
  for (std::size_t k = 0; k < hz.rows(); ++k) {
    EXPECT_NEAR(m.contributions[0][k], plant.kz * (hz.inputs[0][k] - hz.inputs[0][0]), 0.05) << k;
    EXPECT_NEAR(m.contributions[1][k], plant.kc * (hc.inputs[0][k] - hc.inputs[0][0]), 0.05) << k;
    EXPECT_NEAR(m.predicted[k], hz.target[0] + m.contributions[0][k] + m.contributions[1][k], 1e-9);
  }
  EXPECT_LT(m.test.rmse, 0.15);  // the noise (0.1 um) and the modules' estimation error
  EXPECT_GT(m.reductionPeak, 0.95);
  EXPECT_GT(m.errorPeak, 20.0);

  // The C drive's gain changes (new bearings): a new C test re-identifies the C module only.
  modules::Plant changed = plant;
  changed.kc = -4.0;
  const ThermalModule c2 = fitThermalModule("c", plantTest(0, 1, changed, 4, {"Tc"}), o);
  const ThermalSeries nz = plantTest(0.5, 0.5, changed, 5, {"Tz"}),
                      nc = plantTest(0.5, 0.5, changed, 5, {"Tc"});
  const ModulesEvaluation stale = evaluateModules({z, c}, {nz, nc});
  const ModulesEvaluation fresh = evaluateModules({z, c2}, {nz, nc});
  EXPECT_LT(fresh.test.rmse, 0.15);
  EXPECT_GT(stale.test.rmse, 3.0 * fresh.test.rmse);
  EXPECT_EQ(fresh.contributions[0], evaluateModules({z, c}, {nz, nc}).contributions[0]);

  // A module's inputs must be its test series' inputs.
  EXPECT_THROW(evaluateModules({z, c}, {hz, hz}), ValidationError);
  EXPECT_THROW(evaluateModules({z}, {hz, hc}), ValidationError);
}

// The speed budget holds for the optimised build. The sanitize preset (Debug, ASan + UBSan; the
// compiler defines __SANITIZE_ADDRESS__) runs the same training about ten times slower: there the
// bound is scaled, the assertion stays.
#ifdef __SANITIZE_ADDRESS__
constexpr double kSpeedBudgetFactor = 25.0;
#else
constexpr double kSpeedBudgetFactor = 1.0;
#endif

TEST(ThermalModel, GnnmciTrainsOnAFourHourLogWellUnderASecond) {
  ThermalSimOptions so;
  so.durationMin = 240.0;  // 4 h at 1-min sampling: 241 rows
  const ThermalSeries s = selectThermalSeries(simulateThermalTest(so), "disp_z_um", {"T1", "T2", "T3", "T4"});
  ASSERT_EQ(s.rows(), 241u);
  const std::clock_t start = std::clock();
  const ThermalTraining t = fitThermalModel({s}, ThermalFitOptions{});
  const double cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  std::printf("[ figures  ] GNNMCI training on a 4 h log (241 rows, 4 inputs, %ld evaluations): %.3f s CPU\n",
              t.run.evaluations, cpu);
  EXPECT_EQ(t.run.evaluations, 90 * 101);
  // CPU time of this process: not disturbed by other load on the machine
  EXPECT_LT(cpu, 1.0 * kSpeedBudgetFactor);
}

TEST(ThermalModel, JsonRoundTripGivesTheSamePredictions) {
  const ThermalSeries s = selectThermalSeries(simulateThermalTest({}), "disp_z_um", {"T1", "T2"});
  for (auto kind : {ThermalModelKind::Gnnmci, ThermalModelKind::Gmc, ThermalModelKind::Mlp}) {
    ThermalFitOptions o;
    o.model = kind;
    o.gnnmci.iterations = 10;
    const ThermalTraining t = fitThermalModel({s.head(300)}, o);
    const std::string text = dumpJson(thermalModelToJson(t.model));
    const ThermalModel back = thermalModelFromJson(parseJson(text, "m.json"), "m.json");
    EXPECT_EQ(back.kind, kind);
    EXPECT_EQ(back.inputs, t.model.inputs);
    EXPECT_EQ(predictChange(back, s), predictChange(t.model, s)) << toString(kind);
  }
  auto err = [](const std::string& text) -> std::string {
    try {
      (void)thermalModelFromJson(parseJson(text, "m.json"), "m.json");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string head =
      R"({"format": "metrofit-thermal-model", "version": 1, "model": "gmc", "target": "d", "inputs": ["T1", "T2"], )";
  EXPECT_EQ(err(head + R"("time_unit_min": 1, "grey": {"b1": 0.1, "b": [1], "u": 0}})"),
            "m.json: field 'grey.b': expected 2 numbers, found 1");
  EXPECT_EQ(err(head + R"("time_unit_min": 0, "grey": {"b1": 0.1, "b": [1, 2], "u": 0}})"),
            "m.json: field 'time_unit_min': must be positive");
  EXPECT_EQ(err(head + R"("time_unit_min": 1})"), "m.json: field 'grey': missing");
  EXPECT_EQ(err(R"({"format": "x"})"), "m.json: field 'format': expected \"metrofit-thermal-model\"");
}

TEST(ThermalModel, CompensationValuesAreTheNegatedPrediction) {
  const ThermalSeries s = selectThermalSeries(simulateThermalTest({}), "disp_z_um", {"T1", "T2"});
  ThermalFitOptions o;
  o.gnnmci.iterations = 20;
  const ThermalModel m = fitThermalModel({s}, o).model;
  ASSERT_GT(m.grey.b1, 0.0);
  // New data without the target column: compensation from the inputs alone.
  ThermalLog newData = simulateThermalTest([] {
    ThermalSimOptions x;
    x.seed = 9;
    return x;
  }());
  newData.channels.erase(newData.channels.begin() + newData.indexOf("disp_z_um"));
  const ThermalSeries n = selectThermalSeries(newData, "disp_z_um", {"T1", "T2"}, false);
  EXPECT_FALSE(n.hasTarget());
  const Compensation c = compensationValues(m, n);
  ASSERT_EQ(c.predicted.size(), n.rows());
  EXPECT_EQ(c.predicted[0], 0.0);
  for (std::size_t k = 0; k < c.predicted.size(); ++k) EXPECT_EQ(c.compensation[k], -c.predicted[k]);
  const std::string csv = compensationToCsv(c);
  EXPECT_EQ(csv.rfind("time_min,predicted_disp_z_um,compensation_disp_z_um\n0,0,0\n1,", 0), 0u)
      << csv.substr(0, 80);
  const CsvTable t = parseCsv(csv, "c.csv");
  EXPECT_EQ(t.rowCount(), n.rows());
  EXPECT_TRUE(test::near(t.number(200, 1), c.predicted[200], 1e-6));
  // An unstable grey model gives no compensation values.
  ThermalModel unstable = m;
  unstable.grey.b1 = -0.01;
  try {
    (void)compensationValues(unstable, n);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("unstable"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace metrofit::thermal
