// QIF 3 Results files through metrofit-cli (issue 29 item 1, the dataset kind `qif`): spc
// --characteristic, match / diagnose matching with --part, setup with a QIF file as the CMM report series,
// and project add (kind qif, auto by content, probe points of one part). The files are the public samples
// in ../shared/data/real/cmm-qif-samples; the values checked are the facts its README lists, read from the
// XML by hand (not by our reader), and CSV files written here from those facts.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cli/cli_runner.h"
#include "core/common/numformat.h"
#include "core/io/json_util.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using test::cli;
using test::CliRun;
using test::lines;

nlohmann::json json(const test::TempDir& tmp, const std::string& name) {
  return parseJson(test::readText(tmp.file(name)), name);
}

std::string sample(const std::string& name) {
  return test::realData("cmm-qif-samples/" + name).string();
}

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

// README, SheetMetal facts 1 and 2: the position of hole W1RXXMRA19 over parts 1-6 (parts 1 and 6 to the
// file's digits, the others to the six decimals the README gives).
const double kPosition19[6] = {1.076016018900693, 0.846893, 0.870595, 0.897298, 0.927406, 1.632768254314692};
// README, SheetMetal fact 5: profile W1RISMRA09V over parts 1-6.
const double kProfile09[6] = {0.224164, 0.148093, 0.201837, 0.228307, 0.228307, 0.183654};

double mean(const double (&v)[6]) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / 6.0;
}

TEST(QifCli, SpcChartsOneCharacteristicOverTheMeasuredParts) {
  const std::string file = sample("SheetMetal_QIF_Results_6_samples.QIF");
  METROFIT_REQUIRE_PATH(file);
  test::TempDir tmp;
  CliRun r =
      cli("spc --data " + quoted(file) + " --characteristic W1RXXMRA19P --subgroup 2 --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("characteristic 'W1RXXMRA19P', 3 subgroups of 2"), std::string::npos) << r.err;
  const nlohmann::json a = json(tmp, "a.json");
  EXPECT_NEAR(a["mean"].get<double>(), mean(kPosition19), 1e-6);
  // A position zone of diameter 1.25: limits 0 and 1.25 (the README's pass / fail rule).
  EXPECT_EQ(a["lsl"], 0.0);
  EXPECT_EQ(a["usl"], 1.25);
  // The same series from a CSV written from the README's values: the same limits (to the README's digits).
  std::string csv = "position_mm\n";
  for (double v : kPosition19) csv += num::general(v, 17) + "\n";
  test::writeText(tmp.file("p.csv"), csv);
  r = cli("spc --data p.csv --column position_mm --subgroup 2 --lsl 0 --usl 1.25 --nominal 0 --out b.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json b = json(tmp, "b.json");
  for (const char* key : {"center", "ucl", "lcl"})
    EXPECT_NEAR(a["xbar_chart"][key].get<double>(), b["xbar_chart"][key].get<double>(), 2e-6) << key;
  EXPECT_EQ(a["in_control"], b["in_control"]);
  // A profile, by its Name: the README's six values.
  r = cli("spc --data " + quoted(file) + " --characteristic W1RISMRA09V --subgroup 3 --out c.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(json(tmp, "c.json")["mean"].get<double>(), mean(kProfile09), 1e-6);
  // Four Position characteristics: the type alone is ambiguous, refused naming them.
  r = cli("spc --data " + quoted(file) + " --characteristic Position --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  for (const char* name : {"W1RXXMRA19P", "W1RXXMRA20P", "W1RXXMRA21P", "W1RXXMRA22P"})
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  r = cli("spc --data " + quoted(file) + " --column W1RXXMRA19P --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--characteristic"), std::string::npos) << r.err;
}

TEST(QifCli, MatchTakesOnePartAndItsMeasuredFeatures) {
  const std::string series = sample("SheetMetal_QIF_Results_6_samples.QIF");
  const std::string one = sample("QIF_Results_Sample.QIF");
  METROFIT_REQUIRE_PATH(series);
  METROFIT_REQUIRE_PATH(one);
  test::TempDir tmp;
  // Six parts and no choice: refused, naming the parts by number and serial.
  CliRun r = cli("match --data " + quoted(series) + " --method closed-form", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("6 measured parts"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("6 (SN5802806)"), std::string::npos) << r.err;
  r = cli("match --data " + quoted(series) + " --part 7 --method closed-form", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("part 7"), std::string::npos) << r.err;
  // Part 1 with every degree of freedom held: the per-point deviation is actual - nominal, here of hole
  // W1RXXMRA19 (README fact 1), and all 21 features are points.
  r = cli("match --data " + quoted(series) +
              " --part 1 --method closed-form --lock rx,ry,rz,x,y,z --per-point p1.csv --out a.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("on 21 points"), std::string::npos) << r.err;
  const std::string p1 = test::readText(tmp.file("p1.csv"));
  const auto at = p1.find("\nW1RXXMRA19,Circle,");
  ASSERT_NE(at, std::string::npos) << p1;
  const std::string row = p1.substr(at + 1, p1.find('\n', at + 1) - at - 1);
  std::vector<double> values;
  for (std::size_t pos = row.find(',', row.find(',') + 1); pos != std::string::npos;
       pos = row.find(',', pos + 1))
    values.push_back(std::strtod(row.c_str() + pos + 1, nullptr));
  ASSERT_EQ(values.size(), 4u) << row;
  EXPECT_NEAR(values[1], 2434.01 - 2433.974609375, 1e-9);
  EXPECT_NEAR(values[2], 801.525055991931 - 800.617431640625, 1e-9);
  EXPECT_NEAR(values[3], 889.88 - 890.049621582031, 1e-9);
  // Part 6 is another measurement: another posture.
  r = cli("match --data " + quoted(series) + " --part 6 --method closed-form --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(json(tmp, "a.json")["after"]["rmse_mm"], json(tmp, "b.json")["after"]["rmse_mm"]);
  // A file of one part needs no --part; REFCIRC1 (DeterminationMode Set) is no measured point.
  r = cli("match --data " + quoted(one) + " --method closed-form --per-point q.csv", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("on 5 points"), std::string::npos) << r.err;
  EXPECT_EQ(test::readText(tmp.file("q.csv")).find("REFCIRC1"), std::string::npos);
  // The loop on one part's features.
  r = cli("diagnose matching --data " + quoted(series) + " --part 2 --out d.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(json(tmp, "d.json")["residual_check"].contains("white"));
}

// A setup model of one dimension, the position of hole W1RXXMRA19 (nominal 0, zone 0..1.25), on one
// work offset.
const char* kModel = R"({
  "name": "sheet metal", "axis": "Z", "step_mm": 0.001, "bounds_mm": [-2, 2],
  "setup": [{"id": "W1", "kind": "wks"}],
  "features": [{"id": "F1"}],
  "dimensions": [{"id": "D1", "nominal": 0, "lower": 0, "upper": 1.25, "label": "W1RXXMRA19P"}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "F1", "to": "D1", "weight": 1}]})";

TEST(QifCli, SetupReadsTheMeasuredPartsAsTheReportSeries) {
  const std::string file = sample("SheetMetal_QIF_Results_6_samples.QIF");
  METROFIT_REQUIRE_PATH(file);
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kModel);
  std::string csv = "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n";
  for (int k = 0; k < 6; ++k)
    csv += std::to_string(k + 1) + ",0,D1,0," + num::general(kPosition19[k], 17) + ",0,1.25\n";
  test::writeText(tmp.file("r.csv"), csv);
  CliRun r = cli("setup --model m.json --data " + quoted(file) + " --method exact --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("6 parts"), std::string::npos) << r.err;
  r = cli("setup --model m.json --data r.csv --method exact --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json a = json(tmp, "a.json"), b = json(tmp, "b.json");
  ASSERT_EQ(a["corrections_mm"].size(), b["corrections_mm"].size());
  EXPECT_NEAR(a["f1_mm"].get<double>(), b["f1_mm"].get<double>(), 1e-5);
}

TEST(QifCli, ProjectAddByKindByContentAndOnePartAsProbePoints) {
  const std::string file = sample("SheetMetal_QIF_Results_6_samples.QIF");
  METROFIT_REQUIRE_PATH(file);
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  CliRun r = cli("project add P.metrofit qif " + quoted(file) + " --id sheet", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit auto " + quoted(file) + " --id guessed", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("read as qif"), std::string::npos) << r.err;
  // Probe points are those of one part: without --part refused naming the parts, the project unchanged.
  const std::string before = test::readText(tmp.file("P.metrofit"));
  r = cli("project add P.metrofit probe-points " + quoted(file) + " --id points", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("1 (SN5802801)"), std::string::npos) << r.err;
  EXPECT_EQ(test::readText(tmp.file("P.metrofit")), before);
  r = cli("project add P.metrofit probe-points " + quoted(file) + " --id points --part 2", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  // --part is for probe points of a QIF file only.
  r = cli("project add P.metrofit qif " + quoted(file) + " --id x --part 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--part"), std::string::npos) << r.err;
  // Another format as qif: named.
  test::writeText(tmp.file("w.csv"), "a,b\n1,2\n");
  r = cli("project add P.metrofit qif w.csv --id y", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a QIF 3 document"), std::string::npos) << r.err;

  r = cli("project list P.metrofit --out l.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json l = json(tmp, "l.json");
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0]["kind"], "qif");
  EXPECT_EQ(l[0]["rows"], 6);  // measured parts
  // 21 characteristic items (README): each a column of the series.
  EXPECT_EQ(l[0]["columns"].size(), 21u);
  EXPECT_NE(std::find(l[0]["columns"].begin(), l[0]["columns"].end(), "W1RXXMRA19P"), l[0]["columns"].end());
  EXPECT_EQ(l[1]["kind"], "qif");
  EXPECT_EQ(l[2]["kind"], "probe_points");
  EXPECT_EQ(l[2]["rows"], 21);  // the features of part 2
  const nlohmann::json project = json(tmp, "P.metrofit");
  EXPECT_EQ(project["datasets"][2]["part"], 2);
}

TEST(QifCli, ResultsDoNotDependOnTheLocale) {
  const std::string file = sample("SheetMetal_QIF_Results_6_samples.QIF");
  METROFIT_REQUIRE_PATH(file);
  test::TempDir tmp;
  const char* old = std::getenv("LC_ALL");
  const std::string keep = old ? old : "";
  std::string outputs[3];
  const char* locales[3] = {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"};
  for (int k = 0; k < 3; ++k) {
    ::setenv("LC_ALL", locales[k], 1);
    const CliRun r =
        cli("spc --data " + quoted(file) + " --characteristic W1RXXMRA20P --subgroup 3 --out s.json", tmp);
    ASSERT_EQ(r.code, 0) << locales[k] << ": " << r.err;
    outputs[k] = test::readText(tmp.file("s.json"));
  }
  if (old)
    ::setenv("LC_ALL", keep.c_str(), 1);
  else
    ::unsetenv("LC_ALL");
  EXPECT_EQ(outputs[0], outputs[1]);
  EXPECT_EQ(outputs[0], outputs[2]);
}

}  // namespace
}  // namespace metrofit
