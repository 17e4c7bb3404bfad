#include "core/optim/ga.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace metrofit::optim {

bool Ga::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (!common.isValid(why)) return false;
  if (populationSize < 4) {
    return no("populationSize must be at least 4 (got " + std::to_string(populationSize) + ")");
  }
  if (!(mutationProbability >= 0.0 && mutationProbability <= 1.0)) {
    return no("mutationProbability must be in [0, 1] (got " + num::toString(mutationProbability) + ")");
  }
  if (!(intermediateExtension >= 0.0 && intermediateExtension <= 1.0)) {
    return no("intermediateExtension must be in [0, 1] (got " + num::toString(intermediateExtension) + ")");
  }
  if (!(mutationShape > 0.0 && std::isfinite(mutationShape))) {
    return no("mutationShape must be finite and > 0 (got " + num::toString(mutationShape) + ")");
  }
  return true;
}

Ga::Ga() = default;
Ga::Ga(Options options) : options_(std::move(options)) {}

namespace {

struct Individual {
  std::vector<double> x;
  double f = 0.0;
};

}  // namespace

Result Ga::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, name() + " options");
  Tracker tracker(name(), problem, options_.common, observer);
  Rng& rng = tracker.rng();
  const Options& o = options_;
  const std::size_t n = tracker.dimension();
  const std::size_t size = static_cast<std::size_t>(o.populationSize);
  const double budget = static_cast<double>(o.common.maxEvaluations);

  // Iteration 0: the random initial population.
  std::vector<Individual> population;
  population.reserve(size);
  while (population.size() < size && !tracker.exhausted()) {
    Individual ind{tracker.randomPoint(), 0.0};
    ind.f = tracker.evaluate(ind.x);
    population.push_back(std::move(ind));
  }
  bool stop = tracker.endIteration();

  std::vector<std::size_t> order(size);
  std::vector<Individual> next;
  next.reserve(size);
  while (!stop) {
    // 1. Pairwise tournaments on a random pairing (Fisher-Yates shuffle); winners qualify.
    std::iota(order.begin(), order.end(), std::size_t{0});
    for (std::size_t i = size - 1; i > 0; --i) std::swap(order[i], order[rng.below(i + 1)]);
    next.clear();
    for (std::size_t k = 0; k + 1 < size; k += 2) {
      const Individual& a = population[order[k]];
      const Individual& b = population[order[k + 1]];
      next.push_back(a.f <= b.f ? a : b);
    }
    if (size % 2 == 1) next.push_back(population[order[size - 1]]);
    const std::size_t winners = next.size();

    // 2. Children fill the losers' places.
    while (next.size() < size && !tracker.exhausted()) {
      const std::size_t i1 = rng.below(winners);
      std::size_t i2 = rng.below(winners - 1);
      if (i2 >= i1) ++i2;
      const std::vector<double>& p1 = next[i1].x;
      const std::vector<double>& p2 = next[i2].x;
      Individual child;
      child.x.resize(n);
      const double d = o.intermediateExtension;
      for (std::size_t i = 0; i < n; ++i) {
        if (o.crossover == Crossover::Intermediate) {
          child.x[i] = p1[i] + rng.uniform(-d, 1.0 + d) * (p2[i] - p1[i]);
        } else {
          child.x[i] = rng.uniform() < 0.5 ? p1[i] : p2[i];
        }
      }
      // Non-uniform mutation (Michalewicz): step sizes shrink as the budget is used.
      const double t = static_cast<double>(tracker.evaluations()) / budget;
      const double exponent = std::pow(1.0 - t, o.mutationShape);
      for (std::size_t i = 0; i < n; ++i) {
        if (rng.uniform() >= o.mutationProbability) continue;
        const double xi = std::clamp(child.x[i], problem.lower(i), problem.upper(i));
        const bool up = rng.uniform() < 0.5;
        const double room = up ? problem.upper(i) - xi : xi - problem.lower(i);
        const double delta = room * (1.0 - std::pow(rng.uniform(), exponent));
        child.x[i] = up ? xi + delta : xi - delta;
      }
      child.f = tracker.evaluate(child.x);  // clamps / snaps in place
      next.push_back(std::move(child));
    }
    // A generation cut short by the budget keeps its winners and the children made so far.
    population.swap(next);
    stop = tracker.endIteration();
  }
  return tracker.finish();
}

}  // namespace metrofit::optim
