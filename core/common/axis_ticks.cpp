#include "core/common/axis_ticks.h"

#include <cmath>

namespace metrofit::ticks {

namespace {
bool usable(double x) {
  return x > 0.0 && std::isfinite(x);
}
}  // namespace

double niceFloor(double x) {
  if (!usable(x)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * decade <= x * (1.0 + 1e-12)) return m * decade;
  return decade;
}

double niceCeil(double x) {
  if (!usable(x)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= x * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

double niceStep(double span, int count) {
  if (!usable(span) || count < 1) return 1.0;
  return niceCeil(span / count);
}

std::vector<double> tickValues(double lo, double hi, int count) {
  std::vector<double> out;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return out;
  const double step = niceStep(hi - lo, count);
  const double eps = 1e-9 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps && out.size() < 1000; k += 1.0)
    out.push_back(k * step == 0.0 ? 0.0 : k * step);
  return out;
}

}  // namespace metrofit::ticks
