// metrofit-cli setup: setup-data correction (CONTRACT.md). The method lands with issue 4.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <memory>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/matching/probe_points.h"
#include "core/thermal/thermal_log.h"

namespace metrofit::cli {
namespace {

struct MethodArgs {
  std::string model, data, method, machine, errors, path, target, inputs, out;
  long budget = 5000;
  std::uint64_t seed = 1;
  double tolerance = 0.05, trainFraction = 0.5;
  bool allowScale = false;
};

}  // namespace

void registerSetupCommand(CLI::App& app) {
  auto a = std::make_shared<MethodArgs>();
  auto* sub = app.add_subcommand("setup", "Setup-data correction (work and tool offsets) from CMM reports");
  existingFile(sub->add_option("--model", a->model, "Setup model (relation graph, JSON)")->required());
  existingFile(sub->add_option("--data", a->data, "CMM report series (CSV)")->required());
  sub->add_option("--method", a->method, "exact|cripso|pso|ga|coa")
      ->check(CLI::IsMember({"exact", "cripso", "pso", "ga", "coa"}))
      ->default_val("exact");
  sub->add_option("--budget", a->budget, "Evaluation budget of a metaheuristic")->check(CLI::PositiveNumber);
  addSeed(sub, a->seed);
  addOut(sub, a->out);
  sub->callback([a] {
    selectRunner([a]() -> int {
      (void)readJsonFile(a->model);
      (void)readCsvFile(a->data);
      notInThisBuild("setup-data correction", "issue 4");
    });
  });
}

}  // namespace metrofit::cli
