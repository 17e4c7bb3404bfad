// metrofit-bench --diagnose / --real-diagnose, setup and matching (see bench_diagnose_sm.h).
//
// Protocol (as bench_diagnose.cpp: the effect has a fixed size, the noise sigma is rms(effect) / r
// for the effect-to-noise ratio r, where the effect is the noiseless data with the effect minus the
// noiseless data without it, over the observations the diagnosis fits):
//  * setup: the demo's paper model (resources/demo/setup/paper_example.json, 10 setup data, 28
//    dimensions), 10 parts, 12 min per part with a time jitter of 0.5, constant setup errors
//    uniform in +-0.03 mm (Eq. 12, seed = trial seed), CMM resolution 0.0001 mm, noise uniform in
//    +-w2 with sigma = w2 / sqrt(3). Effects: tool_wear:T23 (0.002 mm/part), drift:W3
//    (0.0002 mm/min). Clean data: w2 = 0.01 mm.
//  * matching: a planar, position-only hole plate (400 holes uniform in a disc of radius 300 mm,
//    posture rz 0.01 deg, t (0.05, -0.03) mm; observations: x and y residuals). Effects: scale
//    (30 ppm), distortion (30 ppm at 25 deg). Clean data: noise 0.006 mm per axis.
//  * matching-s: the probed S-piece of probe_sim.h (40 points with normals, the paper-like posture;
//    observations: deviations along the normals). Effects: scale (100 ppm), surface_offset:ruled+
//    (0.02 mm), surface_offset:hole1 (0.02 mm). Clean data: noise 0.006 mm.
//  * Detected: the effect is accepted and its parameter is within 30 % (mm_per_part, mm_per_min,
//    ppm, mm; distortion: the relative error of the vector (ppm cos 2a, ppm sin 2a), so that an
//    angle error of 8.6 deg alone counts as 30 %).
#include "bench_diagnose_sm.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/io/csv.h"
#include "core/matching/hole_table.h"
#include "core/setup/report.h"
#include "core/sim/effects_matching.h"
#include "core/sim/effects_setup.h"

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

template <class ParamErr>
DiagnoseTrial judge(const Diagnosis& d, const std::string& effect, ParamErr paramErr) {
  DiagnoseTrial t;
  for (const Candidate* c : d.accepted()) {
    if (!effect.empty() && c->name == effect && !t.detected) {
      const double e = paramErr(*c);
      t.paramRelError = std::isfinite(e) ? e : 1e9;
      t.detected = e <= 0.30;
      if (!t.detected) t.otherAccepted = true;
    } else {
      t.otherAccepted = true;
    }
  }
  return t;
}

double rel(double est, double truth) {
  return std::isfinite(est) ? std::abs(est - truth) / std::abs(truth) : 1e9;
}

// ---- setup ----------------------------------------------------------------------------------------

constexpr double kWearMmPerPart = 0.002;
constexpr double kDriftMmPerMin = 0.0002;

DiagnoseTrial runSetup(const setup::Model& model, const std::string& effect, double ratio,
                       std::uint64_t seed) {
  SetupEffectsSimOptions o;
  o.base.parts = 10;
  o.base.minutesPerPart = 12.0;
  o.base.resolutionMm = 0.0001;
  o.base.seed = seed;
  o.timeJitter = 0.5;
  double truth = 0.0;
  if (effect == "tool_wear:T23") {
    o.toolWearMmPerPart = {{"T23", kWearMmPerPart}};
    truth = kWearMmPerPart;
  } else if (effect == "drift:W3") {
    o.driftMmPerMin = {{"W3", kDriftMmPerMin}};
    truth = kDriftMmPerMin;
  }
  if (effect.empty()) {
    o.base.w2 = 0.01;
  } else {
    // rms of the effect alone: no setup errors, no noise, no rounding.
    SetupEffectsSimOptions e = o;
    e.base.w1 = 0.0;
    e.base.w2 = 0.0;
    e.base.resolutionMm = 0.0;
    const CsvTable t = parseCsv(simulateSetupEffectsReport(model, e), "effect");
    const std::vector<double> meas = t.numericColumn("measured_mm"), nom = t.numericColumn("nominal_mm");
    double ss = 0.0;
    for (std::size_t i = 0; i < meas.size(); ++i) ss += (meas[i] - nom[i]) * (meas[i] - nom[i]);
    const double sigma = std::sqrt(ss / static_cast<double>(meas.size())) / ratio;
    o.base.w2 = std::sqrt(3.0) * sigma;
  }
  const setup::Measurements m =
      setup::cmmReportFromCsv(parseCsv(simulateSetupEffectsReport(model, o), "sim.csv"), model);
  const Diagnosis d = diagnose::diagnoseSetup(model, m);
  const std::string key = effect.rfind("tool_wear", 0) == 0 ? "mm_per_part" : "mm_per_min";
  return judge(d, effect, [&](const Candidate& c) { return rel(numberParam(c, key), truth); });
}

// ---- matching ----------------------------------------------------------------------------------

MatchingEffects matchingEffect(const std::string& effect, bool sPiece) {
  MatchingEffects e;
  if (effect == "scale") e.scalePpm = sPiece ? 100.0 : 30.0;
  if (effect == "distortion") {
    e.distortionPpm = 30.0;
    e.distortionAngleDeg = 25.0;
  }
  if (effect.rfind("surface_offset:", 0) == 0) e.surfaceOffsetsMm = {{effect.substr(15), 0.02}};
  return e;
}

double matchingParamError(const Candidate& c, const MatchingEffects& e) {
  if (c.name == "scale") return rel(numberParam(c, "ppm"), e.scalePpm);
  if (c.name == "distortion") {
    const double a = 2.0 * numberParam(c, "angle_deg") * std::numbers::pi / 180.0;
    const double a0 = 2.0 * e.distortionAngleDeg * std::numbers::pi / 180.0;
    const double ppm = numberParam(c, "ppm");
    return std::hypot(ppm * std::cos(a) - e.distortionPpm * std::cos(a0),
                      ppm * std::sin(a) - e.distortionPpm * std::sin(a0)) /
           e.distortionPpm;
  }
  return rel(numberParam(c, "mm"), e.surfaceOffsetsMm.front().second);
}

DiagnoseTrial runPlate(const std::string& effect, double ratio, std::uint64_t seed) {
  HolePlateSimOptions o;
  o.holes = 400;
  o.seed = seed;
  const MatchingEffects e = matchingEffect(effect, false);
  if (effect.empty()) {
    o.noiseMm = 0.006;
  } else {
    HolePlateSimOptions z = o;
    z.noiseMm = 0.0;
    const ProbePointSet with = simulateHolePlate(z, e), without = simulateHolePlate(z, {});
    double ss = 0.0;
    for (std::size_t i = 0; i < with.points.size(); ++i)
      ss += (with.points[i].measured - without.points[i].measured).head<2>().squaredNorm();
    o.noiseMm = std::sqrt(ss / (2.0 * static_cast<double>(with.points.size()))) / ratio;
  }
  const Diagnosis d = diagnose::diagnoseMatching(simulateHolePlate(o, e));
  return judge(d, effect, [&](const Candidate& c) { return matchingParamError(c, e); });
}

DiagnoseTrial runSPiece(const std::string& effect, double ratio, std::uint64_t seed) {
  ProbeSimOptions o = ProbeSimOptions::sPieceDefaults();
  o.seed = seed;
  const MatchingEffects e = matchingEffect(effect, true);
  if (!effect.empty()) {
    ProbeSimOptions z = o;
    z.noiseMm = 0.0;
    const ProbePointSet with = simulateProbingWithEffects(z, e), without = simulateProbing(z);
    const Eigen::Matrix3d R = rotationFromDeg(o.rotationDeg[0], o.rotationDeg[1], o.rotationDeg[2]);
    double ss = 0.0;
    for (std::size_t i = 0; i < with.points.size(); ++i) {
      const double dn = (R * with.points[i].normal).dot(with.points[i].measured - without.points[i].measured);
      ss += dn * dn;
    }
    o.noiseMm = std::sqrt(ss / static_cast<double>(with.points.size())) / ratio;
  }
  const Diagnosis d = diagnose::diagnoseMatching(simulateProbingWithEffects(o, e));
  return judge(d, effect, [&](const Candidate& c) { return matchingParamError(c, e); });
}

std::string paramsText(const Candidate& c) {
  std::string s;
  for (const auto& p : c.parameters) {
    char buf[96];
    // Numbers, or text (a generic effect's "form", cyclic's "axis").
    if (const double* v = std::get_if<double>(&p.value))
      std::snprintf(buf, sizeof buf, "%s%s=%.4g", s.empty() ? "" : " ", p.name.c_str(), *v);
    else
      std::snprintf(buf, sizeof buf, "%s%s=%s", s.empty() ? "" : " ", p.name.c_str(),
                    std::get<std::string>(p.value).c_str());
    s += buf;
    if (p.standardError) {
      std::snprintf(buf, sizeof buf, "+-%.2g", *p.standardError);
      s += buf;
    }
  }
  return s;
}

}  // namespace

std::vector<DomainRunner> setupMatchingRunners(const std::string& sourceDir) {
  auto model = std::make_shared<setup::Model>(
      setup::readModel(sourceDir + "/resources/demo/setup/paper_example.json"));
  return {{"setup",
           {"tool_wear:T23", "drift:W3"},
           [model](const std::string& effect, double ratio, std::uint64_t seed) {
             return runSetup(*model, effect, ratio, seed);
           }},
          {"matching", {"scale", "distortion"}, runPlate},
          {"matching-s", {"scale", "surface_offset:ruled+", "surface_offset:hole1"}, runSPiece}};
}

nlohmann::json benchRealDiagnoseSdss(const std::string& sdssDir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(sdssDir))
    if (entry.is_regular_file() && entry.path().filename().string().rfind("D", 0) == 0)
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  nlohmann::json out = nlohmann::json::array();
  std::printf("real-diagnose matching  SDSS plug plates (%s), tolerance 0.05 mm\n", sdssDir.c_str());
  std::printf("  %-28s %5s %12s %12s  %s\n", "file", "holes", "rmse before", "rmse after",
              "accepted effects");
  for (const auto& path : files) {
    const HoleTable table = readHoleTable(path.string());
    const Diagnosis d = diagnose::diagnoseMatching(table.points);
    std::string found;
    for (const Candidate* c : d.accepted())
      found += (found.empty() ? "" : "; ") + c->name + " " + paramsText(*c);
    if (found.empty()) found = "(none)";
    std::printf("  %-28s %5zu %9.4f mm %9.4f mm  %s\n", path.filename().string().c_str(),
                table.points.points.size(), d.baseline.rmse, d.final.rmse, found.c_str());
    nlohmann::json j = diagnose::toJson(d);
    j["file"] = path.filename().string();
    j["holes"] = table.points.points.size();
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace metrofit::bench
