// GNNMCI(1,N) (Abdulshahed 2016, grey neural network thermal model, Eq. 2.3-2.9, Fig. 2): the mapping with
// the paper's weight assignment, and PSO training.
#include "core/thermal/gnnmci.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/sim/thermal_sim.h"
#include "core/thermal/thermal_model.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

GreySeries series(std::size_t n, bool uneven) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k)
    t[k] = static_cast<double>(k) + (uneven ? 0.3 * std::sin(1.7 * static_cast<double>(k)) : 0.0);
  GreySeries s;
  s.time = greyTime(t, meanStepMin(t));
  s.inputs.assign(3, std::vector<double>(n));
  for (std::size_t k = 0; k < n; ++k) {
    s.inputs[0][k] = 4.0 * (1.0 - std::exp(-t[k] / 30.0));
    s.inputs[1][k] = std::sin(t[k] / 20.0);
    s.inputs[2][k] = 0.01 * t[k];
  }
  return s;
}

TEST(Gnnmci, MappingWithTheAssignedWeightsIsTheGmcTimeResponse) {
  // Eq. 2.5-2.6: w11 = b1, w21 = -x_1^(1)(1), w2j = b_j, w2,N+1 = u, w3j = 1 + e^{-w11 k} and
  // theta = -x_1^(1)(1)(1 + e^{-w11 k}): layer D must equal Eq. 2.4 = Eq. 2.2, for any x_1^(1)(1).
  const GmcParameters p{0.045, {0.9, -0.4, 2.0}, 0.25};
  const GnnmciWeights w = GnnmciWeights::fromGmc(p);
  EXPECT_EQ(w.w11, p.b1);
  EXPECT_EQ(w.w2, (std::vector<double>{0.9, -0.4, 2.0, 0.25}));
  EXPECT_EQ(w.toGmc().b, p.b);
  for (bool uneven : {false, true}) {
    const GreySeries s = series(200, uneven);
    const auto xAgo = inputsAgo(s);
    for (double x11 : {0.0, 3.5, -12.0}) {
      const auto gmc = gmcTimeResponse(p, x11, xAgo, s.time);
      const auto net = gnnmciForward(w, x11, xAgo, s.time);
      ASSERT_EQ(net.size(), gmc.size());
      for (std::size_t k = 0; k < gmc.size(); ++k)
        ASSERT_TRUE(test::near(net[k], gmc[k], 1e-10, 1e-12)) << "k " << k << " x11 " << x11;
      EXPECT_TRUE(test::near(net[0], x11, 1e-12));  // the initial condition
    }
  }
}

TEST(Gnnmci, LayersAreThoseOfFigure2) {
  const GmcParameters p{0.1, {0.5, 0.2, -0.3}, 1.0};
  const GnnmciWeights w = GnnmciWeights::fromGmc(p);
  const GreySeries s = series(50, false);
  const auto xAgo = inputsAgo(s);
  const GnnmciLayerInputs in = gnnmciLayerInputs(w.w11, xAgo, s.time);
  const double x11 = 2.0;
  const auto forward = gnnmciForward(w, x11, xAgo, s.time);
  for (std::size_t k : {std::size_t{0}, std::size_t{7}, std::size_t{49}}) {
    const GnnmciLayers l = gnnmciLayers(w, x11, in, s.time, k);
    const double kk = static_cast<double>(k);
    EXPECT_DOUBLE_EQ(l.a, 0.1 * kk);                                // layer A: w11 k
    EXPECT_DOUBLE_EQ(l.b, 1.0 / (1.0 + std::exp(-0.1 * kk)));       // layer B: sigmoid
    EXPECT_DOUBLE_EQ(l.w3, 1.0 + std::exp(-0.1 * kk));              // tied w3j
    EXPECT_DOUBLE_EQ(l.theta, -x11 * (1.0 + std::exp(-0.1 * kk)));  // Eq. 2.6
    ASSERT_EQ(l.c.size(), 5u);                                      // c_1, three inputs, the u node
    EXPECT_DOUBLE_EQ(l.c[0], l.b * -x11);
    EXPECT_DOUBLE_EQ(l.c[2], in.inputs[1][k] * l.b * 0.2);
    EXPECT_DOUBLE_EQ(l.c[4], in.unit[k] * l.b * 1.0);
    EXPECT_TRUE(test::near(l.d, forward[k], 0.0, 1e-13));
  }
  // The u node's input is the convolution of 1: sum of e^{-w11 (k - tau + 1/2)} over the intervals.
  double expected = 0.0;
  for (int tau = 1; tau <= 7; ++tau) expected += std::exp(-0.1 * (7 - tau + 0.5));
  EXPECT_TRUE(test::near(in.unit[7], expected, 1e-12));
}

TEST(Gnnmci, FitnessIsEquation29OnTheRestoredOutput) {
  const GmcParameters p{0.05, {0.7, 0.1, -0.2}, 0.0};
  GreySeries s = series(80, false);
  s.target = gmcPredict(p, s);  // x11 = 0 -> target[0] = 0
  const GnnmciWeights w = GnnmciWeights::fromGmc(p);
  EXPECT_LT(gnnmciFitness(w, {s}), 1e-20);
  GnnmciWeights off = w;
  off.w2[0] += 0.1;
  const auto y = gnnmciPredict(off, s);
  double f = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) f += (y[k] - s.target[k]) * (y[k] - s.target[k]);
  EXPECT_DOUBLE_EQ(gnnmciFitness(off, {s}), f);
  EXPECT_DOUBLE_EQ(gnnmciFitness(off, {s, s}), 2.0 * f);
}

/// The simulated spindle log's first half (thermal_sim.h, seed 1) as grey segments on changes.
std::vector<GreySeries> spindleFitPart() {
  const ThermalSeries s =
      selectThermalSeries(simulateThermalTest({}), "disp_z_um", {"T1", "T2", "T3", "T4"}).head(240);
  GreySeries g;
  g.time = greyTime(s.timeMin, meanStepMin(s.timeMin));
  g.target = change(s.target);
  for (const auto& in : s.inputs) g.inputs.push_back(change(in));
  return {g};
}

TEST(Gnnmci, TrainingReducesTheFitnessAndIsReproducible) {
  const auto segs = spindleFitPart();
  for (auto mode : {GnnmciOptions::Training::Pso, GnnmciOptions::Training::PsoLeastSquares}) {
    GnnmciOptions o;
    o.training = mode;
    o.seed = 7;
    const GnnmciTraining a = trainGnnmci(segs, o), b = trainGnnmci(segs, o);
    ASSERT_EQ(a.run.trace.size(), 101u) << toString(mode);  // iteration 0 (random swarm) + 100
    for (std::size_t i = 0; i < a.run.trace.size(); ++i) ASSERT_EQ(a.run.trace[i].best, b.run.trace[i].best);
    EXPECT_EQ(a.weights.w2, b.weights.w2);
    EXPECT_EQ(a.firstFitness, a.run.trace.front().best);
    EXPECT_DOUBLE_EQ(a.fitness, gnnmciFitness(a.weights, segs));  // the reported fitness is Eq. 2.9
    for (std::size_t i = 1; i < a.run.trace.size(); ++i)
      EXPECT_LE(a.run.trace[i].best, a.run.trace[i - 1].best);
    std::printf(
        "[ figures  ] GNNMCI %s on the spindle log's first 240 rows: Eq. 2.9 %.4g -> %.4g um^2 "
        "(fit RMSE %.3f um), w11 %.4g\n",
        toString(mode), a.firstFitness, a.fitness, std::sqrt(a.fitness / 240.0), a.weights.w11);
  }
  // The literal swarm (all weights in the particles) starts far off and must come down a long way.
  GnnmciOptions o;
  o.training = GnnmciOptions::Training::Pso;
  const GnnmciTraining t = trainGnnmci(segs, o);
  EXPECT_LT(t.fitness, 0.05 * t.firstFitness);
  o.seed = 8;
  EXPECT_NE(trainGnnmci(segs, o).run.trace.front().best, t.run.trace.front().best);
}

TEST(Gnnmci, RecoversAKnownModelFromNoisyData) {
  // Data from a GMC(1,N) time response (b1 = 0.08 -> time constant 12.5 samples) plus 1 % noise.
  const GmcParameters truth{0.08, {0.32, -0.12, 1.5}, 0.0};
  GreySeries s = series(240, false);
  s.target = gmcPredict(truth, s);
  Rng rng(3);
  double peak = 0.0;
  for (double v : s.target) peak = std::max(peak, std::abs(v));
  for (std::size_t k = 1; k < s.target.size(); ++k) s.target[k] += rng.normal(0.0, 0.01 * peak);
  const GnnmciTraining t = trainGnnmci({s}, GnnmciOptions{});
  EXPECT_TRUE(test::near(t.weights.w11, truth.b1, 0.0, 0.05)) << t.weights.w11;
  for (std::size_t j = 0; j < 3; ++j)
    EXPECT_TRUE(test::near(t.weights.w2[j] / t.weights.w11, truth.b[j] / truth.b1, 0.05, 0.05)) << j;
  // The fit is at the noise level: RMSE within 10 % of the 1 % noise.
  EXPECT_TRUE(test::near(std::sqrt(t.fitness / 240.0), 0.01 * peak, 0.0, 0.1));
}

TEST(Gnnmci, ObserverCancelsTheSwarm) {
  const auto segs = spindleFitPart();
  FunctionObserver stop([](const IterationSummary& s) {
    return s.iteration >= 3 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const GnnmciTraining t = trainGnnmci(segs, GnnmciOptions{}, &stop);
  EXPECT_EQ(t.run.termination, Termination::Cancelled);
  EXPECT_EQ(t.run.iterations, 4);
  EXPECT_GT(t.weights.w11, 0.0);
}

TEST(Gnnmci, OptionsValidation) {
  GnnmciOptions o;
  std::string why;
  EXPECT_TRUE(o.isValid(&why)) << why;
  EXPECT_EQ(o.particles, 90);
  EXPECT_EQ(o.c1, 1.5);
  EXPECT_EQ(o.c2, 2.0);
  EXPECT_EQ(o.inertiaStart, 0.9);
  EXPECT_EQ(o.inertiaEnd, 0.4);
  o.particles = 1;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_EQ(why, "the swarm needs at least 2 particles");
  o = {};
  o.gainBound = 0.0;
  EXPECT_FALSE(o.isValid(&why));
}

}  // namespace
}  // namespace metrofit::thermal
