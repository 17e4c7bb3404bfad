#pragma once
// metrofit-bench --kinematic-chain: the kinematic-compensation paper's chain from SPC to compensation
// (edges machined along X and Y -> regression offset angles -> actuator errors -> Eq. 15 references) and
// the three-axis identification from circular tests in XY, YZ and ZX, on simulated machines with known
// errors, against peers on the same machines in the same run (see bench_kinematic_chain.cpp).
#include <nlohmann/json.hpp>

namespace metrofit::bench {

struct KinematicChainBenchOptions {
  int seeds = 20;  ///< simulated machines
  int repeat = 5;  ///< timed runs per seed and method (median)
};

/// Runs the section, prints its table to stdout and returns the figures as JSON.
nlohmann::json benchKinematicChain(const KinematicChainBenchOptions& options);

}  // namespace metrofit::bench
