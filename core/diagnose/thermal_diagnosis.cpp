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
using ModelState = ThermalEffectSet;

struct Fit {
  bool ok = false;
  Phrase why;                       ///< when not ok
  std::vector<double> residual;     ///< all rows, y - prediction
  double rmse = 0.0, maxAbs = 0.0;  ///< fit rows
  double heldout = 0.0;             ///< held-out rows
  double sse = 0.0, s2 = 0.0;       ///< fit rows
  std::vector<std::string> names;   ///< column names (without the intercept)
  Eigen::VectorXd beta, se;         ///< per column, original units
};

class Problem {
 public:
  Problem(const ThermalLog& log, const ThermalDiagnosisOptions& o) : log_(log), o_(o) {
    y_ = log.channel(o.target).values;
    n_ = log.rows();
    nFit_ = thermal::fitRowCount(n_, o.trainFraction);
  }

  std::size_t rows() const { return n_; }
  std::size_t fitRows() const { return nFit_; }
  const std::vector<double>& time() const { return log_.timeMin; }

  Fit fit(const ModelState& m) const {
    std::vector<std::vector<double>> cols;
    Fit f;
    for (ThermalRegressor& r : thermalRegressors(log_, o_.inputs, m)) {
      cols.push_back(std::move(r.values));
      f.names.push_back(std::move(r.name));
    }
    const auto p = static_cast<Eigen::Index>(cols.size());
    const auto nf = static_cast<Eigen::Index>(nFit_);
    if (nf < p + 3) {
      f.why = Phrase("too few fit rows (%1) for %2 coefficients",
                     {A::integer(static_cast<long long>(nFit_)), A::integer(p + 1)});
      return f;
    }
    // Centre and scale every column on the fit rows (conditioning); the intercept absorbs the means.
    Eigen::VectorXd mean(p), sd(p);
    Eigen::MatrixXd X(nf, p + 1);
    X.col(0).setOnes();
    for (Eigen::Index j = 0; j < p; ++j) {
      const auto& c = cols[static_cast<std::size_t>(j)];
      double s = 0.0;
      for (Eigen::Index k = 0; k < nf; ++k) s += c[static_cast<std::size_t>(k)];
      mean(j) = s / static_cast<double>(nf);
      double v = 0.0;
      for (Eigen::Index k = 0; k < nf; ++k) v += std::pow(c[static_cast<std::size_t>(k)] - mean(j), 2);
      sd(j) = std::sqrt(v / static_cast<double>(nf));
      if (!(sd(j) > 1e-12 * std::max(1.0, std::abs(mean(j))))) {
        f.why = Phrase("column '%1' is constant on the fit rows",
                       {A::name(f.names[static_cast<std::size_t>(j)])});
        return f;
      }
      for (Eigen::Index k = 0; k < nf; ++k) X(k, j + 1) = (c[static_cast<std::size_t>(k)] - mean(j)) / sd(j);
    }
    Eigen::VectorXd yf(nf);
    for (Eigen::Index k = 0; k < nf; ++k) yf(k) = y_[static_cast<std::size_t>(k)];
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
    if (qr.rank() < p + 1) {
      f.why = Phrase("the columns are linearly dependent on the fit rows");
      return f;
    }
    const Eigen::VectorXd b = qr.solve(yf);
    f.residual.resize(n_);
    double sseFit = 0.0, sseHeld = 0.0;
    for (std::size_t k = 0; k < n_; ++k) {
      double pred = b(0);
      for (Eigen::Index j = 0; j < p; ++j)
        pred += b(j + 1) * (cols[static_cast<std::size_t>(j)][k] - mean(j)) / sd(j);
      const double r = y_[k] - pred;
      f.residual[k] = r;
      if (k < nFit_) {
        sseFit += r * r;
        f.maxAbs = std::max(f.maxAbs, std::abs(r));
      } else {
        sseHeld += r * r;
      }
    }
    f.sse = sseFit;
    f.rmse = std::sqrt(sseFit / static_cast<double>(nf));
    f.heldout = n_ > nFit_ ? std::sqrt(sseHeld / static_cast<double>(n_ - nFit_)) : 0.0;
    f.s2 = sseFit / static_cast<double>(nf - p - 1);
    const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(p + 1, p + 1).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd Rinv =
        R.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p + 1, p + 1));
    const Eigen::MatrixXd P = qr.colsPermutation().toDenseMatrix().cast<double>();
    const Eigen::MatrixXd cov = f.s2 * (P * Rinv * Rinv.transpose() * P.transpose());
    f.beta.resize(p);
    f.se.resize(p);
    for (Eigen::Index j = 0; j < p; ++j) {
      f.beta(j) = b(j + 1) / sd(j);
      f.se(j) = std::sqrt(std::max(0.0, cov(j + 1, j + 1))) / sd(j);
    }
    f.ok = true;
    return f;
  }

  double medianStep() const {
    std::vector<double> d;
    for (std::size_t k = 1; k < n_; ++k) d.push_back(log_.timeMin[k] - log_.timeMin[k - 1]);
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    return d[d.size() / 2];
  }

 private:
  const ThermalLog& log_;
  const ThermalDiagnosisOptions& o_;
  std::vector<double> y_;
  std::size_t n_ = 0, nFit_ = 0;
};

struct LagEstimate {
  double tau = 0.0;
  std::optional<double> se;
  Fit fit;
};

/// 1-D search over tau for `withTau(tau)` (see the header comment).
template <class WithTau>
LagEstimate searchLag(const Problem& pb, int gridPoints, WithTau withTau) {
  const double lo = 0.5 * pb.medianStep();
  const double hi = std::max(2.0 * lo, pb.time()[pb.fitRows() - 1] - pb.time()[0]);
  auto sse = [&](double logTau) {
    const Fit f = pb.fit(withTau(std::exp(logTau)));
    return f.ok ? f.sse : std::numeric_limits<double>::infinity();
  };
  const double a = std::log(lo), b = std::log(hi);
  const int g = std::max(8, gridPoints);
  std::vector<double> grid(static_cast<std::size_t>(g)), val(static_cast<std::size_t>(g));
  std::size_t best = 0;
  for (int i = 0; i < g; ++i) {
    grid[static_cast<std::size_t>(i)] = a + (b - a) * i / (g - 1);
    val[static_cast<std::size_t>(i)] = sse(grid[static_cast<std::size_t>(i)]);
    if (val[static_cast<std::size_t>(i)] < val[best]) best = static_cast<std::size_t>(i);
  }
  // Golden section between the neighbours of the best grid point.
  double l = grid[best == 0 ? 0 : best - 1], r = grid[std::min<std::size_t>(best + 1, grid.size() - 1)];
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = r - phi * (r - l), d = l + phi * (r - l);
  double fc = sse(c), fd = sse(d);
  for (int it = 0; it < 40 && r - l > 1e-6; ++it) {
    if (fc < fd) {
      r = d;
      d = c;
      fd = fc;
      c = r - phi * (r - l);
      fc = sse(c);
    } else {
      l = c;
      c = d;
      fc = fd;
      d = l + phi * (r - l);
      fd = sse(d);
    }
  }
  double logTau = fc < fd ? c : d;
  if (val[best] < std::min(fc, fd)) logTau = grid[best];
  LagEstimate e;
  e.tau = std::exp(logTau);
  e.fit = pb.fit(withTau(e.tau));
  if (e.fit.ok) {
    const double h = 0.02 * e.tau;
    const Fit fm = pb.fit(withTau(e.tau - h)), fp = pb.fit(withTau(e.tau + h));
    if (fm.ok && fp.ok) {
      const double curv = (fp.sse - 2.0 * e.fit.sse + fm.sse) / (h * h);
      if (curv > 0.0) e.se = std::sqrt(2.0 * e.fit.s2 / curv);
    }
  }
  return e;
}

/// Ranks the candidates that passed the tests: the log ratios of the held-out and of the fit rmse
/// together (lower is better), so that a lucky extrapolation with hardly any in-sample gain does
/// not win over an effect that explains both parts of the data.
double rankOf(const Fit& f, const Fit& cur) {
  return std::log(f.heldout / cur.heldout) + std::log(f.rmse / cur.rmse);
}

ErrorSummary summaryOf(const Fit& f) {
  ErrorSummary s;
  s.rmse = f.rmse;
  s.maxAbs = f.maxAbs;
  s.heldoutRmse = f.heldout;
  return s;
}

double noiseLevel(const Fit& f, std::size_t nFit) {
  double s = 0.0;
  for (std::size_t k = 1; k < nFit; ++k) s += std::pow(f.residual[k] - f.residual[k - 1], 2);
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

/// One candidate added to `base`: the model state, its fit, the parameters and their text.
struct Eval {
  ModelState next;
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
                       const std::string& name, const ModelState& base, const std::string& u) {
  Eval e;
  e.next = base;
  if (isLag(name)) {
    const std::string col = name == "lag" ? "" : name.substr(4);
    const LagEstimate le = searchLag(pb, o.lagGridPoints, [&](double tau) {
      ModelState s = base;
      if (col.empty())
        s.lagAll = tau;
      else
        s.lagCol[col] = tau;
      return s;
    });
    if (col.empty())
      e.next.lagAll = le.tau;
    else
      e.next.lagCol[col] = le.tau;
    e.fit = le.fit;
    e.parameters = {{"tau_min", le.tau, le.se}};
    e.paramText = {le.se ? Phrase("tau %1 +- %2 min", {num(le.tau), num(*le.se, 2)})
                         : Phrase("tau %1 min", {num(le.tau)})};
  } else {
    if (name == "drift")
      e.next.drift = true;
    else
      e.next.extra.push_back(name.substr(6));
    e.fit = pb.fit(e.next);
    if (e.fit.ok) linearParameters(log, name, e.fit, u, e);
  }
  return e;
}

}  // namespace

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
  return true;
}

Diagnosis diagnoseThermal(const ThermalLog& log, const ThermalDiagnosisOptions& o, Observer* observer) {
  validate(log, o);
  const Problem pb(log, o);
  Diagnosis d;
  d.domain = "thermal";
  d.units = log.channel(o.target).unit;
  const std::string u = d.units.empty() ? "" : " " + d.units;

  ModelState state;
  Fit cur = pb.fit(state);
  if (!cur.ok) throw ValidationError(ErrorContext{log.source, 0, 0, "inputs"}, cur.why.english());
  d.baseline = summaryOf(cur);
  const double noise = noiseLevel(cur, pb.fitRows());
  {
    Phrases model = {Phrase("%1 = c0", {A::name(o.target)})};
    for (std::size_t j = 0; j < o.inputs.size(); ++j)
      model.push_back(
          Phrase(" + %1 %2", {num(cur.beta(static_cast<Eigen::Index>(j))), A::name(o.inputs[j])}));
    d.addNote({Phrase("declared model (static, fitted on the first %1 of %2 rows): %3",
                      {A::integer(static_cast<long long>(pb.fitRows())),
                       A::integer(static_cast<long long>(pb.rows())), A::text(std::move(model))})});
    d.addNote(
        {Phrase("noise level (first differences of the fit residual): %1%2", {num(noise), A::unit(u)})});
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
  for (int round = 0; round < o.maxRounds && !cancelled; ++round) {
    // This round's candidates.
    std::vector<std::string> names;
    if (!(state.lagAll > 0.0)) names.push_back("lag");
    if (o.inputs.size() > 1 || state.lagAll > 0.0)
      for (const auto& in : o.inputs)
        if (!state.lagCol.count(in)) names.push_back("lag:" + in);
    for (const auto& c : undeclared)
      if (std::find(state.extra.begin(), state.extra.end(), c) == state.extra.end())
        names.push_back("input:" + c);
    if (!state.drift) names.push_back("drift");
    if (names.empty()) break;

    std::vector<Candidate> tried;
    std::vector<ModelState> states;
    std::vector<Fit> fits;
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string& name = names[i];
      Candidate c;
      c.name = name;
      c.round = round;
      c.rmseBefore = cur.rmse;
      c.heldoutBefore = cur.heldout;
      Eval ev0 = evaluateCandidate(pb, log, o, name, state, u);
      ModelState next = ev0.next;
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
        c.score = cur.heldout > 0.0 ? (f.heldout - cur.heldout) / cur.heldout : 0.0;
        const double explained = std::sqrt(std::max(0.0, cur.heldout * cur.heldout - f.heldout * f.heldout));
        const bool gain = f.heldout <= (1.0 - o.minHeldoutGain) * cur.heldout;
        const bool aboveNoise = explained >= o.minExplainedNoise * noise;
        // In-sample evidence too: the fit's sum of squares must fall by more than the BIC penalty
        // of the added parameter (n ln(SSE0 / SSE1) > ln n), so that a coefficient the fit rows
        // cannot determine does not win by a lucky extrapolation.
        const double nf = static_cast<double>(pb.fitRows());
        const double dBic = nf * std::log(f.sse / cur.sse) + std::log(nf);
        const bool inSample = dBic < 0.0;
        std::vector<PhraseArg> args = {num(cur.heldout), num(f.heldout),
                                       A::unit(u),       pct(cur.heldout, f.heldout),
                                       num(cur.rmse),    num(f.rmse)};
        Phrases ev;
        if (paramText.empty()) {
          ev.push_back(Phrase("held-out rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3", std::move(args)));
        } else {
          args.push_back(A::text(paramText));
          ev.push_back(Phrase("held-out rmse %1 -> %2%3 (%4), fit rmse %5 -> %6%3, %7", std::move(args)));
        }
        if (f.heldout > cur.heldout)
          ev.push_back(Phrase("; rejected: held-out error worse"));
        else if (!gain)
          ev.push_back(Phrase("; rejected: held-out gain below %1 %", {num(100.0 * o.minHeldoutGain, 2)}));
        else if (!aboveNoise)
          ev.push_back(Phrase("; rejected: explains %1%2, below %3 x the noise level %4%2",
                              {num(explained), A::unit(u), num(o.minExplainedNoise), num(noise)}));
        else if (!inSample)
          ev.push_back(Phrase("; rejected: no in-sample evidence (fit dBIC %1 >= 0)", {num(dBic)}));
        c.setEvidence(std::move(ev));
        if (gain && aboveNoise && inSample && (!best || rankOf(f, cur) < rankOf(fits[*best], cur))) best = i;
      }
      tried.push_back(std::move(c));
      states.push_back(std::move(next));
      fits.push_back(std::move(f));

      if (progress.afterCandidate(round, i, names.size(), cur.heldout, "heldout_rmse")) {
        cancelled = true;
        break;
      }
    }
    if (cancelled) best.reset();
    bool pairAccepted = false;
    if (!best && !cancelled && o.tryPairs) {
      // Two effects together: when no single candidate passes, each of the three with the strongest
      // in-sample evidence is tried with every other candidate (alone, each may extrapolate worse
      // than the declared model, while together they explain the data). Same tests, with the
      // penalty of 2 parameters.
      const double nf = static_cast<double>(pb.fitRows());
      std::vector<std::size_t> strong;
      for (std::size_t i = 0; i < fits.size(); ++i)
        if (fits[i].ok && nf * std::log(fits[i].sse / cur.sse) + std::log(nf) < 0.0) strong.push_back(i);
      std::sort(strong.begin(), strong.end(),
                [&](std::size_t a, std::size_t b) { return fits[a].sse < fits[b].sse; });
      if (strong.size() > 3) strong.resize(3);
      std::optional<Eval> bestA, bestB;
      Fit bestFit;
      std::array<std::string, 2> bestNames;
      std::vector<std::pair<std::size_t, std::size_t>> pairs;
      for (std::size_t x : strong)
        for (std::size_t y = 0; y < fits.size(); ++y)
          if (y != x && fits[y].ok &&
              std::find(pairs.begin(), pairs.end(), std::make_pair(y, x)) == pairs.end())
            pairs.emplace_back(x, y);
      for (const auto& [px, py] : pairs) {
        {
          const std::string &na = names[px], &nb = names[py];
          if (isLag(na) && isLag(nb)) continue;
          Eval ea = evaluateCandidate(pb, log, o, na, state, u);
          const Eval eb = evaluateCandidate(pb, log, o, nb, ea.next, u);
          if (!eb.fit.ok) continue;
          Fit pf = eb.fit;
          ModelState ps = eb.next;
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
          const double explained =
              std::sqrt(std::max(0.0, cur.heldout * cur.heldout - pf.heldout * pf.heldout));
          const bool pass = pf.heldout <= (1.0 - o.minHeldoutGain) * cur.heldout &&
                            explained >= o.minExplainedNoise * noise &&
                            nf * std::log(pf.sse / cur.sse) + 2.0 * std::log(nf) < 0.0;
          if (pass && (!bestA || rankOf(pf, cur) < rankOf(bestFit, cur))) {
            ea.next = ps;
            bestNames = {na, nb};
            bestA = ea;
            bestB = fb;
            bestFit = pf;
          }
        }
      }
      if (bestA) {
        const Eval* parts[2] = {&*bestA, &*bestB};
        for (int w = 0; w < 2; ++w) {
          Candidate c;
          c.name = bestNames[w];
          c.round = round;
          c.accepted = true;
          c.parameters = parts[w]->parameters;
          c.rmseBefore = cur.rmse;
          c.rmseAfter = bestFit.rmse;
          c.heldoutBefore = cur.heldout;
          c.heldoutAfter = bestFit.heldout;
          c.score = cur.heldout > 0.0 ? (bestFit.heldout - cur.heldout) / cur.heldout : 0.0;
          c.setEvidence(
              {Phrase("accepted together with %1: held-out rmse %2 -> %3%4 (%5), fit rmse %6 -> %7%4, %8",
                      {A::name(bestNames[1 - w]), num(cur.heldout), num(bestFit.heldout), A::unit(u),
                       pct(cur.heldout, bestFit.heldout), num(cur.rmse), num(bestFit.rmse),
                       A::text(parts[w]->paramText)})});
          ResidualPlot plot;
          plot.setLabels(timeLabel(), residualLabel(d.units));
          plot.x = log.timeMin;
          plot.before = cur.residual;
          plot.after = bestFit.residual;
          c.plot = std::move(plot);
          tried.push_back(std::move(c));
        }
        state = bestA->next;
        cur = bestFit;
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
      ResidualPlot plot;
      plot.setLabels(timeLabel(), residualLabel(d.units));
      plot.x = log.timeMin;
      plot.before = cur.residual;
      plot.after = fits[*best].residual;
      c.plot = std::move(plot);
      state = states[*best];
      cur = fits[*best];
    }
    for (auto& c : tried) d.effects.push_back(std::move(c));
    if (!best && !pairAccepted) break;
  }
  progress.addNote(d);
  d.final = summaryOf(cur);
  return d;
}

}  // namespace metrofit::diagnose
