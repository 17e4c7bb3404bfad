#include "core/optim/gasimplex.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/optim/neldermead.h"

namespace metrofit::optim {

bool GaSimplex::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  std::string common_why;
  if (!common.isValid(&common_why)) return no(common_why);
  if (populationSize < 2)
    return no("the GA population size must be at least 2, got " + std::to_string(populationSize));
  if (!(crossoverProbability >= 0.0 && crossoverProbability <= 1.0))
    return no("the crossover probability must be in [0, 1], got " + num::toString(crossoverProbability));
  if (!(mutationProbability >= 0.0 && mutationProbability <= 1.0))
    return no("the mutation probability must be in [0, 1] (0: 1/dimension), got " +
              num::toString(mutationProbability));
  if (!(gaFraction > 0.0 && gaFraction <= 1.0))
    return no("the GA share of the budget must be in (0, 1], got " + num::toString(gaFraction));
  if (!(simplexStep > 0.0 && simplexStep <= 1.0))
    return no("the simplex initial step must be in (0, 1] (fraction of each range), got " +
              num::toString(simplexStep));
  if (!(simplexTolerance >= 0.0) || !std::isfinite(simplexTolerance))
    return no("the simplex tolerance must be finite and >= 0, got " + num::toString(simplexTolerance));
  return true;
}

long GaSimplex::gaBudget() const {
  const double b = std::floor(options_.gaFraction * static_cast<double>(options_.common.maxEvaluations));
  return std::max(1L, static_cast<long>(b));
}

namespace {

/// Binary (k-ary) tournament: the best of k uniformly drawn individuals.
std::size_t tournament(Rng& rng, const std::vector<double>& fit, int k) {
  std::size_t best = rng.below(fit.size());
  for (int t = 1; t < k; ++t) {
    const std::size_t c = rng.below(fit.size());
    if (fit[c] < fit[best]) best = c;
  }
  return best;
}

}  // namespace

Result GaSimplex::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, "ga-simplex options");
  Tracker tracker(name(), problem, options_.common, observer);
  Rng& rng = tracker.rng();
  const std::size_t n = tracker.dimension();
  const std::size_t np = static_cast<std::size_t>(options_.populationSize);
  const long gaEvals = gaBudget();
  const double pm =
      options_.mutationProbability > 0.0 ? options_.mutationProbability : 1.0 / static_cast<double>(n);
  const double pc = options_.crossoverProbability;
  std::vector<double> lo(n), range(n);
  for (std::size_t j = 0; j < n; ++j) {
    lo[j] = problem.lower(j);
    range[j] = problem.upper(j) - lo[j];
  }
  const auto gaLeft = [&] { return !tracker.exhausted() && tracker.evaluations() < gaEvals; };

  // Generation 0.
  std::vector<double> pop, fit;
  pop.reserve(np * n);
  for (std::size_t i = 0; i < np && gaLeft(); ++i) {
    std::vector<double> x = tracker.randomPoint();
    fit.push_back(tracker.evaluate(x));
    pop.insert(pop.end(), x.begin(), x.end());
  }
  bool stopped = tracker.endIteration();

  std::vector<double> next, nextFit, c1(n), c2(n);
  const auto mutate = [&](std::vector<double>& x) {
    for (std::size_t j = 0; j < n; ++j) {
      if (rng.uniform() >= pm) continue;
      const double u = rng.uniform();
      const double e = 1.0 / (kMutationEta + 1.0);
      const double delta = u < 0.5 ? std::pow(2.0 * u, e) - 1.0 : 1.0 - std::pow(2.0 * (1.0 - u), e);
      x[j] += delta * range[j];
    }
  };
  while (!stopped && gaLeft() && fit.size() >= 2) {
    const std::size_t size = fit.size();
    next.clear();
    nextFit.clear();
    // Elitism: the best individual survives unchanged (no new evaluation).
    const std::size_t elite =
        static_cast<std::size_t>(std::min_element(fit.begin(), fit.end()) - fit.begin());
    next.insert(next.end(), pop.begin() + static_cast<std::ptrdiff_t>(elite * n),
                pop.begin() + static_cast<std::ptrdiff_t>((elite + 1) * n));
    nextFit.push_back(fit[elite]);
    while (nextFit.size() < size && gaLeft()) {
      const double* p1 = pop.data() + tournament(rng, fit, kTournamentSize) * n;
      const double* p2 = pop.data() + tournament(rng, fit, kTournamentSize) * n;
      const bool cross = rng.uniform() < pc;
      for (std::size_t j = 0; j < n; ++j) {
        if (cross && rng.uniform() < 0.5) {
          const double u = rng.uniform();
          const double e = 1.0 / (kSbxEta + 1.0);
          const double beta = u <= 0.5 ? std::pow(2.0 * u, e) : std::pow(1.0 / (2.0 * (1.0 - u)), e);
          c1[j] = 0.5 * ((1.0 + beta) * p1[j] + (1.0 - beta) * p2[j]);
          c2[j] = 0.5 * ((1.0 - beta) * p1[j] + (1.0 + beta) * p2[j]);
        } else {
          c1[j] = p1[j];
          c2[j] = p2[j];
        }
      }
      for (std::vector<double>* child : {&c1, &c2}) {
        if (nextFit.size() >= size || !gaLeft()) break;
        mutate(*child);
        nextFit.push_back(tracker.evaluate(*child));  // clamps and snaps the child in place
        next.insert(next.end(), child->begin(), child->end());
      }
    }
    pop.swap(next);
    fit.swap(nextFit);
    stopped = tracker.endIteration();
  }

  bool converged = false;
  if (!stopped && !tracker.exhausted() && !tracker.bestX().empty()) {
    converged = NelderMead::refine(tracker, tracker.bestX(), tracker.bestObjective(), options_.simplexStep,
                                   options_.simplexTolerance);
  }
  Result result = tracker.finish();
  if (converged && result.run.termination == Termination::BudgetExhausted) {
    result.run.termination = Termination::Converged;
    result.run.message = "GA then simplex converged (tolerance " + num::toString(options_.simplexTolerance) +
                         ") after " + std::to_string(result.run.evaluations) + " evaluations";
  }
  return result;
}

}  // namespace metrofit::optim
