#pragma once
// The statistics behind the closed loop of the linear(ised) domains (setup, matching): a declared
// model whose design X may be rank deficient, candidate effects as extra columns Z, and the
// evidence that decides whether an effect is accepted.
//
// Fit of y on [X Z] (least squares). X is reduced to an orthonormal basis U of its column space by
// a rank-revealing SVD (columns scaled to unit norm first, rank = number of singular values above
// 1e-9 times the largest), so a rank-deficient declared model (e.g. a work offset and a tool offset
// that act on the same features) is fitted by its minimum-norm solution without harm: only its
// column space matters for the residual. The effect coefficients follow from the
// Frisch-Waugh-Lovell theorem: with the projector P = I - U U^T,
//   Zp = P Z,   yp = P y,   beta = (Zp^T Zp)^-1 Zp^T yp,   r = yp - Zp beta,   RSS = |r|^2,
//   sigma^2 = RSS / (n - rank(X) - k),   Cov(beta) = sigma^2 (Zp^T Zp)^-1.
// An effect is identifiable only when every column of Zp keeps more than 1e-6 of its norm (it is
// not absorbed by the declared model) and Zp has full column rank (same SVD test).
//
// Acceptance ("an information criterion with a conservative threshold" and "a
// practically relevant amount"): the Bayesian information criterion of a Gaussian linear model,
//   BIC = n ln(RSS / n) + p ln n,     dBIC = n ln(RSS_after / RSS_before) + k ln n,
// with k the parameters the effect adds, except that the data term uses the residual degrees of
// freedom of the model before, nu = n - rank, instead of n:
//   dBIC = nu ln(RSS_after / RSS_before) + k ln n.
// For large n the two agree; for small n (40 probe points, 6 posture parameters) n ln(RSS0/RSS1)
// overstates the evidence (about (n/nu) times the nested F statistic) and the false-positive rate
// doubled in the detection study. Accepted when dBIC < -threshold (default 10, "very strong"
// evidence on the Kass & Raftery 1995 scale; under the null hypothesis nu ln(RSS0/RSS1) is about
// chi-square with k degrees of freedom, so the false-positive rate per candidate is about
// P(chi2_k > k ln n + 10), 1e-4 for k = 1, n = 100) AND the fit rmse drops by at least
// minRelativeReduction of its value and by at least minAbsoluteReduction (data units).
#include <cstddef>
#include <string>

#include <Eigen/Core>

#include "core/common/text.h"

namespace metrofit::diagnose {

/// The column space of a declared-model design matrix (see above).
class ColumnSpace {
 public:
  /// `X` may have zero columns (then the space is {0}).
  explicit ColumnSpace(const Eigen::MatrixXd& X);
  int rank() const { return static_cast<int>(basis_.cols()); }
  Eigen::Index rows() const { return rows_; }
  /// v - U U^T v (the part of v the declared model cannot explain).
  Eigen::VectorXd residual(const Eigen::VectorXd& v) const;
  Eigen::MatrixXd residual(const Eigen::MatrixXd& V) const;

 private:
  Eigen::Index rows_ = 0;
  Eigen::MatrixXd basis_;  ///< U, orthonormal columns
};

/// Least squares of y on [X Z] (X as its ColumnSpace).
struct EffectEstimate {
  bool identifiable = true;    ///< false: a column of Z is absorbed by X or Z is rank deficient
  std::string why;             ///< why not identifiable
  Eigen::VectorXd beta;        ///< effect coefficients (size k)
  Eigen::MatrixXd covariance;  ///< k x k
  Eigen::VectorXd residual;    ///< y - fitted
  double rss = 0.0;
  int rank = 0;  ///< rank(X) + k
  long dof = 0;  ///< n - rank
};
EffectEstimate estimateEffects(const ColumnSpace& declared, const Eigen::VectorXd& y,
                               const Eigen::MatrixXd& Z);

/// Acceptance thresholds (see above).
struct AcceptanceOptions {
  double bicThreshold = 10.0;          ///< accept only when dBIC < -bicThreshold
  double minRelativeReduction = 0.02;  ///< rmse must drop by at least this fraction of its value
  double minAbsoluteReduction = 0.0;   ///< and by at least this much (data units)

  bool isValid(std::string* why) const;
};

/// nu ln(rssAfter / rssBefore) + k ln n with nu = dofBefore (both RSS floored at 1e-300).
/// `extraPenalty` is added as it is (a search over shapes, e.g. a generic effect's variable).
double deltaBic(double rssBefore, double rssAfter, std::size_t n, long dofBefore, int addedParameters,
                double extraPenalty = 0.0);

/// The decision and its one-line reason.
struct AcceptanceDecision {
  bool accepted = false;
  std::string reason;   ///< e.g. "dBIC = -53.2 < -10, rmse 0.01 -> 0.0059 mm (-41.3 %)"
  Phrases reasonParts;  ///< reason == english(reasonParts) (core/common/text.h)
};
/// `rmseCount` is the count the rmse is taken over (0: n; e.g. the points when each point gives
/// two or three observations, so that the rmse is that of the residual distances).
AcceptanceDecision decideAcceptance(const AcceptanceOptions& options, double rssBefore, double rssAfter,
                                    std::size_t n, long dofBefore, int addedParameters,
                                    const std::string& unit, std::size_t rmseCount = 0,
                                    double extraPenalty = 0.0);

/// sqrt(mean of squares), 0 for an empty vector.
double rootMeanSquare(const Eigen::VectorXd& v);

}  // namespace metrofit::diagnose
