#pragma once
// The setup correction's methods by name, with the paper's settings, so that the CLI, the GUI and
// the statistical validation share one set of defaults (STYLE.md §3).
//
//   exact   core/setup/exact.h (LP / MILP with GLPK)
//   cripso  optim::Cripso, |P| = 100, w = 0.75, c1 = c2 = cos(pi/2 Li/L)      (paper, Eq. 1, 11)
//   pso     optim::Pso::Options::stryczek2016(): 100 particles, asynchronous gbest, w = 0.75,
//           c1 = c2 = cos(pi/2 Li/L)
//   ga      optim::Ga, population 50, gene mutation probability 0.1
//   coa     optim::Coa, at most 40 habitats, 5-10 eggs
// The paper's budget is 5000 solutions; its COA ran 100 iterations, "approximately 30,000 solutions"
// (kCoaPaperBudget).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/optim/algorithm.h"

namespace metrofit::setup {

inline constexpr long kPaperBudget = 5000;
inline constexpr long kCoaPaperBudget = 30000;

/// "exact", "cripso", "pso", "ga", "coa".
std::vector<std::string> setupMethodNames();
/// The metaheuristics only: "cripso", "pso", "ga", "coa".
std::vector<std::string> setupMetaheuristicNames();

/// A metaheuristic by name with the paper's settings; OptionsError naming `field` for an unknown
/// name (or "exact", which is not an optim::Algorithm: use solveExact).
std::unique_ptr<optim::Algorithm> makeSetupAlgorithm(const std::string& method, long budget,
                                                     std::uint64_t seed, bool keepTrace = true,
                                                     const std::string& field = "--method");

}  // namespace metrofit::setup
