#include "core/optim/neldermead.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/optim/optim_contract_b.h"
#include "testsupport.h"

namespace metrofit::optim {
namespace {

using test::box;

Result runNelderMead(const Problem& p, std::uint64_t seed, long budget, Observer* observer) {
  NelderMead::Options o;  // no start point: a random start drawn from the seed
  o.common.seed = seed;
  o.common.maxEvaluations = budget;
  o.common.traceBestX = true;
  return NelderMead(o).optimise(p, observer);
}

double shiftedParabola1D(std::span<const double> x) {
  return (x[0] - 3.0) * (x[0] - 3.0);
}

TEST(NelderMead, BadOptionsRejectedWithClearMessage) {
  auto with = [](auto change) {
    NelderMead::Options o;
    change(o);
    return o;
  };
  test::expectRejected<NelderMead>(with([](auto& o) { o.initialStep = 0.0; }),
                                   "initial step must be in (0, 1]");
  test::expectRejected<NelderMead>(with([](auto& o) { o.initialStep = 2.0; }),
                                   "initial step must be in (0, 1]");
  test::expectRejected<NelderMead>(with([](auto& o) { o.tolerance = -1e-3; }),
                                   "tolerance must be finite and >= 0");
  test::expectRejected<NelderMead>(with([](auto& o) { o.tolerance = INFINITY; }), "tolerance must be finite");
  test::expectRejected<NelderMead>(with([](auto& o) {
                                     o.start = {0.0, NAN};
                                   }),
                                   "start point coordinate 1 is not finite");
  test::expectRejected<NelderMead>(with([](auto& o) { o.common.maxEvaluations = -5; }),
                                   "budget must be positive");

  // A start point of the wrong size is only detectable against the problem.
  NelderMead::Options o;
  o.start = {0.0, 0.0, 0.0};
  const FunctionProblem p = box(sphere, -1.0, 1.0, 2);
  try {
    NelderMead(o).optimise(p);
    ADD_FAILURE() << "no OptionsError";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("nelder-mead options"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the start point has 3 coordinates, the problem 'test' has 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(NelderMead, StandardCoefficientsGoldenSteps1D) {
  // f = (x - 3)^2 on [0, 10], start 1, initial step 0.1 * 10 = 1. Vertices 1 (f 4) and 2 (f 1).
  // Iteration 1: centroid 2, reflect 2 + 1 (2 - 1) = 3 (f 0 < best) -> expand 2 + 2 (3 - 2) = 4
  //   (f 1, worse than 3) -> keep 3. Iteration 2: simplex {3, 2}, centroid 3, reflect 4 (f 1, not
  //   better than the worst 1) -> inside contraction 3 - 0.5 (3 - 2) = 2.5 (f 0.25 < 1) accepted.
  EXPECT_EQ(NelderMead::kReflection, 1.0);
  EXPECT_EQ(NelderMead::kExpansion, 2.0);
  EXPECT_EQ(NelderMead::kContraction, 0.5);
  EXPECT_EQ(NelderMead::kShrink, 0.5);
  FunctionProblem inner("parabola", {0.0}, {10.0}, shiftedParabola1D);
  test::RecordingProblem p(inner);
  NelderMead::Options o;
  o.start = {1.0};
  o.common.maxEvaluations = 6;
  NelderMead(o).optimise(p);
  const auto pts = p.points();
  ASSERT_EQ(pts.size(), 6u);
  const double expected[] = {1.0, 2.0, 3.0, 4.0, 4.0, 2.5};
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_DOUBLE_EQ(pts[i][0], expected[i]) << "point " << i;
}

TEST(NelderMead, InitialSimplexStaysInsideTheBoxAndStartIsSnapped) {
  // Start outside the box is clamped onto it; the vertex that would leave the box goes the other way.
  FunctionProblem inner("grid", {0.0, -1.0}, {1.0, 1.0}, test::shiftedSphere, 0.05);
  test::RecordingProblem p(inner);
  NelderMead::Options o;
  o.start = {3.0, 0.512};
  o.initialStep = 0.25;
  o.common.maxEvaluations = 3;
  NelderMead(o).optimise(p);
  const auto pts = p.points();
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[0], (std::vector<double>{1.0, 0.5}));
  EXPECT_DOUBLE_EQ(pts[1][0], 0.75);  // 1 + 0.25 would leave the box: 1 - 0.25
  EXPECT_DOUBLE_EQ(pts[1][1], 0.5);
  EXPECT_DOUBLE_EQ(pts[2][0], 1.0);
  EXPECT_DOUBLE_EQ(pts[2][1], 1.0);  // 0.5 + 0.25 * 2
}

TEST(NelderMead, SameSeedSameTraceBitForBitDifferentSeedDiffers) {
  test::expectSameSeedSameTrace(runNelderMead);
}

TEST(NelderMead, GivenStartMakesTheRunIndependentOfTheSeed) {
  const FunctionProblem p = box(rosenbrock, -5.0, 10.0, 4);
  NelderMead::Options o;
  o.start = {-1.2, 1.0, -1.2, 1.0};
  o.common.maxEvaluations = 3000;
  o.common.seed = 1;
  const Result a = NelderMead(o).optimise(p);
  o.common.seed = 2;
  EXPECT_TRUE(test::sameRun(a, NelderMead(o).optimise(p)));
}

TEST(NelderMead, EveryEvaluatedPointInsideBoundsAndOnGrid) {
  test::expectFeasibleOnGrid(runNelderMead);
}

TEST(NelderMead, ObserverSeesEveryIterationAndCanStop) {
  test::expectObserverSeesEveryIterationAndCanStop(runNelderMead);
}

TEST(NelderMead, BudgetNeverExceeded) {
  test::expectBudgetNeverExceeded(runNelderMead, /*usesWholeBudget=*/false);
}

TEST(NelderMead, ParallelInstancesEqualSequentialResults) {
  test::expectParallelEqualsSequential(runNelderMead);
}

TEST(NelderMead, ConvergesOnSphere10D) {
  // Random starts in [-5, 5]^10, default tolerance 1e-8, budget 20000: converged, f < 1e-10, for
  // every one of 10 seeds.
  const FunctionProblem p = box(sphere, -5.0, 5.0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    NelderMead::Options o;
    o.common.seed = seed;
    o.common.maxEvaluations = 20000;
    const Result r = NelderMead(o).optimise(p);
    EXPECT_EQ(r.run.termination, Termination::Converged) << "seed " << seed << ": " << r.run.message;
    EXPECT_LT(r.bestObjective, 1e-10) << "seed " << seed;
  }
}

TEST(NelderMead, ConvergesOnRosenbrock10DFromItsBasin) {
  // A local method: starts x0_i = 1 + U(-0.5, 0.5) (drawn from the seed), tolerance 1e-10, budget
  // 50000: f < 1e-12 for every one of 10 seeds (typical 1e-18 after ~2500 evaluations). From
  // random starts in the whole box about a third of the runs end in Rosenbrock's local minimum near
  // (-1, 1, ..., 1) (f = 3.9866), as a local method must.
  const FunctionProblem p = box(rosenbrock, -5.0, 10.0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    NelderMead::Options o;
    Rng rng(seed);
    for (int i = 0; i < 10; ++i) o.start.push_back(1.0 + rng.uniform(-0.5, 0.5));
    o.tolerance = 1e-10;
    o.common.maxEvaluations = 50000;
    const Result r = NelderMead(o).optimise(p);
    EXPECT_EQ(r.run.termination, Termination::Converged) << "seed " << seed << ": " << r.run.message;
    EXPECT_LT(r.bestObjective, 1e-12) << "seed " << seed;
  }
}

}  // namespace
}  // namespace metrofit::optim
