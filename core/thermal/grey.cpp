#include "core/thermal/grey.h"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "core/common/error.h"

namespace metrofit::thermal {

double meanStepMin(std::span<const double> timeMin) {
  if (timeMin.size() < 2) throw std::invalid_argument("meanStepMin: need at least two samples");
  return (timeMin.back() - timeMin.front()) / static_cast<double>(timeMin.size() - 1);
}

GreyTime greyTime(std::span<const double> timeMin, double unitMin) {
  if (!(unitMin > 0.0) || !std::isfinite(unitMin)) throw std::invalid_argument("greyTime: unit must be > 0");
  GreyTime g;
  g.unitMin = unitMin;
  const std::size_t n = timeMin.size();
  g.tau.resize(n);
  g.weight.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    g.tau[k] = (timeMin[k] - timeMin[0]) / unitMin;
    g.weight[k] = k == 0 ? 1.0 : (timeMin[k] - timeMin[k - 1]) / unitMin;
    if (k > 0 && std::abs(g.weight[k] - 1.0) > 1e-9) g.uniform = false;
  }
  return g;
}

std::vector<double> ago(std::span<const double> x0, std::span<const double> weight) {
  std::vector<double> x1(x0.size());
  double acc = 0.0;
  for (std::size_t k = 0; k < x0.size(); ++k) {
    const double h = weight.empty() || k == 0 ? 1.0 : weight[k];
    acc += h * x0[k];
    x1[k] = acc;
  }
  return x1;
}

std::vector<double> iago(std::span<const double> x1, std::span<const double> weight) {
  std::vector<double> x0(x1.size());
  for (std::size_t k = 0; k < x1.size(); ++k) {
    if (k == 0) {
      x0[k] = x1[0];
    } else {
      const double h = weight.empty() ? 1.0 : weight[k];
      x0[k] = (x1[k] - x1[k - 1]) / h;
    }
  }
  return x0;
}

std::vector<std::vector<double>> inputsAgo(const GreySeries& s) {
  std::vector<std::vector<double>> out;
  out.reserve(s.inputs.size());
  for (const auto& in : s.inputs) out.push_back(ago(in, s.time.weight));
  return out;
}

std::vector<double> gmcTimeResponse(const GmcParameters& p, double x11,
                                    const std::vector<std::vector<double>>& xAgo, const GreyTime& time) {
  const std::size_t n = time.size();
  if (xAgo.size() != p.b.size()) throw std::invalid_argument("gmcTimeResponse: one b_j per input needed");
  auto f = [&](std::size_t k) {
    double v = p.u;
    for (std::size_t j = 0; j < xAgo.size(); ++j) v += p.b[j] * xAgo[j][k];
    return v;
  };
  std::vector<double> out(n);
  if (n == 0) return out;
  out[0] = x11;
  double s = 0.0;
  double fPrev = f(0);
  const double decay1 = std::exp(-p.b1), half1 = std::exp(-0.5 * p.b1);
  for (std::size_t k = 1; k < n; ++k) {
    const double h = time.weight[k];
    const double decay = time.uniform ? decay1 : std::exp(-p.b1 * h);
    const double half = time.uniform ? half1 : std::exp(-0.5 * p.b1 * h);
    const double fk = f(k);
    s = decay * s + half * h * 0.5 * (fk + fPrev);
    fPrev = fk;
    out[k] = x11 * std::exp(-p.b1 * time.tau[k]) + s;
  }
  return out;
}

std::vector<double> gmcPredict(const GmcParameters& p, const GreySeries& s) {
  const double x11 = s.target.empty() ? 0.0 : s.target[0];
  return iago(gmcTimeResponse(p, x11, inputsAgo(s), s.time), s.time.weight);
}

GmcParameters fitGmcLeastSquares(const std::vector<GreySeries>& segments) {
  if (segments.empty()) throw std::invalid_argument("fitGmcLeastSquares: no data");
  const std::size_t m = segments.front().inputs.size();
  std::size_t rows = 0;
  for (const auto& s : segments) {
    if (s.inputs.size() != m) throw std::invalid_argument("fitGmcLeastSquares: segments differ in inputs");
    if (s.target.size() != s.time.size()) throw std::invalid_argument("fitGmcLeastSquares: no target");
    if (s.time.size() >= 2) rows += s.time.size() - 1;
  }
  const auto p = static_cast<Eigen::Index>(m + 2);
  if (rows < m + 2) throw std::invalid_argument("fitGmcLeastSquares: fewer equations than parameters");
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows), p);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
  Eigen::Index r = 0;
  for (const auto& s : segments) {
    const std::vector<double> x1 = ago(s.target, s.time.weight);
    const auto xj = inputsAgo(s);
    for (std::size_t k = 1; k < s.time.size(); ++k, ++r) {
      a(r, 0) = -0.5 * (x1[k] + x1[k - 1]);
      for (std::size_t j = 0; j < m; ++j)
        a(r, static_cast<Eigen::Index>(j + 1)) = 0.5 * (xj[j][k] + xj[j][k - 1]);
      a(r, p - 1) = 1.0;
      y(r) = s.target[k];
    }
  }
  // Equilibrate the columns (the AGO columns grow with time, the constant column does not) so that
  // the rank decision of the QR is about dependence, not about scale.
  Eigen::VectorXd scale(p);
  for (Eigen::Index c = 0; c < p; ++c) {
    const double norm = a.col(c).norm();
    scale(c) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  const Eigen::MatrixXd as = a * scale.asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(as);
  qr.setThreshold(1e-12);
  if (qr.rank() < p) {
    throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"},
                          "the GMC(1,N) least-squares system is rank deficient (rank " +
                              std::to_string(qr.rank()) + " of " + std::to_string(p) +
                              "): the target and inputs are linearly dependent on the fitting rows");
  }
  const Eigen::VectorXd sol = scale.asDiagonal() * qr.solve(y);
  GmcParameters out;
  out.b1 = sol(0);
  out.b.resize(m);
  for (std::size_t j = 0; j < m; ++j) out.b[j] = sol(static_cast<Eigen::Index>(j + 1));
  out.u = sol(p - 1);
  return out;
}

}  // namespace metrofit::thermal
