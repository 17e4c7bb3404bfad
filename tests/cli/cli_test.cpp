// End-to-end tests of metrofit-cli (docs/file-formats.md#command-line): exit codes, one-line errors,
// atomic --out, the demo and the report.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
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

// --help, of metrofit-cli and of every subcommand, names where the file formats and JSON results are
// described: the installed document and its path in the source tree, which must exist.
TEST(Cli, HelpNamesTheFileFormatsDocument) {
  test::TempDir tmp;
  for (const char* sub : {"", "setup", "thermal fit", "diagnose thermal", "project add"}) {
    const CliRun h = cli(std::string(sub) + " --help", tmp);
    EXPECT_EQ(h.code, 0) << sub;
    EXPECT_NE(h.out.find("/usr/share/doc/metrofit/file-formats.md"), std::string::npos) << sub << h.out;
    EXPECT_NE(h.out.find("docs/file-formats.md in the source tree"), std::string::npos) << sub << h.out;
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(test::sourceDir() / "docs" / "file-formats.md"));
}

// Messages name the unknown subcommand and point to the subcommand's own --help; lists
// typed with blanks ("a, b") are trimmed; the diagnosis JSON numbers rounds from 1.
TEST(Cli, MessagesNameTheSubcommandAndItsHelp) {
  test::TempDir tmp;
  const CliRun fti = cli("thermal fti", tmp);
  EXPECT_EQ(fti.code, 2);
  EXPECT_EQ(lines(fti.err), 1) << fti.err;
  EXPECT_NE(fti.err.find("thermal: unknown subcommand 'fti' (one of: fit,"), std::string::npos) << fti.err;
  EXPECT_NE(fti.err.find("see metrofit-cli thermal --help"), std::string::npos) << fti.err;
  const CliRun fam = cli("kinematic", tmp);
  EXPECT_NE(fam.err.find("kinematic: a subcommand is required"), std::string::npos) << fam.err;
  const CliRun fit = cli("thermal fit --data nope.csv --target a --inputs b", tmp);
  EXPECT_EQ(fit.code, 2);
  EXPECT_NE(fit.err.find("see metrofit-cli thermal fit --help"), std::string::npos) << fit.err;
}

TEST(Cli, ListOptionsAreTrimmedAndRoundsAre1Based) {
  test::TempDir tmp;
  ASSERT_EQ(cli("demo --out-dir demo", tmp).code, 0);
  const CliRun r = cli(
      "diagnose thermal --data demo/data/diagnose_thermal.csv --target disp_z_um --inputs 'T2, T4 ,T_amb' "
      "--out d.json",
      tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(test::readText(tmp.file("d.json")));
  ASSERT_FALSE(j["effects"].empty());
  int smallest = 1000;
  for (const auto& e : j["effects"]) smallest = std::min(smallest, e["round"].get<int>());
  EXPECT_EQ(smallest, 1);
}

// A bad study setting stops `report` with exit 2 and a line naming the study and field.
TEST(Cli, ReportRejectsBadStudySettings) {
  test::TempDir tmp;
  ASSERT_EQ(cli("demo --out-dir demo", tmp).code, 0);
  nlohmann::json p = nlohmann::json::parse(test::readText(tmp.file("demo/demo.metrofit")));
  p["studies"]["thermal"]["target"] = "disp_x_um";
  test::writeText(tmp.file("demo/bad.metrofit"), p.dump());
  const CliRun r = cli("report --project demo/bad.metrofit --out bad.pdf", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("studies.thermal.target"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("disp_x_um"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("bad.pdf")));
  p = nlohmann::json::parse(test::readText(tmp.file("demo/demo.metrofit")));
  p["datasets"][0]["kind"] = "setup-model";
  test::writeText(tmp.file("demo/bad.metrofit"), p.dump());
  const CliRun k = cli("report --project demo/bad.metrofit --out bad.pdf", tmp);
  EXPECT_EQ(k.code, 2);
  EXPECT_NE(k.err.find("datasets[0].kind"), std::string::npos) << k.err;
}

// The demo report as its reader sees it (pdftotext): the summary first (pages 1-2 for the
// demo's eight findings), nothing elided,
// no source paths, seed numbers or ASCII stand-ins for symbols.
TEST(Cli, DemoReportReadsAsAReport) {
  if (std::system("command -v pdftotext > /dev/null 2>&1") != 0)
    FAIL() << "pdftotext (poppler-utils) missing: packaging/install-deps.sh installs it";
  test::TempDir tmp;
  ASSERT_EQ(cli("demo --out-dir demo", tmp).code, 0);
  ASSERT_EQ(std::system(("pdftotext demo/metrofit-demo-report.pdf '" + tmp.file("all.txt") +
                         "' && pdftotext -l 2 "
                         "demo/metrofit-demo-report.pdf '" +
                         tmp.file("p1.txt") + "'")
                            .insert(0, "cd '" + tmp.path().string() + "' && ")
                            .c_str()),
            0);
  const std::string all = test::readText(tmp.file("all.txt")), page1 = test::readText(tmp.file("p1.txt"));
  for (const char* needle : {"What each study found", "What to change on the machine", "corrections-fanuc.nc",
                             "Error before and after", "What the closed loop found"})
    EXPECT_NE(page1.find(needle), std::string::npos) << "page 1 lacks " << needle;
  for (const char* needle : {"References", "Appendix: data provenance", "Stryczek", "Jiang", "Abdulshahed",
                             "Recommendation: ", "not usable"})
    EXPECT_NE(all.find(needle), std::string::npos) << "the report lacks " << needle;
  for (const char* word : {"\xE2\x80\xA6", "seed 00", "core/", "resources/", ".cpp", ".h)", "issue ", "+-",
                           "->", " um ", " um)", "degC"})
    EXPECT_EQ(all.find(word), std::string::npos)
        << "the report says " << word << " at: "
        << all.substr(std::min(all.size(), all.find(word) - std::min<std::size_t>(60, all.find(word))), 120);
}

// The report is English; on a German or Polish desktop (the GUI's Export report runs this command
// with the user's environment) its chart legends must not switch to decimal commas inside English
// sentences (seen: "exact optimum f1 = 0,0797 mm", "T1: lag -6,4 min").
TEST(Cli, ReportNumbersDoNotFollowTheSystemLocale) {
  if (std::system("command -v pdftotext > /dev/null 2>&1") != 0)
    FAIL() << "pdftotext (poppler-utils) missing: packaging/install-deps.sh installs it";
  test::TempDir tmp;
  ASSERT_EQ(cli("demo --out-dir demo", tmp).code, 0);
  // The test also runs under each locale of the matrix (LOCALES); LC_ALL makes the German case explicit.
  for (const char* locale : {"de_DE.UTF-8"}) {
    SCOPED_TRACE(locale);
    ASSERT_EQ(::setenv("LC_ALL", locale, 1), 0);
    const CliRun r = cli("report --project demo/demo.metrofit --out r.pdf", tmp);
    ::unsetenv("LC_ALL");
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_EQ(std::system(("cd '" + tmp.path().string() + "' && pdftotext r.pdf r.txt").c_str()), 0);
    const std::string text = test::readText(tmp.file("r.txt"));
    EXPECT_NE(text.find("exact optimum f1 = 0.0797 mm"), std::string::npos);
    EXPECT_EQ(text.find("exact optimum f1 = 0,"), std::string::npos);
    EXPECT_EQ(text.find(": lag -6,4 min"), std::string::npos);
    EXPECT_NE(text.find(": lag -6.4 min"), std::string::npos);
  }
}

}  // namespace
}  // namespace metrofit
