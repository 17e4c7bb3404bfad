// metrofit-cli thermal fit|predict|export|hysteresis|modular|simulate
// (docs/file-formats.md#thermal-fit-result; Abdulshahed 2016, grey neural network thermal model).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/sim/thermal_modular_sim.h"
#include "core/study/study_settings.h"
#include "core/thermal/control_export.h"
#include "core/thermal/hysteresis.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::cli {
namespace {

using thermal::ThermalModelKind;

// The defaults a project's thermal study has (core/study/study_settings.h ThermalSettings), as the report
// and the Thermal page use them; --train-fraction's own default depends on the model (defaultTrainFraction).
struct FitArgs {
  std::string data, target, inputs, model = "gnnmci", training = "pso-ls", out, saveModel;
  double trainFraction = ThermalSettings{}.trainFraction;  // used only when --train-fraction is given
  std::uint64_t seed = ThermalSettings{}.seed;
  int iterations = 0;
};

struct PredictArgs {
  std::string modelFile, data, out;
};

struct ExportArgs {
  std::string model, format, out, axis = "Z";
  double periodS = 0.0;
  double limitUm = thermal::ControlExportOptions{}.limitUm;
  std::vector<std::string> grid;  ///< INPUT=FROM:TO:STEP
};

struct HysteresisArgs {
  std::string data, target, inputs, out;
  double smoothingMin = thermal::HysteresisOptions{}.smoothingMin;
};

struct ModularArgs {
  std::vector<std::string> train;
  std::vector<std::string> modules;       ///< NAME:FILE:INPUTS
  std::vector<std::string> moduleModels;  ///< NAME:MODEL.json
  std::string test, target, inputs, model = "gnnmci", training = "pso-ls", out, saveModel, saveModules;
  std::uint64_t seed = ThermalSettings{}.seed;
};

struct SimulateArgs {
  std::string test = "z", out;
  std::uint64_t seed = ModularSimOptions{}.seed;
};

void summary(const std::string& line) {
  std::fprintf(stderr, "%s\n", line.c_str());
}

std::string num(double v, int digits = 4) {
  return std::isfinite(v) ? CsvWriter::formatNumber(v, digits) : "n/a";
}

/// The progress line of a training on a terminal: "thermal fit:  42 %" (nothing before the first
/// progress value).
std::function<std::string(const IterationSummary&)> percentLine(std::string what) {
  return [what = std::move(what)](const IterationSummary& s) {
    if (s.progress < 0.0) return std::string();
    return what + ": " + std::to_string(static_cast<int>(100.0 * s.progress)) + " %";
  };
}

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::json metricsJson(const thermal::ThermalMetrics& m) {
  return {{"rows", m.n}, {"R", m.r}, {"RMSE", m.rmse}, {"E", m.e}, {"residual_band", m.residualBand}};
}

nlohmann::json trainingJson(const thermal::ThermalTraining& t) {
  nlohmann::json j{{"termination", toString(t.run.termination)},
                   {"message", t.run.message},
                   {"iterations", t.run.iterations},
                   {"evaluations", t.run.evaluations},
                   {"fitness", t.fitness},
                   {"first_fitness", t.firstFitness}};
  return j;
}

nlohmann::json traceJson(const RunInfo& run) {
  nlohmann::json trace = nlohmann::json::array();
  for (const auto& s : run.trace) {
    trace.push_back({{"iteration", s.iteration}, {"evaluations", s.evaluations}, {"best", s.best}});
  }
  return trace;
}

thermal::ThermalFitOptions fitOptions(const std::string& model, const std::string& training,
                                      std::uint64_t seed, int iterations) {
  thermal::ThermalFitOptions o;
  o.model = thermal::thermalModelKind(model);
  o.gnnmci.training = training == "pso" ? thermal::GnnmciOptions::Training::Pso
                                        : thermal::GnnmciOptions::Training::PsoLeastSquares;
  o.setSeed(seed);
  if (iterations > 0) {
    o.gnnmci.iterations = iterations;
    o.mlp.maxEpochs = iterations;
  }
  return o;
}

std::string unitOf(const ThermalLog& log, const std::string& column) {
  const std::string u = log.channel(column).unit;
  return u.empty() ? "" : " " + u;
}

/// An MTConnect log (ThermalLog::gaps): how it was resampled and how many rows a gap in a used column left
/// out (docs/file-formats.md#mtconnect-logs). Nothing for a CSV log.
void addGapKeys(nlohmann::json& j, const ThermalLog& log, const thermal::ThermalSeries& series) {
  if (!log.gaps) return;
  j["resampling"] = log.resampling;
  j["rows_with_gaps_left_out"] = series.rowsWithGapsLeftOut;
}

std::string gapNote(const ThermalLog& log, const thermal::ThermalSeries& series) {
  if (!log.gaps || series.rowsWithGapsLeftOut == 0) return "";
  return "; " + std::to_string(series.rowsWithGapsLeftOut) + " rows with gaps left out";
}

/// A note for the summary line when least squares gave an unstable grey model.
std::string unstableNote(const thermal::ThermalModel& m) {
  if (!thermal::isGrey(m.kind) || m.grey.b1 > 0.0) return "";
  return "; unstable model: b1 = " + num(m.grey.b1) + " <= 0";
}

int runFit(const FitArgs& a, bool fractionGiven) {
  const ThermalLog log = readThermalArgs(a.data, a.target, a.inputs);
  const bool autoModel = a.model == "auto";
  thermal::ThermalFitOptions o = fitOptions(autoModel ? "linear" : a.model, a.training, a.seed, a.iterations);
  const double fraction = fractionGiven ? a.trainFraction : thermal::defaultTrainFraction(o.model);
  const thermal::ThermalSeries series = thermal::selectThermalSeries(log, a.target, splitList(a.inputs));
  const auto start = std::chrono::steady_clock::now();
  thermal::ThermalEvaluation ev;
  thermal::ThermalSelection selection;
  if (autoModel) {
    // --model auto: chosen on the fit rows only (blocked cross-validation, thermal_model.h).
    selection = thermal::chooseThermalModel(series, thermal::fitRowCount(series.rows(), fraction), o);
    o.model = selection.chosen;
  }
  {
    TerminalProgress progress(percentLine("thermal fit"));
    ev = thermal::fitAndEvaluate(series, fraction, o, progress.observer());
  }
  const double secs = seconds(start);
  const thermal::ThermalTraining& t = ev.training;
  if (t.run.termination == Termination::Cancelled) throw std::runtime_error("training was cancelled");
  nlohmann::json j;
  j["model"] = toString(o.model);
  j["target"] = a.target;
  j["inputs"] = t.model.inputs;
  j["train_fraction"] = fraction;
  j["train_rows"] = ev.fitRows;
  j["heldout_rows"] = ev.heldoutRows;
  j["fit_rmse"] = ev.fit.rmse;
  j["heldout_rmse"] = ev.heldout.rmse;
  // Table 4's indices are those of the testing data: the held-out rows.
  j["R"] = ev.heldout.r;
  j["E"] = ev.heldout.e;
  j["residual_band"] = ev.heldout.residualBand;
  j["fit"] = metricsJson(ev.fit);
  j["heldout"] = metricsJson(ev.heldout);
  j["parameters"] = thermal::thermalModelParameters(t.model);
  j["training"] = trainingJson(t);
  if (autoModel) {
    nlohmann::json cv;
    for (std::size_t i = 0; i < selection.candidates.size(); ++i) {
      cv[toString(selection.candidates[i])] =
          std::isfinite(selection.cvRmse[i]) ? nlohmann::json(selection.cvRmse[i]) : nlohmann::json();
    }
    j["selection"] = {{"requested", "auto"},
                      {"chosen", toString(selection.chosen)},
                      {"method", "blocked cross-validation on the fit rows"},
                      {"folds", selection.folds},
                      {"cv_rmse", cv}};
  }
  if (!std::isnan(t.cvRmse)) j["cv_rmse"] = t.cvRmse;
  // "heldout_verdict": the model's pass / fail on the held-out rows (diagnose's "heldout_check" is the
  // residual check of those rows, so the fit's verdict has a name of its own).
  j["heldout_verdict"] = {{"passed", !ev.heldoutFails()},
                          {"rule", "held-out E >= 0, finite, and a stable grey model (b1 > 0)"}};
  if (o.model == ThermalModelKind::Gnnmci || o.model == ThermalModelKind::Mlp) j["seed"] = a.seed;
  if (o.model == ThermalModelKind::Gnnmci) {
    j["training"]["method"] = toString(o.gnnmci.training);
    j["trace"] = traceJson(t.run);
  }
  addGapKeys(j, log, series);
  if (!a.saveModel.empty()) writeResult(a.saveModel, dumpJson(thermal::thermalModelToJson(t.model)));
  writeResult(a.out, dumpJson(j));
  const std::string unit = unitOf(log, a.target);
  std::string chosen;
  if (autoModel) {
    chosen = " (auto: blocked CV RMSE on the fit rows";
    for (std::size_t i = 0; i < selection.candidates.size(); ++i)
      chosen +=
          std::string(i ? ", " : " ") + toString(selection.candidates[i]) + " " + num(selection.cvRmse[i]);
    chosen += ")";
  }
  const std::string failed =
      ev.heldoutFails() ? "; held-out test FAILED (the model extrapolates poorly)" : "";
  summary("thermal fit: " + std::string(toString(o.model)) + chosen + " on " + a.data + ", " +
          std::to_string(ev.fitRows) + " fit / " + std::to_string(ev.heldoutRows) +
          " held-out rows: fit RMSE " + num(ev.fit.rmse) + unit + ", held-out RMSE " + num(ev.heldout.rmse) +
          unit + ", R " + num(ev.heldout.r, 3) + ", E " + num(ev.heldout.e, 3) + ", band " +
          num(ev.heldout.residualBand) + unit + " (" + num(secs, 2) + " s)" + unstableNote(t.model) + failed +
          gapNote(log, series));
  return 0;
}

int runPredict(const PredictArgs& a) {
  const thermal::ThermalModel model = thermal::thermalModelFromJson(readJsonFile(a.modelFile), a.modelFile);
  const ThermalLog log = readThermalLog(a.data, 3, csvOptions());
  const thermal::ThermalSeries series = thermal::selectThermalSeries(log, model.target, model.inputs, false);
  const thermal::Compensation c = thermal::compensationValues(model, series);
  writeResult(a.out, thermal::compensationToCsv(c));
  double peak = 0.0;
  for (double v : c.predicted) peak = std::max(peak, std::abs(v));
  const std::string unit = series.hasTarget() ? unitOf(log, model.target) : "";
  std::string line = "thermal predict: " + std::string(toString(model.kind)) + " model on " + a.data + ", " +
                     std::to_string(series.rows()) + " rows, predicted error up to " + num(peak) + unit +
                     gapNote(log, series);
  if (series.hasTarget()) {
    const auto y = thermal::change(series.target);
    const thermal::ThermalMetrics m = thermal::thermalMetrics(y, c.predicted);
    line +=
        "; against " + model.target + ": RMSE " + num(m.rmse) + unit + ", band " + num(m.residualBand) + unit;
  }
  summary(line);
  return 0;
}

/// --grid INPUT=FROM:TO:STEP (the input or table column name may itself contain '=' and ':' only before
/// the last '=').
thermal::ControlGridAxis parseGrid(const std::string& spec) {
  const auto fail = [&](const std::string& why) -> thermal::ControlGridAxis {
    throw OptionsError(ErrorContext{{}, 0, 0, "--grid"},
                       "expected INPUT=FROM:TO:STEP (e.g. t5_degC=0:10:1), " + why);
  };
  const std::size_t eq = spec.rfind('=');
  if (eq == std::string::npos || eq == 0) return fail("got '" + spec + "'");
  const std::string range = spec.substr(eq + 1);
  const std::size_t c1 = range.find(':'), c2 = range.rfind(':');
  if (c1 == std::string::npos || c2 == c1) return fail("got '" + spec + "'");
  const auto from = num::parseDouble(range.substr(0, c1)),
             to = num::parseDouble(range.substr(c1 + 1, c2 - c1 - 1)),
             step = num::parseDouble(range.substr(c2 + 1));
  if (!from || !to || !step) return fail("'" + range + "' are not three numbers");
  return {spec.substr(0, eq), *from, *to, *step};
}

int runExport(const ExportArgs& a) {
  const thermal::ThermalModel model = thermal::thermalModelFromJson(readJsonFile(a.model), a.model);
  thermal::ControlExportOptions o;
  o.source = a.model;
  o.axis = a.axis.empty() ? 'Z' : a.axis[0];
  o.samplePeriodS = a.periodS;
  o.limitUm = a.limitUm;
  for (const auto& g : a.grid) o.grid.push_back(parseGrid(g));
  const thermal::ControlFormat format = thermal::controlFormat(a.format);
  const std::string text = thermal::exportControl(model, format, o);
  writeResult(a.out, text);
  summary("thermal export: " + std::string(toString(model.kind)) + " model of " + model.target + " (" +
          a.model + ") as " + toString(format) + (a.out.empty() ? "" : " to " + a.out));
  return 0;
}

int runHysteresis(const HysteresisArgs& a) {
  const ThermalLog log = readThermalArgs(a.data, a.target, a.inputs);
  const thermal::ThermalSeries series = thermal::selectThermalSeries(log, a.target, splitList(a.inputs));
  thermal::HysteresisOptions o;
  o.smoothingMin = a.smoothingMin;
  const thermal::HysteresisAnalysis h = thermal::analyseHysteresis(series, o);
  nlohmann::json hj = thermal::hysteresisToJson(h);
  addGapKeys(hj, log, series);
  writeResult(a.out, dumpJson(hj));
  std::string line = "thermal hysteresis: " + std::to_string(h.heatingRows) + " heating / " +
                     std::to_string(h.coolingRows) + " cooling rows;";
  for (const auto& s : h.sensors)
    line += " " + s.sensor + " tau " + num(s.tauMin, 3) + " min, loop " + num(s.normalisedLoopArea, 2) + ";";
  line.pop_back();
  summary(line);
  return 0;
}

/// The figures of a prediction of the test log (thermal modular, pooled or module by module).
void addModularFigures(nlohmann::json& j, const thermal::ModularEvaluation& m) {
  j["R"] = m.test.r;
  j["RMSE"] = m.test.rmse;
  j["E"] = m.test.e;
  j["residual_band"] = m.test.residualBand;
  j["error_peak"] = m.errorPeak;
  j["error_rms"] = m.errorRms;
  j["reduction_peak"] = m.reductionPeak;
  j["reduction_rms"] = m.reductionRms;
}

[[noreturn]] void moduleFail(const std::string& option, const std::string& what) {
  throw OptionsError(ErrorContext{{}, 0, 0, option}, what);
}

/// `thermal modular --module NAME:FILE:INPUTS ... [--module-model NAME:MODEL.json ...]`: each module
/// identified on its own test (or taken from a saved model), the test log predicted as their sum.
int runModules(const ModularArgs& a) {
  if (!a.train.empty()) moduleFail("--module", "cannot be combined with --train (one pooled model)");
  const ThermalLog testLog = readThermalLog(a.test, 3, csvOptions());
  (void)testLog.channel(a.target);
  const thermal::ThermalFitOptions o = fitOptions(a.model, a.training, a.seed, 0);
  std::vector<thermal::ThermalModule> modules;
  std::vector<thermal::ThermalSeries> tests;
  std::vector<std::string> names;
  const auto checkName = [&](const std::string& option, const std::string& name) {
    if (name.empty()) moduleFail(option, "a module needs a name before the first ':'");
    for (const auto& n : names)
      if (n == name) moduleFail(option, "module '" + name + "' is given twice");
    names.push_back(name);
  };
  const auto testSeries = [&](const std::string& option, const std::string& name,
                              const std::vector<std::string>& inputs) {
    for (const auto& in : inputs) {
      if (in == a.target) moduleFail(option, "module '" + name + "': '" + in + "' is also the --target");
      if (testLog.indexOf(in) < 0)
        moduleFail(option, "module '" + name + "': the test log " + a.test + " has no column '" + in + "'");
    }
    return thermal::selectThermalSeries(testLog, a.target, inputs);
  };
  for (const std::string& spec : a.modules) {
    const std::size_t first = spec.find(':'), last = spec.rfind(':');
    if (first == std::string::npos || last == first)
      moduleFail("--module", "expected NAME:FILE:INPUTS (e.g. z:z_test.csv:T5,T6), got '" + spec + "'");
    const std::string name = spec.substr(0, first), file = spec.substr(first + 1, last - first - 1);
    checkName("--module", name);
    const std::vector<std::string> inputs = splitList(spec.substr(last + 1));
    if (inputs.empty()) moduleFail("--module", "module '" + name + "' needs at least one input column");
    const ThermalLog log = readThermalArgs(file, a.target, spec.substr(last + 1));
    {
      TerminalProgress progress(percentLine("thermal modular: module " + name));
      modules.push_back(thermal::fitThermalModule(name, thermal::selectThermalSeries(log, a.target, inputs),
                                                  o, progress.observer()));
    }
    if (modules.back().training.run.termination == Termination::Cancelled)
      throw std::runtime_error("training was cancelled");
    tests.push_back(testSeries("--module", name, inputs));
  }
  for (const std::string& spec : a.moduleModels) {
    const std::size_t colon = spec.find(':');
    if (colon == std::string::npos)
      moduleFail("--module-model", "expected NAME:MODEL.json, got '" + spec + "'");
    const std::string name = spec.substr(0, colon), file = spec.substr(colon + 1);
    checkName("--module-model", name);
    thermal::ThermalModule m;
    m.name = name;
    m.training.model = thermal::thermalModelFromJson(readJsonFile(file), file);
    if (m.training.model.target != a.target)
      moduleFail("--module-model", "module '" + name + "' (" + file + ") models '" + m.training.model.target +
                                       "', not the --target '" + a.target + "'");
    tests.push_back(testSeries("--module-model", name, m.training.model.inputs));
    modules.push_back(std::move(m));
  }
  const thermal::ModulesEvaluation m = thermal::evaluateModules(modules, tests);
  nlohmann::json j;
  j["target"] = a.target;
  j["test"] = a.test;
  addModularFigures(j, m);
  j["modules"] = nlohmann::json::array();
  const std::string unit = unitOf(testLog, a.target);
  std::string parts;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const thermal::ThermalModule& mod = modules[i];
    const double peak = m.contributionPeaks[i];
    nlohmann::json e{{"name", mod.name},
                     {"model", toString(mod.training.model.kind)},
                     {"inputs", mod.training.model.inputs},
                     {"identified_on", mod.test.empty() ? nlohmann::json(nullptr) : nlohmann::json(mod.test)},
                     {"contribution_peak", peak},
                     {"parameters", thermal::thermalModelParameters(mod.training.model)}};
    j["modules"].push_back(std::move(e));
    parts += (parts.empty() ? "" : ", ") + mod.name + " " + num(peak) + unit;
  }
  if (!a.saveModules.empty()) thermal::saveThermalModules(modules, a.saveModules);
  writeResult(a.out, dumpJson(j));
  summary("thermal modular: " + std::to_string(modules.size()) + " modules (" + parts +
          " at their peaks), on " + a.test + ": error " + num(m.errorPeak) + unit + " -> +-" +
          num(m.residualPeak) + unit + " (" + num(100.0 * m.reductionPeak, 3) + " % less), RMSE " +
          num(m.test.rmse) + unit + ", R " + num(m.test.r, 3) + ", E " + num(m.test.e, 3));
  return 0;
}

int runModular(const ModularArgs& a) {
  if (!a.modules.empty() || !a.moduleModels.empty()) return runModules(a);
  if (a.train.empty()) moduleFail("--train", "give the training tests (--train) or the modules (--module)");
  if (a.inputs.empty()) moduleFail("--inputs", "is required with --train");
  const auto inputs = splitList(a.inputs);
  std::vector<thermal::ThermalSeries> train;
  for (const auto& f : a.train) {
    train.push_back(thermal::selectThermalSeries(readThermalArgs(f, a.target, a.inputs), a.target, inputs));
  }
  const ThermalLog testLog = readThermalArgs(a.test, a.target, a.inputs);
  const thermal::ThermalSeries test = thermal::selectThermalSeries(testLog, a.target, inputs);
  const thermal::ThermalFitOptions o = fitOptions(a.model, a.training, a.seed, 0);
  thermal::ModularEvaluation m;
  {
    TerminalProgress progress(percentLine("thermal modular"));
    m = thermal::fitModular(train, test, o, progress.observer());
  }
  if (m.training.run.termination == Termination::Cancelled)
    throw std::runtime_error("training was cancelled");
  nlohmann::json j;
  j["model"] = toString(o.model);
  j["target"] = a.target;
  j["inputs"] = inputs;
  j["train"] = a.train;
  j["test"] = a.test;
  addModularFigures(j, m);
  j["parameters"] = thermal::thermalModelParameters(m.training.model);
  j["training"] = trainingJson(m.training);
  addGapKeys(j, testLog, test);
  if (!a.saveModel.empty()) writeResult(a.saveModel, dumpJson(thermal::thermalModelToJson(m.training.model)));
  writeResult(a.out, dumpJson(j));
  const std::string unit = unitOf(testLog, a.target);
  summary("thermal modular: " + std::string(toString(o.model)) + " fitted on " +
          std::to_string(a.train.size()) + " tests, on " + a.test + ": error " + num(m.errorPeak) + unit +
          " -> +-" + num(m.residualPeak) + unit + " (" + num(100.0 * m.reductionPeak, 3) + " % less), RMSE " +
          num(m.test.rmse) + unit + ", R " + num(m.test.r, 3) + ", E " + num(m.test.e, 3) +
          unstableNote(m.training.model));
  return 0;
}

int runSimulate(const SimulateArgs& a) {
  ModularSimOptions o;
  o.seed = a.seed;
  const ModularTest test = a.test == "z"   ? ModularTest::ZHeating
                           : a.test == "c" ? ModularTest::CHeating
                                           : ModularTest::Combined;
  const ThermalLog log = simulateModularTest(test, o);
  writeResult(a.out, thermalLogToCsv(log));
  summary("thermal simulate: " + a.test + " heating test, " + std::to_string(log.rows()) + " rows, seed " +
          std::to_string(a.seed));
  return 0;
}

void addColumns(CLI::App* sub, std::string& target, std::string& inputs) {
  sub->add_option("--target", target, "Column to model (e.g. disp_z_um)")->required();
  sub->add_option("--inputs", inputs, "Comma-separated input columns")->required();
}

}  // namespace

void registerThermalCommands(CLI::App& app) {
  auto* th = app.add_subcommand(
      "thermal", "Thermal error modelling (GNNMCI(1,N), GMC(1,N), MLP; Abdulshahed et al. 2016)");
  th->require_subcommand(1);

  auto f = std::make_shared<FitArgs>();
  auto* fit =
      th->add_subcommand("fit", "Fit a thermal error model on the first part of a log, test on the rest");
  existingFile(
      fit->add_option("--data", f->data, "Thermal log (CSV, or an MTConnect SHDR log or Streams document)")
          ->required());
  addColumns(fit, f->target, f->inputs);
  fit->add_option(
         "--model", f->model,
         "gnnmci|gmc|mlp (the thermal paper), linear (static regression), lag (first-order lag per sensor), "
         "dlag (distributed lag) or auto (chosen by blocked cross-validation on the fit rows)")
      ->check(CLI::IsMember({"gnnmci", "gmc", "mlp", "linear", "lag", "dlag", "auto"}))
      ->capture_default_str();
  addThermalLogOptions(fit);
  // The defaults in the help are the constants the fit uses (thermal::defaultTrainFraction), not re-typed.
  auto* fraction =
      fit->add_option("--train-fraction", f->trainFraction,
                      "Fraction of rows (from the start) used for fitting; default " +
                          num(thermal::defaultTrainFraction(ThermalModelKind::Gnnmci)) + ", " +
                          num(thermal::defaultTrainFraction(ThermalModelKind::Mlp)) + " for mlp (Table 3)")
          ->check(CLI::Range(0.05, 0.95));
  fit->add_option("--training", f->training,
                  "gnnmci: pso-ls (swarm over w11, layer-C weights by least squares) or pso (all weights)")
      ->check(CLI::IsMember({"pso", "pso-ls"}))
      ->capture_default_str();
  fit->add_option("--iterations", f->iterations, "PSO iterations (gnnmci) or maximum LM epochs (mlp)")
      ->check(CLI::Range(1, 1000000));
  fit->add_option("--save-model", f->saveModel, "Also write the fitted model (JSON) for 'thermal predict'");
  addSeed(fit, f->seed);
  addOut(fit, f->out);
  fit->callback([f, fraction] {
    const bool given = fraction->count() > 0;
    selectRunner([f, given]() -> int { return runFit(*f, given); });
  });

  auto p = std::make_shared<PredictArgs>();
  auto* pred = th->add_subcommand(
      "predict",
      "Compensation values from a fitted model on new data (CSV time, predicted error, compensation)");
  existingFile(pred->add_option("--model-file", p->modelFile, "Model written by 'thermal fit --save-model'")
                   ->required());
  existingFile(pred->add_option("--data", p->data, "Thermal log with the model's input columns")->required());
  addThermalLogOptions(pred);
  pred->add_option("--out", p->out, "Result file (CSV; written atomically). Default: stdout");
  pred->callback([p] { selectRunner([p]() -> int { return runPredict(*p); }); });

  auto e = std::make_shared<ExportArgs>();
  auto* exp = th->add_subcommand(
      "export",
      "A saved model in a form a machine control runs (ST function block, Siemens, Heidenhain, ISG, "
      "table)");
  existingFile(
      exp->add_option("--model", e->model, "Model written by 'thermal fit --save-model'")->required());
  exp->add_option("--format", e->format,
                  "st (IEC 61131-3 function block), siemens (TEMP_COMP setting data), heidenhain (TEMPCOMP "
                  "formula), isg (ISG / Beckhoff axis parameters) or csv (table on a grid)")
      ->check(CLI::IsMember({"st", "siemens", "heidenhain", "isg", "csv"}))
      ->required();
  exp->add_option("--axis", e->axis, "The compensated axis (siemens, heidenhain, isg)")
      ->check(CLI::IsMember({"X", "Y", "Z", "A", "B", "C", "U", "V", "W"}))
      ->capture_default_str();
  exp->add_option("--period-s", e->periodS,
                  "PLC filter period in seconds for the vendor forms' filter coefficients; default: the "
                  "model's log step")
      ->check(positiveNumber());
  exp->add_option("--limit-um", e->limitUm, "st: the compensation output is limited to +-this (um)")
      ->check(positiveNumber())
      ->capture_default_str();
  exp->add_option(
      "--grid", e->grid,
      "csv: INPUT=FROM:TO:STEP, the grid of one input or table column (repeat); default 0..10 in " +
          std::to_string(thermal::kDefaultGridPoints) + " points (mlp: its training range)");
  exp->add_option("--out", e->out, "File to write (written atomically). Default: stdout");
  exp->callback([e] { selectRunner([e]() -> int { return runExport(*e); }); });

  auto h = std::make_shared<HysteresisArgs>();
  auto* hys = th->add_subcommand(
      "hysteresis", "Displacement against each sensor over heating and cooling: loop areas and sensor lags");
  existingFile(hys->add_option("--data", h->data, "Thermal log (CSV)")->required());
  addColumns(hys, h->target, h->inputs);
  addThermalLogOptions(hys);
  hys->add_option("--smoothing-min", h->smoothingMin, "Window (min) of the heating / cooling phase detection")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  addOut(hys, h->out);
  hys->callback([h] { selectRunner([h]() -> int { return runHysteresis(*h); }); });

  auto m = std::make_shared<ModularArgs>();
  auto* mod = th->add_subcommand(
      "modular", "Fit one model on several tests (e.g. Z and C heating), predict another (Section 4.3)");
  existingFile(
      mod->add_option("--train", m->train,
                      "Training test log (CSV); repeat for each test (one model fitted on all of them)"));
  mod->add_option(
      "--module", m->modules,
      "NAME:FILE:INPUTS, e.g. z:z_test.csv:T5,T6: a module identified on its own test with its own "
      "inputs; repeat per module, the test log is predicted as their sum");
  mod->add_option("--module-model", m->moduleModels,
                  "NAME:MODEL.json: a module taken from a saved model (identify only the others again)");
  mod->add_option("--save-modules", m->saveModules, "Folder to write each module's model to (NAME.json)");
  existingFile(mod->add_option("--test", m->test, "Test log to predict (CSV)")->required());
  mod->add_option("--target", m->target, "Column to model (e.g. disp_z_um)")->required();
  mod->add_option("--inputs", m->inputs, "Comma-separated input columns (with --train)");
  mod->add_option("--model", m->model, "gnnmci|gmc|mlp|linear|lag|dlag (see thermal fit)")
      ->check(CLI::IsMember({"gnnmci", "gmc", "mlp", "linear", "lag", "dlag"}))
      ->capture_default_str();
  addThermalLogOptions(mod);
  mod->add_option("--training", m->training, "gnnmci: pso-ls or pso (see thermal fit)")
      ->check(CLI::IsMember({"pso", "pso-ls"}))
      ->capture_default_str();
  mod->add_option("--save-model", m->saveModel, "Also write the fitted model (JSON)");
  addSeed(mod, m->seed);
  addOut(mod, m->out);
  mod->callback([m] { selectRunner([m]() -> int { return runModular(*m); }); });

  auto s = std::make_shared<SimulateArgs>();
  auto* sim = th->add_subcommand("simulate", "A simulated ram heating test (Z axis, C axis or both)");
  sim->add_option("--test", s->test, "z|c|combined")
      ->check(CLI::IsMember({"z", "c", "combined"}))
      ->capture_default_str();
  addSeed(sim, s->seed);
  sim->add_option("--out", s->out, "Thermal log to write (CSV; written atomically). Default: stdout");
  sim->callback([s] { selectRunner([s]() -> int { return runSimulate(*s); }); });
}

}  // namespace metrofit::cli
