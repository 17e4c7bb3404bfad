#pragma once
// metrofit-bench --setup: the exact setup correction's solve time on the paper's example
// (target < 1 ms) and on a generated 500 setup data x 5000 dimensions model (target < 1 s), and
// CRIPSO's solutions per second against the paper's 5000 solutions in 0.58 s (ratio).
#include <string>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

/// Runs the section, prints one line per measurement and returns
/// {"paper": {"exact_ms", "exact_cpu_ms", "f1_mm", "f1_optimal", "target_ms"}, "large": {"setup_data",
/// "dimensions", "exact_ms", "f1_mm", "f1_optimal", "f2_minimal", "target_ms"}, "cripso": {"budget",
/// "seconds", "solutions_per_s", "paper_solutions_per_s", "ratio"}}.
nlohmann::json benchSetup(const std::string& sourceDir, int repeat);

}  // namespace metrofit::bench
