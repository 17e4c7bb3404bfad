// The statistics of the closed loop (core/diagnose/linear_evidence.h) against closed-form results.
#include "core/diagnose/linear_evidence.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/rng.h"

namespace metrofit::diagnose {
namespace {

TEST(LinearEvidence, RankDeficientDeclaredModelGivesTheOrdinaryLeastSquaresEffect) {
  // Declared: an intercept written twice (rank 1). Effect: a slope in t.
  const int n = 50;
  Eigen::MatrixXd X(n, 2);
  Eigen::VectorXd t(n), y(n);
  Rng rng(5);
  for (int i = 0; i < n; ++i) {
    X(i, 0) = 1.0;
    X(i, 1) = 1.0;
    t(i) = i * 0.7;
    y(i) = 2.0 + 0.5 * t(i) + rng.normal(0.0, 0.1);
  }
  const ColumnSpace declared(X);
  EXPECT_EQ(declared.rank(), 1);
  const EffectEstimate e = estimateEffects(declared, y, t);
  ASSERT_TRUE(e.identifiable);
  EXPECT_EQ(e.rank, 2);
  EXPECT_EQ(e.dof, n - 2);
  // Simple regression: slope = Sxy / Sxx, se = s / sqrt(Sxx).
  const double tm = t.mean(), ym = y.mean();
  const double sxx = (t.array() - tm).square().sum();
  const double sxy = ((t.array() - tm) * (y.array() - ym)).sum();
  const double slope = sxy / sxx;
  const Eigen::VectorXd r = (y.array() - ym - slope * (t.array() - tm)).matrix();
  EXPECT_NEAR(e.beta(0), slope, 1e-12);
  EXPECT_NEAR(e.rss, r.squaredNorm(), 1e-12);
  EXPECT_NEAR(std::sqrt(e.covariance(0, 0)), std::sqrt(r.squaredNorm() / (n - 2) / sxx), 1e-12);
  // An effect the declared model explains is not identifiable.
  const EffectEstimate absorbed = estimateEffects(declared, y, Eigen::VectorXd::Constant(n, 3.0));
  EXPECT_FALSE(absorbed.identifiable);
  EXPECT_EQ(absorbed.why, "absorbed by the declared model");
  EXPECT_DOUBLE_EQ(absorbed.rss, declared.residual(y).squaredNorm());
}

TEST(LinearEvidence, BicAndTheDecision) {
  EXPECT_NEAR(deltaBic(2.0, 1.0, 100, 94, 1), 94.0 * std::log(0.5) + std::log(100.0), 1e-12);
  AcceptanceOptions o;  // dBIC < -10, >= 2 %
  AcceptanceDecision d = decideAcceptance(o, 100.0, 50.0, 100, 90, 1, "mm");
  EXPECT_TRUE(d.accepted) << d.reason;
  EXPECT_EQ(d.reason.rfind("dBIC = -57.8 < -10, rmse 1 -> 0.7071 mm (-29.3 %)", 0), 0u) << d.reason;
  // Strong, but not practically relevant: 1.5 % of the rmse.
  d = decideAcceptance(o, 1.0, 0.9703, 100000, 99990, 1, "mm");
  EXPECT_FALSE(d.accepted);
  EXPECT_NE(d.reason.find("below the relevant 2.0 %"), std::string::npos) << d.reason;
  // Relevant but weak.
  d = decideAcceptance(o, 1.0, 0.8, 20, 14, 1, "mm");
  EXPECT_FALSE(d.accepted);
  EXPECT_NE(d.reason.find("not below -10"), std::string::npos) << d.reason;
  o.minRelativeReduction = 1.0;
  EXPECT_FALSE(o.isValid(nullptr));
}

}  // namespace
}  // namespace metrofit::diagnose
