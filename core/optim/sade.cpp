#include "core/optim/sade.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

namespace metrofit::optim {

bool Sade::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  std::string common_why;
  if (!common.isValid(&common_why)) return no(common_why);
  if (populationSize < 4)
    return no(
        "the population size NP must be at least 4 (DE/rand/1 needs "
        "three partners besides the target), "
        "got " +
        std::to_string(populationSize));
  if (!(f0 > 0.0 && f0 <= 1.0)) return no("F0 must be in (0, 1], got " + num::toString(f0));
  if (maxGenerations < 0)
    return no(
        "the maximum generation Gm must be >= 1 (or 0: derived from the "
        "budget), got " +
        std::to_string(maxGenerations));
  if (!(crMin >= 0.0 && crMin <= 1.0)) return no("CRmin must be in [0, 1], got " + num::toString(crMin));
  if (!(crMax >= 0.0 && crMax <= 1.0)) return no("CRmax must be in [0, 1], got " + num::toString(crMax));
  if (crMin > crMax)
    return no("CRmin must not exceed CRmax, got CRmin " + num::toString(crMin) + " > CRmax " +
              num::toString(crMax));
  return true;
}

long Sade::Options::effectiveMaxGenerations() const {
  if (maxGenerations > 0) return maxGenerations;
  const long np = std::max(1, populationSize);
  const long rest = common.maxEvaluations - np;
  return std::max(1L, (rest + np - 1) / np);
}

namespace {

/// Uniform index in [0, n) by a multiplication instead of a division (bias below n / 2^53).
std::size_t pick(Rng& rng, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)));
}

/// Fills the np x n population with uniform random feasible points and evaluates them (as far as
/// the budget goes; rows beyond it keep fitness +inf).
void randomPopulation(Tracker& tracker, std::size_t np, std::vector<double>& pop, std::vector<double>& fit) {
  const std::size_t n = tracker.dimension();
  std::fill(fit.begin(), fit.end(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < np && !tracker.exhausted(); ++i) {
    const std::vector<double> x = tracker.randomPoint();
    std::span<double> row(pop.data() + i * n, n);
    std::copy(x.begin(), x.end(), row.begin());
    fit[i] = tracker.evaluate(row);
  }
}

/// The tracker's result; a run that stopped after generation Gm says so instead of "budget".
Result finishRun(Tracker& tracker, bool reachedGm, long gm) {
  Result result = tracker.finish();
  if (reachedGm && result.run.termination == Termination::BudgetExhausted) {
    result.run.termination = Termination::MaxIterations;
    result.run.message = "reached the maximum generation Gm = " + std::to_string(gm) + " after " +
                         std::to_string(result.run.evaluations) + " evaluations";
  }
  return result;
}

}  // namespace

double Sade::mutationFactor(double f0, long g, long gm) {
  const double lambda =
      std::exp(1.0 - static_cast<double>(gm) / static_cast<double>(gm + 1 - std::clamp(g, 1L, gm)));
  return f0 * std::exp2(lambda);
}

double Sade::crossoverRate(double crMin, double crMax, long g, long gm) {
  return crMin + static_cast<double>(std::clamp(g, 1L, gm)) * (crMax - crMin) / static_cast<double>(gm);
}

namespace {

/// The decision box's lower and upper bounds.
std::pair<std::vector<double>, std::vector<double>> bounds(const Problem& problem, std::size_t n) {
  std::vector<double> lo(n), hi(n);
  for (std::size_t j = 0; j < n; ++j) {
    lo[j] = problem.lower(j);
    hi[j] = problem.upper(j);
  }
  return {std::move(lo), std::move(hi)};
}

/// Adaptation::SuccessHistory: SHADE (Tanabe & Fukunaga 2013), see the header.
Result optimiseShade(const Sade::Options& o, Tracker& tracker, long gm) {
  Rng& rng = tracker.rng();
  const Problem& problem = tracker.problem();
  const std::size_t n = tracker.dimension();
  const std::size_t np = static_cast<std::size_t>(o.populationSize);
  constexpr std::size_t kMemory = 6;  // H, L-SHADE's value

  const auto [lo, hi] = bounds(problem, n);
  std::vector<double> pop(np * n), next(np * n), trial(n);
  std::vector<double> fit(np), nextFit(np);
  randomPopulation(tracker, np, pop, fit);
  bool stop = tracker.endIteration();

  std::vector<double> memF(kMemory, 0.5), memCr(kMemory, 0.5);
  std::size_t memNext = 0;
  std::vector<double> archive;  // replaced parents, at most NP rows
  archive.reserve(np * n);
  std::vector<std::size_t> order(np);
  std::vector<double> sF, sCr, sW;
  bool reachedGm = false;
  for (long g = 1; !stop; ++g) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fit[a] < fit[b]; });
    std::copy(pop.begin(), pop.end(), next.begin());
    std::copy(fit.begin(), fit.end(), nextFit.begin());
    sF.clear();
    sCr.clear();
    sW.clear();
    const std::size_t archived = archive.size() / n;
    for (std::size_t i = 0; i < np && !tracker.exhausted(); ++i) {
      const std::size_t r = pick(rng, kMemory);
      double cr = std::clamp(rng.normal(memCr[r], 0.1), 0.0, 1.0);
      double f;
      do f = memF[r] + 0.1 * std::tan(std::numbers::pi * (rng.uniform() - 0.5));  // Cauchy(M_F, 0.1)
      while (f <= 0.0);
      f = std::min(f, 1.0);
      if (tracker.progress() < 0.25) cr = std::max(cr, 0.5);  // jSO-style floor, first quarter
      // current-to-pbest/1: pbest among the best p NP, p ~ U[2/NP, 0.2]
      const double p = std::max(2.0 / static_cast<double>(np), 0.2 * rng.uniform());
      const std::size_t top = std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(p * np)));
      const std::size_t pb = order[pick(rng, std::min(top, np))];
      std::size_t r1, r2;
      do r1 = pick(rng, np);
      while (r1 == i);
      do r2 = pick(rng, np + archived);
      while (r2 == i || r2 == r1);
      const double* xi = pop.data() + i * n;
      const double* xp = pop.data() + pb * n;
      const double* x1 = pop.data() + r1 * n;
      const double* x2 = r2 < np ? pop.data() + r2 * n : archive.data() + (r2 - np) * n;
      const std::size_t jrand = pick(rng, n);
      for (std::size_t j = 0; j < n; ++j) {
        const bool take = (rng.uniform() < cr) | (j == jrand);
        double v = xi[j] + f * (xp[j] - xi[j]) + f * (x1[j] - x2[j]);
        if (v < lo[j]) v = 0.5 * (lo[j] + xi[j]);  // midpoint to the violated bound
        if (v > hi[j]) v = 0.5 * (hi[j] + xi[j]);
        trial[j] = take ? v : xi[j];
      }
      const double ft = tracker.evaluate(trial);
      if (ft <= fit[i]) {
        std::copy(trial.begin(), trial.end(), next.begin() + static_cast<std::ptrdiff_t>(i * n));
        nextFit[i] = ft;
        if (ft < fit[i]) {
          if (archive.size() / n < np) {
            archive.insert(archive.end(), xi, xi + n);
          } else {
            std::copy(xi, xi + n, archive.begin() + static_cast<std::ptrdiff_t>(pick(rng, np) * n));
          }
          sF.push_back(f);
          sCr.push_back(cr);
          sW.push_back(fit[i] - ft);
        }
      }
    }
    if (!sF.empty()) {  // weighted Lehmer mean of F, weighted mean of CR (weights: improvements)
      double w = 0.0, f2 = 0.0, f1 = 0.0, c = 0.0;
      for (std::size_t k = 0; k < sF.size(); ++k) {
        w += sW[k];
        f2 += sW[k] * sF[k] * sF[k];
        f1 += sW[k] * sF[k];
        c += sW[k] * sCr[k];
      }
      if (w > 0.0 && f1 > 0.0) {
        memF[memNext] = f2 / f1;
        memCr[memNext] = c / w;
        memNext = (memNext + 1) % kMemory;
      }
    }
    pop.swap(next);
    fit.swap(nextFit);
    stop = tracker.endIteration();
    if (!stop && g >= gm) {
      stop = true;
      reachedGm = true;
    }
    // Restart when the population has collapsed onto one point (fitness range below 1e-8
    // relative to the best; a population converging to an optimum of 0 keeps converging): the rest of the
    // budget goes to a fresh population; the best stays in the tracker.
    if (!stop) {
      const auto [mn, mx] = std::minmax_element(fit.begin(), fit.end());
      if (*mx - *mn <= 1e-8 * std::abs(*mn)) {
        randomPopulation(tracker, np, pop, fit);
        std::fill(memF.begin(), memF.end(), 0.5);
        std::fill(memCr.begin(), memCr.end(), 0.5);
        archive.clear();
      }
    }
  }
  return finishRun(tracker, reachedGm, gm);
}

}  // namespace

Result Sade::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, "sade options");
  Tracker tracker(name(), problem, options_.common, observer);
  if (options_.adaptation == Adaptation::SuccessHistory)
    return optimiseShade(options_, tracker, options_.effectiveMaxGenerations());
  Rng& rng = tracker.rng();
  const std::size_t n = tracker.dimension();
  const std::size_t np = static_cast<std::size_t>(options_.populationSize);
  const long gm = options_.effectiveMaxGenerations();

  const auto [lo, hi] = bounds(problem, n);

  // Generation 0: NP uniform random feasible points.
  std::vector<double> pop(np * n), next(np * n), trial(n);
  std::vector<double> fit(np), nextFit(np);
  randomPopulation(tracker, np, pop, fit);
  bool stop = tracker.endIteration();

  // jDE state (SelfAdaptive only): each individual's F_i and CR_i.
  const bool jde = options_.adaptation == Adaptation::SelfAdaptive;
  std::vector<double> fi, cri;
  if (jde) {
    fi.resize(np);
    cri.resize(np);
    for (std::size_t i = 0; i < np; ++i) {
      fi[i] = 0.1 + 0.9 * rng.uniform();
      cri[i] = rng.uniform();
    }
  }

  bool reachedGm = false;
  for (long g = 1; !stop; ++g) {
    const double fG = mutationFactor(options_.f0, g, gm);                     // Eq. (10)
    const double crG = crossoverRate(options_.crMin, options_.crMax, g, gm);  // Eq. (11)
    std::copy(pop.begin(), pop.end(), next.begin());
    std::copy(fit.begin(), fit.end(), nextFit.begin());
    for (std::size_t i = 0; i < np && !tracker.exhausted(); ++i) {
      std::size_t r1, r2, r3;
      do r1 = pick(rng, np);
      while (r1 == i);
      do r2 = pick(rng, np);
      while (r2 == i || r2 == r1);
      do r3 = pick(rng, np);
      while (r3 == i || r3 == r1 || r3 == r2);
      const double* xi = pop.data() + i * n;
      const double* x1 = pop.data() + r1 * n;
      const double* x2 = pop.data() + r2 * n;
      const double* x3 = pop.data() + r3 * n;
      double f = fG, cr = crG;
      if (jde) {
        f = rng.uniform() < 0.1 ? 0.1 + 0.9 * rng.uniform() : fi[i];
        cr = rng.uniform() < 0.1 ? rng.uniform() : cri[i];
      }
      const std::size_t jrand = pick(rng, n);
      for (std::size_t j = 0; j < n; ++j) {
        // Binomial crossover without an unpredictable branch: one draw per coordinate.
        const bool take = (rng.uniform() < cr) | (j == jrand);
        double v = x1[j] + f * (x2[j] - x3[j]);
        if (take & ((v < lo[j]) | (v > hi[j]))) {
          if (jde)  // re-drawn uniformly in the box
            v = lo[j] + rng.uniform() * (hi[j] - lo[j]);
          else  // bounce-back between the (feasible) base vector and the violated bound
            v = v < lo[j] ? lo[j] + rng.uniform() * (x1[j] - lo[j]) : hi[j] - rng.uniform() * (hi[j] - x1[j]);
        }
        trial[j] = take ? v : xi[j];
      }
      const double ft = tracker.evaluate(trial);
      if (jde && ft <= fit[i]) {  // steady state: the trial replaces its target at once
        std::copy(trial.begin(), trial.end(), pop.begin() + static_cast<std::ptrdiff_t>(i * n));
        fit[i] = ft;
        fi[i] = f;
        cri[i] = cr;
      }
      if (ft <= fit[i]) {
        std::copy(trial.begin(), trial.end(), next.begin() + static_cast<std::ptrdiff_t>(i * n));
        nextFit[i] = ft;
      }
    }
    pop.swap(next);
    fit.swap(nextFit);
    stop = tracker.endIteration();
    if (!stop && g >= gm) {
      stop = true;
      reachedGm = true;
    }
  }

  return finishRun(tracker, reachedGm, gm);
}

}  // namespace metrofit::optim
