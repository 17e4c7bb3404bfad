// MTConnect SHDR logs, Streams and Devices documents (core/io/mtconnect.h), against the real OKUMA
// adapter log and the cppagent documents in ../shared/data/real/mtconnect-samples (facts from its README
// and counts made here by plain text scanning, not by the reader), and against SHDR written here from the
// protocol's description with the zero-order-hold table worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/file_io.h"
#include "core/io/mtconnect.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string sample(const std::string& name) {
  return test::realData("mtconnect-samples/" + name).string();
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(line);
  }
  return out;
}

TEST(MtconnectTime, IsoTimestampsToEpochSeconds) {
  EXPECT_EQ(*parseIsoTimestamp("1970-01-01T00:00:00Z"), 0.0);
  // 2022-08-08 is day 19212 after 1970-01-01 (52 years with 13 leap days, plus Jan-Jul 2022 and 7 days).
  EXPECT_NEAR(*parseIsoTimestamp("2022-08-08T13:51:34.7167146Z"),
              19212 * 86400.0 + 13 * 3600 + 51 * 60 + 34.7167146, 1e-6);
  EXPECT_EQ(*parseIsoTimestamp("2000-03-01T00:00:00+01:00"), 11017 * 86400.0 - 3600.0);
  EXPECT_FALSE(parseIsoTimestamp("2022-08-08 13:51"));
  EXPECT_FALSE(parseIsoTimestamp("08.08.2022T13:51:34Z"));
  EXPECT_FALSE(parseIsoTimestamp("2022-13-08T13:51:34Z"));
}

// Written from the protocol: two samples, one out of time order, an UNAVAILABLE, a TEMPERATURE condition
// (never a column), a command line and an asset block.
const char* kShdr =
    "2024-01-01T00:00:10Z|T1|20.5|S1|1000\n"
    "2024-01-01T00:00:05Z|T1|20.0\n"
    "* shdrVersion: 2\n"
    "2024-01-01T00:00:20Z|T1|UNAVAILABLE\n"
    "2024-01-01T00:00:21Z|@ASSET@|A1|CuttingTool|--multiline--XY\n"
    "<CuttingTool assetId=\"A1\"/>\n"
    "--multiline--XY\n"
    "2024-01-01T00:00:31.5Z|T1|21|Tc|WARNING|1|HIGH||too hot\n"
    "2024-01-01T00:00:40Z|S1|1200\n";

TEST(MtconnectShdr, ZeroOrderHoldOnTheGrid) {
  const MtcLog log = shdrFromText(kShdr, "w.shdr");
  EXPECT_EQ(log.commands, 1u);
  EXPECT_EQ(log.assets, 1u);
  ASSERT_EQ(log.observations.size(), 7u);  // T1 x4, S1 x2, Tc
  const MtcSampleTable t = mtconnectSampleTable(log, 10.0);
  EXPECT_EQ(t.table.header(), (std::vector<std::string>{"time_min", "T1", "S1"}));
  ASSERT_EQ(t.skipped.size(), 1u);
  EXPECT_EQ(t.skipped[0], "Tc: a condition");
  // t0 = 00:00:05 (the first sample); rows at 5, 15, 25, 35 s (the last sample is at 40 s).
  ASSERT_EQ(t.table.rowCount(), 4u);
  const char* expected[4][3] = {{"0", "20", ""},
                                {"0.16666666666666666", "20.5", "1000"},
                                {"0.3333333333333333", "", "1000"},  // T1 UNAVAILABLE since 20 s
                                {"0.5", "21", "1000"}};              // S1 = 1200 only at 40 s
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(t.table.cell(r, c), expected[r][c]) << r << "," << c;
  EXPECT_NE(t.rule.find("last observation at or before"), std::string::npos);
}

TEST(MtconnectShdr, BadInputNamesTheLine) {
  try {
    (void)shdrFromText("2024-01-01T00:00:10Z|T1|20.5\n2024-01-01 00:00|T1|3\n", "w.shdr");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("w.shdr:2"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)shdrFromText("2024-01-01T00:00:10Z|@ASSET@|A|T|--multiline--Q\n<x/>\n", "w.shdr"),
               ParseError);
  // No numeric sample at all.
  EXPECT_THROW((void)mtconnectSampleTable(shdrFromText("2024-01-01T00:00:10Z|mode|AUTOMATIC\n", "w"), 1.0),
               ValidationError);
  EXPECT_THROW((void)mtconnectSampleTable(shdrFromText(kShdr, "w"), 0.0), OptionsError);
}

TEST(MtconnectDevices, DataItemsOfTheCppagentDemo) {
  const std::string path = sample("Devices.xml");
  METROFIT_REQUIRE_PATH(path);
  const MtcDevices d = readMtconnectDevices(path);
  // README: OKUMA 100 data items, Mazak 116.
  std::size_t okuma = 0, mazak = 0;
  for (const MtcDataItem& i : d.items) {
    okuma += i.device == "OKUMA";
    mazak += i.device == "Mazak";
  }
  EXPECT_EQ(okuma, 100u);
  EXPECT_EQ(mazak, 116u);
  const MtcDataItem* s1 = d.find("S1speed");  // by name
  ASSERT_NE(s1, nullptr);
  EXPECT_EQ(s1->id, "LS1speed");
  EXPECT_EQ(s1->category, "SAMPLE");
  EXPECT_EQ(s1->type, "ROTARY_VELOCITY");
  EXPECT_EQ(s1->units, "REVOLUTION/MINUTE");
  const MtcDataItem* stemp = d.find("Stemp");
  ASSERT_NE(stemp, nullptr);
  EXPECT_EQ(stemp->category, "SAMPLE");
  EXPECT_EQ(stemp->units, "CELSIUS");
  // A TEMPERATURE condition is a condition, not a temperature.
  const MtcDataItem* cond = d.find("Stemp_cond");
  ASSERT_NE(cond, nullptr);
  EXPECT_EQ(cond->type, "TEMPERATURE");
  EXPECT_EQ(cond->category, "CONDITION");
}

TEST(MtconnectShdr, TheRealOkumaLog) {
  const std::string log = sample("okuma.txt"), devices = sample("Devices.xml");
  METROFIT_REQUIRE_PATH(log);
  METROFIT_REQUIRE_PATH(devices);
  const std::string text = readFile(log);
  // Counts made here by scanning the text (the README's figures): 10 770 lines, 9 command lines, asset
  // blocks and removals, the distinct keys of the data lines.
  const std::vector<std::string> lines = linesOf(text);
  EXPECT_EQ(lines.size(), 10770u);
  std::size_t commands = 0, assetLines = 0;
  bool inBlock = false;
  std::string marker;
  for (const std::string& l : lines) {
    if (inBlock) {
      if (l == marker) inBlock = false;
      continue;
    }
    if (!l.empty() && l[0] == '*') ++commands;
    if (l.find("|@") != std::string::npos) {
      ++assetLines;
      const auto m = l.find("--multiline--");
      if (m != std::string::npos) {
        inBlock = true;
        marker = l.substr(m);
      }
    }
  }
  EXPECT_EQ(commands, 9u);
  EXPECT_GE(assetLines, 118u + 34u);

  EXPECT_TRUE(looksLikeShdr(text));
  const MtcDevices d = readMtconnectDevices(devices);
  const MtcLog shdr = shdrFromText(text, "okuma.txt", &d);
  EXPECT_EQ(shdr.commands, commands);
  EXPECT_EQ(shdr.assets, assetLines);
  std::set<std::string> keys;
  std::size_t conditions = 0;
  for (const MtcObservation& o : shdr.observations) {
    keys.insert(o.key);
    conditions += o.condition;
  }
  EXPECT_EQ(keys.size(), 89u);  // README: 89 distinct keys
  // Condition lines, counted by their form (key|NORMAL||||): 40 in the file (the README says 42).
  std::size_t conditionLines = 0;
  for (const std::string& l : lines) conditionLines += l.find("|NORMAL||||") != std::string::npos;
  EXPECT_EQ(conditionLines, 40u);
  EXPECT_EQ(conditions, conditionLines);
  // Timestamps are not in order (README: 1 165 backward steps); the table is in time order anyway.
  std::size_t backward = 0;
  for (std::size_t i = 1; i < shdr.observations.size(); ++i)
    backward += shdr.observations[i].timeS < shdr.observations[i - 1].timeS;
  EXPECT_GT(backward, 0u);

  const MtcSampleTable t = mtconnectSampleTable(shdr, 10.0, &d);
  const std::vector<std::string>& header = t.table.header();
  ASSERT_FALSE(header.empty());
  EXPECT_EQ(header[0], "time_min");
  for (const char* k : {"S1speed", "X1actm", "Z1actw"})
    EXPECT_NE(std::find(header.begin(), header.end(), k), header.end()) << k;
  // No temperature is observed in this log (README); events, conditions and the 3-vector path position
  // are not columns; ApplicationInstallDate is not declared.
  for (const char* k : {"avail", "system", "p1LPathPos", "ApplicationInstallDate"})
    EXPECT_EQ(std::find(header.begin(), header.end(), k), header.end()) << k;
  auto skipped = [&](const std::string& key) {
    return std::find_if(t.skipped.begin(), t.skipped.end(),
                        [&](const std::string& s) { return s.rfind(key + ": ", 0) == 0; }) != t.skipped.end();
  };
  EXPECT_TRUE(skipped("ApplicationInstallDate"));
  EXPECT_TRUE(skipped("p1LPathPos"));
  // S1speed: its values on the grid lie within what the log holds (README: 0 to 2100 rev/min).
  const int s1 = t.table.columnIndex("S1speed");
  double lo = 1e300, hi = -1e300;
  for (std::size_t r = 0; r < t.table.rowCount(); ++r) {
    const std::string& cell = t.table.cell(r, static_cast<std::size_t>(s1));
    if (cell.empty()) continue;
    const double v = *num::parseDouble(cell);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 2100.0);
  EXPECT_GT(hi, 0.0);
  // The grid spans the sample observations (README: 13:37 to 14:30 UTC, about 53 min; asset timestamps,
  // which are older, do not count).
  const double minutes = (static_cast<double>(t.table.rowCount()) - 1.0) * 10.0 / 60.0;
  EXPECT_GT(minutes, 30.0);
  EXPECT_LT(minutes, 70.0);
}

TEST(MtconnectStreams, TheCppagentTestDocument) {
  const std::string path = sample("Streams_response_document_test.xml");
  METROFIT_REQUIRE_PATH(path);
  const std::string text = readFile(path);
  EXPECT_TRUE(looksLikeMtconnectStreams(text));
  EXPECT_FALSE(looksLikeShdr(text));
  const MtcLog log = mtconnectStreamsFromText(text, "s.xml");
  ASSERT_EQ(log.observations.size(), 4u);  // README: four observations
  const MtcSampleTable t = mtconnectSampleTable(log, 1.0);
  EXPECT_EQ(t.table.header(), (std::vector<std::string>{"time_min", "c1"}));
  ASSERT_EQ(t.table.rowCount(), 1u);
  EXPECT_EQ(t.table.cell(0, 1), "1556.33");
  EXPECT_EQ(t.skipped.size(), 3u);  // two asset events and the controller mode
}

}  // namespace
}  // namespace metrofit
