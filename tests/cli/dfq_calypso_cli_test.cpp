// Q-DAS DFQ files and Zeiss Calypso tables through metrofit-cli (issue 29): spc --characteristic N|NAME,
// setup with a DFQ / Calypso _chr file as the CMM report series, match with a Calypso _fet file, and
// project add (kinds dfq and calypso, and auto by content). The files are written here from the formats'
// field lists (AQDEF K fields; Calypso's table columns), not by Metrofit's writers, except where the
// writer's own output is read back (setup --dfq). Each result is compared with the same data given in the
// CSV forms of docs/file-formats.md, which the other tests check against independent references.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/cli_runner.h"
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

// Two characteristics; 12 measured parts; the 5th value of characteristic 1 removed (attribute 255); a
// description with a decimal comma; 8-bit (Windows-1252: ä = E4); value lines with 0x0F / 0x14.
const double kBore[12] = {12.503, 12.498, 12.501, 12.505, 99.0,   12.497,
                          12.502, 12.500, 12.499, 12.504, 12.496, 12.501};
const double kLength[12] = {40.02, 40.01, 39.99, 40.00, 40.03, 39.98,
                            40.01, 40.02, 40.00, 39.99, 40.01, 40.00};

std::string dfq() {
  std::string t =
      "K0100 2\r\nK1001/1 4711\r\nK1002/1 Welle\r\nK2142/0 mm\r\n"
      "K2001/1 1\r\nK2002/1 Durchmesser 12,5\r\nK2101/1 12.5\r\nK2110/1 12.49\r\nK2111/1 12.51\r\n"
      "K2001/2 2\r\nK2002/2 L\xE4nge\r\nK2101/2 40\r\nK2110/2 39.95\r\nK2111/2 40.05\r\n";
  for (int i = 0; i < 12; ++i) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "%.3f\x0F%d\x0F"
                  "01.03.2024/08:%02d:00\x14%.2f\x0F"
                  "0\r\n",
                  kBore[i], i == 4 ? 255 : 0, i, kLength[i]);
    t += line;
  }
  return t;
}

TEST(DfqCli, SpcByNumberAndByNameEqualsTheCsvOfTheValidValues) {
  test::TempDir tmp;
  test::writeText(tmp.file("w.dfq"), dfq());
  std::string csv = "bore_mm\n";
  for (int i = 0; i < 12; ++i)
    if (i != 4) csv += std::to_string(kBore[i]) + "\n";
  test::writeText(tmp.file("w.csv"), csv);
  CliRun r = cli("spc --data w.dfq --characteristic 1 --subgroup 2 --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("characteristic '1 (Durchmesser 12,5)'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(1 trailing values left out)"), std::string::npos) << r.err;  // 11 valid values
  r = cli("spc --data w.dfq --characteristic 'durchmesser 12,5' --subgroup 2 --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  // The nominal and limits come from K2101 / K2110 / K2111.
  r = cli(
      "spc --data w.csv --column bore_mm --subgroup 2 --nominal 12.5 --lsl 12.49 --usl 12.51 --out c.json",
      tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json(tmp, "a.json"), json(tmp, "c.json"));
  EXPECT_EQ(json(tmp, "b.json"), json(tmp, "c.json"));
  // The umlaut of the 8-bit file, as UTF-8: by name.
  r = cli("spc --data w.dfq --characteristic 'L\xC3\xA4nge' --subgroup 3 --out d.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json(tmp, "d.json")["usl"], 40.05);
}

TEST(DfqCli, AmbiguousOrMissingChoicesAreRefusedNamingTheCandidates) {
  test::TempDir tmp;
  std::string two = dfq();
  two.replace(two.find("K2001/2 2"), 9, "K2001/2 1");  // both characteristics numbered 1
  test::writeText(tmp.file("w.dfq"), two);
  CliRun r = cli("spc --data w.dfq --characteristic 1 --subgroup 2 --out a.json", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("w.dfq"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'1' is ambiguous"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'1' (Durchmesser 12,5), '1' (L\xC3\xA4nge)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("a.json")));
  r = cli("spc --data w.dfq --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--characteristic"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is required"), std::string::npos) << r.err;
  r = cli("spc --data w.dfq --characteristic Rundheit --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no characteristic 'Rundheit'"), std::string::npos) << r.err;
  r = cli("spc --data w.dfq --column bore --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--characteristic"), std::string::npos) << r.err;
  test::writeText(tmp.file("bad.dfq"), "K0100 1\r\nK0001/1 12.5mm\r\n");
  r = cli("spc --data bad.dfq --subgroup 2", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.dfq:2: field 'K0001/1'"), std::string::npos) << r.err;
}

std::string demo(const std::string& name) {
  return "'" + (test::sourceDir() / "resources/demo/setup" / name).string() + "'";
}

TEST(DfqCli, SetupReadsTheDfqOfItsOwnReportAsTheSameSeries) {
  test::TempDir tmp;
  const std::string report =
      "'" + (test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string() + "'";
  CliRun r = cli(
      "setup --model " + demo("paper_example.json") + " --data " + report + " --dfq f.dfq --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("setup --model " + demo("paper_example.json") + " --data f.dfq --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json a = json(tmp, "a.json"), b = json(tmp, "b.json");
  EXPECT_EQ(a["corrections_mm"], b["corrections_mm"]);
  EXPECT_NEAR(a["f1_mm"].get<double>(), b["f1_mm"].get<double>(), 1e-12);
  EXPECT_NEAR(a["f"].get<double>(), b["f"].get<double>(), 1e-12);
}

const char* kModel = R"({
  "name": "flange", "axis": "Z", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
  "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
  "features": [{"id": "F1"}, {"id": "F2"}],
  "dimensions": [{"id": "D1", "nominal": 40.0, "lower": -0.05, "upper": 0.05, "label": "Abstand_E1"},
                 {"id": "D2", "nominal": 12.5, "lower": -0.01, "upper": 0.02, "label": "Durchmesser_B1"}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F2", "weight": 1},
           {"from": "F1", "to": "D1", "weight": 1}, {"from": "F2", "to": "D2", "weight": 1}]})";

const std::string kChr =
    "planid\tpartnb\tid\ttype\tidsymbol\tactual\tnominal\tuppertol\tlowertol\tdeviation\r\n"
    "Flansch\t1\tDurchmesser_B1\tDiameter\t\t12,5130\t12,5000\t0,0200\t-0,0100\t0,0130\r\n"
    "Flansch\t1\tAbstand_E1\tDistance\t\t40,0320\t40,0000\t0,0500\t-0,0500\t0,0320\r\n"
    "Flansch\t2\tDurchmesser_B1\tDiameter\t\t12,5110\t12,5000\t0,0200\t-0,0100\t0,0110\r\n"
    "Flansch\t2\tAbstand_E1\tDistance\t\t40,0280\t40,0000\t0,0500\t-0,0500\t0,0280\r\n";

TEST(CalypsoCli, SetupReadsTheChrTableAsTheCsvSeries) {
  test::TempDir tmp;
  test::writeText(tmp.file("m.json"), kModel);
  test::writeText(tmp.file("flansch_chr.txt"), kChr);
  test::writeText(tmp.file("r.csv"),
                  "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n"
                  "1,0,D2,12.5,12.513,-0.01,0.02\n1,0,D1,40,40.032,-0.05,0.05\n"
                  "2,0,D2,12.5,12.511,-0.01,0.02\n2,0,D1,40,40.028,-0.05,0.05\n");
  CliRun r = cli("setup --model m.json --data flansch_chr.txt --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("2 parts"), std::string::npos) << r.err;
  r = cli("setup --model m.json --data r.csv --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json(tmp, "a.json")["corrections_mm"], json(tmp, "b.json")["corrections_mm"]);
  EXPECT_NEAR(json(tmp, "a.json")["f1_mm"].get<double>(), json(tmp, "b.json")["f1_mm"].get<double>(), 1e-12);
  // A tolerance that disagrees with the model is named with its line.
  std::string off = kChr;
  off.replace(off.find("0,0500\t-0,0500\t0,0280"), 6, "0,0600");
  test::writeText(tmp.file("off_chr.txt"), off);
  r = cli("setup --model m.json --data off_chr.txt", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("off_chr.txt:5"), std::string::npos) << r.err;
  // spc on a characteristic of the table (four parts): by its id.
  test::writeText(tmp.file("vier_chr.txt"),
                  kChr +
                      "Flansch\t3\tAbstand_E1\tDistance\t\t40,0300\t40,0000\t0,0500\t-0,0500\t0,0300\r\n"
                      "Flansch\t4\tAbstand_E1\tDistance\t\t40,0260\t40,0000\t0,0500\t-0,0500\t0,0260\r\n");
  r = cli("spc --data vier_chr.txt --characteristic Abstand_E1 --subgroup 2 --out s.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json(tmp, "s.json")["lsl"], 39.95);
}

TEST(CalypsoCli, FeaturesFileIsMatchedLikeTheProbePointCsv) {
  test::TempDir tmp;
  // Six points on three faces of a block, measured 0.01 mm off along x and rotated slightly.
  test::writeText(
      tmp.file("block_fet.txt"),
      "planid\tpartnb\tid\ttype\tx\ty\tz\tx_nom\ty_nom\tz_nom\tnx\tny\tnz\r\n"
      "Block\t1\tP1\tPoint\t10,0100\t2,0010\t3,0000\t10,0000\t2,0000\t3,0000\t1,0000\t0,0000\t0,0000\r\n"
      "Block\t1\tP2\tPoint\t10,0100\t8,0010\t6,0000\t10,0000\t8,0000\t6,0000\t1,0000\t0,0000\t0,0000\r\n"
      "Block\t1\tP3\tPoint\t4,0100\t10,0000\t3,0000\t4,0000\t10,0000\t3,0000\t0,0000\t1,0000\t0,0000\r\n"
      "Block\t1\tP4\tPoint\t7,0100\t10,0000\t7,0000\t7,0000\t10,0000\t7,0000\t0,0000\t1,0000\t0,0000\r\n"
      "Block\t1\tP5\tPoint\t3,0100\t3,0020\t10,0000\t3,0000\t3,0000\t10,0000\t0,0000\t0,0000\t1,0000\r\n"
      "Block\t1\tP6\tPoint\t8,0100\t6,0000\t10,0000\t8,0000\t6,0000\t10,0000\t0,0000\t0,0000\t1,0000\r\n");
  test::writeText(tmp.file("p.csv"),
                  "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n"
                  "P1,Point,10,2,3,1,0,0,10.01,2.001,3\nP2,Point,10,8,6,1,0,0,10.01,8.001,6\n"
                  "P3,Point,4,10,3,0,1,0,4.01,10,3\nP4,Point,7,10,7,0,1,0,7.01,10,7\n"
                  "P5,Point,3,3,10,0,0,1,3.01,3.002,10\nP6,Point,8,6,10,0,0,1,8.01,6,10\n");
  CliRun r = cli("match --data block_fet.txt --method closed-form --tolerance 0.005 --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("match --data p.csv --method closed-form --tolerance 0.005 --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json a = json(tmp, "a.json"), b = json(tmp, "b.json");
  for (const char* key : {"translation_mm", "rotation_deg"})
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[key][k].get<double>(), b[key][k].get<double>(), 1e-12) << key;
  EXPECT_NEAR(a["translation_mm"][0].get<double>(), 0.01, 2e-3);
  EXPECT_EQ(a["out_of_tolerance"], b["out_of_tolerance"]);
}

TEST(DfqCalypsoCli, ProjectAddByKindAndByContent) {
  test::TempDir tmp;
  test::writeText(tmp.file("w.dfq"), dfq());
  test::writeText(tmp.file("messung.txt"), dfq());  // recognised by content, not by the name
  test::writeText(tmp.file("flansch_chr.txt"), kChr);
  test::writeText(tmp.file("tabelle.txt"), kChr);
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  CliRun r = cli("project add P.metrofit dfq w.dfq", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit auto messung.txt", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("read as dfq"), std::string::npos) << r.err;
  r = cli("project add P.metrofit calypso flansch_chr.txt", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project add P.metrofit auto tabelle.txt", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("read as calypso"), std::string::npos) << r.err;
  r = cli("project list P.metrofit --out l.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json l = json(tmp, "l.json");
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l[0]["kind"], "dfq");
  EXPECT_EQ(l[0]["rows"], 12);  // measured parts
  EXPECT_EQ(l[0]["columns"], (nlohmann::json{"1 (Durchmesser 12,5)", "2 (L\xC3\xA4nge)"}));
  EXPECT_EQ(l[1]["kind"], "dfq");
  EXPECT_EQ(l[2]["kind"], "calypso");
  EXPECT_EQ(l[2]["rows"], 4);
  EXPECT_EQ(l[3]["kind"], "calypso");
  // A file that is not of the kind: exit 2 naming it, the project unchanged.
  const std::string before = test::readText(tmp.file("P.metrofit"));
  r = cli("project add P.metrofit dfq flansch_chr.txt --id x", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("flansch_chr.txt:1: not a Q-DAS DFQ file"), std::string::npos) << r.err;
  r = cli("project add P.metrofit calypso w.dfq --id y", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a Zeiss Calypso table"), std::string::npos) << r.err;
  r = cli("project add P.metrofit dfq w.dfq --id z --delimiter ';'", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::readText(tmp.file("P.metrofit")), before);
}

}  // namespace
}  // namespace metrofit
