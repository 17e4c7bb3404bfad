// MTConnect logs read as thermal logs (core/thermal/thermal_log.h readThermalLog, thermal_data.h): the real
// OKUMA SHDR log of ../shared/data/real/mtconnect-samples (with the Devices.xml beside it) on a 1 s grid,
// its zero-order-hold values checked against a plain scan of the file made here (not the reader), and the
// gaps of an SHDR written here: an UNAVAILABLE stretch in a used column leaves those rows out (counted), in
// an unused column it leaves every row in. Runs under C, de_DE and pl_PL (LOCALES): no locale may change a
// number.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/mtconnect.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "testsupport.h"

namespace metrofit {
namespace {

struct Obs {
  double t = 0.0;  ///< seconds of the day (every line of the sample is on 2022-08-08)
  std::string value;
  long line = 0;
};

/// "2022-08-08T13:51:34.7167146Z" -> seconds of the day, by hand.
double secondsOfDay(const std::string& ts) {
  EXPECT_EQ(ts.substr(0, 11), "2022-08-08T") << ts;
  const double h = std::stod(ts.substr(11, 2)), m = std::stod(ts.substr(14, 2));
  double s = 0.0;
  std::string sec = ts.substr(17);
  if (!sec.empty() && sec.back() == 'Z') sec.pop_back();
  s = *num::parseDouble(sec);
  return h * 3600.0 + m * 60.0 + s;
}

/// The observations of every key of a plain SHDR scan: agent commands, asset blocks (until their closing
/// --multiline-- tag) and condition lines (level NORMAL/WARNING/FAULT and four more fields) skipped, the
/// rest read as key|value pairs.
std::map<std::string, std::vector<Obs>> scan(const std::string& text) {
  std::map<std::string, std::vector<Obs>> out;
  std::istringstream in(text);
  std::string line, closing;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!closing.empty()) {
      if (line == closing) closing.clear();
      continue;
    }
    if (line.empty() || line[0] == '*') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, '|');) f.push_back(field);
    if (line.back() == '|') f.push_back("");
    if (f.size() < 3) continue;
    if (f[1].rfind('@', 0) == 0) {
      const auto ml = line.find("--multiline--");
      if (ml != std::string::npos) closing = line.substr(ml);
      continue;
    }
    if (f.size() == 7 && (f[2] == "NORMAL" || f[2] == "WARNING" || f[2] == "FAULT")) continue;
    const double t = secondsOfDay(f[0]);
    for (std::size_t k = 1; k + 1 < f.size(); k += 2) out[f[k]].push_back({t, f[k + 1], n});
  }
  return out;
}

/// The last observation at or before t (by time; equal times: the later line), nullptr when none.
const Obs* heldAt(const std::vector<Obs>& obs, double t) {
  const Obs* best = nullptr;
  for (const Obs& o : obs)
    if (o.t <= t && (!best || o.t > best->t || (o.t == best->t && o.line > best->line))) best = &o;
  return best;
}

TEST(ThermalMtconnect, TheRealOkumaLogOnAOneSecondGrid) {
  const std::string file = test::realData("mtconnect-samples/okuma.txt").string();
  METROFIT_REQUIRE_PATH(file);
  const ThermalLog log = readThermalLog(file);  // no interval: the default grid, 1 s
  EXPECT_TRUE(log.gaps);
  EXPECT_EQ(log.timeColumn, "time_min");
  EXPECT_NE(log.resampling.find("zero-order hold"), std::string::npos) << log.resampling;
  EXPECT_NE(log.resampling.find("every 1 s"), std::string::npos) << log.resampling;
  // README: spindle speeds and axis positions are samples; conditions never are columns.
  for (const char* key : {"S1speed", "X1actm", "Z1actm"}) EXPECT_GE(log.indexOf(key), 0) << key;
  for (const char* key : {"system", "CoolantSystem1_cond", "avail", "pexecution"})
    EXPECT_LT(log.indexOf(key), 0) << key;

  const auto obs = scan(test::readText(file));
  // The grid: from the first to the last observation of the columns, 1 s apart (the log is not in time
  // order: the minimum and maximum over the whole file).
  double t0 = 1e99, t1 = -1e99;
  for (const ThermalChannel& c : log.channels) {
    ASSERT_TRUE(obs.count(c.name)) << c.name;
    for (const Obs& o : obs.at(c.name)) {
      t0 = std::min(t0, o.t);
      t1 = std::max(t1, o.t);
    }
  }
  // README: sessions from 13:37 to 14:30 UTC.
  EXPECT_GT(t0, 13 * 3600.0 + 37 * 60.0);
  EXPECT_LT(t1, 14 * 3600.0 + 31 * 60.0);
  ASSERT_EQ(log.rows(), static_cast<std::size_t>(std::floor(t1 - t0 + 1e-6)) + 1);
  EXPECT_NEAR(log.timeMin[1] - log.timeMin[0], 1.0 / 60.0, 1e-12);

  // Every 37th row of three columns: the value held at the grid time, read from the scan (rows whose grid
  // time lies within 1 ms of an observation of the key are not asked: the reader's epoch seconds and
  // these seconds of the day round differently there).
  int checked = 0;
  for (const char* key : {"S1speed", "X1actm", "Z1actm"}) {
    const std::vector<Obs>& o = obs.at(key);
    const ThermalChannel& c = log.channel(key);
    for (std::size_t r = 0; r < log.rows(); r += 37) {
      const double t = t0 + static_cast<double>(r);
      bool near = false;
      for (const Obs& x : o) near = near || std::abs(x.t - t) < 1e-3;
      if (near) continue;
      const Obs* held = heldAt(o, t);
      if (!held || held->value == "UNAVAILABLE" || held->value.empty()) {
        EXPECT_TRUE(std::isnan(c.values[r])) << key << " row " << r;
      } else {
        EXPECT_EQ(c.values[r], *num::parseDouble(held->value))
            << key << " row " << r << " line " << held->line;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);

  // A 10 s grid: a tenth of the rows (give or take the last one), the same held values.
  CsvReadOptions tenSeconds;
  tenSeconds.sampleIntervalMin = 10.0 / 60.0;
  const ThermalLog coarse = readThermalLog(file, 3, tenSeconds);
  EXPECT_EQ(coarse.rows(), static_cast<std::size_t>(std::floor((t1 - t0) / 10.0 + 1e-6)) + 1);
  EXPECT_NE(coarse.resampling.find("every 10 s"), std::string::npos) << coarse.resampling;
}

/// An SHDR log written here: T1, T2, T3 and disp every 10 s for 300 s; T2 UNAVAILABLE from 100 s until
/// its next value at 130 s, T3 UNAVAILABLE from 200 s until 230 s; only changes are sent.
std::string gapLog() {
  std::string s = "* shdrVersion: 2.0\n";
  for (int k = 0; k <= 30; ++k) {
    const std::string ts = "2024-03-01T08:" + std::string(k * 10 / 60 < 10 ? "0" : "") +
                           std::to_string(k * 10 / 60) + ":" + (k * 10 % 60 < 10 ? "0" : "") +
                           std::to_string(k * 10 % 60) + ".0000000Z";
    const double t1 = 20.0 + 0.1 * k, t2 = 21.0 + 0.05 * k + 0.2 * std::sin(k), t3 = 19.0 + 0.02 * k * k;
    const double disp = 0.5 * (t1 - 20.0) + 0.3 * (t2 - 21.0);
    s += ts + "|T1|" + num::fixed(t1, 3);
    if (k == 10) s += "|T2|UNAVAILABLE";
    if (k < 10 || k >= 13) s += "|T2|" + num::fixed(t2, 3);
    if (k == 20) s += "|T3|UNAVAILABLE";
    if (k < 20 || k >= 23) s += "|T3|" + num::fixed(t3, 3);
    s += "|disp|" + num::fixed(disp, 4) + "\n";
    if (k == 5) s += ts + "|system|NORMAL||||\n";  // a condition: never a column
  }
  return s;
}

TEST(ThermalMtconnect, GapsInAUsedColumnLeaveTheirRowsOutAndAreCounted) {
  test::TempDir tmp;
  test::writeText(tmp.file("gaps.txt"), gapLog());
  CsvReadOptions o;
  o.sampleIntervalMin = 10.0 / 60.0;
  const ThermalLog log = readThermalLog(tmp.file("gaps.txt"), 3, o);
  ASSERT_EQ(log.rows(), 31u);
  EXPECT_LT(log.indexOf("system"), 0);
  // By hand: T2 has no value at 100, 110, 120 s (rows 10-12), T3 none at 200, 210, 220 s (rows 20-22).
  for (std::size_t r = 0; r < 31; ++r) {
    EXPECT_EQ(std::isnan(log.channel("T2").values[r]), r >= 10 && r <= 12) << r;
    EXPECT_EQ(std::isnan(log.channel("T3").values[r]), r >= 20 && r <= 22) << r;
  }
  EXPECT_EQ(log.channel("T2").values[13], *num::parseDouble(num::fixed(21.0 + 0.65 + 0.2 * std::sin(13), 3)));

  const thermal::ThermalSeries both = thermal::selectThermalSeries(log, "disp", {"T1", "T2"});
  EXPECT_EQ(both.rowsWithGapsLeftOut, 3u);
  EXPECT_EQ(both.rows(), 28u);
  EXPECT_NEAR(both.timeMin[10], 130.0 / 60.0, 1e-12);  // row 10 of the series is the grid's 130 s
  for (const auto& in : both.inputs)
    for (double v : in) EXPECT_TRUE(std::isfinite(v));
  // T3's gap is in a column not used: nothing left out.
  const thermal::ThermalSeries t1Only = thermal::selectThermalSeries(log, "disp", {"T1"});
  EXPECT_EQ(t1Only.rowsWithGapsLeftOut, 0u);
  EXPECT_EQ(t1Only.rows(), 31u);
  // T3 used: its three rows.
  EXPECT_EQ(thermal::selectThermalSeries(log, "disp", {"T1", "T3"}).rowsWithGapsLeftOut, 3u);
  EXPECT_EQ(thermal::selectThermalSeries(log, "disp", {"T2", "T3"}).rowsWithGapsLeftOut, 6u);

  // What the diagnosis reads: the rows without a gap in the used columns, and no channel with a gap.
  std::size_t leftOut = 0;
  const ThermalLog clean = thermal::thermalLogWithoutGaps(log, {"disp", "T1", "T2"}, &leftOut);
  EXPECT_EQ(leftOut, 3u);
  EXPECT_FALSE(clean.gaps);
  EXPECT_EQ(clean.rows(), 28u);
  EXPECT_LT(clean.indexOf("T3"), 0);  // a gap left in rows 20-22: not offered
  for (const ThermalChannel& c : clean.channels)
    for (double v : c.values) EXPECT_TRUE(std::isfinite(v)) << c.name;
  // As CSV a gap is an empty cell, never "nan".
  EXPECT_EQ(thermalLogToCsv(log).find("nan"), std::string::npos);
}

TEST(ThermalMtconnect, ACsvLogKeepsItsRules) {
  // A NaN in a log built in code is still an error naming the row (no gaps there).
  ThermalLog log;
  log.source = "built";
  log.timeMin = {0.0, 1.0, 2.0};
  log.channels = {{"T1", "", {1.0, std::nan(""), 3.0}}, {"disp", "um", {0.0, 1.0, 2.0}}};
  EXPECT_THROW((void)thermal::selectThermalSeries(log, "disp", {"T1"}), ValidationError);
}

}  // namespace
}  // namespace metrofit
