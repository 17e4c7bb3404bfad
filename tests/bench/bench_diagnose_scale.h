#pragma once
// metrofit-bench --diagnose-scale: `diagnose thermal` time against the number of
// rows, up to a week of 1 Hz data (604 800 rows, 20 data columns), on one core; and how fast a
// cancel takes effect.
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/thermal/thermal_log.h"

namespace metrofit::bench {

/// A synthetic 1 Hz thermal log of `rows` rows: time_s, spindle_rpm (a random programme of 0.5-4 h
/// steps), T1..T18 (first-order lags of the spindle heat with time constants 5 min to 6 h, a daily
/// ambient cycle, 0.01 K noise) and disp_um = -2 L_20min[T1] - 1.5 T2 + T3 + 0.0003 um/rpm spindle
/// + 0.3 um noise (declared inputs T1, T2, T3: the loop should find the lag of T1 and the spindle).
ThermalLog scaleLog(std::size_t rows, std::uint64_t seed = 1);

/// Times diagnoseThermal (declared T1, T2, T3, train fraction 0.5) on scaleLog of each size, and the
/// time from a cancel to the return on the largest.
nlohmann::json benchDiagnoseScale(const std::vector<std::size_t>& rows);

}  // namespace metrofit::bench
