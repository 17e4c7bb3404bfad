// metrofit-cli kinematic identify|compensate (CONTRACT.md; issue 6).
//   identify   --data C.csv [--out E.json]
//   compensate --errors E.json --path N.csv [--out F.csv] [--gcode F.nc] [--step-nc F.p21]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/export.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/measured_path.h"

namespace metrofit::cli {
namespace {

struct IdentifyArgs {
  std::string data, out;
};

struct CompensateArgs {
  std::string errors, path, out, gcode, stepNc;
  double feed = 1000.0;
};

std::string g(double v, const char* format = "%.6g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

int runIdentify(const IdentifyArgs& a) {
  const MeasuredPath path = readMeasuredPath(a.data);
  const IdentifyResult r = identifyActuatorErrors(path);
  if (r.run.termination == Termination::Failed) {
    throw std::runtime_error("identification failed on " + a.data + ": " + r.run.message);
  }
  writeResult(a.out, dumpJson(identifyResultToJson(r)));
  const ActuatorErrors2& e = r.errors;
  std::fprintf(
      stderr,
      "kinematic identify: %zu points, origin (%s, %s) mm, a = %s deg, b = %s deg, squareness %s deg "
      "(+-%s), rmse %s mm, %ld iteration%s (%s)\n",
      r.points, g(e.originMm.x()).c_str(), g(e.originMm.y()).c_str(), g(e.xAxisAngleDeg).c_str(),
      g(e.yAxisAngleDeg).c_str(), g(e.squarenessDeg()).c_str(), g(r.squarenessStdErrDeg, "%.2g").c_str(),
      g(r.rmseMm, "%.3g").c_str(), r.run.iterations, r.run.iterations == 1 ? "" : "s",
      toString(r.run.termination));
  return 0;
}

int runCompensate(const CompensateArgs& a) {
  const ActuatorErrors2 errors = readActuatorErrors(a.errors);
  const NominalPath nominal = readNominalPath(a.path);
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(errors);
  const auto commands = compensatePath(machine, nominal.points);

  // Build every output first, so bad input writes nothing.
  const std::string csv = commandPathToCsv(commands);
  std::string gcode, stepNc;
  if (!a.gcode.empty()) {
    GcodeOptions o;
    o.programName = "compensated " + std::filesystem::path(a.path).filename().string();
    o.feedMmPerMin = a.feed;
    gcode = compensatedPathToGcode(commands, errors, o);
  }
  if (!a.stepNc.empty()) {
    if (commands.size() < 2) {
      throw ValidationError(ErrorContext{a.path, 0, 0, {}},
                            "has 1 point: a STEP-NC toolpath (--step-nc) needs at least 2");
    }
    StepNcOptions o;
    o.fileName = std::filesystem::path(a.stepNc).filename().string();
    o.timestamp = utcNow();
    o.projectName = "Metrofit compensated " + std::filesystem::path(a.path).filename().string();
    stepNc = compensatedPathToStepNc(commands, errors, o);
  }
  if (!a.gcode.empty()) writeFileAtomic(a.gcode, gcode);
  if (!a.stepNc.empty()) writeFileAtomic(a.stepNc, stepNc);
  writeResult(a.out, csv);

  double largest = 0.0;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    largest = std::max(largest, (commands[i] - nominal.points[i]).norm());
  }
  std::string wrote;
  if (!a.gcode.empty()) wrote += ", G-code " + a.gcode;
  if (!a.stepNc.empty()) wrote += ", STEP-NC " + a.stepNc;
  std::fprintf(stderr,
               "kinematic compensate: %zu points of %s, largest correction %s mm (squareness %s deg)%s\n",
               commands.size(), a.path.c_str(), g(largest, "%.4g").c_str(), g(errors.squarenessDeg()).c_str(),
               wrote.c_str());
  return 0;
}

}  // namespace

void registerKinematicCommands(CLI::App& app) {
  auto* kin = app.add_subcommand("kinematic", "Kinematic error identification and compensation");
  kin->require_subcommand(1);

  auto a = std::make_shared<IdentifyArgs>();
  auto* id =
      kin->add_subcommand("identify", "Identify actuator errors from a measured path or circular test");
  existingFile(id->add_option("--data", a->data, "Measured path (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)")
                   ->required());
  addOut(id, a->out);
  id->callback([a] { selectRunner([a]() -> int { return runIdentify(*a); }); });

  auto b = std::make_shared<CompensateArgs>();
  auto* comp = kin->add_subcommand("compensate", "Compensated references for a nominal path");
  existingFile(comp->add_option("--errors", b->errors, "Errors (JSON written by identify)")->required());
  existingFile(comp->add_option("--path", b->path, "Nominal path (CSV x_mm,y_mm)")->required());
  comp->add_option("--out", b->out,
                   "Compensated references (CSV x_cmd_mm,y_cmd_mm; atomic). Default: stdout");
  comp->add_option("--gcode", b->gcode, "Also write the references as G-code (G01 blocks)");
  comp->add_option("--step-nc", b->stepNc, "Also write the references as a STEP-NC Part 21 file");
  comp->add_option("--feed", b->feed, "Feed of the G-code, mm/min")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  comp->callback([b] { selectRunner([b]() -> int { return runCompensate(*b); }); });
}

}  // namespace metrofit::cli
