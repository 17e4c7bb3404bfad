#include "core/thermal/thermal_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace metrofit::thermal {

ThermalMetrics thermalMetrics(std::span<const double> y, std::span<const double> p) {
  if (y.size() != p.size()) throw std::invalid_argument("thermalMetrics: sizes differ");
  ThermalMetrics m;
  m.n = y.size();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (m.n == 0) {
    m.r = m.rmse = m.e = m.residualBand = nan;
    return m;
  }
  const double nd = static_cast<double>(m.n);
  double my = 0.0, mp = 0.0;
  for (std::size_t k = 0; k < m.n; ++k) {
    my += y[k];
    mp += p[k];
  }
  my /= nd;
  mp /= nd;
  double syy = 0.0, spp = 0.0, syp = 0.0, srr = 0.0, band = 0.0;
  for (std::size_t k = 0; k < m.n; ++k) {
    const double dy = y[k] - my, dp = p[k] - mp, r = y[k] - p[k];
    syy += dy * dy;
    spp += dp * dp;
    syp += dy * dp;
    srr += r * r;
    band = std::max(band, std::abs(r));
  }
  m.rmse = std::sqrt(srr / nd);
  m.residualBand = band;
  m.r = syy > 0.0 && spp > 0.0 ? syp / std::sqrt(syy * spp) : nan;
  m.e = syy > 0.0 ? 1.0 - srr / syy : nan;
  return m;
}

}  // namespace metrofit::thermal
