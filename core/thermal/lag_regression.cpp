#include "core/thermal/lag_regression.h"

#include "core/thermal/linear_least_squares.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace metrofit::thermal {

std::vector<double> firstOrderLagMin(std::span<const double> x, std::span<const double> tMin, double tauMin) {
  if (x.size() != tMin.size())
    throw std::invalid_argument("firstOrderLagMin: time and values differ in size");
  std::vector<double> s(x.begin(), x.end());
  if (!(tauMin > 0.0) || s.empty()) return s;
  double step = -1.0, a = 0.0;  // one exponential per run of equal steps
  for (std::size_t k = 1; k < s.size(); ++k) {
    if (tMin[k] - tMin[k - 1] != step) {
      step = tMin[k] - tMin[k - 1];
      a = -std::expm1(-step / tauMin);
    }
    s[k] = s[k - 1] + a * (x[k] - s[k - 1]);
  }
  return s;
}

std::vector<std::vector<double>> lagColumns(const std::vector<LagTerm>& terms, const LagData& d) {
  std::vector<std::vector<double>> out;
  out.reserve(terms.size());
  for (const LagTerm& t : terms) {
    if (t.input >= d.inputs.size()) throw std::invalid_argument("lagColumns: no such input");
    std::vector<double> c = firstOrderLagMin(d.inputs[t.input], d.timeMin, t.tauMin);
    const double x0 = c.empty() ? 0.0 : d.inputs[t.input][0];
    for (double& v : c) v -= x0;
    out.push_back(std::move(c));
  }
  return out;
}

namespace {

/// The design [1, columns] and the target change of all logs, rows concatenated.
struct Design {
  Eigen::MatrixXd x;
  Eigen::VectorXd y;
};

Design design(const std::vector<LagTerm>& terms, const std::vector<LagData>& logs) {
  std::size_t rows = 0;
  for (const auto& d : logs) rows += d.timeMin.size();
  Design out;
  out.x.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(terms.size() + 1));
  out.y.resize(static_cast<Eigen::Index>(rows));
  Eigen::Index r0 = 0;
  for (const auto& d : logs) {
    if (d.target.size() != d.timeMin.size())
      throw std::invalid_argument("LagRegression: fitting needs a target");
    const auto cols = lagColumns(terms, d);
    const auto n = static_cast<Eigen::Index>(d.timeMin.size());
    for (Eigen::Index k = 0; k < n; ++k) {
      out.x(r0 + k, 0) = 1.0;
      for (std::size_t c = 0; c < cols.size(); ++c)
        out.x(r0 + k, static_cast<Eigen::Index>(c + 1)) = cols[c][static_cast<std::size_t>(k)];
      out.y(r0 + k) = d.target[static_cast<std::size_t>(k)] - d.target[0];
    }
    r0 += n;
  }
  return out;
}

Eigen::VectorXd solve(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
  return linearLeastSquares(x, y);
}

}  // namespace

Eigen::VectorXd linearLeastSquares(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
  if (x.rows() < x.cols()) throw std::invalid_argument("LagRegression: fewer rows than coefficients");
  Eigen::VectorXd scale(x.cols());
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    const double norm = x.col(c).norm();
    scale(c) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x * scale.asDiagonal());
  qr.setThreshold(1e-10);
  return scale.asDiagonal() * qr.solve(y);
}

LagRegression fitLagTerms(const std::vector<LagTerm>& terms, const std::vector<LagData>& logs) {
  const Design d = design(terms, logs);
  const Eigen::VectorXd b = solve(d.x, d.y);
  LagRegression r;
  r.terms = terms;
  r.intercept = b(0);
  r.coef.resize(terms.size());
  for (std::size_t t = 0; t < terms.size(); ++t) r.coef[t] = b(static_cast<Eigen::Index>(t + 1));
  return r;
}

std::vector<double> predictLag(const LagRegression& r, const LagData& d) {
  const auto cols = lagColumns(r.terms, d);
  std::vector<double> out(d.timeMin.size(), r.intercept);
  for (std::size_t t = 0; t < cols.size(); ++t)
    for (std::size_t k = 0; k < out.size(); ++k) out[k] += r.coef[t] * cols[t][k];
  return out;
}

double blockedCvRmse(const std::vector<LagTerm>& terms, const std::vector<LagData>& logs, int folds) {
  const Design d = design(terms, logs);
  const Eigen::Index n = d.x.rows();
  folds = std::max(2, folds);
  if (n < static_cast<Eigen::Index>(folds) * (d.x.cols() + 1)) return std::numeric_limits<double>::infinity();
  double sse = 0.0;
  for (int f = 0; f < folds; ++f) {
    const Eigen::Index b = n * f / folds, e = n * (f + 1) / folds;
    Eigen::MatrixXd xt(n - (e - b), d.x.cols());
    Eigen::VectorXd yt(n - (e - b));
    xt.topRows(b) = d.x.topRows(b);
    xt.bottomRows(n - e) = d.x.bottomRows(n - e);
    yt.head(b) = d.y.head(b);
    yt.tail(n - e) = d.y.tail(n - e);
    const Eigen::VectorXd coef = solve(xt, yt);
    sse += (d.y.segment(b, e - b) - d.x.middleRows(b, e - b) * coef).squaredNorm();
  }
  return std::sqrt(sse / static_cast<double>(n));
}

LagRegression fitLagModel(LagForm form, std::size_t inputs, const std::vector<LagData>& logs,
                          double* cvRmse) {
  auto termsOf = [&](const std::vector<double>& tau) {
    std::vector<LagTerm> terms;
    for (std::size_t j = 0; j < inputs; ++j) {
      if (form == LagForm::Static) {
        terms.push_back({j, 0.0});
      } else if (form == LagForm::Lag) {
        terms.push_back({j, tau[j]});
      } else {
        terms.push_back({j, 0.0});
        terms.push_back({j, tau[j]});
      }
    }
    return terms;
  };
  std::vector<double> tau(inputs, form == LagForm::DistributedLag ? 30.0 : 0.0);
  std::map<std::vector<double>, double> cache;
  auto score = [&](const std::vector<double>& t) {
    auto it = cache.find(t);
    if (it != cache.end()) return it->second;
    return cache[t] = blockedCvRmse(termsOf(t), logs);
  };
  double best = score(tau);
  if (form != LagForm::Static) {
    for (int sweep = 0; sweep < 2; ++sweep) {
      bool changed = false;
      for (std::size_t j = 0; j < inputs; ++j) {
        for (double g : kLagGridMin) {
          if (form == LagForm::DistributedLag && !(g > 0.0)) continue;  // x and L_0[x] are one column
          std::vector<double> t = tau;
          t[j] = g;
          const double s = score(t);
          if (s < best) {
            best = s;
            tau = t;
            changed = true;
          }
        }
      }
      if (!changed) break;
    }
  }
  if (cvRmse) *cvRmse = best;
  return fitLagTerms(termsOf(tau), logs);
}

}  // namespace metrofit::thermal
