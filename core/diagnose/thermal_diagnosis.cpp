#include "core/diagnose/thermal_diagnosis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>

#include <Eigen/Dense>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/diagnose/loop.h"
#include "core/diagnose/thermal_applied.h"
#include "core/io/csv.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_model.h"

namespace metrofit::diagnose {
namespace {

using A = PhraseArg;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Above this many rows the lag search's grid and its per-fold refinement run on group means
/// (see the header comment); the reported tau and every reported error are computed on every row.
constexpr std::size_t kCoarseRows = 20000;

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

/// sum_k w_k x_k y_k over [b, e) with four partial sums (the additions of one sum would wait on each
/// other; four chains run at once). `w` may be null (all weights 1).
double weightedDot(const double* w, const double* x, const double* y, std::size_t b, std::size_t e) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t k = b;
  if (w) {
    for (; k + 4 <= e; k += 4) {
      s0 += w[k] * x[k] * y[k];
      s1 += w[k + 1] * x[k + 1] * y[k + 1];
      s2 += w[k + 2] * x[k + 2] * y[k + 2];
      s3 += w[k + 3] * x[k + 3] * y[k + 3];
    }
    for (; k < e; ++k) s0 += w[k] * x[k] * y[k];
  } else {
    for (; k + 4 <= e; k += 4) {
      s0 += x[k] * y[k];
      s1 += x[k + 1] * y[k + 1];
      s2 += x[k + 2] * y[k + 2];
      s3 += x[k + 3] * y[k + 3];
    }
    for (; k < e; ++k) s0 += x[k] * y[k];
  }
  return (s0 + s1) + (s2 + s3);
}
/// sum_k w_k x_k over [b, e) (w may be null), four partial sums.
double weightedSum(const double* w, const double* x, std::size_t b, std::size_t e) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t k = b;
  for (; k + 4 <= e; k += 4) {
    s0 += w ? w[k] * x[k] : x[k];
    s1 += w ? w[k + 1] * x[k + 1] : x[k + 1];
    s2 += w ? w[k + 2] * x[k + 2] : x[k + 2];
    s3 += w ? w[k + 3] * x[k + 3] : x[k + 3];
  }
  for (; k < e; ++k) s0 += w ? w[k] * x[k] : x[k];
  return (s0 + s1) + (s2 + s3);
}

/// The model state: the declared inputs plus the accepted effects (thermal_applied.h, shared with
/// every fit of the thermal study that includes applied effects).
struct State {
  ThermalEffectSet effects;
  std::vector<int> generics;  ///< accepted generic effects (Problem::generic indices)
};

bool operator==(const State& a, const State& b) {
  return a.effects.lagAll == b.effects.lagAll && a.effects.lagCol == b.effects.lagCol &&
         a.effects.extra == b.effects.extra && a.effects.drift == b.effects.drift && a.generics == b.generics;
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
  Phrase why;                  ///< when not ok
  double rmse = 0.0;           ///< fit rows
  double heldout = 0.0;        ///< held-out rows (reported only)
  double sse = 0.0, s2 = 0.0;  ///< fit rows
  double cv = kInf;            ///< blocked validation rmse (fit rows only)
  bool cvOk = false;
  std::vector<std::string> names;  ///< column names (without the intercept)
  Eigen::VectorXd beta, se;        ///< per column, original units
  // For residuals: standardised coefficients and the scaling.
  Eigen::VectorXd coef, mean, sd;
  double ybar = 0.0;
};

/// A fit's residual on every row (y - prediction) and its summaries.
struct Residual {
  std::vector<double> r;
  double maxAbs = 0.0;         ///< fit rows
  std::vector<char> excluded;  ///< per row: a gross error excluded from the fits
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
      edge_.push_back(
          static_cast<std::size_t>(std::llround(static_cast<double>(nFit_) * (K + f - 1) / (2.0 * K))));
    edge_.push_back(nFit_);
    edge_.push_back(n_);
    // The median step of the fit rows (the lag search's lower end).
    std::vector<double> d;
    for (std::size_t k = 1; k < nFit_; ++k) d.push_back(log_.timeMin[k] - log_.timeMin[k - 1]);
    if (d.empty()) d.push_back(1.0);
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    medianStep_ = d[d.size() / 2];
    // Equal steps (time only, no target): the lag filter needs one exponential.
    const double step = n_ > 1 ? log_.timeMin[1] - log_.timeMin[0] : 0.0;
    bool uniform = n_ > 1;
    for (std::size_t k = 1; k < n_ && uniform; ++k)
      uniform = std::abs((log_.timeMin[k] - log_.timeMin[k - 1]) - step) <= 1e-9 * step;
    uniformStep_ = uniform ? step : 0.0;
    y0_ = y_.empty() ? 0.0 : y_[0];
    yc_.resize(n_);
    for (std::size_t k = 0; k < n_; ++k) yc_[k] = y_[k] - y0_;
    w_.assign(n_, 1.0);
    const std::size_t m = (n_ + kCoarseRows - 1) / kCoarseRows;
    coarse_ = m > 1;
    if (coarse_) {
      for (std::size_t b = 0; b + 1 < edge_.size(); ++b) {
        gOfBlock_.push_back(gEdge_.size());
        for (std::size_t k = edge_[b]; k < edge_[b + 1]; k += m) gEdge_.push_back(k);
      }
      gOfBlock_.push_back(gEdge_.size());
      gEdge_.push_back(n_);
      gTime_ = groupMeans(log_.timeMin);
    }
    prepareSums();
  }

  /// Excludes rows (gross errors of the target, 0-based) from every fit: weight 0 in every sum.
  void exclude(const std::vector<std::size_t>& rows) {
    for (std::size_t k : rows) w_[k] = 0.0;
    anyExcluded_ = !rows.empty();
    store_.clear();
    dots_.clear();
    temporary_.clear();
    prepareSums();
  }
  bool excluded(std::size_t k) const { return w_[k] == 0.0; }

  /// Cancel inside a candidate (a lag search on a long log takes a while): the observer is asked
  /// again with the last step's figures (no new step); once it says Stop every fit returns at once
  /// and the loop ends after the candidate with the note "cancelled".
  void setObserver(Observer* o) { observer_ = o; }
  void setStep(long steps, double current) const {
    pollSteps_ = steps;
    pollCurrent_ = current;
  }
  bool poll() const {
    if (stopped_ || !observer_) return stopped_;
    IterationSummary s;
    s.iteration = std::max(0L, pollSteps_ - 1);
    s.evaluations = pollSteps_;
    s.best = pollCurrent_;
    s.components = {{"cv_rmse", pollCurrent_}};
    if (observer_->onIteration(s) == ObserverDecision::Stop) stopped_ = true;
    return stopped_;
  }
  bool stopped() const { return stopped_; }

  /// The coarse groups of the fit rows (begin, end), empty below kCoarseRows rows.
  std::vector<std::pair<std::size_t, std::size_t>> fitGroups() const {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    if (!coarse_) return out;
    for (std::size_t g = 0; g + 1 < gEdge_.size() && gEdge_[g] < nFit_; ++g)
      out.emplace_back(gEdge_[g], gEdge_[g + 1]);
    return out;
  }
  /// The row weights, or null when no row is excluded (the sums skip the multiplication).
  const double* weights() const { return anyExcluded_ ? w_.data() : nullptr; }

  /// The weighted per-block counts and sums of the target (full and coarse resolution).
  void prepareSums() {
    const std::size_t B = edge_.size() - 1;
    blockN_.assign(B, 0.0);
    ySum_.assign(B, 0.0);
    yy_.assign(B, 0.0);
    for (std::size_t b = 0; b < B; ++b)
      for (std::size_t k = edge_[b]; k < edge_[b + 1]; ++k) {
        blockN_[b] += w_[k];
        ySum_[b] += w_[k] * yc_[k];
        yy_[b] += w_[k] * yc_[k] * yc_[k];
      }
    fitN_ = 0.0;
    for (std::size_t b = 0; b + 1 < B; ++b) fitN_ += blockN_[b];
    if (coarse_) {
      const std::size_t G = gEdge_.size() - 1;
      gW_.assign(G, 0.0);
      yMean_.assign(G, 0.0);
      for (std::size_t g = 0; g < G; ++g) {
        double s = 0.0;
        for (std::size_t k = gEdge_[g]; k < gEdge_[g + 1]; ++k) {
          gW_[g] += w_[k];
          s += w_[k] * yc_[k];
        }
        yMean_[g] = gW_[g] > 0.0 ? s / gW_[g] : 0.0;
      }
      yyCoarse_.assign(B, 0.0);
      for (std::size_t b = 0; b < B; ++b)
        for (std::size_t g = gOfBlock_[b]; g < gOfBlock_[b + 1]; ++g)
          yyCoarse_[b] += gW_[g] * yMean_[g] * yMean_[g];
    }
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
          throw ValidationError(
              ErrorContext{log_.source, 0, 0, o_.target},
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

  /// One column of a model: `key` identifies its values (the store computes them once), `name` is
  /// the loop's name for its coefficient.
  struct ColumnSpec {
    std::string key;   ///< "in:T2", "lag:T2@<tau>", "extra:rpm", "drift", "pred:<view>"
    std::string name;  ///< "T2", "input:rpm", "drift", "declared", "lag:T2"
  };

  /// The columns of a model state (without the intercept); empty when the view's grey model could
  /// not be fitted.
  std::vector<ColumnSpec> columns(const State& s, int view) const {
    std::vector<ColumnSpec> out;
    auto lagKey = [](const std::string& col, double tau) {
      char buf[64];
      metrofit::c_snprintf(buf, sizeof buf, "@%a", tau);
      return "lag:" + col + buf;
    };
    if (!grey()) {
      for (const auto& in : o_.inputs) {
        const auto it = s.effects.lagCol.find(in);
        const double tau = it != s.effects.lagCol.end() ? it->second : s.effects.lagAll;
        out.push_back({tau > 0.0 ? lagKey(in, tau) : "in:" + in, in});
      }
    } else {
      if (pred_[static_cast<std::size_t>(view)].empty()) return {};
      out.push_back({"pred:" + std::to_string(view), "declared"});
      for (const auto& [col, tau] : s.effects.lagCol) out.push_back({lagKey(col, tau), "lag:" + col});
    }
    for (const auto& e : s.effects.extra) out.push_back({"extra:" + e, "input:" + e});
    if (s.effects.drift) out.push_back({"drift", "drift"});
    for (int i : s.generics) {
      const auto& g = generic_[static_cast<std::size_t>(i)];
      for (Eigen::Index j = 0; j < g.basis.cols(); ++j)
        out.push_back({"gen:" + std::to_string(i) + ":" + std::to_string(j),
                       "unexplained:" + g.form.against + "#" + std::to_string(j)});
    }
    return out;
  }

  /// A generic effect's fixed shape and its basis on every row.
  struct Generic {
    GenericForm form;
    Eigen::MatrixXd basis;
    std::vector<double> values;  ///< the variable on every row
  };
  /// Registers a generic effect (its basis on every row, so that held-out rows are predicted too).
  int addGeneric(const GenericForm& f, const std::vector<double>& values) const {
    generic_.push_back({f, genericBasis(f, values), values});
    return static_cast<int>(generic_.size()) - 1;
  }
  const Generic& generic(int i) const { return generic_[static_cast<std::size_t>(i)]; }

  /// The full view's columns of a state (for the residual check's model columns).
  std::vector<const std::vector<double>*> columnValues(const State& s) const {
    std::vector<const std::vector<double>*> out;
    for (const ColumnSpec& c : columns(s, fullView())) out.push_back(&column(c.key).v);
    return out;
  }

  /// A stored column: its values minus their first value (the intercept absorbs the shift), per
  /// block its sum and its products with the target.
  struct Column {
    std::vector<double> v;
    double shift = 0.0;
    std::vector<double> sum, dotY;
    bool pinned = false;
  };

  /// The column `key` (computed and stored when missing).
  const Column& column(const std::string& fullKey) const {
    if (auto it = store_.find(fullKey); it != store_.end()) return it->second;
    const bool coarse = fullKey.starts_with("~");
    const std::string key = coarse ? fullKey.substr(1) : fullKey;
    Column c;
    std::vector<double> raw;
    bool pin = true;
    if (key.starts_with("in:")) {
      raw = log_.channel(key.substr(3)).values;
    } else if (key.starts_with("extra:")) {
      raw = log_.channel(key.substr(6)).values;
    } else if (key == "drift") {
      raw = log_.timeMin;
    } else if (key.starts_with("pred:")) {
      raw = pred_[static_cast<std::size_t>(std::stoi(key.substr(5)))];
    } else if (key.starts_with("gen:")) {
      const std::size_t colon = key.find(':', 4);
      const Generic& g = generic_[static_cast<std::size_t>(std::stoi(key.substr(4, colon - 4)))];
      const Eigen::VectorXd c = g.basis.col(std::stoi(key.substr(colon + 1)));
      raw.assign(c.data(), c.data() + c.size());
    } else {  // lag:<col>@<tau>
      const std::size_t at = key.rfind('@');
      const std::vector<double>& x = log_.channel(key.substr(4, at - 4)).values;
      const double tau = metrofit::num::strtodC(key.c_str() + at + 1, nullptr);
      // Coarse: the lag of the group means on the groups' mean times (the grid only brackets tau).
      if (coarse) {
        const std::string name = key.substr(4, at - 4);
        auto it = coarseInput_.find(name);
        if (it == coarseInput_.end()) it = coarseInput_.emplace(name, groupMeans(x)).first;
        raw = laggedOn(it->second, gTime_, tau, 0.0);
      } else {
        raw = laggedOn(x, log_.timeMin, tau, uniformStep_);
      }
      pin = false;
    }
    if (coarse && raw.size() == n_) raw = groupMeans(raw);
    c.shift = raw[0];
    c.sum.assign(edge_.size() - 1, 0.0);
    c.dotY.assign(edge_.size() - 1, 0.0);
    if (!coarse) {
      c.v = std::move(raw);
      for (double& x : c.v) x -= c.shift;
      for (std::size_t b = 0; b + 1 < edge_.size(); ++b) {
        c.sum[b] = weightedSum(weights(), c.v.data(), edge_[b], edge_[b + 1]);
        c.dotY[b] = weightedDot(weights(), c.v.data(), yc_.data(), edge_[b], edge_[b + 1]);
      }
    } else {  // group means, weighted by the group sizes
      const std::size_t G = gEdge_.size() - 1;
      c.v.resize(G);
      for (std::size_t g = 0; g < G; ++g) c.v[g] = raw[g] - c.shift;  // (raw has G values here)
      for (std::size_t b = 0; b + 1 < edge_.size(); ++b)
        for (std::size_t g = gOfBlock_[b]; g < gOfBlock_[b + 1]; ++g) {
          c.sum[b] += gW_[g] * c.v[g];
          c.dotY[b] += gW_[g] * c.v[g] * yMean_[g];
        }
    }
    c.pinned = pin;
    if (!pin) temporary_.push_back(fullKey);
    return store_.emplace(fullKey, std::move(c)).first->second;
  }

  /// Per block products of two stored columns (computed once while both are stored).
  const std::vector<double>& dot(const std::string& a, const std::string& b) const {
    const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    if (auto it = dots_.find(key); it != dots_.end()) return it->second;
    const std::vector<double>&x = column(a).v, &y = column(b).v;
    std::vector<double> d(edge_.size() - 1, 0.0);
    if (!a.starts_with("~")) {
      for (std::size_t blk = 0; blk + 1 < edge_.size(); ++blk)
        d[blk] = weightedDot(weights(), x.data(), y.data(), edge_[blk], edge_[blk + 1]);
    } else {
      for (std::size_t blk = 0; blk + 1 < edge_.size(); ++blk)
        for (std::size_t g = gOfBlock_[blk]; g < gOfBlock_[blk + 1]; ++g) d[blk] += gW_[g] * x[g] * y[g];
    }
    return dots_.emplace(key, std::move(d)).first->second;
  }

  /// Keeps the columns of `s` (every view) stored; they are used by every later candidate.
  void pin(const Views& s) const {
    for (int v = 0; v < views(); ++v)
      for (const ColumnSpec& c : columns(s[static_cast<std::size_t>(v)], v)) {
        column(c.key);
        store_.at(c.key).pinned = true;
      }
  }
  /// Drops the columns that are not pinned (a lag searched over tau makes one per tau) and their
  /// products.
  void sweep() const {
    for (const std::string& key : temporary_) {
      auto it = store_.find(key);
      if (it == store_.end() || it->second.pinned) continue;
      store_.erase(it);
      for (auto d = dots_.begin(); d != dots_.end();)
        d = d->first.first == key || d->first.second == key ? dots_.erase(d) : std::next(d);
    }
    temporary_.clear();
  }

  /// The first-order lag of effects_thermal.h (s(0) = x(0), s(k) = s(k-1) + (1 - e^{-dt_k/tau})
  /// (x(k) - s(k-1))), with one exponential when the steps are equal.
  /// On times t (`step` > 0: all steps equal to it). Written s(k) = e s(k-1) + (1 - e) x(k), so that
  /// the chain from one row to the next is one multiply-add.
  static std::vector<double> laggedOn(const std::vector<double>& x, const std::vector<double>& t, double tau,
                                      double step) {
    std::vector<double> s(x.size());
    if (x.empty()) return s;
    s[0] = x[0];
    if (step > 0.0) {
      // s(k) = e s(k-1) + a x(k) = e^2 s(k-2) + (e a x(k-1) + a x(k)): two interleaved chains, each
      // one multiply-add per two rows.
      const double a = -std::expm1(-step / tau), e = 1.0 - a, e2 = e * e, ea = e * a;
      std::size_t k = 1;
      if (x.size() > 1) {
        s[1] = e * s[0] + a * x[1];
        k = 2;
      }
      for (; k + 1 < x.size(); k += 2) {
        s[k] = e2 * s[k - 2] + (ea * x[k - 1] + a * x[k]);
        s[k + 1] = e2 * s[k - 1] + (ea * x[k] + a * x[k + 1]);
      }
      for (; k < x.size(); ++k) s[k] = e * s[k - 1] + a * x[k];
    } else {
      double dt = -1.0, a = 0.0;  // one exponential per run of equal steps
      for (std::size_t k = 1; k < x.size(); ++k) {
        if (t[k] - t[k - 1] != dt) {
          dt = t[k] - t[k - 1];
          a = -std::expm1(-dt / tau);
        }
        s[k] = (1.0 - a) * s[k - 1] + a * x[k];
      }
    }
    return s;
  }
  /// Means of x over the coarse groups.
  std::vector<double> groupMeans(const std::vector<double>& x) const {
    std::vector<double> out(gEdge_.size() - 1);
    for (std::size_t g = 0; g + 1 < gEdge_.size(); ++g) {
      double s = 0.0;
      for (std::size_t k = gEdge_[g]; k < gEdge_[g + 1]; ++k) s += x[k];
      out[g] = s / static_cast<double>(gEdge_[g + 1] - gEdge_[g]);
    }
    return out;
  }

  /// The block Grams of a state in a view: standardised columns [1, z_1..z_p, y - ybar], every
  /// column centred and scaled on the fit rows, assembled from the stored per-block sums and
  /// products.
  Grams grams(const State& s, int view, bool coarse = false) const {
    Grams g;
    if (stopped_) return g;
    std::vector<ColumnSpec> specs = columns(s, view);
    if (coarse && coarse_)
      for (ColumnSpec& c : specs) c.key = "~" + c.key;
    const std::vector<double>& yy = coarse && coarse_ ? yyCoarse_ : yy_;
    if (specs.empty()) return g;  // a fold whose grey model could not be fitted
    const auto p = static_cast<Eigen::Index>(specs.size());
    const double nf = fitN_;
    for (const auto& c : specs) g.names.push_back(c.name);
    if (nf < static_cast<double>(p + 3)) {
      g.why = Phrase("too few fit rows (%1) for %2 coefficients",
                     {A::integer(std::llround(nf)), A::integer(p + 1)});
      return g;
    }
    const std::size_t B = edge_.size() - 1, fitBlocks = B - 1;
    std::vector<const Column*> col;
    for (const auto& c : specs) col.push_back(&column(c.key));
    std::vector<std::vector<const std::vector<double>*>> P(
        static_cast<std::size_t>(p), std::vector<const std::vector<double>*>(static_cast<std::size_t>(p)));
    for (Eigen::Index i = 0; i < p; ++i)
      for (Eigen::Index j = i; j < p; ++j) {
        const auto ii = static_cast<std::size_t>(i), jj = static_cast<std::size_t>(j);
        P[ii][jj] = P[jj][ii] = &dot(specs[ii].key, specs[jj].key);
      }
    g.mean.resize(p);
    g.sd.resize(p);
    for (Eigen::Index j = 0; j < p; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      double s1 = 0.0, s2 = 0.0;
      for (std::size_t b = 0; b < fitBlocks; ++b) {
        s1 += col[jj]->sum[b];
        s2 += (*P[jj][jj])[b];
      }
      g.mean(j) = s1 / nf;
      g.sd(j) = std::sqrt(std::max(0.0, s2 / nf - g.mean(j) * g.mean(j)));
      if (!(g.sd(j) > 1e-12 * std::max(1.0, std::abs(g.mean(j) + col[jj]->shift)))) {
        g.why = Phrase("column '%1' is constant on the fit rows", {A::name(g.names[jj])});
        return g;
      }
    }
    double sy = 0.0;
    for (std::size_t b = 0; b < fitBlocks; ++b) sy += ySum_[b];
    const double ybar = sy / nf;
    g.ybar = ybar + y0_;
    const Eigen::Index q = p + 2;
    for (std::size_t b = 0; b < B; ++b) {
      const double nb = coarse && coarse_ ? coarseN(b) : blockN_[b];
      Eigen::MatrixXd G(q, q);
      G(0, 0) = nb;
      for (Eigen::Index i = 0; i < p; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const double mi = g.mean(i), si = g.sd(i), Si = col[ii]->sum[b];
        G(0, i + 1) = G(i + 1, 0) = (Si - nb * mi) / si;
        for (Eigen::Index j = i; j < p; ++j) {
          const auto jj = static_cast<std::size_t>(j);
          const double mj = g.mean(j), Sj = col[jj]->sum[b];
          G(i + 1, j + 1) = G(j + 1, i + 1) =
              ((*P[ii][jj])[b] - mi * Sj - mj * Si + nb * mi * mj) / (si * g.sd(j));
        }
        G(i + 1, q - 1) = G(q - 1, i + 1) =
            (col[ii]->dotY[b] - mi * ySum_[b] - ybar * Si + nb * mi * ybar) / si;
      }
      G(0, q - 1) = G(q - 1, 0) = ySum_[b] - nb * ybar;
      G(q - 1, q - 1) = yy[b] - 2.0 * ybar * ySum_[b] + nb * ybar * ybar;
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

  /// Rows (weights) of block b and of blocks [0, last].
  double blockRows(int b) const { return blockN_[static_cast<std::size_t>(b)]; }
  double rowsUpTo(int last) const {
    double s = 0.0;
    for (int b = 0; b <= last; ++b) s += blockN_[static_cast<std::size_t>(b)];
    return s;
  }
  double coarseN(std::size_t b) const {
    double s = 0.0;
    for (std::size_t g = gOfBlock_[b]; g < gOfBlock_[b + 1]; ++g) s += gW_[g];
    return s;
  }
  double fitCount() const { return fitN_; }

  /// The sum of squares a view minimises on its own rows (fold f: blocks 0..f; full view: the fit
  /// rows); infinite when the view cannot be fitted.
  double viewSse(const Grams& g, int view) const {
    if (!g.ok || stopped_) return kInf;
    const auto q = static_cast<std::size_t>(g.block[0].rows() - 1);
    if (rowsUpTo(view) < static_cast<double>(q + 1)) return kInf;
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
    const double nf = fitN_;
    f.names = full.names;
    f.sse = s.sse;
    f.rmse = std::sqrt(s.sse / nf);
    f.s2 = s.sse / (nf - static_cast<double>(q));
    const double nHeld = blockN_.back();
    f.heldout = nHeld > 0.0 ? std::sqrt(sseOn(full.block.back(), s.b) / nHeld) : 0.0;
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
      const double nv = blockRows(v + 1);
      if (nv == 0.0) continue;
      if (!gv.ok || rowsUpTo(v) < static_cast<double>(q + 1)) {
        cvOk = false;
        break;
      }
      const Solution sv = solveGram(sumBlocks(gv, v));
      vSse += sseOn(gv.block[static_cast<std::size_t>(v) + 1], sv.b);
      vRows += nv;
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
    out.excluded.assign(n_, 0);
    for (std::size_t k = 0; k < n_; ++k) out.excluded[k] = w_[k] == 0.0;
    const std::vector<ColumnSpec> specs = columns(s, fullView());
    std::vector<const Column*> col;
    for (const auto& c : specs) col.push_back(&column(c.key));
    for (std::size_t k = 0; k < n_; ++k) {
      double pred = f.ybar + f.coef(0);
      for (std::size_t j = 0; j < col.size(); ++j) {
        const auto jj = static_cast<Eigen::Index>(j);
        pred += f.coef(jj + 1) * (col[j]->v[k] - f.mean(jj)) / f.sd(jj);
      }
      out.r[k] = y_[k] - pred;
      if (k < nFit_ && w_[k] > 0.0) out.maxAbs = std::max(out.maxAbs, std::abs(out.r[k]));
    }
    sweep();
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
  double uniformStep_ = 0.0;  ///< the step when all steps are equal (the lag filter's fast path)
  // The target minus its first value: per block its sum and sum of squares.
  std::vector<double> yc_, ySum_, yy_;
  double y0_ = 0.0;
  // The coarse resolution of the lag search: groups of m consecutive rows inside
  // each block, their means weighted by their sizes; m = 1 (no coarse search) up to kCoarseRows rows.
  bool coarse_ = false;
  std::vector<std::size_t> gEdge_, gOfBlock_;
  std::vector<double> yMean_, yyCoarse_, gTime_, gW_;
  Observer* observer_ = nullptr;
  mutable bool stopped_ = false;
  mutable long pollSteps_ = 0;
  mutable double pollCurrent_ = 0.0;
  std::vector<double> w_;  ///< per row: 0 for an excluded gross error, else 1
  bool anyExcluded_ = false;
  std::vector<double> blockN_;                                      ///< per block: the rows not excluded
  double fitN_ = 0.0;                                               ///< fit rows not excluded
  mutable std::map<std::string, std::vector<double>> coarseInput_;  ///< group means of lagged inputs
  mutable std::vector<Generic> generic_;
  mutable std::map<std::string, Column> store_;
  mutable std::map<std::pair<std::string, std::string>, std::vector<double>> dots_;
  mutable std::vector<std::string> temporary_;
};

/// Grams of every view of `states`, computed once per distinct state.
class GramSet {
 public:
  GramSet(const Problem& pb, const Views& states, bool coarse = false) {
    for (int v = 0; v < pb.views(); ++v) {
      const State& s = states[static_cast<std::size_t>(v)];
      const int key = pb.columnsKey(v);
      std::size_t at = cache_.size();
      for (std::size_t i = 0; i < cache_.size(); ++i)
        if (keys_[i] == key && cache_[i].first == s) at = i;
      if (at == cache_.size()) {
        cache_.emplace_back(s, pb.grams(s, v, coarse));
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
  std::vector<double> tau;   ///< per view
  std::optional<double> se;  ///< of the full view's tau
  Views next;
  Fit fit;
};

/// Brent's minimisation (golden section with parabolic steps; Brent 1973, ch. 5) of f on [a, b] to
/// an absolute tolerance `tol` (log tau). Non-finite values force golden steps.
template <class F>
double brentMinimise(double a, double b, double tol, F f) {
  const double cgold = 0.3819660112501051;
  double x = a + cgold * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int it = 0; it < 60; ++it) {
    const double xm = 0.5 * (a + b), tol2 = 2.0 * tol;
    if (std::abs(x - xm) <= tol2 - 0.5 * (b - a)) break;
    bool golden = true;
    if (std::abs(e) > tol && std::isfinite(fx) && std::isfinite(fw) && std::isfinite(fv)) {
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double eOld = e;
      e = d;
      if (q > 0.0 && std::abs(p) < std::abs(0.5 * q * eOld) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = xm >= x ? tol : -tol;
        golden = false;
      }
    }
    if (golden) {
      e = x >= xm ? a - x : b - x;
      d = cgold * e;
    }
    const double u = std::abs(d) >= tol ? x + d : x + (d >= 0.0 ? tol : -tol);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? a : b) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return x;
}

/// 1-D search over tau, per view, for `withTau(tau, view)` (see the header comment): a shared
/// log-spaced grid, then golden section per view on that view's own rows.
template <class WithTau>
LagEstimate searchLag(const Problem& pb, int gridPoints, WithTau withTau, double hint = 0.0) {
  const double lo = 0.5 * pb.medianStep();
  const double hi = std::max(2.0 * lo, pb.time()[pb.fitRows() - 1] - pb.time()[0]);
  const int V = pb.views();
  auto statesAt = [&](double tau) {
    Views s;
    for (int v = 0; v < V; ++v) s.push_back(withTau(tau, v));
    return s;
  };
  const double a = std::log(lo), b = std::log(hi);
  // With a hint: nine points within a factor 3.3 of it instead of the grid over the whole range.
  const int g = hint > 0.0 ? 9 : std::max(8, gridPoints);
  std::vector<double> grid(static_cast<std::size_t>(g));
  std::vector<std::vector<double>> val(static_cast<std::size_t>(V), std::vector<double>(grid.size()));
  for (int i = 0; i < g; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    grid[ii] = hint > 0.0 ? std::clamp(std::log(hint) + 0.3 * (i - 4), a, b) : a + (b - a) * i / (g - 1);
    if (pb.poll()) {
      for (auto& vv : val) vv[ii] = kInf;
      continue;
    }
    {
      const GramSet gs(pb, statesAt(std::exp(grid[ii])), true);
      const auto per = gs.perView();
      for (int v = 0; v < V; ++v)
        val[static_cast<std::size_t>(v)][ii] = pb.viewSse(*per[static_cast<std::size_t>(v)], v);
    }
    pb.sweep();
  }
  LagEstimate e;
  for (int v = 0; v < V; ++v) {
    const auto& vv = val[static_cast<std::size_t>(v)];
    const std::size_t best = static_cast<std::size_t>(std::min_element(vv.begin(), vv.end()) - vv.begin());
    const double l = grid[best == 0 ? 0 : best - 1],
                 r = grid[std::min<std::size_t>(best + 1, grid.size() - 1)];
    const bool full = v == pb.fullView();
    auto sseAt = [&](double logTau, bool coarse) {
      if (pb.poll()) return kInf;
      const double r = pb.viewSse(pb.grams(withTau(std::exp(logTau), v), v, coarse), v);
      pb.sweep();
      return r;
    };
    // The folds on the coarse resolution to 1e-3 in log tau; the fit on all fit rows (its tau is
    // reported) to 1e-3 there, then on every row to 1e-5 within +-0.05 of it.
    double logTau = brentMinimise(l, r, 1e-3, [&](double x) { return sseAt(x, true); });
    if (vv[best] < sseAt(logTau, true)) logTau = grid[best];
    if (full) {
      const double c = logTau;
      logTau = brentMinimise(std::max(a, c - 0.05), std::min(b, c + 0.05), 1e-5,
                             [&](double x) { return sseAt(x, false); });
      if (sseAt(c, false) < sseAt(logTau, false)) logTau = c;
    }
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
  pb.sweep();
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
  double s = 0.0, m = 0.0;
  for (std::size_t k = 1; k < nFit; ++k)
    if (!res.excluded[k] && !res.excluded[k - 1]) {
      s += std::pow(res.r[k] - res.r[k - 1], 2);
      m += 1.0;
    }
  return m > 0.0 ? std::sqrt(s / m / 2.0) : 0.0;
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

/// Parameters of a generic effect (residual_check.h summariseGeneric: form, rms, range, ...) from a
/// fit that contains its columns.
void genericParameters(const Problem& pb, int index, const Fit& f, const std::string& u, Eval& e) {
  const auto& g = pb.generic(index);
  const std::string prefix = "unexplained:" + g.form.against + "#";
  Eigen::VectorXd b(g.basis.cols());
  for (Eigen::Index j = 0; j < b.size(); ++j) {
    const auto c = coefficientOf(f, prefix + std::to_string(j));
    b(j) = c ? c->first : 0.0;
  }
  const GenericSummary gs = summariseGeneric(g.form, b, g.values, u.empty() ? "" : u.substr(1));
  e.parameters = {Parameter{"form", std::string(formName(g.form.form)), std::nullopt}};
  for (const auto& [k, v] : gs.numbers) e.parameters.push_back({k, v, std::nullopt});
  e.paramText = gs.text;
}

Eval evaluateCandidate(const Problem& pb, const ThermalLog& log, const ThermalDiagnosisOptions& o,
                       const std::string& name, const Views& base, const std::string& u, double lagHint = 0.0,
                       int genericIndex = -1) {
  Eval e;
  e.next = base;
  if (isLag(name)) {
    const std::string col = name == "lag" ? "" : name.substr(4);
    LagEstimate le = searchLag(
        pb, o.lagGridPoints,
        [&](double tau, int view) {
          State s = base[static_cast<std::size_t>(view)];
          if (col.empty())
            s.effects.lagAll = tau;
          else
            s.effects.lagCol[col] = tau;
          return s;
        },
        lagHint);
    e.next = std::move(le.next);
    e.fit = le.fit;
    const double tau = le.tau.back();
    e.parameters = {{"tau_min", tau, le.se}};
    e.paramText = {le.se ? Phrase("tau %1 +- %2 min", {num(tau), num(*le.se, 2)})
                         : Phrase("tau %1 min", {num(tau)})};
  } else if (genericIndex >= 0) {
    for (State& s : e.next) s.generics.push_back(genericIndex);
    e.fit = fitViews(pb, e.next);
    if (e.fit.ok) genericParameters(pb, genericIndex, e.fit, u, e);
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
  pb.sweep();
  return e;
}

/// A lag's tau is determined by the fit rows when its standard error is known and below half of it
/// (a lag of 279 +- 230 min fits the fit rows' end and says nothing about the rows after them).
bool determined(const Eval& e) {
  for (const Parameter& p : e.parameters)
    if (p.name == "tau_min") {
      const double tau = std::get<double>(p.value);
      return p.standardError && *p.standardError < 0.5 * tau;
    }
  return true;
}

/// The evidence figures of a candidate: "validation rmse a -> b (c %), fit rmse ..., held-out rmse
/// ... (reported only)".
std::vector<PhraseArg> figureArgs(const Fit& cur, const Fit& f, const std::string& u) {
  return {num(cur.cv),   num(f.cv),   A::unit(u),       pct(cur.cv, f.cv),
          num(cur.rmse), num(f.rmse), num(cur.heldout), num(f.heldout)};
}

/// The variables the residual may depend on (docs/file-formats.md#residual_check), on every row: time (its
/// natural order), row (file order), and every numeric column of the log but the target (declared
/// inputs too: a non-linear dependence on a declared input is structure the model lacks).
std::vector<ResidualVariable> residualVariables(const ThermalLog& log, const std::string& target) {
  std::vector<ResidualVariable> vars;
  ResidualVariable t;
  t.name = "time";
  t.values = log.timeMin;
  t.naturalOrder = true;
  t.label = {Phrase("time (min)")};
  vars.push_back(std::move(t));
  ResidualVariable r;
  r.name = "row";
  for (std::size_t k = 0; k < log.rows(); ++k) r.values.push_back(static_cast<double>(k + 1));
  r.label = {Phrase("data row")};
  vars.push_back(std::move(r));
  for (const auto& c : log.channels) {
    if (c.name == target) continue;
    ResidualVariable v;
    v.name = c.name;
    v.values = c.values;
    v.label = {Phrase("%1", {A::name(c.name)})};
    vars.push_back(std::move(v));
  }
  return vars;
}

/// Groups [begin, end) of `size` consecutive rows of [b, e) (1: every row).
std::vector<std::pair<std::size_t, std::size_t>> rowGroups(std::size_t b, std::size_t e, std::size_t size) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t g = b; g < e; g += size) out.emplace_back(g, std::min(e, g + size));
  return out;
}

/// The residual check of the rows of `groups` that were not excluded, on the means of each group,
/// against the model's columns and the variables; with `withExcluded` the excluded rows of the groups
/// go along for the plot.
ResidualCheck checkRows(const Problem& pb, const State& s, const Residual& res,
                        const std::vector<ResidualVariable>& vars,
                        const std::vector<std::pair<std::size_t, std::size_t>>& groups, bool withExcluded) {
  const auto cols = pb.columnValues(s);
  const std::size_t width = 1 + cols.size() + vars.size();
  std::vector<std::vector<double>> means(width);  // residual, columns..., variables...
  std::vector<long> first;
  std::vector<double> sum(width);
  for (const auto& [gb, ge] : groups) {
    std::fill(sum.begin(), sum.end(), 0.0);
    double cnt = 0.0;
    long row = 0;
    for (std::size_t k = gb; k < ge; ++k) {
      if (res.excluded[k]) continue;
      if (cnt == 0.0) row = static_cast<long>(k + 1);
      cnt += 1.0;
      sum[0] += res.r[k];
      for (std::size_t j = 0; j < cols.size(); ++j) sum[1 + j] += (*cols[j])[k];
      for (std::size_t j = 0; j < vars.size(); ++j) sum[1 + cols.size() + j] += vars[j].values[k];
    }
    if (cnt == 0.0) continue;
    for (std::size_t j = 0; j < width; ++j) means[j].push_back(sum[j] / cnt);
    first.push_back(row);
  }
  const auto n = static_cast<Eigen::Index>(first.size());
  ResidualCheckInput in;
  in.residual = Eigen::Map<const Eigen::VectorXd>(means[0].data(), n);
  in.modelColumns.resize(n, static_cast<Eigen::Index>(cols.size()));
  for (std::size_t j = 0; j < cols.size(); ++j)
    in.modelColumns.col(static_cast<Eigen::Index>(j)) =
        Eigen::Map<const Eigen::VectorXd>(means[1 + j].data(), n);
  in.unitRow = std::move(first);
  for (std::size_t j = 0; j < vars.size(); ++j) {
    ResidualVariable w = vars[j];
    w.values = std::move(means[1 + cols.size() + j]);
    in.variables.push_back(std::move(w));
  }
  if (withExcluded && !groups.empty()) {
    const std::size_t b = groups.front().first, e = groups.back().second;
    for (std::size_t k = b; k < e; ++k)
      if (res.excluded[k]) in.excludedResidual.push_back(res.r[k]);
    if (!in.excludedResidual.empty())
      for (const ResidualVariable& v : vars) {
        std::vector<double> x;
        for (std::size_t k = b; k < e; ++k)
          if (res.excluded[k]) x.push_back(v.values[k]);
        in.excludedValues.push_back(std::move(x));
      }
  }
  // Periodic in time with an unknown period (a coolant or air-conditioning cycle no logged column sees).
  ResidualCheckOptions options;
  options.periodSearch = true;
  return checkResidual(in, options);
}

/// The residual check (residual_check.h) of a state's fit on the fit rows that were not excluded.
/// With `coarse` above kCoarseRows rows, the round's search for structure (which generic candidates to
/// try) runs on the means of the problem's coarse groups; the final check uses every row.
ResidualCheck checkOf(const Problem& pb, const State& s, const Residual& res,
                      const std::vector<ResidualVariable>& vars, bool coarse = false) {
  const auto groups = pb.fitGroups();
  if (coarse && !groups.empty()) return checkRows(pb, s, res, vars, groups, false);
  return checkRows(pb, s, res, vars, rowGroups(0, pb.fitRows(), 1), true);
}

/// The residual check of the held-out rows that were not excluded (the model's columns as in the
/// fit); above kCoarseRows rows on means of consecutive groups of rows.
ResidualCheck heldoutCheckOf(const Problem& pb, const State& s, const Residual& res,
                             const std::vector<ResidualVariable>& vars) {
  const std::size_t b = pb.fitRows(), e = pb.rows();
  return checkRows(pb, s, res, vars,
                   rowGroups(b, e, std::max<std::size_t>(1, (e - b + kCoarseRows - 1) / kCoarseRows)), true);
}

/// The variable a named effect is chosen for (its generic alternative is unexplained:<that>).
std::string variableOf(const std::string& name) {
  if (name.starts_with("lag:")) return name.substr(4);
  if (name.starts_with("input:")) return name.substr(6);
  if (name == "drift") return "time";
  return {};
}

}  // namespace

const char* toString(ThermalDeclaredModel m) {
  switch (m) {
    case ThermalDeclaredModel::Gmc:
      return "gmc";
    case ThermalDeclaredModel::Gnnmci:
      return "gnnmci";
    case ThermalDeclaredModel::Linear:
      break;
  }
  return "linear";
}

ThermalDeclaredModel thermalDeclaredModel(const std::string& name, const std::string& field) {
  for (ThermalDeclaredModel m :
       {ThermalDeclaredModel::Linear, ThermalDeclaredModel::Gmc, ThermalDeclaredModel::Gnnmci})
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
  if (log.gaps) {
    // An MTConnect log: the rows with a value in the target and every declared input, and the channels
    // with a value in all of them (thermal_data.h), so no gap reaches a fit or a test.
    std::vector<std::string> used = o.inputs;
    used.push_back(o.target);
    return diagnoseThermal(thermal::thermalLogWithoutGaps(log, used), o, observer);
  }
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
  pb.pin(state);
  Fit cur = fitViews(pb, state);
  if (!cur.ok) throw ValidationError(ErrorContext{log.source, 0, 0, "inputs"}, cur.why.english());
  Residual curRes = pb.residual(state[full], cur);
  // Gross errors (`outliers`, docs/file-formats.md#residual_check): robust z of the declared model's residual
  // on the fit rows (residual_check.h findOutliers), excluded from every fit (weight 0), the model refitted.
  std::vector<Outlier> outliers, heldoutOutliers;
  double outlierThreshold = 0.0, heldoutThreshold = 0.0;
  {
    ResidualCheckInput in;
    in.residual.resize(static_cast<Eigen::Index>(pb.fitRows()));
    for (std::size_t k = 0; k < pb.fitRows(); ++k) {
      in.residual(static_cast<Eigen::Index>(k)) = curRes.r[k];
      in.unitRow.push_back(static_cast<long>(k + 1));
    }
    outliers = findOutliers(in, {}, &outlierThreshold);
    // The held-out rows' gross errors, on their own robust scale (the declared model's prediction
    // there may drift): excluded from the held-out figures and listed in the held-out check only.
    // They decide nothing (the held-out rows are in no fit), so the effects stay the same.
    ResidualCheckInput held;
    held.residual.resize(static_cast<Eigen::Index>(pb.rows() - pb.fitRows()));
    for (std::size_t k = pb.fitRows(); k < pb.rows(); ++k) {
      held.residual(static_cast<Eigen::Index>(k - pb.fitRows())) = curRes.r[k];
      held.unitRow.push_back(static_cast<long>(k + 1));
    }
    heldoutOutliers = findOutliers(held, {}, &heldoutThreshold);
    for (Outlier& x : heldoutOutliers) x.unit += pb.fitRows();
    if (!outliers.empty() || !heldoutOutliers.empty()) {
      std::vector<std::size_t> rows;
      for (const Outlier& x : outliers) rows.push_back(x.unit);
      for (const Outlier& x : heldoutOutliers) rows.push_back(x.unit);
      pb.exclude(rows);
      pb.pin(state);
      cur = fitViews(pb, state);
      if (!cur.ok) throw ValidationError(ErrorContext{log.source, 0, 0, "inputs"}, cur.why.english());
      curRes = pb.residual(state[full], cur);
    }
  }
  d.baseline = summaryOf(cur, curRes);
  const double noise = noiseLevel(curRes, pb.fitRows());
  const std::vector<ResidualVariable> variables = residualVariables(log, o.target);
  std::vector<std::string> genericTaken;
  if (pb.grey()) {
    std::string inputs;
    for (const auto& in : o.inputs) inputs += (inputs.empty() ? "" : ", ") + in;
    const auto [ownFit, ownHeld] = pb.declaredOwnRmse();
    d.addNote({Phrase(
        "declared model %1 of %2 (fitted on the first %3 of %4 rows as thermal fit does; alone: fit "
        "rmse %5, held-out rmse %6%7); the loop fits the target on its prediction (coefficient %8) "
        "and the candidate effects",
        {A::name(o.declared == ThermalDeclaredModel::Gmc ? "GMC(1,N)" : "GNNMCI(1,N)"), A::name(inputs),
         A::integer(static_cast<long long>(pb.fitRows())), A::integer(static_cast<long long>(pb.rows())),
         num(ownFit), num(ownHeld), A::unit(u), num(cur.beta(0))})});
  } else {
    Phrases model = {Phrase("%1 = c0", {A::name(o.target)})};
    for (std::size_t j = 0; j < o.inputs.size(); ++j)
      model.push_back(
          Phrase(" + %1 %2", {num(cur.beta(static_cast<Eigen::Index>(j))), A::name(o.inputs[j])}));
    d.addNote({Phrase("declared model (static, fitted on the first %1 of %2 rows): %3",
                      {A::integer(static_cast<long long>(pb.fitRows())),
                       A::integer(static_cast<long long>(pb.rows())), A::text(std::move(model))})});
  }
  if (!outliers.empty()) {
    Phrases note = {Phrase("%1 gross errors excluded before the fit (robust z above %2):",
                           {A::integer(static_cast<long long>(outliers.size())), num(outlierThreshold)})};
    for (const Outlier& x : outliers)
      note.push_back(Phrase(" row %1 (%2%3)",
                            {A::integer(x.row.value_or(0)), A::signedNumber(x.residual, 3), A::unit(u)}));
    d.addNote(std::move(note));
  }
  {
    d.addNote(
        {Phrase("noise level (first differences of the fit residual): %1%2", {num(noise), A::unit(u)})});
    d.addNote(
        {Phrase("effects chosen on the fit rows by blocked forward validation (%1 folds, validation "
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

  /// The thermal domain of the shared loop (loop.h): the target as a linear function of the model's
  /// columns (declared inputs or a grey model's prediction, lagged inputs, further inputs, drift,
  /// generic bases), effects chosen by blocked forward validation on the fit rows.
  struct Domain final : LoopDomain {
    Problem& pb;
    const ThermalLog& log;
    const ThermalDiagnosisOptions& o;
    const std::string& u;
    const std::string units;  // a copy: the diagnosis is moved into the loop
    const std::vector<ResidualVariable>& variables;
    const std::vector<std::string>& undeclared;
    const std::size_t full;
    const double noise, nf;
    Views& state;
    Fit& cur;
    Residual& curRes;
    long steps = 0;
    // The round's candidates (by slot).
    ResidualCheck check;  // of the current residual (the structure the candidates are for)
    double genericPenalty = 0.0;
    std::map<std::string, int> genericOf;
    std::vector<std::string> names;
    std::vector<Views> states;
    std::vector<Fit> fits;
    std::vector<Eval> evals;  // the single candidates (the pair search starts from them)

    Domain(Problem& pb_, const ThermalLog& log_, const ThermalDiagnosisOptions& o_, const std::string& u_,
           const std::string& units_, const std::vector<ResidualVariable>& variables_,
           const std::vector<std::string>& undeclared_, std::size_t full_, double noise_, Views& state_,
           Fit& cur_, Residual& curRes_)
        : pb(pb_),
          log(log_),
          o(o_),
          u(u_),
          units(units_),
          variables(variables_),
          undeclared(undeclared_),
          full(full_),
          noise(noise_),
          nf(pb_.fitCount()),
          state(state_),
          cur(cur_),
          curRes(curRes_) {}

    bool beginRound(int) override {
      names.clear();
      states.clear();
      fits.clear();
      evals.clear();
      genericOf.clear();
      return !pb.poll();
    }
    std::vector<std::string> namedCandidates(const std::set<std::string>&) override {
      const ThermalEffectSet& now = state[full].effects;
      std::vector<std::string> out;
      if (!(now.lagAll > 0.0) && !pb.grey()) out.push_back("lag");
      if (o.inputs.size() > 1 || now.lagAll > 0.0 || pb.grey())
        for (const auto& in : o.inputs)
          if (!now.lagCol.count(in)) out.push_back("lag:" + in);
      for (const auto& c : undeclared)
        if (std::find(now.extra.begin(), now.extra.end(), c) == now.extra.end()) out.push_back("input:" + c);
      if (!now.drift) out.push_back("drift");
      return out;
    }
    // Generic candidates (docs/file-formats.md#generic-effects): the strongest structures of the current
    // residual on the fit rows, each a basis of its variable (evaluated on every row), under the same
    // evidence plus the search penalty 2 ln(tests) in the in-sample criterion.
    ResidualCheck roundCheck() override {
      check = checkOf(pb, state[full], curRes, variables, true);
      genericPenalty = genericSearchPenalty(check);
      return check;
    }
    std::optional<GenericForm> prepareGeneric(const GenericForm& form) override {
      GenericForm g = form;
      const ThermalEffectSet& now = state[full].effects;
      const ResidualVariable* v = findVariable(variables, g.against);
      const int ch = log.indexOf(g.against);
      if (!v ||
          (ch >= 0 && channelKind(log.channels[static_cast<std::size_t>(ch)]) == ChannelKind::Displacement))
        return std::nullopt;  // another displacement channel is an output, not a cause
      // A column the model has already (a declared input of the static model, an accepted input:c):
      // the generic effect is its curvature only (the linear part would repeat the column).
      const bool column =
          (!pb.grey() && std::find(o.inputs.begin(), o.inputs.end(), g.against) != o.inputs.end()) ||
          std::find(now.extra.begin(), now.extra.end(), g.against) != now.extra.end();
      if (column && g.form == DependenceForm::Linear) return std::nullopt;
      if (column && g.form == DependenceForm::Smooth) g.withoutLinear = true;
      genericOf["unexplained:" + g.against] = pb.addGeneric(g, v->values);
      return g;
    }
    std::optional<LoopTrial> tryNamed(const std::string& name, int, std::size_t slot) override {
      return tryCandidate(name, slot);
    }
    std::optional<LoopTrial> tryGeneric(const GenericForm& g, double, int, std::size_t slot) override {
      return tryCandidate("unexplained:" + g.against, slot);
    }

    std::optional<LoopTrial> tryCandidate(const std::string& name, std::size_t slot) {
      (void)slot;
      LoopTrial t;
      Candidate& c = t.candidate;
      c.name = name;
      c.rmseBefore = cur.rmse;
      c.heldoutBefore = cur.heldout;
      const auto gi = genericOf.find(name);
      const int generic = gi == genericOf.end() ? -1 : gi->second;
      pb.setStep(steps, cur.cv);
      Eval ev0 = evaluateCandidate(pb, log, o, name, state, u, 0.0, generic);
      if (pb.stopped()) return std::nullopt;  // stopped inside the candidate: it is not listed
      if (generic >= 0) c.generic = pb.generic(generic).form;
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
        const double width = generic >= 0 ? static_cast<double>(pb.generic(generic).basis.cols()) : 1.0;
        const double dBic =
            nf * std::log(f.sse / cur.sse) + width * std::log(nf) + (generic >= 0 ? genericPenalty : 0.0);
        const bool inSample = dBic < 0.0;
        std::vector<PhraseArg> args = figureArgs(cur, f, u);
        Phrases ev;
        if (paramText.empty()) {
          ev.push_back(
              Phrase("validation rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, held-out rmse %7 -> %8%3",
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
        else if (!determined(ev0))
          ev.push_back(
              Phrase("; rejected: the fit rows do not determine tau (standard error above half of it)"));
        c.setEvidence(std::move(ev));
        t.estimable = true;
        t.passes = gain && aboveNoise && inSample && determined(ev0);
      }
      names.push_back(name);
      states.push_back(ev0.next);
      fits.push_back(std::move(f));
      evals.push_back(std::move(ev0));
      ++steps;
      return t;
    }

    // "A named effect must explain what it was chosen for": a passing named effect is rejected when a
    // generic effect of the same variable validates better by the acceptance margin (loop.h: the
    // thermal form of "a generic effect of the same variable explains clearly more"; the generic one
    // need not pass: then neither is taken and the final check reports the structure)
    // (minHeldoutGain; a tie, e.g. drift and a linear function of time, keeps the name); named
    // effects are preferred to generic ones otherwise (the generic one is kept for what no name
    // explains). The choice is repeated while the chosen name fails to explain what it was chosen for.
    std::optional<long> choose(std::vector<LoopTrial>& trials) override {
      std::vector<bool> passed(trials.size());
      for (std::size_t i = 0; i < trials.size(); ++i) passed[i] = trials[i].passes;
      std::set<std::size_t> notTaken;
      std::optional<std::size_t> best;
      while (true) {
        {
          std::optional<std::size_t> named, gen;
          for (std::size_t i = 0; i < fits.size(); ++i) {
            if (!passed[i]) continue;
            const bool isGeneric = names[i].starts_with("unexplained:");
            if (!isGeneric) {
              const std::string var = variableOf(names[i]);
              const auto alt = std::find(names.begin(), names.end(), "unexplained:" + var);
              if (!var.empty() && alt != names.end()) {
                const auto j = static_cast<std::size_t>(alt - names.begin());
                if (j < fits.size() && fits[j].ok && fits[j].cvOk &&
                    fits[j].cv < (1.0 - o.minHeldoutGain) * fits[i].cv) {
                  passed[i] = false;
                  trials[i].candidate.addEvidence(
                      {Phrase("; rejected: the generic %1 validates better (%2 against %3%4)",
                              {A::name(names[j]), num(fits[j].cv), num(fits[i].cv), A::unit(u)})});
                  continue;
                }
              }
            }
            std::optional<std::size_t>& slot = isGeneric ? gen : named;
            if (!slot || rankOf(fits[i], cur) < rankOf(fits[*slot], cur)) slot = i;
          }
          // The name is preferred unless a generic effect of a measured column validates better by the
          // acceptance margin: then the name is not what the data need first (a curvature in T2 is
          // not a lag of every input), and the generic one is taken; the name may still pass later. A
          // function of time or row does not displace a name (it describes the fit rows, it predicts
          // nothing: on a grey model's log a spline in time validated 0.85 um and held out 9.1 um
          // where the named input:spindle_rpm held out 1.7 um).
          // A step or a cycle in time or row does predict (a constant after the change point, the same
          // cycle on): it displaces a name that validates worse (a re-zeroed gauge's step was taken by
          // lag:T_amb validating 2.11 um where the step in time validated 1.36 um, held out 28 against 0.5
          // um).
          const auto predicting = [&](std::size_t i) {
            const std::optional<GenericForm>& g = trials[i].candidate.generic;
            return g && g->form == DependenceForm::Step;
          };
          const bool measured =
              gen &&
              ((names[*gen] != "unexplained:time" && names[*gen] != "unexplained:row") || predicting(*gen));
          if (named && measured && fits[*gen].cv < (1.0 - o.minHeldoutGain) * fits[*named].cv) {
            if (notTaken.insert(*named).second)
              trials[*named].candidate.addEvidence(
                  {Phrase("; not taken: the generic %1 validates better (%2 against %3%4)",
                          {A::name(names[*gen]), num(fits[*gen].cv), num(fits[*named].cv), A::unit(u)})});
            named.reset();
          }
          best = named ? named : gen;
        }
        if (best && names[*best] == "lag") {
          // The specific claim first: `lag` (every input lagged) over the best passing `lag:<col>` only
          // when it validates another minHeldoutGain better (the fit rows often cannot tell whether an
          // input that hardly changes on them is lagged too).
          std::optional<std::size_t> one;
          for (std::size_t i = 0; i < names.size() && i < fits.size(); ++i)
            if (names[i].starts_with("lag:") && passed[i] &&
                (!one || rankOf(fits[i], cur) < rankOf(fits[*one], cur)))
              one = i;
          if (one && !(fits[*best].cv <= (1.0 - o.minHeldoutGain) * fits[*one].cv)) best = one;
        }
        // "A named effect must explain what it was chosen for" (docs/file-formats.md#generic-effects): after
        // a named effect of a variable (input:c: c; drift: time) the fit rows' residual must depend on that
        // variable at most half as much as before (variance explained by its structure: share x rmse^2);
        // otherwise it is rejected and the next one is chosen (an input that followed a periodic coolant load
        // by chance took 13 % of the validation error and left its own dependence as it was). Not "no longer
        // at all": a second effect correlated with the variable (the spindle heats T2) still shows through it
        // until it is added. Not for a lag: a lagged input changes how the residual depends on the input
        // itself (on a grey model's log the right lag:T2 left half of its T2 dependence until the spindle's
        // effect was added).
        if (!best || names[*best].starts_with("unexplained:") || isLag(names[*best])) break;
        const std::string var = variableOf(names[*best]);
        if (var.empty()) break;
        pb.pin(states[*best]);
        const Residual after = pb.residual(states[*best][full], fits[*best]);
        const ResidualCheck rc = checkOf(pb, states[*best][full], after, variables, true);
        pb.pin(state);
        auto on = [&](const ResidualCheck& c) {
          return std::find_if(c.structure.begin(), c.structure.end(),
                              [&](const StructureItem& x) { return x.against == var; });
        };
        const auto still = on(rc);
        if (still == rc.structure.end()) break;
        const auto before = on(check);
        const double was = before == check.structure.end() ? 0.0 : before->share * cur.rmse * cur.rmse;
        const double is = still->share * fits[*best].rmse * fits[*best].rmse;
        if (is <= 0.5 * was) break;
        passed[*best] = false;
        trials[*best].candidate.addEvidence(
            {Phrase("; rejected: the residual still depends on %1 after it (%2, p = %3)",
                    {A::name(var), A::name(formName(still->form)), A::number(still->p, 2)})});
        best.reset();
      }
      for (std::size_t i = 0; i < trials.size(); ++i) trials[i].passes = passed[i] && !notTaken.count(i);
      return best ? static_cast<long>(*best) : -1L;
    }

    std::vector<Candidate> whenNoneChosen(const std::vector<LoopTrial>&, int round) override {
      std::vector<Candidate> out;
      if (!(o.tryPairs && cur.cvOk)) return out;
      {
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
        // Partners: every linear candidate (a column each), and the lags among the six candidates with
        // the lowest fit error (before the coarse lag grid every lag: on a week of 1 Hz data that was up to
        // 60 pairs, each with one or two lag searches).
        std::vector<std::size_t> byFit;
        for (std::size_t i = 0; i < fits.size(); ++i)
          if (fits[i].ok) byFit.push_back(i);
        std::stable_sort(byFit.begin(), byFit.end(),
                         [&](std::size_t a, std::size_t b) { return fits[a].sse < fits[b].sse; });
        std::vector<std::size_t> partners;
        for (std::size_t r = 0; r < byFit.size(); ++r)
          if (!isLag(names[byFit[r]]) || r < 6) partners.push_back(byFit[r]);
        std::sort(partners.begin(), partners.end());
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for (std::size_t x : strong)
          for (std::size_t y : partners)
            if (y != x && std::find(pairs.begin(), pairs.end(), std::make_pair(y, x)) == pairs.end())
              pairs.emplace_back(x, y);
        for (const auto& [px, py] : pairs) {
          const std::string &na = names[px], &nb = names[py];
          if (isLag(na) && isLag(nb)) continue;
          if (na.starts_with("unexplained:") || nb.starts_with("unexplained:")) continue;
          Eval ea = evals[px];  // na added to the current model, as evaluated above
          const Eval eb = evaluateCandidate(pb, log, o, nb, ea.next, u);
          if (!eb.fit.ok) continue;
          Fit pf = eb.fit;
          Views ps = eb.next;
          if (isLag(na)) {  // re-estimate the lag with the other effect present, near its tau alone
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
          const bool pass =
              pf.cv <= (1.0 - o.minHeldoutGain) * cur.cv && explained >= o.minExplainedNoise * noise &&
              nf * std::log(pf.sse / cur.sse) + 2.0 * std::log(nf) < 0.0 && determined(ea) && determined(fb);
          if (pass && (!bestA || rankOf(pf, cur) < rankOf(bestFit, cur))) {
            bestNames = {na, nb};
            bestA = ea;
            bestB = fb;
            bestFit = pf;
            bestStates = ps;
          }
        }
        if (bestA) {
          pb.pin(bestStates);
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
            c.setEvidence(
                {Phrase("accepted together with %1: validation rmse %2 -> %3%4 (%5), fit rmse %6 -> "
                        "%7%4, held-out rmse %8 -> %9%4, %10",
                        std::move(args))});
            c.plot = residualPlot(after);
            out.push_back(std::move(c));
          }
          state = bestStates;
          pb.pin(state);
          cur = bestFit;
          curRes = after;
        }
      }
      return out;
    }

    /// The current residual against time, before and `after` an accepted candidate.
    ResidualPlot residualPlot(const Residual& after) const {
      ResidualPlot plot;
      plot.setLabels(timeLabel(), residualLabel(units));
      plot.x = log.timeMin;
      plot.before = curRes.r;
      plot.after = after.r;
      return plot;
    }

    void accept(std::size_t slot, Candidate& c) override {
      pb.pin(states[slot]);
      const Residual after = pb.residual(states[slot][full], fits[slot]);
      c.plot = residualPlot(after);
      state = states[slot];
      cur = fits[slot];
      curRes = after;
    }
    double currentError() const override { return cur.cv; }
    void finish(Diagnosis& dg, std::vector<Candidate*>, bool stopped) override {
      if (pb.stopped()) dg.addNote({Phrase("cancelled")});
      dg.final = summaryOf(cur, curRes);
      // The final residual's check on the fit rows (outliers excluded, listed).
      // (After a stop on a long log: the group means, to return at once.)
      dg.residualCheck = checkOf(pb, state[full], curRes, variables, stopped);
      // The held-out rows' residual, checked on its own: what the model still misses where it
      // predicts (a sensor re-zeroed after the fit rows, a change of the machine); reported only.
      if (pb.rows() > pb.fitRows() && !stopped)
        dg.heldoutCheck = heldoutCheckOf(pb, state[full], curRes, variables);
    }
    double dataCriterion() const override { return 0.0; }
  };

  pb.setObserver(observer);
  Domain domain(pb, log, o, u, d.units, variables, undeclared, full, noise, state, cur, curRes);
  Diagnosis out =
      runLoop(domain, LoopStyle::everyRound(o.maxRounds, "cv_rmse"), {}, observer, std::move(d)).diagnosis;
  out.residualCheck->outliers = outliers;
  out.residualCheck->outlierThreshold = outlierThreshold;
  if (out.heldoutCheck) {
    out.heldoutCheck->outliers = heldoutOutliers;
    out.heldoutCheck->outlierThreshold = heldoutThreshold;
  }
  return out;
}

}  // namespace metrofit::diagnose
