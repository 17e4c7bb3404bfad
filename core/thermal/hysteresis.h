#pragma once
// Hysteresis of thermal sensors against the thermal displacement (Abdulshahed et al. 2016, grey neural
// network thermal model, Section 3.1, Fig. 8-9): the displacement plotted against each sensor over heating
// and cooling traces a loop whose width shows how much the sensor lags (the paper: T2 "Ram rear" ~10 min
// behind, FBG sensors almost linear).
//
// Phases: the target's change since the first row, smoothed by a centred moving average over
// `smoothingMin`, is "heating" where its magnitude grows and "cooling" where it shrinks (central
// difference; +1 / -1 per row).
// Loop area (shoelace formula over the whole trajectory, closed back to the first point), in sensor
// unit x target unit:  A = 1/2 |sum_k (s_k y_{k+1} - s_{k+1} y_k)|;  normalised by the ranges,
// A / (range(s) range(y)), it is a dimensionless hysteresis index (0: a line; 0.785: a circle).
// Lag: a first-order lag with time constant tau,
//   L_tau[x](1) = x(1),  L_tau[x](k) = L(k-1) + (1 - e^{-(t_k - t_{k-1}) / tau}) (x(k) - L(k-1))
// (exact for an input held between samples; tau = 0: L = x), fitted both ways by least squares on
// (offset, gain) for every tau and a 1-D search on tau (log grid, then golden section):
//   sensor       ~ a + g L_tau[displacement]   (the sensor lags the displacement: tau_min = +tau)
//   displacement ~ a + g L_tau[sensor]         (the displacement lags the sensor: tau_min = -tau)
// whichever explains more variance; r2_static is the fit without lag (tau = 0).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/thermal/thermal_data.h"

namespace metrofit::thermal {

/// L_tau[x] on the time axis (see above) is lag_regression.h firstOrderLagMin.

struct LagFit {
  double tauMin = 0.0;
  double gain = 0.0, offset = 0.0;
  double r2 = 0.0;        ///< coefficient of determination at tau
  double r2Static = 0.0;  ///< at tau = 0
};
/// Fits response ~ offset + gain L_tau[driver] for tau in [0, tauMaxMin].
LagFit fitLag(std::span<const double> timeMin, std::span<const double> driver,
              std::span<const double> response, double tauMaxMin);

struct HysteresisOptions {
  double smoothingMin = 10.0;  ///< moving-average window for the phases
  double maxLagMin = 0.0;      ///< largest tau searched; 0: half the log's duration

  bool isValid(std::string* why) const;
};

struct SensorHysteresis {
  std::string sensor;
  double loopArea = 0.0;            ///< sensor unit x target unit
  double normalisedLoopArea = 0.0;  ///< loop area / (range sensor x range target)
  double tauMin = 0.0;              ///< > 0: sensor lags the displacement; < 0: the displacement lags
  double gain = 0.0;                ///< of the chosen lag fit
  double r2 = 0.0, r2Static = 0.0;
};

struct HysteresisAnalysis {
  std::string target;
  std::vector<int> phase;  ///< +1 heating, -1 cooling, per row
  std::size_t heatingRows = 0, coolingRows = 0;
  std::vector<SensorHysteresis> sensors;  ///< in the order of the series' inputs
};

/// Analyses every input of `series` against its target (ValidationError for constant columns).
HysteresisAnalysis analyseHysteresis(const ThermalSeries& series, const HysteresisOptions& options = {});
nlohmann::json hysteresisToJson(const HysteresisAnalysis& a);

}  // namespace metrofit::thermal
