// End-to-end tests of `metrofit-cli thermal ...` (docs/file-formats.md#command-line): the JSON of
// `thermal fit`, exit codes, one-line errors naming file and field, predict / hysteresis / modular.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/cli_runner.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

nlohmann::json readJson(const test::TempDir& tmp, const std::string& name) {
  return parseJson(test::readText(tmp.file(name)), name);
}

/// The simulated spindle log (the demo's thermal_demo.csv is seed 7).
void spindleLog(const test::TempDir& tmp) {
  ASSERT_EQ(cli("simulate thermal --seed 7 --out log.csv", tmp).code, 0);
}

TEST(ThermalCli, FitWritesTheContractKeysForEveryModel) {
  test::TempDir tmp;
  spindleLog(tmp);
  for (const char* model : {"gnnmci", "gmc", "mlp"}) {
    const std::string out = std::string(model) + ".json";
    const CliRun r =
        cli(std::string("thermal fit --data log.csv --target disp_z_um --inputs T1,T2,T3,T4 --model ") +
                model + " --train-fraction 0.5 --out " + out,
            tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_EQ(
        r.err.rfind(std::string("thermal fit: ") + model + " on log.csv, 241 fit / 240 held-out rows", 0), 0u)
        << r.err;
    EXPECT_TRUE(r.out.empty());
    const nlohmann::json j = readJson(tmp, out);
    EXPECT_EQ(j["model"], model);
    for (const char* key : {"fit_rmse", "heldout_rmse", "R", "E", "residual_band"})
      EXPECT_TRUE(j[key].is_number()) << model << " " << key;
    EXPECT_EQ(j["train_rows"], 241);
    EXPECT_EQ(j["heldout_rows"], 240);
    EXPECT_EQ(j["train_fraction"], 0.5);
    EXPECT_EQ(j["inputs"], (nlohmann::json{"T1", "T2", "T3", "T4"}));
    EXPECT_TRUE(j["parameters"].is_object());
    EXPECT_EQ(j["heldout"]["RMSE"], j["heldout_rmse"]);
    EXPECT_EQ(j["heldout"]["R"], j["R"]);
    EXPECT_EQ(j["fit"]["RMSE"], j["fit_rmse"]);
    EXPECT_EQ(j.contains("trace"), std::string(model) == "gnnmci");
  }
  const nlohmann::json g = readJson(tmp, "gnnmci.json");
  EXPECT_EQ(g["trace"].size(), 101u);
  EXPECT_EQ(g["training"]["method"], "pso-ls");
  EXPECT_LT(g["heldout_rmse"].get<double>(), 1.5);
  EXPECT_GT(g["parameters"]["w11"].get<double>(), 0.0);
}

TEST(ThermalCli, RegressionModelsAndAutoOnTheRealLog) {
  // Linear / lag / dlag / auto on the real CAIVIAC log (ch1, t5, t9 and the spindle
  // speed); auto names what it chose and every candidate's blocked-CV score; every result says
  // whether the held-out test passed; the chosen model's JSON goes through thermal predict.
  test::TempDir tmp;
  const std::string data = (test::sourceDir() / "resources/demo/data/thermal_caiviac.csv").string();
  const std::string base =
      "thermal fit --data " + data + " --target ch1_um --inputs t5_degC,t9_degC,spindle_rpm";
  for (const char* model : {"linear", "lag", "dlag"}) {
    const CliRun r = cli(base + " --model " + model + " --out " + model + ".json", tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    const nlohmann::json j = readJson(tmp, std::string(model) + ".json");
    EXPECT_EQ(j["model"], model);
    EXPECT_EQ(j["train_rows"], 5558);
    EXPECT_TRUE(j["heldout_verdict"]["passed"].is_boolean());
    EXPECT_FALSE(j.contains("seed"));
    EXPECT_EQ(j["parameters"]["terms"].size(), std::string(model) == "dlag" ? 6u : 3u);
  }
  const CliRun r = cli(base + " --model auto --out auto.json --save-model m.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("(auto: blocked CV RMSE on the fit rows linear "), std::string::npos) << r.err;
  const nlohmann::json j = readJson(tmp, "auto.json");
  EXPECT_EQ(j["selection"]["requested"], "auto");
  EXPECT_EQ(j["selection"]["chosen"], j["model"]);
  EXPECT_EQ(j["selection"]["folds"], 5);
  for (const char* c : {"linear", "lag", "dlag", "gmc"})
    EXPECT_TRUE(j["selection"]["cv_rmse"].contains(c)) << c;
  EXPECT_EQ(j["heldout_verdict"]["passed"], true);
  EXPECT_FALSE(j.contains("heldout_check"));  // diagnose's name for the held-out rows' residual check
  const nlohmann::json lin = readJson(tmp, "linear.json");
  EXPECT_LT(j["heldout_rmse"].get<double>(), lin["heldout_rmse"].get<double>());
  const CliRun p = cli("thermal predict --model-file m.json --data " + data + " --out comp.csv", tmp);
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(p.err.find("against ch1_um"), std::string::npos) << p.err;
}

TEST(ThermalCli, SameSeedSameResultAndModelDefaultFraction) {
  test::TempDir tmp;
  spindleLog(tmp);
  const std::string args =
      "thermal fit --data log.csv --target disp_z_um --inputs T1,T2 --iterations 20 --seed 5";
  const CliRun a = cli(args, tmp), b = cli(args, tmp);  // JSON on stdout
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(parseJson(a.out, "stdout")["seed"], 5);
  EXPECT_NE(cli(args + "0", tmp).out, a.out);  // seed 50
  // Table 3: the MLP's default split is 70 / 30.
  const CliRun m = cli("thermal fit --data log.csv --target disp_z_um --inputs T1,T2 --model mlp", tmp);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(parseJson(m.out, "stdout")["train_rows"], 337);
}

TEST(ThermalCli, BadInputExits2WithOneLineNamingFileAndField) {
  test::TempDir tmp;
  std::string constant = "time_min,T1,T2,d_um\n";
  for (int k = 0; k < 20; ++k)
    constant +=
        std::to_string(k) + "," + std::to_string(20 + 0.1 * k) + ",21.5," + std::to_string(-0.2 * k) + "\n";
  test::writeText(tmp.file("c.csv"), constant);
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"thermal fit --data c.csv --target d_um --inputs T1,T2 --out r.json",
       "metrofit-cli: c.csv: field 'T2': input is constant (21.5) on all 10 fitting rows; a model cannot "
       "learn from it "
       "(drop it from --inputs)\n"},
      {"thermal fit --data c.csv --target d_um --inputs T1,T9 --out r.json",
       "metrofit-cli: c.csv: field 'T9': no such column in the thermal log (it has: T1, T2, d_um)\n"},
      {"thermal fit --data c.csv --target d_um --inputs T1 --model mlp --out r.json",
       "metrofit-cli: c.csv: 14 fitting rows are too few: the MLP with 1 input and 10 hidden neurons has 31 "
       "weights "
       "and needs at least 32 rows (use more rows, a larger --train-fraction or fewer inputs)\n"},
      {"thermal hysteresis --data c.csv --target d_um --inputs T2 --out h.json",
       "metrofit-cli: c.csv: field 'T2': is constant; there is no loop to analyse\n"},
  };
  for (const auto& c : cases) {
    const CliRun r = cli(c.args, tmp);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.err, c.expected) << c.args;
  }
  const CliRun f = cli("thermal fit --data c.csv --target d_um --inputs T1 --train-fraction 0.99", tmp);
  EXPECT_EQ(f.code, 2);
  EXPECT_EQ(lines(f.err), 1);
  EXPECT_NE(f.err.find("--train-fraction"), std::string::npos) << f.err;
  const CliRun m = cli("thermal fit --data c.csv --target d_um --inputs T1 --model ann", tmp);
  EXPECT_EQ(m.code, 2);
  EXPECT_NE(m.err.find("--model"), std::string::npos) << m.err;
  // Nothing half-written is left behind.
  EXPECT_EQ(test::listFolder(tmp.path()), (std::vector<std::string>{"c.csv"}));
}

// A log of sensor columns only: --sample-interval gives its time on every
// command that reads a thermal log; without it, with a time column or without a unit: exit 2.
TEST(ThermalCli, SampleIntervalReadsALogWithoutATimeColumn) {
  test::TempDir tmp;
  spindleLog(tmp);
  // log.csv without its time_min column (one row a minute): sensors.csv.
  const std::string text = test::readText(tmp.file("log.csv"));
  std::string sensors;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::string line = text.substr(pos, end - pos);
    sensors += line.substr(line.find(',') + 1) + "\n";
    pos = end == std::string::npos ? text.size() : end + 1;
  }
  test::writeText(tmp.file("sensors.csv"), sensors);
  const std::string fit = "thermal fit --target disp_z_um --inputs T1,T2,T3,T4 --model linear ";
  ASSERT_EQ(cli(fit + "--data log.csv --out with_time.json", tmp).code, 0);
  const CliRun r = cli(fit + "--data sensors.csv --sample-interval 1min --out interval.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  // The same rows a minute apart: the same fit as with the time column.
  const auto a = readJson(tmp, "with_time.json"), b = readJson(tmp, "interval.json");
  EXPECT_DOUBLE_EQ(a["heldout_rmse"].get<double>(), b["heldout_rmse"].get<double>());
  EXPECT_EQ(cli(fit + "--data sensors.csv --sample-interval 60s --out s.json", tmp).code, 0);
  EXPECT_DOUBLE_EQ(readJson(tmp, "s.json")["heldout_rmse"].get<double>(), b["heldout_rmse"].get<double>());

  for (const char* args :
       {"--data sensors.csv", "--data sensors.csv --sample-interval 60",
        "--data sensors.csv --sample-interval 5 parsecs", "--data log.csv --sample-interval 1min"}) {
    const CliRun bad = cli(fit + args, tmp);
    EXPECT_EQ(bad.code, 2) << args << ": " << bad.err;
    EXPECT_EQ(lines(bad.err), 1) << bad.err;
  }
  EXPECT_NE(cli(fit + "--data sensors.csv", tmp).err.find("--sample-interval"), std::string::npos);
  EXPECT_NE(cli(fit + "--data log.csv --sample-interval 1min", tmp).err.find("time_min"), std::string::npos);

  // The other readers of thermal logs.
  EXPECT_EQ(cli("thermal hysteresis --data sensors.csv --sample-interval 1min --target disp_z_um --inputs T1 "
                "--out h.json",
                tmp)
                .code,
            0);
  EXPECT_EQ(
      cli("diagnose thermal --data sensors.csv --sample-interval 1min --target disp_z_um --inputs T2,T4 "
          "--out d.json",
          tmp)
          .code,
      0);
  // A project remembers the interval; its report reads the log with it.
  ASSERT_EQ(cli("project new p.metrofit", tmp).code, 0);
  const CliRun add = cli("project add p.metrofit thermal-log sensors.csv --sample-interval 1min", tmp);
  ASSERT_EQ(add.code, 0) << add.err;
  EXPECT_DOUBLE_EQ(readJson(tmp, "p.metrofit")["datasets"][0]["sample_interval_min"].get<double>(), 1.0);
  const CliRun list = cli("project list p.metrofit", tmp);
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_EQ(parseJson(list.out, "list")[0]["rows"].get<long>(), 481);
  EXPECT_EQ(cli("project add p.metrofit probe-points sensors.csv --id x --sample-interval 1min", tmp).code,
            2);
}

TEST(ThermalCli, PredictWritesCompensationValues) {
  test::TempDir tmp;
  spindleLog(tmp);
  const CliRun f =
      cli("thermal fit --data log.csv --target disp_z_um --inputs T1,T2,T3 --save-model m.json --out r.json",
          tmp);
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_EQ(readJson(tmp, "m.json")["format"], "metrofit-thermal-model");
  ASSERT_EQ(cli("simulate thermal --seed 8 --out new.csv", tmp).code, 0);
  const CliRun p = cli("thermal predict --model-file m.json --data new.csv --out c.csv", tmp);
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_EQ(lines(p.err), 1);
  EXPECT_EQ(p.err.rfind("thermal predict: gnnmci model on new.csv, 481 rows", 0), 0u) << p.err;
  const CsvTable t = readCsvFile(tmp.file("c.csv"));
  EXPECT_EQ(t.header(),
            (std::vector<std::string>{"time_min", "predicted_disp_z_um", "compensation_disp_z_um"}));
  ASSERT_EQ(t.rowCount(), 481u);
  double peak = 0.0;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    EXPECT_EQ(t.number(r, 2), -t.number(r, 1) + 0.0);
    peak = std::max(peak, std::abs(t.number(r, 1)));
  }
  EXPECT_GT(peak, 20.0);  // the spindle grows by tens of um
  // A broken model file is bad input naming the field.
  test::writeText(tmp.file("bad.json"),
                  R"({"format": "metrofit-thermal-model", "version": 1, "model": "gmc"})");
  const CliRun b = cli("thermal predict --model-file bad.json --data new.csv --out x.csv", tmp);
  EXPECT_EQ(b.code, 2);
  EXPECT_EQ(b.err, "metrofit-cli: bad.json: field 'target': missing\n");
  EXPECT_FALSE(std::filesystem::exists(tmp.file("x.csv")));
}

TEST(ThermalCli, HysteresisAndModular) {
  test::TempDir tmp;
  for (const char* t : {"z", "c", "combined"})
    ASSERT_EQ(cli(std::string("thermal simulate --test ") + t + " --out " + t + ".csv", tmp).code, 0);
  const std::string cols = " --target disp_z_um --inputs FBG1_ue,FBG2_ue,FBG3_ue,FBG4_ue,T2";
  const CliRun h = cli("thermal hysteresis --data z.csv" + cols + " --out h.json", tmp);
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_EQ(lines(h.err), 1);
  const nlohmann::json hj = readJson(tmp, "h.json");
  ASSERT_EQ(hj["sensors"].size(), 5u);
  EXPECT_EQ(hj["sensors"][4]["sensor"], "T2");
  EXPECT_GT(hj["sensors"][4]["tau_min"].get<double>(), 0.0);
  for (const char* key : {"loop_area", "normalised_loop_area", "r2", "r2_static"})
    EXPECT_TRUE(hj["sensors"][0][key].is_number()) << key;
  const CliRun m =
      cli("thermal modular --train z.csv --train c.csv --test combined.csv" + cols + " --out m.json", tmp);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(lines(m.err), 1);
  const nlohmann::json mj = readJson(tmp, "m.json");
  EXPECT_EQ(mj["train"], (nlohmann::json{"z.csv", "c.csv"}));
  EXPECT_GE(mj["reduction_peak"].get<double>(), 0.85);
  for (const char* key : {"R", "RMSE", "E", "residual_band", "error_peak"})
    EXPECT_TRUE(mj[key].is_number()) << key;
}

// Modules identified on their own tests (Z module on the Z test with the Z motor sensors, C module on
// the C test with the C motor sensor), the combined test predicted as their sum; the C module saved and
// taken back with --module-model while Z is identified again gives the same prediction; bad module
// specifications exit 2 naming the option.
TEST(ThermalCli, ModulesEachOnTheirOwnTestAndOneTakenFromASavedModel) {
  test::TempDir tmp;
  for (const char* t : {"z", "c", "combined"})
    ASSERT_EQ(cli(std::string("thermal simulate --test ") + t + " --out " + t + ".csv", tmp).code, 0);
  const std::string common = " --test combined.csv --target disp_z_um --model dlag";
  const CliRun m = cli("thermal modular --module z:z.csv:T5,T6 --module c:c.csv:T1" + common +
                           " --save-modules . --out m.json",
                       tmp);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(lines(m.err), 1);
  EXPECT_NE(m.err.find("2 modules"), std::string::npos) << m.err;
  const nlohmann::json mj = readJson(tmp, "m.json");
  ASSERT_EQ(mj["modules"].size(), 2u);
  EXPECT_EQ(mj["modules"][0]["name"], "z");
  EXPECT_EQ(mj["modules"][0]["inputs"], (nlohmann::json{"T5", "T6"}));
  EXPECT_EQ(mj["modules"][0]["identified_on"], "z.csv");
  EXPECT_EQ(mj["modules"][1]["inputs"], (nlohmann::json{"T1"}));
  // Both drives cool the ram's growth (negative) and neither module explains it all alone.
  const double zPeak = mj["modules"][0]["contribution_peak"].get<double>();
  const double cPeak = mj["modules"][1]["contribution_peak"].get<double>();
  EXPECT_LT(zPeak, 0.0);
  EXPECT_LT(cPeak, 0.0);
  EXPECT_LT(std::abs(zPeak), mj["error_peak"].get<double>());
  EXPECT_LT(std::abs(cPeak), mj["error_peak"].get<double>());
  EXPECT_GE(mj["reduction_peak"].get<double>(), 0.9);

  const CliRun again = cli(
      "thermal modular --module z:z.csv:T5,T6 --module-model c:c.json" + common + " --out again.json", tmp);
  ASSERT_EQ(again.code, 0) << again.err;
  const nlohmann::json aj = readJson(tmp, "again.json");
  EXPECT_TRUE(aj["modules"][1]["identified_on"].is_null());
  EXPECT_DOUBLE_EQ(aj["RMSE"].get<double>(), mj["RMSE"].get<double>());
  EXPECT_DOUBLE_EQ(aj["modules"][1]["contribution_peak"].get<double>(), cPeak);

  for (const auto& [args, field] : std::vector<std::pair<std::string, std::string>>{
           {" --module z.csv:T5", "--module"},
           {" --module z:z.csv:T5 --module z:c.csv:T1", "--module"},
           {" --module z:z.csv:T5 --train c.csv", "--module"},
           {" --module z:z.csv:NOPE", "NOPE"},
           {" --module-model c", "--module-model"}}) {
    const CliRun bad = cli("thermal modular" + args + common, tmp);
    EXPECT_EQ(bad.code, 2) << args << "\n" << bad.err;
    EXPECT_EQ(lines(bad.err), 1) << args << "\n" << bad.err;
    EXPECT_NE(bad.err.find(field), std::string::npos) << args << "\n" << bad.err;
  }
}

}  // namespace
}  // namespace metrofit
