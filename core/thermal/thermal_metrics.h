#pragma once
// The performance indices of Abdulshahed et al. 2016 (grey neural network thermal model), Table 4, for
// measured values y_k and model outputs y^_k, k = 1..n, residuals r_k = y_k - y^_k:
//   R    = sum (y - mean y)(y^ - mean y^) / sqrt(sum (y - mean y)^2 sum (y^ - mean y^)^2)   (Pearson)
//   RMSE = sqrt(sum r^2 / n)                                              [the target's units]
//   E    = 1 - sum r^2 / sum (y - mean y)^2          (Nash-Sutcliffe efficiency coefficient)
//   band = max |r|                     (the "residual" column: the model keeps the error within +-band)
// R is undefined (NaN) when either series is constant and E when y is constant; all are NaN for
// n = 0. JSON writers turn NaN into null.
#include <cstddef>
#include <span>

namespace metrofit::thermal {

struct ThermalMetrics {
  std::size_t n = 0;
  double r = 0.0;
  double rmse = 0.0;
  double e = 0.0;
  double residualBand = 0.0;
};

/// Table 4's indices of `predicted` against `measured` (same size).
ThermalMetrics thermalMetrics(std::span<const double> measured, std::span<const double> predicted);

}  // namespace metrofit::thermal
