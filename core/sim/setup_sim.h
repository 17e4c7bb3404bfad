#pragma once
// Simulated measurement data for the setup correction (the simulator plays machine and CMM).
//
// The paper's statistical validation (Stryczek 2016, "Validate the results of the proposed
// scheme", Eq. 12-13): a measurement set is made of
//   setup-data errors   E^sd_i = w1 (1 - 2 r)      per setup datum i          (Eq. 12)
//   random errors       E_q    = w2 (1 - 2 r)      per dimension q            (Eq. 13)
// with r uniform in [0, 1) drawn afresh for every value and w1 = 0.03 mm, w2 = 0.02 mm in the
// paper. The setup errors act on the dimensions through the gain matrix G of the model (model.h,
// Eq. 4-5), so the deviation of dimension q is
//   e_q = (G E^sd)_q + E_q,
// and the correction that undoes the setup errors is x = -E^sd (when the bounds allow it).
// Set j is deterministic in (seed, j): sets can be generated in any order or in parallel.
//
// A simulated CMM report series (the CSV of docs/file-formats.md#cmm-report-series:
// part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm) uses ONE draw of
// E^sd for the whole series and fresh random errors E_q for every part:
//   measured = nominal + (G E^sd)_q + E_q, rounded to the CMM resolution.
// The "part" column is the part (fixture load) number 1..parts, time_min = part *
// minutesPerPart; the nominal is the model's (0 when the model has none).
#include <cstdint>
#include <string>
#include <vector>

#include "core/setup/model.h"

namespace metrofit {

struct SetupSimOptions {
  double w1 = 0.03;              ///< Eq. 12 weight of the setup-data errors, mm
  double w2 = 0.02;              ///< Eq. 13 weight of the random errors, mm
  int parts = 5;                 ///< parts in a simulated report series
  double minutesPerPart = 12.0;  ///< time between parts in the series, min
  double resolutionMm = 0.001;   ///< CMM resolution the measured values are rounded to (0: none)
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

struct SetupMeasurementSet {
  std::vector<double> setupErrorMm;  ///< E^sd_i, one per setup datum
  std::vector<double> deviationMm;   ///< e_q, one per dimension
};

/// Measurement set `index` of the statistical validation (Eq. 12-13).
SetupMeasurementSet simulateSetupSet(const setup::Model& model, const SetupSimOptions& options,
                                     std::size_t index);
/// Sets 0..count-1.
std::vector<SetupMeasurementSet> simulateSetupSets(const setup::Model& model, const SetupSimOptions& options,
                                                   std::size_t count);

/// A CMM report series (CSV text, see above). When `setupErrorMm` is given it receives E^sd.
std::string simulateSetupReport(const setup::Model& model, const SetupSimOptions& options,
                                std::vector<double>* setupErrorMm = nullptr);

}  // namespace metrofit
