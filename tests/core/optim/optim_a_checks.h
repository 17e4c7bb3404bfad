#pragma once
// Checks shared by the CRIPSO, PSO, GA and COA tests (optim_tests_a): test problems, a problem
// that records every point it is asked to evaluate, and generic checks of the Algorithm contract
// (determinism, feasibility, budget, observer, threads). Each check takes the algorithm type and
// its Options, so every test file states its own settings and tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/common/error.h"
#include "core/common/run.h"
#include "core/optim/algorithm.h"
#include "core/optim/problem.h"

namespace metrofit::optim::test {

/// Wraps a problem and records every x it is asked to evaluate (thread-safe).
class RecordingProblem final : public Problem {
 public:
  explicit RecordingProblem(const Problem& inner) : inner_(inner) {}
  std::string name() const override { return inner_.name(); }
  std::size_t dimension() const override { return inner_.dimension(); }
  double lower(std::size_t i) const override { return inner_.lower(i); }
  double upper(std::size_t i) const override { return inner_.upper(i); }
  double gridStep() const override { return inner_.gridStep(); }
  std::vector<std::string> componentNames() const override { return inner_.componentNames(); }
  double evaluate(std::span<const double> x, std::span<double> components) const override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      seen_.emplace_back(x.begin(), x.end());
    }
    return inner_.evaluate(x, components);
  }
  std::vector<std::vector<double>> seen() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return seen_;
  }

 private:
  const Problem& inner_;
  mutable std::mutex mutex_;
  mutable std::vector<std::vector<double>> seen_;
};

/// sum (x_i - c_i)^2 on [lower, upper]^n, optionally on a grid. With the default centre the grid
/// optimum is unique: c_i = lower + (37 + 13 i + 0.3) step, so the best grid point has index
/// k_i = 37 + 13 i (n <= 12 keeps it inside [-0.1, 0.1] with step 0.001).
class ShiftedSphere final : public Problem {
 public:
  ShiftedSphere(std::size_t n, double lower, double upper, double step, std::vector<double> centre = {})
      : n_(n), lower_(lower), upper_(upper), step_(step), centre_(std::move(centre)) {
    if (centre_.empty()) {
      for (std::size_t i = 0; i < n_; ++i) centre_.push_back(lower_ + (gridIndex(i) + 0.3) * step_);
    }
  }
  static double gridIndex(std::size_t i) { return 37.0 + 13.0 * static_cast<double>(i); }

  std::string name() const override { return "shifted sphere"; }
  std::size_t dimension() const override { return n_; }
  double lower(std::size_t) const override { return lower_; }
  double upper(std::size_t) const override { return upper_; }
  double gridStep() const override { return step_; }
  double evaluate(std::span<const double> x, std::span<double>) const override {
    double s = 0.0;
    for (std::size_t i = 0; i < n_; ++i) s += (x[i] - centre_[i]) * (x[i] - centre_[i]);
    return s;
  }

 private:
  std::size_t n_;
  double lower_, upper_, step_;
  std::vector<double> centre_;
};

inline FunctionProblem sphere10() {
  return FunctionProblem("sphere", std::vector<double>(10, -5.0), std::vector<double>(10, 5.0), sphere);
}
inline FunctionProblem rosenbrock10() {
  return FunctionProblem("rosenbrock", std::vector<double>(10, -5.0), std::vector<double>(10, 5.0),
                         rosenbrock);
}

/// True when the grid point x is the unique grid optimum of the default ShiftedSphere.
inline ::testing::AssertionResult isGridOptimum(const std::vector<double>& x, double lower, double step) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double k = std::round((x[i] - lower) / step);
    if (k != ShiftedSphere::gridIndex(i)) {
      return ::testing::AssertionFailure() << "x[" << i << "] = " << x[i] << " is grid index " << k
                                           << ", expected " << ShiftedSphere::gridIndex(i);
    }
  }
  return ::testing::AssertionSuccess();
}

/// Bit-for-bit equality of two runs: result and every trace entry.
inline void expectIdenticalRuns(const Result& a, const Result& b) {
  EXPECT_EQ(a.bestX, b.bestX);
  EXPECT_EQ(a.bestObjective, b.bestObjective);
  EXPECT_EQ(a.run.evaluations, b.run.evaluations);
  EXPECT_EQ(a.run.termination, b.run.termination);
  ASSERT_EQ(a.run.trace.size(), b.run.trace.size());
  for (std::size_t k = 0; k < a.run.trace.size(); ++k) {
    EXPECT_EQ(a.run.trace[k].iteration, b.run.trace[k].iteration);
    EXPECT_EQ(a.run.trace[k].evaluations, b.run.trace[k].evaluations);
    EXPECT_EQ(a.run.trace[k].best, b.run.trace[k].best);
    EXPECT_EQ(a.run.trace[k].bestX, b.run.trace[k].bestX);
  }
}

/// The options are rejected both by isValid (with `message` in `why`) and by optimise, which
/// throws OptionsError naming the method's options and carrying the same message.
template <class Alg>
void expectRejected(const typename Alg::Options& options, const std::string& message) {
  std::string why;
  EXPECT_FALSE(options.isValid(&why));
  EXPECT_NE(why.find(message), std::string::npos) << "why = '" << why << "'";
  const FunctionProblem problem = sphere10();
  const Alg alg(options);
  try {
    (void)alg.optimise(problem);
    ADD_FAILURE() << "no OptionsError for '" << message << "'";
  } catch (const OptionsError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(alg.name() + " options"), std::string::npos) << what;
    EXPECT_NE(what.find(message), std::string::npos) << what;
  }
}

/// Same seed: identical trace and result, bit for bit; another seed: another run.
template <class Alg>
void checkSeedDeterminism(typename Alg::Options options, const Problem& problem) {
  options.common.keepTrace = true;
  options.common.traceBestX = true;
  options.common.seed = 11;
  const Result a = Alg(options).optimise(problem);
  const Result b = Alg(options).optimise(problem);
  expectIdenticalRuns(a, b);
  options.common.seed = 12;
  const Result c = Alg(options).optimise(problem);
  bool differs = c.bestX != a.bestX || c.run.trace.size() != a.run.trace.size();
  for (std::size_t k = 0; !differs && k < a.run.trace.size(); ++k)
    differs = a.run.trace[k].best != c.run.trace[k].best;
  EXPECT_TRUE(differs) << "seeds 11 and 12 gave the same run";
}

/// Every evaluated x is inside the bounds and on the grid; the problem saw exactly the evaluations
/// the result reports, and the best x is one of them.
template <class Alg>
void checkEvaluatesOnlyFeasiblePoints(typename Alg::Options options, const Problem& inner) {
  RecordingProblem problem(inner);
  const Result r = Alg(options).optimise(problem);
  const auto seen = problem.seen();
  ASSERT_EQ(static_cast<long>(seen.size()), r.run.evaluations);
  EXPECT_EQ(r.run.evaluations, options.common.maxEvaluations);
  long infeasible = 0;
  for (const auto& x : seen) infeasible += problem.isFeasible(x) ? 0 : 1;
  EXPECT_EQ(infeasible, 0) << "of " << seen.size() << " evaluated points";
  EXPECT_TRUE(problem.isFeasible(r.bestX));
  EXPECT_NE(std::find(seen.begin(), seen.end(), r.bestX), seen.end());
}

/// The budget is never exceeded, whatever its size relative to the population.
template <class Alg>
void checkBudgetNeverExceeded(typename Alg::Options options, const Problem& inner) {
  for (long budget : {1L, 2L, 7L, 49L, 50L, 51L, 99L, 101L, 1234L}) {
    SCOPED_TRACE("budget " + std::to_string(budget));
    options.common.maxEvaluations = budget;
    RecordingProblem problem(inner);
    const Result r = Alg(options).optimise(problem);
    EXPECT_EQ(static_cast<long>(problem.seen().size()), budget);
    EXPECT_EQ(r.run.evaluations, budget);
    EXPECT_EQ(r.run.termination, Termination::BudgetExhausted);
    ASSERT_FALSE(r.run.trace.empty());
    EXPECT_EQ(r.run.trace.back().evaluations, budget);
    EXPECT_TRUE(problem.isFeasible(r.bestX));
  }
}

/// The observer sees one summary per iteration (0, 1, 2, ...) with increasing evaluations and a
/// non-increasing best, the same as the trace; a Stop ends the run early as Cancelled.
template <class Alg>
void checkObserver(typename Alg::Options options, const Problem& problem) {
  options.common.keepTrace = true;
  std::vector<IterationSummary> seen;
  FunctionObserver all([&](const IterationSummary& s) {
    seen.push_back(s);
    return ObserverDecision::Continue;
  });
  const Result r = Alg(options).optimise(problem, &all);
  ASSERT_GE(seen.size(), 3u);
  ASSERT_EQ(seen.size(), r.run.trace.size());
  EXPECT_EQ(static_cast<long>(seen.size()), r.run.iterations);
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].iteration, static_cast<long>(k));
    EXPECT_EQ(seen[k].evaluations, r.run.trace[k].evaluations);
    EXPECT_EQ(seen[k].best, r.run.trace[k].best);
    if (k > 0) {
      EXPECT_GT(seen[k].evaluations, seen[k - 1].evaluations) << "iteration " << k;
      EXPECT_LE(seen[k].best, seen[k - 1].best) << "iteration " << k;
    }
  }
  EXPECT_EQ(seen.back().evaluations, options.common.maxEvaluations);
  EXPECT_EQ(r.run.termination, Termination::BudgetExhausted);

  long calls = 0;
  FunctionObserver stopper([&](const IterationSummary& s) {
    ++calls;
    return s.iteration == 2 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const Result stopped = Alg(options).optimise(problem, &stopper);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(stopped.run.termination, Termination::Cancelled);
  EXPECT_EQ(stopped.run.iterations, 3);
  EXPECT_EQ(stopped.run.evaluations, seen[2].evaluations);
  EXPECT_LT(stopped.run.evaluations, options.common.maxEvaluations);
  EXPECT_EQ(stopped.bestObjective, seen[2].best);  // same seed: the same first three iterations

  CancelToken token;
  token.cancel();
  const Result cancelled = Alg(options).optimise(problem, &token);
  EXPECT_EQ(cancelled.run.termination, Termination::Cancelled);
  EXPECT_EQ(cancelled.run.iterations, 1);
}

/// A target objective ends the run as Converged once the best reaches it.
template <class Alg>
void checkTargetObjective(typename Alg::Options options, const Problem& problem, double target) {
  options.common.targetObjective = target;
  const Result r = Alg(options).optimise(problem);
  EXPECT_EQ(r.run.termination, Termination::Converged) << r.run.message;
  EXPECT_LE(r.bestObjective, target);
  EXPECT_LT(r.run.evaluations, options.common.maxEvaluations);
}

/// Four instances run in threads on one shared problem give the results of sequential runs.
template <class Alg>
void checkThreadSafety(typename Alg::Options options, const Problem& problem) {
  options.common.traceBestX = true;
  std::vector<Result> sequential, parallel(4);
  for (int t = 0; t < 4; ++t) {
    options.common.seed = 100 + static_cast<std::uint64_t>(t);
    sequential.push_back(Alg(options).optimise(problem));
  }
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    options.common.seed = 100 + static_cast<std::uint64_t>(t);
    threads.emplace_back(
        [&parallel, &problem, t, alg = Alg(options)] { parallel[t] = alg.optimise(problem); });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) {
    SCOPED_TRACE("thread " + std::to_string(t));
    expectIdenticalRuns(sequential[t], parallel[t]);
  }
}

/// Best objectives of runs with seeds 1..count (sorted), for convergence checks over seeds.
template <class Alg>
std::vector<double> bestOverSeeds(typename Alg::Options options, const Problem& problem, int count = 10) {
  options.common.keepTrace = false;
  std::vector<double> best;
  for (int s = 1; s <= count; ++s) {
    options.common.seed = static_cast<std::uint64_t>(s);
    best.push_back(Alg(options).optimise(problem).bestObjective);
  }
  std::sort(best.begin(), best.end());
  return best;
}

/// All runs below `tolerance`; the message lists median and worst.
inline ::testing::AssertionResult allBelow(const std::vector<double>& sortedBest, double tolerance) {
  const double worst = sortedBest.back(), median = sortedBest[sortedBest.size() / 2];
  if (worst < tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "worst " << worst << " (median " << median << ") is not below " << tolerance;
}

/// Runs seeds 1..count on the default grid ShiftedSphere and checks each finds the grid optimum.
template <class Alg>
void checkFindsGridOptimum(typename Alg::Options options, std::size_t dimension, int count = 10) {
  const ShiftedSphere problem(dimension, -0.1, 0.1, 0.001);
  options.common.keepTrace = false;
  for (int s = 1; s <= count; ++s) {
    SCOPED_TRACE("seed " + std::to_string(s));
    options.common.seed = static_cast<std::uint64_t>(s);
    const Result r = Alg(options).optimise(problem);
    EXPECT_TRUE(problem.isFeasible(r.bestX));
    EXPECT_TRUE(isGridOptimum(r.bestX, -0.1, 0.001));
  }
}

}  // namespace metrofit::optim::test
