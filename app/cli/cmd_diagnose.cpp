// metrofit-cli diagnose thermal|kinematic|setup|matching (docs/file-formats.md#diagnose-result): fit the
// declared model, trace the residual to an effect the model lacks, add it, report the error before and after.
//   diagnose thermal   --data L.csv --target COL --inputs A,B,... [--train-fraction F]
//                      [--declared linear|gmc|gnnmci] [--seed N] [--out R.json]
//   diagnose kinematic --data C.csv [--feed MM_PER_MIN] [--out R.json]
//   diagnose setup     --data R.csv --model M.json [--out R.json]
//   diagnose matching  --data P.csv [--tolerance T] [--out R.json]
// Every domain writes the JSON of docs/file-formats.md#diagnose-result (core/diagnose/diagnosis.h toJson)
// through finishDiagnosis, which also prints the one-line summary.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/kinematics/measured_path.h"
#include "core/matching/hole_table.h"
#include "core/matching/probe_points.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/study/diagnosis_study.h"
#include "core/study/study_settings.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"

namespace metrofit::cli {
namespace {

struct MethodArgs {
  std::string model, data, method, machine, errors, path, target, inputs, out, declared = "linear";
  // Defaults come from the diagnosis study's settings type (core/study/study_settings.h
  // DiagnosisDomainSettings), as a project's; the seed (no study key) from the thermal loop's options.
  std::uint64_t seed = diagnose::ThermalDiagnosisOptions{}.seed;
  double tolerance = DiagnosisDomainSettings{}.toleranceMm;
  double trainFraction = DiagnosisDomainSettings{}.trainFraction;
  double feed = DiagnosisDomainSettings{}.feedMmPerMin;
  int part = 0;  ///< matching: a QIF file of several measured parts, the part (1-based)
  bool allowScale = false;
};

std::string num(double v, int digits = 3) {
  return std::isfinite(v) ? CsvWriter::formatNumber(v, digits) : "n/a";
}

/// The progress line of a diagnosis on a terminal: "diagnose thermal: candidate 12".
std::function<std::string(const IterationSummary&)> candidateLine(std::string what) {
  return [what = std::move(what)](const IterationSummary& s) {
    return what + ": candidate " + std::to_string(s.evaluations);
  };
}

/// Writes the JSON of docs/file-formats.md#diagnose-result (atomically to `out`, or stdout) and prints the
/// one-line summary: "diagnose <domain> on <data>: rmse a -> b <unit>[, held-out h0 -> h1]; accepted: x
/// (params); N tried; residual white: ... | not white: still depends on ...[; k outliers excluded]".
/// `extra`: keys added to the JSON (an MTConnect log's resampling and rows left out for gaps).
int finishDiagnosis(const diagnose::Diagnosis& d, const std::string& data, const std::string& out,
                    const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json j = diagnose::toJson(d);
  for (const auto& [key, value] : extra.items()) j[key] = value;
  writeResult(out, dumpJson(j));
  const std::string u = d.units.empty() ? "" : " " + d.units;
  std::string line = "diagnose " + d.domain + " on " + data + ": rmse " + num(d.baseline.rmse) + " -> " +
                     num(d.final.rmse) + u;
  if (d.baseline.heldoutRmse && d.final.heldoutRmse)
    line += ", held-out rmse " + num(*d.baseline.heldoutRmse) + " -> " + num(*d.final.heldoutRmse) + u;
  const auto acc = d.accepted();
  if (acc.empty()) {
    line += "; no undeclared effect found";
  } else {
    line += "; accepted:";
    for (std::size_t i = 0; i < acc.size(); ++i) {
      line += (i ? ", " : " ") + acc[i]->name + " (";
      for (std::size_t k = 0; k < acc[i]->parameters.size(); ++k) {
        const auto& p = acc[i]->parameters[k];
        line += (k ? " " : "") + p.name + " ";
        if (const double* v = std::get_if<double>(&p.value))
          line += num(*v);
        else
          line += std::get<std::string>(p.value);
      }
      line += ")";
    }
  }
  line += "; " + std::to_string(d.effects.size()) + " candidates tried";
  if (d.residualCheck) {
    line += "; residual " + d.residualCheck->summary;
    if (!d.residualCheck->outliers.empty())
      line += "; " + std::to_string(d.residualCheck->outliers.size()) + " outliers excluded";
  }
  if (d.baseline.heldoutRmse && d.final.heldoutRmse && !d.accepted().empty() &&
      *d.final.heldoutRmse > *d.baseline.heldoutRmse)
    line +=
        "; warning: the held-out rmse rose with the accepted effects (they do not carry over beyond the "
        "fit rows)";
  if (d.heldoutCheck) {
    if (!d.heldoutCheck->white) line += "; held-out rows: " + d.heldoutCheck->summary;
    if (!d.heldoutCheck->outliers.empty())
      line += "; " + std::to_string(d.heldoutCheck->outliers.size()) + " held-out outliers excluded";
  }
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

int runThermal(const MethodArgs& a) {
  const ThermalLog log = readThermalArgs(a.data, a.target, a.inputs);
  diagnose::ThermalDiagnosisOptions o;
  o.target = a.target;
  o.inputs = splitList(a.inputs);
  o.trainFraction = a.trainFraction;
  o.declared = diagnose::thermalDeclaredModel(a.declared);
  o.seed = a.seed;
  diagnose::Diagnosis d;
  {
    TerminalProgress progress(candidateLine("diagnose thermal"));
    d = diagnose::diagnoseThermal(log, o, progress.observer());
  }
  nlohmann::json extra = nlohmann::json::object();
  if (log.gaps) {
    // An MTConnect log (docs/file-formats.md#mtconnect-logs): diagnosed on its rows without a gap in the
    // target or an input.
    std::vector<std::string> used = o.inputs;
    used.push_back(o.target);
    std::size_t leftOut = 0;
    (void)thermal::thermalLogWithoutGaps(log, used, &leftOut);
    extra["resampling"] = log.resampling;
    extra["rows_with_gaps_left_out"] = leftOut;
  }
  return finishDiagnosis(d, a.data, a.out, extra);
}

int runKinematic(const MethodArgs& a) {
  const MeasuredPath path = readMeasuredPath(a.data, csvOptions());
  diagnose::KinematicDiagnosisOptions o;
  o.feedMmPerMin = a.feed;
  diagnose::Diagnosis d;
  {
    TerminalProgress progress(candidateLine("diagnose kinematic"));
    d = diagnose::diagnoseKinematic(path, o, progress.observer());
  }
  return finishDiagnosis(d, a.data, a.out);
}

/// Setup (core/diagnose/setup_diagnosis.h): the report series (CSV or DMIS) against the model.
int runSetup(const MethodArgs& a) {
  const setup::Model model = setup::readModel(a.model);
  const setup::Measurements m = setup::readMeasurements({a.data}, model, csvOptions(), dmisOptions());
  diagnose::Diagnosis d;
  {
    TerminalProgress progress(candidateLine("diagnose setup"));
    d = diagnose::diagnoseSetup(model, m, {}, progress.observer());
  }
  return finishDiagnosis(d, a.data, a.out);
}

/// Matching (core/diagnose/matching_diagnosis.h): probe CSV or PC-DMIS hole table.
int runMatching(const MethodArgs& a) {
  const ProbePointSet set = readProbePointsAnyFormat(a.data, 3, csvOptions(), a.part);
  diagnose::MatchingDiagnosisOptions o;
  o.toleranceMm = a.tolerance;
  diagnose::Diagnosis d;
  {
    TerminalProgress progress(candidateLine("diagnose matching"));
    d = diagnose::diagnoseMatching(set, o, progress.observer());
  }
  return finishDiagnosis(d, a.data, a.out);
}

}  // namespace

void registerDiagnoseCommands(CLI::App& app) {
  auto* dg =
      app.add_subcommand("diagnose", "Closed loop: residual -> missing effect -> error before and after");
  dg->require_subcommand(1);
  const std::map<std::string, std::string> summaries = {
      {"thermal",
       "Thermal log: displacement as a static function of --inputs; tries lag, undeclared inputs, drift"},
      {"kinematic",
       "Circular test: actuator origins and orientations; tries backlash, scale, cyclic error, servo lag"},
      {"setup", "CMM report series: constant setup-data errors; tries tool wear and drift of a datum"},
      {"matching", "Probe points: rigid posture; tries scale, surface offsets, in-plane distortion"}};
  for (const char* domain : {"thermal", "kinematic", "setup", "matching"}) {
    auto a = std::make_shared<MethodArgs>();
    auto* sub = dg->add_subcommand(domain, summaries.at(domain));
    existingFile(sub->add_option("--data", a->data, "Measured data")->required());
    if (std::string(domain) == "setup")
      existingFile(sub->add_option("--model", a->model, "Setup model (JSON)")->required());
    if (std::string(domain) == "thermal") {
      sub->add_option("--target", a->target, "Column to model")->required();
      sub->add_option("--inputs", a->inputs, "Declared input columns")->required();
      sub->add_option("--train-fraction", a->trainFraction, "Fraction of rows fitted; the rest is held out")
          ->check(CLI::Range(0.05, 0.95))
          ->capture_default_str();
      sub->add_option(
             "--declared", a->declared,
             "Declared model the loop starts from: linear (static regression), gmc (GMC(1,N)) or gnnmci "
             "(GNNMCI(1,N), trained with --seed)")
          ->check(CLI::IsMember({"linear", "gmc", "gnnmci"}))
          ->capture_default_str();
    }
    if (std::string(domain) == "kinematic") {
      sub->add_option("--feed", a->feed, "Feed rate of the test, mm/min (for servo_lag's tau_s)")
          ->check(positiveNumber())
          ->capture_default_str();
    }
    if (std::string(domain) == "matching") {
      sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")->check(positiveNumber());
      sub->add_option("--part", a->part, "A QIF file of several measured parts: the part, by its number")
          ->check(CLI::Range(1, 1000000));
    }
    addSeed(sub, a->seed);
    if (std::string(domain) == "thermal") {
      addThermalLogOptions(sub);
    } else {
      addCsvOptions(sub);
    }
    if (std::string(domain) == "setup") addDmisOptions(sub);
    addOut(sub, a->out);
    const std::string d = domain;
    sub->callback([a, d] {
      selectRunner([a, d]() -> int {
        if (d == "thermal") return runThermal(*a);
        if (d == "kinematic") return runKinematic(*a);
        if (d == "setup") return runSetup(*a);
        return runMatching(*a);  // the loop above registers these four domains only
      });
    });
  }
}

}  // namespace metrofit::cli
