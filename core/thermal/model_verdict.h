#pragma once
// Is a fitted thermal model usable for compensation? The one place where the thresholds live: the
// report, the GUI's thermal page and the tests all judge a model with judgeThermalModel.
//
// A model is judged on its held-out rows (the rows it was not fitted on), with the indices of the
// thermal paper's Table 4 (Abdulshahed et al. 2016):
//   diverging    RMSE not finite, or larger than kDivergenceFactor x the largest |target| value
//                (the prediction runs away, as an unstable GMC(1,N) with b1 <= 0 does);
//   E < kMinEfficiency (0)  the Nash-Sutcliffe efficiency E = 1 - SSE / SST is negative: the model
//                predicts worse than the mean of the measured error, so compensating with it adds error;
//   R < kMinCorrelation (0.5)  the prediction hardly follows the measured error.
// The first failing test is the reason. A usable model still has its residual band (the largest
// |residual|) to be read against the tolerance.
#include <span>

#include "core/thermal/thermal_metrics.h"

namespace metrofit::thermal {

inline constexpr double kMinEfficiency = 0.0;       ///< held-out E below this: not usable
inline constexpr double kMinCorrelation = 0.5;      ///< held-out R below this: not usable
inline constexpr double kDivergenceFactor = 100.0;  ///< held-out RMSE above this x max |target|: diverging

enum class ModelVerdict {
  Usable,
  Diverges,            ///< RMSE not finite or far above the size of the error itself
  NegativeEfficiency,  ///< E < kMinEfficiency
  LowCorrelation,      ///< R < kMinCorrelation
};

/// The prediction runs away: RMSE not finite or above kDivergenceFactor x `targetScale` (the largest
/// |target| value). Tables show "diverges" instead of such figures.
bool diverges(const ThermalMetrics& metrics, double targetScale);
/// Judges a model by its held-out metrics; `targetScale` is the largest |target| value of the log.
ModelVerdict judgeThermalModel(const ThermalMetrics& heldout, double targetScale);
/// Largest |value|.
double targetScale(std::span<const double> target);

}  // namespace metrofit::thermal
