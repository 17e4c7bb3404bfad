// metrofit-bench --diagnose --open (see bench_open_world.h).
//
// Protocol: seeds 1..N (N = --seeds, default 100) per case; the data of core/sim/open_world.h at the
// effect-to-noise ratio (5: the visible part of the effect has rms 5 sigma; a gross error is 30
// sigma), Gaussian noise in the effect and gross-error cases, diagnosed with the defaults of each
// domain:
//   thermal    diagnoseThermal, target disp_z_um, declared inputs T2, T4, T_amb;
//   kinematic  diagnoseKinematic, feed 1000 mm/min;
//   setup      diagnoseSetup on the demo's paper model (resources/demo/setup/paper_example.json),
//              20 parts;
//   matching   diagnoseMatching on the S-piece's 40 points with normals.
// A gross error counts as listed when an entry of residual_check.outliers has the 1-based data row
// of the one simulated (or, for an entry without a row, its unit), or its id (matching), or its part
// and dimension (setup). A generic effect is an accepted candidate with `generic` set or a name
// starting with `unexplained:`; every other accepted name is a catalogue name.
#include "bench_open_world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/sim/open_world.h"

namespace metrofit::bench {
namespace {

using diagnose::Diagnosis;
using diagnose::ResidualCheck;

struct Result {
  Diagnosis diagnosis;
  OpenWorldTruth truth;
};
using Runner = std::function<Result(const std::string& name, double ratio, std::uint64_t seed)>;

Runner runnerFor(OpenWorldDomain domain, const std::string& sourceDir) {
  switch (domain) {
    case OpenWorldDomain::Thermal:
      return [](const std::string& name, double ratio, std::uint64_t seed) {
        OpenThermalCase c = openWorldThermal(name, ratio, seed);
        diagnose::ThermalDiagnosisOptions o;
        o.target = c.target;
        o.inputs = c.inputs;
        return Result{diagnose::diagnoseThermal(c.log, o), std::move(c.truth)};
      };
    case OpenWorldDomain::Kinematic:
      return [](const std::string& name, double ratio, std::uint64_t seed) {
        OpenKinematicCase c = openWorldKinematic(name, ratio, seed);
        diagnose::KinematicDiagnosisOptions o;
        o.feedMmPerMin = c.feedMmPerMin;
        return Result{diagnose::diagnoseKinematic(c.path, o), std::move(c.truth)};
      };
    case OpenWorldDomain::Setup: {
      auto model = std::make_shared<setup::Model>(
          setup::readModel(sourceDir + "/resources/demo/setup/paper_example.json"));
      return [model](const std::string& name, double ratio, std::uint64_t seed) {
        OpenSetupCase c = openWorldSetup(*model, name, ratio, seed);
        return Result{diagnose::diagnoseSetup(*model, c.measurements), std::move(c.truth)};
      };
    }
    case OpenWorldDomain::Matching:
      break;
  }
  return [](const std::string& name, double ratio, std::uint64_t seed) {
    OpenMatchingCase c = openWorldMatching(name, ratio, seed);
    return Result{diagnose::diagnoseMatching(c.points), std::move(c.truth)};
  };
}

/// What one diagnosis says about one case.
struct Trial {
  bool error = false;           // the diagnosis threw
  bool hasCheck = false;        // residual_check present
  bool white = true;            // residual_check.white (true without a check)
  bool generic = false;         // an `unexplained:*` effect accepted
  bool catalogue = false;       // a catalogue name accepted
  bool rightVariable = false;   // strongest structure / accepted generic names a truth variable
  bool outlierListed = false;   // the simulated gross error is among the outliers
  std::size_t outliers = 0;     // outliers listed
  double finalOverSigma = 0.0;  // final fit rmse / noise sigma
  double amplitude = 0.0;       // the simulated effect's amplitude (data units)
  double position = -1.0;       // a step's or gross error's place in the data order (0..1), else -1
  bool grossCase = false;       // the case is a gross error
  bool blockCase = false;       // the case is a block of points off the rest (truth.blockRows)
  bool blockReported = false;   // >= 90 % of the block's rows are among the outliers or blocks
  std::vector<std::string> catalogueNames;
  std::string strongest;  // against of the strongest structure (or of the generic effect)
};

bool inTruth(const OpenWorldTruth& t, const std::string& against) {
  for (const auto& a : t.against)
    if (a == against) return true;
  return false;
}

Trial judge(const Result& r) {
  Trial t;
  const Diagnosis& d = r.diagnosis;
  t.finalOverSigma = d.final.rmse / r.truth.noiseSigma;
  t.amplitude = r.truth.amplitude;
  t.position = r.truth.position.value_or(-1.0);
  t.grossCase = r.truth.kind == OpenCaseKind::Outlier;
  t.blockCase = !r.truth.blockRows.empty();
  std::set<long> reportedRows;  // rows of the outliers and blocks the checks report
  for (const auto* c : d.accepted()) {
    if (c->generic || c->name.rfind("unexplained:", 0) == 0) {
      t.generic = true;
      const std::string against = c->generic ? c->generic->against : c->name.substr(12);
      if (t.strongest.empty()) t.strongest = against;
      t.rightVariable |= inTruth(r.truth, against);
    } else {
      t.catalogue = true;
      t.catalogueNames.push_back(c->name);
    }
  }
  // The check of the fitted rows and (thermal) the held-out rows' own check: a structure or a gross
  // error either one reports counts.
  std::vector<const ResidualCheck*> checks;
  if (d.residualCheck) checks.push_back(&*d.residualCheck);
  if (d.heldoutCheck) checks.push_back(&*d.heldoutCheck);
  for (const ResidualCheck* check : checks) {
    const auto& rc = *check;
    t.white = t.hasCheck ? t.white && rc.white : rc.white;
    t.hasCheck = true;
    if (!rc.structure.empty()) {
      if (t.strongest.empty()) t.strongest = rc.structure.front().against;
      t.rightVariable |= inTruth(r.truth, rc.structure.front().against);
    }
    t.outliers += rc.outliers.size();
    for (const auto& o : rc.outliers) reportedRows.insert(o.row.value_or(static_cast<long>(o.unit) + 1));
    for (const auto& b : rc.blocks) reportedRows.insert(b.rows.begin(), b.rows.end());
    const OpenWorldTruth& w = r.truth;
    for (const auto& o : rc.outliers) {
      if (!w.outlierUnit) break;
      // The 1-based data row when the entry has one (its unit may index the refitted set), else the unit.
      const bool rowOrUnit = o.row ? (w.outlierRow && *o.row == *w.outlierRow) : o.unit == *w.outlierUnit;
      const bool id = o.id && !w.outlierId.empty() && *o.id == w.outlierId;
      const bool partDim = o.part && o.dimension && !w.outlierPart.empty() && *o.part == w.outlierPart &&
                           *o.dimension == w.outlierDimension;
      t.outlierListed |= rowOrUnit || id || partDim;
    }
  }
  if (t.blockCase) {
    std::size_t hit = 0;
    for (long row : r.truth.blockRows) hit += reportedRows.count(row);
    t.blockReported = 10 * hit >= 9 * r.truth.blockRows.size();
  }
  return t;
}

struct Tally {
  int runs = 0, errors = 0, noCheck = 0;
  int detected = 0, generic = 0, flaggedOnly = 0, catalogue = 0, rightVariable = 0;
  int falseFlag = 0, outliersListed = 0, truthListed = 0, notWhite = 0, anyAccepted = 0;
  int blockRuns = 0, blockReported = 0;
  std::map<std::string, int> catalogueNames, strongest;
  std::vector<double> finalOverSigma, amplitude;
  // Steps and gross errors by their place in the data: [0] first half, [1] second half (a thermal
  // fit uses the first half); runs and hits (effects: found; gross errors: listed).
  int halfRuns[2] = {0, 0}, halfHits[2] = {0, 0};
  double seconds = 0.0;

  void add(const Trial& t) {
    ++runs;
    if (t.error) {
      ++errors;
      return;
    }
    noCheck += !t.hasCheck;
    finalOverSigma.push_back(t.finalOverSigma);
    amplitude.push_back(t.amplitude);
    if (t.position >= 0.0) {
      const int h = t.position < 0.5 ? 0 : 1;
      ++halfRuns[h];
      halfHits[h] += t.grossCase ? t.outlierListed : (!t.white || t.generic || t.catalogue);
    }
    const bool accepted = t.generic || t.catalogue;
    detected += !t.white || accepted;
    generic += t.generic;
    flaggedOnly += !t.white && !accepted;
    catalogue += t.catalogue;
    rightVariable += t.rightVariable;
    falseFlag += !t.white || accepted;
    notWhite += !t.white;
    anyAccepted += accepted;
    outliersListed += t.outliers > 0;
    truthListed += t.outlierListed;
    blockRuns += t.blockCase;
    blockReported += t.blockReported;
    for (const auto& n : t.catalogueNames) ++catalogueNames[n];
    if (!t.strongest.empty()) ++strongest[t.strongest];
  }
};

double pct(int k, int n) {
  return n > 0 ? 100.0 * k / n : 0.0;
}

std::string fixed1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string topList(const std::map<std::string, int>& m) {
  std::vector<std::pair<int, std::string>> v;
  for (const auto& [k, c] : m) v.push_back({c, k});
  std::sort(v.rbegin(), v.rend());
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < 3; ++i)
    s += (s.empty() ? "" : ", ") + v[i].second + " " + std::to_string(v[i].first);
  return s;
}

nlohmann::json tallyJson(const Tally& t) {
  return {{"runs", t.runs},
          {"errors", t.errors},
          {"without_residual_check", t.noCheck},
          {"flagged_or_explained", t.detected},
          {"explained_generic", t.generic},
          {"flagged_only", t.flaggedOnly},
          {"catalogue_accepted", t.catalogue},
          {"right_variable", t.rightVariable},
          {"not_white", t.notWhite},
          {"any_accepted", t.anyAccepted},
          {"outliers_listed", t.outliersListed},
          {"gross_error_listed", t.truthListed},
          {"block_runs", t.blockRuns},
          {"block_reported", t.blockReported},
          {"catalogue_names", t.catalogueNames},
          {"strongest_against", t.strongest},
          {"final_rmse_over_sigma_median", median(t.finalOverSigma)},
          {"amplitude_median", median(t.amplitude)},
          {"first_half", {{"runs", t.halfRuns[0]}, {"hits", t.halfHits[0]}}},
          {"second_half", {{"runs", t.halfRuns[1]}, {"hits", t.halfHits[1]}}},
          {"seconds", t.seconds}};
}

/// The cases added for the loop's two misses (issue 32 item 5) and their own targets: found (not
/// white, or an effect accepted, or the block's rows reported) >= 95 %; a catalogue name accepted
/// (the false effect: the nearest name for a shape no entry models, or a name for a block of points)
/// <= 2 %; and for a block, its rows reported (>= 90 % of them among the outliers or blocks of the
/// check) >= 95 %.
const std::set<std::string>& issue32Cases() {
  static const std::set<std::string> names{"centrifugal_rpm", "scale_damage", "local_bump", "tool_runin",
                                           "surface_tilt"};
  return names;
}

}  // namespace

nlohmann::json benchDiagnoseOpen(const OpenBenchOptions& o) {
  std::vector<OpenWorldDomain> domains;
  for (OpenWorldDomain d : {OpenWorldDomain::Thermal, OpenWorldDomain::Kinematic, OpenWorldDomain::Setup,
                            OpenWorldDomain::Matching})
    if (o.domains.empty() || std::find(o.domains.begin(), o.domains.end(), toString(d)) != o.domains.end())
      domains.push_back(d);
  nlohmann::json out{{"ratio", o.ratio}, {"seeds", o.seeds}, {"domains", nlohmann::json::object()}};
  std::printf("diagnose-open  effect-to-noise %.1f (gross errors %.0f sigma), %d seeds per case\n", o.ratio,
              6.0 * o.ratio, o.seeds);
  std::printf("diagnose-open  %-9s %-20s %5s %8s %8s %8s %8s %8s %8s %8s %7s  %s\n", "domain", "case", "runs",
              "found", "generic", "flagonly", "catalog", "rightvar", "outl.lst", "rmse/sd", "s", "notes");
  for (OpenWorldDomain domain : domains) {
    const Runner run = runnerFor(domain, o.sourceDir);
    Tally effects, open, clean, gross;
    std::vector<std::pair<std::string, Tally>> added;  // issue32Cases of the domain
    nlohmann::json cases = nlohmann::json::object();
    for (const OpenWorldCaseInfo& info : openWorldCases(domain)) {
      Tally t;
      std::string firstError;
      const auto start = std::chrono::steady_clock::now();
      for (int s = 1; s <= o.seeds; ++s) {
        Trial trial;
        try {
          trial = judge(run(info.name, o.ratio, static_cast<std::uint64_t>(s)));
        } catch (const std::exception& e) {
          trial.error = true;
          if (firstError.empty()) firstError = e.what();
        }
        t.add(trial);
        if (info.kind == OpenCaseKind::Effect) effects.add(trial);
        if (info.kind != OpenCaseKind::Clean) open.add(trial);
        if (info.kind == OpenCaseKind::Clean) clean.add(trial);
        if (info.kind == OpenCaseKind::Outlier) gross.add(trial);
      }
      t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::string notes;
      auto note = [&](const std::string& part) { notes += (notes.empty() ? "" : "; ") + part; };
      if (info.kind == OpenCaseKind::Clean) note("false flags " + fixed1(pct(t.falseFlag, t.runs)) + " %");
      if (info.kind == OpenCaseKind::Outlier)
        note("gross error listed " + fixed1(pct(t.truthListed, t.runs)) + " %");
      if (t.blockRuns) note("block rows reported " + fixed1(pct(t.blockReported, t.blockRuns)) + " %");
      if (info.kind != OpenCaseKind::Clean && !t.amplitude.empty()) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "A %.3g %s", median(t.amplitude),
                      domain == OpenWorldDomain::Thermal ? "um" : "mm");
        note(buf);
      }
      if (t.halfRuns[0] + t.halfRuns[1] > 0)
        note(std::string(info.kind == OpenCaseKind::Outlier ? "listed" : "found") +
             " when in the first half " + fixed1(pct(t.halfHits[0], t.halfRuns[0])) + " % of " +
             std::to_string(t.halfRuns[0]) + ", second half " + fixed1(pct(t.halfHits[1], t.halfRuns[1])) +
             " % of " + std::to_string(t.halfRuns[1]));
      if (!t.catalogueNames.empty()) note("catalogue: " + topList(t.catalogueNames));
      if (!t.strongest.empty()) note("against: " + topList(t.strongest));
      if (t.noCheck) note("no residual_check in " + std::to_string(t.noCheck));
      if (t.errors) note(std::to_string(t.errors) + " errors (" + firstError + ")");
      const int n = t.runs;
      if (info.kind == OpenCaseKind::Clean) {
        std::printf("diagnose-open  %-9s %-20s %5d %7.1f%% %8s %8s %7.1f%% %8s %7.1f%% %8.2f %7.1f  %s\n",
                    toString(domain), info.name.c_str(), n, pct(t.falseFlag, n), "-", "-",
                    pct(t.catalogue, n), "-", pct(t.outliersListed, n), median(t.finalOverSigma), t.seconds,
                    notes.c_str());
      } else if (info.kind == OpenCaseKind::Outlier) {
        std::printf(
            "diagnose-open  %-9s %-20s %5d %7.1f%% %7.1f%% %7.1f%% %7.1f%% %8s %7.1f%% %8.2f %7.1f  %s\n",
            toString(domain), info.name.c_str(), n, pct(t.detected, n), pct(t.generic, n),
            pct(t.flaggedOnly, n), pct(t.catalogue, n), "-", pct(t.truthListed, n), median(t.finalOverSigma),
            t.seconds, notes.c_str());
      } else {
        std::printf(
            "diagnose-open  %-9s %-20s %5d %7.1f%% %7.1f%% %7.1f%% %7.1f%% %7.1f%% %7.1f%% %8.2f %7.1f  %s\n",
            toString(domain), info.name.c_str(), n, pct(t.detected, n), pct(t.generic, n),
            pct(t.flaggedOnly, n), pct(t.catalogue, n), pct(t.rightVariable, n), pct(t.outliersListed, n),
            median(t.finalOverSigma), t.seconds, notes.c_str());
      }
      nlohmann::json j = tallyJson(t);
      j["kind"] = info.kind == OpenCaseKind::Clean     ? "clean"
                  : info.kind == OpenCaseKind::Outlier ? "outlier"
                                                       : "effect";
      j["form"] = info.form;
      if (!firstError.empty()) j["first_error"] = firstError;
      if (issue32Cases().count(info.name)) added.emplace_back(info.name, t);
      cases[info.name] = std::move(j);
    }
    const double a = pct(effects.detected, effects.runs), b = pct(open.catalogue, open.runs),
                 c = pct(clean.falseFlag, clean.runs), cOut = pct(clean.outliersListed, clean.runs),
                 dl = pct(gross.truthListed, gross.runs);
    std::printf(
        "diagnose-open  %-9s (a) structure flagged or explained %.1f %% (target >= 95 %%): generic %.1f %%, "
        "flagged only %.1f %%, catalogue name %.1f %%; right variable %.1f %%\n",
        toString(domain), a, pct(effects.generic, effects.runs), pct(effects.flaggedOnly, effects.runs),
        pct(effects.catalogue, effects.runs), pct(effects.rightVariable, effects.runs));
    std::printf(
        "diagnose-open  %-9s (b) catalogue name accepted on open-world cases %.1f %% (target <= 2 %%)\n",
        toString(domain), b);
    std::printf(
        "diagnose-open  %-9s (c) false flags on clean data %.1f %% (target <= 1 %%); outliers listed on "
        "clean "
        "data %.1f %%\n",
        toString(domain), c, cOut);
    std::printf("diagnose-open  %-9s (d) gross error listed %.1f %%%s\n", toString(domain), dl,
                effects.noCheck + clean.noCheck + gross.noCheck
                    ? "   [results without residual_check counted as white]"
                    : "");
    for (const auto& [name, t] : added) {
      std::printf(
          "diagnose-open  %-9s (e) %s: found %.1f %% (target >= 95 %%), catalogue name %.1f %% (target <= 2 "
          "%%)",
          toString(domain), name.c_str(), pct(t.detected, t.runs), pct(t.catalogue, t.runs));
      if (t.blockRuns)
        std::printf(", block rows reported %.1f %% (target >= 95 %%)", pct(t.blockReported, t.blockRuns));
      std::printf("\n");
    }
    out["domains"][toString(domain)] = {
        {"cases", std::move(cases)},
        {"structure_flagged_or_explained_rate", a / 100.0},
        {"explained_generic_rate", pct(effects.generic, effects.runs) / 100.0},
        {"flagged_only_rate", pct(effects.flaggedOnly, effects.runs) / 100.0},
        {"catalogue_on_effect_cases_rate", pct(effects.catalogue, effects.runs) / 100.0},
        {"right_variable_rate", pct(effects.rightVariable, effects.runs) / 100.0},
        {"wrong_catalogue_rate", b / 100.0},
        {"clean_false_flag_rate", c / 100.0},
        {"clean_outliers_listed_rate", cOut / 100.0},
        {"gross_error_listed_rate", dl / 100.0},
        {"without_residual_check", effects.noCheck + clean.noCheck + gross.noCheck},
        {"errors", open.errors + clean.errors}};
  }
  return out;
}

nlohmann::json benchOpenCase(const OpenBenchOptions& o, const std::string& domain, const std::string& name,
                             std::uint64_t seed) {
  for (OpenWorldDomain d : {OpenWorldDomain::Thermal, OpenWorldDomain::Kinematic, OpenWorldDomain::Setup,
                            OpenWorldDomain::Matching}) {
    if (domain != toString(d)) continue;
    const Result r = runnerFor(d, o.sourceDir)(name, o.ratio, seed);
    const OpenWorldTruth& t = r.truth;
    std::string against;
    for (const auto& a : t.against) against += (against.empty() ? "" : ", ") + a;
    std::printf("open-case %s %s seed %llu, effect-to-noise %.1f: %s; noise %s sigma %.4g; against: %s\n",
                domain.c_str(), name.c_str(), static_cast<unsigned long long>(seed), o.ratio,
                t.description.c_str(), toString(t.noise), t.noiseSigma,
                against.empty() ? "-" : against.c_str());
    const nlohmann::json dj = diagnose::toJson(r.diagnosis);
    std::printf("%s\n", dj.dump(1).c_str());
    return {{"truth",
             {{"case", t.caseName},
              {"form", t.form},
              {"against", t.against},
              {"description", t.description},
              {"amplitude", t.amplitude},
              {"noise_sigma", t.noiseSigma}}},
            {"diagnosis", dj}};
  }
  throw std::runtime_error("unknown domain '" + domain + "' (thermal, kinematic, setup, matching)");
}

}  // namespace metrofit::bench
