// End-to-end tests of metrofit-cli (CONTRACT.md "Command line"): exit codes, one-line errors,
// atomic --out, the demo and the report.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/cli_runner.h"
#include "core/io/json_util.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"
#include "core/thermal/thermal_log.h"
#include "metrofit/version.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

TEST(Cli, VersionAndHelp) {
  test::TempDir tmp;
  const CliRun v = cli("--version", tmp);
  EXPECT_EQ(v.code, 0);
  EXPECT_EQ(v.out, std::string("metrofit ") + kVersion + "\n");
  const CliRun h = cli("--help", tmp);
  EXPECT_EQ(h.code, 0);
  for (const char* sub :
       {"demo", "setup", "match", "kinematic", "thermal", "diagnose", "report", "simulate"}) {
    EXPECT_NE(h.out.find(sub), std::string::npos) << sub;
  }
}

TEST(Cli, UnknownSubcommandOrOptionExits2WithOneLine) {
  test::TempDir tmp;
  for (const char* args :
       {"frobnicate", "demo --no-such-option", "", "thermal", "setup --model", "match --data x.csv"}) {
    const CliRun r = cli(args, tmp);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("metrofit-cli: ", 0), 0u) << r.err;
  }
  const CliRun u = cli("frobnicate", tmp);
  EXPECT_EQ(u.err.rfind("metrofit-cli: unknown subcommand 'frobnicate' (one of: demo, report,", 0), 0u)
      << u.err;
  const CliRun r = cli("match --data missing.csv", tmp);
  EXPECT_NE(r.err.find("missing.csv"), std::string::npos) << r.err;
  test::writeText(tmp.file("p.csv"), "id,qx,qy,px,py\n1,0,0,0,0\n2,1,0,1,0\n3,0,1,0,1\n");
  const CliRun bad = cli("match --data p.csv --tolerance -1", tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--tolerance"), std::string::npos) << bad.err;
}

TEST(Cli, BadInputFileExits2NamingFileLineAndField) {
  test::TempDir tmp;
  test::writeText(tmp.file("log.csv"), "time_min,T1,disp_z_um\n0,20,0\n1,abc,1\n2,21,2\n");
  const CliRun r = cli("thermal fit --data log.csv --target disp_z_um --inputs T1", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "metrofit-cli: log.csv:3:2: field 'T1': 'abc' is not a number\n");
  test::writeText(tmp.file("good.csv"), "time_min,T1,disp_z_um\n0,20,0\n1,20.5,1\n2,21,2\n");
  const CliRun c = cli("thermal fit --data good.csv --target disp_z_um --inputs T7", tmp);
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("field 'T7'"), std::string::npos) << c.err;
  test::writeText(tmp.file("pts.csv"), "id,qx,qy,px,py\n1,0,0,0,0\n1,1,0,1,0\n3,0,1,0,1\n");
  const CliRun m = cli("match --data pts.csv", tmp);
  EXPECT_EQ(m.code, 2);
  EXPECT_EQ(m.err, "metrofit-cli: pts.csv:3:1: field 'id': duplicate point id '1' (first on line 2)\n");
  test::writeText(tmp.file("model.json"), "{\"name\": \"x\",");
  test::writeText(tmp.file("r.csv"), "part\n1\n");
  const CliRun s = cli("setup --model model.json --data r.csv", tmp);
  EXPECT_EQ(s.code, 2);
  EXPECT_NE(s.err.find("model.json:1:"), std::string::npos) << s.err;
}

TEST(Cli, SimulateWritesAtomicallyAndReproducibly) {
  test::TempDir tmp;
  ASSERT_EQ(cli("simulate thermal --seed 3 --out a.csv", tmp).code, 0);
  ASSERT_EQ(cli("simulate thermal --seed 3 --out b.csv", tmp).code, 0);
  EXPECT_EQ(test::readText(tmp.file("a.csv")), test::readText(tmp.file("b.csv")));
  EXPECT_EQ(readThermalLog(tmp.file("a.csv")).rows(), 481u);
  const CliRun p = cli("simulate probe --seed 3", tmp);  // stdout when --out is omitted
  EXPECT_EQ(p.code, 0);
  EXPECT_EQ(p.out.rfind("id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n", 0), 0u);
  EXPECT_EQ(lines(p.err), 1);
  // The demo data are reproducible from the command line, as resources/demo/README.md says.
  ASSERT_EQ(cli("simulate thermal --seed 7 --out t7.csv", tmp).code, 0);
  EXPECT_EQ(test::readText(tmp.file("t7.csv")),
            test::readText((test::sourceDir() / "resources/demo/data/thermal_demo.csv").string()));
  // An unwritable --out leaves nothing behind and exits 2.
  const CliRun w = cli("simulate thermal --out no/such/dir/x.csv", tmp);
  EXPECT_EQ(w.code, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp.file("no")));
  EXPECT_EQ(test::listFolder(tmp.path()), (std::vector<std::string>{"a.csv", "b.csv", "t7.csv"}));
}

TEST(Cli, DemoWritesProjectDataAndReport) {
  test::TempDir tmp;
  const CliRun r = cli("demo --out-dir demo", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto dir = tmp.path() / "demo";
  const std::string pdf = (dir / "metrofit-demo-report.pdf").string();
  EXPECT_EQ(r.out, pdf + "\n");         // prints where the report is
  EXPECT_EQ(lines(r.err), 1) << r.err;  // and one summary line, no Qt chatter
  ASSERT_TRUE(std::filesystem::exists(pdf));
  EXPECT_EQ(test::readText(pdf).rfind("%PDF-", 0), 0u);
  EXPECT_GT(std::filesystem::file_size(pdf), 20000u);
  const Project p = loadProject((dir / "demo.metrofit").string());
  // Every dataset of the bundled project, each with its data file next to it.
  EXPECT_EQ(p.datasets.size(),
            loadProject((test::sourceDir() / "resources/demo/demo.metrofit").string()).datasets.size());
  EXPECT_GE(p.datasets.size(), 5u);
  for (const auto& d : p.datasets)
    EXPECT_TRUE(std::filesystem::exists(resolveDatasetPath((dir / "demo.metrofit").string(), d))) << d.id;
  EXPECT_TRUE(std::filesystem::exists(dir / "data" / "LICENSE-MIT-CAIVIAC.txt"));
  // `report` on the saved project gives a PDF too.
  const CliRun rep = cli("report --project demo/demo.metrofit --out again.pdf", tmp);
  ASSERT_EQ(rep.code, 0) << rep.err;
  EXPECT_EQ(test::readText(tmp.file("again.pdf")).rfind("%PDF-", 0), 0u);
  const CliRun missing = cli("report --project nope.metrofit --out x.pdf", tmp);
  EXPECT_EQ(missing.code, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp.file("x.pdf")));
}

}  // namespace
}  // namespace metrofit
