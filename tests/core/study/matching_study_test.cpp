// The S-shaped test piece (core/sim/probe_sim.h), the matching study end to end
// (core/study/matching_study.h) and the machine definition in the project file (core/project/project.h).
#include "core/study/matching_study.h"

#include <gtest/gtest.h>

#include <map>

#include "core/common/error.h"
#include "core/project/project.h"
#include "core/sim/probe_sim.h"
#include "testsupport.h"

namespace metrofit::matching {
namespace {

ProbePointSet sPiece(std::uint64_t seed = 7) {
  ProbeSimOptions o = ProbeSimOptions::sPieceDefaults();
  o.seed = seed;
  return simulateProbing(o);
}

TEST(SPiece, FortyPointsOnPlaneHolesAndRuledSurfaces) {
  const ProbePointSet s = sPiece();
  ASSERT_EQ(s.points.size(), 40u);
  EXPECT_TRUE(s.hasNormals);
  EXPECT_FALSE(s.planar);
  std::map<std::string, int> count;
  for (const ProbePoint& p : s.points) {
    ++count[p.surface];
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12) << p.id;
  }
  EXPECT_EQ(count, (std::map<std::string, int>{
                       {"plane", 8}, {"hole1", 4}, {"hole2", 4}, {"ruled+", 12}, {"ruled-", 12}}));
  // Holes: points on the cylinder (radius 12 around the axis), normal towards the axis.
  for (const ProbePoint& p : s.points) {
    if (p.surface == "hole1") {
      const Eigen::Vector3d r = p.nominal - Eigen::Vector3d(35.0, 105.0, p.nominal.z());
      EXPECT_NEAR(r.norm(), 12.0, 1e-12);
      EXPECT_NEAR(p.normal.dot(r.normalized()), -1.0, 1e-12);
    }
    if (p.surface == "plane") {
      EXPECT_EQ(p.normal, Eigen::Vector3d::UnitZ());
    }
  }
  // The two sides of the wall are 3 mm apart along y and face away from each other.
  for (int i = 0; i < 12; ++i) {
    const ProbePoint& a = s.points[16 + i];
    const ProbePoint& b = s.points[28 + i];
    EXPECT_NEAR(a.nominal.y() - b.nominal.y(), 3.0, 1e-12);
    EXPECT_GT(a.normal.y(), 0.0);
    EXPECT_LT(b.normal.y(), 0.0);
    EXPECT_NEAR(a.normal.z(), -b.normal.z(), 1e-12);
  }
  EXPECT_THROW(parseProbeShape("cube", "--shape"), OptionsError);
  EXPECT_EQ(parseProbeShape("s-piece", "--shape"), ProbeShape::SPiece);
}

TEST(SPiece, PaperLikePostureErrorAndMatchingBringsAllInside) {
  const ProbePointSet s = sPiece();
  MatchOptions o;
  o.method = MatchMethod::Sade;
  o.toleranceMm = kSPieceToleranceMm;
  const MatchResult r = matchPosture(s, o);
  // The paper: all 40 points out of +-0.035 mm, average over tolerance about 1.8797 mm.
  EXPECT_EQ(r.before.overall.outOfTolerance, 40u);
  EXPECT_NEAR(r.before.overall.meanOverToleranceMm, 1.88, 0.05);
  // After SADE with the paper's settings: none out (noise 0.006 mm), at the least-squares optimum.
  EXPECT_EQ(r.after.overall.outOfTolerance, 0u);
  EXPECT_LT(r.after.overall.maxAbsMm, 0.025);
  o.method = MatchMethod::ClosedForm;
  const MatchResult cf = matchPosture(s, o);
  EXPECT_LT(r.after.overall.rmseMm - cf.after.overall.rmseMm, 1e-6);
  EXPECT_GE(r.after.overall.rmseMm - cf.after.overall.rmseMm, -1e-12);
  // The fit recovers the simulated posture.
  const Eigen::Vector3d a = cf.pose.anglesDeg();
  EXPECT_NEAR(a.x(), -0.29, 0.005);
  EXPECT_NEAR(a.y(), -0.46, 0.005);
  EXPECT_NEAR(a.z(), -0.52, 0.005);
  EXPECT_NEAR(cf.pose.translation.x(), 1.73, 0.02);
  EXPECT_NEAR(cf.pose.translation.y(), -0.23, 0.02);
  EXPECT_NEAR(cf.pose.translation.z(), 1.57, 0.02);
}

TEST(SPiece, DemoDataIsSimulatorOutput) {
  EXPECT_EQ(test::readText((test::sourceDir() / "resources/demo/data/probe_s_piece.csv").string()),
            probePointsToCsv(sPiece(7)));
}

TEST(Study, RunsEveryMethodAdjustsAndRemeasures) {
  const ProbePointSet s = sPiece();
  MatchingStudyOptions o;
  o.toleranceMm = kSPieceToleranceMm;
  o.machine = machine::MachineDefinition::preset(machine::Topology::AcTable);
  const MatchingStudyResult r = runMatchingStudy(s, o);
  ASSERT_EQ(r.runs.size(), 4u);
  ASSERT_EQ(r.seconds.size(), 4u);
  for (MatchMethod m :
       {MatchMethod::Sade, MatchMethod::GaSimplex, MatchMethod::ClosedForm, MatchMethod::Minimax})
    ASSERT_NE(r.of(m), nullptr);
  EXPECT_EQ(r.primaryRun().method, MatchMethod::Sade);
  EXPECT_TRUE(r.of(MatchMethod::Sade)->rough.has_value());
  EXPECT_FALSE(r.of(MatchMethod::Sade)->run.trace.empty());
  EXPECT_FALSE(r.of(MatchMethod::GaSimplex)->run.trace.empty());
  // Minimax never has a larger max than least squares.
  EXPECT_LE(r.of(MatchMethod::Minimax)->after.overall.maxAbsMm,
            r.of(MatchMethod::ClosedForm)->after.overall.maxAbsMm + 1e-12);
  // The adjustment is the machine's for the primary posture.
  const machine::Adjustment a =
      machine::adjustmentFor(o.machine, r.primaryRun().pose.rotation, r.primaryRun().pose.translation);
  EXPECT_EQ(r.adjustment.topology, machine::Topology::AcTable);
  EXPECT_NEAR((r.adjustment.linearMm - a.linearMm).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.adjustment.rotaryDeg[0], a.rotaryDeg[0]);
  // The remeasure loop ends with every point inside.
  ASSERT_TRUE(r.remeasure.has_value());
  EXPECT_TRUE(r.remeasure->inTolerance);
  ASSERT_GE(r.remeasure->rounds.size(), 2u);
  EXPECT_EQ(r.remeasure->rounds.front().measured.overall.outOfTolerance, 40u);
  EXPECT_EQ(r.remeasure->rounds.back().measured.overall.outOfTolerance, 0u);
  EXPECT_EQ(r.remeasure->outcome, RemeasureOutcome::InTolerance);
  // The cell's part is where the probe found it: the true error of round 0 is the data's own.
  ASSERT_TRUE(r.remeasure->rounds.front().truth.has_value());
  const std::vector<double> dataDeviations = s.deviations();
  for (std::size_t i = 0; i < dataDeviations.size(); ++i)
    EXPECT_NEAR(r.remeasure->rounds.front().truth->deviations[i], dataDeviations[i], 1e-9);
  ASSERT_NE(r.remeasure->trueRemaining(), nullptr);
  EXPECT_LE(r.remeasure->trueRemaining()->overall.maxAbsMm, kSPieceToleranceMm);

  // A tolerance tighter than the part's form error (the data's residual after the best fit): the
  // loop now fails instead of reporting success.
  MatchingStudyOptions tight = o;
  tight.methods = {MatchMethod::ClosedForm};
  tight.primary = MatchMethod::ClosedForm;
  tight.toleranceMm = 0.5 * r.of(MatchMethod::ClosedForm)->after.overall.maxAbsMm;
  const MatchingStudyResult failed = runMatchingStudy(s, tight);
  ASSERT_TRUE(failed.remeasure.has_value());
  EXPECT_FALSE(failed.remeasure->inTolerance);
  EXPECT_EQ(failed.remeasure->outcome, RemeasureOutcome::FormError) << failed.remeasure->run.message;
  ASSERT_NE(failed.remeasure->trueRemaining(), nullptr);
  EXPECT_GT(failed.remeasure->trueRemaining()->overall.outOfTolerance, 0u);

  // The observer can stop the study.
  FunctionObserver stop([](const IterationSummary&) { return ObserverDecision::Stop; });
  const MatchingStudyResult stopped = runMatchingStudy(s, o, &stop);
  ASSERT_EQ(stopped.runs.size(), 1u);
  EXPECT_EQ(stopped.runs[0].run.termination, Termination::Cancelled);
  EXPECT_FALSE(stopped.remeasure.has_value());
}

Project demoLikeProject() {
  Project p;
  p.datasets.push_back({"block", dataset_kind::kProbePoints, "data/block.csv", "", "", {}});
  p.datasets.push_back({"s_piece", dataset_kind::kProbePoints, "data/s.csv", "", "", {}});
  p.datasets.push_back({"log", dataset_kind::kThermalLog, "data/log.csv", "", "", {}});
  return p;
}

std::string settingsError(const nlohmann::json& matchingStudy) {
  Project p = demoLikeProject();
  p.studies["matching"] = matchingStudy;
  try {
    (void)matchingStudySettings(p, "cell.metrofit");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Study, SettingsFromTheProject) {
  Project p = demoLikeProject();
  MatchingStudySettings s = matchingStudySettings(p);
  EXPECT_EQ(s.datasetId, "block");
  EXPECT_EQ(s.options.toleranceMm, 0.05);
  EXPECT_EQ(s.options.primary, MatchMethod::Sade);
  EXPECT_EQ(s.options.machine.topology, machine::Topology::Xfyzba);
  p.studies["matching"] = {{"dataset", "s_piece"},
                           {"tolerance_mm", 0.035},
                           {"method", "closed-form"},
                           {"allow_scale", true},
                           {"seed", 3},
                           {"machine", {{"topology", "bc"}, {"rotary_axis_point_mm", {1.0, 2.0, 0.0}}}}};
  s = matchingStudySettings(p);
  EXPECT_EQ(s.datasetId, "s_piece");
  EXPECT_EQ(s.options.toleranceMm, 0.035);
  EXPECT_EQ(s.options.primary, MatchMethod::ClosedForm);
  EXPECT_TRUE(s.options.allowScale);
  EXPECT_EQ(s.options.seed, 3u);
  EXPECT_EQ(s.options.machine.topology, machine::Topology::BcTable);
  EXPECT_EQ(s.options.machine.rotaryAxisPoint, Eigen::Vector3d(1.0, 2.0, 0.0));
  EXPECT_FALSE(s.options.locks.any());
  p.studies["matching"]["locks"] = "rz,z";  // written by the matching page, read by CLI and report
  s = matchingStudySettings(p);
  EXPECT_EQ(s.options.locks.toString(), "rz,z");
  EXPECT_EQ(
      settingsError({{"locks", 3}}),
      "cell.metrofit: field 'studies.matching.locks': must be a list of rx, ry, rz, x, y, z (string, e.g. "
      "\"rz,z\")");
  EXPECT_NE(settingsError({{"locks", "rz,q"}}).find("studies.matching.locks"), std::string::npos);

  EXPECT_EQ(settingsError({{"dataset", "nope"}}),
            "cell.metrofit: field 'studies.matching.dataset': no dataset 'nope' in the project");
  EXPECT_EQ(
      settingsError({{"dataset", "log"}}),
      "cell.metrofit: field 'studies.matching.dataset': 'log' is a thermal_log dataset, not probe_points");
  EXPECT_EQ(settingsError({{"tolerance_mm", -1}}),
            "cell.metrofit: field 'studies.matching.tolerance_mm': must be a number >= 0 (mm)");
  EXPECT_EQ(settingsError({{"method", "newton"}}),
            "cell.metrofit: field 'studies.matching.method': unknown matching method 'newton' (one of sade, "
            "ga-simplex, "
            "closed-form, minimax)");
  EXPECT_EQ(settingsError({{"allow_scale", "yes"}}),
            "cell.metrofit: field 'studies.matching.allow_scale': must be true or false");
  EXPECT_EQ(settingsError({{"seed", -2}}),
            "cell.metrofit: field 'studies.matching.seed': must be an integer >= 0");
}

TEST(ProjectMachine, RoundTripThroughTheProjectFile) {
  const auto dir = test::outDir() / "study_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "machine.metrofit").string();
  for (machine::Topology t :
       {machine::Topology::Xfyzba, machine::Topology::AcTable, machine::Topology::BcTable}) {
    Project p = demoLikeProject();
    p.studies["matching"] = {{"dataset", "s_piece"}, {"tolerance_mm", 0.035}};
    machine::MachineDefinition def = machine::MachineDefinition::preset(t);
    def.lx = 1.5;
    def.lz = -210.0;
    def.lab = -95.0;
    def.tiltAxisPoint = Eigen::Vector3d(0.0, 10.0, -120.0);
    setMatchingMachine(p, def);
    saveProject(p, path);
    const Project back = loadProject(path);
    EXPECT_EQ(back, p);
    machine::MachineDefinition read;
    ASSERT_TRUE(matchingMachine(back, &read, path));
    EXPECT_EQ(read.topology, t);
    EXPECT_EQ(read.lx, 1.5);
    EXPECT_EQ(read.lz, -210.0);
    EXPECT_EQ(read.lab, -95.0);
    EXPECT_EQ(read.tiltAxisPoint, def.tiltAxisPoint);
    EXPECT_EQ(read.rotaryMinDeg, def.rotaryMinDeg);
    EXPECT_EQ(read.rotaryMaxDeg, def.rotaryMaxDeg);
    EXPECT_EQ(back.studies["matching"]["tolerance_mm"], 0.035);  // the other keys stay
  }
  // Short names as people write them: "ac", "bc".
  Project p = demoLikeProject();
  p.studies["matching"]["machine"] = {{"topology", "ac"}, {"LX_mm", 2.0}};
  machine::MachineDefinition read;
  ASSERT_TRUE(matchingMachine(p, &read));
  EXPECT_EQ(read.topology, machine::Topology::AcTable);
  // No machine: false, output untouched.
  Project none = demoLikeProject();
  read.lx = 42.0;
  EXPECT_FALSE(matchingMachine(none, &read));
  EXPECT_EQ(read.lx, 42.0);
}

std::string loadError(const nlohmann::json& machineJson) {
  Project p = demoLikeProject();
  nlohmann::json j = p.toJson();
  j["studies"]["matching"]["machine"] = machineJson;
  try {
    (void)Project::fromJson(j, "cell.metrofit");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ProjectMachine, InvalidMachinesAreRejectedOnLoad) {
  EXPECT_EQ(loadError({{"topology", "xfyzba"}}), "no error");
  EXPECT_EQ(loadError("xfyzba"), "cell.metrofit: field 'studies.matching.machine': must be an object");
  EXPECT_EQ(
      loadError({{"topology", "hexapod"}}),
      "cell.metrofit: field 'studies.matching.machine.topology': unknown machine topology 'hexapod' (one of "
      "xfyzba, ac-table, bc-table, head-table)");
  EXPECT_EQ(loadError({{"topology", "xfyzba"}, {"LX_mm", "long"}})
                .rfind("cell.metrofit: field 'studies.matching.machine.LX_mm': ", 0),
            0u);
  EXPECT_EQ(
      loadError({{"rotary_travel_deg", {1, 2}}}),
      "cell.metrofit: field 'studies.matching.machine.rotary_travel_deg': expected [[min, max], [min, max]]");
  nlohmann::json j = demoLikeProject().toJson();
  j["studies"]["matching"] = 5;
  EXPECT_THROW((void)Project::fromJson(j, "cell.metrofit"), ValidationError);
}

}  // namespace
}  // namespace metrofit::matching

namespace metrofit::matching {
namespace {

TEST(DeviationMagnification, LargestDeviationAtAboutFifteenPercentOfThePart) {
  ProbePointSet set;
  for (const double x : {0.0, 120.0}) {
    ProbePoint p;
    p.nominal = Eigen::Vector3d(x, 0.5 * x, 0.0);
    set.points.push_back(p);
  }
  // Extent 120 mm, largest deviation 0.04 mm: 0.15 * 120 / 0.04 = 450 -> 200 (1-2-5 rounded down).
  EXPECT_DOUBLE_EQ(deviationMagnification(set, 0.04), 200.0);
  // A tiny part counts as 1 mm; the factor is kept in [1, 1e5].
  EXPECT_DOUBLE_EQ(deviationMagnification(set, 1e-9), 1e5);
  EXPECT_DOUBLE_EQ(deviationMagnification(set, 500.0), 1.0);
  EXPECT_DOUBLE_EQ(deviationMagnification(set, 0.0), 100.0);
  EXPECT_DOUBLE_EQ(deviationMagnification(ProbePointSet{}, 0.04), 100.0);
}

}  // namespace
}  // namespace metrofit::matching
