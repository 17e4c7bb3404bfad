#pragma once
// metrofit-bench --diagnose --open: the open-world detection study of the closed
// loop. Per domain, the cases of core/sim/open_world.h (effects no catalogue entry models, a gross
// error, clean data with Gaussian, Laplace and Student-t5 noise), `seeds` data sets each at one
// effect-to-noise ratio (default 5), diagnosed with the domain's `diagnose` and scored on what the
// result says (docs/file-formats.md#residual_check):
//   (a) effect cases: structure flagged or explained = residual_check.white == false, or any effect
//       accepted; reported separately: explained by a generic effect (`unexplained:*` accepted),
//       flagged only (not white, nothing accepted), a catalogue name accepted; and whether the
//       strongest structure (or an accepted generic effect) names a variable of the truth;
//       target >= 95 %;
//   (b) a catalogue name accepted on an open-world case (effect or gross-error cases): target <= 2 %;
//   (c) clean data: false flags (white == false or anything accepted), target <= 1 %; outliers
//       listed on clean data reported separately;
//   (d) gross-error cases: the unit hit is listed in residual_check.outliers;
//   (e) the cases of the loop's two misses (issue 32 item 5: centrifugal_rpm, scale_damage,
//       local_bump, tool_runin, surface_tilt), per case: found (as (a)) >= 95 %, a catalogue name
//       accepted (the nearest name taken for a shape no entry models, or a name for a block of points)
//       <= 2 %, and for scale_damage its block's rows reported (>= 90 % of them among the check's
//       outliers or blocks) >= 95 %.
// A result without residual_check counts as white with no outliers (and is counted). The table also
// gives, per case, the median of the final fit rmse over the noise sigma (rmse/sd; the kinematic
// rmse is a distance, sqrt 2 sigma for pure noise), the catalogue names accepted and the strongest
// `against` found (the three most frequent each).
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

struct OpenBenchOptions {
  int seeds = 100;                   ///< data sets per case
  double ratio = 5.0;                ///< effect-to-noise ratio of the effect and gross-error cases
  std::string sourceDir;             ///< for the setup model (resources/demo/setup/paper_example.json)
  std::vector<std::string> domains;  ///< empty: thermal, kinematic, setup, matching
};

/// Runs the study, prints one table row per case and the four figures per domain, returns the JSON.
nlohmann::json benchDiagnoseOpen(const OpenBenchOptions& options);

/// One data set of the study, to look at a failure (metrofit-bench --open-case DOMAIN CASE SEED):
/// prints the truth and the diagnosis JSON (docs/file-formats.md#diagnose-result) and returns {"truth",
/// "diagnosis"}.
nlohmann::json benchOpenCase(const OpenBenchOptions& options, const std::string& domain,
                             const std::string& name, std::uint64_t seed);

}  // namespace metrofit::bench
