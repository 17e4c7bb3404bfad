#include "core/matching/probe_points.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string error(const std::string& text) {
  try {
    (void)probePointsFromCsv(parseCsv(text, "pts.csv"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kHeader = "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n";

TEST(ProbePoints, FullFormWithNormals) {
  const ProbePointSet s =
      probePointsFromCsv(parseCsv(std::string(kHeader) + "A,top,0,0,10,0,0,1,0,0,10.02\n"
                                                         "B,top,10,0,10,0,0,1,10,0,9.99\n"
                                                         "C,side,0,5,5,-1,0,0,-0.03,5,5\n",
                                  "p"));
  EXPECT_TRUE(s.hasNormals);
  EXPECT_FALSE(s.planar);
  const auto d = s.deviations();
  EXPECT_TRUE(test::near(d[0], 0.02, 1e-12));
  EXPECT_TRUE(test::near(d[1], -0.01, 1e-12));
  EXPECT_TRUE(test::near(d[2], 0.03, 1e-12));  // outward along -x
}

TEST(ProbePoints, PositionOnlyAndPlanarForms) {
  const ProbePointSet pos =
      probePointsFromCsv(parseCsv("id,surface,qx,qy,qz,px,py,pz\nH1,holes,0,0,0,0.03,0.04,0\n"
                                  "H2,holes,1,0,0,1,0,0\nH3,holes,0,1,0,0,1,0\n",
                                  "p"));
  EXPECT_FALSE(pos.hasNormals);
  EXPECT_TRUE(test::near(pos.deviations()[0], 0.05, 1e-12));  // full distance
  const ProbePointSet planar =
      probePointsFromCsv(parseCsv("id,qx,qy,px,py\n1,0,0,0.1,0\n2,5,0,5,0\n3,0,5,0,5\n", "p"));
  EXPECT_TRUE(planar.planar);
  EXPECT_EQ(planar.points[0].surface, "");
  EXPECT_EQ(planar.points[0].nominal.z(), 0.0);
}

TEST(ProbePoints, ValidationErrors) {
  const std::string h = kHeader;
  EXPECT_EQ(error(h + "A,top,0,0,0,0,0,1,0,0,0\nA,top,1,0,0,0,0,1,1,0,0\nC,top,0,1,0,0,0,1,0,1,0\n"),
            "pts.csv:3:1: field 'id': duplicate point id 'A' (first on line 2)");
  EXPECT_EQ(error(h + "A,top,0,0,0,0,0,0,0,0,0\nB,top,1,0,0,0,0,1,1,0,0\nC,top,0,1,0,0,0,1,0,1,0\n"),
            "pts.csv:2:6: field 'nx': zero normal vector; every point needs a unit normal");
  EXPECT_EQ(error(h + "A,top,0,0,0,0,0,2,0,0,0\nB,top,1,0,0,0,0,1,1,0,0\nC,top,0,1,0,0,0,1,0,1,0\n"),
            "pts.csv:2:6: field 'nx': normal is not a unit vector (length 2)");
  EXPECT_EQ(error(h + "A,top,0,0,0,0,0,1,0,0,0\nB,top,1,0,0,0,0,1,1,0,0\n"),
            "pts.csv: has 2 points, at least 3 needed");
  EXPECT_EQ(error("id,qx,qy,px\n1,0,0,0\n"),
            "pts.csv: field 'py': missing column (the file has: id, qx, qy, px)");
  EXPECT_EQ(error("id,qx,qy,qz,nx,px,py,pz\n1,0,0,0,1,0,0,0\n"),
            "pts.csv: field 'ny': missing column (the file has: id, qx, qy, qz, nx, px, py, pz)");
  EXPECT_EQ(error(h + ",top,0,0,0,0,0,1,0,0,0\n"), "pts.csv:2:1: field 'id': empty point id");
}

TEST(ProbePoints, CsvRoundTripOfDemoData) {
  const auto path = (test::sourceDir() / "resources/demo/data/probe_points_demo.csv").string();
  const ProbePointSet s = readProbePoints(path);
  EXPECT_EQ(s.points.size(), 35u);
  EXPECT_EQ(probePointsToCsv(s), test::readText(path));
}

}  // namespace
}  // namespace metrofit
