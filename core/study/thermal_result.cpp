#include "core/study/thermal_result.h"

#include <cmath>
#include <string>

#include "core/thermal/model_verdict.h"

namespace metrofit {

int bestUsableThermalModel(const ThermalComparison& c) {
  const double scale = thermal::targetScale(c.series.target);
  int best = -1;
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    if (!c.fitted(i)) continue;
    const thermal::ThermalEvaluation& ev = c.models[i];
    if (thermal::judgeThermalModel(ev.heldout, scale) != thermal::ModelVerdict::Usable) continue;
    if (best < 0 || ev.heldout.rmse < c.models[static_cast<std::size_t>(best)].heldout.rmse)
      best = static_cast<int>(i);
  }
  return best;
}

nlohmann::json thermalSettingsJson(const ThermalModelSettings& s) {
  return {{"target", s.target},
          {"inputs", s.inputs},
          {"train_fraction", s.trainFraction},
          {"seed", s.seed},
          {"applied", s.applied.is_null() ? nlohmann::json::array() : s.applied}};
}

nlohmann::json thermalResultJson(const ThermalComparison& c) {
  // A non-finite figure (a diverging model) is written as null: JSON has no inf.
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json models = nlohmann::json::array();
  for (std::size_t i = 0; i < kThermalModelOrder.size(); ++i) {
    const std::string name = thermal::toString(kThermalModelOrder[i]);
    if (!c.failed[i].empty()) {
      models.push_back({{"model", name}, {"failed", c.failed[i]}});
      continue;
    }
    if (!c.fitted(i)) continue;
    const thermal::ThermalEvaluation& ev = c.models[i];
    models.push_back({{"model", name},
                      {"fit_rmse", number(ev.fit.rmse)},
                      {"heldout_rmse", number(ev.heldout.rmse)},
                      {"R", number(ev.heldout.r)},
                      {"E", number(ev.heldout.e)},
                      {"residual_band", number(ev.heldout.residualBand)}});
  }
  const int best = bestUsableThermalModel(c);
  return {{"rows", c.series.rows()},
          {"fit_rows", c.fitRows},
          {"heldout_rows", c.heldoutRows},
          {"best_model",
           best >= 0 ? nlohmann::json(thermal::toString(kThermalModelOrder[static_cast<std::size_t>(best)]))
                     : nlohmann::json()},
          {"models", models}};
}

}  // namespace metrofit
