// metrofit-cli match --cad (docs/file-formats.md#match-to-a-cad-part): measured points against an STL
// part written by the test (tests/core/geometry/mesh_fixtures.h) from analytic surfaces in a known
// posture; the JSON keys of `match` plus per_point and cad; exit 2 with one line naming the file for
// bad input. Run under C, de_DE and pl_PL (LOCALES): the numbers keep '.'.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "../core/geometry/mesh_fixtures.h"
#include "cli_runner.h"
#include "testsupport.h"

namespace metrofit::test {
namespace {

/// The composite part of tests/core/matching/cad_match_test.cpp: a sphere (144 x 72 facets, chord error
/// 4.8 um), a cylinder along y and a plane, which together fix all six parameters.
std::vector<Facet> partFacets() {
  std::vector<Facet> f = sphereFacets({30, 0, 20}, 10.0, 144, 72);
  for (const auto& c : cylinderFacets({-30, -20, 20}, {0, 1, 0}, 10.0, 40.0, 256, 2)) f.push_back(c);
  for (const auto& p : planeFacets(-60, 60, -60, 60, 0.0, 1, 1)) f.push_back(p);
  return f;
}

/// Points on the analytic surfaces moved by the posture rotation_deg (0.4, -0.3, 0.6), translation
/// (0.3, -0.2, 0.15) mm, no noise; header as given.
std::string pointsCsv(const std::string& header = "id,px,py,pz") {
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.6 * kMeshPi / 180, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(-0.3 * kMeshPi / 180, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.4 * kMeshPi / 180, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d t(0.3, -0.2, 0.15);
  std::vector<Eigen::Vector3d> s;
  const double golden = kMeshPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 120; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / 120, r = std::sqrt(1.0 - z * z);
    s.push_back(Eigen::Vector3d(30, 0, 20) +
                10.0 * Eigen::Vector3d(r * std::cos(golden * i), r * std::sin(golden * i), z));
  }
  for (int i = 0; i < 20; ++i)
    for (int k = 0; k < 4; ++k) {
      const double ph = 2 * kMeshPi * (i + 0.3 * k) / 20;
      s.push_back({-30 + 10 * std::cos(ph), -10.0 + 6.0 * k, 20 + 10 * std::sin(ph)});
    }
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k) {
      const double x = -55 + 22.0 * i, y = -55 + 22.0 * k;
      if (std::abs(std::abs(x) - 30) < 15 && std::abs(y) < 25) continue;
      s.push_back({x, y, 0.0});
    }
  std::string out = header + "\n";
  char line[160];
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector3d p = R * s[i] + t;
    std::snprintf(line, sizeof line, "Q%zu,%.9f,%.9f,%.9f\n", i + 1, p.x(), p.y(), p.z());
    out += line;
  }
  return out;
}

class MatchCadCli : public ::testing::Test {
 protected:
  void SetUp() override {
    writeText(tmp.file("part.stl"), binaryStl(partFacets(), "solid part (binary)"));
    writeText(tmp.file("points.csv"), pointsCsv());
  }
  TempDir tmp;
};

TEST_F(MatchCadCli, RecoversThePostureWithTheMatchKeys) {
  const CliRun r = cli("match --cad part.stl --data points.csv --per-point pp.csv --out r.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("match: closed-form to part.stl (", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("converged"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(readText(tmp.file("r.json")));
  for (const char* key : {"method", "rotation_deg", "translation_mm", "rmse_mm", "max_abs_mm",
                          "out_of_tolerance", "machine", "per_point", "cad"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["cad"]["file"], "part.stl");
  EXPECT_EQ(j["cad"]["triangles"].get<std::size_t>(), partFacets().size());
  EXPECT_TRUE(j["cad"].contains("max_distance_mm"));
  // Tolerances: the first-order bounds cad_match_test.cpp computes for this part from its chord error
  // (at most 0.01 deg and 0.01 mm), here without noise.
  const double rot[3] = {0.4, -0.3, 0.6}, tr[3] = {0.3, -0.2, 0.15};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j["rotation_deg"][k].get<double>(), rot[k], 0.01) << k;
    EXPECT_NEAR(j["translation_mm"][k].get<double>(), tr[k], 0.01) << k;
  }
  // The points are on the true surfaces, outside the inscribed facets by at most the chord error.
  EXPECT_LT(j["max_abs_mm"].get<double>(), 0.0048 + 0.002);
  EXPECT_GT(j["out_of_tolerance"]["before"].get<int>(), 0);
  EXPECT_EQ(j["out_of_tolerance"]["after"].get<int>(), 0);
  ASSERT_GT(j["per_point"].size(), 100u);
  EXPECT_EQ(j["per_point"][0]["id"], "Q1");
  for (const char* key : {"d_mm", "dx_mm", "dy_mm", "dz_mm"})
    EXPECT_TRUE(j["per_point"][0].contains(key)) << key;
  const std::string pp = readText(tmp.file("pp.csv"));
  EXPECT_EQ(pp.rfind("id,surface,d_mm,dx_mm,dy_mm,dz_mm\nQ1,", 0), 0u) << pp.substr(0, 80);
}

TEST_F(MatchCadCli, MillimetreColumnsLocksAndMinimax) {
  writeText(tmp.file("mm.csv"), pointsCsv("id,x_mm,y_mm,z_mm"));
  const CliRun r = cli("match --cad part.stl --data mm.csv --method minimax --lock rz,z --out r.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(readText(tmp.file("r.json")));
  EXPECT_EQ(j["method"], "minimax");
  EXPECT_EQ(j["rotation_deg"][2].get<double>(), 0.0);
  EXPECT_EQ(j["translation_mm"][2].get<double>(), 0.0);
  EXPECT_EQ(j["locked"], nlohmann::json::array({"rz", "z"}));
}

TEST_F(MatchCadCli, BadInputExitsTwoWithOneLineNamingTheFile) {
  const std::string bin = readText(tmp.file("part.stl"));
  writeText(tmp.file("cut.stl"), bin.substr(0, bin.size() - 10));
  CliRun r = cli("match --cad cut.stl --data points.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cut.stl: starts with 'solid' but is not text"), std::string::npos) << r.err;

  writeText(tmp.file("bad.stl"), "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n");
  r = cli("match --cad bad.stl --data points.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.stl:4: 'zero' is not a number (triangle 1, vertex 1)"), std::string::npos)
      << r.err;

  writeText(tmp.file("nocols.csv"), "id,a,b,c\n1,2,3,4\n");
  r = cli("match --cad part.stl --data nocols.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nocols.csv:1: measured points need the columns"), std::string::npos) << r.err;

  r = cli("match --cad part.stl --data points.csv --method sade", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("closed-form (least squares) or minimax, not sade"), std::string::npos) << r.err;

  r = cli("match --cad missing.stl --data points.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.stl"), std::string::npos) << r.err;

  // A plane alone cannot fix an in-plane shift: the error names the data file and the remedy is a lock.
  writeText(tmp.file("plane.stl"), asciiStl(planeFacets(-60, 60, -60, 60, 0.0, 2, 2)));
  writeText(tmp.file("flat.csv"),
            "id,px,py,pz\nA,0,0,0.1\nB,10,0,0.1\nC,0,10,0.1\nD,10,10,0.2\nE,-5,3,0\nF,-20,-20,0\nG,20,-30,0."
            "1\nH,-30,25,0\n");
  r = cli("match --cad plane.stl --data flat.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("metrofit-cli: flat.csv: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("normal"), std::string::npos) << r.err;
  r = cli("match --cad plane.stl --data flat.csv --lock rz,x,y --out r.json", tmp);
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace metrofit::test
