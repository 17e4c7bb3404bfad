#include "core/sim/effects_thermal.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/thermal/lag_regression.h"

namespace metrofit {
namespace {

bool isSimColumn(const std::string& name) {
  for (const char* c : {"spindle_rpm", "T1", "T2", "T3", "T4", "T_amb"})
    if (name == c) return true;
  return false;
}

}  // namespace

bool ThermalEffectsOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  std::string bad;
  if (!sensors.isValid(&bad)) return no(bad);
  if (target.empty()) return no("target must be named");
  if (isSimColumn(target)) return no("target '" + target + "' is a sensor column of the simulated log");
  if (declaredInputs.size() != coefficients.size()) return no("one coefficient per declared input is needed");
  for (const auto& in : declaredInputs)
    if (!isSimColumn(in)) return no("declared input '" + in + "' is not a column of the simulated log");
  for (double b : coefficients)
    if (!std::isfinite(b)) return no("coefficients must be finite");
  if (!std::isfinite(intercept)) return no("intercept must be finite");
  if (!(lagTauMin >= 0.0) || !std::isfinite(lagTauMin)) return no("lag tau must be finite and not negative");
  if (!lagColumn.empty() &&
      std::find(declaredInputs.begin(), declaredInputs.end(), lagColumn) == declaredInputs.end())
    return no("lag column '" + lagColumn + "' is not a declared input");
  for (const auto& e : extraInputs) {
    if (!isSimColumn(e.column))
      return no("extra input '" + e.column + "' is not a column of the simulated log");
    if (std::find(declaredInputs.begin(), declaredInputs.end(), e.column) != declaredInputs.end())
      return no("extra input '" + e.column + "' is a declared input");
    if (!std::isfinite(e.coefficient)) return no("extra input coefficients must be finite");
  }
  if (!std::isfinite(driftPerMin)) return no("drift must be finite");
  if (!(noiseUm >= 0.0) || !std::isfinite(noiseUm)) return no("noise must be finite and not negative");
  return true;
}

ThermalEffectSignal thermalEffectSignal(const ThermalLog& log, const ThermalEffectsOptions& o) {
  const std::size_t n = log.rows();
  ThermalEffectSignal sig;
  sig.declared.assign(n, o.intercept);
  sig.withEffects.assign(n, o.intercept);
  for (std::size_t j = 0; j < o.declaredInputs.size(); ++j) {
    const std::vector<double>& x = log.channel(o.declaredInputs[j]).values;
    const bool lagged = o.lagTauMin > 0.0 && (o.lagColumn.empty() || o.lagColumn == o.declaredInputs[j]);
    const std::vector<double> xe = lagged ? thermal::firstOrderLagMin(x, log.timeMin, o.lagTauMin) : x;
    for (std::size_t k = 0; k < n; ++k) {
      sig.declared[k] += o.coefficients[j] * (x[k] - x[0]);
      sig.withEffects[k] += o.coefficients[j] * (xe[k] - x[0]);
    }
  }
  for (const auto& e : o.extraInputs) {
    const std::vector<double>& z = log.channel(e.column).values;
    for (std::size_t k = 0; k < n; ++k) sig.withEffects[k] += e.coefficient * (z[k] - z[0]);
  }
  for (std::size_t k = 0; k < n; ++k) sig.withEffects[k] += o.driftPerMin * (log.timeMin[k] - log.timeMin[0]);
  return sig;
}

ThermalLog simulateThermalEffects(const ThermalEffectsOptions& o) {
  requireValid(o, "thermal effects simulation");
  ThermalSimOptions so = o.sensors;
  so.seed = o.seed;
  ThermalLog log = simulateThermalTest(so);
  log.source = "simulated thermal test with undeclared effects";
  const ThermalEffectSignal sig = thermalEffectSignal(log, o);
  // A separate stream for the target noise, so that the sensors do not change with the effects.
  Rng rng(o.seed ^ 0x5eed7a46e7ULL);
  std::vector<double> y(log.rows());
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = sig.withEffects[k] + rng.normal(0.0, o.noiseUm);
  const int idx = log.indexOf(o.target);
  if (idx >= 0) {
    log.channels[static_cast<std::size_t>(idx)].values = std::move(y);
  } else {
    std::string unit;
    if (o.target.size() > 3 && o.target.compare(o.target.size() - 3, 3, "_um") == 0) unit = "um";
    log.channels.push_back({o.target, unit, std::move(y)});
  }
  return log;
}

}  // namespace metrofit
