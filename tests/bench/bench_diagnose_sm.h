#pragma once
// metrofit-bench --diagnose / --real-diagnose, setup and matching domains: the runners of
// the detection study (bench_diagnose.h) and the real-data diagnosis of the SDSS plug plates.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_diagnose.h"

namespace metrofit::bench {

/// "setup" (tool_wear:T23, drift:W3 on the demo's paper model), "matching" (scale, distortion on a
/// planar position-only hole plate) and "matching-s" (scale, surface_offset:ruled+,
/// surface_offset:hole1 on the probed S-piece with normals).
std::vector<DomainRunner> setupMatchingRunners(const std::string& sourceDir);

/// The matching diagnosis of every plate file of the SDSS directory (PC-DMIS hole tables): what was
/// found, the rmse before / after, printed one line per plate.
nlohmann::json benchRealDiagnoseSdss(const std::string& sdssDir);

}  // namespace metrofit::bench
