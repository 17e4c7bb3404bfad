#pragma once
// metrofit-bench --kinematic: identification of a 720-point circular test (target: in
// milliseconds), side by side with peers on the same data in the same run (see bench_kinematic.cpp).
#include <nlohmann/json.hpp>

namespace metrofit::bench {

/// Runs the section, prints it to stdout and returns {"points", "metrofit_ms", "metrofit_zero_start_ms",
/// "peer": "...", "peer_ms", "ratio", "affine_ms", "max_angle_diff_deg", "max_origin_diff_mm", ...}.
nlohmann::json benchKinematic(int repeat);

}  // namespace metrofit::bench
