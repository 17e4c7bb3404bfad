// The statistical validation (core/study/setup_validation.h) and the methods by name (methods.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "../setup/setup_fixtures.h"
#include "core/common/error.h"
#include "core/setup/exact.h"
#include "core/setup/methods.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/sim/setup_sim.h"
#include "core/study/setup_validation.h"

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

// The share estimate against the truth of the simulator: the configured weights, and the variance
// share measured on the drawn errors themselves (|G s|^2 and |e - G s|^2 of every set, summed).
TEST(SetupShare, RecoversTheConfiguredWeightsAndTheDrawnVarianceShare) {
  const Model m = readModel(test::paperModelPath());
  const Eigen::MatrixXd G = gainMatrix(m);
  for (const auto& [w1, w2] :
       std::vector<std::pair<double, double>>{{0.03, 0.02}, {0.01, 0.04}, {0.045, 0.005}}) {
    SetupSimOptions sim;
    sim.w1 = w1;
    sim.w2 = w2;
    sim.seed = 17;
    std::vector<std::vector<double>> sets;
    double setupSq = 0.0, randomSq = 0.0;
    for (std::size_t j = 0; j < 400; ++j) {
      const SetupMeasurementSet set = simulateSetupSet(m, sim, j);
      const Eigen::Map<const Eigen::VectorXd> s(set.setupErrorMm.data(), G.cols());
      const Eigen::Map<const Eigen::VectorXd> e(set.deviationMm.data(), G.rows());
      setupSq += (G * s).squaredNorm();
      randomSq += (e - G * s).squaredNorm();
      sets.push_back(set.deviationMm);
    }
    const ShareEstimate est = estimateSetupShare(m, sets);
    EXPECT_EQ(est.sets, 400u);
    EXPECT_NEAR(est.weightShare, w1 / (w1 + w2), 0.03) << w1 << " " << w2;
    EXPECT_NEAR(est.w1Mm, w1, 0.1 * w1 + 0.002);
    EXPECT_NEAR(est.w2Mm, w2, 0.1 * w2 + 0.002);
    EXPECT_NEAR(est.varianceShare, setupSq / (setupSq + randomSq), 0.03);
  }
  EXPECT_THROW(estimateSetupShare(m, {std::vector<double>(3, 0.0)}), OptionsError);
}

TEST(SetupShare, PartDeviationSetsAverageRepeatedRowsAndSkipIncompleteParts) {
  const Model m = readModel(test::paperModelPath());
  const std::size_t n = m.dimensions.size();
  Measurements meas;
  meas.parts = {"1", "2"};
  for (std::size_t q = 0; q < n; ++q) {
    meas.rows.push_back({"1", 0.0, q, 0.01 * static_cast<double>(q), "r.csv", 1});
    if (q == 0) meas.rows.push_back({"1", 0.0, q, 0.02, "r.csv", 2});    // repeated: averaged
    if (q + 1 < n) meas.rows.push_back({"2", 0.0, q, 1.0, "r.csv", 3});  // part 2 misses one dimension
  }
  meas.deviationMm.assign(n, 0.0);
  const auto sets = partDeviationSets(m, meas);
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_DOUBLE_EQ(sets[0][0], 0.01);
  EXPECT_DOUBLE_EQ(sets[0][n - 1], 0.01 * static_cast<double>(n - 1));
}

TEST(SetupValidation, SummaryAndThePapersRange) {
  const Model m = readModel(test::paperModelPath());
  ValidationOptions o = smallRun();
  o.sets = 100;
  o.trials = 1;
  o.methods = {"cripso"};
  o.simulation.w1 = kPaperW1Mm;
  o.simulation.w2 = kPaperW2Mm;
  const ValidationResult r = runValidation(m, o);
  const ValidationSummary sum = summarizeValidation(m, o, r);
  ASSERT_EQ(sum.sets, 100u);
  double lo = 1e9, hi = -1e9, gap = 0.0;
  for (const ValidationSet& s : r.sets) {
    lo = std::min(lo, s.f1Before);
    hi = std::max(hi, s.f1Before);
    gap += s.exactF1 - s.trials.at(0).f1;
  }
  EXPECT_EQ(sum.f1BeforeMin, lo);
  EXPECT_EQ(sum.f1BeforeMax, hi);
  ASSERT_EQ(sum.methods.size(), 1u);
  EXPECT_EQ(sum.methods[0].trials, 100u);
  EXPECT_NEAR(sum.methods[0].meanGapF1, gap / 100.0, 1e-12);
  EXPECT_EQ(sum.exactProven, 100u);
  // The paper's practical example with its weights: the paper's range -0.011..0.063 mm is inside the
  // bands of the simulator's extremes, and the bands hold this run's own extremes too.
  EXPECT_TRUE(sum.paperRangeApplies);
  EXPECT_TRUE(sum.paperRangeConsistent);
  EXPECT_LT(sum.minBandLo, kPaperF1BeforeMinMm);
  EXPECT_GT(sum.maxBandHi, kPaperF1BeforeMaxMm);
  EXPECT_LT(sum.minBandLo, lo);
  EXPECT_GT(sum.minBandHi, lo);
  EXPECT_NEAR(sum.share.weightShare, 0.6, 0.05);

  // Tolerances 0.05 mm wider on both sides: every budget grows by 0.05 mm, so the paper's range is
  // no longer what this model gives.
  Model wide = m;
  for (Dimension& d : wide.dimensions) {
    d.lower -= 0.05;
    d.upper += 0.05;
  }
  const ValidationResult rw = runValidation(wide, o);
  const ValidationSummary sw = summarizeValidation(wide, o, rw);
  EXPECT_NEAR(sw.f1BeforeMin, lo + 0.05, 1e-9);
  EXPECT_TRUE(sw.paperRangeApplies);
  EXPECT_FALSE(sw.paperRangeConsistent);
  // Other weights: not compared.
  ValidationOptions other = o;
  other.simulation.w1 = 0.05;
  other.trials = 0;
  EXPECT_FALSE(summarizeValidation(m, other, runValidation(m, other)).paperRangeApplies);
}

TEST(SetupValidation, ForeseenF1IsTheLeastSquaresLine) {
  ValidationResult r;
  for (int i = 0; i < 5; ++i) {
    ValidationSet s;
    s.f1Before = 0.01 * i;
    s.exactF1 = 0.07 + 0.5 * s.f1Before + (i % 2 ? 0.001 : -0.001);
    r.sets.push_back(s);
  }
  // Hand-computed line through (0, .069) (.01, .076) (.02, .079) (.03, .086) (.04, .089):
  // slope = sum dx dy / sum dx^2 = 0.0005 / 0.001 = 0.5, mean y 0.0798 at x 0.02.
  EXPECT_NEAR(foreseenF1(r, 0.022), 0.0798 + 0.5 * 0.002, 1e-12);
  r.sets.resize(1);
  EXPECT_TRUE(std::isnan(foreseenF1(r, 0.022)));
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
