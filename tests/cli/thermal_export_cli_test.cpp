// metrofit-cli thermal export (core/thermal/control_export.h): every form byte-identical under
// C.UTF-8, de_DE.UTF-8 and pl_PL.UTF-8, refusals (grey models, the MLP in the vendor forms) and bad
// options exit 2 with one line naming the model file and the form, and write nothing. What the files
// compute is checked in tests/core/thermal/control_export_test.cpp (an ST interpreter over the real log).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_runner.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

const char* kForms[] = {"st", "siemens", "heidenhain", "isg", "csv"};

const std::string kGnnmci = R"({"format": "metrofit-thermal-model", "version": 1, "model": "gnnmci",
  "target": "d_um", "inputs": ["T1"], "time_unit_min": 1.0, "grey": {"b": [0.2], "b1": 0.5, "u": 0.0}})";

const std::string kMlp =
    R"({"format": "metrofit-thermal-model", "version": 1, "model": "mlp", "target": "d_um",
  "inputs": ["T1", "T2"], "time_unit_min": 0.25, "mlp": {"hidden": 2, "in_min": [0, 0], "in_max": [5, 3],
  "out_min": -2.5, "out_max": 3.25, "w": [[0.5, -0.25], [1.5, 0.75]], "c": [0.1, -0.2], "v": [0.3, -0.6],
  "v0": 0.05}})";

int cliUnderLocale(const std::string& locale, const std::string& args, const test::TempDir& tmp) {
  const std::string cmd = "cd '" + tmp.path().string() + "' && LC_ALL=" + locale + " '" +
                          (test::binDir() / "metrofit-cli").string() + "' " + args + " >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ThermalExportCli, EveryFormIsByteIdenticalUnderEveryLocale) {
  test::TempDir tmp;
  const std::string data = (test::sourceDir() / "resources/demo/data/thermal_caiviac.csv").string();
  const CliRun fit =
      cli("thermal fit --data '" + data +
              "' --target ch1_um --inputs t5_degC,t9_degC,spindle_rpm --model lag --save-model "
              "lag.json --out fit.json",
          tmp);
  ASSERT_EQ(fit.code, 0) << fit.err;
  test::writeText(tmp.file("mlp.json"), kMlp);
  struct Case {
    std::string model, form;
  };
  std::vector<Case> cases;
  for (const char* f : kForms) cases.push_back({"lag.json", f});
  cases.push_back({"mlp.json", "st"});
  cases.push_back({"mlp.json", "csv"});
  for (const Case& c : cases) {
    const std::string plain = "thermal export --model " + c.model + " --format " + c.form + " --out out.txt";
    std::string first;
    for (const char* loc : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
      ASSERT_EQ(cliUnderLocale(loc, plain, tmp), 0) << c.model << " " << c.form << " " << loc;
      const std::string text = test::readText(tmp.file("out.txt"));
      if (first.empty())
        first = text;
      else
        EXPECT_EQ(text, first) << c.model << " as " << c.form << " under " << loc;
    }
    ASSERT_FALSE(first.empty());
    EXPECT_NE(first.find("Metrofit thermal compensation, form '" + c.form + "'"), std::string::npos);
    EXPECT_NE(first.find("Sample period"), std::string::npos);
    EXPECT_NE(first.find("Limits"), std::string::npos);
  }
  // --grid, --period-s and --axis.
  const CliRun g =
      cli("thermal export --model lag.json --format csv --grid spindle_rpm=0:4000:2000 --out t.csv", tmp);
  ASSERT_EQ(g.code, 0) << g.err;
  EXPECT_NE(test::readText(tmp.file("t.csv")).find("\n0,0,4000,"), std::string::npos);
  const CliRun m = cli("thermal export --model mlp.json --format csv --grid spindle_rpm=0:4000:2000", tmp);
  EXPECT_EQ(m.code, 2) << m.err;
  EXPECT_NE(m.err.find("field '--grid': 'spindle_rpm' is not an input"), std::string::npos) << m.err;
  const CliRun p = cli("thermal export --model lag.json --format siemens --axis X --period-s 1", tmp);
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(p.out.find("$MA_TEMP_COMP_TYPE[X1]=1"), std::string::npos) << p.out;
  EXPECT_NE(p.out.find("here T = 1 s"), std::string::npos) << p.out;
  const CliRun r = cli("thermal export --model lag.json --format st --out fb.st", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err, "thermal export: lag model of ch1_um (lag.json) as st to fb.st\n");
  EXPECT_NE(test::readText(tmp.file("fb.st")).find("FUNCTION_BLOCK FB_METROFIT_THERMAL_ch1_um\n"),
            std::string::npos);
  // Standard output without --out.
  const CliRun s = cli("thermal export --model lag.json --format isg", tmp);
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("\nlr_param.temp_comp 1\n"), std::string::npos) << s.out;
}

TEST(ThermalExportCli, ModelsThatCannotTakeAFormExit2NamingTheFileAndWhy) {
  test::TempDir tmp;
  test::writeText(tmp.file("g.json"), kGnnmci);
  test::writeText(tmp.file("mlp.json"), kMlp);
  for (const char* f : kForms) {
    const CliRun r = cli(std::string("thermal export --model g.json --format ") + f + " --out out.txt", tmp);
    EXPECT_EQ(r.code, 2) << f << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_EQ(
        r.err.rfind(
            std::string("metrofit-cli: g.json: field 'model': the gnnmci model cannot be exported as ") + f +
                ": ",
            0),
        0u)
        << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_FALSE(std::filesystem::exists(tmp.file("out.txt"))) << f;
  }
  for (const char* f : {"siemens", "heidenhain", "isg"}) {
    const CliRun r =
        cli(std::string("thermal export --model mlp.json --format ") + f + " --out out.txt", tmp);
    EXPECT_EQ(r.code, 2) << f << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(std::string("mlp.json: field 'model': the mlp model cannot be exported as ") + f),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("nonlinear"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp.file("out.txt"))) << f;
  }
  // Bad options: an unknown form, a malformed grid, a negative limit.
  for (const char* args : {"--format fanuc", "--format csv --grid T1=0:1", "--format csv --grid T1=a:b:c",
                           "--format st --limit-um -1"}) {
    const CliRun r = cli(std::string("thermal export --model mlp.json --out out.txt ") + args, tmp);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp.file("out.txt"))) << args;
  }
}

}  // namespace
}  // namespace metrofit
