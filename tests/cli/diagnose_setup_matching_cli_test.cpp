// End-to-end tests of `metrofit-cli diagnose setup` and `diagnose matching`
// (docs/file-formats.md#diagnose-result): the JSON keys, what is found in simulated data, exit codes and
// one-line errors.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_runner.h"
#include "core/io/json_util.h"
#include "core/matching/probe_points.h"
#include "core/setup/model.h"
#include "core/sim/effects_matching.h"
#include "core/sim/effects_setup.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

std::string paperModel() {
  return (test::sourceDir() / "resources/demo/setup/paper_example.json").string();
}

std::string q(const std::string& s) {
  return "'" + s + "'";
}

void checkContractKeys(const nlohmann::json& j, const std::string& domain) {
  EXPECT_EQ(j["domain"], domain);
  for (const char* part : {"baseline", "final"}) {
    ASSERT_TRUE(j.contains(part)) << part;
    EXPECT_TRUE(j[part].contains("rmse"));
    EXPECT_TRUE(j[part].contains("max_abs"));
  }
  ASSERT_TRUE(j["effects"].is_array());
  for (const auto& e : j["effects"])
    for (const char* key : {"name", "accepted", "parameters", "rmse_before", "rmse_after", "evidence"})
      EXPECT_TRUE(e.contains(key)) << key;
}

TEST(DiagnoseSetupCli, FindsToolWearInASimulatedSeries) {
  test::TempDir tmp;
  const setup::Model model = setup::readModel(paperModel());
  SetupEffectsSimOptions o;
  o.base.parts = 10;
  o.base.w2 = 0.01;
  o.base.resolutionMm = 0.0001;
  o.base.seed = 21;
  o.toolWearMmPerPart = {{"T23", 0.003}};
  test::writeText(tmp.file("r.csv"), simulateSetupEffectsReport(model, o));
  const CliRun r = cli("diagnose setup --model " + q(paperModel()) + " --data r.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  checkContractKeys(j, "setup");
  EXPECT_EQ(j["effects"][0]["name"], "tool_wear:T23");
  EXPECT_EQ(j["effects"][0]["accepted"], true);
  EXPECT_NEAR(j["effects"][0]["parameters"]["mm_per_part"].get<double>(), 0.003, 0.0009);
  EXPECT_EQ(j["effects"].size(), 12u);
  for (std::size_t i = 1; i < j["effects"].size(); ++i) EXPECT_EQ(j["effects"][i]["accepted"], false);
  EXPECT_LT(j["final"]["rmse"].get<double>(), j["baseline"]["rmse"].get<double>());
  // --out writes the same JSON.
  const CliRun w = cli("diagnose setup --model " + q(paperModel()) + " --data r.csv --out d.json", tmp);
  ASSERT_EQ(w.code, 0) << w.err;
  EXPECT_EQ(readJsonFile(tmp.file("d.json")), j);
}

TEST(DiagnoseSetupCli, BadInputsExitTwoWithOneLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("bad.csv"),
                  "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n"
                  "1,10,P9.D9,12,12.01,-0.1,0.1\n");
  CliRun r = cli("diagnose setup --model " + q(paperModel()) + " --data bad.csv", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.csv:2"), std::string::npos) << r.err;
  r = cli("diagnose setup --data bad.csv", tmp);  // --model is required
  EXPECT_EQ(r.code, 2) << r.err;
  r = cli("diagnose setup --model " + q(paperModel()) + " --data missing.csv", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
}

TEST(DiagnoseMatchingCli, FindsTheDistortionOfAHolePlate) {
  test::TempDir tmp;
  HolePlateSimOptions o;
  o.holes = 300;
  o.seed = 4;
  MatchingEffects e;
  e.distortionPpm = 60.0;
  e.distortionAngleDeg = 35.0;
  test::writeText(tmp.file("p.csv"), probePointsToCsv(simulateHolePlate(o, e)));
  const CliRun r = cli("diagnose matching --data p.csv --tolerance 0.05", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  checkContractKeys(j, "matching");
  EXPECT_EQ(j["effects"][0]["name"], "distortion");
  EXPECT_EQ(j["effects"][0]["accepted"], true);
  EXPECT_NEAR(j["effects"][0]["parameters"]["ppm"].get<double>(), 60.0, 18.0);
  EXPECT_NEAR(j["effects"][0]["parameters"]["angle_deg"].get<double>(), 35.0, 5.0);
  EXPECT_TRUE(j["effects"][0]["uncertainty"].contains("ppm"));
}

TEST(DiagnoseMatchingCli, ReadsAHoleTableAndFindsNothingInACleanPlate) {
  test::TempDir tmp;
  HolePlateSimOptions o;
  o.holes = 50;
  o.seed = 6;
  const ProbePointSet set = simulateHolePlate(o, {});
  std::string text = "Plug Plate: 9999\nDate: 2026-11-21\n\n    Meas X    Meas Y     Nom X     Nom Y\n";
  for (const ProbePoint& p : set.points) {
    char line[160];
    std::snprintf(line, sizeof line, "%10.3f%10.3f%10.3f%10.3f\n", p.measured.x(), p.measured.y(),
                  p.nominal.x(), p.nominal.y());
    text += line;
  }
  test::writeText(tmp.file("D9999_1"), text);
  const CliRun r = cli("diagnose matching --data D9999_1", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  checkContractKeys(j, "matching");
  for (const auto& eff : j["effects"]) EXPECT_EQ(eff["accepted"], false) << eff["evidence"];
  EXPECT_DOUBLE_EQ(j["final"]["rmse"].get<double>(), j["baseline"]["rmse"].get<double>());
}

TEST(DiagnoseMatchingCli, BadInputsExitTwoWithOneLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("two.csv"),
                  "id,surface,qx,qy,px,py\n"
                  "A,s,0,0,0.001,0\n"
                  "B,s,10,0,10.002,0\n");
  CliRun r = cli("diagnose matching --data two.csv", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  r = cli("diagnose matching --data two.csv --tolerance -1", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
}

}  // namespace
}  // namespace metrofit
