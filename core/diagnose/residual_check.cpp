#include "core/diagnose/residual_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>

#include <Eigen/Dense>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>

namespace metrofit::diagnose {
namespace {

using A = PhraseArg;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

double chiSquareSurvival(double x, double dof) {
  if (!(x > 0.0)) return 1.0;
  if (!std::isfinite(x)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared_distribution<double>(dof), x));
}

double fSurvival(double x, double d1, double d2) {
  if (!(x > 0.0)) return 1.0;
  if (!std::isfinite(x)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(d1, d2), x));
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  double m = *mid;
  if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), mid));
  return m;
}

/// The q-quantile (linear interpolation) of sorted values.
double quantileSorted(const std::vector<double>& s, double q) {
  if (s.empty()) return 0.0;
  const double pos = q * static_cast<double>(s.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const double f = pos - static_cast<double>(i);
  return i + 1 < s.size() ? s[i] * (1.0 - f) + s[i + 1] * f : s[i];
}

/// An orthonormal basis of [1, J] (columns scaled first; rank by column-pivoting QR).
Eigen::MatrixXd orthonormalBasis(const Eigen::MatrixXd& J, Eigen::Index n, int components) {
  const int C = std::max(1, components);
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, J.cols() + C);
  for (Eigen::Index i = 0; i < n; ++i) X(i, i % C) = 1.0;
  if (J.cols() > 0) X.rightCols(J.cols()) = J;
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    const double norm = X.col(j).norm();
    if (norm > 0.0) X.col(j) /= norm;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
  qr.setThreshold(1e-10);
  const Eigen::Index rank = qr.rank();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, rank);
  Q = qr.householderQ() * Q;
  return Q;
}

/// The F test of G beyond [1, J] for a residual r orthogonal to [1, J] (see the header comment).
struct FTest {
  bool ok = false;
  double ssr = 0.0;  ///< SSE0 - SSE1
  double F = 0.0, p = 1.0;
  int q = 0;
  Eigen::VectorXd coefficients;  ///< of G (on the projected problem)
};

FTest fTest(const Eigen::VectorXd& r, const Eigen::MatrixXd& U, const Eigen::MatrixXd& G, double sse0) {
  FTest t;
  const Eigen::Index n = r.size();
  if (G.cols() == 0) return t;
  const Eigen::MatrixXd UtG = U.transpose() * G;
  const Eigen::MatrixXd M = G.transpose() * G - UtG.transpose() * UtG;
  const Eigen::VectorXd g = G.transpose() * r - UtG.transpose() * (U.transpose() * r);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M);
  const double top = es.eigenvalues().cwiseAbs().maxCoeff();
  if (!(top > 0.0)) return t;
  // Columns that G shares with [1, J] are dropped by the eigenvalue cut (relative to G's own scale).
  const double gscale = G.colwise().squaredNorm().maxCoeff();
  Eigen::VectorXd coef = Eigen::VectorXd::Zero(G.cols());
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const double lambda = es.eigenvalues()(i);
    if (!(lambda > 1e-9 * gscale) || !(lambda > 1e-12 * top)) continue;
    const double c = es.eigenvectors().col(i).dot(g);
    t.ssr += c * c / lambda;
    coef += es.eigenvectors().col(i) * (c / lambda);
    ++t.q;
  }
  const Eigen::Index p = U.cols();
  const double dof2 = static_cast<double>(n - p - t.q);
  if (t.q == 0 || dof2 < 1.0) return t;
  t.ssr = std::clamp(t.ssr, 0.0, sse0);
  const double sse1 = std::max(sse0 - t.ssr, 1e-300 * std::max(1.0, sse0));
  t.F = (t.ssr / t.q) / (sse1 / dof2);
  t.p = fSurvival(t.F, t.q, dof2);
  t.coefficients = coef;
  t.ok = true;
  return t;
}

/// Natural cubic spline (restricted cubic spline) columns on u with knots k (K >= 3): u and K - 2
/// non-linear terms, each divided by (k_K - k_1)^2.
void splineColumns(const std::vector<double>& k, double u, double* out) {
  const std::size_t K = k.size();
  out[0] = u;
  const double span2 = std::pow(k[K - 1] - k[0], 2);
  auto p3 = [](double x) { return x > 0.0 ? x * x * x : 0.0; };
  for (std::size_t j = 0; j + 2 < K; ++j) {
    const double a = p3(u - k[j]);
    const double b = p3(u - k[K - 2]) * (k[K - 1] - k[j]) / (k[K - 1] - k[K - 2]);
    const double c = p3(u - k[K - 1]) * (k[K - 2] - k[j]) / (k[K - 1] - k[K - 2]);
    out[j + 1] = (a - b + c) / span2;
  }
}

std::vector<double> finiteSorted(const std::vector<double>& v) {
  std::vector<double> s;
  s.reserve(v.size());
  for (double x : v)
    if (std::isfinite(x)) s.push_back(x);
  std::sort(s.begin(), s.end());
  return s;
}

std::size_t distinctCount(const std::vector<double>& sorted) {
  std::size_t c = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (i == 0 || sorted[i] != sorted[i - 1]) ++c;
  return c;
}

/// Ljung-Box on r sorted by `order` (stable: ties keep the observation order).
ResidualTest ljungBox(const Eigen::VectorXd& r, const std::vector<double>& order, int maxLag,
                      const std::string& name) {
  ResidualTest t;
  t.name = "ljung_box";
  t.against = name;
  const auto n = static_cast<std::size_t>(r.size());
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return order[a] < order[b]; });
  const double mean = r.mean();
  std::vector<double> e(n);
  double c0 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    e[i] = r(static_cast<Eigen::Index>(idx[i])) - mean;
    c0 += e[i] * e[i];
  }
  const int h = std::min<int>(maxLag, static_cast<int>(n / 5));
  t.dof = h;
  if (h < 1 || !(c0 > 0.0)) return t;
  double Q = 0.0;
  for (int k = 1; k <= h; ++k) {
    double ck = 0.0;
    for (std::size_t i = static_cast<std::size_t>(k); i < n; ++i)
      ck += e[i] * e[i - static_cast<std::size_t>(k)];
    const double rho = ck / c0;
    Q += rho * rho / static_cast<double>(n - static_cast<std::size_t>(k));
  }
  Q *= static_cast<double>(n) * static_cast<double>(n + 2);
  t.statistic = Q;
  t.p = chiSquareSurvival(Q, h);
  return t;
}

Phrase formPhrase(DependenceForm f) {
  switch (f) {
    case DependenceForm::Linear:
      return Phrase("linear");
    case DependenceForm::Smooth:
      return Phrase("smooth");
    case DependenceForm::Step:
      return Phrase("step");
    case DependenceForm::Periodic:
      return Phrase("periodic");
    case DependenceForm::Level:
      return Phrase("per level");
  }
  return Phrase("linear");
}

Eigen::MatrixXd basisOnFinite(const GenericForm& f, const std::vector<double>& values);

/// The period search of the header comment: r orthogonal to U already; `base` carries the
/// variable's name and components. The best shape, its F test (p corrected) and M.
struct FoundPeriod {
  GenericForm shape;
  FTest test;
  int searched = 0;
};
std::optional<FoundPeriod> periodSearch(const Eigen::VectorXd& r, const Eigen::MatrixXd& U, double sse0,
                                        const ResidualVariable& v, const GenericForm& base,
                                        const ResidualCheckOptions& o);

}  // namespace

const char* formName(DependenceForm f) {
  switch (f) {
    case DependenceForm::Linear:
      return "linear";
    case DependenceForm::Smooth:
      return "smooth";
    case DependenceForm::Step:
      return "step";
    case DependenceForm::Periodic:
      return "periodic";
    case DependenceForm::Level:
      return "level";
  }
  return "linear";
}

bool ResidualCheckOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(level > 0.0 && level < 0.5)) return no("level must be in (0, 0.5)");
  if (maxLag < 1 || maxLag > 1000) return no("maxLag must be in 1..1000");
  if (splineKnots < 3 || splineKnots > 12) return no("splineKnots must be in 3..12");
  if (harmonics < 1 || harmonics > 20) return no("harmonics must be in 1..20");
  if (stepPositions < 1 || stepPositions > 200) return no("stepPositions must be in 1..200");
  if (!(outlierFactor >= 1.0) || !std::isfinite(outlierFactor)) return no("outlierFactor must be >= 1");
  if (!(maxOutlierFraction >= 0.0 && maxOutlierFraction <= 0.5))
    return no("maxOutlierFraction must be in [0, 0.5]");
  if (!(winsorZ >= 0.0) || !std::isfinite(winsorZ)) return no("winsorZ must be finite and >= 0");
  if (!(blockZ >= 0.0) || !std::isfinite(blockZ)) return no("blockZ must be finite and >= 0");
  return true;
}

Eigen::MatrixXd genericBasis(const GenericForm& f, const std::vector<double>& values) {
  Eigen::MatrixXd G = basisOnFinite(f, values);
  if (f.withoutLinear && f.form == DependenceForm::Smooth && G.cols() > 1) {
    Eigen::MatrixXd H = G.rightCols(G.cols() - 1);
    G = std::move(H);
  }
  if (f.subset && (f.form == DependenceForm::Linear || f.form == DependenceForm::Smooth ||
                   f.form == DependenceForm::Step)) {
    Eigen::MatrixXd H(G.rows(), G.cols() + 1);
    for (std::size_t i = 0; i < values.size(); ++i) H(static_cast<Eigen::Index>(i), 0) = 1.0;
    H.rightCols(G.cols()) = G;
    G = std::move(H);
  }
  // Observations where the variable does not apply (NaN: e.g. the part number of `dimension:<d>` on
  // the rows of other dimensions) get no contribution.
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) G.row(static_cast<Eigen::Index>(i)).setZero();
  if (f.components <= 1) return G;
  const int C = f.components;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(G.rows(), G.cols() * C);
  for (Eigen::Index i = 0; i < G.rows(); ++i) E.block(i, (i % C) * G.cols(), 1, G.cols()) = G.row(i);
  return E;
}

namespace {
Eigen::MatrixXd basisOnFinite(const GenericForm& f, const std::vector<double>& values) {
  const auto n = static_cast<Eigen::Index>(values.size());
  switch (f.form) {
    case DependenceForm::Linear: {
      Eigen::MatrixXd G(n, 1);
      for (Eigen::Index i = 0; i < n; ++i)
        G(i, 0) = (values[static_cast<std::size_t>(i)] - f.centre) / f.scale;
      return G;
    }
    case DependenceForm::Smooth: {
      const auto K = static_cast<Eigen::Index>(f.knots.size());
      Eigen::MatrixXd G(n, K - 1);
      std::vector<double> row(static_cast<std::size_t>(K - 1));
      for (Eigen::Index i = 0; i < n; ++i) {
        splineColumns(f.knots, (values[static_cast<std::size_t>(i)] - f.centre) / f.scale, row.data());
        for (Eigen::Index j = 0; j < K - 1; ++j) G(i, j) = row[static_cast<std::size_t>(j)];
      }
      return G;
    }
    case DependenceForm::Step: {
      Eigen::MatrixXd G(n, 1);
      const double at = f.knots.empty() ? 0.0 : f.knots.front();
      for (Eigen::Index i = 0; i < n; ++i) G(i, 0) = values[static_cast<std::size_t>(i)] > at ? 1.0 : 0.0;
      return G;
    }
    case DependenceForm::Periodic: {
      Eigen::MatrixXd G(n, 2 * f.harmonics);
      for (Eigen::Index i = 0; i < n; ++i) {
        const double v = values[static_cast<std::size_t>(i)];
        const double a = f.period > 0.0 ? 2.0 * kPi * v / f.period : v * kDeg;
        for (int k = 1; k <= f.harmonics; ++k) {
          G(i, 2 * (k - 1)) = std::cos(k * a);
          G(i, 2 * (k - 1) + 1) = std::sin(k * a);
        }
      }
      return G;
    }
    case DependenceForm::Level: {
      Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, std::max(0, f.levels - 1));
      for (Eigen::Index i = 0; i < n; ++i) {
        const double x = values[static_cast<std::size_t>(i)];
        if (!std::isfinite(x)) continue;
        const auto l = static_cast<int>(std::lround(x));
        if (l >= 1 && l < f.levels) G(i, l - 1) = 1.0;
      }
      return G;
    }
  }
  return Eigen::MatrixXd(n, 0);
}
}  // namespace

namespace {
std::optional<FoundPeriod> periodSearch(const Eigen::VectorXd& r, const Eigen::MatrixXd& U, double sse0,
                                        const ResidualVariable& v, const GenericForm& base,
                                        const ResidualCheckOptions& o) {
  if (!std::all_of(v.values.begin(), v.values.end(), [](double x) { return std::isfinite(x); }))
    return std::nullopt;
  const std::vector<double> s = finiteSorted(v.values);
  if (s.size() < 8) return std::nullopt;
  std::vector<double> gaps;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s[i] > s[i - 1]) gaps.push_back(s[i] - s[i - 1]);
  if (gaps.size() < 7) return std::nullopt;
  const double dt = median(gaps);
  const double span = s.back() - s.front();
  // At least three cycles in the data: fewer are a slow wander, not a cycle (with 1.5 the CAIVIAC
  // log's wander was taken as cycles of 395 to 590 min over its fit rows and the held-out error rose).
  constexpr double kMinCycles = 3.0, kStep = 0.25;
  const double maxCycles = std::min<double>(o.periodMaxCycles, span / (4.0 * dt));
  if (!(dt > 0.0) || !(maxCycles >= kMinCycles + 1.0)) return std::nullopt;
  GenericForm f = base;
  f.form = DependenceForm::Periodic;
  f.harmonics = 1;
  f.knots.clear();
  f.subset = false;
  f.withoutLinear = false;
  // The search (grid and refinement) runs on at most kSearchRows evenly strided observations of a long
  // series (the shortest candidate period still spans kSearchRows / maxCycles of them); the test of the
  // period found uses every observation. A week of 1 Hz data otherwise spent most of its time here.
  constexpr Eigen::Index kSearchRows = 20000;
  const Eigen::Index n = r.size();
  Eigen::VectorXd rs;
  Eigen::MatrixXd Us;
  ResidualVariable vs;
  double sse0s = sse0;
  const bool strided = n > 2 * kSearchRows;
  if (strided) {
    const Eigen::Index m = kSearchRows, stride = n / m;
    rs.resize(m);
    Eigen::MatrixXd Um(m, U.cols());
    vs = v;
    vs.values.resize(static_cast<std::size_t>(m));
    if (!v.weights.empty()) vs.weights.resize(static_cast<std::size_t>(m));
    for (Eigen::Index i = 0; i < m; ++i) {
      const Eigen::Index k = i * stride;
      rs(i) = r(k);
      Um.row(i) = U.row(k);
      vs.values[static_cast<std::size_t>(i)] = v.values[static_cast<std::size_t>(k)];
      if (!v.weights.empty())
        vs.weights[static_cast<std::size_t>(i)] = v.weights[static_cast<std::size_t>(k)];
    }
    Us = orthonormalBasis(Um, m, 1);  // U's columns span the intercept; the repeated one is dropped
    rs -= Us * (Us.transpose() * rs);
    sse0s = rs.squaredNorm();
  }
  auto ssrAt = [&](double cycles, FTest* out) {
    f.period = span / cycles;
    FTest t =
        out || !strided ? fTest(r, U, variableBasis(f, v), sse0) : fTest(rs, Us, variableBasis(f, vs), sse0s);
    const double value = t.ok ? t.ssr : -1.0;
    if (out) *out = std::move(t);
    return value;
  };
  double bestC = kMinCycles, bestSsr = -1.0;
  for (double c = kMinCycles; c <= maxCycles + 1e-9; c += kStep) {
    const double q = ssrAt(c, nullptr);
    if (q > bestSsr) bestSsr = q, bestC = c;
  }
  if (!(bestSsr >= 0.0)) return std::nullopt;
  // Golden-section refinement of the number of cycles within one grid step on either side.
  double a = std::max(kMinCycles, bestC - kStep), b = std::min(maxCycles, bestC + kStep);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = ssrAt(x1, nullptr), f2 = ssrAt(x2, nullptr);
  for (int it = 0; it < 30 && b - a > 1e-6 * bestC; ++it) {
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - g * (b - a);
      f1 = ssrAt(x1, nullptr);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + g * (b - a);
      f2 = ssrAt(x2, nullptr);
    }
  }
  const double refined = f1 > f2 ? x1 : x2;
  if (std::max(f1, f2) > bestSsr) bestC = refined;
  FoundPeriod found;
  ssrAt(bestC, &found.test);
  if (!found.test.ok) return std::nullopt;
  found.shape = f;
  found.shape.period = span / bestC;
  // The false-alarm probability of the best of a continuous search (Baluev 2008, for a uniformly
  // sampled span): p (1 + W sqrt(pi z / 3)), z = -ln p, W the band in cycles per span. Bonferroni over
  // the W independent periods alone was measured at 2.5 % false alarms at the nominal 1 %.
  const double W = maxCycles - kMinCycles;
  found.searched = static_cast<int>(std::ceil(W - 1e-9));
  const double p = found.test.p;
  const double z = p > 0.0 ? -std::log(p) : 700.0;
  found.test.p = std::min(1.0, p * (1.0 + W * std::sqrt(kPi * z / 3.0)));
  return found;
}
}  // namespace

std::optional<PeriodSearch> searchPeriod(const Eigen::VectorXd& residual, const Eigen::MatrixXd& modelColumns,
                                         const std::vector<double>& values,
                                         const ResidualCheckOptions& options) {
  const Eigen::Index n = residual.size();
  if (n < 8 || values.size() != static_cast<std::size_t>(n)) return std::nullopt;
  const Eigen::MatrixXd U = orthonormalBasis(modelColumns, n, 1);
  const Eigen::VectorXd r = residual - U * (U.transpose() * residual);
  ResidualVariable v;
  v.values = values;
  GenericForm base;
  const std::optional<FoundPeriod> f = periodSearch(r, U, r.squaredNorm(), v, base, options);
  if (!f) return std::nullopt;
  return PeriodSearch{f->shape.period, f->test.F, f->test.p, f->searched, f->test.ssr};
}

Eigen::MatrixXd variableBasis(const GenericForm& form, const ResidualVariable& v) {
  Eigen::MatrixXd G = genericBasis(form, v.values);
  if (v.weights.size() == static_cast<std::size_t>(G.rows()))
    for (Eigen::Index i = 0; i < G.rows(); ++i) G.row(i) *= v.weights[static_cast<std::size_t>(i)];
  return G;
}

std::vector<GenericForm> candidateForms(const ResidualVariable& v, const ResidualCheckOptions& o) {
  std::vector<GenericForm> out;
  const std::vector<double> s = finiteSorted(v.values);
  if (s.size() < 4) return out;
  const std::size_t distinct = distinctCount(s);
  if (distinct < 2) return out;
  GenericForm base;
  base.against = v.name;
  base.subset = s.size() < v.values.size();
  switch (v.kind) {
    case ResidualVariable::Kind::Category: {
      base.form = DependenceForm::Level;
      base.levels =
          static_cast<int>(std::max<std::size_t>(v.levels.size(), static_cast<std::size_t>(s.back()) + 1));
      if (base.levels >= 2 && distinct >= 2) out.push_back(base);
      return out;
    }
    case ResidualVariable::Kind::Angle: {
      base.form = DependenceForm::Periodic;
      base.harmonics = std::min<int>(o.harmonics, static_cast<int>(distinct / 4));
      if (base.harmonics >= 1) out.push_back(base);
      return out;
    }
    case ResidualVariable::Kind::Continuous:
      break;
  }
  base.centre = quantileSorted(s, 0.5);
  base.scale = std::max(s.back() - s.front(), 1e-300);
  GenericForm lin = base;
  lin.form = DependenceForm::Linear;
  out.push_back(lin);
  if (distinct >= 6) {
    GenericForm sm = base;
    sm.form = DependenceForm::Smooth;
    const int K = std::min<int>(o.splineKnots, static_cast<int>(distinct / 2));
    // Knots at equally spaced quantiles with the boundary knots at the extremes (with Harrell's 5 % /
    // 95 % boundaries the spline is linear near the ends of the range, and a quadratic bow of a
    // straightness error left a remainder that a named cyclic error took up in the study).
    std::vector<double> knots;
    for (int j = 0; j < K; ++j) {
      const double q = static_cast<double>(j) / (K - 1);
      knots.push_back((quantileSorted(s, q) - base.centre) / base.scale);
    }
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    if (knots.size() >= 3) {
      sm.knots = knots;
      out.push_back(sm);
    }
  }
  if (distinct >= 3) {
    // Change points midway between neighbouring distinct values at quantiles 5 % .. 95 %.
    std::set<double> seen;
    for (int j = 0; j < o.stepPositions; ++j) {
      const double q = o.stepPositions == 1 ? 0.5 : 0.05 + 0.90 * j / (o.stepPositions - 1);
      const double x = quantileSorted(s, q);
      const auto hi = std::upper_bound(s.begin(), s.end(), x);
      if (hi == s.end()) continue;
      const auto lo = std::lower_bound(s.begin(), s.end(), x);
      const double at = 0.5 * (*lo + *hi);
      if (!seen.insert(at).second) continue;
      GenericForm st = base;
      st.form = DependenceForm::Step;
      st.knots = {at};
      out.push_back(st);
    }
  }
  return out;
}

namespace {
/// P(a run of R or more | m exceedances among N) <= (N - R + 1) prod_{j<R} (m - j) / (N - j).
double runBound(std::size_t N, std::size_t m, std::size_t R) {
  if (R < 2 || R > m || R > N) return 1.0;
  double b = static_cast<double>(N - R + 1);
  for (std::size_t j = 0; j < R && b > 0.0; ++j) b *= static_cast<double>(m - j) / static_cast<double>(N - j);
  return std::min(1.0, b);
}
}  // namespace

ResidualTest blockTest(const ResidualCheckInput& in, const std::vector<double>& order,
                       const std::string& name, double blockZ, double listBelow,
                       std::vector<ResidualBlock>* blocks) {
  ResidualTest t;
  t.name = "block";
  t.against = name;
  const auto n = static_cast<std::size_t>(in.residual.size());
  if (n < 8 || order.size() != n) return t;
  std::vector<double> r(in.residual.data(), in.residual.data() + n);
  const double med = median(r);
  std::vector<double> dev(n);
  for (std::size_t i = 0; i < n; ++i) dev[i] = std::abs(r[i] - med);
  const double sd = 1.4826 * median(dev);
  if (!(sd > 0.0)) return t;
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return order[a] < order[b]; });
  const int C = std::max(1, in.components);
  const double correction = 2.0 * C;
  double best = 1.0;
  for (int c = 0; c < C; ++c) {
    std::vector<std::size_t> seq;  // the coordinate's observations in the order
    for (std::size_t i : idx)
      if (static_cast<int>(i % static_cast<std::size_t>(C)) == c) seq.push_back(i);
    const std::size_t N = seq.size();
    for (const double sign : {1.0, -1.0}) {
      std::size_t m = 0;
      for (std::size_t i : seq) m += sign * (r[i] - med) / sd > blockZ;
      // Every run of exceedances: its start and length.
      std::vector<std::pair<std::size_t, std::size_t>> runs;
      for (std::size_t k = 0; k < N;) {
        if (!(sign * (r[seq[k]] - med) / sd > blockZ)) {
          ++k;
          continue;
        }
        std::size_t e = k;
        while (e < N && sign * (r[seq[e]] - med) / sd > blockZ) ++e;
        runs.emplace_back(k, e - k);
        k = e;
      }
      for (const auto& [start, len] : runs) {
        const double p = std::min(1.0, correction * runBound(N, m, len));
        if (len >= 2 && p < best) {
          best = p;
          t.statistic = static_cast<double>(len);
          t.dof = static_cast<int>(m);
        }
        if (!blocks || len < 2 || !(p <= listBelow)) continue;
        ResidualBlock b;
        b.order = name;
        b.component = c;
        b.p = p;
        for (std::size_t k = start; k < start + len; ++k) {
          const std::size_t i = seq[k];
          const std::size_t u = in.unitOf.empty() ? i : in.unitOf[i];
          b.units.push_back(u);
          b.rows.push_back(u < in.unitRow.size() ? in.unitRow[u] : static_cast<long>(u) + 1);
          b.meanZ += (r[i] - med) / sd / static_cast<double>(len);
        }
        blocks->push_back(std::move(b));
      }
    }
  }
  t.p = best;
  return t;
}

std::vector<Outlier> findOutliers(const ResidualCheckInput& in, const ResidualCheckOptions& o,
                                  double* threshold) {
  std::vector<Outlier> out;
  const auto n = static_cast<std::size_t>(in.residual.size());
  if (n < 8) {
    if (threshold) *threshold = std::numeric_limits<double>::infinity();
    return out;
  }
  std::vector<double> r(in.residual.data(), in.residual.data() + n);
  const double med = median(r);
  std::vector<double> dev(n);
  for (std::size_t i = 0; i < n; ++i) dev[i] = std::abs(r[i] - med);
  const double mad = 1.4826 * median(dev);
  const boost::math::normal_distribution<double> N;
  const double z =
      o.outlierFactor * boost::math::quantile(boost::math::complement(N, 0.005 / static_cast<double>(n)));
  if (threshold) *threshold = z;
  if (!o.detectOutliers || !(mad > 0.0)) return out;
  std::map<std::size_t, std::pair<double, double>> worst;  // unit -> (z, residual)
  std::size_t units = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t u = in.unitOf.empty() ? i : in.unitOf[i];
    units = std::max(units, u + 1);
    const double zi = dev[i] / mad;
    if (zi > z) {
      auto it = worst.find(u);
      if (it == worst.end() || it->second.first < zi) worst[u] = {zi, r[i]};
    }
  }
  const auto limit =
      std::max<std::size_t>(1, static_cast<std::size_t>(o.maxOutlierFraction * static_cast<double>(units)));
  if (worst.size() > limit) return out;
  for (const auto& [u, zr] : worst) {
    Outlier x;
    x.unit = u;
    if (u < in.unitRow.size()) x.row = in.unitRow[u];
    if (u < in.unitPart.size() && !in.unitPart[u].empty()) x.part = in.unitPart[u];
    if (u < in.unitDimension.size() && !in.unitDimension[u].empty()) x.dimension = in.unitDimension[u];
    if (u < in.unitId.size() && !in.unitId[u].empty()) x.id = in.unitId[u];
    x.residual = zr.second;
    x.robustZ = zr.first;
    out.push_back(std::move(x));
  }
  std::sort(out.begin(), out.end(), [](const Outlier& a, const Outlier& b) { return a.robustZ > b.robustZ; });
  return out;
}

ResidualCheck checkResidual(const ResidualCheckInput& in, const ResidualCheckOptions& o) {
  ResidualCheck c;
  c.level = o.level;
  const Eigen::Index n = in.residual.size();
  c.observations = static_cast<std::size_t>(n);
  if (n < 8) {
    c.summaryParts = {Phrase("too few observations (%1) to test the residual", {A::integer(n)})};
    c.summary = english(c.summaryParts);
    return c;
  }
  const Eigen::MatrixXd U = orthonormalBasis(in.modelColumns, n, in.components);
  // The residual of the model refitted on [1, J] (it is already orthogonal to J; the intercept may
  // not be in the model): project once more so the tests' algebra holds exactly.
  Eigen::VectorXd w = in.residual;
  if (o.winsorZ > 0.0) {
    std::vector<double> v(w.data(), w.data() + n);
    const double med = median(v);
    for (double& x : v) x = std::abs(x - med);
    const double sd = 1.4826 * median(v);
    if (sd > 0.0)
      for (Eigen::Index i = 0; i < n; ++i)
        w(i) = std::clamp(w(i), med - o.winsorZ * sd, med + o.winsorZ * sd);
  }
  const Eigen::VectorXd r = w - U * (U.transpose() * w);
  const double sse0 = r.squaredNorm();

  struct Found {
    std::size_t variable;
    GenericForm shape;
    FTest test;
    std::size_t testIndex;
  };
  std::vector<Found> found;
  std::vector<std::pair<std::size_t, std::vector<ResidualBlock>>> blockRuns;  // test index, its runs
  for (std::size_t vi = 0; vi < in.variables.size(); ++vi) {
    const ResidualVariable& v = in.variables[vi];
    if (v.values.size() != static_cast<std::size_t>(n)) continue;
    if (v.naturalOrder &&
        std::all_of(v.values.begin(), v.values.end(), [](double x) { return std::isfinite(x); })) {
      c.tests.push_back(ljungBox(r, v.values, o.maxLag, v.name));
      if (o.blockZ > 0.0) {
        std::vector<ResidualBlock> runs;
        c.tests.push_back(blockTest(in, v.values, v.name, o.blockZ, 1.0, &runs));
        blockRuns.emplace_back(c.tests.size() - 1, std::move(runs));
      }
    }
    std::vector<GenericForm> forms = candidateForms(v, o);
    for (GenericForm& f : forms) f.components = std::max(1, in.components);
    // Steps: the best change point of the search, Bonferroni-corrected for the positions tried.
    std::optional<Found> bestStep;
    int steps = 0;
    for (const GenericForm& f : forms) {
      const FTest t = fTest(r, U, variableBasis(f, v), sse0);
      if (!t.ok) continue;
      if (f.form == DependenceForm::Step) {
        ++steps;
        if (!bestStep || t.p < bestStep->test.p) bestStep = Found{vi, f, t, 0};
        continue;
      }
      ResidualTest rt;
      rt.name = "f_test";
      rt.against = v.name;
      rt.form = formName(f.form);
      rt.statistic = t.F;
      rt.p = t.p;
      rt.dof = t.q;
      c.tests.push_back(rt);
      found.push_back({vi, f, t, c.tests.size() - 1});
    }
    // Periodic with an unknown period (ordered continuous variables), corrected for the search.
    if (o.periodSearch && v.kind == ResidualVariable::Kind::Continuous && v.naturalOrder) {
      GenericForm base;
      base.against = v.name;
      base.components = std::max(1, in.components);
      if (std::optional<FoundPeriod> pf = periodSearch(r, U, sse0, v, base, o)) {
        ResidualTest rt;
        rt.name = "f_test";
        rt.against = v.name;
        rt.form = "periodic";
        rt.statistic = pf->test.F;
        rt.p = pf->test.p;
        rt.dof = pf->test.q;
        c.tests.push_back(rt);
        found.push_back({vi, pf->shape, pf->test, c.tests.size() - 1});
      }
    }
    if (bestStep) {
      bestStep->test.p = std::min(1.0, bestStep->test.p * steps);
      ResidualTest rt;
      rt.name = "f_test";
      rt.against = v.name;
      rt.form = "step";
      rt.statistic = bestStep->test.F;
      rt.p = bestStep->test.p;
      rt.dof = bestStep->test.q;
      c.tests.push_back(rt);
      bestStep->testIndex = c.tests.size() - 1;
      found.push_back(*bestStep);
    }
  }
  // Holm's step-down procedure at the family-wise level.
  std::vector<std::size_t> order(c.tests.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return c.tests[a].p < c.tests[b].p; });
  const std::size_t m = c.tests.size();
  for (std::size_t k = 0; k < m; ++k) {
    if (c.tests[order[k]].p <= o.level / static_cast<double>(m - k))
      c.tests[order[k]].rejected = true;
    else
      break;
  }
  c.white = std::none_of(c.tests.begin(), c.tests.end(), [](const ResidualTest& t) { return t.rejected; });

  // Blocks: the runs of a rejected block test with a corrected bound at most level / tests, each
  // once (the same observations may form a block in two orders, e.g. row and time).
  for (auto& [ti, runs] : blockRuns) {
    if (!c.tests[ti].rejected) continue;
    for (ResidualBlock& b : runs) {
      if (!(b.p <= o.level / static_cast<double>(std::max<std::size_t>(1, m)))) continue;
      std::vector<std::size_t> key = b.units;
      std::sort(key.begin(), key.end());
      const bool seen = std::any_of(c.blocks.begin(), c.blocks.end(), [&](const ResidualBlock& x) {
        std::vector<std::size_t> k2 = x.units;
        std::sort(k2.begin(), k2.end());
        return k2 == key && x.component == b.component;
      });
      if (!seen) c.blocks.push_back(std::move(b));
    }
  }
  std::stable_sort(c.blocks.begin(), c.blocks.end(), [](const ResidualBlock& a, const ResidualBlock& b) {
    return a.units.size() > b.units.size() || (a.units.size() == b.units.size() && a.p < b.p);
  });

  // Structure: per variable, its strongest rejected form.
  std::map<std::size_t, const Found*> perVariable;
  for (const Found& f : found) {
    if (!c.tests[f.testIndex].rejected) continue;
    auto it = perVariable.find(f.variable);
    if (it == perVariable.end() || f.test.p < it->second->test.p ||
        (f.test.p == it->second->test.p && f.test.ssr > it->second->test.ssr))
      perVariable[f.variable] = &f;
  }
  for (const auto& [vi, f] : perVariable) {
    StructureItem s;
    s.against = in.variables[vi].name;
    s.form = f->shape.form;
    s.p = f->test.p;
    s.share = sse0 > 0.0 ? f->test.ssr / sse0 : 0.0;
    s.shape = f->shape;
    c.structure.push_back(std::move(s));
  }
  std::stable_sort(c.structure.begin(), c.structure.end(),
                   [](const StructureItem& a, const StructureItem& b) { return a.share > b.share; });

  // Text.
  if (c.white) {
    c.summaryParts = {Phrase("white: no test finds structure at the %1 % family-wise level (%2 tests)",
                             {A::number(100.0 * o.level, 3), A::integer(static_cast<long long>(m))})};
  } else if (!c.structure.empty()) {
    c.summaryParts = {Phrase("not white: still depends on ")};
    for (std::size_t i = 0; i < c.structure.size() && i < 3; ++i) {
      if (i > 0) c.summaryParts.push_back(Phrase(", "));
      c.summaryParts.push_back(
          Phrase("%1 (%2, %3 % of the residual variance)",
                 {A::name(c.structure[i].against), A::text({formPhrase(c.structure[i].form)}),
                  A::number(100.0 * c.structure[i].share, 2)}));
    }
    if (c.structure.size() > 3)
      c.summaryParts.push_back(
          Phrase(" and %1 more", {A::integer(static_cast<long long>(c.structure.size() - 3))}));
  } else {
    const auto lb = std::find_if(c.tests.begin(), c.tests.end(),
                                 [](const ResidualTest& t) { return t.rejected && t.name == "ljung_box"; });
    if (lb != c.tests.end())
      c.summaryParts = {Phrase("not white: serially correlated in %1 order (Ljung-Box p = %2)",
                               {A::name(lb->against), A::number(lb->p, 2)})};
    else
      c.summaryParts = {Phrase("not white")};
  }
  if (!c.blocks.empty()) {
    const ResidualBlock& b = c.blocks.front();
    c.summaryParts.push_back(
        Phrase("; %1 consecutive observations in %2 order off the rest (rows %3 to %4, mean robust z %5)",
               {A::integer(static_cast<long long>(b.units.size())), A::name(b.order),
                A::integer(b.rows.front()), A::integer(b.rows.back()), A::number(b.meanZ, 3)}));
    if (c.blocks.size() > 1)
      c.summaryParts.push_back(
          Phrase(" and %1 more blocks", {A::integer(static_cast<long long>(c.blocks.size() - 1))}));
  }
  c.summary = english(c.summaryParts);

  // Plot of the strongest structure: the residual and the generic fit (on [1, G]).
  if (!c.structure.empty()) {
    const StructureItem& s = c.structure.front();
    const auto vit = std::find_if(in.variables.begin(), in.variables.end(),
                                  [&](const ResidualVariable& v) { return v.name == s.against; });
    const ResidualVariable& v = *vit;
    const Eigen::MatrixXd G = variableBasis(s.shape, v);
    const int C = std::max(1, in.components);
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, G.cols() + C);
    for (Eigen::Index i = 0; i < n; ++i) X(i, i % C) = 1.0;
    X.rightCols(G.cols()) = G;
    const Eigen::VectorXd b = X.colPivHouseholderQr().solve(in.residual);
    const Eigen::VectorXd fit = X * b;
    ResidualCheck::Plot p;
    p.against = v.name;
    p.xLabel = v.label.empty() ? Phrases{Phrase("%1", {A::name(v.name)})} : v.label;
    // Observations where the variable does not apply (NaN) are not drawn.
    for (Eigen::Index i = 0; i < n; ++i) {
      const double xv = v.values[static_cast<std::size_t>(i)];
      if (!std::isfinite(xv)) continue;
      p.x.push_back(xv);
      p.residual.push_back(in.residual(i));
      p.fit.push_back(fit(i));
    }
    p.categories = v.levels;
    p.components = C;
    const std::size_t vi = static_cast<std::size_t>(vit - in.variables.begin());
    if (vi < in.excludedValues.size())
      for (std::size_t k = 0; k < in.excludedResidual.size() && k < in.excludedValues[vi].size(); ++k) {
        if (!std::isfinite(in.excludedValues[vi][k])) continue;
        p.outlierX.push_back(in.excludedValues[vi][k]);
        p.outlierResidual.push_back(in.excludedResidual[k]);
      }
    c.plot = std::move(p);
  }
  return c;
}

GenericSummary summariseContribution(const GenericForm& f, Eigen::VectorXd contribution,
                                     const std::string& unit) {
  GenericSummary s;
  if (contribution.size() > 0) contribution.array() -= contribution.mean();
  const double rms = contribution.size()
                         ? std::sqrt(contribution.squaredNorm() / static_cast<double>(contribution.size()))
                         : 0.0;
  const double range = contribution.size() ? contribution.maxCoeff() - contribution.minCoeff() : 0.0;
  const std::string u = unit.empty() ? "" : " " + unit;
  s.numbers = {{"rms", rms}, {"range", range}};
  s.text = {Phrase("%1 in %2, rms %3%4, range %5%4", {A::text({formPhrase(f.form)}), A::name(f.against),
                                                      A::number(rms, 3), A::unit(u), A::number(range, 3)})};
  return s;
}

GenericSummary summariseGeneric(const GenericForm& f, const Eigen::VectorXd& b,
                                const std::vector<double>& values, const std::string& unit) {
  GenericSummary s = summariseContribution(f, genericBasis(f, values) * b, unit);
  const std::string u = unit.empty() ? "" : " " + unit;
  Phrases text = std::move(s.text);
  if (f.form == DependenceForm::Step && b.size() == 1) {
    s.numbers.push_back({"at", f.knots.front()});
    s.numbers.push_back({"step", b(0)});
    text.push_back(
        Phrase(", step %1%2 at %3", {A::signedNumber(b(0), 3), A::unit(u), A::number(f.knots.front(), 4)}));
  } else if (f.form == DependenceForm::Periodic) {
    int bestK = 1;
    double bestAmp = 0.0;
    for (int k = 1; k <= f.harmonics && 2 * k <= b.size(); ++k) {
      const double amp = std::hypot(b(2 * (k - 1)), b(2 * (k - 1) + 1));
      if (amp > bestAmp) bestAmp = amp, bestK = k;
    }
    s.numbers.push_back({"harmonic", bestK});
    s.numbers.push_back({"amplitude", bestAmp});
    if (f.period > 0.0) {
      s.numbers.push_back({"period", f.period});
      text.push_back(
          Phrase(", period %1, amplitude %2%3", {A::number(f.period, 4), A::number(bestAmp, 3), A::unit(u)}));
    } else {
      text.push_back(Phrase(", strongest harmonic %1 (amplitude %2%3)",
                            {A::integer(bestK), A::number(bestAmp, 3), A::unit(u)}));
    }
  }
  s.text = std::move(text);
  return s;
}

std::vector<GenericForm> genericCandidates(const ResidualCheck& check, const std::vector<std::string>& taken,
                                           std::size_t count) {
  std::vector<GenericForm> out;
  for (const StructureItem& s : check.structure) {
    if (out.size() >= count) break;
    if (std::find(taken.begin(), taken.end(), s.against) != taken.end()) continue;
    out.push_back(s.shape);
  }
  return out;
}

double genericSearchPenalty(const ResidualCheck& check) {
  const auto searched = std::count_if(check.tests.begin(), check.tests.end(),
                                      [](const ResidualTest& t) { return t.name != "block"; });
  return 2.0 * std::log(std::max<double>(2.0, static_cast<double>(searched)));
}

const ResidualVariable* findVariable(const std::vector<ResidualVariable>& variables,
                                     const std::string& name) {
  for (const ResidualVariable& v : variables)
    if (v.name == name) return &v;
  return nullptr;
}

nlohmann::json toJson(const ResidualCheck& c) {
  nlohmann::json tests = nlohmann::json::array();
  for (const ResidualTest& t : c.tests) {
    nlohmann::json j = {
        {"name", t.name}, {"statistic", t.statistic}, {"p", t.p}, {"dof", t.dof}, {"rejected", t.rejected}};
    if (t.name == "ljung_box" || t.name == "block")
      j["order"] = t.against;
    else {
      j["against"] = t.against;
      j["form"] = t.form;
    }
    tests.push_back(std::move(j));
  }
  nlohmann::json structure = nlohmann::json::array();
  for (const StructureItem& s : c.structure) {
    nlohmann::json j = {{"against", s.against}, {"form", formName(s.form)}, {"p", s.p}, {"share", s.share}};
    if (s.form == DependenceForm::Step && !s.shape.knots.empty()) j["at"] = s.shape.knots.front();
    if (s.form == DependenceForm::Periodic && s.shape.period > 0.0) j["period"] = s.shape.period;
    structure.push_back(std::move(j));
  }
  nlohmann::json outliers = nlohmann::json::array();
  for (const Outlier& o : c.outliers) {
    nlohmann::json j = {{"row", o.row ? nlohmann::json(*o.row) : nlohmann::json(nullptr)},
                        {"residual", o.residual},
                        {"robust_z", o.robustZ}};
    if (o.part) j["part"] = *o.part;
    if (o.dimension) j["dimension"] = *o.dimension;
    j["id"] = o.id ? nlohmann::json(*o.id) : nlohmann::json(nullptr);
    outliers.push_back(std::move(j));
  }
  nlohmann::json blocks = nlohmann::json::array();
  for (const ResidualBlock& b : c.blocks)
    blocks.push_back({{"order", b.order},
                      {"component", b.component},
                      {"rows", b.rows},
                      {"length", b.units.size()},
                      {"mean_robust_z", b.meanZ},
                      {"p", b.p}});
  nlohmann::json j = {{"white", c.white},
                      {"level", c.level},
                      {"tests", tests},
                      {"structure", structure},
                      {"outliers", outliers},
                      {"outlier_threshold", c.outlierThreshold},
                      {"observations", c.observations},
                      {"summary", c.summary}};
  if (!blocks.empty()) j["blocks"] = std::move(blocks);
  return j;
}

}  // namespace metrofit::diagnose
