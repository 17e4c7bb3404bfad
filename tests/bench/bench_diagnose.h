#pragma once
// metrofit-bench --diagnose / --real-diagnose: the detection study of the closed loop.
//
// Per domain and effect, `seeds` simulated data sets at each effect-to-noise ratio, plus clean data
// (the declared model exact up to the noise): detection rate (the effect accepted with its
// parameters within 30 %), median relative parameter error, rate of other effects accepted, and
// the false-positive rate on clean data (any effect accepted). A domain is a DomainRunner: the
// setup and matching domains add theirs with a couple of lines in bench_main.cpp.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

/// What one diagnosis of one simulated data set found.
struct DiagnoseTrial {
  bool detected = false;       ///< the simulated effect was accepted
  double paramRelError = 0.0;  ///< largest relative error of its key parameters (when detected)
  bool otherAccepted = false;  ///< some other effect was accepted (a false positive)
};

struct DomainRunner {
  std::string domain;                ///< "thermal", "kinematic", ...
  std::vector<std::string> effects;  ///< the effects simulated, one row each
  /// Simulates `effect` ("" = clean data) at the effect-to-noise ratio (ignored for clean data)
  /// with `seed`, diagnoses it, and says what was found.
  std::function<DiagnoseTrial(const std::string& effect, double ratio, std::uint64_t seed)> run;
};

struct DiagnoseBenchOptions {
  int seeds = 50;
  int cleanSeeds = 100;  ///< clean data sets per domain (false-positive rate)
  std::vector<double> ratios{2.0, 5.0, 10.0};
};

/// The thermal (lag, input:spindle_rpm, drift) and kinematic (backlash, scale, cyclic, servo_lag)
/// runners; the effect-to-noise ratio is the rms of the effect's contribution to the data (per
/// coordinate for paths) divided by the noise sigma.
std::vector<DomainRunner> thermalKinematicRunners();

/// Runs the study and prints one table row per domain, effect and ratio.
nlohmann::json benchDiagnose(const std::vector<DomainRunner>& runners, const DiagnoseBenchOptions& options);

/// The thermal diagnosis of the real CAIVIAC log (target ch3_um, declared t5, t9, t1): what was
/// found and the error before / after.
nlohmann::json benchRealDiagnose(const std::string& caiviacCsv);

/// The thermal diagnosis of the real CAIVIAC log for the issue-15 targets ch1_um, ch3_um and
/// ch5_um, each with the declared inputs t5_degC, t9_degC: baseline and final fit / held-out rmse,
/// the accepted effects and the residual check, one block per target.
nlohmann::json benchRealDiagnoseCaiviac(const std::string& caiviacCsv);

/// Writes the demo data with one undeclared effect each (metrofit-bench --diagnose-demo DIR):
///   DIR/diagnose_thermal.csv   the spindle test of thermal_sim.h (seed 7), target disp_z_um =
///       -3 T2 - 1.5 T4 + T_amb (um, changes since the first row) with T2 through a first-order lag of
///       15 min (`lag:T2`), noise 0.25 um;
///   DIR/diagnose_circular.csv  the circular test of circular_sim.h (R 100 mm, 360 points per loop,
///       CCW then CW, default actuator errors, seed 7) with backlash x 8 um, y 5 um, noise 0.5 um.
/// Returns a one-line description of each file.
std::vector<std::string> writeDiagnoseDemo(const std::string& dir);

}  // namespace metrofit::bench
