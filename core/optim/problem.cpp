#include "core/optim/problem.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace metrofit::optim {

void Problem::snap(std::span<double> x) const {
  const double step = gridStep();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lo = lower(i), hi = upper(i);
    x[i] = snapCoordinate(x[i], lo, hi, step, step > 0.0 ? 1.0 / step : 0.0, gridPoints(lo, hi, step));
  }
}

bool Problem::isFeasible(std::span<const double> x) const {
  if (x.size() != dimension()) return false;
  const double step = gridStep();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] >= lower(i) && x[i] <= upper(i))) return false;
    if (step > 0.0) {
      const double k = (x[i] - lower(i)) / step;
      if (std::abs(k - std::round(k)) > 1e-9 * std::max(1.0, std::abs(k))) return false;
    }
  }
  return true;
}

double sphere(std::span<const double> x) {
  double s = 0.0;
  for (double v : x) s += v * v;
  return s;
}

double rosenbrock(std::span<const double> x) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i + 1] - x[i] * x[i], b = 1.0 - x[i];
    s += 100.0 * a * a + b * b;
  }
  return s;
}

double rastrigin(std::span<const double> x) {
  double s = 10.0 * static_cast<double>(x.size());
  for (double v : x) s += v * v - 10.0 * std::cos(2.0 * std::numbers::pi * v);
  return s;
}

}  // namespace metrofit::optim
