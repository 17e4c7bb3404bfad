// metrofit-bench --thermal / --real-thermal (see bench_thermal.h).
//
// Protocol
//  * Training time: fitThermalModel on the whole 241-row log (thermal_sim.h with durationMin = 240,
//    stepMin = 1, seed 1; inputs T1..T4, target disp_z_um), wall clock, median of `repeat` runs, for
//    GNNMCI(1,N) (PSO 90 x 100 + the initial swarm, pso-ls; seed 1), the MLP (4-10-1, LM, Table 3
//    stopping, seed 1) and GMC(1,N) (least squares). Ratio = GNNMCI / peer.
//  * Modular: the demo's three simulated tests (resources/demo/data/thermal_modular_{z,c,combined}.csv,
//    or simulateModularTest with seed 7 when they are missing), inputs FBG1..4 and T2 (the paper's),
//    each model fitted on Z + C together (seed 1) and predicting the combined test: error reduction
//    1 - max|residual| / max|error| (the paper's ">= 85 %") and by RMS, Table 4 on the combined test,
//    the ordering of the three models by RMSE as measured.
//  * Real logs: fit on the first half (train fraction 0.5, seed 1), predict the second; Table 4 on the
//    held-out half for each model. CAIVIAC: target ch3_um (the largest displacement), inputs the 16
//    temperatures; SJTU: target delta L (um), inputs T0..T15, time = row index x 1 min (the file has no
//    time column).
//  * Table 4 for CAIVIAC: ch1, ch3, ch5; every model (the paper's three, linear, lag,
//    dlag, auto) on t5, t9 (the issue's inputs) and on t5, t9, spindle_rpm; auto chooses on the fit
//    rows only; target: the chosen model (t5, t9, rpm) at most half the static regression's (t5, t9)
//    held-out RMSE on ch1 and not above it on ch3 / ch5.
#include "bench_thermal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/io/csv.h"
#include "core/sim/thermal_modular_sim.h"
#include "core/sim/thermal_sim.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;
using thermal::ThermalModelKind;

constexpr ThermalModelKind kKinds[3] = {ThermalModelKind::Gnnmci, ThermalModelKind::Gmc,
                                        ThermalModelKind::Mlp};

double seconds(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

thermal::ThermalFitOptions options(ThermalModelKind kind) {
  thermal::ThermalFitOptions o;
  o.model = kind;
  o.setSeed(1);
  return o;
}

nlohmann::json metricsJson(const thermal::ThermalMetrics& m) {
  return {{"rows", m.n}, {"R", m.r}, {"RMSE", m.rmse}, {"E", m.e}, {"residual_band", m.residualBand}};
}

std::string ordering(const double value[3], const char* by) {
  int idx[3] = {0, 1, 2};
  std::sort(idx, idx + 3, [&](int a, int b) { return value[a] < value[b]; });
  std::string s;
  for (int i = 0; i < 3; ++i) s += std::string(i ? " < " : "") + toString(kKinds[idx[i]]);
  return s + " (by " + by + ")";
}

ThermalLog modularTest(const std::string& dir, ModularTest test) {
  const std::string path = dir + "/thermal_modular_" + toString(test) + ".csv";
  if (std::filesystem::exists(path)) return readThermalLog(path);
  ModularSimOptions o;
  o.seed = 7;
  return simulateModularTest(test, o);
}

nlohmann::json realLog(const char* name, const ThermalLog& log, const std::string& target,
                       const std::vector<std::string>& inputs) {
  const thermal::ThermalSeries s = thermal::selectThermalSeries(log, target, inputs);
  nlohmann::json j{{"rows", s.rows()}, {"target", target}, {"inputs", inputs}};
  double rmse[3] = {0, 0, 0}, band[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const auto a = Clock::now();
    const thermal::ThermalEvaluation ev = thermal::fitAndEvaluate(s, 0.5, options(kKinds[i]));
    const double t = seconds(a);
    rmse[i] = ev.heldout.rmse;
    band[i] = ev.heldout.residualBand;
    std::printf(
        "real %-8s %-6s %zu fit / %zu held-out rows: fit RMSE %.3f, held-out RMSE %.3f um, R %.4f, E %.4f, "
        "band %.3f um (%.2f s)\n",
        name, toString(kKinds[i]), ev.fitRows, ev.heldoutRows, ev.fit.rmse, ev.heldout.rmse, ev.heldout.r,
        ev.heldout.e, ev.heldout.residualBand, t);
    j[toString(kKinds[i])] = {
        {"fit", metricsJson(ev.fit)}, {"heldout", metricsJson(ev.heldout)}, {"seconds", t}};
  }
  j["ordering"] = ordering(rmse, "RMSE");
  j["ordering_band"] = ordering(band, "residual band");
  std::printf("real %-8s ordering on the held-out half: %s; %s\n", name,
              j["ordering"].get<std::string>().c_str(), j["ordering_band"].get<std::string>().c_str());
  return j;
}

/// The SJTU file: "delta L" then T0..T15, one row per minute, no time column (README of the data).
ThermalLog readSjtu(const std::string& path) {
  const CsvTable t = readCsvFile(path);
  ThermalLog log;
  log.source = path;
  log.timeColumn = "time_min";
  for (std::size_t r = 0; r < t.rowCount(); ++r) log.timeMin.push_back(static_cast<double>(r));
  for (std::size_t c = 0; c < t.columnCount(); ++c) {
    const std::string name = t.header()[c] == "delta L" ? "delta_L_um" : t.header()[c];
    log.channels.push_back({name, name == "delta_L_um" ? "um" : "degC", t.numericColumn(c)});
  }
  return log;
}

/// Table 4 for the real CAIVIAC log, ch1, ch3, ch5, first half fit, second half
/// held out, every model on the issue's declared inputs (t5, t9) and with the spindle speed added
/// (the heat source a thermal engineer tries next); `auto` chooses on the fit rows only.
nlohmann::json realTable4(const ThermalLog& log) {
  nlohmann::json out;
  const std::vector<std::pair<std::string, std::vector<std::string>>> sets = {
      {"t5,t9", {"t5_degC", "t9_degC"}}, {"t5,t9,rpm", {"t5_degC", "t9_degC", "spindle_rpm"}}};
  bool doneAll = true;
  std::printf(
      "real-thermal Table 4, CAIVIAC, first half fit, second half held out (held-out R, RMSE um, E; "
      "FAILED: held-out E < 0 or unstable)\n");
  for (const char* ch : {"ch1_um", "ch3_um", "ch5_um"}) {
    nlohmann::json jc;
    double staticDeclared = 0.0, chosenRmse = 0.0;
    for (const auto& [setName, inputs] : sets) {
      const thermal::ThermalSeries s = thermal::selectThermalSeries(log, ch, inputs);
      nlohmann::json js;
      for (int k = 0; k < 7; ++k) {
        thermal::ThermalFitOptions o =
            options(k < 6 ? thermal::kAllThermalModelKinds[k] : ThermalModelKind::Linear);
        std::string label = toString(o.model);
        const auto a = Clock::now();
        nlohmann::json extra;
        if (k == 6) {
          const thermal::ThermalSelection sel =
              thermal::chooseThermalModel(s, thermal::fitRowCount(s.rows(), 0.5), o);
          o.model = sel.chosen;
          label = std::string("auto->") + toString(sel.chosen);
          for (std::size_t i = 0; i < sel.candidates.size(); ++i)
            extra[toString(sel.candidates[i])] =
                std::isfinite(sel.cvRmse[i]) ? nlohmann::json(sel.cvRmse[i]) : nlohmann::json();
        }
        const thermal::ThermalEvaluation ev = thermal::fitAndEvaluate(s, 0.5, o);
        const double t = seconds(a);
        std::string taus;
        for (const auto& term : ev.training.model.regression.terms) {
          if (term.tauMin > 0.0)
            taus += " " + inputs[term.input] + ":" + CsvWriter::formatNumber(term.tauMin) + "min";
        }
        if (thermal::isGrey(o.model) && ev.training.model.grey.b1 > 0.0)
          taus = " tau " +
                 CsvWriter::formatNumber(ev.training.model.timeUnitMin / ev.training.model.grey.b1, 4) +
                 "min";
        std::printf("  %-6s %-9s %-13s fit RMSE %7.3f | held-out R %7.3f RMSE %8.3f E %8.3f%s%s (%.2f s)\n",
                    ch, setName.c_str(), label.c_str(), ev.fit.rmse, ev.heldout.r, ev.heldout.rmse,
                    ev.heldout.e, ev.heldoutFails() ? " FAILED" : "", taus.c_str(), t);
        nlohmann::json jm{{"fit", metricsJson(ev.fit)},
                          {"heldout", metricsJson(ev.heldout)},
                          {"heldout_passed", !ev.heldoutFails()},
                          {"seconds", t}};
        if (k == 6) {
          jm["chosen"] = toString(o.model);
          jm["cv_rmse"] = extra;
        }
        js[k == 6 ? std::string("auto") : label] = jm;
        if (k == 3 && setName == "t5,t9") staticDeclared = ev.heldout.rmse;
        if (k == 6 && setName == "t5,t9,rpm") chosenRmse = ev.heldout.rmse;
      }
      jc[setName] = js;
    }
    const double ratio = chosenRmse / staticDeclared;
    const bool met = std::string(ch) == "ch1_um" ? ratio <= 0.5 : ratio <= 1.0;
    doneAll = doneAll && met;
    std::printf(
        "  %-6s chosen (auto, t5,t9,rpm) %.3f um vs static regression (t5,t9) %.3f um: ratio %.2f "
        "(target %s): %s\n",
        ch, chosenRmse, staticDeclared, ratio, std::string(ch) == "ch1_um" ? "<= 0.5" : "<= 1",
        met ? "met" : "NOT met");
    jc["ratio_chosen_to_static"] = ratio;
    jc["target_met"] = met;
    out[ch] = jc;
  }
  out["target_met"] = doneAll;
  return out;
}

}  // namespace

nlohmann::json benchThermal(const std::string& demoDataDir, int repeat) {
  nlohmann::json out;
  // ---- training time on a 4 h log at 1 min ----
  ThermalSimOptions so;
  so.durationMin = 240.0;
  so.stepMin = 1.0;
  const thermal::ThermalSeries s =
      thermal::selectThermalSeries(simulateThermalTest(so), "disp_z_um", {"T1", "T2", "T3", "T4"});
  double median[3] = {0, 0, 0};
  long evaluations[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    std::vector<double> t;
    for (int k = 0; k < std::max(1, repeat); ++k) {
      const auto a = Clock::now();
      const thermal::ThermalTraining tr = thermal::fitThermalModel({s}, options(kKinds[i]));
      t.push_back(seconds(a));
      evaluations[i] = tr.run.evaluations;
    }
    std::sort(t.begin(), t.end());
    median[i] = t[t.size() / 2];
  }
  std::printf(
      "thermal training on a 4 h log (%zu rows at 1 min, 4 inputs): GNNMCI(1,N) %.1f ms (%ld fitness "
      "evaluations), MLP (LM) %.1f ms, GMC(1,N) (least squares) %.3f ms; ratio GNNMCI/MLP = %.2f, "
      "GNNMCI/GMC = %.0f (target: GNNMCI well under 1 s)\n",
      s.rows(), median[0] * 1e3, evaluations[0], median[2] * 1e3, median[1] * 1e3, median[0] / median[2],
      median[0] / median[1]);
  out["training"] = {{"rows", s.rows()},
                     {"gnnmci_ms", median[0] * 1e3},
                     {"gnnmci_evaluations", evaluations[0]},
                     {"mlp_ms", median[2] * 1e3},
                     {"gmc_ms", median[1] * 1e3},
                     {"ratio_gnnmci_mlp", median[0] / median[2]},
                     {"ratio_gnnmci_gmc", median[0] / median[1]},
                     {"target_met", median[0] < 1.0}};

  // ---- modular case ----
  const std::vector<std::string> in{"FBG1_ue", "FBG2_ue", "FBG3_ue", "FBG4_ue", "T2"};
  const thermal::ThermalSeries z =
      thermal::selectThermalSeries(modularTest(demoDataDir, ModularTest::ZHeating), "disp_z_um", in);
  const thermal::ThermalSeries c =
      thermal::selectThermalSeries(modularTest(demoDataDir, ModularTest::CHeating), "disp_z_um", in);
  const thermal::ThermalSeries h =
      thermal::selectThermalSeries(modularTest(demoDataDir, ModularTest::Combined), "disp_z_um", in);
  nlohmann::json modular;
  double rmse[3] = {0, 0, 0}, band[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const auto a = Clock::now();
    const thermal::ModularEvaluation m = thermal::fitModular({z, c}, h, options(kKinds[i]));
    const double t = seconds(a);
    rmse[i] = m.test.rmse;
    band[i] = m.residualPeak;
    std::printf(
        "thermal modular %-6s combined test error %.2f um -> +-%.2f um (%.1f %% less), RMSE %.3f um (%.1f %% "
        "less), R %.4f, E %.4f (%.2f s)\n",
        toString(kKinds[i]), m.errorPeak, m.residualPeak, 100.0 * m.reductionPeak, m.test.rmse,
        100.0 * m.reductionRms, m.test.r, m.test.e, t);
    modular[toString(kKinds[i])] = {{"error_peak", m.errorPeak},         {"residual_peak", m.residualPeak},
                                    {"reduction_peak", m.reductionPeak}, {"reduction_rms", m.reductionRms},
                                    {"test", metricsJson(m.test)},       {"seconds", t}};
  }
  modular["ordering"] = ordering(rmse, "RMSE");
  modular["ordering_band"] = ordering(band, "residual band");
  modular["target_met"] = modular["gnnmci"]["reduction_peak"].get<double>() >= 0.85;
  std::printf("thermal modular ordering on the combined test: %s; %s; GNNMCI reduction >= 85 %%: %s\n",
              modular["ordering"].get<std::string>().c_str(),
              modular["ordering_band"].get<std::string>().c_str(),
              modular["target_met"].get<bool>() ? "yes" : "NO");
  out["modular"] = modular;
  return out;
}

nlohmann::json benchRealThermal(const std::string& caiviacCsv, const std::string& sjtuCsv) {
  nlohmann::json out;
  {
    const ThermalLog log = readThermalLog(caiviacCsv);
    std::vector<std::string> temps;
    for (const ThermalChannel& ch : log.channels) {
      if (channelKind(ch) == ChannelKind::Temperature) temps.push_back(ch.name);
    }
    out["caiviac"] = realLog("CAIVIAC", log, "ch3_um", temps);
    out["caiviac_table4"] = realTable4(log);
  }
  if (std::filesystem::exists(sjtuCsv)) {
    const ThermalLog log = readSjtu(sjtuCsv);
    std::vector<std::string> temps;
    for (int i = 0; i <= 15; ++i) temps.push_back("T" + std::to_string(i));
    out["sjtu"] = realLog("SJTU", log, "delta_L_um", temps);
  } else {
    std::printf("real SJTU: %s not found; skipped\n", sjtuCsv.c_str());
    out["sjtu"] = nullptr;
  }
  return out;
}

}  // namespace metrofit::bench
