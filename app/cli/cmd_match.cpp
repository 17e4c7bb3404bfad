// metrofit-cli match: posture matching (CONTRACT.md). The method lands with issue 5.
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

void registerMatchCommand(CLI::App& app) {
  auto a = std::make_shared<MethodArgs>();
  auto* sub = app.add_subcommand("match", "Workpiece posture matching and 5-axis machine adjustment");
  existingFile(sub->add_option("--data", a->data, "Probe points (CSV)")->required());
  sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")->check(CLI::PositiveNumber);
  sub->add_option("--method", a->method, "sade|ga-simplex|closed-form|minimax")
      ->check(CLI::IsMember({"sade", "ga-simplex", "closed-form", "minimax"}))
      ->default_val("sade");
  sub->add_flag("--allow-scale", a->allowScale, "Fit an isotropic scale too");
  sub->add_option("--machine", a->machine, "Machine topology, e.g. xfyzba")->default_val("xfyzba");
  addSeed(sub, a->seed);
  addOut(sub, a->out);
  sub->callback([a] {
    selectRunner([a]() -> int {
      (void)readProbePoints(a->data);
      notInThisBuild("posture matching", "issue 5");
    });
  });
}

}  // namespace metrofit::cli
