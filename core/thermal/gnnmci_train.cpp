// GNNMCI(1,N) training by PSO (Abdulshahed 2016, grey neural network thermal model, Eq. 2.7-2.9); the
// particle box and the two training modes are documented in gnnmci.h.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/optim/pso.h"
#include "core/thermal/gnnmci.h"

namespace metrofit::thermal {

const char* toString(GnnmciOptions::Training t) {
  return t == GnnmciOptions::Training::Pso ? "pso" : "pso-ls";
}

namespace {

/// The fitness of Eq. 2.9 over the particle coordinates (log10 w11 [, normalised gains, u]).
class GnnmciProblem final : public optim::Problem {
 public:
  GnnmciProblem(const std::vector<GreySeries>& segments, const GnnmciOptions& o)
      : segments_(segments), leastSquares_(o.training == GnnmciOptions::Training::PsoLeastSquares) {
    m_ = segments.front().inputs.size();
    double yMin = std::numeric_limits<double>::infinity(), yMax = -yMin;
    std::vector<double> xMin(m_, yMin), xMax(m_, yMax);
    double span = 0.0;
    for (const auto& s : segments) {
      if (s.inputs.size() != m_ || s.target.size() != s.time.size() || s.time.size() < 2)
        throw std::invalid_argument(
            "trainGnnmci: every segment needs a target, the same inputs, >= 2 samples");
      xAgo_.push_back(inputsAgo(s));
      samples_ += s.time.size();
      span = std::max(span, s.time.tau.back());
      for (double y : s.target) {
        yMin = std::min(yMin, y);
        yMax = std::max(yMax, y);
      }
      for (std::size_t j = 0; j < m_; ++j) {
        for (double x : s.inputs[j]) {
          xMin[j] = std::min(xMin[j], x);
          xMax[j] = std::max(xMax[j], x);
        }
      }
    }
    rangeY_ = yMax - yMin;
    if (!(rangeY_ > 0.0)) throw std::invalid_argument("trainGnnmci: constant target");
    for (std::size_t j = 0; j < m_; ++j) {
      rangeX_.push_back(xMax[j] - xMin[j]);
      if (!(rangeX_.back() > 0.0)) throw std::invalid_argument("trainGnnmci: constant input");
    }
    upper0_ = std::log10(1.0 / o.minLagSteps);
    lower0_ = std::min(std::log10(1.0 / (o.maxLagFactor * span)), upper0_ - 1.0);
    gain_ = o.gainBound;
  }

  std::string name() const override { return "GNNMCI(1,N) fitness (Eq. 2.9)"; }
  std::size_t dimension() const override { return leastSquares_ ? 1 : m_ + 2; }
  double lower(std::size_t i) const override { return i == 0 ? lower0_ : -gain_; }
  double upper(std::size_t i) const override { return i == 0 ? upper0_ : gain_; }
  std::vector<std::string> componentNames() const override { return {"fit_rmse"}; }

  /// The network weights of a particle.
  GnnmciWeights weights(std::span<const double> p) const {
    GnnmciWeights w;
    w.w11 = std::pow(10.0, p[0]);
    if (leastSquares_) {
      std::vector<GnnmciLayerInputs> in;
      w.w2 = layerCLeastSquares(w.w11, in);
      return w;
    }
    w.w2.resize(m_ + 1);
    for (std::size_t j = 0; j < m_; ++j) w.w2[j] = w.w11 * p[j + 1] * rangeY_ / rangeX_[j];
    w.w2[m_] = p[m_ + 1] * rangeY_;
    return w;
  }

  /// Eq. 2.9 through the network (gnnmciForward, IAGO).
  double fitness(const GnnmciWeights& w) const {
    double f = 0.0;
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const GreySeries& seg = segments_[s];
      const std::vector<double> x1 = gnnmciForward(w, seg.target.front(), xAgo_[s], seg.time);
      const std::vector<double> y = iago(x1, seg.time.weight);
      for (std::size_t k = 0; k < y.size(); ++k) {
        const double r = y[k] - seg.target[k];
        f += r * r;
      }
    }
    return std::isfinite(f) ? f : std::numeric_limits<double>::infinity();
  }

  double evaluate(std::span<const double> x, std::span<double> components) const override {
    double f = 0.0;
    if (leastSquares_) {
      // Layer-C inputs once per particle: for the least squares and for the network's output.
      GnnmciWeights w;
      w.w11 = std::pow(10.0, x[0]);
      std::vector<GnnmciLayerInputs> in;
      w.w2 = layerCLeastSquares(w.w11, in);
      for (std::size_t s = 0; s < segments_.size(); ++s) {
        const GreySeries& seg = segments_[s];
        const std::vector<double> y =
            iago(gnnmciForward(w, seg.target.front(), in[s], seg.time), seg.time.weight);
        for (std::size_t k = 0; k < y.size(); ++k) f += (y[k] - seg.target[k]) * (y[k] - seg.target[k]);
      }
      if (!std::isfinite(f)) f = std::numeric_limits<double>::infinity();
    } else {
      f = fitness(weights(x));
    }
    components[0] = std::sqrt(f / static_cast<double>(samples_));
    return f;
  }

  std::size_t samples() const { return samples_; }

 private:
  /// For a given w11: the layer-C weights minimising Eq. 2.9 (the output is linear in them).
  std::vector<double> layerCLeastSquares(double w11, std::vector<GnnmciLayerInputs>& inputs) const {
    const auto cols = static_cast<Eigen::Index>(m_ + 1);
    Eigen::MatrixXd a(static_cast<Eigen::Index>(samples_), cols);
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(samples_));
    Eigen::Index row = 0;
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const GreySeries& seg = segments_[s];
      const std::size_t n = seg.time.size();
      inputs.push_back(gnnmciLayerInputs(w11, xAgo_[s], seg.time));
      const GnnmciLayerInputs& in = inputs.back();
      for (std::size_t j = 0; j <= m_; ++j) {
        const std::vector<double> col = iago(j < m_ ? in.inputs[j] : in.unit, seg.time.weight);
        for (std::size_t k = 0; k < n; ++k)
          a(row + static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = col[k];
      }
      // The initial-condition path (w21, theta) is fixed by x_1^(1)(1): move it to the right-hand side.
      std::vector<double> ic(n, 0.0);
      const double x11 = seg.target.front();
      if (x11 != 0.0) {
        for (std::size_t k = 0; k < n; ++k) ic[k] = x11 * std::exp(-w11 * seg.time.tau[k]);
      }
      const std::vector<double> icRestored = iago(ic, seg.time.weight);
      for (std::size_t k = 0; k < n; ++k)
        rhs(row + static_cast<Eigen::Index>(k)) = seg.target[k] - icRestored[k];
      row += static_cast<Eigen::Index>(n);
    }
    // Equilibrated columns so that the rank decision is about dependence, not scale.
    Eigen::VectorXd scale(cols);
    for (Eigen::Index c = 0; c < cols; ++c) {
      const double norm = a.col(c).norm();
      scale(c) = norm > 0.0 ? 1.0 / norm : 1.0;
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a * scale.asDiagonal());
    const Eigen::VectorXd sol = scale.asDiagonal() * qr.solve(rhs);
    std::vector<double> w2(m_ + 1);
    for (std::size_t j = 0; j <= m_; ++j) {
      const double v = sol(static_cast<Eigen::Index>(j));
      w2[j] = std::isfinite(v) ? v : 0.0;
    }
    return w2;
  }

  const std::vector<GreySeries>& segments_;
  bool leastSquares_;
  std::vector<std::vector<std::vector<double>>> xAgo_;
  std::size_t m_ = 0, samples_ = 0;
  double rangeY_ = 1.0;
  std::vector<double> rangeX_;
  double lower0_ = -3.0, upper0_ = 0.0, gain_ = 5.0;
};

}  // namespace

GnnmciTraining trainGnnmci(const std::vector<GreySeries>& segments, const GnnmciOptions& o,
                           Observer* observer) {
  requireValid(o, "GNNMCI options");
  if (segments.empty()) throw std::invalid_argument("trainGnnmci: no data");
  const GnnmciProblem problem(segments, o);
  optim::Pso::Options po = optim::Pso::Options::abdulshahed2016();
  po.swarmSize = o.particles;
  po.c1 = o.c1;
  po.c2 = o.c2;
  po.inertiaStart = o.inertiaStart;
  po.inertiaEnd = o.inertiaEnd;
  po.common.seed = o.seed;
  po.common.keepTrace = o.keepTrace;
  po.common.maxEvaluations = static_cast<long>(o.particles) * (o.iterations + 1);
  GnnmciTraining t;
  bool first = true;
  FunctionObserver relay([&](const IterationSummary& s) {
    if (first) {
      t.firstFitness = s.best;
      first = false;
    }
    return observer ? observer->onIteration(s) : ObserverDecision::Continue;
  });
  optim::Result r = optim::Pso(po).optimise(problem, &relay);
  t.weights = problem.weights(r.bestX);
  t.fitness = r.bestObjective;
  t.samples = problem.samples();
  for (std::size_t i = 0; i < problem.dimension(); ++i) {
    t.lowerX.push_back(problem.lower(i));
    t.upperX.push_back(problem.upper(i));
  }
  t.run = std::move(r.run);
  return t;
}

}  // namespace metrofit::thermal
