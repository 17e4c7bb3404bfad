#pragma once
// The MLP baseline of Abdulshahed et al. 2016 (grey neural network thermal model, Section 4.4, Table 3): a
// three-layer feed-forward network, N inputs, 10 hidden neurons with the logistic sigmoid ("logarithmic
// sigmoid"), one linear output neuron, trained by Levenberg-Marquardt on the mean squared error.
//
// Network (inputs and output normalised to [-1, 1] by the min / max of the training rows, the
// "mapminmax" of the MATLAB toolbox the paper used):
//   y^ = v_0 + sum_h v_h s(W_h . x + c_h),   s(z) = 1 / (1 + e^{-z})
// Levenberg-Marquardt (Marquardt 1963; MATLAB trainlm): with residuals e = y - y^ and the Jacobian
// J = d y^ / d theta over all training rows, each epoch tries
//   (J^T J + mu I) delta = J^T e,   theta <- theta + delta
// and accepts the step when the MSE decreases (mu <- mu * muDecrease), otherwise mu <- mu * muIncrease
// and retries; the epoch fails when mu exceeds muMax.
// Stopping (Table 3 where it says): MSE <= goal (0.0001, on the normalised output), maxEpochs (5000),
// gradient norm |J^T e| / rows below minGradient, mu above muMax, or — not in Table 3, added so that
// long logs do not spend 5000 epochs on noise — an MSE that improved by less than a relative
// `minRelativeImprovement` over the last `stallEpochs` epochs. Table 3's learning rate and momentum
// belong to gradient descent and are not used by Levenberg-Marquardt.
// Initial weights: seeded, uniform in [-1, 1] / sqrt(inputs + 1) for the hidden layer and in
// [-1, 1] / sqrt(hidden + 1) for the output layer (same seed, same network, bit for bit).
#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/common/run.h"

namespace metrofit::thermal {

struct MlpOptions {
  int hidden = 10;        ///< hidden neurons (Table 3: 10)
  int maxEpochs = 5000;   ///< Table 3
  double goalMse = 1e-4;  ///< performance goal on the normalised output (Table 3)
  double mu0 = 1e-3, muDecrease = 0.1, muIncrease = 10.0, muMax = 1e10;  ///< trainlm defaults
  double minGradient = 1e-7;                                             ///< trainlm min_grad
  int stallEpochs = 25;                                                  ///< see above
  double minRelativeImprovement = 1e-5;                                  ///< see above
  std::uint64_t seed = 1;
  bool keepTrace = true;

  bool isValid(std::string* why) const;
};

/// A trained network with its normalisation (evaluates in the data's own units).
struct Mlp {
  Eigen::VectorXd inMin, inMax;  ///< per input, from the training rows
  double outMin = 0.0, outMax = 1.0;
  Eigen::MatrixXd w;  ///< hidden x inputs
  Eigen::VectorXd c;  ///< hidden biases
  Eigen::VectorXd v;  ///< output weights, one per hidden neuron
  double v0 = 0.0;    ///< output bias

  std::size_t inputs() const { return static_cast<std::size_t>(w.cols()); }
  std::size_t hidden() const { return static_cast<std::size_t>(w.rows()); }
  /// Number of weights and biases: hidden (inputs + 1) + hidden + 1.
  static std::size_t parameterCount(std::size_t inputs, std::size_t hidden) {
    return hidden * (inputs + 1) + hidden + 1;
  }
  /// The output for one row of inputs (data units).
  double predict(std::span<const double> x) const;
  /// One output per row of `x` (rows x inputs).
  Eigen::VectorXd predict(const Eigen::MatrixXd& x) const;
};

struct MlpTraining {
  Mlp net;
  double mse = 0.0;  ///< final MSE on the normalised training output
  RunInfo run;       ///< one trace entry per epoch; best = normalised MSE, components "mu"
};

/// Trains on `x` (rows x inputs) and `y` (rows). Needs at least 2 rows, every input and the output
/// not constant (std::invalid_argument otherwise; callers validate with messages first).
MlpTraining trainMlp(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const MlpOptions& options,
                     Observer* observer = nullptr);

}  // namespace metrofit::thermal
