// metrofit-cli kinematic identify|compensate (CONTRACT.md; issue 6) and the kinematic simulators.
//   identify   --data C.csv [--out E.json]
//   compensate --errors E.json --path N.csv [--out F.csv] [--gcode F.nc] [--step-nc F.p21]
//   simulate circular [--radius R] [--centre X,Y] [--points N] [--start-angle D] [--origin X,Y]
//                     [--x-angle A] [--y-angle B] [--noise S] [--seed N] [--out C.csv]
//       a circular test (core/sim/circular_sim.h): one loop CCW, then one CW, through the machine
//       with the given actuator errors plus noise; CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm.
//   simulate bores [--parts N] [same machine options] [--scatter S] [--drift D] [--out B.csv]
//       an SPC series: the diameters of N bores circle-interpolated on that machine (see runBores).
#include <CLI/CLI.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/export.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/measured_path.h"
#include "core/sim/circular_sim.h"

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
  const MeasuredPath path = readMeasuredPath(a.data, csvOptions());
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
  const NominalPath nominal = readNominalPath(a.path, csvOptions());
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

/// The machine and test options shared by `simulate circular` and `simulate bores`.
struct CircularArgs {
  std::string out;
  double radius = 100.0;
  std::vector<double> centre{0.0, 0.0};
  int points = 360;
  double startAngle = 0.0;
  std::vector<double> origin;  ///< empty: CircularSimOptions::defaultErrors()
  double xAngle = CircularSimOptions::defaultErrors().xAxisAngleDeg;
  double yAngle = CircularSimOptions::defaultErrors().yAxisAngleDeg;
  double noise = 0.0005;
  std::uint64_t seed = 1;
};

struct BoresArgs {
  CircularArgs machine;
  int parts = 25;
  double scatter = 0.002;
  double drift = 0.0;
};

CircularSimOptions circularOptions(const CircularArgs& a) {
  CircularSimOptions o;
  o.radiusMm = a.radius;
  o.centreMm = Eigen::Vector2d(a.centre[0], a.centre[1]);
  o.pointsPerLoop = a.points;
  o.startAngleDeg = a.startAngle;
  if (a.origin.size() == 2) o.errors.originMm = Eigen::Vector2d(a.origin[0], a.origin[1]);
  o.errors.xAxisAngleDeg = a.xAngle;
  o.errors.yAxisAngleDeg = a.yAngle;
  o.noiseMm = a.noise;
  o.seed = a.seed;
  requireValid(o, "simulate circular");
  return o;
}

/// "# " comment lines stating how the file was made (CSV readers skip them).
std::string circularHeader(const char* what, const CircularSimOptions& o) {
  CsvWriter w;
  w.comment(std::string("metrofit-cli simulate ") + what + ": R " + g(o.radiusMm) + " mm about (" +
            g(o.centreMm.x()) + ", " + g(o.centreMm.y()) + ") mm, " + std::to_string(o.pointsPerLoop) +
            " points per loop, start " + g(o.startAngleDeg) + " deg");
  w.comment("machine: origin (" + g(o.errors.originMm.x()) + ", " + g(o.errors.originMm.y()) +
            ") mm, x axis " + g(o.errors.xAxisAngleDeg) + " deg, y axis " + g(o.errors.yAxisAngleDeg) +
            " deg; noise " + g(o.noiseMm) + " mm (1 sigma per coordinate); seed " + std::to_string(o.seed));
  return w.text();
}

int runCircular(const CircularArgs& a) {
  const CircularSimOptions o = circularOptions(a);
  const MeasuredPath path = simulateCircularTest(o);
  std::string csv = circularHeader("circular", o);
  csv += "# one loop counter-clockwise, then one clockwise\n";
  csv += measuredPathToCsv(path);
  writeResult(a.out, csv);
  std::fprintf(stderr,
               "simulate circular: %zu points (%d CCW, then %d CW), R %s mm, squareness %s deg, noise %s mm, "
               "seed %llu\n",
               path.size(), o.pointsPerLoop, o.pointsPerLoop, g(o.radiusMm).c_str(),
               g(o.errors.squarenessDeg()).c_str(), g(o.noiseMm).c_str(),
               static_cast<unsigned long long>(o.seed));
  return 0;
}

/// Least-squares circle (Kasa's algebraic fit, x^2 + y^2 = 2 cx x + 2 cy y + c, solved by QR):
/// returns (cx, cy, r).
Eigen::Vector3d fitCircle(const std::vector<Eigen::Vector2d>& pts) {
  Eigen::MatrixXd A(static_cast<Eigen::Index>(pts.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    A(k, 0) = 2.0 * pts[i].x();
    A(k, 1) = 2.0 * pts[i].y();
    A(k, 2) = 1.0;
    b(k) = pts[i].squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  return {s(0), s(1), std::sqrt(s(2) + s(0) * s(0) + s(1) * s(1))};
}

/// Bore i (1-based) is the CCW loop of the circular test run through the machine with its own noise
/// seed; the tool radius error of the part, e_i = N(0, scatter^2) + drift (i - 1), widens the bore:
/// diameter_i = 2 (r_i + e_i), r_i the least-squares circle radius of the measured loop. Every draw
/// comes from Rng(seed), so the series is deterministic by seed.
int runBores(const BoresArgs& a) {
  const CircularSimOptions o = circularOptions(a.machine);
  std::vector<Eigen::Vector2d> loop = circularTestCommands(o);
  loop.resize(static_cast<std::size_t>(o.pointsPerLoop));
  Rng rng(o.seed);
  CsvWriter w;
  w.row({"part", "diameter_mm", "centre_x_mm", "centre_y_mm"});
  double sum = 0.0;
  for (int i = 1; i <= a.parts; ++i) {
    const std::uint64_t noiseSeed = rng.next();
    const double toolError = rng.normal(0.0, a.scatter) + a.drift * (i - 1);
    const Eigen::Vector3d c = fitCircle(simulateMachine(o.errors, loop, o.noiseMm, noiseSeed));
    const double d = 2.0 * (c(2) + toolError);
    sum += d;
    w.row({std::to_string(i), CsvWriter::formatNumber(d, 12), CsvWriter::formatNumber(c(0), 9),
           CsvWriter::formatNumber(c(1), 9)});
  }
  std::string csv = circularHeader("bores", o);
  CsvWriter note;
  note.comment("bores: " + std::to_string(a.parts) + " parts, tool radius scatter " + g(a.scatter) +
               " mm (1 sigma), drift " + g(a.drift) +
               " mm per part; diameter = 2 (least-squares radius + "
               "tool radius error)");
  csv += note.text() + w.text();
  writeResult(a.machine.out, csv);
  std::fprintf(stderr, "simulate bores: %d parts, nominal diameter %s mm, mean %s mm, seed %llu\n", a.parts,
               g(2.0 * o.radiusMm).c_str(), g(sum / a.parts, "%.7g").c_str(),
               static_cast<unsigned long long>(o.seed));
  return 0;
}

void addMachineOptions(CLI::App* sub, CircularArgs& a) {
  sub->add_option("--radius", a.radius, "Radius of the test circle, mm")
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  sub->add_option("--centre", a.centre, "Centre of the circle X,Y, mm")
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::Range(-1e6, 1e6))
      ->capture_default_str();
  sub->add_option("--points", a.points, "Points per loop")
      ->check(CLI::Range(3, 1000000))
      ->capture_default_str();
  sub->add_option("--start-angle", a.startAngle, "Angle of the first point, deg")
      ->check(CLI::Range(-360.0, 360.0))
      ->capture_default_str();
  const ActuatorErrors2 d = CircularSimOptions::defaultErrors();
  sub->add_option("--origin", a.origin,
                  "Actuator origin error X,Y, mm (where the tool is at command 0). Default: " +
                      g(d.originMm.x()) + "," + g(d.originMm.y()))
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::Range(-1e3, 1e3));
  sub->add_option("--x-angle", a.xAngle, "Orientation error of the X actuator, deg (CCW positive)")
      ->check(CLI::Range(-ActuatorErrors2::kMaxAngleDeg, ActuatorErrors2::kMaxAngleDeg))
      ->capture_default_str();
  sub->add_option("--y-angle", a.yAngle, "Orientation error of the Y actuator, deg (CCW positive)")
      ->check(CLI::Range(-ActuatorErrors2::kMaxAngleDeg, ActuatorErrors2::kMaxAngleDeg))
      ->capture_default_str();
  sub->add_option("--noise", a.noise, "Measuring noise, mm (1 sigma per coordinate)")
      ->check(CLI::Range(0.0, 1e3))
      ->capture_default_str();
  addSeed(sub, a.seed);
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
  addCsvOptions(id);
  addOut(id, a->out);
  id->callback([a] { selectRunner([a]() -> int { return runIdentify(*a); }); });

  auto b = std::make_shared<CompensateArgs>();
  auto* comp = kin->add_subcommand("compensate", "Compensated references for a nominal path");
  existingFile(comp->add_option("--errors", b->errors, "Errors (JSON written by identify)")->required());
  existingFile(comp->add_option("--path", b->path, "Nominal path (CSV x_mm,y_mm)")->required());
  addCsvOptions(comp);
  comp->add_option("--out", b->out,
                   "Compensated references (CSV x_cmd_mm,y_cmd_mm; atomic). Default: stdout");
  comp->add_option("--gcode", b->gcode, "Also write the references as G-code (G01 blocks)");
  comp->add_option("--step-nc", b->stepNc, "Also write the references as a STEP-NC Part 21 file");
  comp->add_option("--feed", b->feed, "Feed of the G-code, mm/min")
      ->check(positiveNumber())
      ->capture_default_str();
  comp->callback([b] { selectRunner([b]() -> int { return runCompensate(*b); }); });
}

void registerSimulateKinematicCommands(CLI::App& simulate) {
  auto a = std::make_shared<CircularArgs>();
  auto* circ = simulate.add_subcommand(
      "circular",
      "A circular test on a Cartesian machine with actuator errors: one loop CCW, then one CW "
      "(CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)");
  addMachineOptions(circ, *a);
  circ->add_option("--out", a->out, "Circular test (CSV; written atomically). Default: stdout");
  circ->callback([a] { selectRunner([a]() -> int { return runCircular(*a); }); });

  auto b = std::make_shared<BoresArgs>();
  b->machine.radius = 50.0;
  b->machine.points = 90;
  auto* bores = simulate.add_subcommand(
      "bores",
      "An SPC series: diameters of bores circle-interpolated on that machine, with tool radius scatter and "
      "drift (CSV part,diameter_mm,centre_x_mm,centre_y_mm)");
  addMachineOptions(bores, b->machine);
  bores->add_option("--parts", b->parts, "Bores (parts) in the series")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  bores->add_option("--scatter", b->scatter, "Tool radius error from part to part, mm (1 sigma)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  bores->add_option("--drift", b->drift, "Tool radius drift per part (e.g. wear), mm")
      ->check(CLI::Range(-1.0, 1.0))
      ->capture_default_str();
  bores->add_option("--out", b->machine.out, "Bore series (CSV; written atomically). Default: stdout");
  bores->callback([b] { selectRunner([b]() -> int { return runBores(*b); }); });
}

}  // namespace metrofit::cli
