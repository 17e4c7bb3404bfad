#include "core/thermal/model_verdict.h"

#include <algorithm>
#include <cmath>

namespace metrofit::thermal {

bool diverges(const ThermalMetrics& m, double scale) {
  return !std::isfinite(m.rmse) || m.rmse > kDivergenceFactor * std::max(scale, 1e-9);
}

ModelVerdict judgeThermalModel(const ThermalMetrics& heldout, double scale) {
  if (diverges(heldout, scale)) return ModelVerdict::Diverges;
  if (!std::isfinite(heldout.e) || heldout.e < kMinEfficiency) return ModelVerdict::NegativeEfficiency;
  if (!std::isfinite(heldout.r) || heldout.r < kMinCorrelation) return ModelVerdict::LowCorrelation;
  return ModelVerdict::Usable;
}

double targetScale(std::span<const double> target) {
  double s = 0.0;
  for (double v : target) s = std::max(s, std::abs(v));
  return s;
}

}  // namespace metrofit::thermal
