#pragma once
// metrofit-bench --watch [N]: the live loop (core/study/watch.h, `metrofit-cli watch`) against the
// batch run it replaces, in the same run. N simulated CMM reports of the paper's setup model (one part
// each, core/sim/setup_sim.h) are dropped into the watched folder one at a time; at checkpoints the
// time WatchSession::process takes for the next file (without and with the diagnosis) is set beside the
// time of the peer, the batch `metrofit-cli setup --method exact --data F1 .. Fk` on the same files
// without the process start (setup::readMeasurements + setup::solveExact), and the loop's correction is
// checked to equal the batch's.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

nlohmann::json benchWatch(std::size_t files, const std::string& sourceDir);

}  // namespace metrofit::bench
