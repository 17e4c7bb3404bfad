#pragma once
// metrofit-bench --nist: the 27 NIST StRD nonlinear regression problems from both starts, through
// Metrofit's Levenberg-Marquardt (core/optim/least_squares.h) and through Ceres Solver (the peer, same
// analytic derivatives, same starts, same process), with the log relative error of the parameters
// against NIST's certified values and the time (see bench_nist.cpp).
#include <string>

#include <nlohmann/json.hpp>

namespace metrofit::bench {

/// Prints a table and returns [{"problem", "start", "converged", "lre", "time_ns", "ceres_lre",
/// "ceres_time_ns", ...}] (CONTRACT.md, third round). `folder` holds the NIST .dat files.
nlohmann::json benchNist(const std::string& folder, int repeat);

}  // namespace metrofit::bench
