// metrofit-cli thermal fit (CONTRACT.md). The models land with issue 7.
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

void registerThermalCommands(CLI::App& app) {
  auto* th = app.add_subcommand("thermal", "Thermal error modelling");
  th->require_subcommand(1);
  auto a = std::make_shared<MethodArgs>();
  auto* fit =
      th->add_subcommand("fit", "Fit a thermal error model on the first part of a log, test on the rest");
  existingFile(fit->add_option("--data", a->data, "Thermal log (CSV)")->required());
  fit->add_option("--target", a->target, "Column to model (e.g. disp_z_um)")->required();
  fit->add_option("--inputs", a->inputs, "Comma-separated input columns")->required();
  fit->add_option("--model", a->method, "gnnmci|gmc|mlp")
      ->check(CLI::IsMember({"gnnmci", "gmc", "mlp"}))
      ->default_val("gnnmci");
  fit->add_option("--train-fraction", a->trainFraction, "Fraction of rows used for fitting")
      ->check(CLI::Range(0.05, 0.95))
      ->capture_default_str();
  addSeed(fit, a->seed);
  addOut(fit, a->out);
  fit->callback([a] {
    selectRunner([a]() -> int {
      (void)readThermalArgs(a->data, a->target, a->inputs);
      notInThisBuild("thermal model fitting", "issue 7");
    });
  });
}

}  // namespace metrofit::cli
