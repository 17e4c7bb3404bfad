#pragma once
// Checks every metaheuristic of core/optim must pass (the "contract" of algorithm.h), shared by
// sade_test.cpp, neldermead_test.cpp and gasimplex_test.cpp (test target optim_tests_b):
// determinism by seed, feasibility of every evaluated point, the budget, the observer, and
// thread safety of parallel instances on one shared problem.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/optim/algorithm.h"
#include "core/optim/problem.h"

namespace metrofit::optim::test {

/// Runs one method on `problem` with the given seed, budget and observer (traceBestX on).
using RunFn = std::function<Result(const Problem&, std::uint64_t seed, long budget, Observer*)>;

/// Wraps a problem and records every evaluated x (thread-safe).
class RecordingProblem final : public Problem {
 public:
  explicit RecordingProblem(const Problem& inner) : inner_(inner) {}
  std::string name() const override { return "recording " + inner_.name(); }
  std::size_t dimension() const override { return inner_.dimension(); }
  double lower(std::size_t i) const override { return inner_.lower(i); }
  double upper(std::size_t i) const override { return inner_.upper(i); }
  double gridStep() const override { return inner_.gridStep(); }
  std::vector<std::string> componentNames() const override { return inner_.componentNames(); }
  double evaluate(std::span<const double> x, std::span<double> c) const override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      points_.emplace_back(x.begin(), x.end());
    }
    return inner_.evaluate(x, c);
  }
  std::vector<std::vector<double>> points() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return points_;
  }

 private:
  const Problem& inner_;
  mutable std::mutex mutex_;
  mutable std::vector<std::vector<double>> points_;
};

inline FunctionProblem box(FunctionProblem::Fn fn, double lo, double hi, std::size_t n = 10,
                           double step = 0.0) {
  return FunctionProblem("test", std::vector<double>(n, lo), std::vector<double>(n, hi), fn, step);
}

/// A shifted sphere (minimum 0 at x_i = 0.37), so that the optimum is not at the box centre.
inline double shiftedSphere(std::span<const double> x) {
  double s = 0.0;
  for (double v : x) s += (v - 0.37) * (v - 0.37);
  return s;
}

inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// True when two results have the identical trace and best point, bit for bit.
inline ::testing::AssertionResult sameRun(const Result& a, const Result& b) {
  if (a.run.trace.size() != b.run.trace.size())
    return ::testing::AssertionFailure()
           << "trace sizes " << a.run.trace.size() << " vs " << b.run.trace.size();
  for (std::size_t k = 0; k < a.run.trace.size(); ++k) {
    const IterationSummary &s = a.run.trace[k], &t = b.run.trace[k];
    if (s.iteration != t.iteration || s.evaluations != t.evaluations || !sameBits(s.best, t.best) ||
        s.bestX.size() != t.bestX.size())
      return ::testing::AssertionFailure() << "trace entry " << k << " differs";
    for (std::size_t j = 0; j < s.bestX.size(); ++j)
      if (!sameBits(s.bestX[j], t.bestX[j]))
        return ::testing::AssertionFailure() << "trace entry " << k << " best x[" << j << "] differs";
  }
  if (!sameBits(a.bestObjective, b.bestObjective) || a.bestX.size() != b.bestX.size())
    return ::testing::AssertionFailure() << "best " << a.bestObjective << " vs " << b.bestObjective;
  for (std::size_t j = 0; j < a.bestX.size(); ++j)
    if (!sameBits(a.bestX[j], b.bestX[j]))
      return ::testing::AssertionFailure() << "best x[" << j << "] differs";
  if (a.run.termination != b.run.termination || a.run.evaluations != b.run.evaluations)
    return ::testing::AssertionFailure() << "termination or evaluation count differs";
  return ::testing::AssertionSuccess();
}

inline void expectSameSeedSameTrace(const RunFn& run) {
  const FunctionProblem p = box(rastrigin, -5.12, 5.12);
  const Result a = run(p, 7, 3000, nullptr), b = run(p, 7, 3000, nullptr), c = run(p, 8, 3000, nullptr);
  ASSERT_GT(a.run.trace.size(), 2u);
  EXPECT_TRUE(sameRun(a, b));
  EXPECT_FALSE(sameRun(a, c)) << "a different seed must give a different run";
}

/// Every evaluated x is inside the (asymmetric) box and on the grid; the count matches.
inline void expectFeasibleOnGrid(const RunFn& run) {
  FunctionProblem inner("grid", {-1.3, 0.0, -2.0, 0.5, -0.25}, {2.7, 0.05, 1.0, 0.5, 0.35}, shiftedSphere,
                        0.01);
  RecordingProblem p(inner);
  const Result r = run(p, 3, 4000, nullptr);
  const auto points = p.points();
  ASSERT_EQ(static_cast<long>(points.size()), r.run.evaluations);
  ASSERT_GT(points.size(), 100u);
  for (const auto& x : points) ASSERT_TRUE(inner.isFeasible(x));
  EXPECT_TRUE(inner.isFeasible(r.bestX));
  EXPECT_EQ(r.bestX[3], 0.5);  // a variable with lower == upper stays fixed
}

/// The observer is called once per trace entry with consecutive iterations; it can stop the run.
inline void expectObserverSeesEveryIterationAndCanStop(const RunFn& run) {
  const FunctionProblem p = box(rastrigin, -5.12, 5.12);
  std::vector<IterationSummary> seen;
  FunctionObserver all([&](const IterationSummary& s) {
    seen.push_back(s);
    return ObserverDecision::Continue;
  });
  const Result r = run(p, 5, 2000, &all);
  ASSERT_EQ(seen.size(), r.run.trace.size());
  ASSERT_EQ(static_cast<long>(seen.size()), r.run.iterations);
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].iteration, static_cast<long>(k));
    EXPECT_TRUE(sameBits(seen[k].best, r.run.trace[k].best));
    if (k > 0) {
      EXPECT_GE(seen[k].evaluations, seen[k - 1].evaluations);
      EXPECT_LE(seen[k].best, seen[k - 1].best);  // best so far never gets worse
    }
  }
  EXPECT_EQ(seen.back().evaluations, r.run.evaluations);

  int calls = 0;
  FunctionObserver stopAt4([&](const IterationSummary& s) {
    ++calls;
    return s.iteration == 4 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const Result c = run(p, 5, 2000, &stopAt4);
  EXPECT_EQ(c.run.termination, Termination::Cancelled);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(c.run.trace.size(), 5u);
  EXPECT_EQ(c.run.evaluations, c.run.trace.back().evaluations);
  EXPECT_LT(c.run.evaluations, 2000);
  EXPECT_FALSE(c.bestX.empty());

  CancelToken token;
  token.cancel();
  EXPECT_EQ(run(p, 5, 2000, &token).run.termination, Termination::Cancelled);
}

/// The budget is never exceeded, whatever its size relative to the population.
inline void expectBudgetNeverExceeded(const RunFn& run, bool usesWholeBudget) {
  const FunctionProblem inner = box(rastrigin, -5.12, 5.12);
  for (long budget : {1L, 2L, 3L, 7L, 11L, 29L, 30L, 31L, 49L, 50L, 51L, 101L, 997L, 1000L, 2503L}) {
    RecordingProblem p(inner);
    const Result r = run(p, 11, budget, nullptr);
    EXPECT_LE(r.run.evaluations, budget) << "budget " << budget;
    EXPECT_EQ(static_cast<long>(p.points().size()), r.run.evaluations) << "budget " << budget;
    EXPECT_FALSE(r.bestX.empty()) << "budget " << budget;
    if (usesWholeBudget) {
      EXPECT_EQ(r.run.evaluations, budget) << "budget " << budget;
      EXPECT_EQ(r.run.termination, Termination::BudgetExhausted) << "budget " << budget;
    }
  }
}

/// Four instances in parallel threads on one shared problem give the sequential results.
inline void expectParallelEqualsSequential(const RunFn& run) {
  const FunctionProblem p = box(rosenbrock, -5.0, 10.0);
  std::vector<Result> sequential, parallel(4);
  for (std::uint64_t s = 1; s <= 4; ++s) sequential.push_back(run(p, s, 5000, nullptr));
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < 4; ++i)
    threads.emplace_back([&, i] { parallel[i] = run(p, i + 1, 5000, nullptr); });
  for (auto& t : threads) t.join();
  for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(sameRun(sequential[i], parallel[i])) << "instance " << i;
}

/// The options error names the method and says what is wrong.
template <class Algo>
void expectRejected(const typename Algo::Options& options, const std::string& expectedText) {
  std::string why;
  EXPECT_FALSE(options.isValid(&why)) << expectedText;
  EXPECT_NE(why.find(expectedText), std::string::npos) << "message: " << why;
  const FunctionProblem p = box(sphere, -1.0, 1.0, 2);
  try {
    Algo(options).optimise(p);
    ADD_FAILURE() << "no OptionsError for: " << expectedText;
  } catch (const OptionsError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(Algo().name() + " options"), std::string::npos) << what;
    EXPECT_NE(what.find(expectedText), std::string::npos) << what;
  }
}

}  // namespace metrofit::optim::test
