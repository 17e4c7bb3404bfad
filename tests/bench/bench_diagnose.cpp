// metrofit-bench --diagnose / --real-diagnose (see bench_diagnose.h).
//
// Protocol
//  * Thermal: the spindle test of thermal_sim.h (480 min, 1 min steps, 6000 rpm from 10 to 250 min,
//    then cooling; seed = trial seed), declared model disp_z_um = c0 - 3 T2 - 1.5 T4 + T_amb (um),
//    fitted on the first half (heating), held out on the second (cooling). Effects: `lag` (all
//    inputs, tau 15 min), `input:spindle_rpm` (-0.0005 um/rpm), `drift` (0.01 um/min).
//  * Kinematic: the circular test of circular_sim.h (R 100 mm, 360 points per loop, CCW then CW,
//    default actuator errors). Effects: `backlash` (x 6 um, y 4 um), `scale` (x 20, y -10 ppm),
//    `cyclic` (x, period 10 mm, amplitude 3 um, phase 30 deg), `servo_lag` (5 ms at 1000 mm/min).
//  * Effect-to-noise ratio r: the noise sigma is set to rms(effect) / r, where the effect is the
//    noiseless data with the effect minus the noiseless data without it (thermal: the part of it the
//    declared model cannot absorb, i.e. the residual of its least-squares fit on [1, declared inputs]
//    over all rows, because a lag of one sensor is largely a combination of the others; paths: rms
//    per coordinate). Clean data: thermal noise 0.25 um, path noise
//    0.5 um.
//  * Detected: the simulated effect's name is among the accepted effects (for `lag`: `lag` or
//    `lag:<col>`, which the data hardly tell apart when the other inputs change slowly) and its key
//    parameters (tau_min / coefficient / per_min; x_mm and y_mm; x_ppm and y_ppm; axis, period_mm and
//    amplitude_mm; tau_s) are within 30 % of the truth (the largest relative error is reported).
#include "bench_diagnose.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/io/file_io.h"
#include "core/sim/effects_kinematic.h"
#include "core/sim/effects_thermal.h"
#include "core/thermal/thermal_log.h"

namespace metrofit::bench {
namespace {

using diagnose::Candidate;
using diagnose::Diagnosis;

double numberParam(const Candidate& c, const std::string& name) {
  for (const auto& p : c.parameters)
    if (p.name == name)
      if (const double* v = std::get_if<double>(&p.value)) return *v;
  return std::nan("");
}

std::string textParam(const Candidate& c, const std::string& name) {
  for (const auto& p : c.parameters)
    if (p.name == name)
      if (const std::string* v = std::get_if<std::string>(&p.value)) return *v;
  return {};
}

double relErr(double est, double truth) {
  return std::isfinite(est) ? std::abs(est - truth) / std::abs(truth) : 1e9;
}

/// Detection check: `paramErr` gives the largest relative parameter error of the matching effect.
template <class ParamErr>
DiagnoseTrial judge(const Diagnosis& d, const std::string& effect, ParamErr paramErr) {
  DiagnoseTrial t;
  for (const Candidate* c : d.accepted()) {
    const bool same = c->name == effect || (effect == "lag" && c->name.starts_with("lag:"));
    if (!effect.empty() && same && !t.detected) {
      const double e = paramErr(*c);
      t.paramRelError = e;
      t.detected = e <= 0.30;
      if (!t.detected) t.otherAccepted = true;  // found, but with wrong parameters
    } else {
      t.otherAccepted = true;
    }
  }
  return t;
}

// ---- thermal ----------------------------------------------------------------------------------

ThermalEffectsOptions thermalCase(const std::string& effect, std::uint64_t seed) {
  ThermalEffectsOptions o;
  o.seed = seed;
  if (effect == "lag")
    o.lagTauMin = 15.0;
  else if (effect == "input:spindle_rpm")
    o.extraInputs = {{"spindle_rpm", -0.0005}};
  else if (effect == "drift")
    o.driftPerMin = 0.01;
  return o;
}

DiagnoseTrial runThermal(const std::string& effect, double ratio, std::uint64_t seed) {
  ThermalEffectsOptions o = thermalCase(effect, seed);
  if (effect.empty()) {
    o.noiseUm = 0.25;
  } else {
    ThermalSimOptions so = o.sensors;
    so.seed = seed;
    const ThermalLog sensors = simulateThermalTest(so);
    const ThermalEffectSignal sig = thermalEffectSignal(sensors, o);
    // The part of the effect the declared model cannot absorb: the residual of its least-squares
    // fit on [1, declared inputs] over all rows.
    const auto n = static_cast<Eigen::Index>(sig.declared.size());
    Eigen::MatrixXd X(n, static_cast<Eigen::Index>(o.declaredInputs.size()) + 1);
    Eigen::VectorXd e(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto row = static_cast<std::size_t>(k);
      X(k, 0) = 1.0;
      for (std::size_t j = 0; j < o.declaredInputs.size(); ++j)
        X(k, static_cast<Eigen::Index>(j) + 1) = sensors.channel(o.declaredInputs[j]).values[row];
      e(k) = sig.withEffects[row] - sig.declared[row];
    }
    const Eigen::VectorXd r = e - X * X.colPivHouseholderQr().solve(e);
    o.noiseUm = std::sqrt(r.squaredNorm() / static_cast<double>(n)) / ratio;
  }
  const ThermalLog log = simulateThermalEffects(o);
  diagnose::ThermalDiagnosisOptions dopt;
  dopt.target = o.target;
  dopt.inputs = o.declaredInputs;
  const Diagnosis d = diagnose::diagnoseThermal(log, dopt);
  return judge(d, effect, [&](const Candidate& c) {
    if (effect == "lag") return relErr(numberParam(c, "tau_min"), o.lagTauMin);
    if (effect == "drift") return relErr(numberParam(c, "per_min"), o.driftPerMin);
    return relErr(numberParam(c, "coefficient"), o.extraInputs.front().coefficient);
  });
}

// ---- kinematic --------------------------------------------------------------------------------

KinematicEffects kinematicCase(const std::string& effect) {
  KinematicEffects e;
  if (effect == "backlash") {
    e.backlashXMm = 0.006;
    e.backlashYMm = 0.004;
  } else if (effect == "scale") {
    e.scaleXPpm = 20.0;
    e.scaleYPpm = -10.0;
  } else if (effect == "cyclic") {
    e.cyclicAxis = 'x';
    e.cyclicPeriodMm = 10.0;
    e.cyclicAmplitudeMm = 0.003;
    e.cyclicPhaseDeg = 30.0;
  } else if (effect == "servo_lag") {
    e.servoLagS = 0.005;
    e.feedMmPerMin = 1000.0;
  }
  return e;
}

DiagnoseTrial runKinematic(const std::string& effect, double ratio, std::uint64_t seed) {
  KinematicEffectsOptions o;
  o.circle.seed = seed;
  o.effects = kinematicCase(effect);
  if (effect.empty()) {
    o.circle.noiseMm = 0.0005;
  } else {
    const auto cmd = circularTestCommands(o.circle);
    const auto with = simulateMachineWithEffects(o.circle.errors, o.effects, cmd, 0.0, seed);
    const auto without = simulateMachine(o.circle.errors, cmd, 0.0, seed);
    double ss = 0.0;
    for (std::size_t k = 0; k < cmd.size(); ++k) ss += (with[k] - without[k]).squaredNorm();
    o.circle.noiseMm = std::sqrt(ss / (2.0 * static_cast<double>(cmd.size()))) / ratio;
  }
  const MeasuredPath path = simulateCircularTestWithEffects(o);
  diagnose::KinematicDiagnosisOptions dopt;
  dopt.feedMmPerMin = o.effects.feedMmPerMin;
  const Diagnosis d = diagnose::diagnoseKinematic(path, dopt);
  const KinematicEffects& t = o.effects;
  return judge(d, effect, [&](const Candidate& c) {
    if (effect == "backlash")
      return std::max(relErr(numberParam(c, "x_mm"), t.backlashXMm),
                      relErr(numberParam(c, "y_mm"), t.backlashYMm));
    if (effect == "scale")
      return std::max(relErr(numberParam(c, "x_ppm"), t.scaleXPpm),
                      relErr(numberParam(c, "y_ppm"), t.scaleYPpm));
    if (effect == "servo_lag") return relErr(numberParam(c, "tau_s"), t.servoLagS);
    if (textParam(c, "axis") != "x") return 1e9;
    return std::max(relErr(numberParam(c, "period_mm"), t.cyclicPeriodMm),
                    relErr(numberParam(c, "amplitude_mm"), t.cyclicAmplitudeMm));
  });
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::vector<DomainRunner> thermalKinematicRunners() {
  return {{"thermal", {"lag", "input:spindle_rpm", "drift"}, runThermal},
          {"kinematic", {"backlash", "scale", "cyclic", "servo_lag"}, runKinematic}};
}

nlohmann::json benchDiagnose(const std::vector<DomainRunner>& runners, const DiagnoseBenchOptions& o) {
  nlohmann::json out = nlohmann::json::array();
  std::printf("diagnose  %-10s %-20s %6s %5s %10s %14s %10s %8s\n", "domain", "effect", "ratio", "runs",
              "detected", "param err med", "other acc", "s");
  for (const DomainRunner& r : runners) {
    for (const std::string& effect : r.effects) {
      for (const double ratio : o.ratios) {
        const auto start = std::chrono::steady_clock::now();
        int detected = 0, other = 0;
        std::vector<double> errs;
        for (int s = 0; s < o.seeds; ++s) {
          const DiagnoseTrial t = r.run(effect, ratio, 1000 + static_cast<std::uint64_t>(s));
          detected += t.detected;
          other += t.otherAccepted;
          if (t.paramRelError > 0.0 && t.paramRelError < 1e8) errs.push_back(t.paramRelError);
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double rate = static_cast<double>(detected) / o.seeds;
        const double med = median(errs);
        std::printf("diagnose  %-10s %-20s %6.1f %5d %9.1f%% %13.1f%% %9.1f%% %8.1f\n", r.domain.c_str(),
                    effect.c_str(), ratio, o.seeds, 100.0 * rate, 100.0 * med,
                    100.0 * static_cast<double>(other) / o.seeds, secs);
        out.push_back(
            {{"domain", r.domain},
             {"effect", effect},
             {"ratio", ratio},
             {"runs", o.seeds},
             {"detection_rate", rate},
             {"param_rel_error_median", std::isfinite(med) ? nlohmann::json(med) : nlohmann::json()},
             {"other_accepted_rate", static_cast<double>(other) / o.seeds}});
      }
    }
    const auto start = std::chrono::steady_clock::now();
    int fp = 0;
    for (int s = 0; s < o.cleanSeeds; ++s)
      fp += r.run("", 0.0, 5000 + static_cast<std::uint64_t>(s)).otherAccepted;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("diagnose  %-10s %-20s %6s %5d %10s %14s %9.1f%% %8.1f   <- false positives on clean data\n",
                r.domain.c_str(), "(clean)", "-", o.cleanSeeds, "-", "-",
                100.0 * static_cast<double>(fp) / o.cleanSeeds, secs);
    out.push_back({{"domain", r.domain},
                   {"effect", "clean"},
                   {"runs", o.cleanSeeds},
                   {"false_positive_rate", static_cast<double>(fp) / o.cleanSeeds}});
  }
  return out;
}

std::vector<std::string> writeDiagnoseDemo(const std::string& dir) {
  ThermalEffectsOptions t;
  t.seed = 7;
  t.lagTauMin = 15.0;
  t.lagColumn = "T2";
  t.noiseUm = 0.25;
  writeFileAtomic(dir + "/diagnose_thermal.csv", thermalLogToCsv(simulateThermalEffects(t)));
  KinematicEffectsOptions k;
  k.circle.seed = 7;
  k.circle.noiseMm = 0.0005;
  k.effects.backlashXMm = 0.008;
  k.effects.backlashYMm = 0.005;
  writeFileAtomic(dir + "/diagnose_circular.csv", measuredPathToCsv(simulateCircularTestWithEffects(k)));
  return {dir + "/diagnose_thermal.csv: lag:T2 15 min, seed 7",
          dir + "/diagnose_circular.csv: backlash x 8 um, y 5 um, seed 7"};
}

nlohmann::json benchRealDiagnose(const std::string& caiviacCsv) {
  const ThermalLog log = readThermalLog(caiviacCsv);
  diagnose::ThermalDiagnosisOptions o;
  o.target = "ch3_um";
  o.inputs = {"t5_degC", "t9_degC", "t1_degC"};
  const auto start = std::chrono::steady_clock::now();
  const Diagnosis d = diagnose::diagnoseThermal(log, o);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "real-diagnose CAIVIAC (%zu rows), target %s, declared inputs t5_degC,t9_degC,t1_degC, train "
      "fraction 0.5 (%.1f s)\n",
      log.rows(), o.target.c_str(), secs);
  std::printf("  baseline: fit rmse %.3f um, max |r| %.3f um, held-out rmse %.3f um\n", d.baseline.rmse,
              d.baseline.maxAbs, *d.baseline.heldoutRmse);
  for (const Candidate* c : d.accepted())
    std::printf("  round %d %-18s %s\n", c->round, c->name.c_str(), c->evidence.c_str());
  std::printf(
      "  final:    fit rmse %.3f um, max |r| %.3f um, held-out rmse %.3f um (%zu candidates tried, %zu "
      "accepted); held-out %s\n",
      d.final.rmse, d.final.maxAbs, *d.final.heldoutRmse, d.effects.size(), d.accepted().size(),
      *d.final.heldoutRmse <= *d.baseline.heldoutRmse ? "not worse" : "WORSE");
  nlohmann::json j = diagnose::toJson(d);
  j["seconds"] = secs;
  return j;
}

nlohmann::json benchRealDiagnoseCaiviac(const std::string& caiviacCsv) {
  const ThermalLog log = readThermalLog(caiviacCsv);
  nlohmann::json out = nlohmann::json::array();
  for (const char* target : {"ch1_um", "ch3_um", "ch5_um"}) {
    diagnose::ThermalDiagnosisOptions o;
    o.target = target;
    o.inputs = {"t5_degC", "t9_degC"};
    const auto start = std::chrono::steady_clock::now();
    const Diagnosis d = diagnose::diagnoseThermal(log, o);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "real-diagnose CAIVIAC (%zu rows), target %s, declared t5_degC,t9_degC, train fraction %.1f (%.1f "
        "s)\n",
        log.rows(), target, o.trainFraction, secs);
    std::printf("  baseline: fit rmse %.3f um, max |r| %.3f um, held-out rmse %.3f um\n", d.baseline.rmse,
                d.baseline.maxAbs, d.baseline.heldoutRmse.value_or(std::nan("")));
    for (const Candidate* c : d.accepted())
      std::printf("  round %d %-18s %s\n", c->round, c->name.c_str(), c->evidence.c_str());
    std::printf(
        "  final:    fit rmse %.3f um, max |r| %.3f um, held-out rmse %.3f um (%zu tried, %zu accepted)\n",
        d.final.rmse, d.final.maxAbs, d.final.heldoutRmse.value_or(std::nan("")), d.effects.size(),
        d.accepted().size());
    if (d.residualCheck)
      std::printf("  residual check: %s (%zu outliers)\n", d.residualCheck->summary.c_str(),
                  d.residualCheck->outliers.size());
    else
      std::printf("  residual check: (none in the result)\n");
    nlohmann::json j = diagnose::toJson(d);
    j["target"] = target;
    j["inputs"] = o.inputs;
    j["seconds"] = secs;
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace metrofit::bench
