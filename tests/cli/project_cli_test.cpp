// End-to-end tests of own data (docs/file-formats.md#own-data-in-a-project): `project new|add|list`,
// --delimiter / --decimal on the readers, `-` for standard input, one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "cli/cli_runner.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

/// The CSV text written the German way: ';' between fields, ',' as the decimal separator.
std::string german(const std::string& text) {
  std::string out = text;
  for (char& c : out) c = c == ',' ? ';' : c == '.' ? ',' : c;
  return out;
}

nlohmann::json readJson(const test::TempDir& tmp, const std::string& name) {
  return parseJson(test::readText(tmp.file(name)), name);
}

const std::string kRealPlate = test::realData("cmm-plugplate-sdss/D8131_1").string();

TEST(ProjectCli, GermanLogWithMappedColumnsInAProject) {
  test::TempDir tmp;
  ASSERT_EQ(cli("simulate thermal --seed 7 --out log.csv", tmp).code, 0);
  std::string text = test::readText(tmp.file("log.csv"));
  // The file's own names: Zeit for time_min, dZ for disp_z_um.
  text.replace(text.find("time_min"), 8, "Zeit");
  text.replace(text.find("disp_z_um"), 9, "dZ");
  std::filesystem::create_directories(tmp.path() / "data");
  test::writeText(tmp.file("data/messung.csv"), german(text));

  CliRun r = cli("project new p/P.metrofit --name 'Eigene Daten'", tmp);
  EXPECT_NE(r.code, 0) << "the folder p does not exist";
  std::filesystem::create_directories(tmp.path() / "p");
  r = cli("project new p/P.metrofit --name 'Eigene Daten'", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add p/P.metrofit thermal-log data/messung.csv --map time_min=Zeit --map disp_z_um=dZ",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;

  const nlohmann::json project = readJson(tmp, "p/P.metrofit");
  EXPECT_EQ(project["name"], "Eigene Daten");
  ASSERT_EQ(project["datasets"].size(), 1u);
  const nlohmann::json& d = project["datasets"][0];
  EXPECT_EQ(d["id"], "messung");
  EXPECT_EQ(d["kind"], "thermal_log");
  EXPECT_EQ(d["path"], "../data/messung.csv");
  EXPECT_EQ(d["map"]["time_min"], "Zeit");
  EXPECT_EQ(d["map"]["disp_z_um"], "dZ");

  r = cli("project list p/P.metrofit --out list.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = readJson(tmp, "list.json");
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["id"], "messung");
  EXPECT_EQ(list[0]["kind"], "thermal_log");
  EXPECT_EQ(list[0]["path"], "../data/messung.csv");
  std::istringstream in(text);
  std::string line;
  long dataLines = -1;  // minus the header
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ++dataLines;
  EXPECT_EQ(list[0]["rows"].get<long>(), dataLines);
  const auto columns = list[0]["columns"].get<std::vector<std::string>>();
  EXPECT_EQ(columns.front(), "time_min");
  EXPECT_NE(std::find(columns.begin(), columns.end(), "disp_z_um"), columns.end());

  // The project's report reads the dataset through its mapping and dialect.
  r = cli("report --project p/P.metrofit --out r.pdf", tmp);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(tmp.file("r.pdf")));
}

TEST(ProjectCli, ReadersTakeTheGermanDialectAndStandardInput) {
  test::TempDir tmp;
  ASSERT_EQ(cli("simulate thermal --seed 7 --out log.csv", tmp).code, 0);
  test::writeText(tmp.file("de.csv"), german(test::readText(tmp.file("log.csv"))));
  const std::string fit = "thermal fit --target disp_z_um --inputs T1,T2 --model gmc ";
  ASSERT_EQ(cli(fit + "--data log.csv --out a.json", tmp).code, 0);
  CliRun r = cli(fit + "--data de.csv --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli(fit + "--data de.csv --delimiter ';' --decimal , --out c.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli(fit + "--data - --out d.json < de.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const double a = readJson(tmp, "a.json")["fit_rmse"].get<double>();
  EXPECT_EQ(readJson(tmp, "b.json")["fit_rmse"].get<double>(), a);
  EXPECT_EQ(readJson(tmp, "c.json")["fit_rmse"].get<double>(), a);
  EXPECT_EQ(readJson(tmp, "d.json")["fit_rmse"].get<double>(), a);

  // A wrong explicit decimal: exit 2, one line naming file, line and field.
  r = cli(fit + "--data de.csv --decimal . --out e.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("de.csv:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("decimal separator is '.'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("e.json")));
  // A bad row from standard input names <stdin>.
  test::writeText(tmp.file("bad.csv"),
                  "time_min;T1;T2;disp_z_um\n0;20;20;0\n1;20,5;x;1\n2;21;21;2\n3;22;22;3\n");
  r = cli(fit + "--data - < bad.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("<stdin>:3:3: field 'T2': 'x' is not a number"), std::string::npos) << r.err;
  // Option values are checked by the parser.
  r = cli(fit + "--data de.csv --delimiter '|'", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--delimiter"), std::string::npos) << r.err;
}

TEST(ProjectCli, AddChecksTheFileAndNamesWhatIsWrong) {
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  EXPECT_EQ(cli("project new P.metrofit", tmp).code, 2);  // never overwrites
  test::writeText(tmp.file("log.csv"), "Zeit;T1;dZ\n0;20;0\n1;21;-1,5\n2;22;-3\n");
  CliRun r = cli("project add P.metrofit thermal-log log.csv --map time_min=Time", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("log.csv: field 'time_min'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'Time'"), std::string::npos) << r.err;
  r = cli("project add P.metrofit weather log.csv", tmp);
  EXPECT_EQ(r.code, 2);
  r = cli("project add P.metrofit thermal-log log.csv", tmp);  // no time column without the mapping
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("log.csv"), std::string::npos) << r.err;
  // Nothing was added by the failed calls.
  EXPECT_EQ(readJson(tmp, "P.metrofit")["datasets"].size(), 0u);

  r = cli("project add P.metrofit thermal-log log.csv --map time_min=Zeit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit thermal-log log.csv --map time_min=Zeit --id log", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("already has a dataset 'log'"), std::string::npos) << r.err;
  // From standard input: copied into the project's folder.
  r = cli("project add P.metrofit thermal-log - --id piped --map time_min=Zeit < log.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(test::readText(tmp.file("piped.csv")), test::readText(tmp.file("log.csv")));
  r = cli("project list P.metrofit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = parseJson(r.out, "stdout");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[1]["id"], "piped");
  EXPECT_EQ(list[1]["path"], "piped.csv");
  EXPECT_EQ(list[1]["rows"], 3);
  EXPECT_EQ(list[1]["columns"], (nlohmann::json{"time_min", "T1", "dZ"}));
}

TEST(ProjectCli, BallbarExportIsAddedAsACircularTestByItsColumns) {
  // The radial-only form (docs/file-formats.md#circular-test) with a ballbar program's own column names,
  // mapped to the roles; a bad direction cell is refused naming line and column.
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  std::string text = "Angle;Deviation;Dir\n";
  for (int k = 0; k < 8; ++k) text += std::to_string(45 * k) + ";" + (k % 2 ? "1,5" : "-0,5") + ";CCW\n";
  for (int k = 8; k > 0; --k) text += std::to_string(45 * k) + ";" + (k % 2 ? "2,5" : "0,5") + ";CW\n";
  test::writeText(tmp.file("qc20.csv"), text);
  CliRun r = cli("project add P.metrofit circular-test qc20.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("qc20.csv"), std::string::npos) << r.err;
  r =
      cli("project add P.metrofit circular-test qc20.csv --map angle_deg=Angle --map deviation_um=Deviation "
          "--map direction=Dir",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project list P.metrofit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = parseJson(r.out, "stdout");
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["kind"], "circular_test");
  EXPECT_EQ(list[0]["rows"], 16);
  test::writeText(tmp.file("bad.csv"), "angle_deg,deviation_um,direction\n0,1,ccw\n90,2,ccw\n180,1,left\n");
  r = cli("project add P.metrofit circular-test bad.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.csv:4:3: field 'direction': 'left' is not a direction"), std::string::npos)
      << r.err;
}

TEST(ProjectCli, RealHoleTableAndTheDemoProject) {
  test::TempDir tmp;
  if (std::filesystem::exists(kRealPlate)) {
    ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
    CliRun r = cli("project add P.metrofit hole-table " + kRealPlate + " --id plate", tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    r = cli("project add P.metrofit hole-table " + kRealPlate + " --decimal ,", tmp);
    EXPECT_EQ(r.code, 2) << "a hole table is not CSV";
    r = cli("project list P.metrofit", tmp);
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json list = parseJson(r.out, "stdout");
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0]["kind"], "hole_table");
    EXPECT_EQ(list[0]["rows"], 82);  // the report's 82 hole rows
  }
  // Projects written before datasets had dialects (no delimiter, decimal or map keys) still list.
  const auto demo = test::sourceDir() / "resources" / "demo";
  const nlohmann::json old = {
      {"format", "metrofit-project"},
      {"version", 1},
      {"name", "old"},
      {"datasets",
       {{{"id", "model"}, {"kind", "setup_model"}, {"path", (demo / "setup/paper_example.json").string()}},
        {{"id", "report"},
         {"kind", "cmm_report"},
         {"path", (demo / "setup/paper_example_report.csv").string()}},
        {{"id", "log"}, {"kind", "thermal_log"}, {"path", (demo / "data/thermal_demo.csv").string()}},
        {{"id", "probe"}, {"kind", "probe_points"}, {"path", (demo / "data/probe_s_piece.csv").string()}},
        {{"id", "circle"}, {"kind", "circular_test"}, {"path", (demo / "data/circular_demo.csv").string()}},
        {{"id", "bores"}, {"kind", "feature_series"}, {"path", (demo / "data/bores_demo.csv").string()}}}}};
  test::writeText(tmp.file("old.metrofit"), old.dump(2));
  const CliRun r = cli("project list old.metrofit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = parseJson(r.out, "stdout");
  ASSERT_EQ(list.size(), 6u);
  for (const auto& d : list) {
    if (d["kind"] == "thermal_log") {
      const auto columns = d["columns"].get<std::vector<std::string>>();
      EXPECT_EQ(columns.front().rfind("time_", 0), 0u) << d.dump();
    }
    EXPECT_GT(d["rows"].get<long>(), 0) << d.dump();
  }
}

}  // namespace
// The OGP reports of ../shared/data/real/cmm-ogp-hps-svt (real, GPL-3.0, read in place): added without
// options, recognised by their content; a garbled copy fails with one line naming file and line.
TEST(ProjectCli, RealOgpReportsAreAddedWithoutOptions) {
  const std::string dir = test::realData("cmm-ogp-hps-svt/survey_data").string() + "/";
  METROFIT_REQUIRE_PATH(dir);
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  CliRun r =
      cli("project add P.metrofit cmm-report " + dir + "meas1/L0_axial_top_module1_1.txt --id rtf", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit cmm-report " + dir + "L123_fixture_sho.txt --id summary", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit feature-series " + dir + "L123_fixture_sho.txt --id runs", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project list P.metrofit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = parseJson(r.out, "stdout");
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[1]["rows"], 533);  // the summary's 533 printed deviations
  EXPECT_EQ(list[2]["rows"], 13);   // one row per run
  // The runs as an SPC series: the hole-pin diameter of "Step 7" over the 13 runs.
  r = cli("spc --data " + dir + "L123_fixture_sho.txt --column step7.diameter --subgroup 2", tmp);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("6 subgroups of 2"), std::string::npos) << r.err;
  // A garbled copy: a letter in a number on line 15.
  std::string text = test::readText(dir + "fixture/L0/empty_fixture0.txt");
  text.replace(text.find("+454.74389"), 10, "+454.7O389");
  test::writeText(tmp.file("garbled.txt"), text);
  r = cli("project add P.metrofit cmm-report garbled.txt", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("garbled.txt:15:"), std::string::npos) << r.err;
}

}  // namespace metrofit

namespace metrofit {
namespace {

// Reading settings of `project add` (docs/file-formats.md#own-data-in-a-project): --header-lines,
// --comment, --skip-bad-rows, --ta-meaning / --ta-sign, --embed. Files written here from the formats'
// descriptions: a CSV with an instrument preamble; DMIS output in the statement syntax of the standard.
TEST(ProjectCli, AddTakesHeaderCommentSkipDmisAndEmbedOptions) {
  test::TempDir tmp;
  std::filesystem::create_directories(tmp.path() / "p");
  ASSERT_EQ(cli("project new p/P.metrofit", tmp).code, 0);
  test::writeText(
      tmp.file("rig.csv"),
      "Thermal test rig 3\nOperator: K.\n% sensors calibrated\ntime_min,T1,disp_z_um\n0,20.0,0.0\n"
      "10,n/a,1.5\n20,21.0,2.5\n30,21.5\n40,22.0,4.0\n");
  // Detected, the preamble is the header: refused, exit 2, nothing added.
  CliRun r = cli("project add p/P.metrofit thermal-log rig.csv", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  // With the preamble and the comment prefix, strict: an unreadable row is the error (the ragged
  // line 8 when the file is parsed, before the numbers are read).
  r = cli("project add p/P.metrofit thermal-log rig.csv --header-lines 2 --comment %", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "metrofit-cli: rig.csv:8:3: row has 2 fields, the header (line 4) has 3\n");
  // Skipping: both bad rows are named and counted, the project keeps the settings.
  r = cli("project add p/P.metrofit thermal-log rig.csv --header-lines 2 --comment % --skip-bad-rows", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("skipped line 6 (row 2), column 'T1': 'n/a' is not a number"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("skipped line 8 (row 4): row has 2 fields, the header (line 4) has 3"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("3 rows, 2 unreadable rows skipped"), std::string::npos) << r.err;
  nlohmann::json project = readJson(tmp, "p/P.metrofit");
  EXPECT_EQ(project["datasets"][0]["header_lines"], 2);
  EXPECT_EQ(project["datasets"][0]["comment"], "%");
  EXPECT_EQ(project["datasets"][0]["skip_bad_rows"], true);
  EXPECT_FALSE(project["datasets"][0].contains("dmis"));
  r = cli("project list p/P.metrofit", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json list = parseJson(r.out, "stdout");
  EXPECT_EQ(list[0]["rows"], 3);
  EXPECT_EQ(list[0]["skipped_rows"], 2);

  // DMIS: the TA reading is stored with the dataset; the defaults are not written.
  test::writeText(
      tmp.file("part7.dmi"),
      "DMISMN/'part 7',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.012,INTOL\nTA(D2)=TOL/DIAM,18.52,INTOL\n");
  r = cli("project add p/P.metrofit dmis part7.dmi --ta-meaning actual --ta-sign nominal", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add p/P.metrofit dmis part7.dmi --id plain", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  project = readJson(tmp, "p/P.metrofit");
  EXPECT_EQ(project["datasets"][1]["dmis"],
            (nlohmann::json{{"ta_meaning", "actual"}, {"ta_sign", "nominal"}}));
  EXPECT_FALSE(project["datasets"][2].contains("dmis"));

  // Embed: copied to p/data/<id>.<ext>, the path relative to the project; never overwritten.
  r = cli("project add p/P.metrofit dmis part7.dmi --id copy --embed", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(test::readText(tmp.file("p/data/copy.dmi")), test::readText(tmp.file("part7.dmi")));
  project = readJson(tmp, "p/P.metrofit");
  EXPECT_EQ(project["datasets"][3]["path"], "data/copy.dmi");
  EXPECT_EQ(project["datasets"][0]["path"], "../rig.csv");  // the default links
  test::writeText(tmp.file("p/data/taken.dmi"), "DMISMN/'other',05.3\n");
  r = cli("project add p/P.metrofit dmis part7.dmi --id taken --embed", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("taken.dmi: already exists; an embedded copy never overwrites a file"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::readText(tmp.file("p/data/taken.dmi")), "DMISMN/'other',05.3\n");

  // Bad values: exit 2, one line naming the option; nothing added.
  struct Case {
    std::string args, needle;
  };
  const Case cases[] = {
      {"dmis part7.dmi --id b1 --ta-meaning measured", "--ta-meaning"},
      {"dmis part7.dmi --id b2 --ta-sign minus", "--ta-sign"},
      {"thermal-log rig.csv --id b3 --header-lines -1", "--header-lines"},
      {"thermal-log rig.csv --id b4 --comment ' x'", "--comment"},
      {"feature-series rig.csv --id b5 --ta-meaning actual", "field '--ta-meaning': is not a DMIS file"},
      {"dmis part7.dmi --id b6 --header-lines 1", "do not apply"},
  };
  for (const Case& c : cases) {
    r = cli("project add p/P.metrofit " + c.args, tmp);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_EQ(readJson(tmp, "p/P.metrofit")["datasets"].size(), 4u);
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

// `project add P auto FILE`: the kind from the file, and (without --map) the roles its column names
// say, read in the roles' units; --no-guess keeps the file's names (issue 28 item 1).
TEST(ProjectCli, AddGuessesTheKindAndTheRolesWithTheirUnits) {
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  // Probe points as a shop's CMM exports them: German names, coordinates in metres, decimal commas.
  test::writeText(tmp.file("punkte.csv"),
                  "Punkt;Soll X [m];Soll Y [m];Soll Z [m];I;J;K;Ist X [m];Ist Y [m];Ist Z [m]\n"
                  "1;0,1;0;0;1;0;0;0,10002;0;0\n"
                  "2;0;0,1;0;0;1;0;0;0,09999;0\n"
                  "3;0;0;0,1;0;0;1;0;0;0,10001\n"
                  "4;0,1;0,1;0;0;0;1;0,1;0,1;0,00003\n");
  CliRun r = cli("project add P.metrofit auto punkte.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("read as probe_points"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("column 'Soll X [m]' read as qx"), std::string::npos) << r.err;
  nlohmann::json project = readJson(tmp, "P.metrofit");
  ASSERT_EQ(project["datasets"].size(), 1u);
  EXPECT_EQ(project["datasets"][0]["kind"], "probe_points");
  EXPECT_EQ(project["datasets"][0]["map"]["qx"], "Soll X [m]");
  EXPECT_EQ(project["datasets"][0]["map"]["pz"], "Ist Z [m]");
  EXPECT_EQ(project["datasets"][0]["map"]["nz"], "K");
  EXPECT_EQ(project["datasets"][0]["map"]["id"], "Punkt");

  // The same file added with --no-guess keeps its names (and cannot be probe points without a map).
  r = cli("project add P.metrofit probe-points punkte.csv --id raw --no-guess", tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  // An explicit --map is taken as given: nothing guessed beside it.
  r =
      cli("project add P.metrofit probe-points punkte.csv --id mapped --map id=Punkt --map 'qx=Soll X [m]' "
          "--map 'qy=Soll Y [m]' --map 'qz=Soll Z [m]' --map nx=I --map ny=J --map nz=K "
          "--map 'px=Ist X [m]' --map 'py=Ist Y [m]' --map 'pz=Ist Z [m]'",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  project = readJson(tmp, "P.metrofit");
  EXPECT_EQ(project["datasets"][1]["map"], project["datasets"][0]["map"]);
}

}  // namespace
}  // namespace metrofit
