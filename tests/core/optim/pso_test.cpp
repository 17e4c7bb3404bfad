// PSO in its two documented variants: Stryczek 2016 (asynchronous, cos-decaying c1 = c2, w = 0.75,
// 100 particles) and Abdulshahed 2016 (synchronous, w 0.9 -> 0.4, c1 = 1.5, c2 = 2, 90 particles).
#include "core/optim/pso.h"

#include <gtest/gtest.h>

#include "optim_a_checks.h"

namespace metrofit::optim {
namespace {

using test::allBelow;
using test::bestOverSeeds;

Pso::Options stryczek(long budget) {
  Pso::Options o = Pso::Options::stryczek2016();
  o.common.maxEvaluations = budget;
  return o;
}

Pso::Options abdulshahed(long budget) {
  Pso::Options o = Pso::Options::abdulshahed2016();
  o.common.maxEvaluations = budget;
  return o;
}

TEST(Pso, PresetsAreThePapers) {
  const Pso::Options a = Pso::Options::stryczek2016();
  EXPECT_EQ(a.swarmSize, 100);
  EXPECT_EQ(a.update, Pso::Update::Asynchronous);
  EXPECT_EQ(a.acceleration, Pso::Acceleration::Cosine);
  EXPECT_EQ(a.c1, 1.0);
  EXPECT_EQ(a.c2, 1.0);
  EXPECT_EQ(a.inertiaStart, 0.75);
  EXPECT_EQ(a.inertiaEnd, 0.75);
  const Pso::Options defaults;
  EXPECT_EQ(defaults.swarmSize, a.swarmSize);
  EXPECT_EQ(defaults.update, a.update);

  const Pso::Options b = Pso::Options::abdulshahed2016();
  EXPECT_EQ(b.swarmSize, 90);
  EXPECT_EQ(b.update, Pso::Update::Synchronous);
  EXPECT_EQ(b.acceleration, Pso::Acceleration::Constant);
  EXPECT_EQ(b.c1, 1.5);
  EXPECT_EQ(b.c2, 2.0);
  EXPECT_EQ(b.inertiaStart, 0.9);
  EXPECT_EQ(b.inertiaEnd, 0.4);
  EXPECT_TRUE(a.isValid(nullptr));
  EXPECT_TRUE(b.isValid(nullptr));
  EXPECT_EQ(Pso().name(), "pso");
}

TEST(Pso, RejectsBadOptionsWithAClearMessage) {
  Pso::Options o;
  o.swarmSize = 1;
  test::expectRejected<Pso>(o, "swarmSize must be at least 2 (got 1)");
  o = {};
  o.inertiaStart = -0.1;
  test::expectRejected<Pso>(o, "inertiaStart must be in [0, 1.2]");
  o = {};
  o.inertiaEnd = 2.0;
  test::expectRejected<Pso>(o, "inertiaEnd must be in [0, 1.2]");
  o = {};
  o.c1 = -1.0;
  test::expectRejected<Pso>(o, "c1 must be finite and >= 0");
  o = {};
  o.c2 = std::numeric_limits<double>::infinity();
  test::expectRejected<Pso>(o, "c2 must be finite and >= 0");
  o = {};
  o.maxVelocity = 0.0;
  test::expectRejected<Pso>(o, "maxVelocity must be in (0, 1]");
  o = {};
  o.common.maxEvaluations = -5;
  test::expectRejected<Pso>(o, "the evaluation budget must be positive");
}

TEST(Pso, SameSeedSameRunBitForBitOtherSeedOtherRun) {
  for (const auto& o : {stryczek(3000), abdulshahed(3000)}) {
    test::checkSeedDeterminism<Pso>(o, test::sphere10());
    test::checkSeedDeterminism<Pso>(o, test::ShiftedSphere(10, -0.1, 0.1, 0.001));
  }
}

TEST(Pso, TheTwoVariantsDiffer) {
  Pso::Options sync = stryczek(3000);
  sync.update = Pso::Update::Synchronous;
  const Result a = Pso(stryczek(3000)).optimise(test::sphere10());
  const Result b = Pso(sync).optimise(test::sphere10());
  EXPECT_NE(a.bestX, b.bestX);
}

TEST(Pso, EvaluatesOnlyFeasibleGridPoints) {
  const test::ShiftedSphere grid(6, -0.1, 0.1, 0.001, {0.3, -0.25, 0.0504, -0.0996, 0.1, 0.02});
  test::checkEvaluatesOnlyFeasiblePoints<Pso>(stryczek(4000), grid);
  test::checkEvaluatesOnlyFeasiblePoints<Pso>(abdulshahed(4000), grid);
  test::checkEvaluatesOnlyFeasiblePoints<Pso>(abdulshahed(4000), test::sphere10());
}

TEST(Pso, NeverExceedsTheBudget) {
  test::checkBudgetNeverExceeded<Pso>(stryczek(1), test::ShiftedSphere(10, -0.1, 0.1, 0.001));
  test::checkBudgetNeverExceeded<Pso>(abdulshahed(1), test::ShiftedSphere(10, -0.1, 0.1, 0.001));
}

TEST(Pso, ObserverOncePerIterationAndCanStop) {
  test::checkObserver<Pso>(stryczek(1050), test::sphere10());
  test::checkObserver<Pso>(abdulshahed(1000), test::sphere10());
}

TEST(Pso, TargetObjectiveEndsTheRunAsConverged) {
  test::checkTargetObjective<Pso>(stryczek(20000), test::sphere10(), 1e-3);
  test::checkTargetObjective<Pso>(abdulshahed(20000), test::sphere10(), 1e-3);
}

TEST(Pso, ParallelRunsOnASharedProblemMatchSequentialRuns) {
  test::checkThreadSafety<Pso>(stryczek(3000), test::rosenbrock10());
  test::checkThreadSafety<Pso>(abdulshahed(3000), test::rosenbrock10());
}

// Convergence over seeds 1..10; the tolerances hold with margin over seeds 1..100 (Rosenbrock
// 1..200), whose median and worst the comments give.
TEST(Pso, ConvergesOnSphere10D) {
  // 20,000 evaluations. Stryczek 2016 variant: median 7e-20, worst 1.4e-18; Abdulshahed 2016: median 3.5e-12,
  // worst 2.3e-11.
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(stryczek(20000), test::sphere10()), 1e-12));
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(abdulshahed(20000), test::sphere10()), 1e-8));
}

TEST(Pso, ConvergesOnRosenbrock10D) {
  // 30,000 evaluations. Stryczek 2016 variant: median 0.7, worst 7.0; Abdulshahed 2016: median 3.9,
  // worst 7.9.
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(stryczek(30000), test::rosenbrock10()), 15.0));
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(abdulshahed(30000), test::rosenbrock10()), 15.0));
}

TEST(Pso, FindsTheExactGridOptimumIn10D) {
  // 100 of 100 seeds for both variants at 20,000 evaluations.
  test::checkFindsGridOptimum<Pso>(stryczek(20000), 10);
  test::checkFindsGridOptimum<Pso>(abdulshahed(20000), 10);
}

}  // namespace
}  // namespace metrofit::optim

// ---- Pso::Options::ring(): the lbest ring swarm (beyond the papers) ----------------------------
namespace metrofit::optim {
namespace {

using test::allBelow;
using test::bestOverSeeds;

Pso::Options ringOptions(long budget) {
  Pso::Options o = Pso::Options::ring();
  o.common.maxEvaluations = budget;
  return o;
}

TEST(PsoRing, PresetIsTheDocumentedOne) {
  const Pso::Options o = Pso::Options::ring();
  EXPECT_EQ(o.swarmSize, 60);
  EXPECT_EQ(o.neighbours, 2);
  EXPECT_DOUBLE_EQ(o.inertiaStart, 0.7298);
  EXPECT_DOUBLE_EQ(o.inertiaEnd, 0.7298);
  EXPECT_DOUBLE_EQ(o.c1, 1.49618);
  EXPECT_DOUBLE_EQ(o.c2, 1.49618);
  EXPECT_EQ(o.update, Pso::Update::Asynchronous);
  EXPECT_EQ(o.acceleration, Pso::Acceleration::Cosine);
  EXPECT_EQ(Pso::Options{}.neighbours, 0) << "the papers' presets follow the swarm's gbest";
}

TEST(PsoRing, RejectsANeighbourhoodLargerThanTheSwarm) {
  Pso::Options o = ringOptions(1000);
  o.swarmSize = 4;
  o.neighbours = 2;  // 2 * 2 + 1 = 5 > 4
  std::string why;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_NE(why.find("neighbours must be in [0, (swarmSize - 1) / 2]"), std::string::npos) << why;
  o.neighbours = -1;
  EXPECT_FALSE(o.isValid(&why));
  o.neighbours = 1;
  EXPECT_TRUE(o.isValid(&why)) << why;
  o.neighbours = 2;
  EXPECT_THROW((void)Pso(o).optimise(test::sphere10()), OptionsError);
}

TEST(PsoRing, SeedDeterminismFeasibilityBudgetObserverThreads) {
  for (Pso::Update update : {Pso::Update::Asynchronous, Pso::Update::Synchronous}) {
    Pso::Options o = ringOptions(3000);
    o.update = update;
    test::checkSeedDeterminism<Pso>(o, test::sphere10());
    test::checkEvaluatesOnlyFeasiblePoints<Pso>(
        o, test::ShiftedSphere(6, -0.1, 0.1, 0.001, {0.3, -0.25, 0.0504, -0.0996, 0.1, 0.02}));
    test::checkBudgetNeverExceeded<Pso>(o, test::ShiftedSphere(10, -0.1, 0.1, 0.001));
    test::checkThreadSafety<Pso>(o, test::rosenbrock10());
  }
  test::checkObserver<Pso>(ringOptions(1050), test::sphere10());
}

TEST(PsoRing, DiffersFromTheGbestSwarmAndConverges) {
  Pso::Options gbest = ringOptions(3000);
  gbest.neighbours = 0;
  EXPECT_NE(Pso(ringOptions(3000)).optimise(test::sphere10()).bestX,
            Pso(gbest).optimise(test::sphere10()).bestX);
  // 20,000 evaluations on the 10-D sphere: below 1e-6 for every seed 1..10 (the ring spreads
  // information slowly, so it converges later than the gbest swarm; typical 1e-10).
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(ringOptions(20000), test::sphere10()), 1e-6));
  Pso::Options sync = ringOptions(20000);
  sync.update = Pso::Update::Synchronous;
  EXPECT_TRUE(allBelow(bestOverSeeds<Pso>(sync, test::sphere10()), 1e-6));
}

}  // namespace
}  // namespace metrofit::optim
