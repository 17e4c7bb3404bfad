// metrofit-cli match: posture matching and 5-axis machine adjustment (docs/file-formats.md#match-result).
//
//   match --data P.csv|HOLES.txt [--tolerance T] [--method sade|ga-simplex|closed-form|minimax] [--per-point
//   F]
//   [--allow-scale]
//         [--machine xfyzba|ac-table|bc-table|head-table] [--machine-def M.json] [--lock rx,ry,...]
//         [--reference ID,ID,ID] [--seed N] [--out F] [--remeasure [--remeasure-noise MM]]
//         [--frame heidenhain|siemens|fanuc --frame-out F [--frame-decimals N]]
//         [--nominal-element E [--nominal-radius R] [--nominal-criterion C] [--nominal-robust] [--inner]]
//         [--nominal-reference F2 [--pair id|order]]   (--data of measured points only;
//         core/project/nominals.h)
//   match --cad PART.stl --data POINTS.csv [--method closed-form|minimax] [--lock ...] [--tolerance T]
//         [--allow-scale] [--per-point F] [--machine ...] [--frame ...] [--out F]
//
// --cad matches measured points only (POINTS.csv: id,px,py,pz or id,x_mm,y_mm,z_mm) to the surface of
// an STL part (core/matching/cad_match.h: closest points on the mesh, point-to-plane least squares or
// minimax with the DOF locks, repeated until the posture stops changing); the JSON adds "cad": {file,
// triangles, max_distance_mm, fit}. The method defaults to closed-form (least squares); sade and
// ga-simplex need nominal point pairs and are refused, as are --reference and --remeasure.
//
// --frame writes the posture as a controller frame (core/machine/controller_frame.h: HEIDENHAIN
// datum shift + PLANE SPATIAL, SINUMERIK TRANS + AROT, FANUC G68.2 Euler angles) to --frame-out and
// adds "frame": {"format", "file", "angles_deg"} to the JSON.
//
// --remeasure runs the remeasure loop of Step 7 on a simulated cell whose part is where the probe
// found it (core/matching/remeasure.h partAsMeasured) and adds "remeasure" (remeasure.h toJson): the
// rounds, the true remaining error and the outcome. A loop that fails (form_error, beyond_travel,
// not_converged) is a result, not an error: exit 0, the summary line says FAILED.
//
// Writes the JSON of docs/file-formats.md#match-result (core/matching/matching.h toJson) plus "machine": the
// adjustment values of the chosen topology (core/machine/machine.h) and its definition. One summary line on
// stderr.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/geometry/mesh_search.h"
#include "core/geometry/point_table.h"
#include "core/geometry/stl.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/machine/controller_frame.h"
#include "core/machine/machine.h"
#include "core/matching/cad_match.h"
#include "core/matching/hole_table.h"
#include "core/matching/matching.h"
#include "core/matching/probe_points.h"
#include "core/matching/remeasure.h"
#include "core/project/nominals.h"
#include "core/project/project.h"
#include "core/study/study_settings.h"

namespace metrofit::cli {
namespace {

/// The defaults of the study's settings (core/study/study_settings.h MatchingSettings): what a project's
/// matching study without these keys uses, so the CLI, the page and the report agree.
struct MatchArgs {
  std::string data, method = matching::toString(MatchingSettings{}.method), machine = "xfyzba", machineDef,
                    lock, reference, out, frame, frameOut, perPoint, cad;
  /// Nominals for a file of measured points only (core/project/nominals.h).
  NominalSource nominals;
  std::string nominalReferenceFile;
  int frameDecimals = MatchingSettings{}.frameDecimals;
  int part = 0;  ///< a QIF file of several measured parts: the part (1-based)
  std::uint64_t seed = MatchingSettings{}.seed;
  double tolerance = MatchingSettings{}.toleranceMm, remeasureNoise = 0.006;
  bool allowScale = MatchingSettings{}.allowScale, remeasure = false;
};

std::string fmt(double v) {
  if (v == 0.0) v = 0.0;  // no "-0" in the summary line
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

machine::MachineDefinition machineFor(const MatchArgs& a, bool machineGiven) {
  const machine::Topology topology = machine::parseTopology(a.machine, "--machine");
  if (a.machineDef.empty()) return machine::MachineDefinition::preset(topology);
  nlohmann::json j = readJsonFile(a.machineDef);
  if (j.is_object() && j.value("format", "") == "metrofit-project") {
    // A project: its matching study's machine (the one the GUI's Machine dialog edits).
    Project p;
    if (j.contains("studies") && j["studies"].is_object()) p.studies = j["studies"];
    machine::MachineDefinition fromProject;
    if (!matchingMachine(p, &fromProject, a.machineDef))
      throw ValidationError(ErrorContext{a.machineDef, 0, 0, "studies.matching.machine"},
                            "the project defines no machine (Posture matching › Machine… in the GUI)");
    j = fromProject.toJson();
  }
  machine::MachineDefinition def = machine::MachineDefinition::fromJson(j, a.machineDef);
  if (!j.is_object() || !j.contains("topology")) {
    // The file holds geometry only: its values on top of the --machine preset.
    nlohmann::json merged = machine::MachineDefinition::preset(topology).toJson();
    merged.update(j);
    def = machine::MachineDefinition::fromJson(merged, a.machineDef);
  } else if (machineGiven && def.topology != topology) {
    throw OptionsError(ErrorContext{{}, 0, 0, "--machine"}, "'" + a.machine + "' contradicts the topology '" +
                                                                machine::topologyName(def.topology) +
                                                                "' of " + a.machineDef);
  }
  return def;
}

/// --frame: writes the posture as a controller frame and adds "frame" to the JSON.
void writeFrame(const MatchArgs& a, const matching::Pose& pose, nlohmann::json& j) {
  const machine::FrameFormat ff = machine::parseFrameFormat(a.frame, "--frame");
  machine::FrameOptions fo;
  fo.decimals = a.frameDecimals;
  fo.title = a.data;
  // The TNC lists a program under its file name: BEGIN PGM takes the name of --frame-out, made valid.
  fo.programName = machine::frameProgramName(a.frameOut);
  writeFileAtomic(a.frameOut, machine::writeControllerFrame(pose.rotation, pose.translation, ff, fo));
  const auto angles = ff == machine::FrameFormat::Fanuc ? machine::eulerZxzAnglesDeg(pose.rotation)
                                                        : machine::spatialAnglesDeg(pose.rotation);
  j["frame"] = {{"format", a.frame},
                {"file", a.frameOut},
                {"angles_deg", {angles[0], angles[1], angles[2]}},
                {"angles", ff == machine::FrameFormat::Fanuc        ? "I,J,K: Rz(I) Rx(J) Rz(K)"
                           : ff == machine::FrameFormat::Heidenhain ? "SPA,SPB,SPC: Rz(SPC) Ry(SPB) Rx(SPA)"
                                                                    : "X,Y,Z: Rz(Z) Ry(Y) Rx(X)"}};
}

/// match --cad: measured points against an STL part (core/matching/cad_match.h).
int runCadMatch(const MatchArgs& a, bool machineGiven, bool methodGiven) {
  using namespace matching;
  if (!a.reference.empty())
    throw OptionsError(ErrorContext{{}, 0, 0, "--reference"},
                       "does not apply with --cad (there is no rough matching of point pairs)");
  if (a.remeasure) throw OptionsError(ErrorContext{{}, 0, 0, "--remeasure"}, "is not available with --cad");
  CadMatchOptions o;
  o.method = methodGiven ? parseMatchMethod(a.method, "--method") : MatchMethod::ClosedForm;
  o.toleranceMm = a.tolerance;
  o.allowScale = a.allowScale;
  o.locks = DofLocks::parse(a.lock, "--lock");
  {
    std::string why;
    if (!o.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "--method"}, why);
  }
  const ProbePointSet points = readMeasuredPoints(a.data, csvOptions());
  const geometry::MeshSearch cad(geometry::readStl(a.cad));
  const machine::MachineDefinition def = machineFor(a, machineGiven);

  const CadMatchResult r = [&] {
    TerminalProgress progress([](const IterationSummary& s) {
      return "match --cad: iteration " + std::to_string(s.iteration) + ", " + fmt(s.best) + " mm";
    });
    return matchToCad(points, cad, o, progress.observer());
  }();

  const machine::Adjustment adj =
      machine::adjustmentFor(def, r.match.pose.rotation, r.match.pose.translation);
  nlohmann::json j = toJson(r);
  nlohmann::json m = machine::adjustmentToJson(adj);
  m["definition"] = def.toJson();
  j["machine"] = std::move(m);
  j["data"] = a.data;
  if (!a.frame.empty()) writeFrame(a, r.match.pose, j);
  if (!a.perPoint.empty()) writeFileAtomic(a.perPoint, perPointCsv(r.match.after, r.after));
  writeResult(a.out, dumpJson(j));

  const auto names = machine::rotaryAxisNames(def.topology);
  std::string line = "match: " + std::string(toString(o.method)) + " to " + r.cadSource + " (" +
                     std::to_string(r.triangles) + " triangles) on " + std::to_string(points.points.size()) +
                     " points of " + a.data + ": rmse " + fmt(r.match.after.overall.rmseMm) +
                     " mm, max |dev| " + fmt(r.match.after.overall.maxAbsMm) + " mm, out of tolerance " +
                     std::to_string(r.match.before.overall.outOfTolerance) + " -> " +
                     std::to_string(r.match.after.overall.outOfTolerance) + " (+-" + fmt(o.toleranceMm) +
                     " mm); " + r.match.run.message + "; " + machine::topologyName(def.topology) + " S" +
                     names[0] + " " + fmt(adj.rotaryDeg[0]) + " deg, S" + names[1] + " " +
                     fmt(adj.rotaryDeg[1]) + " deg";
  if (!adj.withinTravel) line += " (OUTSIDE TRAVEL: " + adj.travelMessage + ")";
  if (!a.frame.empty()) line += "; " + a.frame + " frame -> " + a.frameOut;
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

int runMatch(const MatchArgs& a, bool machineGiven, bool methodGiven) {
  using namespace matching;
  if (!a.frame.empty() && a.frameOut.empty())
    throw OptionsError(ErrorContext{{}, 0, 0, "--frame"}, "needs --frame-out FILE");
  if (a.frame.empty() && !a.frameOut.empty())
    throw OptionsError(ErrorContext{{}, 0, 0, "--frame-out"}, "needs --frame heidenhain|siemens|fanuc");
  if (!a.cad.empty()) {
    if (!a.nominals.element.empty() || !a.nominalReferenceFile.empty())
      throw OptionsError(
          ErrorContext{{}, 0, 0, "--cad"},
          "the CAD part is the nominal: --nominal-element and --nominal-reference do not apply");
    return runCadMatch(a, machineGiven, methodGiven);
  }
  const ProbePointSet set = [&] {
    if (a.nominals.element.empty() && a.nominalReferenceFile.empty()) {
      if (!(a.nominals == NominalSource{}))
        throw OptionsError(
            ErrorContext{{}, 0, 0, "--nominal-element"},
            "is needed with --nominal-radius, --nominal-criterion, --nominal-robust, --inner or "
            "--pair (or --nominal-reference)");
      return readProbePointsAnyFormat(a.data, 1, csvOptions(), a.part);
    }
    // Measured points only: the nominals from an element fitted to them or from a second measurement.
    NominalSource n = a.nominals;
    n.from = a.nominalReferenceFile.empty() ? "element" : "reference";
    std::optional<geometry::PointSet> reference;
    if (!a.nominalReferenceFile.empty()) {
      n.reference = a.nominalReferenceFile;
      reference = geometry::readPointTable(a.nominalReferenceFile, csvOptions());
    }
    return nominalsFor(geometry::readPointTable(a.data, csvOptions()), n, reference ? &*reference : nullptr)
        .set;
  }();
  MatchOptions o;
  o.method = parseMatchMethod(a.method, "--method");
  o.toleranceMm = a.tolerance;
  o.allowScale = a.allowScale;
  o.locks = DofLocks::parse(a.lock, "--lock");
  o.seed = a.seed;
  if (!a.reference.empty()) {
    o.referenceIds = splitList(a.reference);
    if (o.referenceIds.size() != 3) {
      throw OptionsError(
          ErrorContext{{}, 0, 0, "--reference"},
          "takes exactly three point ids, " + std::to_string(o.referenceIds.size()) + " given");
    }
  }
  const machine::MachineDefinition def = machineFor(a, machineGiven);

  // Progress on a terminal only (the run takes milliseconds on typical sets, longer on large ones).
  const MatchResult r = [&] {
    TerminalProgress progress([](const IterationSummary& s) {
      return "match: iteration " + std::to_string(s.iteration) + ", best " + fmt(s.best) + " mm";
    });
    return matchPosture(set, o, progress.observer());
  }();

  const machine::Adjustment adj = machine::adjustmentFor(def, r.pose.rotation, r.pose.translation);
  nlohmann::json j = toJson(r, set);
  nlohmann::json m = machine::adjustmentToJson(adj);
  m["definition"] = def.toJson();
  j["machine"] = std::move(m);
  j["data"] = a.data;
  if (!a.frame.empty()) writeFrame(a, r.pose, j);
  std::optional<RemeasureResult> loop;
  if (a.remeasure) {
    RemeasureOptions ro;
    ro.match = o;
    ro.machine = def;
    loop = remeasureLoop(simulateCell(partAsMeasured(set), a.remeasureNoise, a.seed), ro);
    nlohmann::json lj = toJson(*loop);
    lj["noise_mm"] = a.remeasureNoise;
    j["remeasure"] = std::move(lj);
  }
  if (!a.perPoint.empty()) writeFileAtomic(a.perPoint, perPointCsv(r.after, set));
  writeResult(a.out, dumpJson(j));

  const auto names = machine::rotaryAxisNames(def.topology);
  std::string line = "match: " + std::string(toString(r.method)) + " on " +
                     std::to_string(set.points.size()) + " points of " + a.data + ": rmse " +
                     fmt(r.after.overall.rmseMm) + " mm, max |dev| " + fmt(r.after.overall.maxAbsMm) +
                     " mm, out of tolerance " + std::to_string(r.before.overall.outOfTolerance) + " -> " +
                     std::to_string(r.after.overall.outOfTolerance) + " (+-" + fmt(o.toleranceMm) + " mm); " +
                     machine::topologyName(def.topology) + " S" + names[0] + " " + fmt(adj.rotaryDeg[0]) +
                     " deg, S" + names[1] + " " + fmt(adj.rotaryDeg[1]) + " deg";
  if (!adj.withinTravel) line += " (OUTSIDE TRAVEL: " + adj.travelMessage + ")";
  if (!a.frame.empty()) line += "; " + a.frame + " frame -> " + a.frameOut;
  if (loop) {
    line += "; remeasure: " + loop->run.message;
    if (const ToleranceEvaluation* t = loop->trueRemaining())
      line += " (true remaining max |dev| " + fmt(t->overall.maxAbsMm) + " mm)";
  }
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

}  // namespace

void registerMatchCommand(CLI::App& app) {
  auto a = std::make_shared<MatchArgs>();
  auto* sub = app.add_subcommand("match", "Workpiece posture matching and 5-axis machine adjustment");
  existingFile(
      sub->add_option("--data", a->data,
                      "Probe points: CSV (id,surface,qx,qy,qz,nx,ny,nz,px,py,pz), a PC-DMIS hole-table "
                      "report, a Zeiss Calypso _fet table or a QIF 3 Results file; with --cad measured "
                      "points only (id,px,py,pz or id,x_mm,y_mm,z_mm)")
          ->required());
  sub->add_option("--part", a->part,
                  "A QIF file of several measured parts: the part to match, by its number (1 = the first "
                  "MeasurementResults)")
      ->check(CLI::Range(1, 1000000));
  existingFile(sub->add_option(
      "--cad", a->cad,
      "CAD nominal: an STL part (ASCII or binary, mm); the measured points are matched to its surface"));
  sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")
      ->check(positiveNumber())
      ->capture_default_str();
  auto* methodOpt = sub->add_option("--method", a->method,
                                    "sade|ga-simplex|closed-form|minimax (with --cad: closed-form|minimax)")
                        ->check(CLI::IsMember({"sade", "ga-simplex", "closed-form", "minimax"}))
                        ->capture_default_str();
  sub->add_flag("--allow-scale", a->allowScale, "Fit an isotropic scale too");
  auto* machineOpt =
      sub->add_option("--machine", a->machine, "Machine topology: xfyzba|ac-table|bc-table|head-table")
          ->check(CLI::IsMember(machine::topologyNames()))
          ->capture_default_str();
  existingFile(
      sub->add_option("--machine-def", a->machineDef,
                      "Machine definition (JSON: pivot lengths, travel; or a .metrofit project's machine)"));
  sub->add_option("--lock", a->lock, "Degrees of freedom held at 0: any of rx,ry,rz,x,y,z");
  sub->add_option("--reference", a->reference, "Three point ids for the rough matching (default: automatic)");
  sub->add_flag("--remeasure", a->remeasure,
                "Also run the remeasure loop on a simulated cell holding the measured part");
  sub->add_option("--remeasure-noise", a->remeasureNoise, "Probing noise of the remeasure loop, mm (1 sigma)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  sub->add_option("--frame", a->frame,
                  "Also write the posture as a controller frame: heidenhain|siemens|fanuc")
      ->check(CLI::IsMember(machine::frameFormatNames()));
  sub->add_option("--frame-out", a->frameOut, "File for --frame (written atomically)");
  sub->add_option(
      "--per-point", a->perPoint,
      "Also write each point's deviation after the fit as CSV: id,surface,d_mm (along the nominal "
      "normal),dx_mm,dy_mm,dz_mm (written atomically)");
  sub->add_option("--frame-decimals", a->frameDecimals, "Decimals of the --frame values (mm and deg)")
      ->check(CLI::Range(0, 12))
      ->capture_default_str();
  sub->add_option(
      "--nominal-element", a->nominals.element,
      "--data holds measured points only (id,x,y,z): their nominals are their feet on this element "
      "fitted to them (plane|line|circle|sphere|cylinder|cone); with --nominal-reference the "
      "element whose normals the reference points take");
  sub->add_option("--nominal-radius", a->nominals.radiusMm,
                  "The element's fixed radius in mm (sphere, circle, "
                  "cylinder)");
  sub->add_option("--nominal-criterion", a->nominals.criterion,
                  "How the element is fitted: ls | minimax [ls]")
      ->check(CLI::IsMember({"ls", "minimax"}));
  sub->add_flag("--nominal-robust", a->nominals.robust, "Leave stray points out of the element's fit");
  sub->add_flag("--inner", a->nominals.inner,
                "The element is a bore or hole (the material is outside it): normals point inwards");
  existingFile(
      sub->add_option("--nominal-reference", a->nominalReferenceFile,
                      "--data holds measured points only: their nominals are the same points of this "
                      "second measurement of the part (id,x,y,z)"));
  sub->add_option("--pair", a->nominals.pair, "How points meet their reference points: id | order [id]")
      ->check(CLI::IsMember({"id", "order"}));
  addSeed(sub, a->seed);
  addCsvOptions(sub);
  addOut(sub, a->out);
  sub->callback([a, machineOpt, methodOpt] {
    const bool machineGiven = machineOpt->count() > 0, methodGiven = methodOpt->count() > 0;
    selectRunner([a, machineGiven, methodGiven]() -> int { return runMatch(*a, machineGiven, methodGiven); });
  });
}

}  // namespace metrofit::cli
