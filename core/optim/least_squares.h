#pragma once
// The one nonlinear least-squares solver of Metrofit: Levenberg-Marquardt on
//   minimise  C(x) = 1/2 |r(x)|^2,   r: R^n -> R^m,  J = dr/dx (m x n).
//
// Method (K. Levenberg 1944; D. W. Marquardt, "An algorithm for least-squares estimation of
// nonlinear parameters", SIAM J. Appl. Math. 11, 1963). Every iteration evaluates J at the current x
// and tries damped Gauss-Newton steps
//   (J^T J + lambda D^T D) delta = -J^T r
// until one lowers C; lambda grows after every rejected trial and shrinks after the accepted one.
//  * Scaling D: Marquardt's (D_jj^2 = the largest (J^T J)_jj seen so far, J. J. More, "The
//    Levenberg-Marquardt algorithm: implementation and theory", 1978), or D = I (Levenberg's).
//  * Damping update: Nielsen's (H. B. Nielsen 1999; Madsen, Nielsen, Tingleff, "Methods for
//    non-linear least squares problems", 2004, Eq. 3.15): after an accepted step with gain ratio
//    rho = actual / predicted decrease, lambda *= max(1/3, 1 - (2 rho - 1)^3), nu = 2; after a
//    rejected trial lambda *= nu, nu *= 2. Or the classic multiplicative one (Marquardt 1963; the
//    trainlm of MATLAB's neural network toolbox): lambda *= dampingDecrease / dampingIncrease.
//  * Linear solve: Householder QR of [J; sqrt(lambda) D] delta = [-r; 0] (no squared condition
//    number), or LDLT of the normal equations (cheaper for many rows, e.g. network training).
//
// Decision: one hand-written implementation here rather than Eigen's unsupported
// LevenbergMarquardt module. Eigen's module is MINPACK's lmder (More's trust region); it cannot
// express what the callers need and have tested: the observer called after every iteration (progress,
// live charts, cancellation through CancelToken), the multiplicative damping schedule of trainlm
// (the MLP's options mu0 / muDecrease / muIncrease / muMax, whose trained weights must not change),
// Nielsen's update, a window cost-stall test, a target cost, and a clean failure on NaN residuals
// (MINPACK propagates them). The implementation is the one the callers had copied, written once.
//
// Stopping (checked in this order; see LeastSquaresTermination):
//   start: C(x0) not finite -> Failed; C(x0) <= targetCost -> TargetCost (no iteration).
//   each iteration, after J: |J^T r|_2 <= gradientTolerance -> GradientTolerance (no observer call).
//   after the trials:  no trial lowered C before lambda > maxDamping, or a rejected trial's predicted
//     decrease C - 1/2|r + J delta|^2 is below 4 eps C (a larger lambda only shortens the step) ->
//     DampingLimit (the minimum at the rounding level); C <= targetCost or C == 0 -> TargetCost; |J delta| <=
//     modelStepTolerance or |delta| <= stepTolerance (|x| + stepTolerance) -> StepTolerance; the cost
//     decreased by at most costTolerance C_{k-w} over the last w = costWindow iterations -> CostTolerance (w
//     = 1: the per-step relative decrease test).
//   then the observer; when it says Stop the run is Cancelled (even if it also converged).
//   after maxIterations iterations: MaxIterations.
// A rejected trial whose step is below the step tolerances also ends the run (StepTolerance): the
// cost cannot be lowered by steps that do not change the model.
//
// Degenerate end (degeneracyTolerance > 0): a run that met one of the convergence tests above is
// reported as Degenerate (not converged) when the parameters are not determined at the point it
// stopped: the Jacobian of relative parameter changes, J diag(s) with s_j = |x_j| (1 where x_j = 0),
// has a numerical rank below n (column-pivoting QR, pivots below degeneracyTolerance times the largest
// count as zero). This is the "stationary point at infinity" a far start can run into (NIST StRD
// BoxBOD from start 1: b2 -> 115, where d r / d b2 ~ e^-115 and the fit is a constant): the cost no
// longer changes, every convergence test is met, and the answer is still wrong. Off by default: a
// neural network's or an over-parametrised model's Jacobian is routinely rank deficient at a
// perfectly usable fit.
//
// Non-finite values: a trial with a non-finite cost or step is rejected like an uphill one; a
// non-finite start cost or Jacobian is Failed with a message. x only ever takes finite accepted
// values, and the summary never holds NaN (a non-finite cost is reported as +infinity).
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>

#include "core/common/run.h"

namespace metrofit::optim {

/// The residual callback: r = r(x) (any fixed size m >= 1) and, when J is not null, the Jacobian
/// J = dr/dx (m x x.size()). Not called with J when LeastSquaresOptions::jacobian is ForwardDifference.
/// Must not throw for finite x; a point outside its domain gives non-finite residuals.
using Residual = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J)>;

struct LeastSquaresOptions {
  enum class Damping { Nielsen, Multiplicative };
  enum class Scaling { Marquardt, Identity };
  enum class LinearSolver { Qr, NormalEquations };
  enum class Jacobian { Analytic, ForwardDifference };

  long maxIterations = 100;      ///< iterations (Jacobian evaluations), >= 1
  double initialDamping = 1e-3;  ///< lambda_0, > 0 (relative to D^T D)
  double maxDamping = 1e20;      ///< no step lowers the cost once lambda exceeds this, > initialDamping
  Damping damping = Damping::Nielsen;
  double dampingDecrease = 0.1;   ///< Multiplicative: lambda factor after an accepted step, (0, 1)
  double dampingIncrease = 10.0;  ///< Multiplicative: lambda factor after a rejected trial, > 1
  Scaling scaling = Scaling::Marquardt;
  LinearSolver linearSolver = LinearSolver::Qr;
  Jacobian jacobian = Jacobian::Analytic;
  /// ForwardDifference: the step of x_j is differenceStep * max(|x_j|, 1), > 0.
  double differenceStep = 1e-7;

  double costTolerance = 1e-12;     ///< relative cost decrease over costWindow iterations, [0, 1)
  long costWindow = 1;              ///< >= 1
  double stepTolerance = 0.0;       ///< relative parameter step, >= 0 (0: off)
  double modelStepTolerance = 0.0;  ///< |J delta| (the change of the modelled residuals), >= 0 (0: off)
  double gradientTolerance = 0.0;   ///< |J^T r|_2, >= 0 (0: off)
  double targetCost = 0.0;          ///< stop once C <= targetCost, >= 0 (0: only an exact fit)
  /// Converged runs whose relative-change Jacobian has numerical rank < n are Degenerate, [0, 1)
  /// (0: off; see the header comment).
  double degeneracyTolerance = 0.0;

  bool isValid(std::string* why) const;
};

enum class LeastSquaresTermination {
  CostTolerance,      ///< the cost stopped decreasing (costTolerance over costWindow)
  StepTolerance,      ///< the step fell below stepTolerance / modelStepTolerance
  GradientTolerance,  ///< |J^T r| <= gradientTolerance
  TargetCost,         ///< C <= targetCost (or an exact fit)
  DampingLimit,       ///< no damped step lowers the cost (a minimum at the rounding level)
  MaxIterations,      ///< maxIterations iterations done
  Cancelled,          ///< the observer said Stop
  Failed,             ///< non-finite start cost or Jacobian, or residuals of size 0 / changing size
  Degenerate,         ///< a convergence test was met where the parameters are not determined
};

const char* toString(LeastSquaresTermination t);

struct LeastSquaresSummary {
  LeastSquaresTermination termination = LeastSquaresTermination::MaxIterations;
  bool converged = false;        ///< one of the first five terminations
  std::string message;           ///< why, in words
  long iterations = 0;           ///< completed iterations (observer calls)
  long residualEvaluations = 0;  ///< calls of the residual without J (trials, finite differences)
  long jacobianEvaluations = 0;  ///< calls with J (or finite-difference Jacobians)
  double initialCost = 0.0;      ///< C(x0) (+inf when not finite)
  double finalCost = 0.0;        ///< C(x) at the returned x (+inf when not finite)
  double damping = 0.0;          ///< lambda at the end
  Eigen::VectorXd residuals;     ///< r at the returned x
  Eigen::MatrixXd jacobian;      ///< J at the returned x (empty when Failed before any J)
};

/// Metrofit's Termination for a least-squares termination: the five converged ones -> Converged,
/// MaxIterations, Cancelled, Failed; Degenerate -> Failed.
Termination toTermination(LeastSquaresTermination t);

/// Minimises 1/2 |f(x)|^2 from x (overwritten with the solution; unchanged when the start fails).
/// Throws OptionsError for invalid options or an empty x. The observer sees one IterationSummary per
/// iteration: iteration, evaluations (residual + Jacobian evaluations), best = C(x), components
/// {"cost", C}, {"damping", lambda}, bestX = x, progress = (iteration + 1) / maxIterations.
LeastSquaresSummary solveLeastSquares(const Residual& f, Eigen::VectorXd& x,
                                      const LeastSquaresOptions& options = {}, Observer* observer = nullptr);

}  // namespace metrofit::optim
