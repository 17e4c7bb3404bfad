#include "core/matching/closed_form.h"

#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/matching/fit_input.h"

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

  double ss = sumSquares(set, x.pose());
  double lambda = 0.0;
  res.termination = Termination::MaxIterations;
  res.message = "Gauss-Newton iteration limit reached";
  int stalls = 0;
  for (int it = 0; it < o.maxIterations; ++it) {
    res.iterations = it + 1;
    const Eigen::Matrix3d R = rotationZyx(x.angles);
    const auto dR = rotationZyxDerivatives(x.angles);
    Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(k, k);
    Eigen::VectorXd Jtr = Eigen::VectorXd::Zero(k);
    Eigen::Matrix<double, 3, Eigen::Dynamic> J(3, k);
    for (const auto& p : set.points) {
      const Eigen::Vector3d Rq = R * p.nominal;
      const Eigen::Vector3d r = p.measured - x.s * Rq - x.t;
      for (Eigen::Index c = 0; c < k; ++c) {
        const int j = freeIdx[static_cast<std::size_t>(c)];
        if (j < 3)
          J.col(c) = -x.s * (dR[static_cast<std::size_t>(j)] * p.nominal);
        else if (j < 6)
          J.col(c) = -Eigen::Vector3d::Unit(j - 3);
        else
          J.col(c) = -Rq;
      }
      JtJ.noalias() += J.transpose() * J;
      Jtr.noalias() += J.transpose() * r;
    }
    bool accepted = false;
    for (int attempt = 0; attempt < 30 && !accepted; ++attempt) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal();
      const Eigen::VectorXd step = A.ldlt().solve(-Jtr);
      if (!step.allFinite()) {
        lambda = lambda == 0.0 ? 1e-9 : lambda * 10.0;
        continue;
      }
      Params trial = x;
      for (Eigen::Index c = 0; c < k; ++c) {
        const int j = freeIdx[static_cast<std::size_t>(c)];
        if (j < 3)
          trial.angles(j) += step(c);
        else if (j < 6)
          trial.t(j - 3) += step(c);
        else
          trial.s += step(c);
      }
      const double trialSs = sumSquares(set, trial.pose());
      if (trialSs <= ss) {
        const double decrease = ss - trialSs;
        x = trial;
        ss = trialSs;
        accepted = true;
        lambda = lambda > 0.0 ? lambda / 10.0 : 0.0;
        if (step.lpNorm<Eigen::Infinity>() <= 1e-15 * (1.0 + x.t.norm()) || decrease <= 1e-30 + 1e-16 * ss)
          ++stalls;
        else
          stalls = 0;
      } else {
        lambda = lambda == 0.0 ? 1e-9 : lambda * 10.0;
      }
    }
    if (!accepted || stalls >= 2) {
      res.termination = Termination::Converged;
      res.message = "Gauss-Newton converged after " + std::to_string(res.iterations) + " iterations";
      break;
    }
  }
  res.pose = x.pose();
  res.sumSquares = ss;
  return res;
}

}  // namespace metrofit::matching
