#pragma once
// metrofit-bench --matching and --real-matching (the matching targets; protocol in bench_matching.cpp).
#include <string>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

struct MatchingBenchOptions {
  int seeds = 20;                ///< random postures / noise per check (seeds 1..N)
  long largePoints = 1'000'000;  ///< closed form vs Eigen::umeyama
  int repeat = 3;                ///< timings: median of this many runs
};

/// Runs the section, prints the figures to stdout and returns them as JSON.
nlohmann::json benchMatching(const MatchingBenchOptions& options);

/// The SDSS plug-plate reports in `dataDir` (../shared/data/real/cmm-plugplate-sdss) with the source
/// program's own similarity fits (fit_*.txt) as the oracle for our closed-form fit with scale.
nlohmann::json benchRealMatching(const std::string& dataDir);

}  // namespace metrofit::bench
