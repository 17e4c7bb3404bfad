// CSV files as shops write them (issue 28 item 1): a title line above the header, ';' and decimal
// commas, units in brackets, German and Polish column names. The files are written here from those
// conventions, and the real CAIVIAC spindle log (../shared/data/real/thermal-spindle-caiviac) is
// rewritten here the way a German spreadsheet saves it and must read back to the same numbers.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/thermal/thermal_log.h"
#include "testsupport.h"

namespace metrofit {
namespace {

const char* kGermanLog =
    "Spindel-W\xC3\xA4rmegang DMU 50, Messung vom 01.05.2024\n"
    "Zeit [min];Temperatur T1 [\xC2\xB0"
    "C];Verlagerung K3 [\xC2\xB5m];Drehzahl [1/min]\n"
    "0;20,5;0,0;0\n"
    "0,25;20,7;1,25;1250\n"
    "0,5;21,0;2,5;1250\n";

TEST(ShopCsv, TitleLineAboveTheHeaderIsSkippedAndKeptAsAComment) {
  const CsvTable t = parseCsv(kGermanLog, "Spindel.csv");
  EXPECT_EQ(t.headerLineNumber(), 2);
  ASSERT_EQ(t.columnCount(), 4u);
  EXPECT_EQ(t.header()[0], "Zeit [min]");
  EXPECT_EQ(t.dialect().delimiter, ';');
  EXPECT_EQ(t.dialect().decimal, ',');
  EXPECT_EQ(t.rowCount(), 3u);
  EXPECT_DOUBLE_EQ(t.number(1, 2), 1.25);
  ASSERT_EQ(t.comments().size(), 1u);
  EXPECT_EQ(t.comments()[0], "Spindel-W\xC3\xA4rmegang DMU 50, Messung vom 01.05.2024");
  EXPECT_EQ(detectCsvPreamble(kGermanLog, {}), 1);
}

TEST(ShopCsv, SeveralTitleAndMetadataLinesAndCommentsBeforeTheHeader) {
  const std::string text =
      "# exported by logger v2\n"
      "Maschine:;DMU 50\n"
      "Datum:;01.05.2024\n"
      "\n"
      "Czas [s];Temperatura T1 [\xC2\xB0"
      "C];Przemieszczenie Z [\xC2\xB5m]\n"
      "0;20,5;0\n"
      "15;20,6;0,5\n";
  EXPECT_EQ(detectCsvPreamble(text, {}), 4);
  const CsvTable t = parseCsv(text, "log.csv");
  EXPECT_EQ(t.headerLineNumber(), 5);
  EXPECT_EQ(t.header()[2], "Przemieszczenie Z [\xC2\xB5m]");
  EXPECT_DOUBLE_EQ(t.number(1, 2), 0.5);
}

TEST(ShopCsv, AHeaderOnTheFirstLineIsFoundAsBefore) {
  EXPECT_EQ(detectCsvPreamble("time_min,T1,disp_z_um\n0,20,0\n1,21,1\n", {}), 0);
  EXPECT_EQ(detectCsvPreamble("# note\ntime_min,T1\n0,20\n", {}), 0);
  // Names above names (no row of numbers anywhere): nothing to detect, the first row is the header.
  EXPECT_EQ(detectCsvPreamble("title only\nid,surface\nP1,top\n", {}), 0);
  // An explicit header line count is not second-guessed.
  CsvReadOptions o;
  o.headerLines = 0;
  EXPECT_THROW((void)parseCsv(kGermanLog, "x.csv", o), ParseError);
}

TEST(ShopCsv, BracketUnitsGiveTheChannelsTheirKindsAndMillimetresBecomeMicrometres) {
  const std::string text =
      "Zeit [min];Temperatur T1 [\xC2\xB0"
      "C];Verlagerung K1 [mm];Verlagerung K3 [\xC2\xB5m];Drehzahl [1/min]\n"
      "0;20,5;0,001;1;0\n"
      "1;20,7;0,002;2;1250\n"
      "2;21,0;0,003;3;1250\n";
  CsvReadOptions o;
  o.columnMap = {{"time_min", "Zeit [min]"}};
  const ThermalLog log = thermalLogFromCsv(parseCsv(text, "log.csv", o));
  ASSERT_EQ(log.channels.size(), 4u);
  EXPECT_EQ(log.channels[0].unit, "degC");
  EXPECT_EQ(channelKind(log.channels[0]), ChannelKind::Temperature);
  EXPECT_EQ(log.channels[1].unit, "um");
  EXPECT_EQ(channelKind(log.channels[1]), ChannelKind::Displacement);
  EXPECT_NEAR(log.channels[1].values[2], 3.0, 1e-12);  // 0,003 mm
  EXPECT_EQ(log.channels[2].unit, "um");
  EXPECT_DOUBLE_EQ(log.channels[2].values[2], 3.0);
  EXPECT_EQ(log.channels[3].unit, "rpm");
  EXPECT_EQ(channelKind(log.channels[3]), ChannelKind::Speed);
}

TEST(ShopCsv, PolishNamesGiveTheChannelsTheirKinds) {
  const ThermalChannel speed{
      "Pr\xC4\x99"
      "dko\xC5\x9B\xC4\x87 obrotowa",
      "",
      {}};
  const ThermalChannel disp{"Przemieszczenie Z", "", {}};
  const ThermalChannel temp{"Temperatura wrzeciona", "", {}};
  EXPECT_EQ(channelKind(speed), ChannelKind::Speed);
  EXPECT_EQ(channelKind(disp), ChannelKind::Displacement);
  EXPECT_EQ(channelKind(temp), ChannelKind::Temperature);
  EXPECT_EQ(channelKind(ThermalChannel{"Drehzahl", "", {}}), ChannelKind::Speed);
  EXPECT_EQ(channelKind(ThermalChannel{"Verlagerung Z", "", {}}), ChannelKind::Displacement);
}

std::string germanNumber(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  for (char& c : s)
    if (c == '.') c = ',';
  return s;
}

TEST(ShopCsv, TheRealCaiviacLogSavedTheGermanWayReadsBackToTheSameNumbers) {
  const auto path = test::realData("thermal-spindle-caiviac/thermal_caiviac.csv");
  METROFIT_REQUIRE_PATH(path);
  const ThermalLog original = readThermalLog(path.string());
  ASSERT_EQ(original.channels.size(), 22u);
  // The German spreadsheet: a title line, ';', decimal commas, time in minutes, names with units in
  // brackets; K5 in mm.
  std::ostringstream out;
  out << "Spindel-W\xC3\xA4rmegang (CAIVIAC FL_THERMAL), 15-s-Raster\n";
  out << "Zeit [min];Drehzahl [1/min]";
  for (int k = 1; k <= 4; ++k) out << ";Verlagerung K" << k << " [\xC2\xB5m]";
  out << ";Verlagerung K5 [mm]";
  for (int k = 1; k <= 16; ++k)
    out << ";Temperatur T" << k
        << " [\xC2\xB0"
           "C]";
  out << "\n";
  for (std::size_t r = 0; r < original.rows(); ++r) {
    out << germanNumber(original.timeMin[r]);
    for (std::size_t c = 0; c < original.channels.size(); ++c) {
      const double v = original.channels[c].values[r] / (c == 5 ? 1000.0 : 1.0);
      out << ';' << germanNumber(v);
    }
    out << "\n";
  }
  const std::string text = out.str();
  const CsvTable table = parseCsv(text, "Spindel_Waermegang.csv");
  EXPECT_EQ(table.headerLineNumber(), 2);
  EXPECT_EQ(table.dialect().decimal, ',');
  EXPECT_TRUE(table.skippedRows().empty());
  CsvReadOptions o;
  o.columnMap = {{"time_min", "Zeit [min]"}};
  const ThermalLog german = thermalLogFromCsv(parseCsv(text, "Spindel_Waermegang.csv", o));
  ASSERT_EQ(german.rows(), original.rows());
  ASSERT_EQ(german.channels.size(), original.channels.size());
  for (std::size_t r = 0; r < original.rows(); ++r) ASSERT_DOUBLE_EQ(german.timeMin[r], original.timeMin[r]);
  for (std::size_t c = 0; c < original.channels.size(); ++c) {
    EXPECT_EQ(channelKind(german.channels[c]), channelKind(original.channels[c])) << german.channels[c].name;
    EXPECT_EQ(german.channels[c].unit, c == 0 ? "rpm" : c <= 5 ? "um" : "degC") << german.channels[c].name;
    for (std::size_t r = 0; r < original.rows(); ++r)
      ASSERT_NEAR(german.channels[c].values[r], original.channels[c].values[r],
                  1e-9 * std::max(1.0, std::abs(original.channels[c].values[r])))
          << german.channels[c].name << " row " << r;
  }
}

}  // namespace
}  // namespace metrofit
