// MTConnect logs through metrofit-cli (issue 29 item 4, the dataset kind `mtconnect`): project add (kind
// mtconnect and auto by content, the sample interval stored), thermal fit / diagnose thermal --data on
// the real OKUMA SHDR log of ../shared/data/real/mtconnect-samples and on an SHDR written here, the
// resampling rule and the rows left out for gaps in the result. The values checked are counted here by a
// plain scan of the file (not by our reader). LOCALES: the same under C, de_DE and pl_PL.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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

std::string okuma() {
  return test::realData("mtconnect-samples/okuma.txt").string();
}

/// Seconds of the day of "2022-08-08T13:51:34.7167146Z" (the sample is one day), by hand.
double secondsOfDay(const std::string& ts) {
  std::string sec = ts.substr(17);
  if (!sec.empty() && sec.back() == 'Z') sec.pop_back();
  return std::stod(ts.substr(11, 2)) * 3600.0 + std::stod(ts.substr(14, 2)) * 60.0 + *num::parseDouble(sec);
}

struct Scan {
  double first = 1e99, last = -1e99;  ///< over the observations of the keys asked for
  std::vector<double> firstOf;        ///< per key asked for: its first time
};

/// A plain scan of an SHDR log: commands, asset blocks and condition lines skipped, the rest key|value
/// pairs; the first and last times of `keys`.
Scan scan(const std::string& text, const std::vector<std::string>& keys) {
  Scan s;
  s.firstOf.assign(keys.size(), 1e99);
  std::istringstream in(text);
  std::string line, closing;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!closing.empty()) {
      if (line == closing) closing.clear();
      continue;
    }
    if (line.empty() || line[0] == '*') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, '|');) f.push_back(field);
    if (f.size() < 3) continue;
    if (f[1].rfind('@', 0) == 0) {
      if (const auto ml = line.find("--multiline--"); ml != std::string::npos) closing = line.substr(ml);
      continue;
    }
    if (f.size() == 7 && (f[2] == "NORMAL" || f[2] == "WARNING" || f[2] == "FAULT")) continue;
    const double t = secondsOfDay(f[0]);
    for (std::size_t k = 1; k + 1 < f.size(); k += 2)
      for (std::size_t i = 0; i < keys.size(); ++i)
        if (f[k] == keys[i]) {
          s.first = std::min(s.first, t);
          s.last = std::max(s.last, t);
          s.firstOf[i] = std::min(s.firstOf[i], t);
        }
  }
  return s;
}

TEST(MtconnectCli, ProjectAddTheRealOkumaLog) {
  METROFIT_REQUIRE_PATH(okuma());
  test::TempDir tmp;
  ASSERT_EQ(cli("project new P.metrofit", tmp).code, 0);
  // Recognised by content (auto) and named as such.
  CliRun r = cli("project add P.metrofit auto '" + okuma() + "' --id okuma", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("mtconnect"), std::string::npos) << r.err;
  // The same file with a 10 s grid, kind given.
  r = cli("project add P.metrofit mtconnect '" + okuma() + "' --id okuma10 --sample-interval 10s", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  r = cli("project list P.metrofit --out list.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json list = json(tmp, "list.json");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["kind"], "mtconnect");
  EXPECT_EQ(list[1]["kind"], "mtconnect");
  std::vector<std::string> columns;
  for (const auto& c : list[0]["columns"]) columns.push_back(c.get<std::string>());
  ASSERT_FALSE(columns.empty());
  EXPECT_EQ(columns.front(), "time_min");
  const std::set<std::string> has(columns.begin(), columns.end());
  for (const char* key : {"S1speed", "X1actm", "Z1actm"}) EXPECT_TRUE(has.count(key)) << key;
  for (const char* key : {"system", "avail", "CoolantSystem1_cond"}) EXPECT_FALSE(has.count(key)) << key;
  // Rows: the grid from the first to the last observation of the columns (a plain scan), 1 s and 10 s.
  const Scan s = scan(test::readText(okuma()), std::vector<std::string>(columns.begin() + 1, columns.end()));
  EXPECT_EQ(list[0]["rows"].get<long>(), static_cast<long>(std::floor(s.last - s.first + 1e-6)) + 1);
  EXPECT_EQ(list[1]["rows"].get<long>(), static_cast<long>(std::floor((s.last - s.first) / 10.0 + 1e-6)) + 1);
  // The interval is kept with the dataset (minutes).
  const nlohmann::json project = json(tmp, "P.metrofit");
  bool stored = false;
  for (const auto& d : project["datasets"])
    if (d["id"] == "okuma10") stored = std::abs(d["sample_interval_min"].get<double>() - 10.0 / 60.0) < 1e-12;
  EXPECT_TRUE(stored) << project.dump();
  // A CSV option does not apply to an MTConnect log.
  r = cli("project add P.metrofit mtconnect '" + okuma() + "' --id x --delimiter ';'", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

TEST(MtconnectCli, ThermalFitOnTheRealOkumaLog) {
  METROFIT_REQUIRE_PATH(okuma());
  test::TempDir tmp;
  CliRun r = cli("thermal fit --data '" + okuma() +
                     "' --target Z1actm --inputs S1speed,X1actm --model linear --out fit.json",
                 tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  const std::string text = test::readText(tmp.file("fit.json"));
  EXPECT_EQ(text.find("nan"), std::string::npos);
  const nlohmann::json j = parseJson(text, "fit.json");
  EXPECT_NE(j["resampling"].get<std::string>().find("zero-order hold"), std::string::npos);
  EXPECT_NE(j["resampling"].get<std::string>().find("every 1 s"), std::string::npos);
  // Rows: the 1 s grid over every sample column; those before the first value of a used column are left
  // out (the README: no UNAVAILABLE among these keys, so that is every gap they have).
  r = cli("project new P.metrofit", tmp);
  r = cli("project add P.metrofit mtconnect '" + okuma() + "' --id okuma", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(cli("project list P.metrofit --out list.json", tmp).code, 0);
  std::vector<std::string> columns;
  const nlohmann::json list = json(tmp, "list.json");
  for (const auto& c : list[0]["columns"]) columns.push_back(c.get<std::string>());
  ASSERT_GT(columns.size(), 3u);
  const std::string log = test::readText(okuma());
  for (const char* key : {"|S1speed|UNAVAILABLE", "|X1actm|UNAVAILABLE", "|Z1actm|UNAVAILABLE"})
    EXPECT_EQ(log.find(key), std::string::npos) << key;
  const Scan all = scan(log, std::vector<std::string>(columns.begin() + 1, columns.end()));
  const Scan used = scan(log, {"Z1actm", "S1speed", "X1actm"});
  const long rows = static_cast<long>(std::floor(all.last - all.first + 1e-6)) + 1;
  const double start = std::max({used.firstOf[0], used.firstOf[1], used.firstOf[2]});
  long gaps = 0;
  for (long k = 0; k < rows; ++k) gaps += all.first + static_cast<double>(k) < start ? 1 : 0;
  EXPECT_EQ(j["rows_with_gaps_left_out"].get<long>(), gaps);
  EXPECT_EQ(j["train_rows"].get<long>() + j["heldout_rows"].get<long>(), rows - gaps);
  EXPECT_TRUE(std::isfinite(j["fit_rmse"].get<double>()));
  // Another grid: 5 s.
  r = cli("thermal fit --data '" + okuma() +
              "' --target Z1actm --inputs S1speed,X1actm --model linear --sample-interval 5s --out fit5.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j5 = json(tmp, "fit5.json");
  EXPECT_NE(j5["resampling"].get<std::string>().find("every 5 s"), std::string::npos);
  const long rows5 = static_cast<long>(std::floor((all.last - all.first) / 5.0 + 1e-6)) + 1;
  EXPECT_EQ(j5["train_rows"].get<long>() + j5["heldout_rows"].get<long>() +
                j5["rows_with_gaps_left_out"].get<long>(),
            rows5);
}

/// An SHDR log written here: T1, T2, T3 and disp every 10 s for 590 s (60 rows on a 10 s grid); T2
/// UNAVAILABLE from 100 s until its next value at 130 s, T3 UNAVAILABLE from 200 s until 230 s; only changes
/// are sent.
std::string gapLog() {
  std::string s = "* shdrVersion: 2.0\n";
  for (int k = 0; k < 60; ++k) {
    const int m = k * 10 / 60, sec = k * 10 % 60;
    const std::string ts = "2024-03-01T08:0" + std::to_string(m) + ":" + (sec < 10 ? "0" : "") +
                           std::to_string(sec) + ".0000000Z";
    const double t1 = 20.0 + 0.1 * k, t2 = 21.0 + 0.05 * k + 0.2 * std::sin(k), t3 = 19.0 + 0.02 * k * k;
    const double disp = 0.5 * (t1 - 20.0) + 0.3 * (t2 - 21.0) + 0.01 * std::cos(3.0 * k);
    s += ts + "|T1|" + num::fixed(t1, 3);
    if (k == 10) s += "|T2|UNAVAILABLE";
    if (k < 10 || k >= 13) s += "|T2|" + num::fixed(t2, 3);
    if (k == 20) s += "|T3|UNAVAILABLE";
    if (k < 20 || k >= 23) s += "|T3|" + num::fixed(t3, 3);
    s += "|disp|" + num::fixed(disp, 4) + "\n";
  }
  return s;
}

TEST(MtconnectCli, GapsInAUsedColumnAreLeftOutAndCounted) {
  test::TempDir tmp;
  test::writeText(tmp.file("gaps.txt"), gapLog());
  const std::string fit = "thermal fit --data gaps.txt --target disp --model linear --sample-interval 10s ";
  // T2 used: its UNAVAILABLE stretch (100, 110, 120 s) is three rows left out of 60.
  CliRun r = cli(fit + "--inputs T1,T2 --out a.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("3 rows with gaps left out"), std::string::npos) << r.err;
  const std::string text = test::readText(tmp.file("a.json"));
  EXPECT_EQ(text.find("nan"), std::string::npos);
  const nlohmann::json a = parseJson(text, "a.json");
  EXPECT_EQ(a["rows_with_gaps_left_out"], 3);
  EXPECT_EQ(a["train_rows"].get<long>() + a["heldout_rows"].get<long>(), 57);
  EXPECT_NE(a["resampling"].get<std::string>().find("every 10 s"), std::string::npos);
  // T3's stretch is in a column not used: nothing left out.
  r = cli(fit + "--inputs T1 --out b.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json b = json(tmp, "b.json");
  EXPECT_EQ(b["rows_with_gaps_left_out"], 0);
  EXPECT_EQ(b["train_rows"].get<long>() + b["heldout_rows"].get<long>(), 60);
  // Both stretches used: six rows.
  r = cli(fit + "--inputs T2,T3 --out c.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json(tmp, "c.json")["rows_with_gaps_left_out"], 6);
  // diagnose thermal on the same log: the same count, no NaN anywhere in its result.
  r = cli("diagnose thermal --data gaps.txt --target disp --inputs T1,T2 --sample-interval 10s --out d.json",
          tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string d = test::readText(tmp.file("d.json"));
  EXPECT_EQ(d.find("nan"), std::string::npos);
  EXPECT_EQ(parseJson(d, "d.json")["rows_with_gaps_left_out"], 3);
  // A CSV log's result has neither key (the keys are added for MTConnect logs only).
  std::string csv = "time_min,T1,disp\n";
  for (int k = 0; k < 40; ++k)
    csv += std::to_string(k) + "," + num::fixed(20.0 + 0.1 * k, 2) + "," +
           num::fixed(0.05 * k + 0.01 * std::sin(k), 4) + "\n";
  test::writeText(tmp.file("log.csv"), csv);
  r = cli("thermal fit --data log.csv --target disp --inputs T1 --model linear --out e.json", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(json(tmp, "e.json").contains("rows_with_gaps_left_out"));
}

TEST(MtconnectCli, BadLogsAreOneLineErrorsNamingFileAndLine) {
  test::TempDir tmp;
  test::writeText(tmp.file("badtime.txt"),
                  "2024-03-01T08:00:00Z|T1|20|disp|0\n2024-03-01T08:00:10Z|T1|21|disp|1\n"
                  "2024-03-01T08:0O:20Z|T1|22|disp|2\n");
  CliRun r = cli("thermal fit --data badtime.txt --target disp --inputs T1 --model linear", tmp);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("badtime.txt:3"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace metrofit
