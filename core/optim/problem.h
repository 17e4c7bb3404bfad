#pragma once
// The optimisation problem interface shared by every metaheuristic (pagmo-like: the problem knows
// nothing of algorithms; STYLE.md §2).
//
// Convention: MINIMISATION of `evaluate`. A problem that maximises (the setup problem's
// f = 10 f1 - f2) returns -f and reports f1, f2, f as named components.
// Decision space: a box [lower_i, upper_i]; optionally a grid (step > 0) anchored at lower_i:
// feasible values are lower_i + k * step, k integer, within the bounds (the setup problem's
// 0.001 mm grid). `snap` maps any point onto the feasible set; algorithms evaluate only snapped
// points, so "bounds are respected exactly" holds for every evaluated x.
// `evaluate` is const and must be thread-safe: many algorithm instances may share one problem.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace metrofit::optim {

/// One coordinate onto the box and grid: clamp (a non-finite value goes to lo), then on a grid
/// round to the nearest of lo + k step, 0 <= k <= kMax (kMax = gridPoints below). Shared by
/// Problem::snap and the Tracker's cached fast path so both give bit-identical points.
/// std::round for k >= 0, inline (std::round is a libm call on baseline x86-64, ~10 % of a setup
/// evaluation): truncation by conversion, then + 1 when the fraction is at least 0.5. Exact: for
/// k < 2^52 the fraction k - trunc(k) is computed without rounding; larger k are integers already.
inline double roundNonNegative(double k) {
  if (!(k < 0x1p52)) return k;
  const double t = static_cast<double>(static_cast<std::int64_t>(k));
  return t + static_cast<double>(k - t >= 0.5);
}

/// invStep = 1 / step (a multiplication instead of a division per coordinate; the same formula in
/// both callers, so the points stay identical).
inline double snapCoordinate(double v, double lo, double hi, double step, double invStep, double kMax) {
  v = std::isfinite(v) ? v : lo;
  v = std::clamp(v, lo, hi);
  if (step > 0.0) {
    const double k = std::min(roundNonNegative((v - lo) * invStep), kMax);
    v = lo + k * step;
  }
  return v;
}

/// Largest k with lo + k step <= hi (+1e-9 step): the grid index range of a coordinate.
inline double gridPoints(double lo, double hi, double step) {
  return step > 0.0 ? std::floor((hi - lo) / step + 1e-9) : 0.0;
}

class Problem {
 public:
  virtual ~Problem() = default;

  virtual std::string name() const = 0;
  virtual std::size_t dimension() const = 0;
  virtual double lower(std::size_t i) const = 0;
  virtual double upper(std::size_t i) const = 0;
  /// Grid step of the decision space (0: continuous).
  virtual double gridStep() const { return 0.0; }
  /// Names of the components `evaluate` fills in (e.g. {"f1", "f2", "f"}); empty by default.
  virtual std::vector<std::string> componentNames() const { return {}; }
  /// Objective to MINIMISE at x (x.size() == dimension()); writes componentNames().size() values
  /// into `components` (which has exactly that size).
  virtual double evaluate(std::span<const double> x, std::span<double> components) const = 0;

  /// Clamps x into the bounds and, on a grid, rounds each coordinate to the nearest grid point
  /// inside the bounds.
  void snap(std::span<double> x) const;
  /// True when x is inside the bounds (and on the grid, within 1e-9 of a step).
  bool isFeasible(std::span<const double> x) const;
};

/// A problem given by box bounds and a callable; for tests, benchmarks and simple uses.
class FunctionProblem : public Problem {
 public:
  using Fn = double (*)(std::span<const double>);
  FunctionProblem(std::string name, std::vector<double> lower, std::vector<double> upper, Fn fn,
                  double step = 0.0)
      : name_(std::move(name)), lower_(std::move(lower)), upper_(std::move(upper)), fn_(fn), step_(step) {}

  std::string name() const override { return name_; }
  std::size_t dimension() const override { return lower_.size(); }
  double lower(std::size_t i) const override { return lower_[i]; }
  double upper(std::size_t i) const override { return upper_[i]; }
  double gridStep() const override { return step_; }
  double evaluate(std::span<const double> x, std::span<double>) const override { return fn_(x); }

 private:
  std::string name_;
  std::vector<double> lower_, upper_;
  Fn fn_;
  double step_;
};

/// Classic test functions (minimum 0): sphere at 0, Rosenbrock at (1,...,1), Rastrigin at 0.
double sphere(std::span<const double> x);
double rosenbrock(std::span<const double> x);
double rastrigin(std::span<const double> x);

}  // namespace metrofit::optim
