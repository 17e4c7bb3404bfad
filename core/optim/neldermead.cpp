#include "core/optim/neldermead.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace metrofit::optim {

bool NelderMead::Options::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  std::string common_why;
  if (!common.isValid(&common_why)) return no(common_why);
  for (std::size_t i = 0; i < start.size(); ++i)
    if (!std::isfinite(start[i])) return no("start point coordinate " + std::to_string(i) + " is not finite");
  if (!(initialStep > 0.0 && initialStep <= 1.0))
    return no("the initial step must be in (0, 1] (fraction of each variable's range), got " +
              num::toString(initialStep));
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    return no("the tolerance must be finite and >= 0, got " + num::toString(tolerance));
  return true;
}

namespace {

/// The simplex: n + 1 vertices stored row by row, their values, and the order by value.
struct Simplex {
  std::size_t n = 0;
  std::vector<double> x;           // (n + 1) * n
  std::vector<double> f;           // n + 1
  std::vector<std::size_t> order;  // vertex indices, best first

  double* vertex(std::size_t k) { return x.data() + k * n; }
  void sort() {
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return f[a] < f[b] || (f[a] == f[b] && a < b); });
  }
};

}  // namespace

bool NelderMead::refine(Tracker& tracker, std::vector<double> start, double startValue, double initialStep,
                        double tolerance) {
  const Problem& problem = tracker.problem();
  const std::size_t n = tracker.dimension();
  std::vector<double> lo(n), range(n);
  for (std::size_t j = 0; j < n; ++j) {
    lo[j] = problem.lower(j);
    range[j] = problem.upper(j) - lo[j];
  }

  Simplex s;
  s.n = n;
  s.x.assign((n + 1) * n, 0.0);
  s.f.assign(n + 1, std::numeric_limits<double>::infinity());
  s.order.resize(n + 1);
  std::iota(s.order.begin(), s.order.end(), std::size_t{0});

  // Initial simplex.
  if (tracker.exhausted()) return false;
  problem.snap(start);
  std::copy(start.begin(), start.end(), s.vertex(0));
  s.f[0] = std::isfinite(startValue) ? startValue : tracker.evaluate(std::span<double>(s.vertex(0), n));
  const double step = problem.gridStep();
  for (std::size_t k = 1; k <= n && !tracker.exhausted(); ++k) {
    double* v = s.vertex(k);
    std::copy(start.begin(), start.end(), v);
    const std::size_t j = k - 1;
    const double h = std::max(initialStep * range[j], step);
    v[j] = (start[j] + h <= lo[j] + range[j]) ? start[j] + h : start[j] - h;
    s.f[k] = tracker.evaluate(std::span<double>(v, n));
  }
  if (tracker.endIteration()) return false;

  std::vector<double> c(n), xr(n), xe(n), xc(n);
  const auto evaluate = [&](std::vector<double>& p) { return tracker.evaluate(p); };
  while (true) {
    s.sort();
    const std::size_t best = s.order.front(), worst = s.order.back(), second = s.order[n - 1];

    // Converged? (f spread and relative x spread both within the tolerance)
    double xSpread = 0.0;
    const double* xb = s.vertex(best);
    for (std::size_t k = 0; k <= n; ++k) {
      const double* xk = s.vertex(k);
      for (std::size_t j = 0; j < n; ++j)
        if (range[j] > 0.0) xSpread = std::max(xSpread, std::abs(xk[j] - xb[j]) / range[j]);
    }
    if (s.f[worst] - s.f[best] <= tolerance && xSpread <= tolerance) return true;
    if (tracker.exhausted()) return false;  // the tracker already reported the last iteration

    std::fill(c.begin(), c.end(), 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const double* xk = s.vertex(s.order[k]);
      for (std::size_t j = 0; j < n; ++j) c[j] += xk[j];
    }
    for (double& v : c) v /= static_cast<double>(n);
    double* xw = s.vertex(worst);

    for (std::size_t j = 0; j < n; ++j) xr[j] = c[j] + kReflection * (c[j] - xw[j]);
    const double fr = evaluate(xr);
    bool shrink = false;
    if (fr < s.f[best]) {
      double fe = std::numeric_limits<double>::infinity();
      if (!tracker.exhausted()) {
        for (std::size_t j = 0; j < n; ++j) xe[j] = c[j] + kExpansion * (xr[j] - c[j]);
        fe = evaluate(xe);
      }
      if (fe < fr) {
        std::copy(xe.begin(), xe.end(), xw);
        s.f[worst] = fe;
      } else {
        std::copy(xr.begin(), xr.end(), xw);
        s.f[worst] = fr;
      }
    } else if (fr < s.f[second]) {
      std::copy(xr.begin(), xr.end(), xw);
      s.f[worst] = fr;
    } else if (!tracker.exhausted()) {
      const bool outside = fr < s.f[worst];
      for (std::size_t j = 0; j < n; ++j)
        xc[j] = outside ? c[j] + kContraction * (xr[j] - c[j]) : c[j] - kContraction * (c[j] - xw[j]);
      const double fc = evaluate(xc);
      if (outside ? fc <= fr : fc < s.f[worst]) {
        std::copy(xc.begin(), xc.end(), xw);
        s.f[worst] = fc;
      } else {
        shrink = true;
      }
    }
    if (shrink) {
      for (std::size_t k = 0; k <= n && !tracker.exhausted(); ++k) {
        if (k == best) continue;
        double* xk = s.vertex(k);
        for (std::size_t j = 0; j < n; ++j) xk[j] = xb[j] + kShrink * (xk[j] - xb[j]);
        s.f[k] = tracker.evaluate(std::span<double>(xk, n));
      }
    }
    if (tracker.endIteration()) return false;
  }
}

Result NelderMead::optimise(const Problem& problem, Observer* observer) const {
  requireValid(options_, "nelder-mead options");
  Tracker tracker(name(), problem, options_.common, observer);
  std::vector<double> start = options_.start;
  if (start.empty()) {
    start = tracker.randomPoint();
  } else if (start.size() != problem.dimension()) {
    throw OptionsError(ErrorContext{{}, 0, 0, "nelder-mead options"},
                       "the start point has " + std::to_string(start.size()) + " coordinates, the problem '" +
                           problem.name() + "' has " + std::to_string(problem.dimension()));
  }
  const bool converged = refine(tracker, std::move(start), std::numeric_limits<double>::quiet_NaN(),
                                options_.initialStep, options_.tolerance);
  Result result = tracker.finish();
  if (converged && result.run.termination == Termination::BudgetExhausted) {
    result.run.termination = Termination::Converged;
    result.run.message = "simplex converged (tolerance " + num::toString(options_.tolerance) + ") after " +
                         std::to_string(result.run.evaluations) + " evaluations";
  }
  return result;
}

}  // namespace metrofit::optim
