#pragma once
// Simulated CMM report series with setup effects the declared model lacks: the
// test data of the setup diagnosis (core/diagnose/setup_diagnosis.h).
//
// Composed with setup_sim.h: simulateSetupReport (one draw of the constant setup-data errors E^sd
// for the whole series, Eq. 12, and fresh random errors per part and dimension, Eq. 13, uniform in
// +-w2, i.e. sigma = w2 / sqrt(3)) makes the series without rounding; then, per row of part p at
// time t_p, the undeclared effects are added through the gain matrix G of the model and the value
// is rounded to the CMM resolution:
//   measured = nominal + (G E^sd)_q + E_q + sum_i G[q][i] delta_i(p),
//   tool_wear:<tool>  delta_T(p) = mm_per_part * (p - 1)              (tool length change)
//   drift:<datum>     delta_i(p) = mm_per_min * (t_p - t_1)           (e.g. thermal drift)
// so part 1 carries exactly E^sd. Times: the interval between parts is drawn uniform in
// minutesPerPart * [1 - timeJitter, 1 + timeJitter] (t_1 = one interval), so that time is not
// exactly proportional to the part number and a drift can be told from a wear of the same datum;
// timeJitter = 0 gives t_p = p * minutesPerPart as setup_sim.h. Deterministic by base.seed.
#include <string>
#include <utility>
#include <vector>

#include "core/setup/model.h"
#include "core/sim/setup_sim.h"

namespace metrofit {

struct SetupEffectsSimOptions {
  SetupSimOptions base;  ///< w1 (constant setup errors), w2 (noise), parts, minutesPerPart, resolution, seed
  double timeJitter = 0.5;  ///< relative spread of the interval between parts, in [0, 1)
  std::vector<std::pair<std::string, double>> toolWearMmPerPart;  ///< tool id -> mm per part
  std::vector<std::pair<std::string, double>> driftMmPerMin;      ///< setup datum id -> mm per min

  bool isValid(std::string* why) const;
};

struct SetupEffectsTruth {
  std::vector<double> setupErrorMm;  ///< E^sd, one per setup datum
  std::vector<double> timeMin;       ///< t_p, one per part
};

/// The report series as CSV text (part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,
/// upper_tol_mm). OptionsError for invalid options or an effect naming no tool / setup datum of the
/// model.
std::string simulateSetupEffectsReport(const setup::Model& model, const SetupEffectsSimOptions& options,
                                       SetupEffectsTruth* truth = nullptr);

}  // namespace metrofit
