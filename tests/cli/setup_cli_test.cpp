// End-to-end tests of `metrofit-cli setup` and `metrofit-cli simulate setup`
// (docs/file-formats.md#setup-result): the JSON keys, exit codes, one-line errors naming file / line / field,
// determinism, exports.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

std::string demo(const char* name) {
  return "'" + (test::sourceDir() / "resources/demo/setup" / name).string() + "'";
}

const char* kSmallModel = R"({"name": "small", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
  "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
  "features": [{"id": "F1"}, {"id": "F2"}],
  "dimensions": [{"id": "D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02, "label": "POS_D1"},
                 {"id": "D2", "nominal": 18.5, "lower": -0.05, "upper": 0.03}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F1", "weight": 1},
           {"from": "W1", "to": "F2", "weight": -1}, {"from": "F1", "to": "D1", "weight": 1},
           {"from": "F1", "to": "D2", "weight": 1}, {"from": "F2", "to": "D2", "weight": -1}]})";

const char* kSmallReport =
    "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n"
    "1,10,D1,42,42.010,-0.02,0.02\n"
    "1,10,D2,18.5,18.495,-0.05,0.03\n";

TEST(SetupCli, ExactOnThePaperExampleWritesTheContractKeys) {
  test::TempDir tmp;
  const CliRun r = cli("setup --model " + demo("paper_example.json") + " --data " +
                           demo("paper_example_report.csv") + " --out result.json",
                       tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("setup: exact on 28 dimensions of 3 parts, 10 setup data: f1 0.0237 -> 0.0797 mm", 0),
            0u)
      << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("result.json"));
  for (const char* key :
       {"method", "corrections_mm", "f1_mm", "f2_mm", "f", "bonus_mm", "evaluations", "trace"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["method"], "exact");
  EXPECT_EQ(j["corrections_mm"].size(), 10u);
  for (const char* id : {"W1", "W2", "W3", "W4", "W5", "W6", "W7", "W8", "T5", "T23"})
    EXPECT_TRUE(j["corrections_mm"].contains(id)) << id;
  const double f1 = j["f1_mm"], f2 = j["f2_mm"], f = j["f"];
  EXPECT_NEAR(f, 10.0 * f1 - f2, 1e-8);
  EXPECT_NEAR(j["bonus_mm"].get<double>(), f1 - j["f1_before_mm"].get<double>(), 1e-8);
  EXPECT_NEAR(f1, 0.0796667, 1e-6);  // means over 3 parts: thirds of a micrometre
  double sq = 0.0;
  for (const auto& [id, v] : j["corrections_mm"].items()) {
    sq += v.get<double>() * v.get<double>();
    EXPECT_NEAR(v.get<double>() * 1000.0, std::round(v.get<double>() * 1000.0), 1e-6)
        << id << " off the grid";
  }
  EXPECT_NEAR(std::sqrt(sq), f2, 1e-8);
  EXPECT_TRUE(j["certificate"]["f1_optimal_on_grid"].get<bool>());
  EXPECT_TRUE(j["certificate"]["f2_minimal"].get<bool>());
  EXPECT_GE(j["certificate"]["lp_f1_mm"].get<double>(), f1);
  EXPECT_GE(j["trace"].size(), 3u);
  EXPECT_EQ(j["trace"][0]["stage"], "lp");
  EXPECT_EQ(j["dimensions"].size(), 28u);
  EXPECT_EQ(j["parts"], 3);
}

TEST(SetupCli, DfqHasOneCharacteristicPerMeasuredDimension) {
  // Read back by the AQDEF K-field rule (docs/file-formats.md#q-das-dfq-export;
  // pypi.org/project/aqdefreader): "Kxxxx/i value" lines, K0100 the count, K2001/i the characteristic,
  // K2101/K2110/K2111 nominal and limits, K0001/i the values; compared with the report's own columns.
  test::TempDir tmp;
  const std::string report = (test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string();
  const CliRun r =
      cli("setup --model " + demo("paper_example.json") + " --data '" + report + "' --dfq f.dfq --out r.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, std::string> fields;
  std::map<int, std::vector<double>> values;
  std::istringstream in(test::readText(tmp.file("f.dfq")));
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    if (key.rfind("K0001/", 0) == 0) {
      values[std::stoi(key.substr(6))].push_back(std::stod(value));
    } else {
      fields[key] = value;
    }
  }
  const CsvTable t = readCsvFile(report);
  const auto nominal = t.numericColumn("nominal_mm"), measured = t.numericColumn("measured_mm");
  const auto lower = t.numericColumn("lower_tol_mm"), upper = t.numericColumn("upper_tol_mm");
  const std::size_t dim = t.requireColumn("dimension");
  std::map<std::string, int> index;
  for (const auto& [key, value] : fields) {
    if (key.rfind("K2001/", 0) == 0) index[value] = std::stoi(key.substr(6));
  }
  EXPECT_EQ(fields.at("K0100"), "28");
  EXPECT_EQ(index.size(), 28u);
  std::map<int, std::size_t> seen;
  for (std::size_t row = 0; row < t.rowCount(); ++row) {
    const int i = index.at(t.cell(row, dim));
    const std::string k = "/" + std::to_string(i);
    EXPECT_NEAR(std::stod(fields.at("K2101" + k)), nominal[row], 1e-12);
    EXPECT_NEAR(std::stod(fields.at("K2110" + k)), nominal[row] + lower[row], 1e-12);
    EXPECT_NEAR(std::stod(fields.at("K2111" + k)), nominal[row] + upper[row], 1e-12);
    EXPECT_EQ(fields.at("K2142" + k), "mm");
    ASSERT_LT(seen[i], values[i].size());
    EXPECT_NEAR(values[i][seen[i]++], measured[row], 1e-9) << t.cell(row, dim);
  }
  for (const auto& [i, n] : seen) EXPECT_EQ(n, values[i].size()) << i;  // 3 parts each, nothing more
}

TEST(SetupCli, MetaheuristicsAreReproducibleAndReportTheirGap) {
  test::TempDir tmp;
  for (const char* method : {"cripso", "pso", "ga", "coa"}) {
    const std::string args = "setup --model " + demo("paper_example.json") + " --data " +
                             demo("paper_example_report.csv") + " --method " + method +
                             " --budget 1500 --seed 4";
    const CliRun a = cli(args, tmp), b = cli(args, tmp);
    ASSERT_EQ(a.code, 0) << method << ": " << a.err;
    EXPECT_EQ(a.out, b.out) << method;  // stdout when --out is omitted; bit for bit
    EXPECT_EQ(lines(a.err), 1) << a.err;
    const nlohmann::json j = nlohmann::json::parse(a.out);
    EXPECT_EQ(j["method"], method);
    EXPECT_EQ(j["evaluations"], 1500);
    EXPECT_GE(j["trace"].size(), 2u);
    EXPECT_TRUE(j["trace"][0].contains("f1_mm"));
    const double gap = j["gap_f1_mm"];
    EXPECT_GE(gap, 0.0) << method;
    EXPECT_NEAR(gap, j["exact"]["f1_mm"].get<double>() - j["f1_mm"].get<double>(), 1e-8);
    EXPECT_NE(a.err.find("gap to exact f1"), std::string::npos) << a.err;
  }
}

TEST(SetupCli, ExportAndDmisData) {
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kSmallModel);
  const std::string dmo = "'" + (test::sourceDir() / "tests/core/setup/data/part_17.dmo").string() + "'";
  const CliRun r =
      cli("setup --model m.json --data " + dmo + " --export fanuc --export-out offsets.nc --out r.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string nc = test::readText(tmp.file("offsets.nc"));
  EXPECT_EQ(nc.rfind("%\nO7001 (METROFIT SETUP CORRECTIONS)\n(SMALL)\n", 0), 0u) << nc;
  EXPECT_NE(nc.find("G10 L2 P1 Z"), std::string::npos);
  EXPECT_NE(nc.find("G10 L11 P5 R"), std::string::npos);
  const nlohmann::json j = readJsonFile(tmp.file("r.json"));
  EXPECT_EQ(j["export"]["format"], "fanuc");
  EXPECT_EQ(j["parts"], 1);
  EXPECT_NE(r.err.find("fanuc -> offsets.nc"), std::string::npos) << r.err;
  // Several reports are merged.
  test::writeText(tmp.file("r.csv"), kSmallReport);
  const CliRun m = cli(
      "setup --model m.json --data r.csv " + dmo + " --export csv --export-out x.csv --tool-offset geometry",
      tmp);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(nlohmann::json::parse(m.out)["parts"], 2);
  EXPECT_NE(test::readText(tmp.file("x.csv")).find("id,kind,register,axis,correction_mm\n"),
            std::string::npos);
}

// DMIS output with tolerance actuals only (no F / FA), written from the statement syntax of the DMIS
// standard (TA(label)=TOL/CORTOL|DIAM,value,INTOL): 0.012 for POS_D1 is a deviation, 18.52 for D2 (nominal
// 18.5) an actual diameter. --ta-meaning says how to read them; the plausibility check against the
// tolerance names the label when the chosen reading contradicts the file's INTOL.
TEST(SetupCli, DmisToleranceActualMeaningIsAnOption) {
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kSmallModel);
  test::writeText(tmp.file("r.dmi"),
                  "DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.012,INTOL\nTA(D2)=TOL/DIAM,18.52,INTOL\n");
  CliRun r = cli("setup --model m.json --data r.dmi", tmp);  // auto: by the nearer of nominal and zero
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["dimensions"][0]["deviation_before_mm"].get<double>(), 0.012, 1e-12);
  EXPECT_NEAR(j["dimensions"][1]["deviation_before_mm"].get<double>(), 0.020, 1e-12);
  r = cli("setup --model m.json --data r.dmi --ta-meaning actual", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("r.dmi:2: field 'TA(POS_D1)': the deviation -41.988 mm is outside"), std::string::npos)
      << r.err;
  r = cli("setup --model m.json --data r.dmi --ta-meaning deviation", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("r.dmi:3: field 'TA(D2)': the deviation 18.52 mm is outside"), std::string::npos)
      << r.err;
  r = cli("setup --model m.json --data r.dmi --ta-meaning mean", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--ta-meaning"), std::string::npos) << r.err;
  // --ta-sign nominal: this writer reports sign(nominal) * (actual - nominal); with positive nominals the
  // same numbers.
  r = cli("setup --model m.json --data r.dmi --ta-sign nominal", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["dimensions"][0]["deviation_before_mm"].get<double>(), 0.012, 1e-12);
  // diagnose setup reads the report with the same options.
  r = cli("diagnose setup --model m.json --data r.dmi --ta-meaning actual", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("TA(POS_D1)"), std::string::npos) << r.err;
}

TEST(SetupCli, BadInputExits2WithOneLineNamingFileLineAndField) {
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kSmallModel);
  test::writeText(tmp.file("r.csv"), kSmallReport);
  nlohmann::json bad = nlohmann::json::parse(kSmallModel);
  bad["arcs"][1]["weight"] = 2;
  test::writeText(tmp.file("bad.json"), bad.dump());
  struct Case {
    std::string args, err;
  };
  const Case cases[] = {
      {"setup --model bad.json --data r.csv",
       "metrofit-cli: bad.json: field 'arcs[1].weight': weight 2 is not +1 or -1\n"},
      {"setup --model m.json --data r.csv --export fanuc",
       "metrofit-cli: field '--export': needs --export-out FILE\n"},
      {"setup --model m.json --data r.csv --export-out x.nc",
       "metrofit-cli: field '--export-out': needs --export fanuc|heidenhain|heidenhain-table|siemens|csv\n"},
      {"setup --model m.json --data r.csv --export heidenhain-table --export-out t.t",
       "metrofit-cli: field '--export': heidenhain-table needs --export-table CURRENT.PR|CURRENT.T (the "
       "control's current preset or tool table)\n"},
      {"setup --model m.json --data r.csv --export fanuc --export-out x.nc --program-number 9001",
       "metrofit-cli: field '--program-number': the Fanuc program number O9001 is in O9000-O9999, which "
       "parameter 3202 bit 4 (NE9) = 1 protects from editing and registration (the file would not load; "
       "O9000-O9029 are also called by T/M/G codes as macros); choose 1..7999, or clear NE9 on the "
       "control\n"},
  };
  for (const Case& c : cases) {
    const CliRun r = cli(c.args, tmp);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.err, c.err) << c.args;
    EXPECT_EQ(r.out, "");
  }
  test::writeText(tmp.file("unknown.csv"), std::string(kSmallReport) + "2,20,D9,1,1,-0.1,0.1\n");
  const CliRun u = cli("setup --model m.json --data unknown.csv", tmp);
  EXPECT_EQ(u.code, 2);
  EXPECT_EQ(
      u.err,
      "metrofit-cli: unknown.csv:4:3: field 'dimension': unknown dimension 'D9' (not in the model m.json)\n");
  for (const char* args :
       {"setup --model m.json --data r.csv --method simplex", "setup --model m.json --data r.csv --budget 0",
        "setup --model m.json --data missing.csv", "setup --model m.json",
        "setup --model m.json --data r.csv --export haas --export-out x"}) {
    const CliRun r = cli(args, tmp);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
  }
  // An unwritable --out leaves nothing behind; the export is not written either.
  const CliRun w = cli("setup --model m.json --data r.csv --out no/such/dir/r.json", tmp);
  EXPECT_EQ(w.code, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp.file("no")));
}

// --export heidenhain-table: the control's current tool table (written here in the TNC table layout:
// BEGIN line, column names whose positions start the columns, left-aligned cells, [END]) comes back
// with the correction of T5 added to its DL cell and every other byte unchanged.
TEST(SetupCli, HeidenhainTableExport) {
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kSmallModel);
  test::writeText(tmp.file("r.csv"), kSmallReport);
  const std::string table =
      "BEGIN TOOL.T MM\n"
      "T       NAME                            L           R           DL        DR\n"
      "5       END_MILL_D10                    +85.125     +5          +0.002    +0\n"
      "[END]\n";
  test::writeText(tmp.file("TOOL.T"), table);
  const CliRun r = cli(
      "setup --model m.json --data r.csv --export heidenhain-table --export-table TOOL.T --export-out new.t",
      tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["export"]["table"], "TOOL.T");
  EXPECT_EQ(j["export"]["written"], nlohmann::json::array({"T5"}));
  EXPECT_EQ(j["export"]["not_written"], nlohmann::json::array({"W1"}));
  const double t5 = j["corrections_mm"]["T5"].get<double>();
  const std::string out = test::readText(tmp.file("new.t"));
  std::vector<std::string> in, got;
  for (const std::string* text : {&table, &out}) {
    std::istringstream s(*text);
    auto& v = text == &table ? in : got;
    for (std::string l; std::getline(s, l);) v.push_back(l);
  }
  ASSERT_EQ(got.size(), 4u) << out;
  EXPECT_EQ(got[0], in[0]);
  EXPECT_EQ(got[1], in[1]);
  EXPECT_EQ(got[3], "[END]");
  // DL is the column from position 64 to 74 (where "DL" and "DR" start in the header line).
  ASSERT_EQ(in[1].find("DL"), 64u);
  ASSERT_EQ(in[1].find("DR"), 74u);
  EXPECT_EQ(got[2].substr(0, 64), in[2].substr(0, 64));
  EXPECT_EQ(got[2].substr(74), in[2].substr(74));
  EXPECT_NEAR(std::stod(got[2].substr(64, 10)), 0.002 + t5, 1e-9) << got[2];
  // The table is required and must be a preset or tool table.
  test::writeText(tmp.file("pallet.p"), "BEGIN PALLET.P MM\nNR\n[END]\n");
  const CliRun bad = cli(
      "setup --model m.json --data r.csv --export heidenhain-table --export-table pallet.p --export-out x.t",
      tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err,
            "metrofit-cli: pallet.p:1: 'PALLET.P' is neither a preset table (.PR) nor a tool table (.T)\n");
  EXPECT_FALSE(std::filesystem::exists(tmp.file("x.t")));
}

// resources/demo/setup/paper_example_report.csv is reproducible from the command line, as
// resources/demo/setup/README.md says.
TEST(SetupCli, SimulateSetupMakesTheDemoReport) {
  test::TempDir tmp;
  const CliRun r = cli(
      "simulate setup --model " + demo("paper_example.json") + " --parts 3 --seed 6 --out report.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(test::readText(tmp.file("report.csv")),
            test::readText((test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string()));
  const CliRun s = cli("simulate setup --model " + demo("paper_example.json") + " --parts 0", tmp);
  EXPECT_EQ(s.code, 2);
}

TEST(SetupCli, ValidateRunsTheSeedsStatisticalValidation) {
  test::TempDir tmp;
  const CliRun r = cli("setup validate --model " + demo("paper_example.json") +
                           " --sets 30 --trials 2 --methods cripso,ga --budget 800 --data " +
                           demo("paper_example_report.csv") + " --out v.json",
                       tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("setup validate: 30 sets x 2 trials of cripso,ga, w1 0.030 w2 0.020 mm", 0), 0u)
      << r.err;
  const nlohmann::json j = readJsonFile(tmp.file("v.json"));
  EXPECT_EQ(j["sets"], 30);
  EXPECT_EQ(j["methods"], nlohmann::json({"cripso", "ga"}));
  ASSERT_EQ(j["series"].size(), 30u);
  // Fig. 18: sorted by f1 before correction; every trial below or at the exact optimum.
  double previous = -1e9, lo = 1e9, hi = -1e9;
  for (const auto& s : j["series"]) {
    const double before = s["f1_before_mm"];
    EXPECT_GE(before, previous);
    previous = before;
    lo = std::min(lo, before);
    hi = std::max(hi, before);
    for (const char* m : {"cripso", "ga"}) {
      ASSERT_EQ(s["f1_mm"][m].size(), 2u);
      for (const auto& f1 : s["f1_mm"][m]) EXPECT_LE(f1.get<double>(), s["exact_f1_mm"].get<double>() + 1e-9);
    }
  }
  EXPECT_EQ(j["f1_before_mm"]["min"].get<double>(), lo);
  EXPECT_EQ(j["f1_before_mm"]["max"].get<double>(), hi);
  EXPECT_EQ(j["method_summary"]["cripso"]["trials"], 60);
  EXPECT_TRUE(j["paper_range"]["applies"].get<bool>());
  EXPECT_EQ(j["paper_range"]["f1_before_min_mm"], -0.011);
  EXPECT_EQ(j["paper_range"]["f1_before_max_mm"], 0.063);
  EXPECT_TRUE(j["paper_range"]["consistent"].get<bool>());
  EXPECT_NEAR(j["share"]["configured_weight_share"].get<double>(), 0.6, 1e-12);
  EXPECT_NEAR(j["share"]["weight_share"].get<double>(), 0.6, 0.1);
  EXPECT_EQ(j["data_share"]["sets"], 3);  // the demo report's three parts
  // The data's f1 before and exact optimum are those of `setup` (0.0237 -> 0.0797 mm, test above).
  EXPECT_NEAR(j["data_share"]["f1_before_mm"].get<double>(), 0.0237, 5e-5);
  EXPECT_NEAR(j["data_share"]["exact_f1_mm"].get<double>(), 0.0797, 5e-5);
  EXPECT_TRUE(j["data_share"].contains("foreseen_f1_mm"));

  // Reproducible; bad input exits 2 with one line; `setup` still needs --model and --data.
  ASSERT_EQ(cli("setup validate --model " + demo("paper_example.json") +
                    " --sets 30 --trials 2 --methods cripso,ga --budget 800 --data " +
                    demo("paper_example_report.csv") + " --threads 1 --out v1.json",
                tmp)
                .code,
            0);
  EXPECT_EQ(test::readText(tmp.file("v.json")), test::readText(tmp.file("v1.json")));
  CliRun bad = cli("setup validate --model " + demo("paper_example.json") + " --methods cripso,exact", tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("--methods"), std::string::npos) << bad.err;
  bad = cli("setup validate --sets 3", tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--model"), std::string::npos) << bad.err;
  bad = cli("setup --model " + demo("paper_example.json"), tmp);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--data is required"), std::string::npos) << bad.err;
}

/// The demo's CSV series (3 parts x 28 dimensions of the paper example, fixture positions P1..P4)
/// copied to `series.csv` and written as DMIS output files, from the DMIS statement syntax: even rows
/// as nominal / actual points (F / FA along Z), odd rows as T / TA = TOL/DISTB with the deviation.
/// Every file has the same FILNAM, as an inspection program writes them. `perPosition`: one file per
/// fixture position per measured part (part<k>_P<j>.dmo, 12 files, each with only P<j>.D*, and
/// PARTSN/'<k>'), else one per part (part<k>.dmo). Rows whose dimension is `skip` (and, when
/// `skipPart` is set, whose part is `skipPart`) are left out. Returns the --data arguments.
std::string writePaperSeries(const test::TempDir& tmp, bool perPosition, const std::string& skip = {},
                             const std::string& skipPart = {}) {
  const std::string csvPath = (test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string();
  test::writeText(tmp.file("series.csv"), test::readText(csvPath));
  const CsvTable t = readCsvFile(csvPath);
  std::map<std::string, std::string> files;
  std::vector<std::string> order;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const std::string part = t.cell(r, t.requireColumn("part"));
    const std::string dim = t.cell(r, t.requireColumn("dimension"));
    const std::string nominal = t.cell(r, t.requireColumn("nominal_mm"));
    const std::string measured = t.cell(r, t.requireColumn("measured_mm"));
    const std::string name =
        "part" + part + (perPosition ? "_" + dim.substr(0, dim.find('.')) : std::string()) + ".dmo";
    std::string& f = files[name];
    if (f.empty()) {
      order.push_back(name);
      f = "DMISMN/'guide pins',05.3\nFILNAM/'GUIDE-PINS',05.3\n" +
          (perPosition ? "PARTSN/'" + part + "'\n" : std::string()) + "UNITS/MM,ANGDEC\n";
    }
    if (dim == skip && (skipPart.empty() || part == skipPart)) continue;
    if (r % 2 == 0) {
      f += "F(" + dim + ")=FEAT/POINT,CART,0,0," + nominal + ",0,0,1\n";
      f += "FA(" + dim + ")=FEAT/POINT,CART,0,0," + measured + ",0,0,1\n";
    } else {
      f += "T(" + dim + ")=TOL/DISTB,NOMINL," + nominal + "," + t.cell(r, t.requireColumn("lower_tol_mm")) +
           "," + t.cell(r, t.requireColumn("upper_tol_mm")) + "\n";
      f += "TA(" + dim + ")=TOL/DISTB," + num::general(test::cnumber(measured) - test::cnumber(nominal), 17) +
           "\n";
    }
  }
  std::string args;
  for (const auto& name : order) {
    test::writeText(tmp.file(name), files[name] + "ENDFIL\n");
    args += " --data " + name;
  }
  return args;
}

/// `setup` of the paper's model on series.csv (to csv.json) and on the DMIS files `dmisArgs`
/// (" --data f1 --data f2 ...", to dmis.json), both in tmp.
struct CsvAndDmisRuns {
  CliRun csv, dmis;
};
CsvAndDmisRuns setupCsvAndDmis(const test::TempDir& tmp, const std::string& dmisArgs) {
  const std::string model = demo("paper_example.json");
  return {cli("setup --model " + model + " --data series.csv --out csv.json", tmp),
          cli("setup --model " + model + dmisArgs + " --out dmis.json", tmp)};
}

/// The setup result JSON files `a` and `b` in tmp give the same corrections, scores and dimensions.
void expectSameResult(const test::TempDir& tmp, const char* a, const char* b) {
  const nlohmann::json x = readJsonFile(tmp.file(a)), y = readJsonFile(tmp.file(b));
  ASSERT_EQ(x["corrections_mm"].size(), y["corrections_mm"].size());
  for (const auto& [id, v] : x["corrections_mm"].items())
    EXPECT_NEAR(v.get<double>(), y["corrections_mm"][id].get<double>(), 1e-12) << id;
  for (const char* key : {"f1_mm", "f2_mm", "f", "f1_before_mm"})
    EXPECT_NEAR(x[key].get<double>(), y[key].get<double>(), 1e-12) << key;
  ASSERT_EQ(x["dimensions"].size(), y["dimensions"].size());
  EXPECT_EQ(x["dimensions"], y["dimensions"]);
}

TEST(SetupCli, DmisFilesOfOnePartEachAreASeriesLikeTheCsv) {
  test::TempDir tmp;
  const std::string data = writePaperSeries(tmp, false);
  const auto [fromCsv, fromDmis] = setupCsvAndDmis(tmp, data);
  ASSERT_EQ(fromCsv.code, 0) << fromCsv.err;
  ASSERT_EQ(fromDmis.code, 0) << fromDmis.err;
  EXPECT_NE(fromDmis.err.find("28 dimensions of 3 parts"), std::string::npos) << fromDmis.err;
  expectSameResult(tmp, "csv.json", "dmis.json");
}

TEST(SetupCli, DmisFilesOfOneFixturePositionEachAreASeriesLikeTheCsv) {
  // 3 measured fixtures x 4 positions: 12 files, each with only its workpiece's 7 dimensions.
  test::TempDir tmp;
  const std::string data = writePaperSeries(tmp, true);
  const auto [fromCsv, fromDmis] = setupCsvAndDmis(tmp, data);
  ASSERT_EQ(fromCsv.code, 0) << fromCsv.err;
  ASSERT_EQ(fromDmis.code, 0) << fromDmis.err;
  EXPECT_NE(fromDmis.err.find("28 dimensions of 3 parts"), std::string::npos) << fromDmis.err;
  expectSameResult(tmp, "csv.json", "dmis.json");
  EXPECT_EQ(readJsonFile(tmp.file("dmis.json"))["parts"], readJsonFile(tmp.file("csv.json"))["parts"]);
}

TEST(SetupCli, DmisSeriesFileMissingADimensionMeasuredByAnotherIsAccepted) {
  // P2.D1 left out of part 2's file: the other parts measure it, as a CSV series without that row.
  test::TempDir tmp;
  const std::string data = writePaperSeries(tmp, true, "P2.D1", "2");
  std::string csv, line;
  std::istringstream in(test::readText(tmp.file("series.csv")));
  while (std::getline(in, line))
    if (line.rfind("2,", 0) != 0 || line.find(",P2.D1,") == std::string::npos) csv += line + "\n";
  test::writeText(tmp.file("series.csv"), csv);
  const auto [fromCsv, fromDmis] = setupCsvAndDmis(tmp, data);
  ASSERT_EQ(fromCsv.code, 0) << fromCsv.err;
  ASSERT_EQ(fromDmis.code, 0) << fromDmis.err;
  expectSameResult(tmp, "csv.json", "dmis.json");
}

TEST(SetupCli, DmisSeriesDimensionMeasuredByNoFileExits2NamingTheDimensionAndTheFiles) {
  test::TempDir tmp;
  const std::string data = writePaperSeries(tmp, true, "P2.D1");
  const CliRun r = cli("setup --model " + demo("paper_example.json") + data + " --out dmis.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no file of the series measures dimension 'P2.D1' of the model"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("files read: part1_P1.dmo, part1_P2.dmo"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("part3_P4.dmo"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("dmis.json")));
}

TEST(SetupCli, ProjectAddTakesADmisSeriesOfSeveralFiles) {
  test::TempDir tmp;
  const std::string data = writePaperSeries(tmp, false);  // " --data f1 --data f2 ..."
  std::vector<std::string> files;
  for (std::size_t at = data.find("--data "); at != std::string::npos; at = data.find("--data ", at + 1)) {
    const std::size_t from = at + 7, to = data.find(' ', from);
    files.push_back(data.substr(from, to == std::string::npos ? std::string::npos : to - from));
  }
  ASSERT_EQ(files.size(), 3u);
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  CliRun r = cli(
      "project add P.metrofit cmm-report " + files[0] + " " + files[1] + " " + files[2] + " --id parts", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json p = readJsonFile(tmp.file("P.metrofit"));
  ASSERT_EQ(p["datasets"].size(), 1u);
  EXPECT_EQ(p["datasets"][0]["path"], files[0]);
  EXPECT_EQ(p["datasets"][0]["paths"], nlohmann::json(files));
  // The rows of the series are those of its files together: 28 measured dimensions in each of the 3
  // files (one part each).
  r = cli("project list P.metrofit --out list.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(readJsonFile(tmp.file("list.json"))[0]["rows"], 3 * 28);
  // Only DMIS output files make a series.
  test::writeText(tmp.file("series.txt"), "part,time_min\n1,0\n");
  r = cli("project add P.metrofit cmm-report " + files[0] + " series.txt --id mixed", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("series.txt"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("only DMIS output files make a series"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace metrofit
