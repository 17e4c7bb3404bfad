// Issue 31 item 3: why the GNNMCI(1,N) PSO curve is flat on the demo (Eq. 2.9 167.3 -> 167.2 in 101
// iterations), with evidence. The demo's thermal study (resources/demo/demo.metrofit, studies.thermal):
// thermal_demo.csv, disp_z_um on T1-T4, train fraction 0.5, seed 1, default options (pso-ls).
//
// Hypothesis (confirmed here): in the default training mode (PsoLeastSquares, gnnmci.h) the swarm
// searches ONE dimension, log10 w11, with 90 particles; the layer-C weights are solved by least squares
// for every particle. 90 uniform samples of a one-dimensional box already land next to the optimum
// at iteration 0, and the inner least squares does the rest, so the curve is flat by construction.
// Evidence (figures printed by the tests; seed 1 unless said):
//  * a fine grid (4001 points) over the same box, log10 w11 in [-2.98, 0.60], with the inner least
//    squares per grid point written here (the library's layer-C inputs, Eigen's QR), has its minimum
//    167.237 at the box's upper wall, w11 = 1 / minLagSteps (time constant 0.25 step); the swarm ends
//    there exactly; iteration 0's best is 167.253, +0.0096 % (seeds 2-5: +0.011, +0.33, +2.7, +0.046 %);
//  * the optimum sits on a plateau: beyond the wall Eq. 2.9 falls only to 165.73 (-0.9 %, w11 >= 10),
//    i.e. the demo's displacement wants no lag beyond the sensors' own; the particle that starts
//    nearest the wall is next to the optimum and the only progress left is moving it onto the wall;
//  * Eq. 2.9 is not flat over the box (the grid's largest value is 7.8 x the minimum): not a flat objective;
//  * the library's fitness equals an independent forward pass written here from the paper's
//    equations (Eq. 2.3-2.6, Fig. 2 layers A-D, IAGO Eq. A.3, Eq. 2.9) to 1e-9;
//  * the literal mode (Pso: every particle carries all weights, the paper's Step 2) with the paper's
//    settings (90 particles, c1 1.5, c2 2, inertia 0.9 -> 0.4) on the same data goes 36830 -> 185.1
//    (a factor of 199), so the PSO update works when the swarm has the weights to search; it ends
//    11 % above the separable optimum.
// Not a bug, so nothing in the training changed. Seen on the way (not asserted, for the next look):
// the static regression (`linear`) reaches 74.2 on the same rows, far below GNNMCI's 165.7 limit.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/thermal/gnnmci.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

ThermalSeries demoSeries() {
  const auto file = test::sourceDir() / "resources" / "demo" / "data" / "thermal_demo.csv";
  return selectThermalSeries(readThermalLog(file.string()), "disp_z_um", {"T1", "T2", "T3", "T4"});
}

/// The fitting rows as the grey segment fitThermalModel trains on (thermal_model.cpp's greySeries):
/// the changes since the first row on the time unit of the mean step.
GreySeries demoFitSegment(const ThermalSeries& all) {
  const ThermalSeries s = all.head(fitRowCount(all.rows(), kDefaultTrainFraction));
  GreySeries g;
  g.time = greyTime(s.timeMin, (s.timeMin.back() - s.timeMin.front()) / static_cast<double>(s.rows() - 1));
  g.target = change(s.target);
  for (const auto& in : s.inputs) g.inputs.push_back(change(in));
  return g;
}

/// For one w11: the layer-C weights w22..w2,N+1 minimising Eq. 2.9 (the restored output is linear in
/// them; the target is a change, so x_1^(1)(1) = 0 and there is no initial-condition term).
GnnmciWeights innerLeastSquares(double w11, const GreySeries& s) {
  const std::size_t n = s.time.size(), m = s.inputs.size();
  const GnnmciLayerInputs in = gnnmciLayerInputs(w11, inputsAgo(s), s.time);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m + 1));
  Eigen::VectorXd y(static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j <= m; ++j) {
    const std::vector<double> col = iago(j < m ? in.inputs[j] : in.unit, s.time.weight);
    for (std::size_t k = 0; k < n; ++k)
      a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = col[k];
  }
  for (std::size_t k = 0; k < n; ++k) y(static_cast<Eigen::Index>(k)) = s.target[k];
  const Eigen::VectorXd sol = a.colPivHouseholderQr().solve(y);
  GnnmciWeights w;
  w.w11 = w11;
  for (Eigen::Index j = 0; j < sol.size(); ++j) w.w2.push_back(sol(j));
  return w;
}

/// Eq. 2.9 through a forward pass written from the paper alone, for equal steps (sample k = 0..n-1 is
/// the paper's k + 1): 1-AGO of the inputs (Eq. A.2); per layer-C node the convolution of Eq. 2.3,
/// I_j(k) = sum_{tau=1}^{k} e^{-w11 (k - tau + 1/2)} (X_j(tau) + X_j(tau-1)) / 2 (and of 1 for the u
/// node); layers A-D of Fig. 2 with w21 = -x_1^(1)(1), w3j = 1 + e^{-w11 k}, theta of Eq. 2.6 read with
/// x_1^(1)(1); IAGO (Eq. A.3); the sum of squares of Eq. 2.9. O(n^2), no recursion, no library call.
double paperFitness(const GnnmciWeights& w, const GreySeries& s) {
  const std::size_t n = s.target.size(), m = s.inputs.size();
  std::vector<std::vector<double>> x1(m, std::vector<double>(n));
  for (std::size_t j = 0; j < m; ++j) {
    double acc = 0.0;
    for (std::size_t k = 0; k < n; ++k) x1[j][k] = acc += s.inputs[j][k];
  }
  const double x11 = s.target[0];  // x_1^(1)(1) = x_1^(0)(1)
  std::vector<double> d(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double kk = static_cast<double>(k);
    std::vector<double> node(m + 1, 0.0);  // I_j(k), then I_0(k)
    for (std::size_t tau = 1; tau <= k; ++tau) {
      const double kernel = std::exp(-w.w11 * (kk - static_cast<double>(tau) + 0.5));
      for (std::size_t j = 0; j < m; ++j) node[j] += kernel * 0.5 * (x1[j][tau] + x1[j][tau - 1]);
      node[m] += kernel;
    }
    const double a = w.w11 * kk;                  // layer A
    const double b = 1.0 / (1.0 + std::exp(-a));  // layer B
    const double w3 = 1.0 + std::exp(-w.w11 * kk);
    double sum = w3 * (b * -x11);                                              // c_1 = b w21
    for (std::size_t j = 0; j <= m; ++j) sum += w3 * (node[j] * b * w.w2[j]);  // c_j = I_j b w2j
    const double theta = -x11 * (1.0 + std::exp(-w.w11 * kk));                 // Eq. 2.6
    d[k] = sum - theta;                                                        // layer D
  }
  double f = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double y = k == 0 ? d[0] : d[k] - d[k - 1];  // IAGO
    f += (y - s.target[k]) * (y - s.target[k]);
  }
  return f;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(GnnmciPsoFlat, TheOneDimensionalSwarmStartsAtTheOptimumOnTheDemo) {
  const ThermalSeries all = demoSeries();
  const GreySeries g = demoFitSegment(all);
  ASSERT_TRUE(g.time.uniform);  // the paper's equal steps, which paperFitness assumes
  ASSERT_EQ(g.target.front(), 0.0);

  // The demo's own path (the GUI's comparison and `thermal fit`: fitAndEvaluate, default options,
  // seed 1) and the swarm trained here on the segment built above are the same run.
  ThermalFitOptions fo;
  fo.setSeed(1);
  const ThermalEvaluation ev = fitAndEvaluate(all, kDefaultTrainFraction, fo);
  auto t0 = std::chrono::steady_clock::now();
  GnnmciOptions o;  // the paper's swarm: 90 particles, c1 1.5, c2 2, inertia 0.9 -> 0.4, 100 iterations
  ASSERT_EQ(o.training, GnnmciOptions::Training::PsoLeastSquares);
  o.seed = 1;
  const GnnmciTraining t = trainGnnmci({g}, o);
  const double swarmSeconds = secondsSince(t0);
  EXPECT_EQ(t.firstFitness, ev.training.firstFitness);
  EXPECT_DOUBLE_EQ(t.fitness, ev.training.fitness);
  EXPECT_TRUE(test::near(t.firstFitness, 167.3, 0.0, 0.05)) << t.firstFitness;  // the numbers
  EXPECT_TRUE(test::near(t.fitness, 167.2, 0.0, 0.05)) << t.fitness;
  ASSERT_EQ(t.lowerX.size(), 1u);  // one dimension: log10 w11
  ASSERT_EQ(t.run.trace.size(), 101u);

  // The grid over the swarm's box in log10 w11.
  t0 = std::chrono::steady_clock::now();
  const double lo = t.lowerX[0], hi = t.upperX[0];
  constexpr int kGrid = 4000;
  double gridMin = std::numeric_limits<double>::infinity(), gridMax = 0.0, argMin = lo;
  for (int i = 0; i <= kGrid; ++i) {
    const double p = lo + (hi - lo) * i / kGrid;
    const double f = gnnmciFitness(innerLeastSquares(std::pow(10.0, p), g), {g});
    if (f < gridMin) {
      gridMin = f;
      argMin = p;
    }
    gridMax = std::max(gridMax, f);
  }
  const double gridSeconds = secondsSince(t0);

  // The library's Eq. 2.9 against the paper's equations written out above, at the grid minimum and at
  // both ends of the box.
  for (double p : {argMin, lo, hi}) {
    const GnnmciWeights w = innerLeastSquares(std::pow(10.0, p), g);
    EXPECT_TRUE(test::near(gnnmciFitness(w, {g}), paperFitness(w, g), 1e-9, 1e-9)) << "log10 w11 " << p;
  }
  EXPECT_TRUE(test::near(t.fitness, paperFitness(t.weights, g), 1e-9, 1e-9));

  const double iter0 = t.run.trace.front().best;
  const double iter0Pct = 100.0 * (iter0 - gridMin) / gridMin;
  const double finalPct = 100.0 * (t.fitness - gridMin) / gridMin;
  std::printf(
      "[ figures  ] GNNMCI pso-ls on the demo (thermal_demo.csv, disp_z_um ~ T1-T4, %zu fit rows, seed 1): "
      "box log10 w11 [%.4f, %.4f] (%.2f decades, 90 particles: mean spacing %.4f); iteration 0 best %.6g, "
      "final %.6g (log10 w11 %.4f), grid minimum %.6g at %.4f (%d points), grid maximum "
      "%.6g (%.1f x the minimum); iteration 0 +%.3f %%, final %+.5f %% of the grid minimum; swarm %.2f s, "
      "grid %.2f s\n",
      g.time.size(), lo, hi, hi - lo, (hi - lo) / 90.0, iter0, t.fitness, std::log10(t.weights.w11), gridMin,
      argMin, kGrid + 1, gridMax, gridMax / gridMin, iter0Pct, finalPct, swarmSeconds, gridSeconds);

  // Eq. 2.9 is not flat over the box (7.8 x from the far end to the optimum): the flat curve is not a
  // flat objective but a swarm that starts next to the optimum.
  EXPECT_GT(gridMax, 2.0 * gridMin);
  // The swarm ends at the grid minimum (to the grid's resolution) ...
  EXPECT_LE(std::abs(finalPct), 0.01);
  // ... and iteration 0 is already next to it (measured +0.0096 %): the curve is flat by construction.
  EXPECT_LT(iter0Pct, 0.05);

  // Where the optimum is: at the box's upper wall, w11 = 1 / minLagSteps (time constant 0.25 step), on
  // a plateau: beyond the wall Eq. 2.9 falls by less than 1 % more (measured 165.73 for w11 >= 10,
  // -0.9 %): the demo's displacement wants no lag beyond the sensors' own. So the particle that starts
  // nearest the wall is already next to the optimum and the only progress is moving it onto the wall.
  EXPECT_NEAR(argMin, hi, 1e-9);
  double beyond = 0.0;
  for (double p : {1.0, 2.0}) {
    beyond = gnnmciFitness(innerLeastSquares(std::pow(10.0, p), g), {g});
    EXPECT_LT(beyond, gridMin) << p;
    EXPECT_GT(beyond, 0.98 * gridMin) << p;
  }
  ThermalFitOptions linear;
  linear.model = ThermalModelKind::Linear;
  const double staticFit = fitAndEvaluate(all, kDefaultTrainFraction, linear).training.fitness;
  std::printf(
      "[ figures  ] beyond the box: Eq. 2.9 %.6g at w11 = 100 (%+.2f %%); the static regression on the same "
      "rows: %.6g\n",
      beyond, 100.0 * (beyond - gridMin) / gridMin, staticFit);

  // Other seeds: the same picture. Measured iteration 0: +0.0096 % (seed 1), +0.011, +0.33, +2.7, +0.046 %
  // (seeds 2-5): which particle lands nearest the wall is luck; asserted with a margin.
  double worst = iter0Pct;
  for (std::uint64_t seed = 2; seed <= 5; ++seed) {
    o.seed = seed;
    const GnnmciTraining ts = trainGnnmci({g}, o);
    const double pct = 100.0 * (ts.firstFitness - gridMin) / gridMin;
    worst = std::max(worst, pct);
    std::printf("[ figures  ] seed %d: iteration 0 %.6g (+%.4f %%), final %.6g\n", static_cast<int>(seed),
                ts.firstFitness, pct, ts.fitness);
    EXPECT_LE(std::abs(100.0 * (ts.fitness - gridMin) / gridMin), 0.01) << "seed " << seed;
    EXPECT_LT(pct, 5.0) << "seed " << seed;
  }
  std::printf(
      "[ figures  ] GNNMCI pso-ls on the demo, seeds 1-5: iteration 0 at most +%.3f %% of the optimum\n",
      worst);
}

TEST(GnnmciPsoFlat, TheLiteralSwarmOverAllWeightsMovesOnTheSameData) {
  // The paper's Step 2 literally: every particle carries w11 and the layer-C weights (6 dimensions on
  // the demo's 4 inputs), the paper's settings. The random swarm starts far off and the PSO update
  // brings it down a long way: the update works, the flat pso-ls curve is the start, not the search.
  const GreySeries g = demoFitSegment(demoSeries());
  GnnmciOptions o;
  o.training = GnnmciOptions::Training::Pso;
  o.seed = 1;
  const auto t0 = std::chrono::steady_clock::now();
  const GnnmciTraining t = trainGnnmci({g}, o);
  const double seconds = secondsSince(t0);
  ASSERT_EQ(t.lowerX.size(), 6u);
  GnnmciOptions ls;
  ls.seed = 1;
  const double optimum = trainGnnmci({g}, ls).fitness;
  std::printf(
      "[ figures  ] GNNMCI pso (all weights, paper's settings) on the demo, seed 1: Eq. 2.9 %.6g -> %.6g "
      "(factor %.1f; %.2f x the pso-ls optimum %.6g), %.2f s\n",
      t.firstFitness, t.fitness, t.firstFitness / t.fitness, t.fitness / optimum, optimum, seconds);
  EXPECT_TRUE(test::near(t.fitness, paperFitness(t.weights, g), 1e-9, 1e-9));
  EXPECT_LT(t.fitness, t.firstFitness / 50.0);   // measured 36830 -> 185.1, a factor of 199
  EXPECT_GE(t.fitness, optimum * (1.0 - 1e-9));  // the separable optimum is the lower bound
}

}  // namespace
}  // namespace metrofit::thermal
