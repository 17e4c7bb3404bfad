// metrofit-bench --kinematic. The problem: a simulated circular test (R 100 mm, 360 points per loop,
// CCW then CW = 720 points, the simulator's default machine errors, 0.5 um noise, seed 1); the
// least-squares problem of core/kinematics/identification.h, min over (o_x, o_y, a, b) of
// sum |o + ir(a) x_k + jr(b) y_k - Pmeas_k|^2.
//
// Timed (median of `repeat` runs of 20 identifications each):
//   metrofit        identifyActuatorErrors with its defaults: affine start, analytic Jacobian, LM by
//                   QR, plus the covariance and standard errors
//   metrofit, zero  the same from o = 0, a = b = 0 (affineStart = false)
//   peer            Eigen's unsupported LevenbergMarquardt (the MINPACK port, lmdif-style) on the same
//                   residuals with a forward-difference Jacobian (Eigen::NumericalDiff), from zero,
//                   xtol 1e-10; no standard errors
//   affine          the linearised closed form alone: the 6-parameter affine fit Pmeas = o + M Pr by
//                   ColPivHouseholderQR and a = atan2(M21, M11), b = atan2(-M12, M22) (not the
//                   least-squares optimum of the 4-parameter model, shown for scale)
// The results are compared: the peer must reach the same optimum.
#include "bench_kinematic.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/kinematics/identification.h"
#include "core/sim/circular_sim.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kInner = 20;
constexpr double kDeg = 180.0 / std::numbers::pi;

template <class F>
double medianMs(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < repeat; ++i) {
    const auto a = Clock::now();
    for (int k = 0; k < kInner; ++k) f();
    t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - a).count() / kInner);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

/// The residuals r_k (x and y) of the model for Eigen's LM; x = (o_x, o_y, a rad, b rad).
struct CircularResiduals {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const MeasuredPath* path = nullptr;
  int inputs() const { return 4; }
  int values() const { return static_cast<int>(2 * path->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const double ca = std::cos(x(2)), sa = std::sin(x(2)), cb = std::cos(x(3)), sb = std::sin(x(3));
    for (std::size_t k = 0; k < path->size(); ++k) {
      const Eigen::Vector2d& c = path->command[k];
      const Eigen::Vector2d& m = path->measured[k];
      const auto i = static_cast<Eigen::Index>(2 * k);
      f(i) = x(0) + ca * c.x() - sb * c.y() - m.x();
      f(i + 1) = x(1) + sa * c.x() + cb * c.y() - m.y();
    }
    return 0;
  }
};

struct Fit {
  double ox = 0, oy = 0, aDeg = 0, bDeg = 0;
};

Fit peerFit(const MeasuredPath& path, int* iterations, int* evaluations) {
  CircularResiduals f;
  f.path = &path;
  Eigen::NumericalDiff<CircularResiduals> numeric(f);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<CircularResiduals>> lm(numeric);
  lm.parameters.xtol = 1e-10;
  lm.parameters.ftol = 1e-12;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  lm.minimize(x);
  if (iterations) *iterations = static_cast<int>(lm.iter);
  if (evaluations) *evaluations = static_cast<int>(lm.nfev);
  return {x(0), x(1), x(2) * kDeg, x(3) * kDeg};
}

Fit affineFit(const MeasuredPath& path) {
  const auto n = static_cast<Eigen::Index>(path.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::MatrixXd B(n, 2);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto& c = path.command[static_cast<std::size_t>(k)];
    const auto& m = path.measured[static_cast<std::size_t>(k)];
    A.row(k) << 1.0, c.x(), c.y();
    B.row(k) << m.x(), m.y();
  }
  const Eigen::MatrixXd X = A.colPivHouseholderQr().solve(B);  // rows: o, M column 1, M column 2
  // Pmeas = o + M Pr with M = [X(1,0) X(2,0); X(1,1) X(2,1)].
  return {X(0, 0), X(0, 1), std::atan2(X(1, 1), X(1, 0)) * kDeg, std::atan2(-X(2, 0), X(2, 1)) * kDeg};
}

}  // namespace

nlohmann::json benchKinematic(int repeat) {
  CircularSimOptions o;  // R 100 mm, 360 points per loop, default machine, 0.5 um noise
  o.seed = 1;
  const MeasuredPath path = simulateCircularTest(o);
  IdentifyOptions zero;
  zero.affineStart = false;

  volatile double sink = 0.0;
  IdentifyResult ours = identifyActuatorErrors(path);
  const double oursMs = medianMs(repeat, [&] { sink = identifyActuatorErrors(path).rmseMm; });
  const IdentifyResult oursZero = identifyActuatorErrors(path, zero);
  const double zeroMs = medianMs(repeat, [&] { sink = identifyActuatorErrors(path, zero).rmseMm; });
  int peerIterations = 0, peerEvaluations = 0;
  const Fit peer = peerFit(path, &peerIterations, &peerEvaluations);
  const double peerMs = medianMs(repeat, [&] { sink = peerFit(path, nullptr, nullptr).aDeg; });
  const Fit affine = affineFit(path);
  const double affineMs = medianMs(repeat, [&] { sink = affineFit(path).aDeg; });
  (void)sink;

  const ActuatorErrors2& e = ours.errors;
  const double angleDiff =
      std::max(std::abs(e.xAxisAngleDeg - peer.aDeg), std::abs(e.yAxisAngleDeg - peer.bDeg));
  const double originDiff = std::max(std::abs(e.originMm.x() - peer.ox), std::abs(e.originMm.y() - peer.oy));
  const double affineAngleDiff =
      std::max(std::abs(e.xAxisAngleDeg - affine.aDeg), std::abs(e.yAxisAngleDeg - affine.bDeg));
  const double trueAngleErr = std::max(std::abs(e.xAxisAngleDeg - o.errors.xAxisAngleDeg),
                                       std::abs(e.yAxisAngleDeg - o.errors.yAxisAngleDeg));
  std::printf(
      "kinematic identification, %zu-point circular test (R 100 mm, 0.5 um noise):\n"
      "  metrofit LM (affine start, analytic J, + std errors) %.3f ms (%ld iterations)\n"
      "  metrofit LM from zero                                %.3f ms (%ld iterations)\n"
      "  peer: Eigen unsupported LevenbergMarquardt + NumericalDiff, from zero %.3f ms (%d iterations, %d "
      "residual evaluations)\n"
      "  linearised closed form (affine QR fit only)          %.3f ms\n"
      "  ratio metrofit/peer = %.2f (both from zero: %.2f); same optimum: |angle diff| %.2g deg, |origin "
      "diff| %.2g mm; affine vs "
      "LM "
      "angle %.2g deg; error vs the simulated truth %.2g deg\n",
      path.size(), oursMs, ours.run.iterations, zeroMs, oursZero.run.iterations, peerMs, peerIterations,
      peerEvaluations, affineMs, oursMs / peerMs, zeroMs / peerMs, angleDiff, originDiff, affineAngleDiff,
      trueAngleErr);
  return {{"points", path.size()},
          {"metrofit_ms", oursMs},
          {"metrofit_iterations", ours.run.iterations},
          {"metrofit_zero_start_ms", zeroMs},
          {"peer", "Eigen unsupported LevenbergMarquardt + NumericalDiff (from zero)"},
          {"peer_ms", peerMs},
          {"peer_iterations", peerIterations},
          {"ratio", oursMs / peerMs},
          {"ratio_zero_start", zeroMs / peerMs},
          {"affine_ms", affineMs},
          {"max_angle_diff_deg", angleDiff},
          {"max_origin_diff_mm", originDiff}};
}

}  // namespace metrofit::bench
