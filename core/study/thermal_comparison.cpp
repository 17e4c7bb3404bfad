// The three thermal models side by side (see thermal_comparison.h).
#include "core/study/thermal_comparison.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include "core/common/error.h"
#include "core/diagnose/thermal_applied.h"
#include "core/study/study_settings.h"
#include "core/thermal/thermal_data.h"

namespace metrofit {
namespace {

bool isAmbient(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("amb") != std::string::npos;
}

double rangeOf(const std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

std::vector<std::string> defaultInputs(const ThermalLog& log) {
  std::vector<std::string> inputs;
  for (const ThermalChannel& c : log.channels) {
    if (channelKind(c) == ChannelKind::Strain && !hasGaps(c)) inputs.push_back(c.name);
  }
  if (!inputs.empty()) {
    if (log.indexOf("T2") >= 0) inputs.push_back("T2");
    return inputs;
  }
  constexpr std::size_t kMaxTemperatures = 8;
  for (const ThermalChannel& c : log.channels) {
    // A channel with a gap (an MTConnect log) is not a default: the user chooses it knowingly.
    if (channelKind(c) == ChannelKind::Temperature && !isAmbient(c.name) && !hasGaps(c) &&
        inputs.size() < kMaxTemperatures && rangeOf(c.values) > 0.0) {
      inputs.push_back(c.name);
    }
  }
  return inputs;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Forwards one model's iterations to the comparison observer.
class ModelObserver final : public Observer {
 public:
  ModelObserver(const ThermalComparisonObserver& fn, int model) : fn_(fn), model_(model) {}
  ObserverDecision onIteration(const IterationSummary& s) override {
    return fn_ ? fn_(model_, s) : ObserverDecision::Continue;
  }

 private:
  const ThermalComparisonObserver& fn_;
  int model_;
};

thermal::ThermalFitOptions fitOptions(thermal::ThermalModelKind kind, std::uint64_t seed) {
  thermal::ThermalFitOptions o;
  o.model = kind;
  o.setSeed(seed);
  return o;
}

/// One line on why a model could not be fitted: the core's message without its location prefix (the
/// log and the settings are those of the whole comparison).
std::string failureReason(const std::exception& e) {
  const auto* error = dynamic_cast<const Error*>(&e);
  std::string text = error != nullptr && !error->detail().empty() ? error->detail() : std::string(e.what());
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

ThermalModelSettings defaultThermalModelSettings(const ThermalLog& log, const nlohmann::json& study,
                                                 const std::string& datasetId) {
  ThermalModelSettings s;
  const auto dataset = study.is_object() ? study.find("dataset") : study.end();
  if (study.is_object() && dataset != study.end() && dataset->is_string() &&
      dataset->get<std::string>() == datasetId) {
    // The study's own log: its settings are used as they are or refused naming the field (a bad
    // fraction, a column the log lacks), never replaced by the defaults below.
    const ThermalSettings t = ThermalSettings::fromJson(study);
    std::string have;
    for (const ThermalChannel& c : log.channels) have += (have.empty() ? "" : ", ") + c.name;
    const auto requireColumn = [&](const std::string& name, const char* key) {
      if (log.indexOf(name) < 0)
        throw ValidationError(ErrorContext{{}, 0, 0, std::string("studies.thermal.") + key},
                              "names the column '" + name + "', which '" + datasetId +
                                  "' does not have (it has: " + have + ")");
    };
    if (!t.target.empty()) requireColumn(t.target, "target");
    for (const std::string& in : t.inputs) requireColumn(in, "inputs");
    if (!t.target.empty() && !t.inputs.empty()) {
      s.target = t.target;
      s.inputs = t.inputs;
    }
    s.trainFraction = t.trainFraction;
    s.seed = t.seed;
  }
  if (s.target.empty()) {
    double best = -1.0;
    for (const ThermalChannel& c : log.channels) {
      if (channelKind(c) == ChannelKind::Displacement && rangeOf(c.values) > best) {
        best = rangeOf(c.values);
        s.target = c.name;
      }
    }
    s.inputs = defaultInputs(log);
  }
  return s;
}

std::vector<std::string> modularInputs(const ThermalLog& log) {
  return defaultInputs(log);
}

ThermalComparison compareThermalModels(const ThermalLog& log, const ThermalModelSettings& settings,
                                       const ThermalComparisonObserver& observer) {
  ThermalComparison c;
  c.settings = settings;
  c.series = thermal::selectThermalSeries(log, settings.target, settings.inputs);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.declaredHeldoutRmse.fill(nan);
  c.appliedHeldoutRmse.fill(nan);
  const diagnose::AppliedThermalEffects applied =
      diagnose::appliedThermalEffects(settings.applied, log, settings.target, settings.inputs);
  if (!applied.empty()) {
    const diagnose::ThermalLogWithEffects with =
        diagnose::withThermalEffects(log, settings.inputs, applied.effects);
    c.appliedSeries = thermal::selectThermalSeries(with.log, settings.target, with.inputs);
    c.appliedText = applied.text();
  }
  c.fitRows = thermal::fitRowCount(c.series.rows(), settings.trainFraction);
  c.heldoutRows = c.series.rows() - std::min(c.fitRows, c.series.rows());
  // A model that cannot be fitted (a numerical failure of that model: a rank-deficient least-squares
  // system, too few rows for its parameters) is recorded and the others are fitted. Bad settings
  // (OptionsError) throw at once; bad data that every model refuses (a constant target, too few
  // held-out rows) throws the first model's error after all have refused it.
  std::exception_ptr firstError;
  bool anyFitted = false;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    ModelObserver forward(observer, static_cast<int>(i));
    const auto start = std::chrono::steady_clock::now();
    const thermal::ThermalFitOptions options = fitOptions(kThermalModelOrder[i], settings.seed);
    try {
      if (c.appliedText.empty()) {
        c.models[i] = thermal::fitAndEvaluate(c.series, settings.trainFraction, options, &forward);
        c.declaredHeldoutRmse[i] = c.models[i].heldout.rmse;
        c.cancelled = c.models[i].training.run.termination == Termination::Cancelled;
      } else {
        try {
          diagnose::ThermalVariantFit v = diagnose::fitDeclaredAndWithEffects(
              c.series, c.appliedSeries, settings.trainFraction, options, &forward);
          c.declaredHeldoutRmse[i] = v.declared.heldout.rmse;
          if (!v.cancelled || v.usesEffects) c.appliedHeldoutRmse[i] = v.withEffects.heldout.rmse;
          c.usesApplied[i] = v.usesEffects;
          c.cancelled = v.cancelled;
          c.models[i] = v.usesEffects ? std::move(v.withEffects) : std::move(v.declared);
        } catch (const OptionsError&) {
          throw;
        } catch (const std::exception&) {
          // One variant cannot be fitted: the model keeps the other one (each fitted alone, the
          // declared one first); when neither can, the declared variant's error is the model's.
          std::exception_ptr declaredError;
          try {
            c.models[i] = thermal::fitAndEvaluate(c.series, settings.trainFraction, options, &forward);
            c.declaredHeldoutRmse[i] = c.models[i].heldout.rmse;
          } catch (const OptionsError&) {
            throw;
          } catch (const std::exception&) {
            declaredError = std::current_exception();
          }
          if (declaredError) {
            try {
              c.models[i] =
                  thermal::fitAndEvaluate(c.appliedSeries, settings.trainFraction, options, &forward);
            } catch (const OptionsError&) {
              throw;
            } catch (const std::exception&) {
              std::rethrow_exception(declaredError);
            }
            c.appliedHeldoutRmse[i] = c.models[i].heldout.rmse;
            c.usesApplied[i] = true;
          }
          c.cancelled = c.models[i].training.run.termination == Termination::Cancelled;
        }
      }
      anyFitted = anyFitted || !c.cancelled;
    } catch (const OptionsError&) {
      throw;
    } catch (const std::exception& e) {
      if (!firstError) firstError = std::current_exception();
      c.models[i] = thermal::ThermalEvaluation{};
      c.failed[i] = failureReason(e);
      if (c.failed[i].empty()) c.failed[i] = "the fit failed";
    }
    c.seconds[i] = secondsSince(start);
    if (c.cancelled) break;
  }
  if (!anyFitted && !c.cancelled && firstError) std::rethrow_exception(firstError);
  return c;
}

std::vector<std::vector<std::string>> moduleInputs(const std::vector<const ThermalLog*>& trainingTests,
                                                   const ThermalLog& test, const std::string& target) {
  // The largest change of a channel from its first value over a log (0 when the log lacks it).
  const auto rise = [](const ThermalLog& log, const std::string& name) {
    const int i = log.indexOf(name);
    if (i < 0) return 0.0;
    const std::vector<double>& v = log.channels[static_cast<std::size_t>(i)].values;
    double r = 0.0;
    for (double x : v) r = std::max(r, std::abs(x - v.front()));
    return r;
  };
  std::vector<std::vector<std::string>> out(trainingTests.size());
  for (const ThermalChannel& c : test.channels) {
    const ChannelKind kind = channelKind(c);
    if (c.name == target || (kind != ChannelKind::Temperature && kind != ChannelKind::Strain)) continue;
    for (std::size_t i = 0; i < trainingTests.size(); ++i) {
      const double own = rise(*trainingTests[i], c.name);
      bool leads = own > 0.0 && trainingTests[i]->indexOf(c.name) >= 0;
      for (std::size_t j = 0; j < trainingTests.size() && leads; ++j)
        if (j != i && (trainingTests[j]->indexOf(c.name) < 0 || own < 2.0 * rise(*trainingTests[j], c.name)))
          leads = false;
      if (leads) out[i].push_back(c.name);
    }
  }
  return out;
}

ModularComparison compareModularModels(const std::vector<const ThermalLog*>& trainingTests,
                                       const ThermalLog& test, const std::string& target,
                                       const std::vector<std::string>& inputs, std::uint64_t seed,
                                       const ThermalComparisonObserver& observer,
                                       const std::vector<std::string>& moduleNames) {
  ModularComparison m;
  m.target = target;
  m.inputs = inputs;
  std::vector<thermal::ThermalSeries> train;
  for (const ThermalLog* log : trainingTests)
    train.push_back(thermal::selectThermalSeries(*log, target, inputs));
  m.test = thermal::selectThermalSeries(test, target, inputs);
  // As compareThermalModels: a model that cannot be fitted on these tests is recorded, the others are
  // fitted; bad settings throw; an error that every model gives is thrown.
  std::exception_ptr firstError;
  bool anyFitted = false;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    ModelObserver forward(observer, static_cast<int>(i));
    try {
      m.models[i] = thermal::fitModular(train, m.test, fitOptions(kThermalModelOrder[i], seed), &forward);
      anyFitted = true;
    } catch (const OptionsError&) {
      throw;
    } catch (const std::exception& e) {
      if (!firstError) firstError = std::current_exception();
      m.models[i] = thermal::ModularEvaluation{};
      m.failed[i] = failureReason(e);
      if (m.failed[i].empty()) m.failed[i] = "the fit failed";
    }
    if (m.models[i].training.run.termination == Termination::Cancelled) {
      m.cancelled = true;
      break;
    }
  }
  if (m.cancelled) return m;
  if (!anyFitted && firstError) std::rethrow_exception(firstError);
  // The same case module by module.
  ModularModules& mm = m.modules;
  mm.inputs = moduleInputs(trainingTests, test, target);
  std::vector<thermal::ThermalModule> modules;
  std::vector<thermal::ThermalSeries> tests;
  for (std::size_t i = 0; i < trainingTests.size(); ++i) {
    mm.names.push_back(i < moduleNames.size() ? moduleNames[i] : trainingTests[i]->source);
    if (mm.inputs[i].empty()) {
      mm.why = "no temperature or strain channel moves at least twice as much in " + mm.names.back() +
               " as in the other tests";
      continue;
    }
    if (!mm.why.empty()) continue;
    try {
      modules.push_back(thermal::fitThermalModule(
          mm.names.back(), thermal::selectThermalSeries(*trainingTests[i], target, mm.inputs[i]),
          fitOptions(thermal::ThermalModelKind::DistributedLag, seed)));
      tests.push_back(thermal::selectThermalSeries(test, target, mm.inputs[i]));
    } catch (const InputError& e) {
      mm.why = mm.names.back() + ": " + e.what();
    }
  }
  mm.tests = mm.names;
  if (mm.why.empty()) {
    mm.evaluation = thermal::evaluateModules(modules, tests);
    mm.fitted = std::move(modules);
  }
  return m;
}

bool identifyModuleAgain(ModularModules& modules, std::size_t index, const ThermalLog& moduleTest,
                         const std::string& testName, const ThermalLog& combined, const std::string& target,
                         std::uint64_t seed, Observer* observer) {
  if (!modules.evaluation || modules.fitted.size() != modules.names.size() || index >= modules.names.size())
    throw std::invalid_argument("identifyModuleAgain: the modules are not all identified");
  const std::vector<std::string>& inputs = modules.inputs[index];
  std::vector<std::string> columns{target};
  columns.insert(columns.end(), inputs.begin(), inputs.end());
  for (const std::string& column : columns) {
    if (moduleTest.indexOf(column) < 0)
      throw ValidationError(ErrorContext{moduleTest.source, 0, 0, column},
                            "the test of module '" + modules.names[index] + "' (" + testName +
                                ") has no column '" + column + "'");
  }
  thermal::ThermalModule fresh = thermal::fitThermalModule(
      modules.names[index], thermal::selectThermalSeries(moduleTest, target, inputs),
      fitOptions(thermal::ThermalModelKind::DistributedLag, seed), observer);
  if (fresh.training.run.termination == Termination::Cancelled) return false;
  std::vector<thermal::ThermalModule> next = modules.fitted;
  next[index] = std::move(fresh);
  std::vector<thermal::ThermalSeries> tests;
  for (const std::vector<std::string>& in : modules.inputs)
    tests.push_back(thermal::selectThermalSeries(combined, target, in));
  thermal::ModulesEvaluation evaluation = thermal::evaluateModules(next, tests);
  modules.fitted = std::move(next);
  modules.evaluation = std::move(evaluation);
  if (modules.tests.size() != modules.names.size()) modules.tests = modules.names;
  modules.tests[index] = testName;
  return true;
}

std::vector<std::string> studyModuleTests(const nlohmann::json& study,
                                          const std::vector<std::string>& names) {
  std::vector<std::string> out = names;
  if (!study.is_object()) return out;
  const auto modules = study.find("modules");
  if (modules == study.end() || !modules->is_object()) return out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto entry = modules->find(names[i]);
    if (entry == modules->end() || !entry->is_object()) continue;
    const auto dataset = entry->find("dataset");
    if (dataset != entry->end() && dataset->is_string() && !dataset->get<std::string>().empty())
      out[i] = dataset->get<std::string>();
  }
  return out;
}

bool identifyModulesOnStudyTests(ModularModules& modules, const nlohmann::json& thermalStudy,
                                 const std::function<const ThermalLog*(const std::string&)>& logOf,
                                 const ThermalLog& combined, const std::string& target, std::uint64_t seed,
                                 Observer* observer) {
  if (!modules.evaluation) return true;
  const std::vector<std::string> wanted = studyModuleTests(thermalStudy, modules.names);
  for (std::size_t i = 0; i < modules.names.size(); ++i) {
    if (i < modules.tests.size() && wanted[i] == modules.tests[i]) continue;
    const ThermalLog* log = logOf ? logOf(wanted[i]) : nullptr;
    if (log == nullptr)
      throw ValidationError(
          ErrorContext{{}, 0, 0, "studies.thermal.modules." + modules.names[i] + ".dataset"},
          "names the dataset '" + wanted[i] + "', which is not a thermal log of the project");
    if (!identifyModuleAgain(modules, i, *log, wanted[i], combined, target, seed, observer)) return false;
  }
  return true;
}

std::vector<PhaseRun> phaseRuns(const std::vector<int>& phase) {
  std::vector<PhaseRun> runs;
  for (std::size_t k = 0; k < phase.size(); ++k) {
    if (runs.empty() || runs.back().phase != phase[k]) {
      runs.push_back({phase[k], k, k});
    } else {
      runs.back().last = k;
    }
  }
  return runs;
}

ThermalLog decimateThermalLog(const ThermalLog& log, std::size_t stride) {
  if (stride <= 1 || log.rows() <= 2) return log;
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < log.rows(); k += stride) rows.push_back(k);
  if (rows.back() != log.rows() - 1) rows.push_back(log.rows() - 1);
  ThermalLog out;
  out.source = log.source;
  out.timeColumn = log.timeColumn;
  for (std::size_t k : rows) out.timeMin.push_back(log.timeMin[k]);
  for (const ThermalChannel& c : log.channels) {
    ThermalChannel d{c.name, c.unit, {}};
    d.values.reserve(rows.size());
    for (std::size_t k : rows) d.values.push_back(c.values[k]);
    out.channels.push_back(std::move(d));
  }
  return out;
}

}  // namespace metrofit
