// Is the poor held-out result of GMC(1,N) on the real CAIVIAC log the method or
// the implementation? An independent GMC(1,N) written here from Abdulshahed 2016 (Appendix A Eq. A.2-A.3,
// Eq. 2.1-2.2 with Tien's 1-based indices, the background value z(k) = (X(k) + X(k-1)) / 2 and the
// normal equations solved by LDLT, the time response by the literal double sum) against
// core/thermal/grey.h (weighted AGO, column-pivoting QR, O(n) recursion), on the real log; then the
// time-step handling: a first-order lag with a known time constant sampled at unequal steps must
// come back with that time constant in minutes. Also the new regression models and `--model auto`
// (blocked cross-validation on the fit rows only: scrambling the held-out target changes nothing).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "core/common/rng.h"
#include "core/thermal/gnnmci.h"
#include "core/thermal/grey.h"
#include "core/thermal/lag_regression.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

struct SeedGmc {
  double b1 = 0.0, u = 0.0;
  std::vector<double> b;
};

std::vector<double> seedAgo(const std::vector<double>& x) {  // Eq. A.2
  std::vector<double> out(x.size());
  double acc = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) out[k] = acc += x[k];
  return out;
}

/// Least squares of x1(k) + b1 z1(k) = sum_j b_j z_j(k) + u, k = 2..n, by the normal equations.
SeedGmc seedFit(const std::vector<double>& y, const std::vector<std::vector<double>>& x) {
  const std::size_t n = y.size(), m = x.size();
  const std::vector<double> y1 = seedAgo(y);
  std::vector<std::vector<double>> x1;
  for (const auto& c : x) x1.push_back(seedAgo(c));
  Eigen::MatrixXd B(static_cast<Eigen::Index>(n - 1), static_cast<Eigen::Index>(m + 2));
  Eigen::VectorXd Y(static_cast<Eigen::Index>(n - 1));
  for (std::size_t k = 1; k < n; ++k) {
    const auto r = static_cast<Eigen::Index>(k - 1);
    B(r, 0) = -0.5 * (y1[k] + y1[k - 1]);
    for (std::size_t j = 0; j < m; ++j)
      B(r, static_cast<Eigen::Index>(j + 1)) = 0.5 * (x1[j][k] + x1[j][k - 1]);
    B(r, static_cast<Eigen::Index>(m + 1)) = 1.0;
    Y(r) = y[k];
  }
  // Scale the columns so that the normal equations are well conditioned enough for LDLT.
  Eigen::VectorXd s = B.colwise().norm().cwiseInverse().transpose();
  const Eigen::MatrixXd Bs = B * s.asDiagonal();
  const Eigen::VectorXd p = s.asDiagonal() * (Bs.transpose() * Bs).ldlt().solve(Bs.transpose() * Y);
  SeedGmc g;
  g.b1 = p(0);
  for (std::size_t j = 0; j < m; ++j) g.b.push_back(p(static_cast<Eigen::Index>(j + 1)));
  g.u = p(static_cast<Eigen::Index>(m + 1));
  return g;
}

/// Eq. 2.2 literally (1-based k): x^(1)(k) = x^(1)(1) e^{-b1 (k-1)} + sum_{tau=2}^{k} e^{-b1 (k - tau
/// + 1/2)} (f(tau) + f(tau-1)) / 2, then IAGO (Eq. A.3).
std::vector<double> seedResponse(const SeedGmc& g, double x11, const std::vector<std::vector<double>>& x) {
  const std::size_t n = x.front().size();
  std::vector<std::vector<double>> x1;
  for (const auto& c : x) x1.push_back(seedAgo(c));
  auto f = [&](std::size_t tau) {  // 1-based
    double v = g.u;
    for (std::size_t j = 0; j < x.size(); ++j) v += g.b[j] * x1[j][tau - 1];
    return v;
  };
  std::vector<double> r1(n);
  for (std::size_t k = 1; k <= n; ++k) {
    double v = x11 * std::exp(-g.b1 * static_cast<double>(k - 1));
    for (std::size_t tau = 2; tau <= k; ++tau)
      v += std::exp(-g.b1 * (static_cast<double>(k) - static_cast<double>(tau) + 0.5)) * 0.5 *
           (f(tau) + f(tau - 1));
    r1[k - 1] = v;
  }
  std::vector<double> r0(n);
  for (std::size_t k = 0; k < n; ++k) r0[k] = k == 0 ? r1[0] : r1[k] - r1[k - 1];
  return r0;
}

ThermalLog caiviac() {
  return readThermalLog((test::sourceDir() / "resources/demo/data/thermal_caiviac.csv").string());
}

/// Every `stride`-th row of a series.
ThermalSeries decimate(const ThermalSeries& s, std::size_t stride) {
  ThermalSeries out = s;
  auto pick = [&](std::vector<double>& v) {
    std::vector<double> w;
    for (std::size_t k = 0; k < v.size(); k += stride) w.push_back(v[k]);
    v = w;
  };
  pick(out.timeMin);
  pick(out.target);
  for (auto& in : out.inputs) pick(in);
  return out;
}

TEST(GmcIndependent, FitAndResponseMatchTheSeedEquationsOnTheRealLog) {
  // ch1 against t5, t9 (the set-up), 1 min steps (every 4th row), first half fits.
  const ThermalSeries all = decimate(selectThermalSeries(caiviac(), "ch1_um", {"t5_degC", "t9_degC"}), 4);
  const std::size_t nf = fitRowCount(all.rows(), 0.5);
  const ThermalSeries fit = all.head(nf);
  ThermalFitOptions o;
  o.model = ThermalModelKind::Gmc;
  const ThermalTraining t = fitThermalModel({fit}, o);
  const SeedGmc ref = seedFit(change(fit.target), {change(fit.inputs[0]), change(fit.inputs[1])});
  EXPECT_TRUE(test::near(t.model.grey.b1, ref.b1, 0.0, 1e-6)) << t.model.grey.b1 << " vs " << ref.b1;
  EXPECT_TRUE(test::near(t.model.grey.b[0], ref.b[0], 0.0, 1e-6));
  EXPECT_TRUE(test::near(t.model.grey.b[1], ref.b[1], 0.0, 1e-6));
  EXPECT_TRUE(test::near(t.model.grey.u, ref.u, 0.0, 1e-6));
  EXPECT_DOUBLE_EQ(t.model.timeUnitMin, 1.0);
  // The response over the whole log (the held-out half continues the fitted one), initial
  // condition x^(1)(1) = 0 (changes since the first row).
  const std::vector<double> core = predictChange(t.model, all);
  const std::vector<double> seed = seedResponse(ref, 0.0, {change(all.inputs[0]), change(all.inputs[1])});
  ASSERT_EQ(core.size(), seed.size());
  double scale = 0.0;
  for (double v : seed) scale = std::max(scale, std::abs(v));
  for (std::size_t k = 0; k < core.size(); ++k) ASSERT_NEAR(core[k], seed[k], 1e-6 * scale) << "row " << k;
  // GNNMCI(1,N)'s grey part: the network (Fig. 2) with the weights of Eq. 2.5's assignment gives the
  // seed's time response too.
  GreySeries g;
  g.time = greyTime(all.timeMin, t.model.timeUnitMin);
  g.inputs = {change(all.inputs[0]), change(all.inputs[1])};
  GmcParameters rp;
  rp.b1 = ref.b1;
  rp.b = ref.b;
  rp.u = ref.u;
  const std::vector<double> net = gnnmciPredict(GnnmciWeights::fromGmc(rp), g);
  for (std::size_t k = 0; k < net.size(); ++k) ASSERT_NEAR(net[k], seed[k], 1e-6 * scale) << "row " << k;
  // The method, not the code: least squares picks a multi-hour lag (tau = h / b1) of the two
  // temperatures, and the held-out half is predicted worse than by a static regression.
  EXPECT_GT(t.model.timeUnitMin / t.model.grey.b1, 180.0);
  const ThermalEvaluation gmc = fitAndEvaluate(all, 0.5, o);
  ThermalFitOptions lo;
  lo.model = ThermalModelKind::Linear;
  const ThermalEvaluation lin = fitAndEvaluate(all, 0.5, lo);
  EXPECT_GT(gmc.heldout.rmse, lin.heldout.rmse);
  EXPECT_TRUE(gmc.heldoutFails());
}

/// y' = (g1 x1 + g2 x2 - y) / tau integrated finely, sampled at the given times.
ThermalLog lagLog(const std::vector<double>& tMin, double tau, double g1, double g2) {
  ThermalLog log;
  log.source = "lag.csv";
  log.timeColumn = "time_min";
  log.timeMin = tMin;
  ThermalChannel x1{"T1", "degC", {}}, x2{"T2", "degC", {}}, y{"disp_um", "um", {}};
  auto in1 = [](double t) {
    return 20.0 + 8.0 * (1.0 - std::exp(-t / 40.0)) -
           3.0 * (t > 200.0 ? 1.0 - std::exp(-(t - 200.0) / 30.0) : 0.0);
  };
  auto in2 = [](double t) { return 22.0 + 2.0 * std::sin(t / 35.0); };
  double state = g1 * in1(0.0) + g2 * in2(0.0), t = 0.0;
  const double dt = 0.001;
  for (double tk : tMin) {
    while (t < tk - 1e-12) {
      const double h = std::min(dt, tk - t);
      const double drive = g1 * in1(t + 0.5 * h) + g2 * in2(t + 0.5 * h);
      state = drive + (state - drive) * std::exp(-h / tau);
      t += h;
    }
    x1.values.push_back(in1(tk));
    x2.values.push_back(in2(tk));
    y.values.push_back(state);
  }
  log.channels = {x1, x2, y};
  return log;
}

TEST(GmcIndependent, TimeConstantInMinutesOnEqualAndUnequalSteps) {
  // Time-step handling and the weighted AGO: the same process sampled every 2 min and at random steps
  // of 0.5-4 min must give GMC(1,N) the same time constant (h / b1, minutes) and static gains
  // (b_j / b1), close to the true 25 min and 1.5, -2.0.
  std::vector<double> equal, unequal;
  for (double t = 0.0; t <= 400.0; t += 2.0) equal.push_back(t);
  Rng rng(3);
  for (double t = 0.0; t <= 400.0; t += 0.5 + 3.5 * rng.uniform()) unequal.push_back(t);
  ThermalFitOptions o;
  o.model = ThermalModelKind::Gmc;
  for (const auto* times : {&equal, &unequal}) {
    const ThermalSeries s = selectThermalSeries(lagLog(*times, 25.0, 1.5, -2.0), "disp_um", {"T1", "T2"});
    const ThermalModel m = fitThermalModel({s}, o).model;
    EXPECT_TRUE(test::near(m.timeUnitMin / m.grey.b1, 25.0, 0.0, 0.05)) << m.timeUnitMin / m.grey.b1;
    EXPECT_TRUE(test::near(m.grey.b[0] / m.grey.b1, 1.5, 0.0, 0.05));
    EXPECT_TRUE(test::near(m.grey.b[1] / m.grey.b1, -2.0, 0.0, 0.05));
    // ... and the lag model finds the same time constant on the grid (25 is between 20 and 30).
    ThermalFitOptions lo;
    lo.model = ThermalModelKind::Lag;
    const ThermalModel l = fitThermalModel({s}, lo).model;
    for (const LagTerm& term : l.regression.terms) {
      EXPECT_GE(term.tauMin, 20.0);
      EXPECT_LE(term.tauMin, 30.0);
    }
  }
}

TEST(LagRegression, FirstOrderLagIsTheExactStepResponse) {
  // A unit step at t = 0 held: s(t) = 1 - exp(-t / tau) at any sampling.
  const std::vector<double> t{0.0, 0.3, 1.0, 2.5, 7.0, 20.0};
  std::vector<double> x(t.size(), 1.0);
  x[0] = 0.0;
  const std::vector<double> s = firstOrderLagMin(x, t, 4.0);
  for (std::size_t k = 1; k < t.size(); ++k) EXPECT_NEAR(s[k], 1.0 - std::exp(-t[k] / 4.0), 1e-12);
  EXPECT_EQ(firstOrderLagMin(x, t, 0.0), x);
}

TEST(ThermalAuto, ChoiceUsesTheFitRowsOnly) {
  // Scrambling the held-out target changes the held-out error and nothing else: the same model, taus
  // and coefficients, the same CV scores.
  const ThermalSeries s =
      decimate(selectThermalSeries(caiviac(), "ch1_um", {"t5_degC", "t9_degC", "spindle_rpm"}), 4);
  const std::size_t nf = fitRowCount(s.rows(), 0.5);
  ThermalSeries scrambled = s;
  Rng rng(11);
  for (std::size_t k = nf; k < s.rows(); ++k) scrambled.target[k] = rng.normal(0.0, 50.0);
  ThermalFitOptions o;
  const ThermalSelection a = chooseThermalModel(s, nf, o), b = chooseThermalModel(scrambled, nf, o);
  EXPECT_EQ(a.chosen, b.chosen);
  EXPECT_EQ(a.cvRmse, b.cvRmse);
  o.model = a.chosen;
  const ThermalEvaluation ea = fitAndEvaluate(s, 0.5, o), eb = fitAndEvaluate(scrambled, 0.5, o);
  EXPECT_EQ(ea.training.model.regression.terms, eb.training.model.regression.terms);
  EXPECT_EQ(ea.training.model.regression.coef, eb.training.model.regression.coef);
  EXPECT_NE(ea.heldout.rmse, eb.heldout.rmse);
  // On the real log with the spindle speed as an input the chosen model at least halves the static
  // regression's held-out error on the inputs (t5, t9).
  ThermalFitOptions lo;
  lo.model = ThermalModelKind::Linear;
  const ThermalSeries declared =
      decimate(selectThermalSeries(caiviac(), "ch1_um", {"t5_degC", "t9_degC"}), 4);
  const ThermalEvaluation lin = fitAndEvaluate(declared, 0.5, lo);
  EXPECT_LT(ea.heldout.rmse, 0.5 * lin.heldout.rmse) << ea.heldout.rmse << " vs " << lin.heldout.rmse;
}

TEST(ThermalAuto, RegressionModelsRoundTripThroughJson) {
  const ThermalSeries s = decimate(selectThermalSeries(caiviac(), "ch5_um", {"t5_degC", "t9_degC"}), 8);
  for (ThermalModelKind k :
       {ThermalModelKind::Linear, ThermalModelKind::Lag, ThermalModelKind::DistributedLag}) {
    ThermalFitOptions o;
    o.model = k;
    const ThermalModel m = fitThermalModel({s}, o).model;
    const ThermalModel back = thermalModelFromJson(thermalModelToJson(m), "m.json");
    EXPECT_EQ(back.kind, k);
    EXPECT_EQ(predictChange(back, s), predictChange(m, s));
    // The regression reproduces its own least squares: an independent normal-equation solve.
    const auto cols = lagColumns(m.regression.terms, {s.timeMin, {s.inputs[0], s.inputs[1]}, s.target});
    Eigen::MatrixXd X(static_cast<Eigen::Index>(s.rows()), static_cast<Eigen::Index>(cols.size() + 1));
    Eigen::VectorXd y(static_cast<Eigen::Index>(s.rows()));
    for (std::size_t r = 0; r < s.rows(); ++r) {
      X(static_cast<Eigen::Index>(r), 0) = 1.0;
      for (std::size_t c = 0; c < cols.size(); ++c)
        X(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c + 1)) = cols[c][r];
      y(static_cast<Eigen::Index>(r)) = s.target[r] - s.target[0];
    }
    const Eigen::VectorXd b = (X.transpose() * X).ldlt().solve(X.transpose() * y);
    EXPECT_NEAR(m.regression.intercept, b(0), 1e-6 * (1.0 + std::abs(b(0))));
    for (std::size_t c = 0; c < cols.size(); ++c)
      EXPECT_NEAR(m.regression.coef[c], b(static_cast<Eigen::Index>(c + 1)),
                  1e-6 * (1.0 + std::abs(b(static_cast<Eigen::Index>(c + 1)))));
  }
}

}  // namespace
}  // namespace metrofit::thermal
