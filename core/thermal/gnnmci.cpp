#include "core/thermal/gnnmci.h"

#include <cmath>
#include <stdexcept>

namespace metrofit::thermal {

GnnmciWeights GnnmciWeights::fromGmc(const GmcParameters& p) {
  GnnmciWeights w;
  w.w11 = p.b1;
  w.w2 = p.b;
  w.w2.push_back(p.u);
  return w;
}

GmcParameters GnnmciWeights::toGmc() const {
  if (w2.empty()) throw std::invalid_argument("GnnmciWeights: w2 needs the u weight");
  GmcParameters p;
  p.b1 = w11;
  p.b.assign(w2.begin(), w2.end() - 1);
  p.u = w2.back();
  return p;
}

namespace {

/// I(k) = e^{-w h_k} I(k-1) + e^{-w h_k / 2} h_k (x(k) + x(k-1)) / 2, I(0) = 0 (Eq. 2.3's kernel).
template <class Value>
void convolve(double w11, const GreyTime& time, Value x, std::vector<double>& out) {
  const std::size_t n = time.size();
  out.assign(n, 0.0);
  const double decay1 = std::exp(-w11), half1 = std::exp(-0.5 * w11);
  double s = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double h = time.weight[k];
    const double decay = time.uniform ? decay1 : std::exp(-w11 * h);
    const double half = time.uniform ? half1 : std::exp(-0.5 * w11 * h);
    s = decay * s + half * h * 0.5 * (x(k) + x(k - 1));
    out[k] = s;
  }
}

void checkShapes(const GnnmciWeights& w, std::size_t inputs) {
  if (w.w2.size() != inputs + 1) {
    throw std::invalid_argument("GNNMCI: " + std::to_string(inputs) + " inputs need " +
                                std::to_string(inputs + 1) + " layer-C weights, got " +
                                std::to_string(w.w2.size()));
  }
}

}  // namespace

GnnmciLayerInputs gnnmciLayerInputs(double w11, const std::vector<std::vector<double>>& xAgo,
                                    const GreyTime& time) {
  GnnmciLayerInputs in;
  in.inputs.resize(xAgo.size());
  for (std::size_t j = 0; j < xAgo.size(); ++j) {
    const auto& x = xAgo[j];
    convolve(
        w11, time, [&x](std::size_t k) { return x[k]; }, in.inputs[j]);
  }
  convolve(
      w11, time, [](std::size_t) { return 1.0; }, in.unit);
  return in;
}

GnnmciLayers gnnmciLayers(const GnnmciWeights& w, double x11, const GnnmciLayerInputs& in,
                          const GreyTime& time, std::size_t k) {
  checkShapes(w, in.inputs.size());
  GnnmciLayers l;
  l.a = w.w11 * time.tau[k];
  const double e = std::exp(-l.a);
  l.b = 1.0 / (1.0 + e);
  const double w21 = -x11;
  l.c.push_back(l.b * w21);
  for (std::size_t j = 0; j < in.inputs.size(); ++j) l.c.push_back(in.inputs[j][k] * l.b * w.w2[j]);
  l.c.push_back(in.unit[k] * l.b * w.w2.back());
  l.w3 = 1.0 + e;
  l.theta = -x11 * (1.0 + e);
  double sum = 0.0;
  for (double c : l.c) sum += l.w3 * c;
  l.d = sum - l.theta;
  return l;
}

std::vector<double> gnnmciForward(const GnnmciWeights& w, double x11,
                                  const std::vector<std::vector<double>>& xAgo, const GreyTime& time) {
  return gnnmciForward(w, x11, gnnmciLayerInputs(w.w11, xAgo, time), time);
}

std::vector<double> gnnmciForward(const GnnmciWeights& w, double x11, const GnnmciLayerInputs& in,
                                  const GreyTime& time) {
  checkShapes(w, in.inputs.size());
  const std::size_t n = time.size();
  std::vector<double> d(n);
  // The same arithmetic as gnnmciLayers, without the per-sample allocation; on equal steps
  // e^{-w11 k} is carried from sample to sample (relative drift ~ k * 1e-16) instead of an exp per row.
  const double decay = std::exp(-w.w11);
  double carried = 1.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) carried *= decay;
    const double e = time.uniform ? carried : std::exp(-w.w11 * time.tau[k]);
    const double b = 1.0 / (1.0 + e);
    const double w3 = 1.0 + e;
    double sum = w3 * (b * -x11);
    for (std::size_t j = 0; j < in.inputs.size(); ++j) sum += w3 * (in.inputs[j][k] * b * w.w2[j]);
    sum += w3 * (in.unit[k] * b * w.w2.back());
    d[k] = sum - (-x11 * (1.0 + e));
  }
  return d;
}

std::vector<double> gnnmciPredict(const GnnmciWeights& w, const GreySeries& s) {
  const double x11 = s.target.empty() ? 0.0 : s.target[0];
  return iago(gnnmciForward(w, x11, inputsAgo(s), s.time), s.time.weight);
}

double gnnmciFitness(const GnnmciWeights& w, const std::vector<GreySeries>& segments) {
  double f = 0.0;
  for (const auto& s : segments) {
    const std::vector<double> y = gnnmciPredict(w, s);
    for (std::size_t k = 0; k < y.size(); ++k) {
      const double r = y[k] - s.target[k];
      f += r * r;
    }
  }
  return f;
}

bool GnnmciOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (particles < 2) return no("the swarm needs at least 2 particles");
  if (!(c1 >= 0.0) || !(c2 >= 0.0) || !std::isfinite(c1) || !std::isfinite(c2))
    return no("c1 and c2 must be finite and >= 0");
  if (!(inertiaStart >= 0.0) || !(inertiaEnd >= 0.0) || inertiaStart > 1.5 || inertiaEnd > 1.5)
    return no("the inertia weights must be in [0, 1.5]");
  if (iterations < 1) return no("at least one PSO iteration is needed");
  if (!(gainBound > 0.0) || !std::isfinite(gainBound)) return no("gainBound must be positive");
  if (!(minLagSteps > 0.0) || !std::isfinite(minLagSteps)) return no("minLagSteps must be positive");
  if (!(maxLagFactor > 0.0) || !std::isfinite(maxLagFactor)) return no("maxLagFactor must be positive");
  return true;
}

}  // namespace metrofit::thermal
