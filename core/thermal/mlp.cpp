#include "core/thermal/mlp.h"

#include <cmath>
#include <stdexcept>

#include "core/common/rng.h"

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

  const double md = static_cast<double>(m);
  Eigen::MatrixXd s;
  Eigen::VectorXd e = yn - forward(l, p, xn, &s);
  double mse = e.squaredNorm() / md;
  double mu = o.mu0;
  long evaluations = 1;
  std::vector<double> history{mse};
  RunInfo& run = out.run;
  run.termination = Termination::MaxIterations;
  run.message = "maximum number of epochs reached";
  Eigen::MatrixXd jac(m, np);
  for (int epoch = 0; epoch < o.maxEpochs; ++epoch) {
    if (mse <= o.goalMse) {
      run.termination = Termination::Converged;
      run.message = "performance goal met";
      break;
    }
    // Jacobian of the outputs with respect to the parameters.
    for (Eigen::Index i = 0; i < l.h; ++i) {
      const Eigen::VectorXd ds = (s.col(i).array() * (1.0 - s.col(i).array())).matrix() * p(l.v(i));
      for (Eigen::Index j = 0; j < n; ++j) jac.col(l.w(i, j)) = ds.cwiseProduct(xn.col(j));
      jac.col(l.c(i)) = ds;
      jac.col(l.v(i)) = s.col(i);
    }
    jac.col(l.v0()).setOnes();
    const Eigen::VectorXd g = jac.transpose() * e;
    if (g.norm() / md < o.minGradient) {
      run.termination = Termination::Converged;
      run.message = "gradient below minGradient";
      break;
    }
    Eigen::MatrixXd jtj(np, np);
    jtj.setZero();
    jtj.selfadjointView<Eigen::Lower>().rankUpdate(jac.transpose());
    jtj = jtj.selfadjointView<Eigen::Lower>();
    bool accepted = false;
    while (mu <= o.muMax) {
      Eigen::MatrixXd a = jtj;
      a.diagonal().array() += mu;
      const Eigen::VectorXd delta = a.ldlt().solve(g);
      const Eigen::VectorXd pNew = p + delta;
      Eigen::MatrixXd sNew;
      const Eigen::VectorXd eNew = yn - forward(l, pNew, xn, &sNew);
      ++evaluations;
      const double mseNew = eNew.squaredNorm() / md;
      if (std::isfinite(mseNew) && mseNew < mse) {
        p = pNew;
        s = std::move(sNew);
        e = eNew;
        mse = mseNew;
        mu *= o.muDecrease;
        accepted = true;
        break;
      }
      mu *= o.muIncrease;
    }
    history.push_back(mse);
    IterationSummary sum;
    sum.iteration = epoch;
    sum.evaluations = evaluations;
    sum.best = mse;
    sum.components = {{"mu", mu}};
    sum.progress = static_cast<double>(epoch + 1) / static_cast<double>(o.maxEpochs);
    if (notify(observer, run, sum, o.keepTrace)) break;
    if (!accepted) {
      run.termination = Termination::Converged;
      run.message = "mu reached muMax (no step lowers the error)";
      break;
    }
    if (mse <= o.goalMse) {
      run.termination = Termination::Converged;
      run.message = "performance goal met";
      break;
    }
    const std::size_t k = history.size() - 1;
    if (k >= static_cast<std::size_t>(o.stallEpochs)) {
      const double before = history[k - static_cast<std::size_t>(o.stallEpochs)];
      if (before - mse <= o.minRelativeImprovement * before) {
        run.termination = Termination::Converged;
        run.message = "MSE stalled (relative improvement below " + std::to_string(o.minRelativeImprovement) +
                      " over " + std::to_string(o.stallEpochs) + " epochs)";
        break;
      }
    }
  }
  run.evaluations = evaluations;
  out.mse = mse;
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
