#include "core/thermal/mlp.h"
#include "core/common/numformat.h"

#include <cmath>
#include <stdexcept>

#include "core/common/rng.h"
#include "core/optim/least_squares.h"

namespace metrofit::thermal {

bool MlpOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (hidden < 1) return no("the MLP needs at least one hidden neuron");
  if (maxEpochs < 1) return no("maxEpochs must be at least 1");
  if (!(goalMse >= 0.0)) return no("the MSE goal must be >= 0");
  if (!(mu0 > 0.0) || !(muDecrease > 0.0 && muDecrease < 1.0) || !(muIncrease > 1.0) || !(muMax > mu0))
    return no("need mu0 > 0, 0 < muDecrease < 1, muIncrease > 1, muMax > mu0");
  if (!(minGradient >= 0.0)) return no("minGradient must be >= 0");
  if (stallEpochs < 1 || !(minRelativeImprovement >= 0.0))
    return no("stallEpochs must be >= 1 and minRelativeImprovement >= 0");
  return true;
}

namespace {

double sigmoid(double z) {
  return 1.0 / (1.0 + std::exp(-z));
}

double normalise(double v, double lo, double hi) {
  return 2.0 * (v - lo) / (hi - lo) - 1.0;
}

/// Parameter vector layout: W (row-major, hidden x inputs), c (hidden), v (hidden), v0.
struct Layout {
  Eigen::Index n, h;
  Eigen::Index size() const { return h * n + h + h + 1; }
  Eigen::Index w(Eigen::Index i, Eigen::Index j) const { return i * n + j; }
  Eigen::Index c(Eigen::Index i) const { return h * n + i; }
  Eigen::Index v(Eigen::Index i) const { return h * n + h + i; }
  Eigen::Index v0() const { return h * n + 2 * h; }
};

/// Outputs (normalised) of the network with parameters p on normalised inputs xn.
Eigen::VectorXd forward(const Layout& l, const Eigen::VectorXd& p, const Eigen::MatrixXd& xn,
                        Eigen::MatrixXd* sOut = nullptr) {
  const Eigen::Index m = xn.rows();
  Eigen::MatrixXd s(m, l.h);
  for (Eigen::Index i = 0; i < l.h; ++i) {
    Eigen::VectorXd z = Eigen::VectorXd::Constant(m, p(l.c(i)));
    for (Eigen::Index j = 0; j < l.n; ++j) z += p(l.w(i, j)) * xn.col(j);
    s.col(i) = z.unaryExpr([](double t) { return sigmoid(t); });
  }
  Eigen::VectorXd y = Eigen::VectorXd::Constant(m, p(l.v0()));
  for (Eigen::Index i = 0; i < l.h; ++i) y += p(l.v(i)) * s.col(i);
  if (sOut) *sOut = std::move(s);
  return y;
}

}  // namespace

double Mlp::predict(std::span<const double> x) const {
  if (x.size() != inputs()) throw std::invalid_argument("Mlp::predict: wrong number of inputs");
  double yn = v0;
  for (Eigen::Index i = 0; i < w.rows(); ++i) {
    double z = c(i);
    for (Eigen::Index j = 0; j < w.cols(); ++j)
      z += w(i, j) * normalise(x[static_cast<std::size_t>(j)], inMin(j), inMax(j));
    yn += v(i) * sigmoid(z);
  }
  return outMin + (yn + 1.0) * 0.5 * (outMax - outMin);
}

Eigen::VectorXd Mlp::predict(const Eigen::MatrixXd& x) const {
  Eigen::VectorXd out(x.rows());
  std::vector<double> row(static_cast<std::size_t>(x.cols()));
  for (Eigen::Index r = 0; r < x.rows(); ++r) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) row[static_cast<std::size_t>(j)] = x(r, j);
    out(r) = predict(row);
  }
  return out;
}

MlpTraining trainMlp(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const MlpOptions& o,
                     Observer* observer) {
  requireValid(o, "MLP options");
  const Eigen::Index m = x.rows(), n = x.cols();
  if (m < 2 || n < 1 || y.size() != m) throw std::invalid_argument("trainMlp: need >= 2 rows and >= 1 input");
  MlpTraining out;
  Mlp& net = out.net;
  net.inMin = x.colwise().minCoeff().transpose();
  net.inMax = x.colwise().maxCoeff().transpose();
  net.outMin = y.minCoeff();
  net.outMax = y.maxCoeff();
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!(net.inMax(j) > net.inMin(j))) throw std::invalid_argument("trainMlp: constant input");
  }
  if (!(net.outMax > net.outMin)) throw std::invalid_argument("trainMlp: constant output");

  Eigen::MatrixXd xn(m, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index r = 0; r < m; ++r) xn(r, j) = normalise(x(r, j), net.inMin(j), net.inMax(j));
  Eigen::VectorXd yn(m);
  for (Eigen::Index r = 0; r < m; ++r) yn(r) = normalise(y(r), net.outMin, net.outMax);

  const Layout l{n, o.hidden};
  const Eigen::Index np = l.size();
  Eigen::VectorXd p(np);
  Rng rng(o.seed);
  const double sIn = 1.0 / std::sqrt(static_cast<double>(n + 1));
  const double sOut = 1.0 / std::sqrt(static_cast<double>(o.hidden + 1));
  for (Eigen::Index i = 0; i < l.h; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) p(l.w(i, j)) = rng.uniform(-1.0, 1.0) * sIn;
    p(l.c(i)) = rng.uniform(-1.0, 1.0) * sIn;
  }
  for (Eigen::Index i = 0; i < l.h; ++i) p(l.v(i)) = rng.uniform(-1.0, 1.0) * sOut;
  p(l.v0()) = rng.uniform(-1.0, 1.0) * sOut;

  // Levenberg-Marquardt of trainlm on the shared solver (core/optim/least_squares.h): residuals
  // y^ - y (cost 1/2 m MSE), mu I damping (identity scaling), LDLT of J^T J + mu I, mu multiplied by
  // muDecrease / muIncrease; the stopping rules of the header mapped onto the solver's.
  const double md = static_cast<double>(m);
  const optim::Residual f = [&](const Eigen::VectorXd& q, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    Eigen::MatrixXd s;
    r = forward(l, q, xn, J ? &s : nullptr) - yn;
    if (!J) return;
    // Jacobian of the outputs with respect to the parameters.
    J->resize(m, np);
    for (Eigen::Index i = 0; i < l.h; ++i) {
      const Eigen::VectorXd ds = (s.col(i).array() * (1.0 - s.col(i).array())).matrix() * q(l.v(i));
      for (Eigen::Index j = 0; j < n; ++j) J->col(l.w(i, j)) = ds.cwiseProduct(xn.col(j));
      J->col(l.c(i)) = ds;
      J->col(l.v(i)) = s.col(i);
    }
    J->col(l.v0()).setOnes();
  };
  optim::LeastSquaresOptions lo;
  lo.maxIterations = o.maxEpochs;
  lo.damping = optim::LeastSquaresOptions::Damping::Multiplicative;
  lo.scaling = optim::LeastSquaresOptions::Scaling::Identity;
  lo.linearSolver = optim::LeastSquaresOptions::LinearSolver::NormalEquations;
  lo.initialDamping = o.mu0;
  lo.dampingDecrease = o.muDecrease;
  lo.dampingIncrease = o.muIncrease;
  lo.maxDamping = o.muMax;
  lo.targetCost = 0.5 * md * o.goalMse;         // MSE <= goal
  lo.gradientTolerance = o.minGradient * md;    // |J^T e| / rows <= minGradient
  lo.costTolerance = o.minRelativeImprovement;  // the stall test over stallEpochs epochs
  lo.costWindow = o.stallEpochs;
  RunInfo& run = out.run;
  FunctionObserver report([&](const IterationSummary& g) {
    IterationSummary sum;
    sum.iteration = g.iteration;
    sum.evaluations = g.evaluations;
    sum.best = 2.0 * g.best / md;  // MSE
    sum.components = {{"mu", g.components.at(1).value}};
    sum.progress = g.progress;
    return notify(observer, run, sum, o.keepTrace) ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  const optim::LeastSquaresSummary sum = optim::solveLeastSquares(f, p, lo, &report);
  using T = optim::LeastSquaresTermination;
  run.termination = optim::toTermination(sum.termination);
  switch (sum.termination) {
    case T::TargetCost:
      run.message = "performance goal met";
      break;
    case T::GradientTolerance:
      run.message = "gradient below minGradient";
      break;
    case T::DampingLimit:
      run.message = "mu reached muMax (no step lowers the error)";
      break;
    case T::CostTolerance:
      run.message = "MSE stalled (relative improvement below " + num::toString(o.minRelativeImprovement) +
                    " over " + std::to_string(o.stallEpochs) + " epochs)";
      break;
    case T::MaxIterations:
      run.message = "maximum number of epochs reached";
      break;
    default:
      run.message = sum.message;
  }
  run.iterations = sum.iterations;
  run.evaluations = sum.residualEvaluations + sum.jacobianEvaluations;
  out.mse = 2.0 * sum.finalCost / md;
  net.w.resize(l.h, n);
  net.c.resize(l.h);
  net.v.resize(l.h);
  for (Eigen::Index i = 0; i < l.h; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) net.w(i, j) = p(l.w(i, j));
    net.c(i) = p(l.c(i));
    net.v(i) = p(l.v(i));
  }
  net.v0 = p(l.v0());
  return out;
}

}  // namespace metrofit::thermal
