#include "core/optim/coa.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace metrofit::optim {

bool Coa::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (!common.isValid(why)) return false;
  if (initialPopulation < 2) {
    return no("initialPopulation must be at least 2 (got " + std::to_string(initialPopulation) + ")");
  }
  if (maxPopulation < 2)
    return no("maxPopulation must be at least 2 (got " + std::to_string(maxPopulation) + ")");
  if (minEggs < 1) return no("minEggs must be at least 1 (got " + std::to_string(minEggs) + ")");
  if (maxEggs < minEggs) {
    return no("maxEggs must be >= minEggs (got maxEggs " + std::to_string(maxEggs) + ", minEggs " +
              std::to_string(minEggs) + ")");
  }
  if (!(radiusCoefficient > 0.0 && std::isfinite(radiusCoefficient))) {
    return no("radiusCoefficient must be finite and > 0 (got " + num::toString(radiusCoefficient) + ")");
  }
  if (!(killFraction >= 0.0 && killFraction < 1.0)) {
    return no("killFraction must be in [0, 1) (got " + num::toString(killFraction) + ")");
  }
  if (clusters < 1) return no("clusters must be at least 1 (got " + std::to_string(clusters) + ")");
  if (!(motionCoefficient > 0.0 && motionCoefficient <= 2.0)) {
    return no("motionCoefficient must be in (0, 2] (got " + num::toString(motionCoefficient) + ")");
  }
  if (!(deviationAngle >= 0.0 && deviationAngle <= std::numbers::pi / 2.0)) {
    return no("deviationAngle must be in [0, pi/2] radians (got " + num::toString(deviationAngle) + ")");
  }
  return true;
}

Coa::Coa() = default;
Coa::Coa(Options options) : options_(std::move(options)) {}

namespace {

struct Cuckoo {
  std::vector<double> x;
  double f = 0.0;
};

double squaredDistance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return s;
}

/// k-means (Lloyd) with k-means++ seeding on `points`; returns the cluster of every point.
/// Deterministic for a given Rng state; empty clusters keep their centre.
std::vector<std::size_t> kMeans(const std::vector<std::vector<double>>& points, std::size_t k, Rng& rng) {
  const std::size_t m = points.size();
  k = std::min(k, m);
  std::vector<std::size_t> label(m, 0);
  if (k <= 1) return label;
  std::vector<std::vector<double>> centres;
  centres.reserve(k);
  centres.push_back(points[rng.below(m)]);
  std::vector<double> d2(m);
  while (centres.size() < k) {
    double total = 0.0;
    for (std::size_t p = 0; p < m; ++p) {
      d2[p] = std::numeric_limits<double>::infinity();
      for (const auto& c : centres) d2[p] = std::min(d2[p], squaredDistance(points[p], c));
      total += d2[p];
    }
    std::size_t pick = m - 1;
    if (total > 0.0) {
      double u = rng.uniform() * total;
      for (std::size_t p = 0; p < m; ++p) {
        if (u < d2[p]) {
          pick = p;
          break;
        }
        u -= d2[p];
      }
    } else {
      pick = rng.below(m);
    }
    centres.push_back(points[pick]);
  }
  const std::size_t dim = points.front().size();
  for (int round = 0; round < 100; ++round) {
    bool changed = round == 0;
    for (std::size_t p = 0; p < m; ++p) {
      std::size_t bestC = 0;
      double bestD = squaredDistance(points[p], centres[0]);
      for (std::size_t c = 1; c < k; ++c) {
        const double d = squaredDistance(points[p], centres[c]);
        if (d < bestD) {
          bestD = d;
          bestC = c;
        }
      }
      if (label[p] != bestC) changed = true;
      label[p] = bestC;
    }
    if (!changed) break;
    for (std::size_t c = 0; c < k; ++c) {
      std::vector<double> sum(dim, 0.0);
      std::size_t count = 0;
      for (std::size_t p = 0; p < m; ++p) {
        if (label[p] != c) continue;
        for (std::size_t i = 0; i < dim; ++i) sum[i] += points[p][i];
        ++count;
      }
      if (count == 0) continue;
      for (std::size_t i = 0; i < dim; ++i) centres[c][i] = sum[i] / static_cast<double>(count);
    }
  }
  return label;
}

/// A uniform random unit vector of dimension n (normalised Gaussian).
std::vector<double> randomDirection(std::size_t n, Rng& rng) {
  std::vector<double> u(n);
  double norm = 0.0;
  do {
    norm = 0.0;
    for (double& v : u) {
      v = rng.normal();
      norm += v * v;
    }
  } while (norm == 0.0);
  norm = std::sqrt(norm);
  for (double& v : u) v /= norm;
  return u;
}

}  // namespace

Result Coa::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, name() + " options");
  Tracker tracker(name(), problem, options_.common, observer);
  Rng& rng = tracker.rng();
  const Options& o = options_;
  const std::size_t n = tracker.dimension();
  std::vector<double> range(n);
  for (std::size_t i = 0; i < n; ++i) range[i] = problem.upper(i) - problem.lower(i);
  auto byObjective = [](const Cuckoo& a, const Cuckoo& b) { return a.f < b.f; };

  // Iteration 0: the initial habitats.
  std::vector<Cuckoo> population;
  while (population.size() < static_cast<std::size_t>(o.initialPopulation) && !tracker.exhausted()) {
    Cuckoo c{tracker.randomPoint(), 0.0};
    c.f = tracker.evaluate(c.x);
    population.push_back(std::move(c));
  }
  bool stop = tracker.endIteration();

  std::vector<Cuckoo> eggs;
  std::vector<int> eggCount;
  while (!stop) {
    // 1. Egg laying within each cuckoo's egg laying radius.
    eggCount.resize(population.size());
    double totalEggs = 0.0;
    for (int& e : eggCount) {
      e = o.minEggs + static_cast<int>(rng.below(static_cast<std::uint64_t>(o.maxEggs - o.minEggs + 1)));
      totalEggs += e;
    }
    eggs.clear();
    for (std::size_t k = 0; k < population.size() && !tracker.exhausted(); ++k) {
      const double elr = o.radiusCoefficient * eggCount[k] / totalEggs;  // fraction of the range
      for (int j = 0; j < eggCount[k] && !tracker.exhausted(); ++j) {
        const std::vector<double> u = randomDirection(n, rng);
        const double rho = rng.uniform();
        Cuckoo egg{population[k].x, 0.0};
        for (std::size_t i = 0; i < n; ++i) egg.x[i] += rho * elr * range[i] * u[i];
        egg.f = tracker.evaluate(egg.x);
        eggs.push_back(std::move(egg));
      }
    }
    if (tracker.exhausted()) {
      stop = tracker.endIteration();
      continue;
    }

    // 2. The worst killFraction of the eggs are detected and killed.
    std::stable_sort(eggs.begin(), eggs.end(), byObjective);
    const auto killed = static_cast<std::size_t>(o.killFraction * static_cast<double>(eggs.size()));
    eggs.resize(eggs.size() - killed);

    // 3. The survivors grow up; the population is capped, the worst die.
    for (Cuckoo& e : eggs) population.push_back(std::move(e));
    std::stable_sort(population.begin(), population.end(), byObjective);
    if (population.size() > static_cast<std::size_t>(o.maxPopulation)) {
      population.resize(static_cast<std::size_t>(o.maxPopulation));
    }

    // 4. Immigration towards the best group's best habitat.
    std::vector<std::vector<double>> scaled(population.size(), std::vector<double>(n));
    for (std::size_t k = 0; k < population.size(); ++k) {
      for (std::size_t i = 0; i < n; ++i) {
        scaled[k][i] = range[i] > 0.0 ? (population[k].x[i] - problem.lower(i)) / range[i] : 0.0;
      }
    }
    const std::vector<std::size_t> label = kMeans(scaled, static_cast<std::size_t>(o.clusters), rng);
    const std::size_t groups = *std::max_element(label.begin(), label.end()) + 1;
    std::vector<double> sum(groups, 0.0);
    std::vector<std::size_t> members(groups, 0);
    std::vector<std::size_t> bestOf(groups, population.size());
    for (std::size_t k = 0; k < population.size(); ++k) {  // population is sorted: first = best
      sum[label[k]] += population[k].f;
      ++members[label[k]];
      if (bestOf[label[k]] == population.size()) bestOf[label[k]] = k;
    }
    std::size_t goalGroup = groups;
    double goalMean = 0.0;
    for (std::size_t g = 0; g < groups; ++g) {
      if (members[g] == 0) continue;
      const double mean = sum[g] / static_cast<double>(members[g]);
      if (goalGroup == groups || mean < goalMean) {
        goalGroup = g;
        goalMean = mean;
      }
    }
    const std::vector<double> goal = scaled[bestOf[goalGroup]];

    std::vector<double> d(n), step(n);
    for (std::size_t k = 1; k < population.size() && !tracker.exhausted(); ++k) {
      double norm = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        d[i] = goal[i] - scaled[k][i];
        norm += d[i] * d[i];
      }
      if (norm == 0.0) continue;  // already at the goal
      norm = std::sqrt(norm);
      if (o.immigration == Immigration::PerDimension) {
        for (std::size_t i = 0; i < n; ++i) step[i] = rng.uniform(0.0, o.motionCoefficient) * d[i];
      } else {
        const double lambda = rng.uniform(0.0, o.motionCoefficient);
        const double phi = rng.uniform(-o.deviationAngle, o.deviationAngle);
        // e: a random unit vector orthogonal to d (none in one dimension).
        std::vector<double> e = randomDirection(n, rng);
        double along = 0.0;
        for (std::size_t i = 0; i < n; ++i) along += e[i] * d[i] / norm;
        double enorm = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
          e[i] -= along * d[i] / norm;
          enorm += e[i] * e[i];
        }
        enorm = std::sqrt(enorm);
        const bool rotate = n > 1 && enorm > 1e-12;
        for (std::size_t i = 0; i < n; ++i) {
          step[i] = lambda * (std::cos(phi) * d[i] + (rotate ? std::sin(phi) * norm * e[i] / enorm : 0.0));
        }
      }
      for (std::size_t i = 0; i < n; ++i) population[k].x[i] += step[i] * range[i];
      population[k].f = tracker.evaluate(population[k].x);  // clamps / snaps in place
    }
    stop = tracker.endIteration();
  }
  return tracker.finish();
}

}  // namespace metrofit::optim
