// metrofit-cli fit-element end to end: the contract's keys, the real Wenzel CMM files read as they are
// (tab-separated, `ID x y z Residues ø`) with the CMM's own residuals as the answer, minimum zone with
// its certificate, --robust, --unit, and bad input (exit 2, one line). Run under C, de_DE and pl_PL
// (LOCALES): the numbers in the JSON keep '.'.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "testsupport.h"

namespace metrofit::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A sphere (centre (10, -5, 3), r 20) sampled over a cap of 120 deg, as CSV with ids; `stray` adds 2 mm
/// to the radius of points P7 and P19.
std::string sphereCsv(bool stray, const std::string& header = "id,x_mm,y_mm,z_mm", double scale = 1.0) {
  std::string s = header + "\n";
  int k = 0;
  for (int ring = 0; ring <= 4; ++ring) {
    const double th = 120.0 * kPi / 180.0 * ring / 4.0;
    const int per = ring == 0 ? 1 : 9;
    for (int j = 0; j < per; ++j, ++k) {
      const double ph = 2.0 * kPi * (j + 0.3 * ring) / per;
      double r = 20.0 + 0.001 * std::sin(7.0 * k);
      if (stray && (k == 7 || k == 19)) r += 2.0;
      const double x = 10.0 + r * std::sin(th) * std::cos(ph), y = -5.0 + r * std::sin(th) * std::sin(ph),
                   z = 3.0 + r * std::cos(th);
      char line[160];
      std::snprintf(line, sizeof line, "P%d,%.9g,%.9g,%.9g\n", k, x * scale, y * scale, z * scale);
      s += line;
    }
  }
  return s;
}

nlohmann::json parse(const std::string& text) {
  return nlohmann::json::parse(text);
}

TEST(FitElementCli, SphereHasTheContractKeys) {
  TempDir tmp;
  writeText(tmp.file("s.csv"), sphereCsv(false));
  const CliRun r = cli("fit-element --data s.csv --element sphere --out out.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("fit-element: sphere (ls) of 37 points"), std::string::npos) << r.err;
  const auto j = parse(readText(tmp.file("out.json")));
  for (const char* key : {"element", "criterion", "centre_mm", "axis", "radius_mm", "form_mm", "rmse_mm",
                          "residuals_mm", "excluded", "condition"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["element"], "sphere");
  EXPECT_EQ(j["criterion"], "ls");
  // The radii carry +-1 um of deterministic form error on a 120 deg cap (noise amplification about
  // 2): the centre is known to a few um, not better.
  EXPECT_NEAR(j["centre_mm"][0].get<double>(), 10.0, 3e-3);
  EXPECT_NEAR(j["centre_mm"][1].get<double>(), -5.0, 3e-3);
  EXPECT_NEAR(j["centre_mm"][2].get<double>(), 3.0, 3e-3);
  EXPECT_NEAR(j["radius_mm"].get<double>(), 20.0, 3e-3);
  EXPECT_TRUE(j["axis"].is_null());
  EXPECT_EQ(j["residuals_mm"].size(), 37u);
  EXPECT_TRUE(j["excluded"].empty());
  EXPECT_EQ(j["condition"].get<std::string>().rfind("well conditioned", 0), 0u);
  EXPECT_TRUE(j["standard_errors"].contains("radius_mm"));
  // Numbers are written with '.' whatever the locale (the test runs under de_DE and pl_PL too).
  const std::string text = readText(tmp.file("out.json"));
  EXPECT_EQ(text.find("\"radius_mm\": 20,"), std::string::npos);
  EXPECT_NE(text.find("\"form_mm\": 0."), std::string::npos) << text.substr(0, 400);
}

TEST(FitElementCli, WenzelFilesGiveTheCmmResiduals) {
  const auto dir = realData("cmm-wenzel-lens-points");
  METROFIT_REQUIRE_PATH(dir / "CIR4_1");
  for (const auto& [file, element] : std::vector<std::pair<std::string, std::string>>{
           {"CIR4_1", "circle"}, {"SPH1_1", "sphere"}, {"SPH2_2", "sphere"}, {"CIR5_3", "circle"}}) {
    TempDir tmp;
    const CliRun r = cli("fit-element --data '" + (dir / file).string() + "' --element " + element, tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = parse(r.out);
    // The file's own residuals, column 5.
    std::ifstream in(dir / file);
    std::string line;
    std::getline(in, line);
    std::size_t i = 0;
    double worst = 0.0;
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::size_t at = 0;
      for (std::size_t tab; (tab = line.find('\t', at)) != std::string::npos; at = tab + 1)
        cells.push_back(line.substr(at, tab - at));
      cells.push_back(line.substr(at));
      ASSERT_GE(cells.size(), 5u);
      const double cmm = cnumber(cells[4]);
      worst = std::max(worst, std::abs(j["residuals_mm"][i].get<double>() - cmm));
      ++i;
    }
    EXPECT_EQ(i, j["residuals_mm"].size());
    EXPECT_LE(worst, 0.001 + 1e-9) << file;
    std::printf("[ measured ] CLI %s: max |ours - CMM| = %.4f mm; %s\n", file.c_str(), worst,
                j["condition"].get<std::string>().c_str());
    if (element == "sphere") EXPECT_EQ(j["condition"].get<std::string>().rfind("badly conditioned", 0), 0u);
  }
}

TEST(FitElementCli, MinimaxCarriesACertificateAndIsNarrower) {
  TempDir tmp;
  std::string csv = "x_mm,y_mm,z_mm\n";
  for (int k = 0; k < 7; ++k) {
    const double ph = 2.0 * kPi * k / 7.0, r = 30.0 + 0.01 * std::cos(3.0 * k + 1.0);
    char line[120];
    std::snprintf(line, sizeof line, "%.9g,%.9g,0\n", r * std::cos(ph), r * std::sin(ph));
    csv += line;
  }
  writeText(tmp.file("c.csv"), csv);
  const CliRun ls = cli("fit-element --data c.csv --element circle --out ls.json", tmp);
  const CliRun mz = cli("fit-element --data c.csv --element circle --criterion minimax --out mz.json", tmp);
  ASSERT_EQ(ls.code, 0) << ls.err;
  ASSERT_EQ(mz.code, 0) << mz.err;
  EXPECT_NE(mz.err.find("zone certified"), std::string::npos) << mz.err;
  const auto a = parse(readText(tmp.file("ls.json"))), b = parse(readText(tmp.file("mz.json")));
  EXPECT_EQ(b["criterion"], "minimax");
  EXPECT_LE(b["form_mm"].get<double>(), a["form_mm"].get<double>());
  ASSERT_TRUE(b.contains("certificate"));
  EXPECT_TRUE(b["certificate"]["holds"].get<bool>());
  EXPECT_GE(b["certificate"]["contacts"].size(), 4u);
  for (const auto& c : b["certificate"]["contacts"]) {
    EXPECT_TRUE(c["point"].is_number());  // no id column: 1-based rows
    EXPECT_NEAR(std::abs(c["residual_mm"].get<double>()), b["form_mm"].get<double>() / 2.0, 1e-9);
  }
}

TEST(FitElementCli, RobustListsTheStrayIdsAndUnitsConvert) {
  TempDir tmp;
  writeText(tmp.file("s.csv"), sphereCsv(true));
  const CliRun r = cli("fit-element --data s.csv --element sphere --robust --out out.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = parse(readText(tmp.file("out.json")));
  EXPECT_EQ(j["excluded"], nlohmann::json::parse(R"(["P7", "P19"])"));
  EXPECT_NEAR(j["radius_mm"].get<double>(), 20.0, 1e-3);
  EXPECT_EQ(j["robust"]["k"].get<double>(), 3.5);
  // Metres in columns id,x,y,z with --unit m; fixed radius.
  writeText(tmp.file("m.csv"), sphereCsv(false, "id,x,y,z", 1e-3));
  const CliRun m = cli("fit-element --data m.csv --element sphere --unit m --radius 20 --out m.json", tmp);
  ASSERT_EQ(m.code, 0) << m.err;
  const auto k = parse(readText(tmp.file("m.json")));
  EXPECT_NEAR(k["centre_mm"][0].get<double>(), 10.0, 1e-3);
  EXPECT_EQ(k["radius_mm"].get<double>(), 20.0);
  EXPECT_TRUE(k["fixed_radius"].get<bool>());
}

TEST(FitElementCli, BadInputExits2WithOneLine) {
  TempDir tmp;
  writeText(tmp.file("two.csv"), "x_mm,y_mm\n1,2\n3,4\n5,6\n");
  writeText(tmp.file("few.csv"), "x_mm,y_mm,z_mm\n1,0,0\n0,1,0\n");
  writeText(tmp.file("text.csv"), "x_mm,y_mm,z_mm\n1,0,0\n0,1,0\nx,1,0\n0,0,1\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"fit-element --data two.csv --element plane", "two.csv: field 'z_mm': missing column"},
      {"fit-element --data few.csv --element circle", "few.csv: a circle needs at least 3 points, got 2"},
      {"fit-element --data text.csv --element plane", "text.csv:4:1: field 'x_mm'"},
      {"fit-element --data few.csv --element torus", "--element"},
      {"fit-element --data few.csv --element line --radius 3", "--radius"},
      {"fit-element --data few.csv --element sphere --radius -1", "--radius"},
      {"fit-element --data few.csv --element plane --unit m", "--unit"},
  };
  for (const auto& [args, expect] : cases) {
    const CliRun r = cli(args + " --out out.json", tmp);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp.file("out.json"))) << args;
  }
}

}  // namespace
}  // namespace metrofit::test
