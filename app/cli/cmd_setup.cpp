// metrofit-cli setup: setup-data correction (docs/file-formats.md#setup-result).
//
//   setup --model M.json --data R.csv [--data R2.dmo ...] [--method exact|cripso|pso|ga|coa]
//         [--budget N] [--seed N] [--time-limit S] [--out F]
//         [--export fanuc|heidenhain|siemens|csv --export-out F] [--tool-offset wear|geometry]
//         [--export heidenhain-table --export-table CURRENT.PR|CURRENT.T --export-out F] [--program-number N]
//
// heidenhain-table: the control's current preset or tool table (saved from the control) with the
// corrections added to its cells, for import (core/setup/export.h updateHeidenhainTable).
//         [--dfq F.dfq]: also the measured features as a Q-DAS DFQ file (core/io/dfq.h), one
//         characteristic per measured dimension
//
// Reads the relation-graph model (core/setup/model.h) and the measurement reports (CSV of
// docs/file-formats.md#cmm-report-series or DMIS output, core/setup/report.h), corrects the setup data with
// the chosen method and writes the JSON of docs/file-formats.md#setup-result: method, corrections_mm {setup
// datum id: mm}, f1_mm, f2_mm, f, bonus_mm, evaluations, trace; plus f1_before_mm, per-dimension before/after
// values, the exact method's certificate, and for a metaheuristic the exact optimum and its gap (the exact
// method always runs: it takes well under a millisecond on the paper's size). One summary line on stderr.
//
//   setup validate --model M.json [--sets N] [--trials M] [--methods cripso,pso,...] [--budget N]
//         [--w1 MM] [--w2 MM] [--seed N] [--data R.csv ...] [--threads N] [--out F]
//
// The paper's statistical validation (core/study/setup_validation.h, Fig. 18): N simulated sets x M trials,
// the f1(0) range checked against the paper's (-0.011..0.063 mm), the share of the setup data in the
// dimension error estimated on the simulated sets and, with --data, on measured data.
//
//   simulate setup --model M.json [--parts N] [--w1 MM] [--w2 MM] [--seed N] [--out R.csv]
//
// A simulated CMM report series (core/sim/setup_sim.h). registerSimulateSetupCommand() is called by
// commands.cpp on the `simulate` subcommand.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/setup/exact.h"
#include "core/setup/export.h"
#include "core/setup/measurements_dfq.h"
#include "core/setup/methods.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/sim/setup_sim.h"
#include "core/study/setup_validation.h"
#include "core/study/study_settings.h"

namespace metrofit::cli {
namespace {

/// method, budget and seed default to the study's settings (core/study/study_settings.h SetupSettings).
struct SetupArgs {
  std::string model, method = SetupSettings{}.method, out, exportFormat, exportOut, exportTable,
                     toolOffset = "wear", dfq;
  int programNumber = setup::ExportOptions{}.programNumber;
  std::vector<std::string> data;
  long budget = SetupSettings{}.budget;
  std::uint64_t seed = SetupSettings{}.seed;
  double timeLimit = 0.0;
};

std::string fmt(double v, int decimals = 4) {
  char buf[48];
  metrofit::c_snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// Rounds away binary noise (grid values like 0.004000000000000001) for the JSON.
double clean(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0.0 ? 0.0 : r;
}

struct SimulateSetupArgs {
  std::string model, out;
  int parts = 5;
  double w1 = 0.03, w2 = 0.02;
  std::uint64_t seed = 1;
};

int runSimulateSetup(const SimulateSetupArgs& a) {
  const setup::Model model = setup::readModel(a.model);
  SetupSimOptions o;
  o.parts = a.parts;
  o.w1 = a.w1;
  o.w2 = a.w2;
  o.seed = a.seed;
  const std::string csv = simulateSetupReport(model, o);
  writeResult(a.out, csv);
  std::fprintf(stderr, "simulate setup: %d parts x %zu dimensions of %s, w1 %s mm, w2 %s mm, seed %llu\n",
               a.parts, model.dimensions.size(), a.model.c_str(), fmt(a.w1, 3).c_str(), fmt(a.w2, 3).c_str(),
               static_cast<unsigned long long>(a.seed));
  return 0;
}

nlohmann::json traceEntry(const IterationSummary& s, const char* stage = nullptr) {
  nlohmann::json e{{"iteration", s.iteration}, {"evaluations", s.evaluations}};
  if (stage) e["stage"] = stage;
  for (const auto& c : s.components) {
    const std::string key = c.name == "f" ? "f" : c.name + "_mm";
    e[key] = clean(c.value);
  }
  return e;
}

nlohmann::json certificateJson(const setup::ExactCertificate& c) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(clean(v)) : nlohmann::json(nullptr); };
  return {{"solver", c.solver},
          {"lp_status", c.lpStatus},
          {"lp_f1_mm", num(c.lpF1)},
          {"grid_status", c.milpStatus},
          {"f1_optimal_on_grid", c.f1Optimal},
          {"grid_f1_mm", num(c.gridF1)},
          {"next_f1_infeasible_mm", num(c.nextF1Infeasible)},
          {"feasibility_probes", c.feasibilityProbes},
          {"least_norm_status", c.normStatus},
          {"f2_minimal", c.f2Optimal},
          {"f2_lower_bound_mm", num(c.f2LowerBound)},
          {"least_norm_rounds", c.normRounds},
          {"cuts", c.cuts},
          {"solver_calls", c.solverCalls}};
}

int runSetup(const SetupArgs& a) {
  if (!a.exportFormat.empty() && a.exportOut.empty())
    throw OptionsError(ErrorContext{{}, 0, 0, "--export"}, "needs --export-out FILE");
  if (a.exportFormat.empty() && !a.exportOut.empty())
    throw OptionsError(ErrorContext{{}, 0, 0, "--export-out"},
                       "needs --export fanuc|heidenhain|heidenhain-table|siemens|csv");
  if ((a.exportFormat == "heidenhain-table") != !a.exportTable.empty()) {
    throw OptionsError(ErrorContext{{}, 0, 0, a.exportTable.empty() ? "--export" : "--export-table"},
                       a.exportTable.empty()
                           ? "heidenhain-table needs --export-table CURRENT.PR|CURRENT.T (the "
                             "control's current preset or tool table)"
                           : "goes with --export heidenhain-table only");
  }
  {
    setup::ExportOptions xo;
    xo.programNumber = a.programNumber;
    std::string why;
    if (!xo.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "--program-number"}, why);
  }
  const setup::Model model = setup::readModel(a.model);
  const setup::Measurements meas = setup::readMeasurements(a.data, model, csvOptions(), dmisOptions());
  const setup::SetupInstance inst(model, meas);

  setup::ExactOptions eo;
  eo.timeLimitSeconds = a.timeLimit;
  const auto t0 = std::chrono::steady_clock::now();
  const setup::ExactResult exact = setup::solveExact(inst, eo);
  const double exactMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  std::vector<double> x;
  nlohmann::json trace = nlohmann::json::array();
  long evaluations = 0;
  std::string termination;
  if (a.method == "exact") {
    x = exact.x;
    evaluations = exact.certificate.solverCalls;
    const char* stages[] = {"lp", "grid"};
    for (std::size_t i = 0; i < exact.run.trace.size(); ++i)
      trace.push_back(traceEntry(exact.run.trace[i], i < 2 ? stages[i] : "least_norm"));
    termination = toString(exact.run.termination);
  } else {
    const setup::SetupProblem problem(inst);
    const auto algorithm = setup::makeSetupAlgorithm(a.method, a.budget, a.seed);
    optim::Result r;
    {
      TerminalProgress progress([&a](const IterationSummary& s) {
        return "setup: " + a.method + " " +
               std::to_string(static_cast<int>(100.0 * std::max(0.0, s.progress))) + " %, f1 " +
               (s.components.empty() ? std::string("?") : fmt(s.components[0].value)) + " mm";
      });
      r = algorithm->optimise(problem, progress.observer());
    }
    x = r.bestX;
    evaluations = r.run.evaluations;
    for (const auto& s : r.run.trace) trace.push_back(traceEntry(s));
    termination = toString(r.run.termination);
  }
  const setup::SetupScore score = inst.score(x);
  const double f1Before = inst.f1Before();

  nlohmann::json j;
  j["method"] = a.method;
  j["corrections_mm"] = nlohmann::json::object();
  for (std::size_t i = 0; i < x.size(); ++i) j["corrections_mm"][inst.datumIds()[i]] = clean(x[i]);
  j["f1_mm"] = clean(score.f1);
  j["f2_mm"] = clean(score.f2);
  j["f"] = clean(score.f);
  j["bonus_mm"] = clean(score.f1 - f1Before);
  j["evaluations"] = evaluations;
  j["trace"] = std::move(trace);
  j["f1_before_mm"] = clean(f1Before);
  j["termination"] = termination;
  j["model"] = a.model;
  j["data"] = a.data;
  j["parts"] = meas.parts.size();
  j["step_mm"] = model.stepMm;
  {
    const std::vector<double> zero(x.size(), 0.0);
    const auto devAfter = inst.deviationsAfter(x);
    const auto budBefore = inst.budgets(zero), budAfter = inst.budgets(x);
    nlohmann::json dims = nlohmann::json::array();
    for (std::size_t q = 0; q < inst.dimensions(); ++q) {
      dims.push_back({{"id", inst.dimensionIds()[q]},
                      {"lower_mm", inst.lowerLimit(q)},
                      {"upper_mm", inst.upperLimit(q)},
                      {"deviation_before_mm", clean(inst.deviation(q))},
                      {"deviation_after_mm", clean(devAfter[q])},
                      {"budget_before_mm", clean(budBefore[q])},
                      {"budget_after_mm", clean(budAfter[q])}});
    }
    j["dimensions"] = std::move(dims);
  }
  nlohmann::json ex{{"f1_mm", clean(exact.score.f1)},
                    {"f2_mm", clean(exact.score.f2)},
                    {"f", clean(exact.score.f)},
                    {"certificate", certificateJson(exact.certificate)}};
  if (a.method == "exact") {
    j["certificate"] = certificateJson(exact.certificate);
  } else {
    j["seed"] = a.seed;
    j["budget"] = a.budget;
    j["exact"] = ex;
    j["gap_f1_mm"] = clean(exact.score.f1 - score.f1);
    j["gap_f2_mm"] = clean(score.f2 - exact.score.f2);
  }

  if (!a.exportFormat.empty()) {
    setup::ExportOptions xo;
    xo.toolOffset = a.toolOffset == "geometry" ? setup::ToolOffset::Geometry : setup::ToolOffset::Wear;
    xo.programNumber = a.programNumber;
    if (a.exportFormat == "heidenhain-table") {
      const setup::TableUpdate u =
          setup::updateHeidenhainTable(model, x, readFile(a.exportTable), a.exportTable, xo);
      writeFileAtomic(a.exportOut, u.text);
      j["export"] = {{"format", a.exportFormat}, {"file", a.exportOut},  {"table", u.table},
                     {"from", a.exportTable},    {"written", u.written}, {"not_written", u.notWritten}};
    } else {
      const std::string text =
          setup::exportCorrections(model, x, setup::parseControllerFormat(a.exportFormat, "--export"), xo);
      writeFileAtomic(a.exportOut, text);
      j["export"] = {{"format", a.exportFormat}, {"file", a.exportOut}};
    }
  }
  if (!a.dfq.empty()) {
    writeFileAtomic(a.dfq, writeDfq(setup::measurementsDfqPart(
                               model, meas, std::filesystem::path(a.model).stem().string())));
  }
  writeResult(a.out, dumpJson(j));

  std::string line = "setup: " + a.method + " on " + std::to_string(inst.dimensions()) + " dimensions of " +
                     std::to_string(meas.parts.size()) + (meas.parts.size() == 1 ? " part" : " parts") +
                     ", " + std::to_string(inst.variables()) + " setup data: f1 " + fmt(f1Before) + " -> " +
                     fmt(score.f1) + " mm (bonus " + fmt(score.f1 - f1Before) + "), |x| " + fmt(score.f2) +
                     " mm";
  if (a.method == "exact") {
    line += std::string("; f1 ") + (exact.certificate.f1Optimal ? "optimal" : "NOT proven optimal") +
            " on the grid, |x| " + (exact.certificate.f2Optimal ? "minimal" : "not proven minimal") + " (" +
            fmt(exactMs, 2) + " ms)";
  } else {
    line += ", " + std::to_string(evaluations) + " evaluations; gap to exact f1 " +
            fmt(exact.score.f1 - score.f1) + " mm";
  }
  if (!a.exportFormat.empty()) line += "; " + a.exportFormat + " -> " + a.exportOut;
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

struct ValidateArgs {
  std::string model, methods = "cripso", out;
  std::vector<std::string> data;
  int sets = 100, trials = 10, threads = 0;
  long budget = setup::kPaperBudget;
  double w1 = 0.03, w2 = 0.02;
  std::uint64_t seed = 1;
};

nlohmann::json shareJson(const setup::ShareEstimate& e) {
  return {{"sets", e.sets},
          {"w1_mm", clean(e.w1Mm)},
          {"w2_mm", clean(e.w2Mm)},
          {"weight_share", clean(e.weightShare)},
          {"variance_share", clean(e.varianceShare)}};
}

int runSetupValidate(const ValidateArgs& a) {
  const setup::Model model = setup::readModel(a.model);
  setup::ValidationOptions o;
  o.sets = static_cast<std::size_t>(a.sets);
  o.trials = a.trials;
  o.methods = splitList(a.methods);
  o.budget = a.budget;
  o.simulation.w1 = a.w1;
  o.simulation.w2 = a.w2;
  o.simulation.seed = a.seed;
  o.seed = a.seed;
  o.threads = a.threads;
  for (const std::string& m : o.methods) {
    const auto names = setup::setupMetaheuristicNames();
    if (std::find(names.begin(), names.end(), m) == names.end())
      throw OptionsError(ErrorContext{{}, 0, 0, "--methods"},
                         "'" + m + "' is not a metaheuristic of the setup correction (cripso, pso, ga, coa)");
  }
  std::optional<setup::Measurements> measured;
  if (!a.data.empty()) measured = setup::readMeasurements(a.data, model, csvOptions(), dmisOptions());

  setup::ValidationResult r;
  {
    TerminalProgress progress;
    r = setup::runValidation(model, o, nullptr, [&progress](std::size_t done, std::size_t total) {
      progress.show("setup validate: set " + std::to_string(done) + " of " + std::to_string(total));
    });
  }
  const setup::ValidationSummary sum = setup::summarizeValidation(model, o, r);

  nlohmann::json j;
  j["model"] = a.model;
  j["sets"] = sum.sets;
  j["trials"] = a.trials;
  j["methods"] = o.methods;
  j["budget"] = a.budget;
  j["w1_mm"] = a.w1;
  j["w2_mm"] = a.w2;
  j["seed"] = a.seed;
  j["f1_before_mm"] = {
      {"min", clean(sum.f1BeforeMin)}, {"max", clean(sum.f1BeforeMax)}, {"mean", clean(sum.f1BeforeMean)}};
  j["exact"] = {{"f1_mean_mm", clean(sum.exactF1Mean)},
                {"bonus_mean_mm", clean(sum.bonusMean)},
                {"proven", sum.exactProven}};
  j["paper_range"] = {{"f1_before_min_mm", setup::kPaperF1BeforeMinMm},
                      {"f1_before_max_mm", setup::kPaperF1BeforeMaxMm},
                      {"min_band_mm", {clean(sum.minBandLo), clean(sum.minBandHi)}},
                      {"max_band_mm", {clean(sum.maxBandLo), clean(sum.maxBandHi)}},
                      {"applies", sum.paperRangeApplies},
                      {"consistent", sum.paperRangeConsistent}};
  nlohmann::json methods = nlohmann::json::object();
  for (const setup::ValidationMethodSummary& m : sum.methods) {
    methods[m.method] = {{"trials", m.trials},
                         {"mean_f1_mm", clean(m.meanF1)},
                         {"mean_gap_f1_mm", clean(m.meanGapF1)},
                         {"max_gap_f1_mm", clean(m.maxGapF1)},
                         {"within_one_step", m.withinStep}};
  }
  j["method_summary"] = std::move(methods);
  nlohmann::json share = shareJson(sum.share);
  share["configured_weight_share"] = clean(a.w1 + a.w2 > 0.0 ? a.w1 / (a.w1 + a.w2) : 0.0);
  j["share"] = std::move(share);
  std::optional<setup::ShareEstimate> dataShare;
  if (measured) {
    dataShare = setup::estimateSetupShare(model, setup::partDeviationSets(model, *measured));
    nlohmann::json d = shareJson(*dataShare);
    d["data"] = a.data;
    // The paper's comparison with Fig. 18: what the data's exact optimum reaches against what the
    // validation foresees for the data's f1 before correction.
    const setup::SetupInstance inst(model, *measured);
    const double exactF1 = setup::solveExact(inst).score.f1;
    const double foreseen = setup::foreseenF1(r, inst.f1Before());
    d["f1_before_mm"] = clean(inst.f1Before());
    d["exact_f1_mm"] = clean(exactF1);
    if (std::isfinite(foreseen)) {
      d["foreseen_f1_mm"] = clean(foreseen);
      d["share_than_configured"] = exactF1 < foreseen - model.stepMm   ? "smaller"
                                   : exactF1 > foreseen + model.stepMm ? "larger"
                                                                       : "similar";
    }
    j["data_share"] = std::move(d);
  }
  // Fig. 18: the sets sorted by f1 before correction, with the exact optimum and every trial's f1.
  nlohmann::json series = nlohmann::json::array();
  const auto order = r.sortedByBefore();
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const setup::ValidationSet& vs = r.sets[order[rank]];
    nlohmann::json trials = nlohmann::json::object();
    for (const std::string& m : o.methods) trials[m] = nlohmann::json::array();
    for (const setup::ValidationTrial& t : vs.trials) trials[t.method].push_back(clean(t.f1));
    series.push_back({{"rank", rank + 1},
                      {"set", vs.index},
                      {"f1_before_mm", clean(vs.f1Before)},
                      {"exact_f1_mm", clean(vs.exactF1)},
                      {"f1_mm", std::move(trials)}});
  }
  j["series"] = std::move(series);
  writeResult(a.out, dumpJson(j));

  std::string line = "setup validate: " + std::to_string(sum.sets) + " sets x " + std::to_string(a.trials) +
                     " trials of " + a.methods + ", w1 " + fmt(a.w1, 3) + " w2 " + fmt(a.w2, 3) +
                     " mm: f1 before " + fmt(sum.f1BeforeMin) + " .. " + fmt(sum.f1BeforeMax) +
                     " mm (paper " + fmt(setup::kPaperF1BeforeMinMm, 3) + " .. " +
                     fmt(setup::kPaperF1BeforeMaxMm, 3) + ": " +
                     (sum.paperRangeApplies ? (sum.paperRangeConsistent ? "consistent" : "NOT consistent")
                                            : "other weights, not compared") +
                     ")";
  for (const setup::ValidationMethodSummary& m : sum.methods)
    line += "; " + m.method + " mean gap " + fmt(m.meanGapF1) + " mm, " + std::to_string(m.withinStep) + "/" +
            std::to_string(m.trials) + " within one step";
  line += "; setup share " + fmt(100.0 * sum.share.weightShare, 0) + " % (configured " +
          fmt(100.0 * (a.w1 + a.w2 > 0.0 ? a.w1 / (a.w1 + a.w2) : 0.0), 0) + " %)";
  if (dataShare)
    line += ", in the data " + fmt(100.0 * dataShare->weightShare, 0) + " % (variance " +
            fmt(100.0 * dataShare->varianceShare, 0) + " %)";
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

}  // namespace

void registerSetupCommand(CLI::App& app) {
  auto a = std::make_shared<SetupArgs>();
  auto* sub = app.add_subcommand("setup", "Setup-data correction (work and tool offsets) from CMM reports");
  // --model and --data are required unless `setup validate` runs (checked in the callback).
  existingFile(sub->add_option("--model", a->model, "Setup model (relation graph, JSON), required"));
  existingFile(
      sub->add_option("--data", a->data,
                      "Measurement report(s): CMM series CSV, DMIS output, a CMM text report, a Q-DAS "
                      "DFQ file or a Zeiss Calypso _chr table, required")
          ->take_all());
  addCsvOptions(sub);
  addDmisOptions(sub);
  sub->add_option("--method", a->method, "exact|cripso|pso|ga|coa")
      ->check(CLI::IsMember(setup::setupMethodNames()))
      ->capture_default_str();
  sub->add_option("--budget", a->budget, "Evaluation budget of a metaheuristic")
      ->check(CLI::Range(1L, 100000000L))
      ->capture_default_str();
  sub->add_option("--time-limit", a->timeLimit,
                  "Time limit of every LP/MILP solve of the exact method, s (0: none)")
      ->check(CLI::Range(0.0, 1.0e6));
  sub->add_option(
         "--export", a->exportFormat,
         "Also write the corrections for a controller: fanuc|heidenhain|heidenhain-table|siemens|csv")
      ->check(CLI::IsMember({"fanuc", "heidenhain", "heidenhain-table", "siemens", "csv"}));
  sub->add_option("--export-out", a->exportOut, "File for --export (written atomically)");
  existingFile(sub->add_option("--export-table", a->exportTable,
                               "heidenhain-table: the control's current preset (.PR) or tool table (.T)"));
  sub->add_option("--program-number", a->programNumber, "Fanuc program number of --export fanuc (1..7999)")
      ->capture_default_str();
  sub->add_option(
      "--dfq", a->dfq,
      "Also write the measured features as a Q-DAS DFQ file (one characteristic per dimension; atomic)");
  sub->add_option("--tool-offset", a->toolOffset, "Tool register of the exports: wear|geometry")
      ->check(CLI::IsMember({"wear", "geometry"}))
      ->capture_default_str();
  addSeed(sub, a->seed);
  addOut(sub, a->out);

  auto v = std::make_shared<ValidateArgs>();
  auto* val = sub->add_subcommand(
      "validate", "The setup paper's statistical validation: N simulated sets x M trials, Fig. 18, w1, w2");
  existingFile(val->add_option("--model", v->model, "Setup model (relation graph, JSON)")->required());
  val->add_option("--sets", v->sets, "Simulated measurement sets N")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  val->add_option("--trials", v->trials, "Trials M of every method on every set")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  val->add_option("--methods", v->methods, "Metaheuristics, comma separated: cripso,pso,ga,coa")
      ->capture_default_str();
  val->add_option("--budget", v->budget, "Evaluations per trial")
      ->check(CLI::Range(1L, 100000000L))
      ->capture_default_str();
  val->add_option("--w1", v->w1, "Weight of the setup-data errors, mm (Eq. 12)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  val->add_option("--w2", v->w2, "Weight of the random errors, mm (Eq. 13)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  existingFile(val->add_option("--data", v->data, "Measured report(s): also estimate the setup share in them")
                   ->take_all());
  val->add_option("--threads", v->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  addSeed(val, v->seed);
  addOut(val, v->out);
  val->callback([v] { selectRunner([v]() -> int { return runSetupValidate(*v); }); });

  sub->callback([a, val] {
    if (val->parsed()) return;
    if (a->model.empty()) throw CLI::RequiredError("--model");
    if (a->data.empty()) throw CLI::RequiredError("--data");
    selectRunner([a]() -> int { return runSetup(*a); });
  });
}

void registerSimulateSetupCommand(CLI::App& simulate) {
  auto a = std::make_shared<SimulateSetupArgs>();
  auto* sub = simulate.add_subcommand(
      "setup",
      "A CMM report series of a setup model: setup-data and random errors (Stryczek 2016, Eq. 12–13)");
  existingFile(sub->add_option("--model", a->model, "Setup model (relation graph, JSON)")->required());
  sub->add_option("--parts", a->parts, "Parts in the series")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  sub->add_option("--w1", a->w1, "Weight of the setup-data errors, mm (Eq. 12)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  sub->add_option("--w2", a->w2, "Weight of the random errors, mm (Eq. 13)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  addSeed(sub, a->seed);
  addOut(sub, a->out);
  sub->callback([a] { selectRunner([a]() -> int { return runSimulateSetup(*a); }); });
}

}  // namespace metrofit::cli
