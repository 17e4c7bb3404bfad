#pragma once
// The least-squares solve behind every regression thermal model (linear, lag, dlag of
// lag_regression.h) and their blocked cross-validation:
//   min_b |X b - y|_2
// by column-pivoting Householder QR (Eigen::ColPivHouseholderQR) on equilibrated columns (each column
// scaled to unit norm, so rank decisions are about dependence, not units; no normal equations, so the
// condition number is not squared). A column that depends on the others within the rank threshold
// (1e-10 relative, on the scaled columns) gets 0.
// Validated on the NIST StRD linear problems (Filip, Pontius, Wampler 1-4, certified values):
// tests/core/thermal/nist_strd_lls_test.cpp.
#include <Eigen/Core>

namespace metrofit::thermal {

/// Throws std::invalid_argument for fewer rows than columns.
Eigen::VectorXd linearLeastSquares(const Eigen::MatrixXd& x, const Eigen::VectorXd& y);

}  // namespace metrofit::thermal
