#pragma once
// metrofit-bench --optimizers: our metaheuristics side by side with pagmo2's pso and sade on the
// same problems at the same evaluation budget (see bench_optim.cpp for the protocol).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

struct OptimBenchOptions {
  int seeds = 25;         ///< runs per problem and method (seeds first..first+N-1); --quick: 5
  int firstSeed = 1;      ///< --first-seed K: another sample of seeds (an out-of-sample check)
  long budget = 10000;    ///< objective evaluations per run (10-D problems)
  std::string sourceDir;  ///< the source tree (for the setup example in resources/demo/setup)
  /// --only P1,P2 / --methods M1,M2: run only these problems / our methods (empty: all). pagmo's
  /// peers always run, so every printed comparison stays a same-run comparison.
  std::vector<std::string> problems, methods;
};

/// Runs the section, prints the table to stdout and returns {"budget", "seeds", "dimension",
/// "rows": [{"problem", "method", "median_best", "best", "worst", "ns_per_eval", "peer",
/// "peer_median_best", "peer_ns_per_eval", "hit_rate"}, ...], "targets": [...]}.
nlohmann::json benchOptimizers(const OptimBenchOptions& options);

}  // namespace metrofit::bench
