// The matching study with nominals from a CAD part (core/project/nominals.h {"from": "cad"},
// MatchingStudyOptions::cad): a box written as ASCII STL here, probe points on its faces moved by a
// known posture; the study's closed-form and minimax runs re-project the points onto the part and
// recover the posture; methods that need fixed point pairs are refused; the part's triangles are
// coloured by the deviation of the nearest probed point. The project path end to end: a cad_model
// dataset and probe points whose nominals come from it, read by readProjectProbePoints.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/geometry/stl.h"
#include "core/matching/cad_match.h"
#include "core/project/datasets.h"
#include "core/project/nominals.h"
#include "core/study/matching_study.h"
#include "samples/box_stl.h"
#include "testsupport.h"

namespace metrofit {
namespace {

/// Points on the faces of the box 100 x 60 x 40 (3 per face, off the edges), moved by `pose`.
ProbePointSet boxPoints(const matching::Pose& pose) {
  const std::vector<Eigen::Vector3d> onPart = {{20, 10, 0},  {70, 45, 0},   {40, 30, 0},    // bottom
                                               {25, 15, 40}, {80, 40, 40},  {50, 20, 40},   // top
                                               {15, 0, 10},  {60, 0, 30},   {90, 0, 20},    // front y=0
                                               {20, 60, 25}, {75, 60, 12},  {45, 60, 33},   // back y=60
                                               {100, 10, 8}, {100, 50, 30}, {100, 30, 20},  // right x=100
                                               {0, 12, 30},  {0, 48, 9},    {0, 33, 22}};   // left x=0
  ProbePointSet set;
  set.source = "box_points.csv";
  for (std::size_t i = 0; i < onPart.size(); ++i) {
    ProbePoint p;
    p.id = "P" + std::to_string(i + 1);
    p.surface = "cad";
    p.measured = pose.apply(onPart[i]);
    set.points.push_back(p);
  }
  return set;
}

matching::Pose knownPose() {
  matching::Pose pose;
  pose.rotation = (Eigen::AngleAxisd(0.004, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(-0.002, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(0.003, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation = Eigen::Vector3d(0.15, -0.08, 0.05);
  return pose;
}

TEST(CadStudy, ClosedFormAndMinimaxRecoverAKnownPostureOfTheBox) {
  const geometry::MeshSearch mesh(geometry::parseStl(test::boxStl(100, 60, 40), "box.stl"));
  auto cad =
      std::make_shared<const geometry::MeshSearch>(geometry::parseStl(test::boxStl(100, 60, 40), "box.stl"));
  const matching::Pose truth = knownPose();
  matching::MatchingStudyOptions o;
  o.cad = cad;
  o.primary = matching::MatchMethod::ClosedForm;
  o.remeasure = false;
  const matching::MatchingStudyResult r = matching::runMatchingStudy(boxPoints(truth), o);
  // Only the methods that re-project: closed form and minimax (the default list has four).
  ASSERT_EQ(r.runs.size(), 2u);
  ASSERT_EQ(r.cadAfter.size(), 2u);
  for (const matching::MatchResult& run : r.runs) {
    // The points lie exactly on the moved box: the posture is recovered to rounding, the deviations
    // after matching vanish.
    EXPECT_LT((run.pose.rotation - truth.rotation).norm(), 1e-7) << matching::toString(run.method);
    EXPECT_LT((run.pose.translation - truth.translation).norm(), 1e-6) << matching::toString(run.method);
    EXPECT_LT(run.after.overall.maxAbsMm, 1e-6);
    EXPECT_GT(run.before.overall.maxAbsMm, 0.1);
  }
  // The closest points after matching are on the box (the nominals the after evaluation is of).
  for (const ProbePoint& p : r.cadAfter.front().points) EXPECT_LT(mesh.closest(p.nominal).distance, 1e-9);
}

TEST(CadStudy, MethodsThatNeedPointPairsAndAppliedEffectsAreRefused) {
  auto cad =
      std::make_shared<const geometry::MeshSearch>(geometry::parseStl(test::boxStl(100, 60, 40), "box.stl"));
  matching::MatchingStudyOptions o;
  o.cad = cad;
  o.remeasure = false;
  o.primary = matching::MatchMethod::Sade;
  try {
    (void)matching::runMatchingStudy(boxPoints({}), o);
    ADD_FAILURE() << "sade ran on CAD nominals";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("studies.matching.method"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("closed-form (least squares) or minimax"), std::string::npos)
        << e.what();
  }
}

TEST(CadStudy, TrianglesAreColouredByTheNearestProbedPoint) {
  const geometry::TriangleMesh box = geometry::parseStl(test::boxStl(100, 60, 40), "box.stl");
  // Two points on the bottom face with deviations +0.01 and -0.02, near the centroids of its two
  // triangles; the other faces are not probed.
  ProbePointSet closest;
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(66, 20, 0), Eigen::Vector3d(33, 40, 0)}) {
    ProbePoint p;
    p.nominal = q;
    closest.points.push_back(p);
  }
  const std::vector<double> dev = matching::triangleDeviations(box, closest, {0.01, -0.02}, 30.0);
  ASSERT_EQ(dev.size(), 12u);
  int coloured = 0;
  for (std::size_t t = 0; t < dev.size(); ++t) {
    const geometry::Triangle& tri = box.triangles[t];
    const Eigen::Vector3d c = (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0;
    // The answer of a search over all points, written here.
    const double d0 = (c - closest.points[0].nominal).norm(), d1 = (c - closest.points[1].nominal).norm();
    if (std::min(d0, d1) > 30.0) {
      EXPECT_TRUE(std::isnan(dev[t])) << t;
    } else {
      ++coloured;
      EXPECT_EQ(dev[t], d0 <= d1 ? 0.01 : -0.02) << t;
    }
  }
  EXPECT_GE(coloured, 2);
  EXPECT_LT(coloured, 12);
}

TEST(CadStudy, AProjectReadsProbePointsWithNominalsFromItsCadPart) {
  test::TempDir tmp;
  test::writeText(tmp.file("box.stl"), test::boxStl(100, 60, 40));
  std::string csv = "id,x,y,z\n";
  for (const ProbePoint& p : boxPoints(knownPose()).points) {
    char line[160];
    std::snprintf(line, sizeof line, "%s,%.9f,%.9f,%.9f\n", p.id.c_str(), p.measured.x(), p.measured.y(),
                  p.measured.z());
    csv += line;
  }
  test::writeText(tmp.file("points.csv"), csv);
  const std::string projectPath = tmp.file("p.metrofit");
  Project project;
  AddDatasetRequest part;
  part.kind = "auto";
  part.file = tmp.file("box.stl");
  const DatasetRef box = addDataset(project, projectPath, part);
  EXPECT_EQ(box.kind, dataset_kind::kCadModel);
  EXPECT_EQ(summarizeDataset(projectPath, box).rows, 12);
  AddDatasetRequest points;
  points.kind = "probe-points";
  points.file = tmp.file("points.csv");
  points.nominals.from = "cad";
  points.nominals.cad = "nowhere";
  EXPECT_THROW(addDataset(project, projectPath, points), ValidationError);
  points.nominals.cad = box.id;
  const DatasetRef pts = addDataset(project, projectPath, points);
  saveProject(project, projectPath);
  const Project reopened = loadProject(projectPath);
  EXPECT_EQ(reopened, project);
  const ProbePointSet set = readProjectProbePoints(reopened, projectPath, *reopened.dataset(pts.id));
  ASSERT_EQ(set.points.size(), 18u);
  ASSERT_TRUE(set.hasNormals);
  // At the identity posture: each nominal is the closest point of the box to the measured point.
  const geometry::MeshSearch mesh(geometry::parseStl(test::boxStl(100, 60, 40), "box.stl"));
  for (const ProbePoint& p : set.points)
    EXPECT_LT((p.nominal - mesh.closest(p.measured).point).norm(), 1e-12) << p.id;
}

}  // namespace
}  // namespace metrofit
