// metrofit-cli kinematic identify|compensate (CONTRACT.md). The methods land with issue 6.
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

void registerKinematicCommands(CLI::App& app) {
  auto* kin = app.add_subcommand("kinematic", "Kinematic error identification and compensation");
  kin->require_subcommand(1);
  auto a = std::make_shared<MethodArgs>();
  auto* id =
      kin->add_subcommand("identify", "Identify actuator errors from a measured path or circular test");
  existingFile(id->add_option("--data", a->data, "Measured path (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)")
                   ->required());
  addOut(id, a->out);
  id->callback([a] {
    selectRunner([a]() -> int {
      const CsvTable t = readCsvFile(a->data);
      for (const char* c : {"x_cmd_mm", "y_cmd_mm", "x_meas_mm", "y_meas_mm"}) (void)t.numericColumn(c);
      notInThisBuild("kinematic identification", "issue 6");
    });
  });
  auto b = std::make_shared<MethodArgs>();
  auto* comp = kin->add_subcommand("compensate", "Compensated references for a nominal path");
  existingFile(comp->add_option("--errors", b->errors, "Errors (JSON written by identify)")->required());
  existingFile(comp->add_option("--path", b->path, "Nominal path (CSV x_mm,y_mm)")->required());
  addOut(comp, b->out);
  comp->callback([b] {
    selectRunner([b]() -> int {
      (void)readJsonFile(b->errors);
      const CsvTable t = readCsvFile(b->path);
      for (const char* c : {"x_mm", "y_mm"}) (void)t.numericColumn(c);
      notInThisBuild("kinematic compensation", "issue 6");
    });
  });
}

}  // namespace metrofit::cli
