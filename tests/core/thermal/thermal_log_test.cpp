#include "core/thermal/thermal_log.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string error(const std::string& text, std::size_t minRows = 3) {
  try {
    (void)thermalLogFromCsv(parseCsv(text, "log.csv"), minRows);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ThermalLog, TimeUnitsAreConvertedToMinutes) {
  const ThermalLog s =
      thermalLogFromCsv(parseCsv("time_s,T1_degC,disp_z_um\n0,20,0\n30,21,1\n90,22,2\n", "a"));
  EXPECT_EQ(s.timeMin, (std::vector<double>{0.0, 0.5, 1.5}));
  EXPECT_EQ(s.timeColumn, "time_s");
  ASSERT_EQ(s.channels.size(), 2u);
  EXPECT_EQ(s.channels[0].unit, "degC");
  EXPECT_EQ(channelKind(s.channels[0]), ChannelKind::Temperature);
  EXPECT_EQ(channelKind(s.channels[1]), ChannelKind::Displacement);
  const ThermalLog h = thermalLogFromCsv(parseCsv("time_h,T1\n0,1\n0.5,2\n1,3\n", "b"));
  EXPECT_EQ(h.timeMin.back(), 60.0);
  EXPECT_EQ(channelKind(h.channels[0]), ChannelKind::Temperature);
  EXPECT_EQ(h.channel("T1").values[1], 2.0);
}

TEST(ThermalLog, ValidationErrors) {
  EXPECT_EQ(error("t,T1\n0,1\n1,2\n2,3\n"),
            "log.csv: field 'time_s|time_min|time_h': no time column; the first column of a thermal log must "
            "be time_s, time_min or time_h, or give the sampling interval (--sample-interval 15s)");
  EXPECT_EQ(error("time_min,T1\n0,1\n2,2\n1,3\n"),
            "log.csv:4:1: field 'time_min': time does not increase (1 after 2); rows must be in strictly "
            "increasing time");
  EXPECT_EQ(error("time_min,T1\n0,1\n0,2\n1,3\n"),
            "log.csv:3:1: field 'time_min': time does not increase (0 after 0); rows must be in strictly "
            "increasing time");
  EXPECT_EQ(error("time_min,T1\n0,1\n1,2\n"), "log.csv: has 2 data rows, at least 3 needed");
  EXPECT_EQ(error("time_min\n0\n1\n2\n"), "log.csv: a thermal log needs sensor columns besides time");
  EXPECT_EQ(error("time_min,time_s,T1\n0,0,1\n1,60,2\n2,120,3\n"),
            "log.csv: field 'time_min': more than one time column; keep one of time_s, time_min, time_h");
  EXPECT_EQ(error("time_min,T1\n0,1\n1,NaN\n2,3\n"), "log.csv:3:2: field 'T1': 'NaN' is not a finite number");
}

TEST(ThermalLog, SampleIntervalGivesTheTimeOfALogWithoutATimeColumn) {
  EXPECT_DOUBLE_EQ(parseSampleInterval("15s"), 0.25);
  EXPECT_DOUBLE_EQ(parseSampleInterval("15 s"), 0.25);
  EXPECT_DOUBLE_EQ(parseSampleInterval("2min"), 2.0);
  EXPECT_DOUBLE_EQ(parseSampleInterval("0.5h"), 30.0);
  EXPECT_DOUBLE_EQ(parseSampleInterval("1 MIN "), 1.0);
  for (const char* bad : {"15", "s", "-5s", "0s", "15 sec", "15ms", "nan s", "", "1e999s"}) {
    try {
      (void)parseSampleInterval(bad);
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const OptionsError& e) {
      EXPECT_NE(std::string(e.what()).find("--sample-interval"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s, min or h"), std::string::npos) << e.what();
    }
  }

  const CsvTable sensors = parseCsv("T1_degC,disp_z_um\n20,0\n21,1\n22,2\n23,2.5\n", "s.csv");
  const ThermalLog log = thermalLogFromCsv(sensors, 3, 0.25);
  EXPECT_EQ(log.timeMin, (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
  EXPECT_EQ(log.timeColumn, "time_min");
  EXPECT_DOUBLE_EQ(log.sampleIntervalMin, 0.25);
  ASSERT_EQ(log.channels.size(), 2u);  // both columns are channels
  EXPECT_EQ(log.channels[0].name, "T1_degC");
  // The CSV it writes has a time column, so it reads back without the interval.
  EXPECT_EQ(thermalLogFromCsv(parseCsv(thermalLogToCsv(log), "w.csv")).timeMin, log.timeMin);
  // Without the interval: the error says how to give it.
  EXPECT_NE(error("T1_degC,disp_z_um\n20,0\n21,1\n22,2\n").find("--sample-interval"), std::string::npos);
  // A time column and an interval: which one is meant is not clear.
  try {
    (void)thermalLogFromCsv(parseCsv("time_s,T1\n0,1\n1,2\n2,3\n", "t.csv"), 3, 0.25);
    ADD_FAILURE() << "time column and interval accepted";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("time_s"), std::string::npos) << e.what();
  }
  // Through readThermalLog: the interval travels in CsvReadOptions.
  test::TempDir tmp;
  test::writeText(tmp.file("s.csv"), "T1;dZ_um\n20,5;0\n21,5;1\n22,5;2\n");
  CsvReadOptions csv;
  csv.sampleIntervalMin = 1.0;
  const ThermalLog read = readThermalLog(tmp.file("s.csv"), 3, csv);
  EXPECT_EQ(read.timeMin, (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_DOUBLE_EQ(read.channels[0].values[1], 21.5);
}

TEST(ThermalLog, UnknownChannelListsTheColumns) {
  const ThermalLog s = thermalLogFromCsv(parseCsv("time_min,T1,T2\n0,1,1\n1,2,2\n2,3,3\n", "x.csv"));
  try {
    (void)s.channel("T9");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "x.csv: field 'T9': no such column in the thermal log (it has: T1, T2)");
  }
}

TEST(ThermalLog, CsvRoundTrip) {
  const ThermalLog a =
      thermalLogFromCsv(parseCsv("time_s,T1,d_um\n0,20.125,0\n15,20.5,-0.25\n30,21,-1\n", "r"));
  const ThermalLog b = thermalLogFromCsv(parseCsv(thermalLogToCsv(a), "r2"));
  EXPECT_EQ(a.timeMin, b.timeMin);
  EXPECT_EQ(b.timeColumn, "time_s");
  EXPECT_EQ(a.channels[1].values, b.channels[1].values);
}

TEST(ThermalLog, RealCaiviacLog) {
  const ThermalLog log =
      readThermalLog((test::sourceDir() / "resources/demo/data/thermal_caiviac.csv").string());
  EXPECT_EQ(log.rows(), 11115u);
  EXPECT_EQ(log.channels.size(), 22u);
  EXPECT_TRUE(test::near(log.timeMin.back(), 166710.0 / 60.0, 1e-9));
  EXPECT_EQ(channelKind(log.channel("spindle_rpm")), ChannelKind::Speed);
  EXPECT_EQ(channelKind(log.channel("ch3_um")), ChannelKind::Displacement);
  EXPECT_EQ(channelKind(log.channel("t5_degC")), ChannelKind::Temperature);
}

}  // namespace
}  // namespace metrofit
