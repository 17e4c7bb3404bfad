// The MLP baseline of Abdulshahed 2016, grey neural network thermal model (Table 3): N-10-1, logistic hidden
// layer, Levenberg-Marquardt.
#include "core/thermal/mlp.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

double smooth(double a, double b) {
  return std::sin(2.0 * a) + 0.5 * b * b - 0.3 * a * b;
}

void makeData(std::size_t rows, std::uint64_t seed, Eigen::MatrixXd* x, Eigen::VectorXd* y) {
  Rng rng(seed);
  x->resize(static_cast<Eigen::Index>(rows), 2);
  y->resize(static_cast<Eigen::Index>(rows));
  for (Eigen::Index r = 0; r < x->rows(); ++r) {
    (*x)(r, 0) = rng.uniform(-1.5, 1.5);
    (*x)(r, 1) = rng.uniform(-1.0, 2.0);
    (*y)(r) = smooth((*x)(r, 0), (*x)(r, 1));
  }
}

TEST(Mlp, LevenbergMarquardtFitsAKnownSmoothFunction) {
  Eigen::MatrixXd x, xt;
  Eigen::VectorXd y, yt;
  makeData(300, 1, &x, &y);
  makeData(200, 2, &xt, &yt);  // unseen points inside the same box
  MlpOptions o;
  o.goalMse = 0.0;
  o.maxEpochs = 300;
  const MlpTraining t = trainMlp(x, y, o);
  EXPECT_EQ(t.net.hidden(), 10u);
  EXPECT_EQ(t.net.inputs(), 2u);
  EXPECT_GT(t.run.iterations, 5);
  // The range of y is about 4; the network must get within 1 % of it on unseen points.
  const Eigen::VectorXd p = t.net.predict(xt);
  const double rmse = std::sqrt((p - yt).squaredNorm() / static_cast<double>(yt.size()));
  EXPECT_LT(rmse, 0.02) << rmse;
  // The trace is monotone: LM accepts only steps that lower the error.
  for (std::size_t i = 1; i < t.run.trace.size(); ++i)
    EXPECT_LE(t.run.trace[i].best, t.run.trace[i - 1].best);
  // Single-row predict agrees with the matrix form.
  const std::vector<double> row{xt(3, 0), xt(3, 1)};
  EXPECT_DOUBLE_EQ(t.net.predict(row), p(3));
}

TEST(Mlp, SameSeedSameNetworkAndGoalStops) {
  Eigen::MatrixXd x;
  Eigen::VectorXd y;
  makeData(120, 3, &x, &y);
  MlpOptions o;
  o.maxEpochs = 40;
  o.goalMse = 0.0;
  const MlpTraining a = trainMlp(x, y, o), b = trainMlp(x, y, o);
  EXPECT_EQ(a.net.w, b.net.w);
  EXPECT_EQ(a.net.v0, b.net.v0);
  ASSERT_EQ(a.run.trace.size(), b.run.trace.size());
  for (std::size_t i = 0; i < a.run.trace.size(); ++i) EXPECT_EQ(a.run.trace[i].best, b.run.trace[i].best);
  o.seed = 2;
  EXPECT_NE(trainMlp(x, y, o).net.w, a.net.w);
  // A reachable goal ends the run as converged with that reason.
  o.goalMse = 1e-2;
  const MlpTraining g = trainMlp(x, y, o);
  EXPECT_EQ(g.run.termination, Termination::Converged);
  EXPECT_EQ(g.run.message, "performance goal met");
  EXPECT_LE(g.mse, 1e-2);
}

TEST(Mlp, ObserverCancels) {
  Eigen::MatrixXd x;
  Eigen::VectorXd y;
  makeData(80, 5, &x, &y);
  MlpOptions o;
  o.goalMse = 0.0;
  FunctionObserver stop([](const IterationSummary& s) {
    return s.iteration >= 2 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const MlpTraining t = trainMlp(x, y, o, &stop);
  EXPECT_EQ(t.run.termination, Termination::Cancelled);
  EXPECT_EQ(t.run.iterations, 3);
}

TEST(Mlp, OptionsValidation) {
  MlpOptions o;
  std::string why;
  EXPECT_TRUE(o.isValid(&why));
  EXPECT_EQ(o.hidden, 10);
  EXPECT_EQ(o.maxEpochs, 5000);
  EXPECT_EQ(o.goalMse, 1e-4);
  o.hidden = 0;
  EXPECT_FALSE(o.isValid(&why));
  EXPECT_EQ(why, "the MLP needs at least one hidden neuron");
  Eigen::MatrixXd x(3, 1);
  x << 1, 1, 1;
  EXPECT_THROW(trainMlp(x, Eigen::Vector3d(1, 2, 3), MlpOptions{}), std::invalid_argument);
  EXPECT_THROW(trainMlp(x, Eigen::Vector3d(1, 2, 3), o), OptionsError);
  EXPECT_EQ(Mlp::parameterCount(5, 10), 71u);
}

}  // namespace
}  // namespace metrofit::thermal
