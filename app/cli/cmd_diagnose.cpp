// metrofit-cli diagnose <domain> (CONTRACT.md). The closed loop lands with issue 8.
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

void registerDiagnoseCommands(CLI::App& app) {
  auto* dg =
      app.add_subcommand("diagnose", "Closed loop: residual -> missing effect -> error before and after");
  dg->require_subcommand(1);
  for (const char* domain : {"thermal", "kinematic", "setup", "matching"}) {
    auto a = std::make_shared<MethodArgs>();
    auto* sub = dg->add_subcommand(domain, std::string("Diagnose the ") + domain + " model");
    existingFile(sub->add_option("--data", a->data, "Measured data")->required());
    if (std::string(domain) == "setup")
      existingFile(sub->add_option("--model", a->model, "Setup model (JSON)")->required());
    if (std::string(domain) == "thermal") {
      sub->add_option("--target", a->target, "Column to model")->required();
      sub->add_option("--inputs", a->inputs, "Declared input columns")->required();
      sub->add_option("--train-fraction", a->trainFraction, "Fraction of rows fitted; the rest is held out")
          ->check(CLI::Range(0.05, 0.95))
          ->capture_default_str();
    }
    if (std::string(domain) == "matching") {
      sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")->check(CLI::PositiveNumber);
    }
    addSeed(sub, a->seed);
    addOut(sub, a->out);
    const std::string d = domain;
    sub->callback([a, d] {
      selectRunner([a, d]() -> int {
        if (d == "thermal")
          (void)readThermalArgs(a->data, a->target, a->inputs);
        else if (d == "matching")
          (void)readProbePoints(a->data);
        else
          (void)readCsvFile(a->data);
        if (!a->model.empty()) (void)readJsonFile(a->model);
        notInThisBuild("the " + d + " diagnosis", "issue 8");
      });
    });
  }
}

}  // namespace metrofit::cli
