#pragma once
// A thermal comparison (thermal_comparison.h) as the project stores it (results.thermal.<log>,
// core/project/stored_results.h, docs/file-formats.md#stored-results): the settings it ran with, its
// figures and the best usable model, the rule the Thermal page and the report share.
#include <nlohmann/json.hpp>

#include "core/study/thermal_comparison.h"

namespace metrofit {

/// The best usable model of a comparison: the fitted model with the lowest held-out RMSE among those
/// thermal::judgeThermalModel calls usable (the rule of the Thermal page and the report); -1: none.
int bestUsableThermalModel(const ThermalComparison& comparison);

/// The settings as stored with a result (core/project/stored_results.h): {"target", "inputs",
/// "train_fraction", "seed", "applied"}.
nlohmann::json thermalSettingsJson(const ThermalModelSettings& settings);

/// The figures of a comparison as the project stores them (results.thermal.<dataset>): {"rows",
/// "fit_rows", "heldout_rows", "best_model" (the model's name as `thermal fit --model` spells it, or
/// null), "models": [{"model", "fit_rmse", "heldout_rmse", "R", "E", "residual_band"} or {"model",
/// "failed": reason}] in kThermalModelOrder}. Models not run (a cancel) are left out.
nlohmann::json thermalResultJson(const ThermalComparison& comparison);

}  // namespace metrofit
