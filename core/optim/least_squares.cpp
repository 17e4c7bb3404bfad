#include "core/optim/least_squares.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/common/error.h"
#include "core/common/numformat.h"

namespace metrofit::optim {
namespace {

std::string num(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A rejected trial whose model predicts a decrease below this share of the cost ends the run: the
/// cost (a sum of m squares) is not known better than a few units of rounding.
constexpr double kRoundingDecrease = 4.0 * std::numeric_limits<double>::epsilon();

/// 1/2 |r|^2, +inf when not finite.
double halfSquaredNorm(const Eigen::VectorXd& r) {
  const double c = 0.5 * r.squaredNorm();
  return std::isfinite(c) ? c : std::numeric_limits<double>::infinity();
}

}  // namespace

bool LeastSquaresOptions::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  auto nonNegative = [](double v) { return v >= 0.0 && std::isfinite(v); };
  if (maxIterations < 1) return no("maxIterations must be at least 1, got " + std::to_string(maxIterations));
  if (!(initialDamping > 0.0) || !std::isfinite(initialDamping))
    return no("initialDamping must be positive and finite, got " + num(initialDamping));
  if (!(maxDamping > initialDamping) || !std::isfinite(maxDamping))
    return no("maxDamping must be finite and above initialDamping, got " + num(maxDamping));
  if (!(dampingDecrease > 0.0 && dampingDecrease < 1.0))
    return no("dampingDecrease must be in (0, 1), got " + num(dampingDecrease));
  if (!(dampingIncrease > 1.0) || !std::isfinite(dampingIncrease))
    return no("dampingIncrease must be finite and above 1, got " + num(dampingIncrease));
  if (!(differenceStep > 0.0 && differenceStep < 1.0))
    return no("differenceStep must be in (0, 1), got " + num(differenceStep));
  if (!nonNegative(costTolerance))
    return no("costTolerance must be finite and >= 0, got " + num(costTolerance));
  if (costWindow < 1) return no("costWindow must be at least 1, got " + std::to_string(costWindow));
  if (!nonNegative(stepTolerance))
    return no("stepTolerance must be finite and >= 0, got " + num(stepTolerance));
  if (!nonNegative(modelStepTolerance))
    return no("modelStepTolerance must be finite and >= 0, got " + num(modelStepTolerance));
  if (!nonNegative(gradientTolerance))
    return no("gradientTolerance must be finite and >= 0, got " + num(gradientTolerance));
  if (!nonNegative(targetCost)) return no("targetCost must be finite and >= 0, got " + num(targetCost));
  if (!(degeneracyTolerance >= 0.0 && degeneracyTolerance < 1.0))
    return no("degeneracyTolerance must be in [0, 1), got " + num(degeneracyTolerance));
  return true;
}

const char* toString(LeastSquaresTermination t) {
  switch (t) {
    case LeastSquaresTermination::CostTolerance:
      return "cost tolerance";
    case LeastSquaresTermination::StepTolerance:
      return "step tolerance";
    case LeastSquaresTermination::GradientTolerance:
      return "gradient tolerance";
    case LeastSquaresTermination::TargetCost:
      return "target cost";
    case LeastSquaresTermination::DampingLimit:
      return "damping limit";
    case LeastSquaresTermination::MaxIterations:
      return "max iterations";
    case LeastSquaresTermination::Cancelled:
      return "cancelled";
    case LeastSquaresTermination::Failed:
      return "failed";
    case LeastSquaresTermination::Degenerate:
      return "degenerate";
  }
  return "?";
}

Termination toTermination(LeastSquaresTermination t) {
  switch (t) {
    case LeastSquaresTermination::MaxIterations:
      return Termination::MaxIterations;
    case LeastSquaresTermination::Cancelled:
      return Termination::Cancelled;
    case LeastSquaresTermination::Failed:
    case LeastSquaresTermination::Degenerate:
      return Termination::Failed;
    default:
      return Termination::Converged;
  }
}

LeastSquaresSummary solveLeastSquares(const Residual& f, Eigen::VectorXd& x, const LeastSquaresOptions& o,
                                      Observer* observer) {
  requireValid(o, "least-squares options");
  if (x.size() == 0)
    throw OptionsError(ErrorContext{{}, 0, 0, "least-squares start"}, "the start point is empty");
  using T = LeastSquaresTermination;
  LeastSquaresSummary out;
  const Eigen::Index n = x.size();
  auto finish = [&](T t, std::string message) {
    out.termination = t;
    out.converged = toTermination(t) == Termination::Converged;
    out.message = std::move(message);
  };
  if (!x.allFinite()) {
    finish(T::Failed, "the start point is not finite");
    out.initialCost = out.finalCost = std::numeric_limits<double>::infinity();
    return out;
  }

  Eigen::Index m = 0;
  // r and J at p (J by forward differences when asked); false when r changed size.
  auto residualAndJacobian = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd& J) {
    if (o.jacobian == LeastSquaresOptions::Jacobian::Analytic) {
      f(p, r, &J);
      ++out.jacobianEvaluations;
      return;
    }
    f(p, r, nullptr);
    ++out.residualEvaluations;
    J.resize(r.size(), n);
    Eigen::VectorXd xp = p, rp;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double h0 = o.differenceStep * std::max(std::abs(p(j)), 1.0);
      xp(j) = p(j) + h0;
      const double h = xp(j) - p(j);  // the step actually taken
      f(xp, rp, nullptr);
      ++out.residualEvaluations;
      J.col(j) = rp.size() == r.size() ? Eigen::VectorXd((rp - r) / h)
                                       : Eigen::VectorXd::Constant(r.size(), std::nan(""));
      xp(j) = p(j);
    }
    ++out.jacobianEvaluations;
  };
  auto jacobianFailure = [&](const Eigen::VectorXd& r, const Eigen::MatrixXd& J) -> std::string {
    if (r.size() != m)
      return "the residual count changed from " + std::to_string(m) + " to " + std::to_string(r.size());
    if (J.rows() != m || J.cols() != n)
      return "the Jacobian is " + std::to_string(J.rows()) + " x " + std::to_string(J.cols()) +
             ", expected " + std::to_string(m) + " x " + std::to_string(n);
    if (!J.allFinite()) return "the Jacobian is not finite at the current point";
    return {};
  };

  Eigen::VectorXd r, rt;
  Eigen::MatrixXd J;
  residualAndJacobian(x, r, J);
  m = r.size();
  double cost = halfSquaredNorm(r);
  out.initialCost = out.finalCost = cost;
  double lambda = o.initialDamping;
  out.damping = lambda;
  if (m == 0) {
    finish(T::Failed, "the residual vector is empty");
    return out;
  }
  if (!std::isfinite(cost)) {
    finish(T::Failed, "the residuals are not finite at the start point");
    out.residuals = r;
    return out;
  }
  bool haveJ = true;
  if (cost <= o.targetCost) {
    finish(T::TargetCost, "the start point meets the target cost");
    out.residuals = r;
    if (jacobianFailure(r, J).empty()) out.jacobian = J;
    return out;
  }

  using LS = LeastSquaresOptions;
  const bool nielsen = o.damping == LS::Damping::Nielsen;
  const bool marquardt = o.scaling == LS::Scaling::Marquardt;
  const bool qr = o.linearSolver == LS::LinearSolver::Qr;
  double nu = 2.0;
  Eigen::VectorXd D2 = Eigen::VectorXd::Zero(n);  // Marquardt scaling: running max of diag(J^T J)
  std::vector<double> history{cost};              // cost after every iteration, [0] = start
  bool stopped = false;
  for (long it = 0; it < o.maxIterations && !stopped; ++it) {
    if (!haveJ) {
      residualAndJacobian(x, r, J);
      cost = halfSquaredNorm(r);
      haveJ = true;
    }
    if (std::string why = jacobianFailure(r, J); !why.empty() || !std::isfinite(cost)) {
      finish(T::Failed, why.empty() ? "the residuals are not finite at the current point" : why);
      break;
    }
    const Eigen::VectorXd g = J.transpose() * r;
    if (o.gradientTolerance > 0.0 && g.norm() <= o.gradientTolerance) {
      finish(T::GradientTolerance, "gradient |J^T r| below tolerance");
      break;
    }
    if (marquardt) D2 = D2.cwiseMax(J.colwise().squaredNorm().transpose());
    Eigen::MatrixXd JtJ;
    if (!qr) {
      JtJ.setZero(n, n);
      JtJ.selfadjointView<Eigen::Lower>().rankUpdate(J.transpose());
      JtJ = JtJ.selfadjointView<Eigen::Lower>();
    }

    // Damped trials from x until one lowers the cost.
    bool accepted = false, ended = false;
    while (!accepted && !ended) {
      Eigen::VectorXd delta;
      if (qr) {
        Eigen::MatrixXd A(m + n, n);
        A.topRows(m) = J;
        if (marquardt)
          A.bottomRows(n) = (std::sqrt(lambda) * D2.cwiseSqrt()).asDiagonal();
        else
          A.bottomRows(n) = std::sqrt(lambda) * Eigen::MatrixXd::Identity(n, n);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + n);
        rhs.head(m) = -r;
        delta = A.householderQr().solve(rhs);
      } else {
        Eigen::MatrixXd A = JtJ;
        if (marquardt)
          A.diagonal() += lambda * D2;
        else
          A.diagonal().array() += lambda;
        delta = A.ldlt().solve(-g);
      }
      const Eigen::VectorXd jd = J * delta;
      const bool smallStep =
          (o.modelStepTolerance > 0.0 && jd.norm() <= o.modelStepTolerance) ||
          (o.stepTolerance > 0.0 && delta.norm() <= o.stepTolerance * (x.norm() + o.stepTolerance));
      double trialCost = std::numeric_limits<double>::infinity();
      const Eigen::VectorXd xt = x + delta;
      if (delta.allFinite() && xt.allFinite()) {
        f(xt, rt, nullptr);
        ++out.residualEvaluations;
        if (rt.size() != m) {
          finish(T::Failed,
                 "the residual count changed from " + std::to_string(m) + " to " + std::to_string(rt.size()));
          stopped = true;
          break;
        }
        trialCost = halfSquaredNorm(rt);
      }
      const double predicted = cost - 0.5 * (r + jd).squaredNorm();
      if (trialCost < cost) {
        const double decrease = cost - trialCost;
        x = xt;
        std::swap(r, rt);
        cost = trialCost;
        haveJ = false;
        accepted = true;
        if (nielsen) {
          const double rho = predicted > 0.0 ? decrease / predicted : 0.0;
          lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
          nu = 2.0;
        } else {
          lambda *= o.dampingDecrease;
        }
        lambda = std::max(lambda, std::numeric_limits<double>::min());  // never 0: it could not grow again
        history.push_back(cost);
        const auto k = static_cast<long>(history.size()) - 1;
        if (cost <= o.targetCost) {
          finish(T::TargetCost, cost == 0.0 ? "exact fit (zero cost)" : "cost below the target");
          ended = true;
        } else if (smallStep) {
          finish(T::StepTolerance, "step below tolerance");
          ended = true;
        } else if (k >= o.costWindow) {
          const double before = history[static_cast<std::size_t>(k - o.costWindow)];
          if (before - cost <= o.costTolerance * before) {
            finish(T::CostTolerance, "cost decrease below tolerance");
            ended = true;
          }
        }
      } else {
        if (nielsen) {
          lambda *= nu;
          nu *= 2.0;
        } else {
          lambda *= o.dampingIncrease;
        }
        if (smallStep) {
          finish(T::StepTolerance, "no further decrease (step below tolerance)");
          ended = true;
        } else if (predicted <= kRoundingDecrease * cost) {
          // Larger damping only shortens the step: the cost cannot change beyond its rounding.
          finish(T::DampingLimit, "no further decrease (the predicted decrease is at the rounding level)");
          ended = true;
        } else if (lambda > o.maxDamping) {
          finish(T::DampingLimit, "no further decrease (at the rounding level)");
          ended = true;
        }
      }
    }
    if (stopped) break;
    if (!accepted) history.push_back(cost);
    out.damping = lambda;
    out.iterations = it + 1;

    IterationSummary s;
    s.iteration = it;
    s.evaluations = out.residualEvaluations + out.jacobianEvaluations;
    s.best = cost;
    s.components = {{"cost", cost}, {"damping", lambda}};
    s.bestX.assign(x.data(), x.data() + n);
    s.progress = static_cast<double>(it + 1) / static_cast<double>(o.maxIterations);
    if (observer && observer->onIteration(s) == ObserverDecision::Stop) {
      finish(T::Cancelled, "stopped by observer");
      break;
    }
    if (ended) break;
    if (it + 1 == o.maxIterations) finish(T::MaxIterations, "iteration limit reached");
  }

  out.damping = lambda;
  out.finalCost = cost;
  if (!haveJ && out.termination != T::Failed) {
    residualAndJacobian(x, r, J);
    out.finalCost = cost = halfSquaredNorm(r);
  }
  out.residuals = r;
  if (jacobianFailure(r, J).empty()) out.jacobian = J;
  if (out.converged && o.degeneracyTolerance > 0.0 && out.jacobian.size() > 0) {
    const Eigen::VectorXd s = x.cwiseAbs().unaryExpr([](double v) { return v > 0.0 ? v : 1.0; });
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> rel(out.jacobian * s.asDiagonal());
    rel.setThreshold(o.degeneracyTolerance);
    if (rel.rank() < n) {
      finish(T::Degenerate,
             "stopped where the parameters are not determined (the Jacobian of relative changes "
             "has rank " +
                 std::to_string(rel.rank()) + " of " + std::to_string(n) + "): not a solution, " +
                 out.message);
    }
  }
  return out;
}

}  // namespace metrofit::optim
