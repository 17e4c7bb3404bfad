#include "core/optim/pso.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace metrofit::optim {

bool Pso::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (!common.isValid(why)) return false;
  if (swarmSize < 2) return no("swarmSize must be at least 2 (got " + std::to_string(swarmSize) + ")");
  if (!(inertiaStart >= 0.0 && inertiaStart <= 1.2)) {
    return no("inertiaStart must be in [0, 1.2] (got " + num::toString(inertiaStart) + ")");
  }
  if (!(inertiaEnd >= 0.0 && inertiaEnd <= 1.2)) {
    return no("inertiaEnd must be in [0, 1.2] (got " + num::toString(inertiaEnd) + ")");
  }
  if (!(c1 >= 0.0 && std::isfinite(c1)))
    return no("c1 must be finite and >= 0 (got " + num::toString(c1) + ")");
  if (!(c2 >= 0.0 && std::isfinite(c2)))
    return no("c2 must be finite and >= 0 (got " + num::toString(c2) + ")");
  if (!(maxVelocity > 0.0 && maxVelocity <= 1.0)) {
    return no("maxVelocity must be in (0, 1] of the range (got " + num::toString(maxVelocity) + ")");
  }
  if (neighbours < 0 || 2L * neighbours + 1 > swarmSize) {
    return no("neighbours must be in [0, (swarmSize - 1) / 2] (got " + std::to_string(neighbours) +
              " with a swarm of " + std::to_string(swarmSize) + ")");
  }
  return true;
}

Pso::Options Pso::Options::stryczek2016() {
  return Options{};
}

Pso::Options Pso::Options::abdulshahed2016() {
  Options o;
  o.swarmSize = 90;
  o.inertiaStart = 0.9;
  o.inertiaEnd = 0.4;
  o.c1 = 1.5;
  o.c2 = 2.0;
  o.acceleration = Acceleration::Constant;
  o.update = Update::Synchronous;
  return o;
}

Pso::Options Pso::Options::ring() {
  Options o;
  o.swarmSize = 60;
  o.inertiaStart = o.inertiaEnd = 0.7298;
  o.c1 = o.c2 = 1.49618;
  o.acceleration = Acceleration::Cosine;
  o.update = Update::Asynchronous;
  o.neighbours = 2;
  return o;
}

Pso::Pso() = default;
Pso::Pso(Options options) : options_(std::move(options)) {}

namespace {

struct Particle {
  std::vector<double> x, v, pbest;
  double f = 0.0, fbest = 0.0;
};

}  // namespace

Result Pso::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, name() + " options");
  Tracker tracker(name(), problem, options_.common, observer);
  Rng& rng = tracker.rng();
  const Options& o = options_;
  const std::size_t n = tracker.dimension();
  const std::size_t size = static_cast<std::size_t>(o.swarmSize);
  const double budget = static_cast<double>(o.common.maxEvaluations);

  std::vector<double> vmax(n);
  for (std::size_t i = 0; i < n; ++i) vmax[i] = o.maxVelocity * (problem.upper(i) - problem.lower(i));

  // Iteration 0: the initial swarm.
  std::vector<Particle> swarm;
  swarm.reserve(size);
  while (swarm.size() < size && !tracker.exhausted()) {
    Particle p;
    p.x = tracker.randomPoint();
    p.v.resize(n);
    for (std::size_t i = 0; i < n; ++i) p.v[i] = rng.uniform(-vmax[i], vmax[i]);
    p.f = tracker.evaluate(p.x);
    p.pbest = p.x;
    p.fbest = p.f;
    swarm.push_back(std::move(p));
  }
  std::size_t best = 0;  // index of the particle whose pbest is gbest
  for (std::size_t k = 1; k < swarm.size(); ++k) {
    if (swarm[k].fbest < swarm[best].fbest) best = k;
  }
  bool stop = tracker.endIteration();

  // Moves particle p with gbest g and the schedule at s; evaluates it and updates its pbest.
  auto move = [&](Particle& p, const std::vector<double>& g, double s) {
    const double w = o.inertiaStart + (o.inertiaEnd - o.inertiaStart) * s;
    const double scale = o.acceleration == Acceleration::Cosine ? std::cos(std::numbers::pi / 2.0 * s) : 1.0;
    const double c1 = o.c1 * scale, c2 = o.c2 * scale;
    for (std::size_t i = 0; i < n; ++i) {
      const double r1 = rng.uniform(), r2 = rng.uniform();
      double v = w * p.v[i] + c1 * r1 * (p.pbest[i] - p.x[i]) + c2 * r2 * (g[i] - p.x[i]);  // Eq. 2.7
      p.v[i] = std::clamp(v, -vmax[i], vmax[i]);
      p.x[i] += p.v[i];                                                          // Eq. 2.8
      if (p.x[i] < problem.lower(i) || p.x[i] > problem.upper(i)) p.v[i] = 0.0;  // absorbing wall
    }
    p.f = tracker.evaluate(p.x);  // clamps / snaps p.x in place
    if (p.f < p.fbest) {
      p.pbest = p.x;
      p.fbest = p.f;
    }
  };

  // The guide of particle k: the swarm's gbest, or the best pbest of its ring neighbourhood.
  const std::size_t reach = static_cast<std::size_t>(o.neighbours);
  auto guide = [&](std::size_t k) {
    if (reach == 0) return best;
    const std::size_t m = swarm.size();
    std::size_t b = k;
    for (std::size_t d = 1; d <= reach; ++d) {
      const std::size_t left = (k + m - d % m) % m, right = (k + d) % m;
      if (swarm[left].fbest < swarm[b].fbest) b = left;
      if (swarm[right].fbest < swarm[b].fbest) b = right;
    }
    return b;
  };

  std::vector<double> gbest;
  while (!stop) {
    if (o.update == Update::Asynchronous) {
      for (std::size_t k = 0; k < size && !tracker.exhausted(); ++k) {
        const double s = static_cast<double>(tracker.evaluations()) / budget;
        gbest = swarm[guide(k)].pbest;
        move(swarm[k], gbest, s);
        if (swarm[k].fbest < swarm[best].fbest) best = k;  // gbest updated after every new solution
      }
    } else {
      const double s = static_cast<double>(tracker.evaluations()) / budget;
      if (reach == 0) {
        gbest = swarm[best].pbest;
        for (std::size_t k = 0; k < size && !tracker.exhausted(); ++k) move(swarm[k], gbest, s);
      } else {
        // Guides from the previous iteration's pbests, fixed before anyone moves.
        std::vector<std::vector<double>> fixed(size);
        for (std::size_t k = 0; k < size; ++k) fixed[k] = swarm[guide(k)].pbest;
        for (std::size_t k = 0; k < size && !tracker.exhausted(); ++k) move(swarm[k], fixed[k], s);
      }
      for (std::size_t k = 0; k < size; ++k) {
        if (swarm[k].fbest < swarm[best].fbest) best = k;  // gbest updated after the sweep
      }
    }
    stop = tracker.endIteration();
  }
  return tracker.finish();
}

}  // namespace metrofit::optim
