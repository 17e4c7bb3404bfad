#include "core/optim/gasimplex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/optim/optim_contract_b.h"
#include "testsupport.h"

namespace metrofit::optim {
namespace {

using test::box;

Result runGaSimplex(const Problem& p, std::uint64_t seed, long budget, Observer* observer) {
  GaSimplex::Options o;
  o.common.seed = seed;
  o.common.maxEvaluations = budget;
  o.common.traceBestX = true;
  return GaSimplex(o).optimise(p, observer);
}

TEST(GaSimplex, BadOptionsRejectedWithClearMessage) {
  auto with = [](auto change) {
    GaSimplex::Options o;
    change(o);
    return o;
  };
  test::expectRejected<GaSimplex>(with([](auto& o) { o.populationSize = 1; }),
                                  "GA population size must be at least 2");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.crossoverProbability = 1.2; }),
                                  "crossover probability must be in [0, 1]");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.mutationProbability = -0.1; }),
                                  "mutation probability must be in [0, 1]");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.gaFraction = 0.0; }),
                                  "GA share of the budget must be in (0, 1]");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.simplexStep = 0.0; }),
                                  "simplex initial step must be in (0, 1]");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.simplexTolerance = NAN; }),
                                  "simplex tolerance must be finite and >= 0");
  test::expectRejected<GaSimplex>(with([](auto& o) { o.common.targetObjective = NAN; }),
                                  "target objective must not be NaN");
  EXPECT_TRUE(GaSimplex::Options{}.isValid(nullptr));
}

TEST(GaSimplex, BudgetSplitGaThenSimplexFromTheGaBest) {
  // 10000 evaluations, 80 % GA: the GA stops at exactly 8000 evaluations; the simplex starts at
  // the GA's best (not evaluated again: its initial simplex costs n = 10 evaluations), first
  // vertex = GA best moved along x_0 only.
  const FunctionProblem inner = box(rastrigin, -5.12, 5.12);
  test::RecordingProblem p(inner);
  GaSimplex::Options o;
  o.common.maxEvaluations = 10000;
  o.common.traceBestX = true;
  const GaSimplex method(o);
  EXPECT_EQ(method.gaBudget(), 8000);
  const Result r = method.optimise(p);
  const auto& trace = r.run.trace;
  const auto gaEnd =
      std::find_if(trace.begin(), trace.end(), [](const auto& s) { return s.evaluations >= 8000; });
  ASSERT_NE(gaEnd, trace.end());
  EXPECT_EQ(gaEnd->evaluations, 8000);
  ASSERT_NE(gaEnd + 1, trace.end());
  EXPECT_EQ((gaEnd + 1)->evaluations, 8010);
  const std::vector<double>& gaBest = gaEnd->bestX;
  const auto pts = p.points();
  ASSERT_GT(pts.size(), 8000u);
  EXPECT_NE(pts[8000][0], gaBest[0]);
  for (std::size_t j = 1; j < 10; ++j) EXPECT_EQ(pts[8000][j], gaBest[j]);
  EXPECT_LE(r.bestObjective, gaEnd->best);
  // Generation sizes: generation 0 and every full generation use NP = 50 evaluations, except the
  // elite, which is carried over without a new evaluation (49 per later generation).
  EXPECT_EQ(trace[0].evaluations, 50);
  EXPECT_EQ(trace[1].evaluations, 99);
}

TEST(GaSimplex, SameSeedSameTraceBitForBitDifferentSeedDiffers) {
  test::expectSameSeedSameTrace(runGaSimplex);
}

TEST(GaSimplex, EveryEvaluatedPointInsideBoundsAndOnGrid) {
  test::expectFeasibleOnGrid(runGaSimplex);
}

TEST(GaSimplex, ObserverSeesEveryGenerationAndIterationAndCanStop) {
  test::expectObserverSeesEveryIterationAndCanStop(runGaSimplex);
}

TEST(GaSimplex, BudgetNeverExceeded) {
  test::expectBudgetNeverExceeded(runGaSimplex, /*usesWholeBudget=*/false);
}

TEST(GaSimplex, ParallelInstancesEqualSequentialResults) {
  test::expectParallelEqualsSequential(runGaSimplex);
}

TEST(GaSimplex, ConvergesOnSphere10D) {
  // Defaults, 20000 evaluations on [-5, 5]^10: f < 1e-10 for every one of 10 seeds.
  const FunctionProblem p = box(sphere, -5.0, 5.0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    GaSimplex::Options o;
    o.common.seed = seed;
    o.common.maxEvaluations = 20000;
    o.common.keepTrace = false;
    EXPECT_LT(GaSimplex(o).optimise(p).bestObjective, 1e-10) << "seed " << seed;
  }
}

TEST(GaSimplex, ConvergesOnRosenbrock10D) {
  // Defaults except simplexTolerance 1e-10, 100000 evaluations on [-5, 10]^10: f < 1e-12 for every
  // one of 10 seeds (typical 1e-17). On the symmetric box [-2.048, 2.048]^10 about a third of the
  // runs end in the local minimum near (-1, 1, ..., 1) (f = 3.9866): the GA's best then lies in
  // that basin and the simplex only refines it.
  const FunctionProblem p = box(rosenbrock, -5.0, 10.0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    GaSimplex::Options o;
    o.common.seed = seed;
    o.common.maxEvaluations = 100000;
    o.common.keepTrace = false;
    o.simplexTolerance = 1e-10;
    const Result r = GaSimplex(o).optimise(p);
    EXPECT_LT(r.bestObjective, 1e-12) << "seed " << seed;
  }
}

}  // namespace
}  // namespace metrofit::optim
