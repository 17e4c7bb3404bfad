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
            "be time_s, "
            "time_min or time_h");
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
