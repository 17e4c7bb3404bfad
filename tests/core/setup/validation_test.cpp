// The statistical validation (core/setup/validation.h) and the methods by name (methods.h).
#include <gtest/gtest.h>

#include <atomic>

#include "core/common/error.h"
#include "core/setup/exact.h"
#include "core/setup/methods.h"
#include "core/setup/objective.h"
#include "core/setup/validation.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

ValidationOptions smallRun() {
  ValidationOptions o;
  o.sets = 6;
  o.trials = 2;
  o.methods = {"cripso", "ga"};
  o.budget = 600;
  o.simulation.seed = 9;
  o.seed = 3;
  return o;
}

TEST(SetupMethods, ByNameWithThePaperSettings) {
  EXPECT_EQ(setupMethodNames(), (std::vector<std::string>{"exact", "cripso", "pso", "ga", "coa"}));
  for (const auto& name : setupMetaheuristicNames())
    EXPECT_EQ(makeSetupAlgorithm(name, 100, 1)->name(), name);
  try {
    (void)makeSetupAlgorithm("exact", 100, 1);
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_STREQ(
        e.what(),
        "field '--method': 'exact' is not a metaheuristic of the setup correction (cripso, pso, ga, coa)");
  }
}

TEST(SetupValidation, DeterministicWhateverTheThreads) {
  const Model m = readModel(test::paperModelPath());
  ValidationOptions o = smallRun();
  o.threads = 1;
  const ValidationResult one = runValidation(m, o);
  o.threads = 3;
  std::atomic<int> calls{0};
  const ValidationResult three = runValidation(m, o, nullptr, [&](std::size_t done, std::size_t total) {
    EXPECT_LE(done, total);
    ++calls;
  });
  EXPECT_EQ(calls, 6);
  ASSERT_EQ(one.sets.size(), 6u);
  ASSERT_EQ(three.sets.size(), 6u);
  EXPECT_FALSE(one.cancelled);
  for (std::size_t j = 0; j < 6; ++j) {
    const ValidationSet& a = one.sets[j];
    const ValidationSet& b = three.sets[j];
    EXPECT_EQ(a.index, j);
    EXPECT_EQ(a.f1Before, b.f1Before);
    EXPECT_EQ(a.exactF1, b.exactF1);
    EXPECT_TRUE(a.exactProven);
    ASSERT_EQ(a.trials.size(), 4u);  // 2 methods x 2 trials
    for (std::size_t t = 0; t < 4; ++t) {
      EXPECT_EQ(a.trials[t].f, b.trials[t].f);  // bit for bit
      EXPECT_EQ(a.trials[t].seed, trialSeed(3, j, t / 2, static_cast<int>(t % 2)));
      EXPECT_GE(a.trials[t].gapF1, -1e-12);  // nothing beats the exact optimum
      EXPECT_NEAR(a.trials[t].gapF1, a.exactF1 - a.trials[t].f1, 1e-15);
    }
    // The set is the simulator's set j, and the exact optimum is solveExact's.
    const SetupInstance inst(m, simulateSetupSet(m, o.simulation, j).deviationMm);
    EXPECT_EQ(a.f1Before, inst.f1Before());
    EXPECT_EQ(a.exactF1, solveExact(inst).score.f1);
  }
  const auto order = one.sortedByBefore();
  for (std::size_t i = 1; i < order.size(); ++i)
    EXPECT_LE(one.sets[order[i - 1]].f1Before, one.sets[order[i]].f1Before);
  EXPECT_NE(trialSeed(3, 0, 0, 0), trialSeed(3, 0, 0, 1));
  EXPECT_NE(trialSeed(3, 0, 0, 0), trialSeed(3, 1, 0, 0));
  EXPECT_NE(trialSeed(3, 0, 0, 0), trialSeed(3, 0, 1, 0));
}

TEST(SetupValidation, CancellationReturnsTheCompleteSets) {
  const Model m = readModel(test::paperModelPath());
  ValidationOptions o = smallRun();
  o.sets = 50;
  o.threads = 2;
  CancelToken cancel;
  const ValidationResult r = runValidation(m, o, &cancel, [&](std::size_t done, std::size_t) {
    if (done == 3) cancel.cancel();
  });
  EXPECT_TRUE(r.cancelled);
  EXPECT_GE(r.sets.size(), 3u);
  EXPECT_LT(r.sets.size(), 50u);
  for (const auto& s : r.sets) EXPECT_EQ(s.trials.size(), 4u);
  ValidationOptions bad = smallRun();
  bad.methods = {"exact"};
  EXPECT_THROW(runValidation(m, bad), OptionsError);
}

}  // namespace
}  // namespace metrofit::setup
