#pragma once
// Grey system operators and the GMC(1,N) grey model of the thermal-error paper (Abdulshahed 2016, grey neural
// network thermal model: Abdulshahed, Longstaff, Fletcher, Potdar, "Thermal error modelling of a gantry-type
// 5-axis machine tool using a Grey Neural Network Model", J. Manuf. Syst. 41, 2016), after Tien (2012).
//
// ---- 1-AGO and IAGO (Appendix A, Eq. A.1-A.3) ------------------------------------------------
//   x^(1)(1) = x^(0)(1),   x^(1)(k) = x^(1)(k-1) + x^(0)(k)          (A.2, accumulation)
//   x^(0)(1) = x^(1)(1),   x^(0)(k) = x^(1)(k) - x^(1)(k-1)          (A.3, inverse)
// The paper assumes equally spaced samples. Thermal logs may be unequally spaced
// (docs/file-formats.md#thermal-log), so the accumulation here is the weighted one that is exact for equal
// steps and consistent with the model's continuous time otherwise: with a time unit h (the mean step of the
// fitting data, kept with a fitted model so that prediction on a log sampled differently uses the same unit),
//   h_1 = 1,  h_k = (t_k - t_{k-1}) / h,   x^(1)(k) = x^(1)(k-1) + h_k x^(0)(k),
//   x^(0)(k) = (x^(1)(k) - x^(1)(k-1)) / h_k,
// i.e. x^(1) is the running integral of x^(0) in units of h (rectangle rule). On equal steps h_k = 1
// and this is exactly Eq. A.2/A.3. The model's "k" becomes the scaled time tau_k = (t_k - t_1) / h.
//
// ---- GMC(1,N) (Eq. 2.1-2.2) --------------------------------------------------------------------
// Eq. 2.1, the grey differential equation on the 1-AGO series (x_1: target, x_2..x_N: inputs):
//   dX_1^(1)/dt + b_1 X_1^(1) = b_2 X_2^(1) + ... + b_N X_N^(1) + u
// b_1: development coefficient (1 / time unit), b_j: driving coefficients, u: grey control parameter.
// Least squares (the paper's "traditional" calibration, Section 4.4; Tien 2012): integrating Eq. 2.1
// over [t_{k-1}, t_k] with the trapezoidal background values z(k) = (X(k) + X(k-1)) / 2 and dividing
// by h_k gives, for k = 2..n,
//   x_1^(0)(k) = -b_1 z_1(k) + sum_j b_j z_j(k) + u
// solved for (b_1, b_2..b_N, u) by column-pivoting Householder QR (Eigen) over all rows of all
// fitting segments (several segments: the modular models of Section 4.3, each from its own start).
// Eq. 2.2, the time response (the convolution integral, midpoint exponential and trapezoidal f):
//   x^_1^(1)(k+1) = x_1^(1)(1) e^{-b_1 k} + u(t-1) sum_{tau=1}^{k} e^{-b_1 (k - tau + 1/2)} (f(tau) +
//   f(tau-1)) / 2 f(tau) = sum_{j=2}^{N} b_j X_j^(1)(tau) + u
// Reading: the sum is over the k intervals between the k+1 samples, so f(tau) is indexed from 0 (the
// first sample) in it, as in Tien's original GMC(1,N) where x^(1)(k) uses tau = 2..k; u(t-1) is the
// unit step (the sum is empty at the first sample). On unequal steps interval i (from t_{i-1} to t_i)
// contributes e^{-b_1 (tau_k - (tau_{i-1} + tau_i) / 2)} h_i (f(i) + f(i-1)) / 2. It is evaluated by
// the equivalent O(n) recursion S(k) = e^{-b_1 h_k} S(k-1) + e^{-b_1 h_k / 2} h_k (f(k) + f(k-1)) / 2.
// The model output is the IAGO of the time response: x^_1^(0) = IAGO(x^_1^(1)).
// Physically (differentiate Eq. 2.1): the displacement is a first-order lag (time constant 1 / b_1)
// of sum_j (b_j / b_1) x_j^(0) plus a decaying start term — a lag model of the thermal error.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace metrofit::thermal {

/// Scaled time of a grey model: tau_k = (t_k - t_1) / unit, weights h_k (h_1 = 1).
struct GreyTime {
  double unitMin = 1.0;        ///< the time unit h in minutes
  std::vector<double> tau;     ///< scaled time of each sample, tau_1 = 0
  std::vector<double> weight;  ///< h_k of the weighted AGO, weight[0] = 1
  bool uniform = true;         ///< all steps equal to the unit (within 1e-9 relative)

  std::size_t size() const { return tau.size(); }
};

/// Mean sampling step (minutes) of strictly increasing times (at least two).
double meanStepMin(std::span<const double> timeMin);
/// The scaled time axis of `timeMin` in units of `unitMin` (> 0).
GreyTime greyTime(std::span<const double> timeMin, double unitMin);

/// 1-AGO, Eq. A.2 (weighted as above when `weight` is given; unit weights otherwise).
std::vector<double> ago(std::span<const double> x0, std::span<const double> weight = {});
/// IAGO, Eq. A.3 (the exact inverse of ago with the same weights).
std::vector<double> iago(std::span<const double> x1, std::span<const double> weight = {});

/// Parameters of GMC(1,N): b_1, driving coefficients b_2..b_N (one per input), u.
struct GmcParameters {
  double b1 = 0.0;
  std::vector<double> b;  ///< b_2 .. b_N
  double u = 0.0;
};

/// One series for a grey model: the target x_1^(0) and the inputs x_j^(0) on a time axis.
struct GreySeries {
  GreyTime time;
  std::vector<double> target;               ///< x_1^(0), one per sample (may be empty for prediction)
  std::vector<std::vector<double>> inputs;  ///< x_j^(0), [input][sample]
};

/// The 1-AGO of every input of a series.
std::vector<std::vector<double>> inputsAgo(const GreySeries& s);

/// Eq. 2.2: the time response x^_1^(1)(k), k = 1..n, from x_1^(1)(1) = `x11` and the inputs' AGO.
std::vector<double> gmcTimeResponse(const GmcParameters& p, double x11,
                                    const std::vector<std::vector<double>>& inputsAgo, const GreyTime& time);
/// The model output in the original domain: IAGO of the time response (x_1^(1)(1) = target[0], or 0
/// when the series has no target).
std::vector<double> gmcPredict(const GmcParameters& p, const GreySeries& s);

/// Least-squares GMC(1,N) over one or more segments (see above). Throws std::runtime_error when the
/// system is rank deficient (e.g. an input that is a multiple of another).
GmcParameters fitGmcLeastSquares(const std::vector<GreySeries>& segments);

}  // namespace metrofit::thermal
