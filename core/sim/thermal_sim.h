#pragma once
// Simulated thermal test of a machine-tool spindle (the simulator plays machine and sensors).
//
// Lumped two-node model, explicit Euler at the log's time step (minutes):
//   heat input        Q(t) = rpm(t) / 1000                                (arbitrary power units)
//   spindle housing   dTs/dt = (gainS * Q - (Ts - Ta)) / tauS
//   column / frame    dTc/dt = (shareC * (Ts - Tc) + (1 - shareC) * (Ta - Tc)) / tauC
//   ambient           Ta(t) = ambient0 + ambientAmp * sin(2 pi t / 1440)
//   displacement      d(t)  = -(kS * (Ts - Ts0) + kC * (Tc - Tc0))      [um, spindle grows to -Z]
// Sensors see the nodes through first-order lags (time constant per sensor), plus white noise:
//   T1 spindle nose (lag 4 min), T2 spindle housing (lag 12 min), T3 column (lag 6 min),
//   T4 bed (column, lag 25 min), T_amb ambient; disp_z_um with its own noise.
// The log has columns time_min,spindle_rpm,T1,T2,T3,T4,T_amb,disp_z_um. Deterministic by seed.
#include <cstdint>
#include <vector>

#include "core/thermal/thermal_log.h"

namespace metrofit {

struct SpeedStep {
  double startMin = 0.0;  ///< the step starts at this time and lasts until the next step
  double rpm = 0.0;
};

struct ThermalSimOptions {
  double durationMin = 480.0;
  double stepMin = 1.0;
  std::vector<SpeedStep> programme{{0.0, 0.0}, {10.0, 6000.0}, {250.0, 0.0}};
  double ambient0 = 20.0, ambientAmp = 0.4;
  double gainS = 2.5, tauS = 35.0;  ///< K per power unit, min
  double shareC = 0.55, tauC = 110.0;
  double kS = 4.0, kC = 2.5;  ///< um per K
  double sensorLagMin[4] = {4.0, 12.0, 6.0, 25.0};
  double noiseTempK = 0.02;
  double noiseDispUm = 0.25;
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

/// Runs the simulation; throws OptionsError when options are invalid.
ThermalLog simulateThermalTest(const ThermalSimOptions& options);

}  // namespace metrofit
