#include "core/diagnose/linear_evidence.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

namespace metrofit::diagnose {
namespace {

constexpr double kRankTolerance = 1e-9;
constexpr double kAbsorbedFraction = 1e-6;

/// Orthonormal basis of span(A) by SVD of the column-normalised matrix (zero columns dropped).
Eigen::MatrixXd orthonormalBasis(const Eigen::MatrixXd& A) {
  if (A.cols() == 0 || A.rows() == 0) return Eigen::MatrixXd(A.rows(), 0);
  Eigen::MatrixXd scaled = A;
  for (Eigen::Index j = 0; j < scaled.cols(); ++j) {
    const double norm = scaled.col(j).norm();
    if (norm > 0.0) scaled.col(j) /= norm;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinU);
  const Eigen::VectorXd& s = svd.singularValues();
  const double largest = s.size() > 0 ? s(0) : 0.0;
  Eigen::Index rank = 0;
  while (rank < s.size() && largest > 0.0 && s(rank) > kRankTolerance * largest) ++rank;
  return svd.matrixU().leftCols(rank);
}

}  // namespace

ColumnSpace::ColumnSpace(const Eigen::MatrixXd& X) : rows_(X.rows()), basis_(orthonormalBasis(X)) {}

Eigen::VectorXd ColumnSpace::residual(const Eigen::VectorXd& v) const {
  if (basis_.cols() == 0) return v;
  return v - basis_ * (basis_.transpose() * v);
}

Eigen::MatrixXd ColumnSpace::residual(const Eigen::MatrixXd& V) const {
  if (basis_.cols() == 0) return V;
  return V - basis_ * (basis_.transpose() * V);
}

EffectEstimate estimateEffects(const ColumnSpace& declared, const Eigen::VectorXd& y,
                               const Eigen::MatrixXd& Z) {
  EffectEstimate e;
  const Eigen::Index n = y.size();
  const Eigen::Index k = Z.cols();
  const Eigen::VectorXd yp = declared.residual(y);
  e.rank = declared.rank() + static_cast<int>(k);
  e.dof = static_cast<long>(n) - e.rank;
  e.beta = Eigen::VectorXd::Zero(k);
  e.covariance = Eigen::MatrixXd::Zero(k, k);
  if (k == 0) {
    e.residual = yp;
    e.rss = yp.squaredNorm();
    e.rank = declared.rank();
    e.dof = static_cast<long>(n) - e.rank;
    return e;
  }
  const Eigen::MatrixXd Zp = declared.residual(Z);
  for (Eigen::Index j = 0; j < k; ++j) {
    const double full = Z.col(j).norm();
    if (!(full > 0.0) || Zp.col(j).norm() <= kAbsorbedFraction * full) {
      e.identifiable = false;
      e.why = "absorbed by the declared model";
      break;
    }
  }
  if (e.identifiable && orthonormalBasis(Zp).cols() < k) {
    e.identifiable = false;
    e.why = "its parameters are not separable with these data";
  }
  if (e.identifiable && e.dof <= 0) {
    e.identifiable = false;
    e.why = "too few data for the parameters";
  }
  if (!e.identifiable) {
    e.residual = yp;
    e.rss = yp.squaredNorm();
    e.rank = declared.rank();
    e.dof = static_cast<long>(n) - e.rank;
    return e;
  }
  const Eigen::MatrixXd normal = Zp.transpose() * Zp;
  const Eigen::MatrixXd inverse = normal.ldlt().solve(Eigen::MatrixXd::Identity(k, k));
  e.beta = inverse * (Zp.transpose() * yp);
  e.residual = yp - Zp * e.beta;
  e.rss = e.residual.squaredNorm();
  const double sigma2 = e.rss / static_cast<double>(e.dof);
  e.covariance = sigma2 * inverse;
  return e;
}

bool AcceptanceOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(bicThreshold >= 0.0) || !std::isfinite(bicThreshold)) return no("the BIC threshold must be >= 0");
  if (!(minRelativeReduction >= 0.0 && minRelativeReduction < 1.0))
    return no("the minimum relative rmse reduction must be in [0, 1)");
  if (!(minAbsoluteReduction >= 0.0) || !std::isfinite(minAbsoluteReduction))
    return no("the minimum absolute rmse reduction must be >= 0");
  return true;
}

double deltaBic(double rssBefore, double rssAfter, std::size_t n, long dofBefore, int addedParameters,
                double extraPenalty) {
  const double floor = 1e-300;
  const double nn = static_cast<double>(n);
  return static_cast<double>(std::max(dofBefore, 1L)) *
             std::log(std::max(rssAfter, floor) / std::max(rssBefore, floor)) +
         addedParameters * std::log(std::max(nn, 1.0)) + extraPenalty;
}

AcceptanceDecision decideAcceptance(const AcceptanceOptions& options, double rssBefore, double rssAfter,
                                    std::size_t n, long dofBefore, int addedParameters,
                                    const std::string& unit, std::size_t rmseCount, double extraPenalty) {
  AcceptanceDecision d;
  const double nn = static_cast<double>(std::max<std::size_t>(rmseCount > 0 ? rmseCount : n, 1));
  const double rmseBefore = std::sqrt(rssBefore / nn);
  const double rmseAfter = std::sqrt(rssAfter / nn);
  const double reduction = rmseBefore - rmseAfter;
  const double relative = rmseBefore > 0.0 ? reduction / rmseBefore : 0.0;
  const double dbic = deltaBic(rssBefore, rssAfter, n, dofBefore, addedParameters, extraPenalty);
  const bool strong = dbic < -options.bicThreshold;
  const bool relevant = relative >= options.minRelativeReduction &&
                        reduction >= options.minAbsoluteReduction && reduction > 0.0;
  d.accepted = strong && relevant;
  // One template per case (a translation sees whole sentences); the English text as before.
  using A = PhraseArg;
  std::vector<PhraseArg> args = {
      A::fixed(dbic, 1), A::number(options.bicThreshold), A::number(rmseBefore, 4), A::number(rmseAfter, 4),
      A::unit(unit),     A::fixed(100.0 * relative, 1)};
  const char* f = strong ? "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %)"
                         : "dBIC = %1 not below -%2, rmse %3 -> %4 %5 (-%6 %)";
  if (strong && !relevant) {
    if (relative < options.minRelativeReduction) {
      f = "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %, below the relevant %7 %)";
      args.push_back(A::fixed(100.0 * options.minRelativeReduction, 1));
    } else {
      f = "dBIC = %1 < -%2, rmse %3 -> %4 %5 (-%6 %, below the relevant %7 %5)";
      args.push_back(A::number(options.minAbsoluteReduction, 3));
    }
  }
  d.reasonParts = {Phrase(f, std::move(args))};
  d.reason = english(d.reasonParts);
  return d;
}

double rootMeanSquare(const Eigen::VectorXd& v) {
  return v.size() == 0 ? 0.0 : std::sqrt(v.squaredNorm() / static_cast<double>(v.size()));
}

}  // namespace metrofit::diagnose
