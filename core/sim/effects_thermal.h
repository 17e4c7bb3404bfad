#pragma once
// Thermal logs with undeclared effects, for the closed loop (docs/file-formats.md#the-declared-models): the
// test data the diagnosis must trace back to the effect the declared model lacks.
//
// The sensor columns come from the spindle simulation of thermal_sim.h (time_min, spindle_rpm,
// T1..T4, T_amb; its own displacement column is replaced). The target is the declared static model
// of the logged inputs plus any mix of undeclared effects plus white noise:
//   y(t) = c0 + sum_j b_j (x~_j(t) - x_j(0)) + sum_e coefficient_e (z_e(t) - z_e(0)) + drift * t
//          + N(0, noise^2)          (inputs as changes since the first row, so y starts near c0)
// where
//   x~_j = x_j                  without a lag,
//   x~_j = L_tau[x_j]           with `lag` (all declared inputs, column empty) or `lag:<col>` (one),
//   L_tau: the first-order lag  s(0) = x(0), s(k) = s(k-1) + (1 - exp(-dt_k / tau)) (x(k) - s(k-1))
//          (exact for an input held constant over each step; the diagnosis filters the same way),
//   z_e: an extra column of the log (`input:<col>`, e.g. spindle_rpm) the declared inputs omit,
//   drift: per_min, a slow trend of the machine or the sensor (time in minutes from the start).
// Units: target um, coefficients um per unit of their column, tau in min. Deterministic by seed.
#include <cstdint>
#include <string>
#include <vector>

#include "core/sim/thermal_sim.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {

/// An extra (undeclared) input: y += coefficient * column (change since the first row).
struct ThermalExtraInput {
  std::string column;  ///< a column of the simulated log, e.g. "spindle_rpm", "T_amb"
  double coefficient = 0.0;
};

struct ThermalEffectsOptions {
  ThermalSimOptions sensors;  ///< the machine and its sensors (thermal_sim.h); its seed is used too
  std::string target = "disp_z_um";
  /// One sensor per node (spindle housing, bed) and the ambient: the faster sensors T1, T3 and the
  /// spindle speed stay undeclared, so no combination of declared inputs imitates a further lag.
  std::vector<std::string> declaredInputs{"T2", "T4", "T_amb"};
  std::vector<double> coefficients{-3.0, -1.5, 1.0};  ///< b_j, um per K
  double intercept = 0.0;                             ///< c0, um

  // Undeclared effects (all off by default: the declared model is then exact up to the noise).
  double lagTauMin = 0.0;  ///< > 0: first-order lag of the declared inputs with this tau
  std::string lagColumn;   ///< empty: all declared inputs (`lag`); else only this one (`lag:<col>`)
  std::vector<ThermalExtraInput> extraInputs;  ///< `input:<col>`
  double driftPerMin = 0.0;                    ///< `drift`, um per min

  double noiseUm = 0.25;  ///< white noise of the target, 1 sigma
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

/// The target without noise and without any effect (c0 + sum b_j x_j) and with the effects; used
/// by the detection study to size an effect for a given effect-to-noise ratio.
struct ThermalEffectSignal {
  std::vector<double> declared;  ///< c0 + sum_j b_j (x_j - x_j(0))
  std::vector<double> withEffects;
};
ThermalEffectSignal thermalEffectSignal(const ThermalLog& sensors, const ThermalEffectsOptions& options);

/// Runs the sensor simulation and writes the target column (replacing the simulator's own
/// displacement when it has the same name). Throws OptionsError when options are invalid.
ThermalLog simulateThermalEffects(const ThermalEffectsOptions& options);

}  // namespace metrofit
