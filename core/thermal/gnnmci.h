#pragma once
// GNNMCI(1,N): the grey neural network model with convolution integral of Abdulshahed 2016 (Abdulshahed et
// al. 2016, Section 2.2, Eq. 2.3-2.9, Fig. 2), trained by particle swarm optimisation.
//
// ---- The mapping (Eq. 2.3-2.6, Fig. 2) ---------------------------------------------------------
// Eq. 2.3 names the convolution part of the GMC(1,N) time response (grey.h, Eq. 2.2):
//   G(k) = u(t-1) sum_{tau=1}^{k} e^{-b_1 (k - tau + 1/2)} (f(tau) + f(tau-1)) / 2,
// Eq. 2.4:  x^_1^(1)(k+1) = x_1^(1)(1) e^{-b_1 k} + G(k), and Eq. 2.5 rewrites it, with
// s = 1 / (1 + e^{-b_1 k}), as  [x_1^(1)(1) - x_1^(1)(1) s + G s] (1 + e^{-b_1 k}).
// Fig. 2 maps this onto four layers; at sample k (scaled time, grey.h):
//   layer A   a = w11 k                                                     (linear)
//   layer B   b = 1 / (1 + e^{-a})                                          (logistic sigmoid)
//   layer C   c_1 = b w21,  c_j = I_j(k) b w2j (one per input),  c_N+1 = I_0(k) b w2,N+1   (linear)
//   layer D   d = sum_j w3j c_j - theta                                     (linear) = x^_1^(1)(k+1)
// with the weight assignment below Eq. 2.5 and the bias of Eq. 2.6:
//   w11 = b_1,  w21 = -x_1^(1)(1),  w2j = d_j = b_j (inputs),  w2,N+1 = u,
//   w31 = ... = w3,N+1 = 1 + e^{-w11 k},   theta = -x_1^(1)(1) (1 + e^{-w11 k}).
// Readings where the paper is ambiguous:
//  * Eq. 2.6 prints theta = (-x_1^(1)(k+1))(1 + e^{-b_1 k}); a bias that contains the network's own
//    output cannot be meant. With x_1^(1)(1) (the initial condition, as in the term it must cancel in
//    Eq. 2.5) the network reproduces Eq. 2.4 exactly, so that is the reading.
//  * Step 1 feeds layer C with "x_j(k)" and leaves d_j = f(b_j) unspecified. For d = G(k) to hold, the
//    node of input j must carry its convolution with the kernel of Eq. 2.3,
//      I_j(k) = sum_tau e^{-w11 (k - tau + 1/2)} (X_j^(1)(tau) + X_j^(1)(tau-1)) / 2,
//    and the u node the convolution of 1, I_0(k); then G = sum_j b_j I_j + u I_0 (G is linear in b_j
//    and u), d_j = b_j, d_N = u. This grey input layer (Yuan et al. 2008, the paper's [38]) is what is
//    implemented: with the assignment above the network output equals the GMC(1,N) time response
//    (Eq. 2.2) exactly, which the tests check. Unequal steps as in grey.h.
//  * The paper's weight table lists one value for all w3j (1.5855) and w21 = 0.001 ~ -x_1^(1)(1) = 0
//    (Table 1 starts from zero): consistent with the tied w3j and the assignment of w21 above. So the
//    trained weights are w11 and w22..w2,N+1; w21, w3j and theta follow from them and from the series'
//    first value (Step 3: "adjusting the connection weights from LA to LC; adjust the bias theta").
// The output of layer D is the 1-AGO series; the prediction is its IAGO (Section 3.2 Step 3).
//
// ---- Training (Eq. 2.7-2.9) ---------------------------------------------------------------------
// PSO (core/optim/pso.h; Eq. 2.7-2.8) with the paper's set-up: 90 particles, c1 = 1.5, c2 = 2,
// inertia decreasing linearly from 0.9 to 0.4, minimising the fitness of Eq. 2.9 on the IAGO-restored
// output over all fitting samples of all segments:
//   f(W) = sum_k (x^_1^(0)(k) - x_1^(0)(k))^2            [target units^2]
// Particle coordinates: a bijective rescaling of the trained weights so that one search box fits
// logs of any length, sampling step and units (the paper does not state its box):
//   p_0 = log10 w11                      in [log10(1 / (maxLagFactor * T)), log10(1 / minLagSteps)]
//   p_j = w2j / w11 * range_j / range_y  in [-gainBound, gainBound]   (static gain, normalised)
//   p_u = w2,N+1 / range_y               in [-gainBound, gainBound]   (start transient, normalised)
// T: the longest fitting segment in time units; range: max - min over the fitting rows. w2j / w11 is
// the static gain of input j (differentiating Eq. 2.1 shows the output is a first-order lag, time
// constant 1 / b_1, of sum_j (b_j / b_1) x_j^(0) plus a start transient of size u).
// Two ways to train (GnnmciOptions::training), both PSO with the paper's parameters on Eq. 2.9:
//  * Pso: every particle carries all trained weights (p_0, p_j, p_u) — the paper's Step 2 literally.
//  * PsoLeastSquares (default): the particles carry w11 only (p_0); for each particle the layer-C
//    weights w22..w2,N+1 are the linear least-squares minimum of Eq. 2.9 (the network output is linear
//    in them for a given w11: x^_1^(0) = IAGO(x_1^(1)(1) e^{-w11 k}) + sum_j w2j IAGO(I_j) +
//    w2,N+1 IAGO(I_0)), solved by column-pivoting QR; the fitness is then evaluated through the network.
//    This is separable least squares (Golub & Pereyra 1973), the "hybrid learning" of least squares plus
//    a search that the paper's introduction cites for ANFIS. Reason, measured on the simulated modular
//    tests (Z + C, 5 inputs, 100 iterations, seeds 1-5): the literal swarm stopped in a local optimum
//    (w11 ~ 0.005, gains at the box walls, Eq. 2.9 ~ 3.2e4 um^2) for 4 of 5 seeds and reached 426 for
//    one; with a +-2 box it ended between 437 and 1449 (3 of 5 worse than GMC(1,N)'s 874). The
//    one-dimensional swarm over w11 reaches 356.25 for every seed. Its optimum is never worse than
//    GMC(1,N)'s least squares when that b_1 lies in the box (those parameters are one point of the
//    inner problem at that w11).
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/run.h"
#include "core/thermal/grey.h"

namespace metrofit::thermal {

/// The trained weights of GNNMCI(1,N): w11 and w22..w2,N+1 (one per input, then u).
struct GnnmciWeights {
  double w11 = 0.0;
  std::vector<double> w2;  ///< size inputs + 1; the last one multiplies the u node

  /// The weight assignment below Eq. 2.5 (w11 = b_1, w2j = b_j, w2,N+1 = u) and its inverse.
  static GnnmciWeights fromGmc(const GmcParameters& p);
  GmcParameters toGmc() const;
};

/// Inputs of layer C: the convolution I_j(k) of each input's 1-AGO and I_0(k) of the unit series.
struct GnnmciLayerInputs {
  std::vector<std::vector<double>> inputs;  ///< [input][sample]
  std::vector<double> unit;                 ///< [sample]
};
GnnmciLayerInputs gnnmciLayerInputs(double w11, const std::vector<std::vector<double>>& inputsAgo,
                                    const GreyTime& time);

/// What every layer computes at one sample (for tests and for showing the network).
struct GnnmciLayers {
  double a = 0.0, b = 0.0;  ///< layers A and B
  std::vector<double> c;    ///< layer C: c_1 (initial condition), one per input, the u node
  double w3 = 0.0;          ///< the tied layer C -> D weight 1 + e^{-w11 k}
  double theta = 0.0;       ///< the bias of Eq. 2.6
  double d = 0.0;           ///< layer D: x^_1^(1) at this sample
};
/// Layers at sample `k` (0-based) for a series whose first target value is `x11`.
GnnmciLayers gnnmciLayers(const GnnmciWeights& w, double x11, const GnnmciLayerInputs& in,
                          const GreyTime& time, std::size_t k);

/// Layer D over a whole series from given layer-C inputs (computed with the same w11).
std::vector<double> gnnmciForward(const GnnmciWeights& w, double x11, const GnnmciLayerInputs& in,
                                  const GreyTime& time);
/// Layer D over a whole series: x^_1^(1)(k), k = 1..n.
std::vector<double> gnnmciForward(const GnnmciWeights& w, double x11,
                                  const std::vector<std::vector<double>>& inputsAgo, const GreyTime& time);
/// The prediction: IAGO of gnnmciForward (x11 = the series' first target value, 0 without target).
std::vector<double> gnnmciPredict(const GnnmciWeights& w, const GreySeries& s);
/// Eq. 2.9 summed over the segments (each one starts from its own first sample).
double gnnmciFitness(const GnnmciWeights& w, const std::vector<GreySeries>& segments);

struct GnnmciOptions {
  /// What the particles carry (see above).
  enum class Training { Pso, PsoLeastSquares };
  Training training = Training::PsoLeastSquares;
  int particles = 90;         ///< swarm size M (paper: 90)
  double c1 = 1.5;            ///< self-confidence factor (paper: 1.5)
  double c2 = 2.0;            ///< swarm-confidence factor (paper: 2)
  double inertiaStart = 0.9;  ///< omega at the first iteration (paper: 0.9)
  double inertiaEnd = 0.4;    ///< omega at the last iteration (paper: 0.4)
  int iterations = 100;       ///< PSO iterations ("epochs"; paper: acceptable after 100)
  double gainBound = 5.0;     ///< box of the normalised gains p_j and p_u
  double minLagSteps = 0.25;  ///< smallest time constant 1 / w11, in time units (steps)
  double maxLagFactor = 4.0;  ///< largest time constant, in multiples of the longest segment
  std::uint64_t seed = 1;     ///< same seed, same weights and trace, bit for bit
  bool keepTrace = true;

  bool isValid(std::string* why) const;
};

struct GnnmciTraining {
  GnnmciWeights weights;
  double fitness = 0.0;        ///< Eq. 2.9 at the best weights [target units^2]
  double firstFitness = 0.0;   ///< best fitness after the first iteration (the random swarm)
  std::size_t samples = 0;     ///< samples in the fitness sum
  std::vector<double> lowerX;  ///< the particle box ((p_0, p_j, p_u) or (p_0)), for reports
  std::vector<double> upperX;
  RunInfo run;  ///< one trace entry per PSO iteration; best = fitness, component "fit_rmse"
};

/// "pso", "pso-ls".
const char* toString(GnnmciOptions::Training t);

/// Trains GNNMCI(1,N) on one or more segments (all with targets, the same inputs, >= 2 samples).
/// Throws OptionsError for invalid options; Cancelled (in run.termination) when the observer stops.
GnnmciTraining trainGnnmci(const std::vector<GreySeries>& segments, const GnnmciOptions& options,
                           Observer* observer = nullptr);

}  // namespace metrofit::thermal
