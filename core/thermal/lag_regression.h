#pragma once
// Regression thermal models of the kind thermal engineers fit on real logs, next to
// the paper's GNNMCI(1,N), GMC(1,N) and MLP (thermal_model.h):
//
//   linear  y(k) - y(1) = c + sum_j b_j (x_j(k) - x_j(1))                       static regression
//   lag     y(k) - y(1) = c + sum_j b_j (L_tau_j[x_j](k) - x_j(1))              first-order lag per
//                                                                               sensor (transfer function)
//   dlag    y(k) - y(1) = c + sum_j (a_j (x_j(k) - x_j(1)) + b_j (L_tau_j[x_j](k) - x_j(1)))
//                                                                               distributed lag: the
//                                                                               sensor now and lagged
// L_tau: the first-order lag (exact for an input held over each step, any spacing; the same filter
// as the closed loop's `lag` effect, core/sim/effects_thermal.h):
//   s(1) = x(1),   s(k) = s(k-1) + (1 - exp(-(t_k - t_{k-1}) / tau)) (x(k) - s(k-1));   tau = 0: s = x.
// Physically: a sensor lags behind the structure's mean temperature (or the structure lags behind
// the heat source the sensor sees); `lag` lets each sensor have its own time constant, `dlag` lets
// the displacement follow a sensor with a lead (a_j and b_j of opposite sign: the displacement
// leads the temperature) or a second slower part.
//
// Fitting: the coefficients by least squares (column-pivoting QR on equilibrated columns, Eigen).
// The time constants tau_j from a grid (kLagGridMin; 0 = no lag for `lag`) by blocked
// cross-validation on the fitting rows only: the rows are cut into K contiguous blocks, each block
// is predicted by the regression fitted on the others, the score is the RMSE over all blocks. The
// filtered inputs of a block come from the inputs only (the filter is causal and never reads the
// target), so no target value of a block decides its own prediction. Coordinate search: starting
// from no lag (`lag`) or the median grid value (`dlag`), each sensor's tau in turn is set to the grid
// value with the lowest score, two sweeps. The same blocked cross-validation scores the candidates
// of `--model auto` (thermal_model.h).
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace metrofit::thermal {

/// The tau grid [min]: spindle time constants are 10-60 min; 0 is "no lag".
inline constexpr double kLagGridMin[] = {0.0, 2.0, 5.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 90.0, 120.0};
/// Blocks of the blocked cross-validation.
inline constexpr int kCvFolds = 5;

/// First-order lag of x sampled at tMin with time constant tau (min); tau <= 0 returns x.
std::vector<double> firstOrderLagMin(std::span<const double> x, std::span<const double> tMin, double tauMin);

/// One regressor: input `input` (index into the model's inputs) through L_tau (tau 0: unfiltered).
struct LagTerm {
  std::size_t input = 0;
  double tauMin = 0.0;
  bool operator==(const LagTerm&) const = default;
};

/// A fitted regression model: c + sum_t coef_t (L_tau_t[x_input_t] - x_input_t(1)).
struct LagRegression {
  std::vector<LagTerm> terms;
  double intercept = 0.0;
  std::vector<double> coef;  ///< one per term
};

/// A log's part the regression sees: time, the inputs [input][row] and (for fitting) the target,
/// all as given (the regression works on changes since the first row itself).
struct LagData {
  std::span<const double> timeMin;
  std::vector<std::span<const double>> inputs;
  std::span<const double> target;  ///< may be empty for prediction
};

/// The regressor columns of `terms` on one log (changes since its first row).
std::vector<std::vector<double>> lagColumns(const std::vector<LagTerm>& terms, const LagData& d);

/// Least squares on every row of several logs (each log's columns from its own first row). Throws
/// std::invalid_argument when there are fewer rows than coefficients.
LagRegression fitLagTerms(const std::vector<LagTerm>& terms, const std::vector<LagData>& logs);

/// The predicted change of the target since the log's first row, one per row.
std::vector<double> predictLag(const LagRegression& r, const LagData& d);

/// Blocked cross-validation RMSE of a term set over the concatenated rows of `logs` (kCvFolds blocks
/// of contiguous rows; each log's columns from its own first row).
double blockedCvRmse(const std::vector<LagTerm>& terms, const std::vector<LagData>& logs,
                     int folds = kCvFolds);

enum class LagForm { Static, Lag, DistributedLag };

/// Fits a regression model of `form` (taus by blocked cross-validation, see above). `cvRmse`
/// receives the cross-validation score of the chosen terms when not null.
LagRegression fitLagModel(LagForm form, std::size_t inputs, const std::vector<LagData>& logs,
                          double* cvRmse = nullptr);

}  // namespace metrofit::thermal
