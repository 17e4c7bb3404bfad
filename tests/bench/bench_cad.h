#pragma once
// metrofit-bench --cad: the closest-point search of CAD nominals (core/geometry/mesh_search.h), the
// k-d tree against a brute-force loop over every triangle in the same run, and one posture match.
#include <nlohmann/json.hpp>

namespace metrofit::bench {

/// Prints the figures to stdout and returns them as JSON.
nlohmann::json benchCad(int repeat);

}  // namespace metrofit::bench
