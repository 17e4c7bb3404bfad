#include "core/optim/least_squares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <Eigen/QR>

#include "core/common/error.h"
#include "core/common/rng.h"

namespace metrofit::optim {
namespace {

using Opt = LeastSquaresOptions;

/// r(x) = A x - b: a linear least-squares problem whose solution Eigen's QR gives independently.
struct Linear {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  Residual residual() const {
    return [this](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
      r = A * x - b;
      if (J) *J = A;
    };
  }
};

Linear randomLinear(std::uint64_t seed, int rows, int cols) {
  Rng rng(seed);
  Linear p{Eigen::MatrixXd(rows, cols), Eigen::VectorXd(rows)};
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) p.A(i, j) = rng.uniform(-1.0, 1.0) * (j + 1);
    p.b(i) = rng.uniform(-5.0, 5.0);
  }
  return p;
}

/// Rosenbrock as least squares: r = (10 (x2 - x1^2), 1 - x1), minimum 0 at (1, 1).
void rosenbrock(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
  r.resize(2);
  r << 10.0 * (x(1) - x(0) * x(0)), 1.0 - x(0);
  if (J) {
    J->resize(2, 2);
    *J << -20.0 * x(0), 10.0, -1.0, 0.0;
  }
}

/// y = A exp(-k t) + c sampled without noise at t = 0, 0.25, ..., 10.
struct Decay {
  Eigen::VectorXd t, y;
  Decay(double A, double k, double c) : t(41), y(41) {
    for (int i = 0; i < 41; ++i) {
      t(i) = 0.25 * i;
      y(i) = A * std::exp(-k * t(i)) + c;
    }
  }
  Residual residual() const {
    return [this](const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
      r.resize(t.size());
      if (J) J->resize(t.size(), 3);
      for (Eigen::Index i = 0; i < t.size(); ++i) {
        const double e = std::exp(-p(1) * t(i));
        r(i) = p(0) * e + p(2) - y(i);
        if (J) J->row(i) << e, -p(0) * t(i) * e, 1.0;
      }
    };
  }
};

void expectNoNan(const LeastSquaresSummary& s, const Eigen::VectorXd& x) {
  EXPECT_TRUE(x.allFinite());
  EXPECT_FALSE(std::isnan(s.initialCost));
  EXPECT_FALSE(std::isnan(s.finalCost));
  EXPECT_FALSE(std::isnan(s.damping));
}

TEST(LeastSquares, LinearProblemMatchesQrAndNormalEquations) {
  const Linear p = randomLinear(7, 30, 4);
  const Eigen::VectorXd xQr = p.A.colPivHouseholderQr().solve(p.b);
  const Eigen::VectorXd xNormal = (p.A.transpose() * p.A).ldlt().solve(p.A.transpose() * p.b);
  ASSERT_LT((xQr - xNormal).norm(), 1e-10);
  for (const auto solver : {Opt::LinearSolver::Qr, Opt::LinearSolver::NormalEquations}) {
    for (const auto scaling : {Opt::Scaling::Marquardt, Opt::Scaling::Identity}) {
      Opt o;
      o.linearSolver = solver;
      o.scaling = scaling;
      Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
      const LeastSquaresSummary s = solveLeastSquares(p.residual(), x, o);
      EXPECT_TRUE(s.converged) << s.message;
      EXPECT_LT((x - xQr).norm(), 1e-8 * (1.0 + xQr.norm()));
      EXPECT_NEAR(s.finalCost, 0.5 * (p.A * xQr - p.b).squaredNorm(), 1e-10);
      EXPECT_GT(s.initialCost, s.finalCost);
      EXPECT_EQ(s.residuals.size(), 30);
      EXPECT_EQ(s.jacobian.rows(), 30);
      EXPECT_LT((s.residuals - (p.A * x - p.b)).norm(), 1e-12);
    }
  }
}

TEST(LeastSquares, RosenbrockReachesOneOne) {
  for (const auto damping : {Opt::Damping::Nielsen, Opt::Damping::Multiplicative}) {
    Opt o;
    o.damping = damping;
    o.maxIterations = 200;
    Eigen::VectorXd x(2);
    x << -1.2, 1.0;  // the classic start
    const LeastSquaresSummary s = solveLeastSquares(rosenbrock, x, o);
    EXPECT_TRUE(s.converged) << s.message;
    EXPECT_NEAR(x(0), 1.0, 1e-8);
    EXPECT_NEAR(x(1), 1.0, 1e-8);
    EXPECT_LT(s.finalCost, 1e-16);
    EXPECT_NEAR(s.initialCost, 0.5 * (4.4 * 4.4 + 2.2 * 2.2), 1e-12);  // r = (-4.4, 2.2)
    EXPECT_GT(s.iterations, 3);
  }
}

TEST(LeastSquares, ExponentialDecayRecoversKnownParameters) {
  const Decay d(2.5, 0.7, 0.3);
  for (const auto jac : {Opt::Jacobian::Analytic, Opt::Jacobian::ForwardDifference}) {
    Opt o;
    o.jacobian = jac;
    o.maxIterations = 200;
    Eigen::VectorXd p(3);
    p << 1.0, 0.2, 0.0;
    const LeastSquaresSummary s = solveLeastSquares(d.residual(), p, o);
    EXPECT_TRUE(s.converged) << s.message;
    EXPECT_NEAR(p(0), 2.5, 1e-6);
    EXPECT_NEAR(p(1), 0.7, 1e-6);
    EXPECT_NEAR(p(2), 0.3, 1e-6);
    EXPECT_LT(s.finalCost, 1e-12);
    if (jac == Opt::Jacobian::ForwardDifference) {
      EXPECT_GT(s.residualEvaluations, 3 * s.jacobianEvaluations);  // n extra residuals per Jacobian
    } else {
      EXPECT_GT(s.jacobianEvaluations, 1);
    }
  }
}

TEST(LeastSquares, InvalidOptionsNameTheField) {
  auto why = [](auto change) {
    Opt o;
    change(o);
    std::string w;
    EXPECT_FALSE(o.isValid(&w));
    return w;
  };
  EXPECT_TRUE(Opt{}.isValid(nullptr));
  EXPECT_NE(why([](Opt& o) { o.costTolerance = -1e-3; }).find("costTolerance"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.stepTolerance = -1.0; }).find("stepTolerance"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.gradientTolerance = -1.0; }).find("gradientTolerance"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.modelStepTolerance = std::nan(""); }).find("modelStepTolerance"),
            std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.maxIterations = 0; }).find("maxIterations"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.initialDamping = 0.0; }).find("initialDamping"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.maxDamping = 1e-6; }).find("maxDamping"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.dampingDecrease = 1.0; }).find("dampingDecrease"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.dampingIncrease = 0.5; }).find("dampingIncrease"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.costWindow = 0; }).find("costWindow"), std::string::npos);
  EXPECT_NE(why([](Opt& o) { o.targetCost = -1.0; }).find("targetCost"), std::string::npos);

  Opt bad;
  bad.maxIterations = 0;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(solveLeastSquares(rosenbrock, x, bad), OptionsError);
  Eigen::VectorXd empty;
  EXPECT_THROW(solveLeastSquares(rosenbrock, empty), OptionsError);
}

TEST(LeastSquares, ObserverSeesEveryIterationAndCancelStopsEarly) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  long calls = 0;
  double last = std::numeric_limits<double>::infinity();
  FunctionObserver watch([&](const IterationSummary& s) {
    EXPECT_EQ(s.iteration, calls);
    EXPECT_LE(s.best, last);  // accepted steps only: the cost never rises
    last = s.best;
    EXPECT_EQ(s.bestX.size(), 2u);
    ++calls;
    return ObserverDecision::Continue;
  });
  const LeastSquaresSummary full = solveLeastSquares(rosenbrock, x, {}, &watch);
  EXPECT_EQ(calls, full.iterations);
  ASSERT_GT(full.iterations, 3);

  x << -1.2, 1.0;
  long seen = 0;
  FunctionObserver stopAtTwo([&](const IterationSummary&) {
    return ++seen >= 2 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const LeastSquaresSummary s = solveLeastSquares(rosenbrock, x, {}, &stopAtTwo);
  EXPECT_EQ(s.termination, LeastSquaresTermination::Cancelled);
  EXPECT_STREQ(toString(s.termination), "cancelled");
  EXPECT_EQ(toTermination(s.termination), Termination::Cancelled);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations, 2);
  EXPECT_GT(std::abs(x(0) - 1.0), 1e-3);  // stopped well before the minimum
  EXPECT_LT(s.finalCost, s.initialCost);

  // A CancelToken raised before the run stops it after the first iteration.
  CancelToken token;
  token.cancel();
  x << -1.2, 1.0;
  const LeastSquaresSummary t = solveLeastSquares(rosenbrock, x, {}, &token);
  EXPECT_EQ(t.termination, LeastSquaresTermination::Cancelled);
  EXPECT_EQ(t.iterations, 1);
}

TEST(LeastSquares, NanResidualAtStartFailsCleanly) {
  const Residual nanEverywhere = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = Eigen::VectorXd::Constant(3, std::nan(""));
    if (J) *J = Eigen::MatrixXd::Ones(3, x.size());
  };
  Eigen::VectorXd x(2);
  x << 0.5, -0.5;
  const LeastSquaresSummary s = solveLeastSquares(nanEverywhere, x);
  EXPECT_EQ(s.termination, LeastSquaresTermination::Failed);
  EXPECT_EQ(toTermination(s.termination), Termination::Failed);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.message.find("not finite"), std::string::npos) << s.message;
  EXPECT_EQ(x(0), 0.5);
  EXPECT_EQ(x(1), -0.5);
  EXPECT_TRUE(std::isinf(s.finalCost));
  expectNoNan(s, x);

  // A non-finite Jacobian is a failure too (not a NaN step).
  const Residual nanJacobian = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r = x;
    if (J) *J = Eigen::MatrixXd::Constant(x.size(), x.size(), std::nan(""));
  };
  x << 0.5, -0.5;
  const LeastSquaresSummary j = solveLeastSquares(nanJacobian, x);
  EXPECT_EQ(j.termination, LeastSquaresTermination::Failed);
  EXPECT_NE(j.message.find("Jacobian"), std::string::npos) << j.message;
  expectNoNan(j, x);
}

TEST(LeastSquares, NanRegionIsAvoidedNotEntered) {
  // r = x - 3 but NaN for x > 2.5: the minimiser must stop at a finite point below 2.5; the
  // Gauss-Newton step from 0 lands at 3, in the NaN region, and is rejected.
  const Residual f = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    r.resize(1);
    r(0) = x(0) > 2.5 ? std::nan("") : x(0) - 3.0;
    if (J) *J = Eigen::MatrixXd::Ones(1, 1);
  };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(1);
  const LeastSquaresSummary s = solveLeastSquares(f, x);
  expectNoNan(s, x);
  EXPECT_LE(x(0), 2.5);
  EXPECT_GT(x(0), 2.0);
  EXPECT_LT(s.finalCost, s.initialCost);
  EXPECT_NE(s.termination, LeastSquaresTermination::Failed) << s.message;
}

TEST(LeastSquares, StoppingRulesEachEndTheRunWithTheirReason) {
  const Decay d(2.5, 0.7, 0.3);
  Eigen::VectorXd p0(3);
  p0 << 1.0, 0.2, 0.0;
  {
    Opt o;
    o.maxIterations = 2;
    Eigen::VectorXd p = p0;
    const LeastSquaresSummary s = solveLeastSquares(d.residual(), p, o);
    EXPECT_EQ(s.termination, LeastSquaresTermination::MaxIterations);
    EXPECT_EQ(s.iterations, 2);
  }
  {
    Opt o;
    o.targetCost = 1e-3;
    Eigen::VectorXd p = p0;
    const LeastSquaresSummary s = solveLeastSquares(d.residual(), p, o);
    EXPECT_EQ(s.termination, LeastSquaresTermination::TargetCost);
    EXPECT_LE(s.finalCost, 1e-3);
    EXPECT_GT(s.finalCost, 1e-12);  // stopped at the target, not at the minimum
  }
  {
    Opt o;
    o.gradientTolerance = 1e-3;
    Eigen::VectorXd p = p0;
    const LeastSquaresSummary s = solveLeastSquares(d.residual(), p, o);
    EXPECT_EQ(s.termination, LeastSquaresTermination::GradientTolerance);
    EXPECT_LE((s.jacobian.transpose() * s.residuals).norm(), 1e-3);
  }
  {
    Opt o;
    o.costTolerance = 0.0;
    o.stepTolerance = 1e-6;
    Eigen::VectorXd p = p0;
    const LeastSquaresSummary s = solveLeastSquares(d.residual(), p, o);
    EXPECT_EQ(s.termination, LeastSquaresTermination::StepTolerance) << s.message;
  }
  {
    Opt o;  // an exact fit of a linear problem with a square, regular A: zero cost
    Linear p{Eigen::Matrix2d{{2.0, 1.0}, {0.0, 1.0}}, Eigen::Vector2d(1.0, 1.0)};
    Eigen::VectorXd x = Eigen::VectorXd::Zero(2);
    o.costTolerance = 0.0;
    const LeastSquaresSummary s = solveLeastSquares(p.residual(), x, o);
    EXPECT_TRUE(s.converged) << s.message;
    EXPECT_NEAR(x(0), 0.0, 1e-12);
    EXPECT_NEAR(x(1), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace metrofit::optim
