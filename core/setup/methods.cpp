#include "core/setup/methods.h"

#include "core/common/error.h"
#include "core/optim/coa.h"
#include "core/optim/cripso.h"
#include "core/optim/ga.h"
#include "core/optim/pso.h"

namespace metrofit::setup {

std::vector<std::string> setupMethodNames() {
  return {"exact", "cripso", "pso", "ga", "coa"};
}

std::vector<std::string> setupMetaheuristicNames() {
  return {"cripso", "pso", "ga", "coa"};
}

std::unique_ptr<optim::Algorithm> makeSetupAlgorithm(const std::string& method, long budget,
                                                     std::uint64_t seed, bool keepTrace,
                                                     const std::string& field) {
  optim::CommonOptions common;
  common.maxEvaluations = budget;
  common.seed = seed;
  common.keepTrace = keepTrace;
  if (method == "cripso") {
    optim::Cripso::Options o;
    o.common = common;
    return std::make_unique<optim::Cripso>(o);
  }
  if (method == "pso") {
    optim::Pso::Options o = optim::Pso::Options::stryczek2016();
    o.common = common;
    return std::make_unique<optim::Pso>(o);
  }
  if (method == "ga") {
    optim::Ga::Options o;
    o.common = common;
    return std::make_unique<optim::Ga>(o);
  }
  if (method == "coa") {
    optim::Coa::Options o;
    o.common = common;
    return std::make_unique<optim::Coa>(o);
  }
  throw OptionsError(
      ErrorContext{{}, 0, 0, field},
      "'" + method + "' is not a metaheuristic of the setup correction (cripso, pso, ga, coa)");
}

}  // namespace metrofit::setup
