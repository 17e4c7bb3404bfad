// metrofit-cli kinematic identify|compensate (docs/file-formats.md#kinematic-identify-result) and the
// kinematic simulators.
//   identify   --data C.csv [--out E.json]
//       the JSON also has "iso230_4": the ISO 230-4 results of the test (core/kinematics/iso230_4.h)
//       and "causes": the ballbar breakdown (core/kinematics/ballbar.h; null when the commands are not
//       one full circle); [--screw-pitch P] adds the cyclic errors of that pitch
//   circular   --data C.csv [--out R.json]
//       the ISO 230-4 results (G, H, F per direction) of a circular test in either form: x/y or the
//       radial-only form a ballbar exports (angle_deg, deviation_um | deviation_mm, ...)
//   positioning --data F [--compensation fanuc|siemens|heidenhain|csv --out-table T] [--axis X] [--out
//   R.json]
//       the ISO 230-2:2014 results of a bidirectional positioning test (core/kinematics/iso230_2.h) and
//       the pitch-error compensation table (minus the mean bidirectional deviation) in a control's form
//   identify3  --xy C1.csv --yz C2.csv --zx C3.csv [--out E3.json]
//       the three-axis actuator errors from circular tests in three planes (identification3.h)
//   compensate3 --errors3 E3.json --path N.csv [--out F.csv]
//       Eq. 15 in three axes: references x_cmd_mm,y_cmd_mm,z_cmd_mm for a nominal path x_mm,y_mm,z_mm
//   from-spc   --x-data X.csv --y-data Y.csv [--position-column C] [--deviation-column C]
//              [--x-nominal-y Y0] [--y-nominal-x X0] [--subgroup N] [--coverage K]
//              [--path N.csv --references F.csv] [--dfq F.dfq] [--out E.json]
//       the SPC regression offset angles of two edges -> actuator errors -> compensation
//       (spc_actuator.h); E.json is readable by `compensate --errors`
//   compensate --errors E.json --path N.csv [--out F.csv] [--gcode F.nc] [--step-nc F.p21]
//   simulate circular [--radius R] [--centre X,Y] [--points N] [--start-angle D] [--origin X,Y]
//                     [--x-angle A] [--y-angle B] [--noise S] [--seed N] [--out C.csv]
//       a circular test (core/sim/circular_sim.h): one loop CCW, then one CW, through the machine
//       with the given actuator errors plus noise; CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm.
//   simulate circular --plane yz|zx [--errors3 E3.json] (or --plane xy --errors3): the same test in
//                     a plane of the three-axis machine (identification3.h), the plane's columns
//   simulate edge --axis x|y [--start S] [--length L] [--points N] [--nominal-cross C] [machine
//                 options] [--out F.csv]: an edge along one axis, CSV position_mm,deviation_mm
//   simulate bores [--parts N] [same machine options] [--scatter S] [--drift D] [--out B.csv]
//       an SPC series: the diameters of N bores circle-interpolated on that machine (see runBores).
#include <CLI/CLI.hpp>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/kinematics/ballbar.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/export.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/identification3.h"
#include "core/kinematics/iso230_2.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"
#include "core/kinematics/spc_actuator.h"
#include "core/sim/circular_sim.h"
#include "core/spc/control_chart.h"
#include "core/study/study_settings.h"

namespace metrofit::cli {
namespace {

struct IdentifyArgs {
  std::string data, out;
  double screwPitchMm = BallbarOptions{}.screwPitchMm;
};

struct CompensateArgs {
  std::string errors, path, out, gcode, stepNc;
  double feed = GcodeOptions{}.feedMmPerMin;
};

std::string g(double v, const char* format = "%.6g") {
  char buf[48];
  metrofit::c_snprintf(buf, sizeof buf, format, v);
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
  nlohmann::json j = identifyResultToJson(r);
  j["iso230_4"] = iso230ResultToJson(evaluateIso230_4(circularTraceOf(path)));
  // The ballbar breakdown of a circular test; any other path (or one the breakdown cannot use) gets
  // null and the reason in the summary, so identify still works on every path it worked on before.
  BallbarOptions ballbar;
  ballbar.screwPitchMm = a.screwPitchMm;
  std::string causes;
  j["causes"] = nullptr;
  try {
    const BallbarBreakdown b = ballbarBreakdown(path, ballbar);
    j["causes"] = ballbarCausesToJson(b);
    if (!b.causes.empty()) {
      const BallbarCause& top = b.causes.front();
      causes = ", top cause " + top.name + " " + g(top.valueUm, "%.3g") + " um (" +
               g(top.share * 100.0, "%.3g") + " %)";
    }
  } catch (const ValidationError& e) {
    causes = ", " + e.detail();  // "no ballbar breakdown: <why>"
  }
  writeResult(a.out, dumpJson(j));
  const ActuatorErrors2& e = r.errors;
  std::fprintf(
      stderr,
      "kinematic identify: %zu points, origin (%s, %s) mm, a = %s deg, b = %s deg, squareness %s deg "
      "(+-%s), rmse %s mm, %ld iteration%s (%s)%s\n",
      r.points, g(e.originMm.x()).c_str(), g(e.originMm.y()).c_str(), g(e.xAxisAngleDeg).c_str(),
      g(e.yAxisAngleDeg).c_str(), g(e.squarenessDeg()).c_str(), g(r.squarenessStdErrDeg, "%.2g").c_str(),
      g(r.rmseMm, "%.3g").c_str(), r.run.iterations, r.run.iterations == 1 ? "" : "s",
      toString(r.run.termination), causes.c_str());
  return 0;
}

std::string isoSummary(const Iso230Result& iso) {
  std::string out;
  for (const Iso230Direction& d : iso.directions) {
    out += std::string(out.empty() ? "" : "; ") + (d.counterClockwise ? "CCW" : "CW") + " G " +
           g(d.circularDeviationMm * 1000.0, "%.3g") + " um, F " +
           g(d.radialDeviationMinMm * 1000.0, "%.3g") + ".." + g(d.radialDeviationMaxMm * 1000.0, "%.3g") +
           " um";
  }
  if (iso.circularHysteresisMm) out += "; H " + g(*iso.circularHysteresisMm * 1000.0, "%.3g") + " um";
  return out;
}

int runCircular(const IdentifyArgs& a) {
  const CircularTrace trace = readCircularTrace(a.data, csvOptions());
  const Iso230Result iso = evaluateIso230_4(trace);
  if (iso.directions.empty()) {
    throw ValidationError(ErrorContext{a.data, 0, 0, {}},
                          "no direction of the test has 3 points on a circle: no ISO 230-4 results");
  }
  nlohmann::json j;
  j["form"] = trace.radialOnly ? "radial" : "xy";
  j["points"] = trace.size();
  j["iso230_4"] = iso230ResultToJson(iso);
  writeResult(a.out, dumpJson(j));
  std::fprintf(stderr, "kinematic circular: %zu points (%s form): %s\n", trace.size(),
               trace.radialOnly ? "radial" : "x/y", isoSummary(iso).c_str());
  return 0;
}

struct PositioningArgs {
  std::string data, out, compensation, outTable, axis = "X";
};

int runPositioning(const PositioningArgs& a) {
  if (a.compensation.empty() != a.outTable.empty()) {
    throw OptionsError(ErrorContext{{}, 0, 0, a.compensation.empty() ? "--compensation" : "--out-table"},
                       "--compensation and --out-table go together");
  }
  PitchTableOptions table;
  if (a.axis.size() != 1) {
    throw OptionsError(ErrorContext{{}, 0, 0, "--axis"}, "'" + a.axis + "' is not one axis letter");
  }
  table.axis = a.axis[0];
  requireValid(table, "--axis");
  std::optional<PitchTableFormat> format;
  if (!a.compensation.empty()) format = parsePitchTableFormat(a.compensation);
  const PositioningTest test = readPositioningTest(a.data, csvOptions());
  const PositioningResult r = evaluateIso230_2(test);
  std::string tableText;
  if (format) tableText = pitchCompensationTable(r, *format, table);
  const std::string json = dumpJson(iso230_2ToJson(r));
  if (format) writeFileAtomic(a.outTable, tableText);
  writeResult(a.out, json);
  std::fprintf(
      stderr,
      "kinematic positioning: %zu targets, %zu approaches: A %s um, R %s um, E %s um, M %s um, B %s um%s\n",
      r.targets.size(), test.samples.size(), g(r.A * 1000.0, "%.4g").c_str(), g(r.R * 1000.0, "%.4g").c_str(),
      g(r.E * 1000.0, "%.4g").c_str(), g(r.M * 1000.0, "%.4g").c_str(), g(r.B * 1000.0, "%.4g").c_str(),
      format ? (", compensation table (" + a.compensation + ") " + a.outTable).c_str() : "");
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

struct Identify3Args {
  std::string xy, yz, zx, out;
};

int runIdentify3(const Identify3Args& a) {
  const std::array<MeasuredPath, 3> tests{readPlanePath(a.xy, TestPlane::XY, csvOptions()),
                                          readPlanePath(a.yz, TestPlane::YZ, csvOptions()),
                                          readPlanePath(a.zx, TestPlane::ZX, csvOptions())};
  const Identify3Result r = identifyActuatorErrors3(tests);
  if (r.run.termination == Termination::Failed) {
    throw std::runtime_error("three-plane identification failed: " + r.run.message);
  }
  writeResult(a.out, dumpJson(identify3ResultToJson(r)));
  const ActuatorErrors3& e = r.errors;
  std::fprintf(stderr,
               "kinematic identify3: %zu points in 3 planes, origin (%s, %s, %s) mm, squareness xy %s deg, "
               "yz %s deg, zx %s deg, rmse %s mm, %ld iteration%s (%s)\n",
               r.points, g(e.originMm.x()).c_str(), g(e.originMm.y()).c_str(), g(e.originMm.z()).c_str(),
               g(e.squarenessDeg(TestPlane::XY)).c_str(), g(e.squarenessDeg(TestPlane::YZ)).c_str(),
               g(e.squarenessDeg(TestPlane::ZX)).c_str(), g(r.rmseMm, "%.3g").c_str(), r.run.iterations,
               r.run.iterations == 1 ? "" : "s", toString(r.run.termination));
  return 0;
}

struct Compensate3Args {
  std::string errors3, path, out;
};

int runCompensate3(const Compensate3Args& a) {
  const ActuatorErrors3 errors = readActuatorErrors3(a.errors3);
  const std::vector<Eigen::Vector3d> nominal = nominalPath3FromCsv(readCsvFile(a.path, csvOptions()));
  const auto commands = compensatePath3(errors, nominal);
  writeResult(a.out, commandPath3ToCsv(commands));
  double largest = 0.0;
  for (std::size_t i = 0; i < commands.size(); ++i)
    largest = std::max(largest, (commands[i] - nominal[i]).norm());
  std::fprintf(
      stderr,
      "kinematic compensate3: %zu points of %s, largest correction %s mm (squareness xy %s, yz %s, zx %s "
      "deg)\n",
      commands.size(), a.path.c_str(), g(largest, "%.4g").c_str(),
      g(errors.squarenessDeg(TestPlane::XY)).c_str(), g(errors.squarenessDeg(TestPlane::YZ)).c_str(),
      g(errors.squarenessDeg(TestPlane::ZX)).c_str());
  return 0;
}

/// The defaults are the project study's (studies.kinematics.from_spc, KinematicsSettings::FromSpc).
struct FromSpcArgs {
  std::string xData, yData;
  std::string positionColumn = KinematicsSettings::FromSpc{}.positionColumn;
  std::string deviationColumn = KinematicsSettings::FromSpc{}.deviationColumn;
  double xNominalY = KinematicsSettings::FromSpc{}.xNominalY,
         yNominalX = KinematicsSettings::FromSpc{}.yNominalX;
  int subgroup = KinematicsSettings::FromSpc{}.subgroup;
  double coverage = KinematicsSettings::FromSpc{}.coverage;
  std::string path, references, out, dfq;
};

int runFromSpc(const FromSpcArgs& a) {
  if (a.references.empty() != a.path.empty()) {
    throw ValidationError(ErrorContext{{}, 0, 0, a.path.empty() ? "--path" : "--references"},
                          "missing: give --path and --references together (the nominal path and where its "
                          "compensated references go)");
  }
  AxisFeatureSeries xf =
      axisFeatureFromCsv(readFeatureTable(a.xData, csvOptions()), a.positionColumn, a.deviationColumn);
  AxisFeatureSeries yf =
      axisFeatureFromCsv(readFeatureTable(a.yData, csvOptions()), a.positionColumn, a.deviationColumn);
  xf.nominalCrossMm = a.xNominalY;
  yf.nominalCrossMm = a.yNominalX;
  SpcActuatorOptions o;
  o.subgroupSize = a.subgroup;
  o.coverageFactor = a.coverage;
  std::string why;
  if (!o.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "--subgroup"}, why);
  const SpcActuatorResult r = actuatorErrorsFromSpc(xf, yf, o);
  nlohmann::json j = spcActuatorResultToJson(r, xf, yf);

  std::string refs;
  double largest = 0.0;
  if (!a.path.empty()) {
    const NominalPath nominal = readNominalPath(a.path, csvOptions());
    const auto commands =
        r.apply ? compensatePath(CartesianMachine2::fromErrors(r.errors), nominal.points) : nominal.points;
    for (std::size_t i = 0; i < commands.size(); ++i) {
      largest = std::max(largest, (commands[i] - nominal.points[i]).norm());
    }
    refs = commandPathToCsv(commands);
    j["compensation"]["path"] = a.path;
    j["compensation"]["references"] = a.references;
    j["compensation"]["largest_correction_mm"] = largest;
  }
  const std::string dfq =
      a.dfq.empty() ? std::string()
                    : edgesDfq(xf, yf, a.deviationColumn, std::filesystem::path(a.xData).filename().string(),
                               std::filesystem::path(a.yData).filename().string());
  if (!a.references.empty()) writeFileAtomic(a.references, refs);
  if (!a.dfq.empty()) writeFileAtomic(a.dfq, dfq);
  writeResult(a.out, dumpJson(j));
  const ActuatorErrors2& e = r.errors;
  std::fprintf(
      stderr,
      "kinematic from-spc: offset angles X %s deg, Y %s deg -> origin (%s, %s) mm, a = %s deg, b = %s "
      "deg, squareness %s deg; %s\n",
      g(r.x.line.angleDeg).c_str(), g(r.y.line.angleDeg).c_str(), g(e.originMm.x()).c_str(),
      g(e.originMm.y()).c_str(), g(e.xAxisAngleDeg).c_str(), g(e.yAxisAngleDeg).c_str(),
      g(e.squarenessDeg()).c_str(), r.reason.c_str());
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
  std::string plane = "xy";  ///< simulate circular only
  std::string errors3;       ///< simulate circular only: three-axis machine (JSON of identify3)
};

struct EdgeArgs {
  CircularArgs machine;
  std::string axis = "x";
  double start = -100.0, length = 200.0, nominalCross = 0.0;
  int points = 50;
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

int runCircularPlane(const CircularArgs& a) {
  const TestPlane plane = a.plane == "yz" ? TestPlane::YZ : a.plane == "zx" ? TestPlane::ZX : TestPlane::XY;
  const ActuatorErrors3 errors =
      a.errors3.empty() ? ActuatorErrors3::plausible() : readActuatorErrors3(a.errors3);
  const CircularSimOptions o = circularOptions(a);
  const MeasuredPath path = simulatePlaneCircularTest(errors, plane, o);
  CsvWriter w;
  w.comment(std::string("metrofit-cli simulate circular --plane ") + planeName(plane) + ": R " +
            g(o.radiusMm) + " mm about (" + g(o.centreMm.x()) + ", " + g(o.centreMm.y()) +
            ") mm in the plane, " + std::to_string(o.pointsPerLoop) + " points per loop, start " +
            g(o.startAngleDeg) + " deg");
  w.comment("three-axis machine: origin (" + g(errors.originMm.x()) + ", " + g(errors.originMm.y()) + ", " +
            g(errors.originMm.z()) + ") mm, squareness xy " + g(errors.squarenessDeg(TestPlane::XY)) +
            " deg, yz " + g(errors.squarenessDeg(TestPlane::YZ)) + " deg, zx " +
            g(errors.squarenessDeg(TestPlane::ZX)) + " deg; noise " + g(o.noiseMm) +
            " mm (1 sigma per coordinate); seed " + std::to_string(o.seed));
  w.comment("one loop counter-clockwise, then one clockwise");
  writeResult(a.out, w.text() + planePathToCsv(path, plane));
  std::fprintf(
      stderr,
      "simulate circular: %zu points in the %s plane (%d CCW, then %d CW), R %s mm, squareness %s deg, "
      "noise %s mm, seed %llu\n",
      path.size(), planeName(plane), o.pointsPerLoop, o.pointsPerLoop, g(o.radiusMm).c_str(),
      g(errors.squarenessDeg(plane)).c_str(), g(o.noiseMm).c_str(), static_cast<unsigned long long>(o.seed));
  return 0;
}

int runCircular(const CircularArgs& a) {
  if (a.plane != "xy" || !a.errors3.empty()) return runCircularPlane(a);
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

int runEdge(const EdgeArgs& a) {
  const CircularSimOptions m = circularOptions(a.machine);
  EdgeSimOptions o;
  o.axis = a.axis == "y" ? 'y' : 'x';
  o.startMm = a.start;
  o.lengthMm = a.length;
  o.points = a.points;
  o.nominalCrossMm = a.nominalCross;
  o.errors = m.errors;
  o.noiseMm = m.noiseMm;
  o.seed = m.seed;
  requireValid(o, "simulate edge");
  const AxisFeatureSeries f = simulateAxisFeature(o);
  CsvWriter w;
  w.comment(std::string("metrofit-cli simulate edge --axis ") + o.axis + ": " + std::to_string(o.points) +
            " points from " + g(o.startMm) + " mm over " + g(o.lengthMm) +
            " mm at the nominal cross coordinate " + g(o.nominalCrossMm) + " mm");
  w.comment("machine: origin (" + g(o.errors.originMm.x()) + ", " + g(o.errors.originMm.y()) +
            ") mm, x axis " + g(o.errors.xAxisAngleDeg) + " deg, y axis " + g(o.errors.yAxisAngleDeg) +
            " deg; noise " + g(o.noiseMm) + " mm; seed " + std::to_string(o.seed));
  w.comment(
      "position_mm: measured coordinate along the axis; deviation_mm: measured cross coordinate - nominal");
  writeResult(a.machine.out, w.text() + axisFeatureToCsv(f));
  std::fprintf(stderr, "simulate edge: %d points along %c, %s axis angle %s deg, noise %s mm, seed %llu\n",
               o.points, o.axis, o.axis == 'x' ? "x" : "y",
               g(o.axis == 'x' ? o.errors.xAxisAngleDeg : o.errors.yAxisAngleDeg).c_str(),
               g(o.noiseMm).c_str(), static_cast<unsigned long long>(o.seed));
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

/// The machine options; `circle` adds the test circle's (radius, centre, points, start angle).
void addMachineOptions(CLI::App* sub, CircularArgs& a, bool circle = true) {
  if (circle) {
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
  }
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
  id->add_option("--screw-pitch", a->screwPitchMm,
                 "Screw pitch (mm): the ballbar breakdown also fits the cyclic error of each axis with this "
                 "period. Default: no cyclic error")
      ->check(positiveNumber());
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

  auto ci = std::make_shared<IdentifyArgs>();
  auto* circular = kin->add_subcommand(
      "circular",
      "ISO 230-4 results (circular deviation G, hysteresis H, radial deviation F) of a circular test");
  existingFile(
      circular
          ->add_option("--data", ci->data,
                       "Circular test (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, or the radial-only "
                       "form angle_deg,deviation_um)")
          ->required());
  addCsvOptions(circular);
  addOut(circular, ci->out);
  circular->callback([ci] { selectRunner([ci]() -> int { return runCircular(*ci); }); });

  auto pa = std::make_shared<PositioningArgs>();
  auto* pos = kin->add_subcommand("positioning",
                                  "ISO 230-2 accuracy and repeatability of positioning of a linear axis, and "
                                  "its pitch-error compensation "
                                  "table");
  existingFile(
      pos->add_option("--data", pa->data,
                      "Positioning test (CSV target_mm,direction,cycle,deviation_mm|measured_mm, or the "
                      "KEY=value form with TGT_DATA[i], REF_DATA_FWD[i,j], REF_DATA_BWD[i,j])")
          ->required());
  pos->add_option("--compensation", pa->compensation,
                  "Also write the pitch-error compensation table (minus the mean bidirectional deviation) in "
                  "this form: fanuc, siemens, heidenhain, csv")
      ->check(CLI::IsMember({"fanuc", "siemens", "heidenhain", "csv"}));
  pos->add_option("--out-table", pa->outTable, "The compensation table file (atomic)");
  pos->add_option("--axis", pa->axis, "Axis letter of the table (X, Y, Z, U, V, W, A, B, C)")
      ->capture_default_str();
  addCsvOptions(pos);
  addOut(pos, pa->out);
  pos->callback([pa] { selectRunner([pa]() -> int { return runPositioning(*pa); }); });

  auto c = std::make_shared<Identify3Args>();
  auto* id3 = kin->add_subcommand(
      "identify3", "Identify the three-axis actuator errors from circular tests in the XY, YZ and ZX planes");
  existingFile(id3->add_option("--xy", c->xy, "XY circular test (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)")
                   ->required());
  existingFile(id3->add_option("--yz", c->yz, "YZ circular test (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)")
                   ->required());
  existingFile(id3->add_option("--zx", c->zx, "ZX circular test (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)")
                   ->required());
  addCsvOptions(id3);
  addOut(id3, c->out);
  id3->callback([c] { selectRunner([c]() -> int { return runIdentify3(*c); }); });

  auto c3 = std::make_shared<Compensate3Args>();
  auto* comp3 = kin->add_subcommand(
      "compensate3",
      "Compensated references in three axes for a nominal path, from the errors identify3 wrote");
  existingFile(comp3->add_option("--errors3", c3->errors3, "Three-axis errors (JSON written by identify3)")
                   ->required());
  existingFile(comp3->add_option("--path", c3->path, "Nominal path (CSV x_mm,y_mm,z_mm)")->required());
  addCsvOptions(comp3);
  comp3->add_option("--out", c3->out,
                    "Compensated references (CSV x_cmd_mm,y_cmd_mm,z_cmd_mm; atomic). Default: stdout");
  comp3->callback([c3] { selectRunner([c3]() -> int { return runCompensate3(*c3); }); });

  auto d = std::make_shared<FromSpcArgs>();
  auto* fs = kin->add_subcommand(
      "from-spc",
      "Actuator errors from the SPC regression offset angles of an edge along X and one along Y, and their "
      "compensation (IEEE Access paper, kinematic compensation algorithm)");
  existingFile(fs->add_option("--x-data", d->xData, "Edge machined along X (CSV position_mm,deviation_mm)")
                   ->required());
  existingFile(fs->add_option("--y-data", d->yData, "Edge machined along Y (CSV position_mm,deviation_mm)")
                   ->required());
  fs->add_option("--position-column", d->positionColumn, "Column of the measured position along the axis, mm")
      ->capture_default_str();
  fs->add_option("--deviation-column", d->deviationColumn,
                 "Column of the measured deviation across the axis (measured - nominal), mm")
      ->capture_default_str();
  fs->add_option("--x-nominal-y", d->xNominalY, "Nominal Y of the X edge, mm")->capture_default_str();
  fs->add_option("--y-nominal-x", d->yNominalX, "Nominal X of the Y edge, mm")->capture_default_str();
  fs->add_option("--subgroup", d->subgroup, "Subgroup size of the residual X-bar/R chart (2..25)")
      ->check(CLI::Range(kMinSubgroupSize, kMaxSubgroupSize))
      ->capture_default_str();
  fs->add_option("--coverage", d->coverage, "Coverage factor k: a slope or intercept counts beyond +-k se")
      ->check(positiveNumber())
      ->capture_default_str();
  existingFile(fs->add_option("--path", d->path, "Nominal path to compensate (CSV x_mm,y_mm)"));
  fs->add_option("--references", d->references,
                 "Compensated references of --path (CSV x_cmd_mm,y_cmd_mm; atomic)");
  fs->add_option("--dfq", d->dfq,
                 "Also write the two edges' deviations as a Q-DAS DFQ file (two characteristics; atomic)");
  addCsvOptions(fs);
  addOut(fs, d->out);
  fs->callback([d] { selectRunner([d]() -> int { return runFromSpc(*d); }); });
}

void registerSimulateKinematicCommands(CLI::App& simulate) {
  auto a = std::make_shared<CircularArgs>();
  auto* circ = simulate.add_subcommand(
      "circular",
      "A circular test on a Cartesian machine with actuator errors: one loop CCW, then one CW "
      "(CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)");
  addMachineOptions(circ, *a);
  circ->add_option("--plane", a->plane, "Plane of the test on the three-axis machine: xy, yz or zx")
      ->check(CLI::IsMember({"xy", "yz", "zx"}))
      ->capture_default_str();
  existingFile(circ->add_option(
      "--errors3", a->errors3,
      "Three-axis machine (JSON as identify3 writes). Default with --plane yz|zx: a plausible machine"));
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

  auto e = std::make_shared<EdgeArgs>();
  auto* edge = simulate.add_subcommand(
      "edge",
      "An edge machined along X or Y on that machine and measured: the feature series of kinematic from-spc "
      "(CSV position_mm,deviation_mm)");
  addMachineOptions(edge, e->machine, false);
  edge->add_option("--axis", e->axis, "Axis the edge runs along: x or y")
      ->check(CLI::IsMember({"x", "y"}))
      ->capture_default_str();
  edge->add_option("--start", e->start, "Commanded start of the edge along the axis, mm")
      ->check(CLI::Range(-1e6, 1e6))
      ->capture_default_str();
  edge->add_option("--length", e->length, "Length of the edge, mm")
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  edge->add_option("--points", e->points, "Measured points along the edge")
      ->check(CLI::Range(3, 1000000))
      ->capture_default_str();
  edge->add_option("--nominal-cross", e->nominalCross,
                   "Nominal cross coordinate of the edge (Y for x, X for y), mm")
      ->check(CLI::Range(-1e6, 1e6))
      ->capture_default_str();
  edge->add_option("--out", e->machine.out, "Edge series (CSV; written atomically). Default: stdout");
  edge->callback([e] { selectRunner([e]() -> int { return runEdge(*e); }); });
}

}  // namespace metrofit::cli
