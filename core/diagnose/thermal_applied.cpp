#include "core/diagnose/thermal_applied.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <mutex>

#include "core/common/error.h"
#include "core/diagnose/applied_entries.h"
#include "core/io/csv.h"
#include "core/project/project.h"
#include "core/thermal/lag_regression.h"

namespace metrofit::diagnose {
namespace {

/// The observers of two runs made at once, shown to one observer as if the runs had been made one
/// after the other: the first run's iterations as they come, the second's queued until the first has
/// ended (then replayed in order, and passed on as they come). The observer is called by one thread
/// at a time; once it says Stop, both runs stop. When the first run is cancelled the second's queue
/// is dropped (the sequential run would not have started it).
class SequencedPair {
 public:
  explicit SequencedPair(Observer* observer) : observer_(observer) {}

  ObserverDecision first(const IterationSummary& s) {
    const std::lock_guard lock(mutex_);
    return stop_ ? ObserverDecision::Stop : forward(s);
  }
  ObserverDecision second(const IterationSummary& s) {
    const std::lock_guard lock(mutex_);
    if (stop_) return ObserverDecision::Stop;
    if (!firstEnded_) {
      queue_.push_back(s);
      return ObserverDecision::Continue;
    }
    return forward(s);
  }
  /// The first run has ended (`cancelled`: it was stopped, or it failed).
  void firstEnded(bool cancelled) {
    const std::lock_guard lock(mutex_);
    firstEnded_ = true;
    if (cancelled) stop_ = true;
    for (const IterationSummary& s : queue_) {
      if (stop_ || forward(s) == ObserverDecision::Stop) break;
    }
    queue_.clear();
  }
  /// The observer said Stop (or the first run was cancelled).
  bool stopped() const {
    const std::lock_guard lock(mutex_);
    return stop_;
  }

 private:
  ObserverDecision forward(const IterationSummary& s) {  // with mutex_ held
    if (!observer_ || observer_->onIteration(s) == ObserverDecision::Continue)
      return ObserverDecision::Continue;
    stop_ = true;
    return ObserverDecision::Stop;
  }

  Observer* observer_;
  mutable std::mutex mutex_;
  bool firstEnded_ = false;
  bool stop_ = false;
  std::vector<IterationSummary> queue_;
};

/// The values of a generic effect's variable on every row, as the closed loop's residual variables
/// (thermal_diagnosis.cpp): `time` in min, `row` 1-based, else the column (which must exist).
std::vector<double> genericVariable(const ThermalLog& log, const std::string& against) {
  if (against == "time") return log.timeMin;
  if (against == "row") {
    std::vector<double> r(log.rows());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = static_cast<double>(k + 1);
    return r;
  }
  return log.channel(against).values;
}

std::string listOf(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

}  // namespace

std::vector<ThermalRegressor> thermalRegressors(const ThermalLog& log, const std::vector<std::string>& inputs,
                                                const ThermalEffectSet& effects) {
  std::vector<ThermalRegressor> out;
  const std::size_t n = log.rows();
  for (const auto& in : inputs) {
    const ThermalChannel& c = log.channel(in);
    const auto it = effects.lagCol.find(in);
    const double tau = it != effects.lagCol.end() ? it->second : effects.lagAll;
    ThermalRegressor r;
    r.name = in;
    r.unit = c.unit;
    if (tau > 0.0) {
      r.channel = "lag:" + in;
      r.lagMin = tau;
      r.values = thermal::firstOrderLagMin(c.values, log.timeMin, tau);
    } else {
      r.channel = in;
      r.values = c.values;
    }
    out.push_back(std::move(r));
  }
  for (const auto& e : effects.extra) {
    const ThermalChannel& c = log.channel(e);
    ThermalRegressor r;
    r.name = r.channel = "input:" + e;
    r.unit = c.unit;
    r.values.resize(n);
    for (std::size_t k = 0; k < n; ++k) r.values[k] = c.values[k] - c.values[0];
    out.push_back(std::move(r));
  }
  if (effects.drift) {
    ThermalRegressor r;
    r.name = r.channel = "drift";
    r.unit = "min";
    r.values.resize(n);
    for (std::size_t k = 0; k < n; ++k) r.values[k] = log.timeMin[k] - log.timeMin[0];
    out.push_back(std::move(r));
  }
  for (const GenericForm& g : effects.generic) {
    const Eigen::MatrixXd basis = genericBasis(g, genericVariable(log, g.against));
    for (Eigen::Index j = 0; j < basis.cols(); ++j) {
      ThermalRegressor r;
      r.name = r.channel = "unexplained:" + g.against + "#" + std::to_string(j + 1);
      r.values.assign(basis.col(j).data(), basis.col(j).data() + basis.rows());
      out.push_back(std::move(r));
    }
  }
  return out;
}

std::string AppliedThermalEffects::text() const {
  std::string s;
  for (const auto& l : labels) s += (s.empty() ? "" : ", ") + l;
  return s;
}

AppliedThermalEffects appliedThermalEffects(const nlohmann::json& applied, const ThermalLog& log,
                                            const std::string& target, const std::vector<std::string>& inputs,
                                            const std::string& field) {
  AppliedThermalEffects out;
  std::vector<std::string> seen;
  static const std::string kKnown = "lag, lag:<column>, input:<column>, drift, unexplained:<variable>";
  const AppliedEntryMessages messages = appliedMessagesKnown(kKnown);
  forEachAppliedEntry(applied, field, messages, [&](const AppliedEntry& entry) {
    const nlohmann::json& e = entry.json;
    const std::string& name = entry.name;
    const ErrorContext where{{}, 0, 0, entry.at("name")};
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw ValidationError(where, "the effect '" + name + "' is applied twice");
    seen.push_back(name);
    const nlohmann::json params =
        e.contains("parameters") && e["parameters"].is_object() ? e["parameters"] : nlohmann::json::object();
    auto column = [&](const std::string& col) {
      if (col.empty()) throw ValidationError(where, "'" + name + "' names no column");
      if (log.indexOf(col) < 0)
        throw ValidationError(where,
                              "'" + name + "': the log " + log.source + " has no column '" + col + "'");
    };
    if (name == "lag" || name.starts_with("lag:")) {
      const auto tau = params.find("tau_min");
      if (tau == params.end() || !tau->is_number() || !(tau->get<double>() > 0.0) ||
          !std::isfinite(tau->get<double>()))
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("parameters.tau_min")},
                              "'" + name + "' needs a positive lag time constant tau_min (min)");
      const double t = tau->get<double>();
      if (name == "lag") {
        if (inputs.empty()) throw ValidationError(where, "'lag' needs at least one input of the model");
        out.effects.lagAll = t;
      } else {
        const std::string col = name.substr(4);
        column(col);
        if (std::find(inputs.begin(), inputs.end(), col) == inputs.end())
          throw ValidationError(where, "'" + name + "': '" + col +
                                           "' is not an input of the model (inputs: " + listOf(inputs) + ")");
        out.effects.lagCol[col] = t;
      }
      out.labels.push_back(name + " (" + CsvWriter::formatNumber(t, 3) + " min)");
    } else if (name.starts_with("input:")) {
      const std::string col = name.substr(6);
      column(col);
      if (col == target) throw ValidationError(where, "'" + name + "' names the target column");
      if (std::find(inputs.begin(), inputs.end(), col) == inputs.end()) out.effects.extra.push_back(col);
      out.labels.push_back(name);
    } else if (name == "drift") {
      out.effects.drift = true;
      out.labels.push_back(name);
    } else if (name.starts_with("unexplained:")) {
      GenericForm g = genericShapeOf(entry);
      if (g.against != "time" && g.against != "row") {
        column(g.against);
        if (g.against == target) throw ValidationError(where, "'" + name + "' names the target column");
      }
      if (g.components != 1)
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("shape.components")},
                              "a thermal log has one target column (components 1)");
      out.labels.push_back(name + " (" + formName(g.form) + ")");
      out.effects.generic.push_back(std::move(g));
    } else {
      throw ValidationError(where, "unknown thermal effect '" + name + "' (known: " + kKnown + ")");
    }
  });
  return out;
}

ThermalLogWithEffects withThermalEffects(const ThermalLog& log, const std::vector<std::string>& inputs,
                                         const ThermalEffectSet& effects) {
  ThermalLogWithEffects out;
  out.log = log;
  for (ThermalRegressor& r : thermalRegressors(log, inputs, effects)) {
    out.inputs.push_back(r.channel);
    if (log.indexOf(r.channel) >= 0) continue;  // a declared input without a lag: the log's own column
    out.log.channels.push_back(ThermalChannel{r.channel, r.unit, std::move(r.values)});
  }
  return out;
}

nlohmann::json projectThermalApplied(const Project& project, const std::string& datasetId) {
  const nlohmann::json none = nlohmann::json::array();
  const auto diag = project.studies.find(study::kDiagnosis);
  if (diag == project.studies.end() || !diag->is_object()) return none;
  const auto block = diag->find("thermal");
  if (block == diag->end() || !block->is_object()) return none;
  const auto applied = block->find("applied");
  if (applied == block->end() || applied->is_null()) return none;
  return block->value("dataset", nlohmann::json()) == nlohmann::json(datasetId) ? *applied : none;
}

bool keepsAppliedEffects(double declaredRmse, double withEffectsRmse) {
  if (!std::isfinite(withEffectsRmse)) return false;
  return !std::isfinite(declaredRmse) || withEffectsRmse < declaredRmse;
}

ThermalVariantFit fitDeclaredAndWithEffects(const thermal::ThermalSeries& declared,
                                            const thermal::ThermalSeries& withEffects, double trainFraction,
                                            const thermal::ThermalFitOptions& options, Observer* observer) {
  // The two fits are independent and each seeded: the with-effects fit runs on a thread of its own
  // while the declared one runs here; the results are those of the sequential run, bit for bit.
  SequencedPair observers(observer);
  auto second = std::async(std::launch::async, [&observers, &withEffects, trainFraction, options] {
    FunctionObserver o([&observers](const IterationSummary& s) { return observers.second(s); });
    return thermal::fitAndEvaluate(withEffects, trainFraction, options, &o);
  });
  ThermalVariantFit v;
  try {
    FunctionObserver o([&observers](const IterationSummary& s) { return observers.first(s); });
    v.declared = thermal::fitAndEvaluate(declared, trainFraction, options, &o);
  } catch (...) {
    observers.firstEnded(true);  // stops the other fit; the future's destructor waits for it
    throw;
  }
  const bool declaredCancelled = v.declared.training.run.termination == Termination::Cancelled;
  observers.firstEnded(declaredCancelled);
  if (declaredCancelled) {
    second.wait();       // stopped at its next iteration; its result (or error) is not reported
    v.cancelled = true;  // the sequential run would not have started the second fit
    return v;
  }
  v.withEffects = second.get();
  if (v.withEffects.training.run.termination == Termination::Cancelled || observers.stopped()) {
    v.cancelled = true;
    v.usesEffects = true;  // the cancelled run is the one reported
    return v;
  }
  v.usesEffects = keepsAppliedEffects(v.declared.heldout.rmse, v.withEffects.heldout.rmse);
  return v;
}

}  // namespace metrofit::diagnose
