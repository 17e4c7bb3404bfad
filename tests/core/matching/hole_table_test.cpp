// PC-DMIS hole-table reports (core/matching/hole_table.h). The excerpts are hand-made in the layout
// of the real plug-plate reports (the SDSS files themselves have no licence and stay out of the
// repository; metrofit-bench --real-matching reads them).
#include "core/matching/hole_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/error.h"
#include "core/matching/closed_form.h"
#include "core/matching/fit_input.h"
#include "testsupport.h"

namespace metrofit {
namespace {

const char* kHeader =
    "    Meas X    Meas Y     Nom X     Nom Y     Err X     Err Y  Meas D   Nom D   Round\r\n";

std::string excerpt() {
  return std::string("Plug Plate: 9001\r\nDate: 2020-02-29\r\n\r\n") + kHeader +
         "    11.610   -10.090    11.650   -10.184    -0.040     0.094   3.265   2.845   0.006\r\n"
         "    -0.207   162.841    -0.079   162.760    -0.128     0.081   2.174   2.167   0.011\r\n"
         "# a comment line\r\n"
         "   210.177    72.484   210.257    72.308    -0.080     0.176   2.174   2.167   0.003\r\n"
         "\r\n"
         "  -132.201  -296.356  -132.308  -296.354     0.107    -0.002   2.176   2.167   0.005\r\n";
}

std::string error(const std::string& text, std::size_t minPoints = 3) {
  try {
    (void)holeTableFromText(text, "D9001_1", minPoints);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(HoleTable, ReadsThePlugPlateLayout) {
  const HoleTable t = holeTableFromText(excerpt(), "D9001_1");
  EXPECT_EQ(t.metadata.at("Plug Plate"), "9001");
  EXPECT_EQ(t.metadata.at("Date"), "2020-02-29");
  const ProbePointSet& s = t.points;
  ASSERT_EQ(s.points.size(), 4u);
  EXPECT_TRUE(s.planar);
  EXPECT_FALSE(s.hasNormals);
  EXPECT_EQ(s.source, "D9001_1");
  EXPECT_EQ(s.points[0].id, "H001");
  EXPECT_EQ(s.points[3].id, "H004");
  EXPECT_EQ(s.points[0].surface, "hole D2.845");
  EXPECT_EQ(s.points[1].surface, "hole D2.167");
  EXPECT_DOUBLE_EQ(s.points[0].nominal.x(), 11.650);
  EXPECT_DOUBLE_EQ(s.points[0].nominal.y(), -10.184);
  EXPECT_DOUBLE_EQ(s.points[0].measured.x(), 11.610);
  EXPECT_DOUBLE_EQ(s.points[0].measured.y(), -10.090);
  EXPECT_EQ(s.points[2].nominal.z(), 0.0);
  ASSERT_EQ(t.measuredDiameterMm.size(), 4u);
  EXPECT_DOUBLE_EQ(t.measuredDiameterMm[0], 3.265);
  EXPECT_DOUBLE_EQ(t.nominalDiameterMm[1], 2.167);
  // Deviation of a position-only point: the whole distance.
  EXPECT_NEAR(s.deviations()[0], std::hypot(-0.040, 0.094), 1e-12);
}

TEST(HoleTable, MinimalColumnsAndLfLineEnds) {
  const HoleTable t = holeTableFromText(
      "Meas X    Meas Y    Nom X    Nom Y\n1.001  2.000  1.000  2.000\n5.000  0.002  5.000  0.000\n"
      "0.000  7.001  0.000  7.000\n",
      "holes.txt");
  ASSERT_EQ(t.points.points.size(), 3u);
  EXPECT_EQ(t.points.points[0].surface, "hole");
  EXPECT_TRUE(t.measuredDiameterMm.empty());
  EXPECT_TRUE(t.metadata.empty());
}

TEST(HoleTable, DetectionByContent) {
  EXPECT_TRUE(looksLikeHoleTable(excerpt()));
  EXPECT_TRUE(looksLikeHoleTable("\xEF\xBB\xBF    Meas X  Meas Y  Nom X  Nom Y\n"));
  EXPECT_FALSE(looksLikeHoleTable("id,surface,qx,qy,px,py\nA,top,0,0,0,0\n"));
  EXPECT_FALSE(looksLikeHoleTable("# comment\nid,qx,qy,px,py\n"));
  EXPECT_FALSE(looksLikeHoleTable(""));

  const auto dir = test::outDir() / "hole_table_test";
  std::filesystem::create_directories(dir);
  const std::string report = (dir / "D9001_1").string();
  const std::string csv = (dir / "points.csv").string();
  test::writeText(report, excerpt());
  test::writeText(csv, "id,qx,qy,px,py\nA,0,0,0.1,0\nB,10,0,10.1,0\nC,0,10,0.1,10\n");
  const ProbePointSet fromReport = readProbePointsAnyFormat(report);
  EXPECT_EQ(fromReport.points.size(), 4u);
  EXPECT_EQ(fromReport.points[0].surface, "hole D2.845");
  const ProbePointSet fromCsv = readProbePointsAnyFormat(csv);
  EXPECT_EQ(fromCsv.points.size(), 3u);
  EXPECT_EQ(fromCsv.points[1].id, "B");
  EXPECT_THROW(readProbePointsAnyFormat((dir / "missing.txt").string()), FileError);
}

TEST(HoleTable, EveryBadInputNamesFileAndLine) {
  const std::string pre = std::string("Plug Plate: 9001\r\n\r\n") + kHeader;
  const std::string good =
      "    11.610   -10.090    11.650   -10.184    -0.040     0.094   3.265   2.845   0.006\r\n";
  const std::string good2 =
      "    -0.207   162.841    -0.079   162.760    -0.128     0.081   2.174   2.167   0.011\r\n";
  const std::string good3 =
      "   210.177    72.484   210.257    72.308    -0.080     0.176   2.174   2.167   0.003\r\n";
  EXPECT_EQ(error("Plug Plate: 9001\n\n"),
            "D9001_1: no hole-table header (a line with the columns Meas X, Meas Y, Nom X, Nom Y)");
  EXPECT_EQ(
      error("Plug Plate: 9001\n1.0 2.0 3.0 4.0\n"),
      "D9001_1:2: not a hole-table report: expected 'Key: value' lines and then a column header with Meas "
      "X, Meas Y, Nom X, Nom Y, found '1.0 2.0 3.0 4.0'");
  EXPECT_EQ(
      error("Meas X  Meas Y  Nom X  Err X\n1 2 3 4\n"),
      "D9001_1:1: field 'Nom Y': missing column (the header has Meas X, Meas Y, Nom X, Nom Y at least)");
  EXPECT_EQ(error(pre + good + "    1.0   2.0   3.0\r\n" + good3),
            "D9001_1:5: has 3 values, the header has 9 columns");
  EXPECT_EQ(error(pre + good +
                  "    -0.207   162.84x    -0.079   162.760    -0.128     0.081   2.174   2.167   "
                  "0.011\r\n" +
                  good3),
            "D9001_1:5:2: field 'Meas Y': '162.84x' is not a finite number");
  EXPECT_EQ(
      error(pre + good +
            "    -0.207   nan    -0.079   162.760    -0.128     0.081   2.174   2.167   0.011\r\n" + good3),
      "D9001_1:5:2: field 'Meas Y': 'nan' is not a finite number");
  // Err X must be Meas X - Nom X (columns shifted or edited by hand).
  EXPECT_EQ(
      error(pre + good +
            "    -0.207   162.841    -0.079   162.760    -0.118     0.081   2.174   2.167   "
            "0.011\r\n" +
            good3),
      "D9001_1:5:5: field 'Err X': -0.118 disagrees with Meas X - Nom X = -0.1280 mm (columns shifted?)");
  EXPECT_EQ(error(pre + good +
                  "    -0.207   162.841    -0.079   162.760    -0.128     0.081   2.174   0.000   "
                  "0.011\r\n" +
                  good3),
            "D9001_1:5:8: field 'Nom D': a hole diameter must be > 0 mm");
  EXPECT_EQ(error(pre + good +
                  "    -0.207   162.841    -0.079   162.760    -0.128     0.081   2.174   2.167   "
                  "-0.011\r\n" +
                  good3),
            "D9001_1:5:9: field 'Round': roundness must not be negative");
  EXPECT_EQ(error(pre + good + good2 + good2),
            "D9001_1:6:3: field 'Nom X': two holes at the same nominal position (-0.079, 162.760), first on "
            "line 5");
  EXPECT_EQ(error(pre + good + good2), "D9001_1: has 2 holes, at least 3 needed");
  EXPECT_EQ(error(pre + good + good2, 2), "no error");
}

TEST(HoleTable, SimilarityFitOfAHandBuiltPlate) {
  // Nominal holes, then the measured ones: rotated by 0.02 deg, scaled by 1 + 20 ppm, shifted by
  // (0.05, -0.03) mm, printed to 0.001 mm as the CMM does. The closed-form fit with scale must find
  // them within the rounding.
  const double th = 0.02 * M_PI / 180.0, s = 1.0 + 20e-6;
  std::string text = std::string("Plug Plate: 9002\n\n") + kHeader;
  const double nominal[][2] = {{-250, -100}, {-120, 240}, {0, 0},    {60, -280},
                               {200, 150},   {290, -40},  {-40, 120}};
  for (const auto& q : nominal) {
    const double mx = s * (std::cos(th) * q[0] - std::sin(th) * q[1]) + 0.05;
    const double my = s * (std::sin(th) * q[0] + std::cos(th) * q[1]) - 0.03;
    char line[200];
    const double rx = std::round(mx * 1000) / 1000, ry = std::round(my * 1000) / 1000;
    std::snprintf(line, sizeof line, "%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%8.3f%8.3f%8.3f\n", rx, ry, q[0],
                  q[1], rx - q[0], ry - q[1], 2.170, 2.167, 0.004);
    text += line;
  }
  const ProbePointSet set = holeTableFromText(text, "D9002_1").points;
  matching::ClosedFormOptions o;
  o.allowScale = true;
  o.locks = matching::effectiveLocks(set, {});
  const matching::Pose pose = matching::closedFormFit(set, o).pose;
  EXPECT_NEAR(pose.anglesDeg().z(), 0.02, 2e-4);
  EXPECT_NEAR(pose.anglesDeg().x(), 0.0, 1e-12);
  EXPECT_NEAR(pose.anglesDeg().y(), 0.0, 1e-12);
  EXPECT_NEAR((pose.scale - 1.0) * 1e6, 20.0, 3.0);
  EXPECT_NEAR(pose.translation.x(), 0.05, 1e-3);
  EXPECT_NEAR(pose.translation.y(), -0.03, 1e-3);
  EXPECT_EQ(pose.translation.z(), 0.0);
}

}  // namespace
}  // namespace metrofit
