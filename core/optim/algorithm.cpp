#include "core/optim/algorithm.h"

#include <cmath>

namespace metrofit::optim {

bool CommonOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (maxEvaluations <= 0) return no("the evaluation budget must be positive");
  if (std::isnan(targetObjective)) return no("the target objective must not be NaN");
  return true;
}

void requireValidProblem(const Problem& p) {
  const ErrorContext ctx{{}, 0, 0, p.name()};
  if (p.dimension() == 0) throw OptionsError(ctx, "the problem has no decision variables");
  if (!(p.gridStep() >= 0.0) || !std::isfinite(p.gridStep()))
    throw OptionsError(ctx, "the grid step must be >= 0");
  for (std::size_t i = 0; i < p.dimension(); ++i) {
    if (!std::isfinite(p.lower(i)) || !std::isfinite(p.upper(i))) {
      throw OptionsError(ctx, "bounds of variable " + std::to_string(i) + " are not finite");
    }
    if (p.lower(i) > p.upper(i)) {
      throw OptionsError(ctx, "lower bound above upper bound for variable " + std::to_string(i));
    }
  }
}

Tracker::Tracker(std::string method, const Problem& problem, const CommonOptions& options, Observer* observer)
    : method_(std::move(method)),
      problem_(problem),
      options_(options),
      observer_(observer),
      rng_(options.seed) {
  requireValid(options_, method_ + " options");
  requireValidProblem(problem_);
  components_.resize(problem_.componentNames().size());
  best_.method = method_;
  best_.bestComponents.assign(components_.size(), 0.0);
  step_ = problem_.gridStep();
  const std::size_t n = problem_.dimension();
  lo_.resize(n);
  hi_.resize(n);
  kMax_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    lo_[i] = problem_.lower(i);
    hi_[i] = problem_.upper(i);
    kMax_[i] = gridPoints(lo_[i], hi_[i], step_);
  }
}

void Tracker::snap(std::span<double> x) const {
  const double step = step_, invStep = step > 0.0 ? 1.0 / step : 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = snapCoordinate(x[i], lo_[i], hi_[i], step, invStep, kMax_[i]);
}

double Tracker::evaluate(std::span<double> x) {
  snap(x);
  const double f = problem_.evaluate(x, components_);
  ++evaluations_;
  // NaN objectives never become the best (a NaN compares false).
  if (f < best_.bestObjective || best_.bestX.empty()) {
    if (!std::isnan(f) || best_.bestX.empty()) {
      best_.bestObjective = std::isnan(f) ? std::numeric_limits<double>::infinity() : f;
      best_.bestX.assign(x.begin(), x.end());
      best_.bestComponents = components_;
    }
  }
  return std::isnan(f) ? std::numeric_limits<double>::infinity() : f;
}

std::vector<double> Tracker::randomPoint() {
  std::vector<double> x(dimension());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = rng_.uniform(lo_[i], hi_[i]);
  snap(x);
  return x;
}

bool Tracker::endIteration() {
  IterationSummary s;
  s.iteration = iteration_++;
  s.evaluations = evaluations_;
  s.best = best_.bestObjective;
  const auto names = problem_.componentNames();
  s.components.reserve(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) s.components.push_back({names[i], best_.bestComponents[i]});
  if (options_.traceBestX) s.bestX = best_.bestX;
  s.progress = std::min(1.0, progress());
  if (notify(observer_, best_.run, s, options_.keepTrace)) {
    stoppedByObserver_ = true;
    return true;
  }
  return exhausted() || best_.bestObjective <= options_.targetObjective;
}

Result Tracker::finish() {
  RunInfo& run = best_.run;
  run.evaluations = evaluations_;
  if (stoppedByObserver_) {
    run.termination = Termination::Cancelled;
    run.message = "stopped by observer after " + std::to_string(evaluations_) + " evaluations";
  } else if (best_.bestObjective <= options_.targetObjective) {
    run.termination = Termination::Converged;
    run.message = "target objective reached";
  } else {
    run.termination = Termination::BudgetExhausted;
    run.message = "evaluation budget of " + std::to_string(options_.maxEvaluations) + " used";
  }
  return best_;
}

}  // namespace metrofit::optim
