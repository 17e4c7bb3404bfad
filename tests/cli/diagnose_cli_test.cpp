// End-to-end tests of `metrofit-cli diagnose thermal|kinematic` (docs/file-formats.md#diagnose-result)
// on the demo data with one undeclared effect each (resources/demo/data/diagnose_*.csv):
// the JSON keys exactly, the one-line summary, atomic --out, exit codes and one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "cli/cli_runner.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

std::string demo(const std::string& name) {
  return "'" + (test::sourceDir() / "resources/demo/data" / name).string() + "'";
}

std::set<std::string> keys(const nlohmann::json& j) {
  std::set<std::string> k;
  for (auto it = j.begin(); it != j.end(); ++it) k.insert(it.key());
  return k;
}

void expectContractEffects(const nlohmann::json& j) {
  ASSERT_TRUE(j.at("effects").is_array());
  ASSERT_FALSE(j.at("effects").empty());
  for (const auto& e : j.at("effects")) {
    for (const char* k : {"name", "accepted", "parameters", "rmse_before", "rmse_after", "evidence"})
      EXPECT_TRUE(e.contains(k)) << k << " in " << e.dump();
    EXPECT_TRUE(e.at("name").is_string());
    EXPECT_TRUE(e.at("accepted").is_boolean());
    EXPECT_TRUE(e.at("parameters").is_object());
    EXPECT_TRUE(e.at("rmse_before").is_number());
    EXPECT_TRUE(e.at("rmse_after").is_number());
    EXPECT_FALSE(e.at("evidence").get<std::string>().empty());
  }
}

TEST(DiagnoseCli, ThermalFindsTheLagOfTheDemoLog) {
  test::TempDir tmp;
  const CliRun r = cli("diagnose thermal --data " + demo("diagnose_thermal.csv") +
                           " --target disp_z_um --inputs T2,T4,T_amb --out result.json",
                       tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("diagnose thermal on "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("accepted: lag:T2 (tau_min 15"), std::string::npos) << r.err;
  const nlohmann::json j = parseJson(test::readText(tmp.file("result.json")), "result.json");
  for (const char* k : {"domain", "baseline", "effects", "final"}) EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j.at("domain"), "thermal");
  EXPECT_EQ(keys(j.at("baseline")), (std::set<std::string>{"rmse", "max_abs", "heldout_rmse"}));
  EXPECT_EQ(keys(j.at("final")), (std::set<std::string>{"rmse", "max_abs", "heldout_rmse"}));
  expectContractEffects(j);
  int accepted = 0;
  for (const auto& e : j.at("effects")) {
    if (!e.at("accepted").get<bool>()) continue;
    ++accepted;
    EXPECT_EQ(e.at("name"), "lag:T2");
    EXPECT_NEAR(e.at("parameters").at("tau_min").get<double>(), 15.0, 1.5);
  }
  EXPECT_EQ(accepted, 1);
  // Before: the static model misses the lag; after: down to the noise (0.25 um).
  EXPECT_GT(j.at("baseline").at("heldout_rmse").get<double>(), 2.0);
  EXPECT_LT(j.at("final").at("heldout_rmse").get<double>(), 0.4);
  // Only the result file is left behind (atomic write).
  int files = 0;
  for (const auto& f : std::filesystem::directory_iterator(tmp.path()))
    files += f.path().filename() != ".stdout" && f.path().filename() != ".stderr";
  EXPECT_EQ(files, 1);
}

TEST(DiagnoseCli, ThermalWarnsWhenTheHeldOutErrorRises) {
  // The real CAIVIAC log, ch5 with t5, t9 declared: the effects chosen on the fit rows raise the
  // held-out rmse (7.27 -> 12.3 um); the summary line says so, and the JSON has the held-out check.
  test::TempDir tmp;
  const CliRun r = cli("diagnose thermal --data " + demo("thermal_caiviac.csv") +
                           " --target ch5_um --inputs t5_degC,t9_degC --out result.json",
                       tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("warning: the held-out rmse rose"), std::string::npos) << r.err;
  const nlohmann::json j = parseJson(test::readText(tmp.file("result.json")), "result.json");
  EXPECT_GT(j.at("final").at("heldout_rmse").get<double>(),
            j.at("baseline").at("heldout_rmse").get<double>());
  ASSERT_TRUE(j.contains("heldout_check"));
  EXPECT_TRUE(j.at("heldout_check").at("white").is_boolean());
}

TEST(DiagnoseCli, KinematicFindsTheBacklashOfTheDemoTest) {
  test::TempDir tmp;
  const CliRun r = cli("diagnose kinematic --data " + demo("diagnose_circular.csv"), tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("accepted: backlash (x_mm 0.008"), std::string::npos) << r.err;
  const nlohmann::json j = parseJson(r.out, "stdout");
  EXPECT_EQ(j.at("domain"), "kinematic");
  EXPECT_EQ(keys(j.at("baseline")), (std::set<std::string>{"rmse", "max_abs"}));
  EXPECT_EQ(keys(j.at("final")), (std::set<std::string>{"rmse", "max_abs"}));
  expectContractEffects(j);
  // Every catalogue effect is tried; besides them only generic effects of the residual's structure
  // (unexplained:<variable>), none of them accepted in the demo test.
  std::set<std::string> names;
  for (const auto& e : j.at("effects")) {
    const std::string name = e.at("name");
    if (name.starts_with("unexplained:"))
      EXPECT_FALSE(e.at("accepted").get<bool>()) << name;
    else
      names.insert(name);
  }
  EXPECT_EQ(names, (std::set<std::string>{"backlash", "scale", "cyclic", "servo_lag"}));
  EXPECT_TRUE(j.at("residual_check").at("white").get<bool>());
  const auto& first = j.at("effects").at(0);
  EXPECT_EQ(first.at("name"), "backlash");
  EXPECT_TRUE(first.at("accepted").get<bool>());
  EXPECT_NEAR(first.at("parameters").at("x_mm").get<double>(), 0.008, 0.0005);
  EXPECT_NEAR(first.at("parameters").at("y_mm").get<double>(), 0.005, 0.0005);
  EXPECT_LT(j.at("final").at("rmse").get<double>(), 0.3 * j.at("baseline").at("rmse").get<double>());
}

TEST(DiagnoseCli, ThermalDeclaredGreyModels) {
  // The demo log's only effect is a lag of T2, which GMC(1,N) and GNNMCI(1,N) have themselves.
  test::TempDir tmp;
  for (const char* m : {"gmc", "gnnmci"}) {
    const CliRun r =
        cli("diagnose thermal --data " + demo("diagnose_thermal.csv") +
                " --target disp_z_um --inputs T2,T4,T_amb --declared " + m + " --seed 3 --out r.json",
            tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("no undeclared effect found"), std::string::npos) << r.err;
    const nlohmann::json j = parseJson(test::readText(tmp.file("r.json")), "r.json");
    EXPECT_LT(j.at("final").at("rmse").get<double>(), 0.3) << m;  // the noise is 0.25 um
    for (const auto& e : j.at("effects")) EXPECT_FALSE(e.at("accepted").get<bool>()) << m;
  }
  const CliRun bad = cli("diagnose thermal --data " + demo("diagnose_thermal.csv") +
                             " --target disp_z_um --inputs T2 --declared mlp",
                         tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--declared"), std::string::npos) << bad.err;
}

TEST(DiagnoseCli, BadInputExitsTwoWithOneLine) {
  test::TempDir tmp;
  // Unknown column.
  CliRun r = cli(
      "diagnose thermal --data " + demo("diagnose_thermal.csv") + " --target disp_z_um --inputs T2,T9", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("T9"), std::string::npos) << r.err;
  // Missing required option.
  r = cli("diagnose thermal --data " + demo("diagnose_thermal.csv") + " --target disp_z_um", tmp);
  EXPECT_EQ(r.code, 2);
  // Train fraction out of range.
  r = cli("diagnose thermal --data " + demo("diagnose_thermal.csv") +
              " --target disp_z_um --inputs T2 --train-fraction 1.5",
          tmp);
  EXPECT_EQ(r.code, 2);
  // A thermal log is not a circular test.
  r = cli("diagnose kinematic --data " + demo("diagnose_thermal.csv") + " --out k.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("x_cmd_mm"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("k.json")));
  // Too few points to identify the machine.
  test::writeText(tmp.file("few.csv"), "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n0,0,0,0\n1,0,1,0\n");
  r = cli("diagnose kinematic --data few.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("few.csv"), std::string::npos) << r.err;
  // A bad feed rate; a missing file.
  r = cli("diagnose kinematic --data " + demo("diagnose_circular.csv") + " --feed -5", tmp);
  EXPECT_EQ(r.code, 2);
  r = cli("diagnose kinematic --data missing.csv", tmp);
  EXPECT_EQ(r.code, 2);
}

}  // namespace
}  // namespace metrofit
