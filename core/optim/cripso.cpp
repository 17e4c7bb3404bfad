#include "core/optim/cripso.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace metrofit::optim {

bool Cripso::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (!common.isValid(why)) return false;
  if (populationSize < 2) {
    return no("populationSize must be at least 2 (got " + std::to_string(populationSize) + ")");
  }
  if (!(inertia >= 0.0 && inertia <= 1.0)) {
    return no("inertia w must be in [0, 1] (got " + num::toString(inertia) + ")");
  }
  return true;
}

Cripso::Cripso() = default;
Cripso::Cripso(Options options) : options_(std::move(options)) {}

namespace {

struct Polyp {
  std::vector<double> x;      // position (feasible, evaluated)
  double f = 0.0;             // objective at x
  std::vector<double> plast;  // last planula (rule I)
  std::vector<double> pbest;  // best planula (descendant) so far; itself before the first (rule II)
  double fbest = 0.0;         // objective at pbest
  bool hasPlanula = false;    // pbest is a descendant (own or inherited), not the polyp itself
};

/// Folds v into [lo, hi] by mirroring at the bounds (period 2 (hi - lo)); non-finite v -> lo.
double reflectIntoBox(double v, double lo, double hi) {
  if (v >= lo && v <= hi) return v;
  const double range = hi - lo;
  if (!std::isfinite(v) || !(range > 0.0)) return lo;
  double t = std::fmod(v - lo, 2.0 * range);
  if (t < 0.0) t += 2.0 * range;
  return t <= range ? lo + t : hi - (t - range);
}

}  // namespace

Result Cripso::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, name() + " options");
  Tracker tracker(name(), problem, options_.common, observer);
  Rng& rng = tracker.rng();
  const std::size_t n = tracker.dimension();
  const std::size_t size = static_cast<std::size_t>(options_.populationSize);
  const double budget = static_cast<double>(options_.common.maxEvaluations);
  const double w = options_.inertia;

  // Iteration 0: the initial reef.
  std::vector<Polyp> reef;
  reef.reserve(size);
  while (reef.size() < size && !tracker.exhausted()) {
    Polyp p;
    p.x = tracker.randomPoint();
    p.plast = tracker.randomPoint();
    p.f = tracker.evaluate(p.x);
    p.pbest = p.x;
    p.fbest = p.f;
    reef.push_back(std::move(p));
  }
  std::size_t best = 0;
  for (std::size_t i = 1; i < reef.size(); ++i) {
    if (reef[i].f < reef[best].f) best = i;
  }
  bool stop = tracker.endIteration();

  std::vector<double> planula(n), lo(n), hi(n);
  for (std::size_t i = 0; i < n; ++i) {
    lo[i] = problem.lower(i);
    hi[i] = problem.upper(i);
  }
  // Eq. 11's c = cos(pi/2 Li/L) advances by a fixed angle per contest (one evaluation each): taken
  // exactly at the start of every iteration and rotated in between (cos was 12 % of a contest).
  const double delta = std::numbers::pi / 2.0 / budget;
  const double cosDelta = std::cos(delta), sinDelta = std::sin(delta);
  while (!stop) {
    const double angle = delta * static_cast<double>(tracker.evaluations());
    double c = std::cos(angle), sn = std::sin(angle);
    for (std::size_t contest = 0; contest < size && !tracker.exhausted(); ++contest) {
      // Contest between two distinct random polyps.
      const std::size_t a = rng.below(size);
      std::size_t b = rng.below(size - 1);
      if (b >= a) ++b;
      const std::size_t winner = reef[a].f <= reef[b].f ? a : b;
      const std::size_t loser = winner == a ? b : a;
      if (loser == best) best = winner;  // a tie with the best: the winner is as good

      Polyp& parent = reef[winner];
      const Polyp& gbest = reef[best];
      for (std::size_t i = 0; i < n; ++i) {
        const double r1 = rng.uniform(), r2 = rng.uniform();
        const double xi = parent.x[i];
        planula[i] = xi + w * (parent.plast[i] - xi) + c * r1 * (parent.pbest[i] - xi) +
                     c * r2 * (gbest.x[i] - xi);  // Eq. 1
      }
      // The planula settles inside the box (reflected at the bounds), on the grid (snapped).
      for (std::size_t i = 0; i < n; ++i) planula[i] = reflectIntoBox(planula[i], lo[i], hi[i]);
      const double f = tracker.evaluate(planula);

      // The winner remembers its last planula and its best planula (rules I, II).
      std::copy(planula.begin(), planula.end(), parent.plast.begin());
      if (!parent.hasPlanula || f < parent.fbest) {
        std::copy(planula.begin(), planula.end(), parent.pbest.begin());
        parent.fbest = f;
        parent.hasPlanula = true;
      }
      // The planula settles in the loser's place (rules I and II).
      Polyp& child = reef[loser];
      for (std::size_t i = 0; i < n; ++i) child.plast[i] = 2.0 * planula[i] - parent.x[i];
      std::copy(planula.begin(), planula.end(), child.x.begin());
      child.f = f;
      std::copy(parent.pbest.begin(), parent.pbest.end(), child.pbest.begin());
      child.fbest = parent.fbest;
      child.hasPlanula = true;
      if (f < reef[best].f) best = loser;
      // Eq. 11 for the next contest: Li + 1.
      const double cNext = c * cosDelta - sn * sinDelta;
      sn = sn * cosDelta + c * sinDelta;
      c = cNext;
    }
    stop = tracker.endIteration();
  }
  return tracker.finish();
}

}  // namespace metrofit::optim
