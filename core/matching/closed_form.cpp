#include "core/matching/closed_form.h"

#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/matching/fit_input.h"
#include "core/optim/least_squares.h"

namespace metrofit::matching {
namespace {

struct Moments {
  std::size_t n = 0;
  Eigen::Vector3d qMean = Eigen::Vector3d::Zero(), pMean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();  ///< sum (p - mean p)(q - mean q)^T
  double sqq = 0.0;
};

Moments moments(const ProbePointSet& set) {
  Moments m;
  m.n = set.points.size();
  for (const auto& p : set.points) {
    m.qMean += p.nominal;
    m.pMean += p.measured;
  }
  m.qMean /= static_cast<double>(m.n);
  m.pMean /= static_cast<double>(m.n);
  for (const auto& p : set.points) {
    const Eigen::Vector3d qc = p.nominal - m.qMean;
    m.K.noalias() += (p.measured - m.pMean) * qc.transpose();
    m.sqq += qc.squaredNorm();
  }
  return m;
}

double sumSquares(const ProbePointSet& set, const Pose& pose) {
  double ss = 0.0;
  for (const auto& p : set.points) ss += (p.measured - pose.apply(p.nominal)).squaredNorm();
  return ss;
}

using Params = PoseParams;

}  // namespace

bool ClosedFormOptions::isValid(std::string* why) const {
  if (maxIterations < 1) {
    if (why) *why = "the Gauss-Newton iteration limit must be >= 1";
    return false;
  }
  return locks.isValid(why);
}

Pose umeyamaFit(const ProbePointSet& set, bool allowScale) {
  if (set.points.empty())
    throw ValidationError(ErrorContext{set.source, 0, 0, {}}, "has no probe points to fit");
  const Moments m = moments(set);
  const double nd = static_cast<double>(m.n);
  const Eigen::Matrix3d sigma = m.K / nd;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d S = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2) = -1.0;
  Pose pose;
  pose.rotation = svd.matrixU() * S.asDiagonal() * svd.matrixV().transpose();
  if (allowScale && m.sqq > 0.0) pose.scale = svd.singularValues().dot(S) / (m.sqq / nd);
  pose.translation = m.pMean - pose.scale * (pose.rotation * m.qMean);
  return pose;
}

ClosedFormResult closedFormFit(const ProbePointSet& set, const ClosedFormOptions& o) {
  requireValid(o, "closed-form options");
  ClosedFormResult res;
  const Pose free = umeyamaFit(set, o.allowScale);
  if (!o.locks.any()) {
    res.pose = free;
    res.sumSquares = sumSquares(set, free);
    res.message = "closed-form SVD solution (Umeyama)";
    return res;
  }
  res.constrained = true;

  // Free parameter indices: 0-2 angles, 3-5 translation, 6 scale.
  std::vector<int> freeIdx;
  for (int j = 0; j < kDofCount; ++j)
    if (!o.locks.locked[j]) freeIdx.push_back(j);
  if (o.allowScale) freeIdx.push_back(6);
  const auto k = static_cast<Eigen::Index>(freeIdx.size());

  Params x;
  x.angles = eulerZyx(free.rotation);
  for (int j = 0; j < 3; ++j)
    if (o.locks.locked[j]) x.angles(j) = o.locks.value[j] * kRadPerDeg;
  {
    const CentredPoints c = centredPoints(set);
    const Pose start = optimalTranslationScale(c, rotationZyx(x.angles), o.locks, o.allowScale);
    x.t = start.translation;
    x.s = start.scale;
  }
  if (k == 0) {
    res.pose = x.pose();
    res.sumSquares = sumSquares(set, res.pose);
    res.message = "every parameter is locked";
    return res;
  }

  // Gauss-Newton with the Levenberg-Marquardt safeguard of core/optim/least_squares.h: a damping of
  // 1e-9 (relative to diag J^T J) is Gauss-Newton in all but name until a step fails; the tolerances
  // stop at the rounding level.
  auto paramsOf = [&](const Eigen::VectorXd& v) {
    Params p = x;
    for (Eigen::Index c = 0; c < k; ++c) {
      const int j = freeIdx[static_cast<std::size_t>(c)];
      if (j < 3)
        p.angles(j) = v(c);
      else if (j < 6)
        p.t(j - 3) = v(c);
      else
        p.s = v(c);
    }
    return p;
  };
  const auto rows = static_cast<Eigen::Index>(3 * set.points.size());
  const optim::Residual f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    const Params q = paramsOf(v);
    const Eigen::Matrix3d R = rotationZyx(q.angles);
    const auto dR = rotationZyxDerivatives(q.angles);
    r.resize(rows);
    if (J) J->resize(rows, k);
    Eigen::Index i = 0;
    for (const auto& p : set.points) {
      const Eigen::Vector3d Rq = R * p.nominal;
      r.segment<3>(i) = p.measured - q.s * Rq - q.t;
      if (J) {
        for (Eigen::Index c = 0; c < k; ++c) {
          const int j = freeIdx[static_cast<std::size_t>(c)];
          if (j < 3)
            J->block<3, 1>(i, c) = -q.s * (dR[static_cast<std::size_t>(j)] * p.nominal);
          else if (j < 6)
            J->block<3, 1>(i, c) = -Eigen::Vector3d::Unit(j - 3);
          else
            J->block<3, 1>(i, c) = -Rq;
        }
      }
      i += 3;
    }
  };
  optim::LeastSquaresOptions lo;
  lo.maxIterations = o.maxIterations;
  lo.initialDamping = 1e-9;
  lo.costTolerance = 0.0;  // the cost is flat at the rounding level before the steps are
  lo.stepTolerance = 1e-15;
  Eigen::VectorXd v(k);
  for (Eigen::Index c = 0; c < k; ++c) {
    const int j = freeIdx[static_cast<std::size_t>(c)];
    v(c) = j < 3 ? x.angles(j) : j < 6 ? x.t(j - 3) : x.s;
  }
  const optim::LeastSquaresSummary sum = optim::solveLeastSquares(f, v, lo);
  x = paramsOf(v);
  res.iterations = static_cast<int>(sum.iterations);
  res.termination = optim::toTermination(sum.termination);
  if (res.termination == Termination::Converged)
    res.message = "Gauss-Newton converged after " + std::to_string(res.iterations) + " iterations";
  else if (res.termination == Termination::MaxIterations)
    res.message = "Gauss-Newton iteration limit reached";
  else
    res.message = "Gauss-Newton failed: " + sum.message;
  res.pose = x.pose();
  res.sumSquares = sumSquares(set, res.pose);
  return res;
}

}  // namespace metrofit::matching
