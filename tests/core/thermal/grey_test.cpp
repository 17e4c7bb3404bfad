// 1-AGO / IAGO (Abdulshahed 2016, grey neural network thermal model, Appendix A) and GMC(1,N) (Eq. 2.1-2.2).
#include "core/thermal/grey.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

std::vector<double> minutes(std::size_t n, double step) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k) * step;
  return t;
}

TEST(Grey, AgoAndIagoOfAppendixA) {
  // Appendix A, Step 2 and 3, by hand: 1, 1+2, 1+2+3, ...; and back.
  const std::vector<double> x0{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(ago(x0), (std::vector<double>{1.0, 3.0, 6.0, 10.0}));
  EXPECT_EQ(iago(std::vector<double>{1.0, 3.0, 6.0, 10.0}), x0);
  // Table 1's displacement column (the paper's first five readings).
  const std::vector<double> d{0.0, -0.2282, -0.5766, -0.8127, -1.1718};
  const std::vector<double> d1 = ago(d);
  EXPECT_TRUE(test::near(d1.back(), -2.7893, 1e-12));
  const std::vector<double> back = iago(d1);
  for (std::size_t k = 0; k < d.size(); ++k) EXPECT_TRUE(test::near(back[k], d[k], 1e-12));
}

TEST(Grey, RoundTripOnRandomDataEqualAndUnequalSteps) {
  Rng rng(4);
  std::vector<double> x(300), t(300);
  double time = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = rng.normal(0.0, 10.0);
    t[k] = time;
    time += rng.uniform(0.2, 3.0);
  }
  const GreyTime uneven = greyTime(t, meanStepMin(t));
  EXPECT_FALSE(uneven.uniform);
  for (const auto* w : {static_cast<const std::vector<double>*>(nullptr), &uneven.weight}) {
    const auto x1 = w ? ago(x, *w) : ago(x);
    const auto back = w ? iago(x1, *w) : iago(x1);
    for (std::size_t k = 0; k < x.size(); ++k) ASSERT_TRUE(test::near(back[k], x[k], 1e-9)) << k;
  }
}

TEST(Grey, WeightedAgoIsTheRunningIntegralInTimeUnits) {
  // Unequal steps: x = 2 everywhere, times 0, 1, 3, 4 min, unit 2 min -> weights 1, 0.5, 1, 0.5.
  const std::vector<double> t{0.0, 1.0, 3.0, 4.0};
  const GreyTime g = greyTime(t, 2.0);
  EXPECT_EQ(g.tau, (std::vector<double>{0.0, 0.5, 1.5, 2.0}));
  EXPECT_EQ(g.weight, (std::vector<double>{1.0, 0.5, 1.0, 0.5}));
  EXPECT_EQ(ago(std::vector<double>{2, 2, 2, 2}, g.weight), (std::vector<double>{2.0, 3.0, 5.0, 6.0}));
  // Equal steps in the unit reduce to Appendix A exactly.
  const GreyTime e = greyTime(minutes(5, 0.25), 0.25);
  EXPECT_TRUE(e.uniform);
  EXPECT_EQ(ago(std::vector<double>{1, 2, 3, 4, 5}, e.weight), ago(std::vector<double>{1, 2, 3, 4, 5}));
}

/// Eq. 2.2 written out literally as the double sum (O(n^2)), f indexed from the first sample.
std::vector<double> literalEq22(const GmcParameters& p, double x11,
                                const std::vector<std::vector<double>>& xAgo, const GreyTime& g) {
  auto f = [&](std::size_t k) {
    double v = p.u;
    for (std::size_t j = 0; j < xAgo.size(); ++j) v += p.b[j] * xAgo[j][k];
    return v;
  };
  std::vector<double> out(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    double s = 0.0;
    for (std::size_t i = 1; i <= k; ++i) {
      const double mid = 0.5 * (g.tau[i] + g.tau[i - 1]);
      s += std::exp(-p.b1 * (g.tau[k] - mid)) * g.weight[i] * 0.5 * (f(i) + f(i - 1));
    }
    out[k] = x11 * std::exp(-p.b1 * g.tau[k]) + s;
  }
  return out;
}

GreySeries drivenSeries(std::size_t n, const std::vector<double>& t) {
  GreySeries s;
  s.time = greyTime(t, meanStepMin(t));
  s.inputs.assign(2, std::vector<double>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const double tk = t[k];
    s.inputs[0][k] = 5.0 * (1.0 - std::exp(-tk / 40.0));
    s.inputs[1][k] = std::sin(tk / 25.0) + 0.02 * tk;
  }
  return s;
}

TEST(Grey, TimeResponseRecursionEqualsTheSumOfEq22) {
  const GmcParameters p{0.07, {0.3, -0.8}, 0.4};
  for (bool uneven : {false, true}) {
    std::vector<double> t = minutes(120, 1.0);
    if (uneven) {
      for (std::size_t k = 0; k < t.size(); ++k) t[k] += 0.3 * std::sin(static_cast<double>(k));
    }
    const GreySeries s = drivenSeries(t.size(), t);
    const auto xAgo = inputsAgo(s);
    const auto fast = gmcTimeResponse(p, 1.7, xAgo, s.time);
    const auto slow = literalEq22(p, 1.7, xAgo, s.time);
    for (std::size_t k = 0; k < t.size(); ++k) ASSERT_TRUE(test::near(fast[k], slow[k], 1e-9, 1e-12)) << k;
    EXPECT_EQ(fast[0], 1.7);
  }
}

TEST(Grey, LeastSquaresRecoversTheParametersOfTheGreyDifferenceEquation) {
  // Data made by the grey difference equation itself, x_1^(0)(k) = -b1 z_1(k) + sum b_j z_j(k) + u,
  // solved forward for X_1^(1)(k): the least squares must give the parameters back (to rounding).
  const GmcParameters truth{0.05, {0.6, -0.25}, 0.3};
  const std::vector<double> t = minutes(150, 1.0);
  GreySeries s = drivenSeries(t.size(), t);
  const auto xAgo = inputsAgo(s);
  std::vector<double> x1(t.size());
  x1[0] = 0.4;
  for (std::size_t k = 1; k < t.size(); ++k) {
    double f = truth.u;
    for (std::size_t j = 0; j < 2; ++j) f += truth.b[j] * 0.5 * (xAgo[j][k] + xAgo[j][k - 1]);
    x1[k] = (x1[k - 1] * (1.0 - 0.5 * truth.b1) + f) / (1.0 + 0.5 * truth.b1);
  }
  s.target = iago(x1);
  const GmcParameters p = fitGmcLeastSquares({s});
  EXPECT_TRUE(test::near(p.b1, truth.b1, 1e-9));
  EXPECT_TRUE(test::near(p.b[0], truth.b[0], 1e-9));
  EXPECT_TRUE(test::near(p.b[1], truth.b[1], 1e-9));
  EXPECT_TRUE(test::near(p.u, truth.u, 1e-9));
}

TEST(Grey, LeastSquaresRecoversTheParametersOfTheTimeResponse) {
  // Data made by the time response of Eq. 2.2 (a different discretisation of Eq. 2.1 than the
  // least-squares equation): the parameters come back within 1 % and the output within 0.5 %.
  const GmcParameters truth{0.05, {0.6, -0.25}, 0.3};
  const std::vector<double> t = minutes(240, 1.0);
  GreySeries s = drivenSeries(t.size(), t);
  s.target = iago(gmcTimeResponse(truth, 0.0, inputsAgo(s), s.time));
  const GmcParameters p = fitGmcLeastSquares({s});
  EXPECT_TRUE(test::near(p.b1, truth.b1, 0.0, 0.01)) << p.b1;
  EXPECT_TRUE(test::near(p.b[0], truth.b[0], 0.0, 0.01)) << p.b[0];
  EXPECT_TRUE(test::near(p.b[1], truth.b[1], 0.0, 0.01)) << p.b[1];
  const auto y = gmcPredict(p, s);
  double peak = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    peak = std::max(peak, std::abs(s.target[k]));
    worst = std::max(worst, std::abs(y[k] - s.target[k]));
  }
  EXPECT_LT(worst, 0.005 * peak);
}

TEST(Grey, LeastSquaresOverTwoSegmentsAndRankDeficiency) {
  const GmcParameters truth{0.08, {0.5, 0.2}, 0.0};
  std::vector<GreySeries> segs;
  for (double phase : {0.0, 2.0}) {
    const std::vector<double> t = minutes(100, 1.0);
    GreySeries s = drivenSeries(t.size(), t);
    for (auto& v : s.inputs[1]) v += phase;
    s.target = iago(gmcTimeResponse(truth, 0.0, inputsAgo(s), s.time));
    segs.push_back(s);
  }
  const GmcParameters p = fitGmcLeastSquares(segs);
  EXPECT_TRUE(test::near(p.b1, truth.b1, 0.0, 0.02)) << p.b1;
  // Two identical inputs make the system rank deficient: a clear input error, not garbage.
  GreySeries dup = segs[0];
  dup.inputs[1] = dup.inputs[0];
  try {
    (void)fitGmcLeastSquares({dup});
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("rank deficient"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace metrofit::thermal
