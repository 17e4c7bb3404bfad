#include "core/diagnose/thermal_diagnosis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <Eigen/Dense>

#include "core/common/error.h"
#include "core/diagnose/thermal_applied.h"
#include "core/io/csv.h"
#include "core/sim/effects_thermal.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::diagnose {
namespace {

using A = PhraseArg;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(double v, int digits = 3) {
  return std::isfinite(v) ? CsvWriter::formatNumber(v, digits) : "n/a";
}

/// fmt() as a phrase argument ("n/a" when not finite).
PhraseArg num(double v, int digits = 3) {
  return A::numberOrNa(v, digits);
}

/// The relative change in percent ("+5.2 %", "-90 %" or "n/a").
PhraseArg pct(double before, double after) {
  if (!(before > 0.0)) return A::text({Phrase("n/a")});
  const double p = 100.0 * (after - before) / before;
  return A::text({Phrase("%1 %", {A::signedNumber(p, 2)})});
}

/// The model state: the declared inputs plus the accepted effects (thermal_applied.h, shared with
/// every fit of the thermal study that includes applied effects).
struct State {
  ThermalEffectSet effects;
};

bool operator==(const State& a, const State& b) {
  return a.effects.lagAll == b.effects.lagAll && a.effects.lagCol == b.effects.lagCol &&
         a.effects.extra == b.effects.extra && a.effects.drift == b.effects.drift;
}

/// One model state per view: views 0..K-1 are the validation folds, view K the fit on all fit rows.
using Views = std::vector<State>;

/// Gram matrices of the standardised columns [1, z_1..z_p, y - ybar] per block of rows.
struct Grams {
  bool ok = false;
  Phrase why;
  std::vector<std::string> names;  ///< column names (without the intercept)
  Eigen::VectorXd mean, sd;        ///< per column, on the fit rows
  double ybar = 0.0;               ///< target mean on the fit rows
  std::vector<Eigen::MatrixXd> block;
};

/// Least squares from a Gram matrix (the sum of some blocks' Grams).
struct Solution {
  bool ok = false;
  int rank = 0;
  Eigen::VectorXd b;    ///< intercept, then the standardised columns
  Eigen::MatrixXd inv;  ///< (X^T X)^+ (for standard errors)
  double sse = 0.0;
};

Solution solveGram(const Eigen::MatrixXd& G) {
  Solution s;
  const Eigen::Index q = G.rows() - 1;
  const Eigen::MatrixXd Gxx = G.topLeftCorner(q, q);
  const Eigen::VectorXd Gxy = G.col(q).head(q);
  // Jacobi scaling, then the pseudo-inverse of the correlation-like matrix (rank = eigenvalues above
  // 1e-11 of the largest: singular values of the scaled design above ~3e-6).
  Eigen::VectorXd d(q);
  for (Eigen::Index j = 0; j < q; ++j) d(j) = Gxx(j, j) > 0.0 ? 1.0 / std::sqrt(Gxx(j, j)) : 0.0;
  const Eigen::MatrixXd S = d.asDiagonal() * Gxx * d.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
  const Eigen::VectorXd& ev = es.eigenvalues();
  const double top = ev.size() ? ev.maxCoeff() : 0.0;
  Eigen::VectorXd invEv = Eigen::VectorXd::Zero(q);
  for (Eigen::Index j = 0; j < q; ++j)
    if (ev(j) > 1e-11 * top && top > 0.0) {
      invEv(j) = 1.0 / ev(j);
      ++s.rank;
    }
  const Eigen::MatrixXd Sinv = es.eigenvectors() * invEv.asDiagonal() * es.eigenvectors().transpose();
  s.inv = d.asDiagonal() * Sinv * d.asDiagonal();
  s.b = s.inv * Gxy;
  s.sse = std::max(0.0, G(q, q) - s.b.dot(Gxy));
  s.ok = true;
  return s;
}

/// Sum of squares of the prediction with coefficients b on a block with Gram G.
double sseOn(const Eigen::MatrixXd& G, const Eigen::VectorXd& b) {
  const Eigen::Index q = G.rows() - 1;
  return std::max(0.0, G(q, q) - 2.0 * b.dot(G.col(q).head(q)) + b.dot(G.topLeftCorner(q, q) * b));
}

struct Fit {
  bool ok = false;
  Phrase why;                       ///< when not ok
  double rmse = 0.0;                ///< fit rows
  double heldout = 0.0;             ///< held-out rows (reported only)
  double sse = 0.0, s2 = 0.0;       ///< fit rows
  double cv = kInf;                 ///< blocked validation rmse (fit rows only)
  bool cvOk = false;
  std::vector<std::string> names;   ///< column names (without the intercept)
  Eigen::VectorXd beta, se;         ///< per column, original units
  // For residuals: standardised coefficients and the scaling.
  Eigen::VectorXd coef, mean, sd;
  double ybar = 0.0;
};

/// A fit's residual on every row (y - prediction) and its summaries.
struct Residual {
  std::vector<double> r;
  double maxAbs = 0.0;  ///< fit rows
};

class Problem {
 public:
  Problem(const ThermalLog& log, const ThermalDiagnosisOptions& o) : log_(log), o_(o) {
    y_ = log.channel(o.target).values;
    n_ = log.rows();
    nFit_ = thermal::fitRowCount(n_, o.trainFraction);
    const int K = o.validationFolds;
    edge_.push_back(0);
    for (int f = 1; f <= K; ++f)
      edge_.push_back(static_cast<std::size_t>(
          std::llround(static_cast<double>(nFit_) * (K + f - 1) / (2.0 * K))));
    edge_.push_back(nFit_);
    edge_.push_back(n_);
    // The median step of the fit rows (the lag search's lower end).
    std::vector<double> d;
    for (std::size_t k = 1; k < nFit_; ++k) d.push_back(log_.timeMin[k] - log_.timeMin[k - 1]);
    if (d.empty()) d.push_back(1.0);
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    medianStep_ = d[d.size() / 2];
  }

  std::size_t rows() const { return n_; }
  std::size_t fitRows() const { return nFit_; }
  int folds() const { return o_.validationFolds; }
  int views() const { return o_.validationFolds + 1; }
  int fullView() const { return o_.validationFolds; }
  const std::vector<double>& time() const { return log_.timeMin; }
  double medianStep() const { return medianStep_; }

  bool grey() const { return o_.declared != ThermalDeclaredModel::Linear; }
  /// Views whose columns are the same for the same state share this key (GramSet).
  int columnsKey(int view) const { return grey() ? view : 0; }

  /// Fits the declared grey model once per view (see the header comment). False when the observer
  /// stopped a training. ValidationError when the model cannot be fitted on the fit rows.
  bool fitDeclared(Observer* observer) {
    if (!grey()) return true;
    const thermal::ThermalSeries series = thermal::selectThermalSeries(log_, o_.target, o_.inputs);
    thermal::ThermalFitOptions fo;
    fo.model = o_.declared == ThermalDeclaredModel::Gmc ? thermal::ThermalModelKind::Gmc
                                                        : thermal::ThermalModelKind::Gnnmci;
    fo.setSeed(o_.seed);
    bool stopped = false;
    // The trainings' progress reaches the observer with component "declared_fit"; its Stop stops them.
    FunctionObserver relay([&](const IterationSummary& it) {
      if (!observer) return ObserverDecision::Continue;
      IterationSummary s = it;
      s.evaluations = 0;
      s.components = {{"declared_fit", it.best}};
      if (observer->onIteration(s) == ObserverDecision::Stop) stopped = true;
      return stopped ? ObserverDecision::Stop : ObserverDecision::Continue;
    });
    pred_.assign(static_cast<std::size_t>(views()), {});
    // The fit on all fit rows first (its errors are the user's), then one per fold.
    for (int v = views() - 1; v >= 0 && !stopped; --v) {
      const std::size_t rows = v == fullView() ? nFit_ : edge_[static_cast<std::size_t>(v) + 1];
      std::vector<double> p;
      try {
        const thermal::ThermalTraining t = thermal::fitThermalModel({series.head(rows)}, fo, &relay);
        if (stopped) break;
        p = thermal::predictTarget(t.model, series);
        if (v == fullView()) declaredTraining_ = t;
      } catch (const std::exception& e) {
        if (v == fullView()) {
          if (dynamic_cast<const InputError*>(&e)) throw;
          throw ValidationError(ErrorContext{log_.source, 0, 0, o_.target},
                                std::string("the declared model cannot be fitted: ") + e.what());
        }
        continue;  // this fold cannot validate
      }
      const bool finite = std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); });
      if (!finite) {
        if (v == fullView())
          throw ValidationError(ErrorContext{log_.source, 0, 0, o_.target},
                                std::string("the declared ") + toString(o_.declared) +
                                    " model is unstable on the fit rows (b1 <= 0): its prediction is not finite");
        continue;
      }
      pred_[static_cast<std::size_t>(v)] = std::move(p);
    }
    return !stopped;
  }

  /// The declared grey model fitted on all fit rows, and its own rmse on the fit and held-out rows.
  const thermal::ThermalTraining& declaredTraining() const { return declaredTraining_; }
  std::pair<double, double> declaredOwnRmse() const {
    const auto& p = pred_[static_cast<std::size_t>(fullView())];
    double a = 0.0, b = 0.0;
    for (std::size_t k = 0; k < n_; ++k) (k < nFit_ ? a : b) += (y_[k] - p[k]) * (y_[k] - p[k]);
    return {std::sqrt(a / static_cast<double>(nFit_)), std::sqrt(b / static_cast<double>(n_ - nFit_))};
  }

  /// The columns of a model state (without the intercept) on every row (empty when the view's grey
  /// model could not be fitted).
  std::vector<ThermalRegressor> columns(const State& s, int view) const {
    if (!grey()) return thermalRegressors(log_, o_.inputs, s.effects);
    std::vector<ThermalRegressor> out;
    const auto& p = pred_[static_cast<std::size_t>(view)];
    if (p.empty()) return out;
    ThermalRegressor g;
    g.name = g.channel = "declared";
    g.unit = log_.channel(o_.target).unit;
    g.values = p;
    out.push_back(std::move(g));
    for (const auto& [col, tau] : s.effects.lagCol) {
      ThermalRegressor r;
      r.name = r.channel = "lag:" + col;
      r.unit = log_.channel(col).unit;
      r.lagMin = tau;
      r.values = firstOrderLag(log_.channel(col).values, log_.timeMin, tau);
      out.push_back(std::move(r));
    }
    ThermalEffectSet rest = s.effects;
    rest.lagAll = 0.0;
    rest.lagCol.clear();
    for (ThermalRegressor& r : thermalRegressors(log_, {}, rest)) out.push_back(std::move(r));
    return out;
  }

  /// The block Grams of a state in a view.
  Grams grams(const State& s, int view) const {
    Grams g;
    std::vector<std::vector<double>> cols;
    for (ThermalRegressor& r : columns(s, view)) {
      cols.push_back(std::move(r.values));
      g.names.push_back(std::move(r.name));
    }
    if (cols.empty()) return g;  // a fold whose grey model could not be fitted
    const auto p = static_cast<Eigen::Index>(cols.size());
    const auto nf = static_cast<Eigen::Index>(nFit_);
    if (nf < p + 3) {
      g.why = Phrase("too few fit rows (%1) for %2 coefficients",
                     {A::integer(static_cast<long long>(nFit_)), A::integer(p + 1)});
      return g;
    }
    // Centre and scale every column on the fit rows (conditioning); the intercept absorbs the means.
    g.mean.resize(p);
    g.sd.resize(p);
    for (Eigen::Index j = 0; j < p; ++j) {
      const auto& c = cols[static_cast<std::size_t>(j)];
      double s = 0.0;
      for (std::size_t k = 0; k < nFit_; ++k) s += c[k];
      g.mean(j) = s / static_cast<double>(nf);
      double v = 0.0;
      for (std::size_t k = 0; k < nFit_; ++k) v += (c[k] - g.mean(j)) * (c[k] - g.mean(j));
      g.sd(j) = std::sqrt(v / static_cast<double>(nf));
      if (!(g.sd(j) > 1e-12 * std::max(1.0, std::abs(g.mean(j))))) {
        g.why = Phrase("column '%1' is constant on the fit rows",
                       {A::name(g.names[static_cast<std::size_t>(j)])});
        return g;
      }
    }
    {
      double s = 0.0;
      for (std::size_t k = 0; k < nFit_; ++k) s += y_[k];
      g.ybar = s / static_cast<double>(nf);
    }
    const Eigen::Index q = p + 2;
    constexpr Eigen::Index kChunk = 2048;
    Eigen::MatrixXd V(kChunk, q);
    for (std::size_t b = 0; b + 1 < edge_.size(); ++b) {
      Eigen::MatrixXd G = Eigen::MatrixXd::Zero(q, q);
      for (std::size_t k0 = edge_[b]; k0 < edge_[b + 1]; k0 += kChunk) {
        const auto m = static_cast<Eigen::Index>(std::min<std::size_t>(kChunk, edge_[b + 1] - k0));
        for (Eigen::Index i = 0; i < m; ++i) {
          const std::size_t k = k0 + static_cast<std::size_t>(i);
          V(i, 0) = 1.0;
          for (Eigen::Index j = 0; j < p; ++j)
            V(i, j + 1) = (cols[static_cast<std::size_t>(j)][k] - g.mean(j)) / g.sd(j);
          V(i, p + 1) = y_[k] - g.ybar;
        }
        G.selfadjointView<Eigen::Lower>().rankUpdate(V.topRows(m).transpose());
      }
      G.triangularView<Eigen::StrictlyUpper>() = G.transpose();
      g.block.push_back(std::move(G));
    }
    g.ok = true;
    return g;
  }

  /// Sum of the Grams of blocks [0, last].
  static Eigen::MatrixXd sumBlocks(const Grams& g, int last) {
    Eigen::MatrixXd G = g.block[0];
    for (int b = 1; b <= last; ++b) G += g.block[static_cast<std::size_t>(b)];
    return G;
  }

  std::size_t blockRows(int b) const { return edge_[static_cast<std::size_t>(b) + 1] - edge_[static_cast<std::size_t>(b)]; }
  std::size_t rowsUpTo(int last) const { return edge_[static_cast<std::size_t>(last) + 1]; }

  /// The sum of squares a view minimises on its own rows (fold f: blocks 0..f; full view: the fit
  /// rows); infinite when the view cannot be fitted.
  double viewSse(const Grams& g, int view) const {
    if (!g.ok) return kInf;
    const auto q = static_cast<std::size_t>(g.block[0].rows() - 1);
    if (rowsUpTo(view) < q + 1) return kInf;
    const Solution s = solveGram(sumBlocks(g, view));
    if (view == fullView() && s.rank < static_cast<int>(q)) return kInf;
    return s.sse;
  }

  /// The fit of a model whose views have the Grams `g` (one per view, g[fullView()] on all fit rows).
  Fit fit(const std::vector<const Grams*>& g) const {
    Fit f;
    const Grams& full = *g[static_cast<std::size_t>(fullView())];
    if (!full.ok) {
      f.why = full.why;
      return f;
    }
    const Eigen::Index q = full.block[0].rows() - 1;  // coefficients with the intercept
    const Eigen::Index p = q - 1;
    const Solution s = solveGram(sumBlocks(full, fullView()));
    if (s.rank < q) {
      f.why = Phrase("the columns are linearly dependent on the fit rows");
      return f;
    }
    const double nf = static_cast<double>(nFit_);
    f.names = full.names;
    f.sse = s.sse;
    f.rmse = std::sqrt(s.sse / nf);
    f.s2 = s.sse / (nf - static_cast<double>(q));
    const std::size_t nHeld = n_ - nFit_;
    f.heldout = nHeld > 0 ? std::sqrt(sseOn(full.block.back(), s.b) / static_cast<double>(nHeld)) : 0.0;
    f.beta.resize(p);
    f.se.resize(p);
    for (Eigen::Index j = 0; j < p; ++j) {
      f.beta(j) = s.b(j + 1) / full.sd(j);
      f.se(j) = std::sqrt(std::max(0.0, f.s2 * s.inv(j + 1, j + 1))) / full.sd(j);
    }
    f.coef = s.b;
    f.mean = full.mean;
    f.sd = full.sd;
    f.ybar = full.ybar;
    // Blocked validation: fold v fits blocks 0..v and predicts block v + 1.
    double vSse = 0.0, vRows = 0.0;
    bool cvOk = true;
    for (int v = 0; v < folds() && cvOk; ++v) {
      const Grams& gv = *g[static_cast<std::size_t>(v)];
      const std::size_t nv = blockRows(v + 1);
      if (nv == 0) continue;
      if (!gv.ok || rowsUpTo(v) < static_cast<std::size_t>(q) + 1) {
        cvOk = false;
        break;
      }
      const Solution sv = solveGram(sumBlocks(gv, v));
      vSse += sseOn(gv.block[static_cast<std::size_t>(v) + 1], sv.b);
      vRows += static_cast<double>(nv);
    }
    f.cvOk = cvOk && vRows > 0.0;
    f.cv = f.cvOk ? std::sqrt(vSse / vRows) : kInf;
    f.ok = true;
    return f;
  }

  /// The residual of a fit of `s` (full view) on every row.
  Residual residual(const State& s, const Fit& f) const {
    Residual out;
    out.r.assign(n_, 0.0);
    const std::vector<ThermalRegressor> cols = columns(s, fullView());
    for (std::size_t k = 0; k < n_; ++k) {
      double pred = f.ybar + f.coef(0);
      for (std::size_t j = 0; j < cols.size(); ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        pred += f.coef(jj + 1) * (cols[j].values[k] - f.mean(jj)) / f.sd(jj);
      }
      out.r[k] = y_[k] - pred;
      if (k < nFit_) out.maxAbs = std::max(out.maxAbs, std::abs(out.r[k]));
    }
    return out;
  }

 private:
  const ThermalLog& log_;
  const ThermalDiagnosisOptions& o_;
  std::vector<double> y_;
  std::size_t n_ = 0, nFit_ = 0;
  std::vector<std::size_t> edge_;  ///< block edges: 0, e_1..e_K, nFit, n
  double medianStep_ = 1.0;
  std::vector<std::vector<double>> pred_;  ///< grey: the declared model's prediction per view
  thermal::ThermalTraining declaredTraining_;
};

/// Grams of every view of `states`, computed once per distinct state.
class GramSet {
 public:
  GramSet(const Problem& pb, const Views& states) {
    for (int v = 0; v < pb.views(); ++v) {
      const State& s = states[static_cast<std::size_t>(v)];
      const int key = pb.columnsKey(v);
      std::size_t at = cache_.size();
      for (std::size_t i = 0; i < cache_.size(); ++i)
        if (keys_[i] == key && cache_[i].first == s) at = i;
      if (at == cache_.size()) {
        cache_.emplace_back(s, pb.grams(s, v));
        keys_.push_back(key);
      }
      index_.push_back(at);
    }
  }
  std::vector<const Grams*> perView() const {
    std::vector<const Grams*> out;
    for (std::size_t i : index_) out.push_back(&cache_[i].second);
    return out;
  }

 private:
  std::vector<std::pair<State, Grams>> cache_;
  std::vector<int> keys_;
  std::vector<std::size_t> index_;
};

Fit fitViews(const Problem& pb, const Views& states) {
  const GramSet gs(pb, states);
  return pb.fit(gs.perView());
}

struct LagEstimate {
  std::vector<double> tau;  ///< per view
  std::optional<double> se;  ///< of the full view's tau
  Views next;
  Fit fit;
};

/// Golden section on log tau between l and r for f (see the header comment).
template <class F>
double goldenSection(double l, double r, double tol, F f) {
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = r - phi * (r - l), d = l + phi * (r - l);
  double fc = f(c), fd = f(d);
  for (int it = 0; it < 40 && r - l > tol; ++it) {
    if (fc < fd) {
      r = d;
      d = c;
      fd = fc;
      c = r - phi * (r - l);
      fc = f(c);
    } else {
      l = c;
      c = d;
      fc = fd;
      d = l + phi * (r - l);
      fd = f(d);
    }
  }
  return fc < fd ? c : d;
}

/// 1-D search over tau, per view, for `withTau(tau, view)` (see the header comment): a shared
/// log-spaced grid, then golden section per view on that view's own rows.
template <class WithTau>
LagEstimate searchLag(const Problem& pb, int gridPoints, WithTau withTau) {
  const double lo = 0.5 * pb.medianStep();
  const double hi = std::max(2.0 * lo, pb.time()[pb.fitRows() - 1] - pb.time()[0]);
  const int V = pb.views();
  auto statesAt = [&](double tau) {
    Views s;
    for (int v = 0; v < V; ++v) s.push_back(withTau(tau, v));
    return s;
  };
  const double a = std::log(lo), b = std::log(hi);
  const int g = std::max(8, gridPoints);
  std::vector<double> grid(static_cast<std::size_t>(g));
  std::vector<std::vector<double>> val(static_cast<std::size_t>(V), std::vector<double>(grid.size()));
  for (int i = 0; i < g; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    grid[ii] = a + (b - a) * i / (g - 1);
    const GramSet gs(pb, statesAt(std::exp(grid[ii])));
    const auto per = gs.perView();
    for (int v = 0; v < V; ++v) val[static_cast<std::size_t>(v)][ii] = pb.viewSse(*per[static_cast<std::size_t>(v)], v);
  }
  LagEstimate e;
  for (int v = 0; v < V; ++v) {
    const auto& vv = val[static_cast<std::size_t>(v)];
    const std::size_t best = static_cast<std::size_t>(std::min_element(vv.begin(), vv.end()) - vv.begin());
    const double l = grid[best == 0 ? 0 : best - 1], r = grid[std::min<std::size_t>(best + 1, grid.size() - 1)];
    auto sse = [&](double logTau) { return pb.viewSse(pb.grams(withTau(std::exp(logTau), v), v), v); };
    // The fit on all fit rows to 1e-6 in log tau (its tau is reported), the folds to 1e-4.
    double logTau = goldenSection(l, r, v == pb.fullView() ? 1e-6 : 1e-4, sse);
    if (vv[best] < sse(logTau)) logTau = grid[best];
    e.tau.push_back(std::exp(logTau));
    e.next.push_back(withTau(e.tau.back(), v));
  }
  e.fit = fitViews(pb, e.next);
  if (e.fit.ok) {
    const int full = pb.fullView();
    const double tau = e.tau.back(), h = 0.02 * tau;
    const double fm = pb.viewSse(pb.grams(withTau(tau - h, full), full), full);
    const double fp = pb.viewSse(pb.grams(withTau(tau + h, full), full), full);
    if (std::isfinite(fm) && std::isfinite(fp)) {
      const double curv = (fp - 2.0 * e.fit.sse + fm) / (h * h);
      if (curv > 0.0) e.se = std::sqrt(2.0 * e.fit.s2 / curv);
    }
  }
  return e;
}

/// Ranks the candidates that passed the tests: the log ratios of the validation and of the fit rmse
/// together (lower is better), so that a lucky extrapolation with hardly any in-sample gain does
/// not win over an effect that explains both.
double rankOf(const Fit& f, const Fit& cur) {
  return std::log(f.cv / cur.cv) + std::log(f.rmse / cur.rmse);
}

ErrorSummary summaryOf(const Fit& f, const Residual& r) {
  ErrorSummary s;
  s.rmse = f.rmse;
  s.maxAbs = r.maxAbs;
  s.heldoutRmse = f.heldout;
  return s;
}

double noiseLevel(const Residual& res, std::size_t nFit) {
  double s = 0.0;
  for (std::size_t k = 1; k < nFit; ++k) s += std::pow(res.r[k] - res.r[k - 1], 2);
  return nFit > 1 ? std::sqrt(s / static_cast<double>(nFit - 1) / 2.0) : 0.0;
}

void validate(const ThermalLog& log, const ThermalDiagnosisOptions& o) {
  requireValid(o, "thermal diagnosis options");
  // Names, duplicates, finiteness: the thermal module's checks (errors name file and column).
  (void)thermal::selectThermalSeries(log, o.target, o.inputs);
  if (o.inputs.empty()) throw ValidationError(ErrorContext{log.source, 0, 0, "inputs"}, "no declared input");
  const std::size_t nFit = thermal::fitRowCount(log.rows(), o.trainFraction);
  const std::size_t need = o.inputs.size() + 5;
  if (nFit < need || log.rows() - nFit < 3) {
    throw ValidationError(ErrorContext{log.source, 0, 0, o.target},
                          "has " + std::to_string(log.rows()) + " rows: with train fraction " +
                              fmt(o.trainFraction) + " the fit needs at least " + std::to_string(need) +
                              " rows and the held-out part at least 3");
  }
}

/// One candidate added to `base`: the model states, the fit, the parameters and their text.
struct Eval {
  Views next;
  Fit fit;
  std::vector<Parameter> parameters;
  Phrases paramText;  ///< e.g. "tau 13.6 +- 0.4 min" (empty when there is none)
};

/// The residual plot's axis titles: "time (min)", "residual (um)" (or "residual" without a unit).
Phrases timeLabel() {
  return {Phrase("time (min)")};
}
Phrases residualLabel(const std::string& units) {
  return {units.empty() ? Phrase("residual") : Phrase("residual (%1)", {A::unit(units)})};
}

bool isLag(const std::string& name) {
  return name == "lag" || name.starts_with("lag:");
}

/// The coefficient named `column` ("input:<col>", "drift") of a fit, with its standard error.
std::optional<std::pair<double, double>> coefficientOf(const Fit& f, const std::string& column) {
  for (std::size_t j = 0; j < f.names.size(); ++j)
    if (f.names[j] == column)
      return std::make_pair(f.beta(static_cast<Eigen::Index>(j)), f.se(static_cast<Eigen::Index>(j)));
  return std::nullopt;
}

/// Parameters of a linear candidate (input:<col>, drift) read from a fit that contains it.
void linearParameters(const ThermalLog& log, const std::string& name, const Fit& f, const std::string& u,
                      Eval& e) {
  // u is " <unit>" or "" (the target has no unit).
  const auto b = coefficientOf(f, name);
  if (!b) return;
  if (name == "drift") {
    e.parameters = {{"per_min", b->first, b->second}};
    e.paramText = {Phrase("drift %1 +- %2%3/min", {num(b->first), num(b->second, 2), A::unit(u)})};
  } else {
    const std::string cu = log.channel(name.substr(6)).unit;
    e.parameters = {{"coefficient", b->first, b->second}};
    e.paramText = {
        cu.empty() ? Phrase("coefficient %1 +- %2%3 per unit", {num(b->first), num(b->second, 2), A::unit(u)})
                   : Phrase("coefficient %1 +- %2%3 per %4",
                            {num(b->first), num(b->second, 2), A::unit(u), A::unit(cu)})};
  }
}

Eval evaluateCandidate(const Problem& pb, const ThermalLog& log, const ThermalDiagnosisOptions& o,
                       const std::string& name, const Views& base, const std::string& u) {
  Eval e;
  e.next = base;
  if (isLag(name)) {
    const std::string col = name == "lag" ? "" : name.substr(4);
    LagEstimate le = searchLag(pb, o.lagGridPoints, [&](double tau, int view) {
      State s = base[static_cast<std::size_t>(view)];
      if (col.empty())
        s.effects.lagAll = tau;
      else
        s.effects.lagCol[col] = tau;
      return s;
    });
    e.next = std::move(le.next);
    e.fit = le.fit;
    const double tau = le.tau.back();
    e.parameters = {{"tau_min", tau, le.se}};
    e.paramText = {le.se ? Phrase("tau %1 +- %2 min", {num(tau), num(*le.se, 2)})
                         : Phrase("tau %1 min", {num(tau)})};
  } else {
    for (State& s : e.next) {
      if (name == "drift")
        s.effects.drift = true;
      else
        s.effects.extra.push_back(name.substr(6));
    }
    e.fit = fitViews(pb, e.next);
    if (e.fit.ok) linearParameters(log, name, e.fit, u, e);
  }
  return e;
}

/// The evidence figures of a candidate: "validation rmse a -> b (c %), fit rmse ..., held-out rmse
/// ... (reported only)".
std::vector<PhraseArg> figureArgs(const Fit& cur, const Fit& f, const std::string& u) {
  return {num(cur.cv),   num(f.cv),   A::unit(u),        pct(cur.cv, f.cv),
          num(cur.rmse), num(f.rmse), num(cur.heldout), num(f.heldout)};
}

}  // namespace

const char* toString(ThermalDeclaredModel m) {
  switch (m) {
    case ThermalDeclaredModel::Gmc: return "gmc";
    case ThermalDeclaredModel::Gnnmci: return "gnnmci";
    case ThermalDeclaredModel::Linear: break;
  }
  return "linear";
}

ThermalDeclaredModel thermalDeclaredModel(const std::string& name, const std::string& field) {
  for (ThermalDeclaredModel m : {ThermalDeclaredModel::Linear, ThermalDeclaredModel::Gmc, ThermalDeclaredModel::Gnnmci})
    if (name == toString(m)) return m;
  throw OptionsError(ErrorContext{{}, 0, 0, field}, "'" + name + "' is not one of linear, gmc, gnnmci");
}

bool ThermalDiagnosisOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (target.empty()) return no("target must be named");
  if (!(trainFraction > 0.0 && trainFraction < 1.0)) return no("train fraction must be in (0, 1)");
  if (!(minHeldoutGain >= 0.0 && minHeldoutGain < 1.0)) return no("minHeldoutGain must be in [0, 1)");
  if (!(minExplainedNoise >= 0.0) || !std::isfinite(minExplainedNoise))
    return no("minExplainedNoise must be finite and not negative");
  if (maxRounds < 0) return no("maxRounds must not be negative");
  if (lagGridPoints < 8 || lagGridPoints > 1000) return no("lagGridPoints must be in [8, 1000]");
  if (validationFolds < 1 || validationFolds > 10) return no("validationFolds must be in [1, 10]");
  return true;
}

Diagnosis diagnoseThermal(const ThermalLog& log, const ThermalDiagnosisOptions& o, Observer* observer) {
  validate(log, o);
  Problem pb(log, o);
  Diagnosis d;
  d.domain = "thermal";
  d.units = log.channel(o.target).unit;
  const std::string u = d.units.empty() ? "" : " " + d.units;
  if (!pb.fitDeclared(observer)) {
    d.addNote({Phrase("cancelled")});
    return d;
  }
  const auto full = static_cast<std::size_t>(pb.fullView());

  Views state(static_cast<std::size_t>(pb.views()));
  Fit cur = fitViews(pb, state);
  if (!cur.ok) throw ValidationError(ErrorContext{log.source, 0, 0, "inputs"}, cur.why.english());
  Residual curRes = pb.residual(state[full], cur);
  d.baseline = summaryOf(cur, curRes);
  const double noise = noiseLevel(curRes, pb.fitRows());
  if (pb.grey()) {
    std::string inputs;
    for (const auto& in : o.inputs) inputs += (inputs.empty() ? "" : ", ") + in;
    const auto [ownFit, ownHeld] = pb.declaredOwnRmse();
    d.addNote({Phrase("declared model %1 of %2 (fitted on the first %3 of %4 rows as thermal fit does; alone: fit "
                      "rmse %5, held-out rmse %6%7); the loop fits the target on its prediction (coefficient %8) "
                      "and the candidate effects",
                      {A::name(o.declared == ThermalDeclaredModel::Gmc ? "GMC(1,N)" : "GNNMCI(1,N)"),
                       A::name(inputs), A::integer(static_cast<long long>(pb.fitRows())),
                       A::integer(static_cast<long long>(pb.rows())), num(ownFit), num(ownHeld), A::unit(u),
                       num(cur.beta(0))})});
  } else {
    Phrases model = {Phrase("%1 = c0", {A::name(o.target)})};
    for (std::size_t j = 0; j < o.inputs.size(); ++j)
      model.push_back(
          Phrase(" + %1 %2", {num(cur.beta(static_cast<Eigen::Index>(j))), A::name(o.inputs[j])}));
    d.addNote({Phrase("declared model (static, fitted on the first %1 of %2 rows): %3",
                      {A::integer(static_cast<long long>(pb.fitRows())),
                       A::integer(static_cast<long long>(pb.rows())), A::text(std::move(model))})});
  }
  {
    d.addNote(
        {Phrase("noise level (first differences of the fit residual): %1%2", {num(noise), A::unit(u)})});
    d.addNote({Phrase("effects chosen on the fit rows by blocked forward validation (%1 folds, validation "
                      "rmse %2%3); the held-out rows only report the error",
                      {A::integer(o.validationFolds), num(cur.cv), A::unit(u)})});
  }

  // Columns a model could have used but did not declare (never the target, never another
  // displacement channel: those are outputs, not causes).
  std::vector<std::string> undeclared;
  for (const auto& c : log.channels) {
    if (c.name == o.target) continue;
    if (std::find(o.inputs.begin(), o.inputs.end(), c.name) != o.inputs.end()) continue;
    if (channelKind(c) == ChannelKind::Displacement) continue;
    undeclared.push_back(c.name);
  }

  LoopProgress progress(observer);
  bool cancelled = false;
  const double nf = static_cast<double>(pb.fitRows());
  for (int round = 0; round < o.maxRounds && !cancelled; ++round) {
    const ThermalEffectSet& now = state[full].effects;
    // This round's candidates.
    std::vector<std::string> names;
    if (!(now.lagAll > 0.0) && !pb.grey()) names.push_back("lag");
    if (o.inputs.size() > 1 || now.lagAll > 0.0 || pb.grey())
      for (const auto& in : o.inputs)
        if (!now.lagCol.count(in)) names.push_back("lag:" + in);
    for (const auto& c : undeclared)
      if (std::find(now.extra.begin(), now.extra.end(), c) == now.extra.end()) names.push_back("input:" + c);
    if (!now.drift) names.push_back("drift");
    if (names.empty()) break;

    std::vector<Candidate> tried;
    std::vector<Views> states;
    std::vector<Fit> fits;
    std::optional<std::size_t> best;
    std::vector<bool> passed(names.size(), false);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string& name = names[i];
      Candidate c;
      c.name = name;
      c.round = round;
      c.rmseBefore = cur.rmse;
      c.heldoutBefore = cur.heldout;
      Eval ev0 = evaluateCandidate(pb, log, o, name, state, u);
      Fit f = ev0.fit;
      const Phrases paramText = ev0.paramText;
      c.parameters = ev0.parameters;
      if (!f.ok) {
        c.rmseAfter = cur.rmse;
        c.heldoutAfter = cur.heldout;
        c.setEvidence({Phrase("not estimable: %1", {A::text({f.why})})});
      } else {
        c.rmseAfter = f.rmse;
        c.heldoutAfter = f.heldout;
        const bool cvUsable = f.cvOk && cur.cvOk && cur.cv > 0.0;
        c.score = cvUsable ? (f.cv - cur.cv) / cur.cv : 0.0;
        const double explained = cvUsable ? std::sqrt(std::max(0.0, cur.cv * cur.cv - f.cv * f.cv)) : 0.0;
        const bool gain = cvUsable && f.cv <= (1.0 - o.minHeldoutGain) * cur.cv;
        const bool aboveNoise = explained >= o.minExplainedNoise * noise;
        // In-sample evidence too: the fit's sum of squares must fall by more than the BIC penalty
        // of the added parameter (n ln(SSE0 / SSE1) > ln n), so that a coefficient the fit rows
        // cannot determine does not win by a lucky extrapolation.
        const double dBic = nf * std::log(f.sse / cur.sse) + std::log(nf);
        const bool inSample = dBic < 0.0;
        std::vector<PhraseArg> args = figureArgs(cur, f, u);
        Phrases ev;
        if (paramText.empty()) {
          ev.push_back(Phrase("validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3",
                              std::move(args)));
        } else {
          args.push_back(A::text(paramText));
          ev.push_back(
              Phrase("validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3, %9",
                     std::move(args)));
        }
        if (!cvUsable)
          ev.push_back(Phrase("; rejected: the validation folds cannot fit it"));
        else if (f.cv > cur.cv)
          ev.push_back(Phrase("; rejected: validation error worse"));
        else if (!gain)
          ev.push_back(Phrase("; rejected: validation gain below %1 %", {num(100.0 * o.minHeldoutGain, 2)}));
        else if (!aboveNoise)
          ev.push_back(Phrase("; rejected: explains %1%2, below %3 x the noise level %4%2",
                              {num(explained), A::unit(u), num(o.minExplainedNoise), num(noise)}));
        else if (!inSample)
          ev.push_back(Phrase("; rejected: no in-sample evidence (fit dBIC %1 >= 0)", {num(dBic)}));
        c.setEvidence(std::move(ev));
        passed[i] = gain && aboveNoise && inSample;
        if (passed[i] && (!best || rankOf(f, cur) < rankOf(fits[*best], cur))) best = i;
      }
      tried.push_back(std::move(c));
      states.push_back(std::move(ev0.next));
      fits.push_back(std::move(f));

      if (progress.afterCandidate(round, i, names.size(), cur.cv, "cv_rmse")) {
        cancelled = true;
        break;
      }
    }
    if (cancelled) best.reset();
    if (best && names[*best] == "lag") {
      // The specific claim first: `lag` (every input lagged) over the best passing `lag:<col>` only
      // when it validates another minHeldoutGain better (the fit rows often cannot tell whether an
      // input that hardly changes on them is lagged too).
      std::optional<std::size_t> one;
      for (std::size_t i = 0; i < names.size() && i < fits.size(); ++i)
        if (names[i].starts_with("lag:") && passed[i] && (!one || rankOf(fits[i], cur) < rankOf(fits[*one], cur)))
          one = i;
      if (one && !(fits[*best].cv <= (1.0 - o.minHeldoutGain) * fits[*one].cv)) best = one;
    }
    bool pairAccepted = false;
    if (!best && !cancelled && o.tryPairs && cur.cvOk) {
      // Two effects together: when no single candidate passes, each of the three with the strongest
      // in-sample evidence is tried with every other candidate (alone, each may extrapolate worse
      // than the declared model, while together they explain the data). Same tests, with the
      // penalty of 2 parameters.
      std::vector<std::size_t> strong;
      for (std::size_t i = 0; i < fits.size(); ++i)
        if (fits[i].ok && nf * std::log(fits[i].sse / cur.sse) + std::log(nf) < 0.0) strong.push_back(i);
      std::sort(strong.begin(), strong.end(),
                [&](std::size_t a, std::size_t b) { return fits[a].sse < fits[b].sse; });
      if (strong.size() > 3) strong.resize(3);
      std::optional<Eval> bestA, bestB;
      Fit bestFit;
      Views bestStates;
      std::array<std::string, 2> bestNames;
      std::vector<std::pair<std::size_t, std::size_t>> pairs;
      for (std::size_t x : strong)
        for (std::size_t y = 0; y < fits.size(); ++y)
          if (y != x && fits[y].ok &&
              std::find(pairs.begin(), pairs.end(), std::make_pair(y, x)) == pairs.end())
            pairs.emplace_back(x, y);
      for (const auto& [px, py] : pairs) {
        const std::string &na = names[px], &nb = names[py];
        if (isLag(na) && isLag(nb)) continue;
        Eval ea = evaluateCandidate(pb, log, o, na, state, u);
        const Eval eb = evaluateCandidate(pb, log, o, nb, ea.next, u);
        if (!eb.fit.ok) continue;
        Fit pf = eb.fit;
        Views ps = eb.next;
        if (isLag(na)) {  // re-estimate the lag with the other effect present
          ea = evaluateCandidate(pb, log, o, na, eb.next, u);
          if (!ea.fit.ok) continue;
          pf = ea.fit;
          ps = ea.next;
        } else {
          linearParameters(log, na, pf, u, ea);
        }
        Eval fb = eb;
        if (!isLag(nb)) linearParameters(log, nb, pf, u, fb);
        if (!pf.cvOk) continue;
        const double explained = std::sqrt(std::max(0.0, cur.cv * cur.cv - pf.cv * pf.cv));
        const bool pass = pf.cv <= (1.0 - o.minHeldoutGain) * cur.cv && explained >= o.minExplainedNoise * noise &&
                          nf * std::log(pf.sse / cur.sse) + 2.0 * std::log(nf) < 0.0;
        if (pass && (!bestA || rankOf(pf, cur) < rankOf(bestFit, cur))) {
          bestNames = {na, nb};
          bestA = ea;
          bestB = fb;
          bestFit = pf;
          bestStates = ps;
        }
      }
      if (bestA) {
        const Residual after = pb.residual(bestStates[full], bestFit);
        const Eval* parts[2] = {&*bestA, &*bestB};
        for (int w = 0; w < 2; ++w) {
          Candidate c;
          c.name = bestNames[static_cast<std::size_t>(w)];
          c.round = round;
          c.accepted = true;
          c.parameters = parts[w]->parameters;
          c.rmseBefore = cur.rmse;
          c.rmseAfter = bestFit.rmse;
          c.heldoutBefore = cur.heldout;
          c.heldoutAfter = bestFit.heldout;
          c.score = (bestFit.cv - cur.cv) / cur.cv;
          std::vector<PhraseArg> args = {A::name(bestNames[static_cast<std::size_t>(1 - w)])};
          for (PhraseArg& a : figureArgs(cur, bestFit, u)) args.push_back(std::move(a));
          args.push_back(A::text(parts[w]->paramText));
          c.setEvidence({Phrase("accepted together with %1: validation rmse %2 -> %3%4 (%5), fit rmse %6 -> "
                                "%7%4, held-out rmse %8 -> %9%4, %10",
                                std::move(args))});
          ResidualPlot plot;
          plot.setLabels(timeLabel(), residualLabel(d.units));
          plot.x = log.timeMin;
          plot.before = curRes.r;
          plot.after = after.r;
          c.plot = std::move(plot);
          tried.push_back(std::move(c));
        }
        state = bestStates;
        cur = bestFit;
        curRes = after;
        pairAccepted = true;
      }
    }
    if (best) {
      for (std::size_t i = 0; i < tried.size(); ++i) {
        if (i != *best && tried[i].evidence.find("; rejected") == std::string::npos &&
            !tried[i].evidence.starts_with("not estimable"))
          tried[i].addEvidence({Phrase("; passed, but %1 explains more", {A::name(tried[*best].name)})});
      }
      Candidate& c = tried[*best];
      c.accepted = true;
      c.prependEvidence(Phrase("accepted: "));
      const Residual after = pb.residual(states[*best][full], fits[*best]);
      ResidualPlot plot;
      plot.setLabels(timeLabel(), residualLabel(d.units));
      plot.x = log.timeMin;
      plot.before = curRes.r;
      plot.after = after.r;
      c.plot = std::move(plot);
      state = states[*best];
      cur = fits[*best];
      curRes = after;
    }
    for (auto& c : tried) d.effects.push_back(std::move(c));
    if (!best && !pairAccepted) break;
  }
  progress.addNote(d);
  d.final = summaryOf(cur, curRes);
  return d;
}

}  // namespace metrofit::diagnose
