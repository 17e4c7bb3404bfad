// CSV dialects (docs/file-formats.md#csv-dialects-and-standard-input: --delimiter / --decimal, default auto)
// and the column mapping (--map ROLE=COLUMN) of core/io/csv.h.
#include <gtest/gtest.h>

#include <sstream>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/thermal/thermal_log.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CsvDialect, DetectsSemicolonWithDecimalComma) {
  const CsvTable t =
      parseCsv("# Messung 3\ntime_min;T1;disp_z_um\n0;20,5;0\n1;20,75;-1,25\n2;21;-2\n", "de.csv");
  EXPECT_EQ(t.dialect().delimiter, ';');
  EXPECT_EQ(t.dialect().decimal, ',');
  ASSERT_EQ(t.columnCount(), 3u);
  EXPECT_EQ(t.number(0, 1), 20.5);
  EXPECT_EQ(t.number(1, 2), -1.25);
  EXPECT_EQ(t.number(2, 1), 21.0);
}

TEST(CsvDialect, SemicolonWithDecimalPointStaysPoint) {
  const CsvTable t = parseCsv("a;b\n1.5;2\n3.25;4\n", "p.csv");
  EXPECT_EQ(t.dialect().delimiter, ';');
  EXPECT_EQ(t.dialect().decimal, '.');
  EXPECT_EQ(t.number(1, 0), 3.25);
}

TEST(CsvDialect, CommaFileKeepsPointAndOldBehaviour) {
  const CsvTable t = parseCsv("a,b\n1.5,2\n", "c.csv");
  EXPECT_EQ(t.dialect(), (CsvDialect{',', '.'}));
  EXPECT_EQ(t.number(0, 0), 1.5);
}

TEST(CsvDialect, ExplicitDialectOverridesDetection) {
  CsvReadOptions o;
  o.dialect = {';', ','};
  // "1.234" would be a '.' number; with decimal ',' it is an error naming line and field.
  const CsvTable t = parseCsv("x;y\n1,5;1.234\n", "e.csv", o);
  EXPECT_EQ(t.number(0, 0), 1.5);
  const std::string m = message([&] { (void)t.number(0, 1); });
  EXPECT_NE(m.find("e.csv:2:2"), std::string::npos) << m;
  EXPECT_NE(m.find("'y'"), std::string::npos) << m;
  EXPECT_NE(m.find("decimal separator is ','"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(CsvDialect, DecimalCommaInPointFileNamesTheCell) {
  CsvReadOptions o;
  o.dialect = {';', '.'};
  const CsvTable t = parseCsv("x;y\n1;2,5\n", "f.csv", o);
  const std::string m = message([&] { (void)t.number(0, 1); });
  EXPECT_NE(m.find("f.csv:2:2"), std::string::npos) << m;
  EXPECT_NE(m.find("decimal separator is '.'"), std::string::npos) << m;
}

TEST(CsvDialect, TieBetweenDecimalFormsIsAnError) {
  const std::string m = message([] { (void)parseCsv("x;y\n1,5;2.5\n", "t.csv"); });
  EXPECT_NE(m.find("t.csv:2:"), std::string::npos) << m;
  EXPECT_NE(m.find("decimal"), std::string::npos) << m;
}

TEST(CsvDialect, ExplicitCommaDelimiterOnSemicolonHeaderSaysSo) {
  CsvReadOptions o;
  o.dialect.delimiter = ',';
  const std::string m = message([&] { (void)parseCsv("a;b\n1;2\n", "s.csv", o); });
  EXPECT_NE(m.find("s.csv:1:1"), std::string::npos) << m;
  EXPECT_NE(m.find("separated by ';'"), std::string::npos) << m;
}

TEST(CsvDialect, ExplicitCommaDelimiterOnTabHeaderSaysSo) {
  CsvReadOptions o;
  o.dialect.delimiter = ',';
  const std::string m = message([&] { (void)parseCsv("a\tb\n1\t2\n", "s.csv", o); });
  EXPECT_NE(m.find("s.csv:1:1"), std::string::npos) << m;
  EXPECT_NE(m.find("separated by tabs"), std::string::npos) << m;
}

TEST(CsvDialect, OptionSpellings) {
  EXPECT_EQ(parseCsvDelimiter("auto"), 0);
  EXPECT_EQ(parseCsvDelimiter(","), ',');
  EXPECT_EQ(parseCsvDelimiter(";"), ';');
  EXPECT_EQ(parseCsvDelimiter("tab"), '\t');
  EXPECT_EQ(parseCsvDecimal("."), '.');
  EXPECT_EQ(parseCsvDecimal(","), ',');
  EXPECT_EQ(csvDelimiterName('\t'), "tab");
  EXPECT_EQ(csvDecimalName(0), "auto");
  EXPECT_THROW(parseCsvDelimiter("|"), OptionsError);
  EXPECT_THROW(parseCsvDecimal(";"), OptionsError);
  EXPECT_EQ(parseColumnMapping("time_min=Zeit [min]"),
            (std::pair<std::string, std::string>{"time_min", "Zeit [min]"}));
  EXPECT_THROW(parseColumnMapping("time_min"), OptionsError);
  EXPECT_THROW(parseColumnMapping("=x"), OptionsError);
}

// Real data: the Wenzel CMM export is tab separated (cmm-wenzel-lens-points/CIR4_1).
TEST(CsvDialect, ReadsTheRealTabSeparatedWenzelExport) {
  const std::string file = test::realData("cmm-wenzel-lens-points/CIR4_1").string();
  METROFIT_REQUIRE_PATH(file);
  const CsvTable t = readCsvFile(file);
  EXPECT_EQ(t.dialect().delimiter, '\t');
  ASSERT_EQ(t.columnCount(), 6u);
  EXPECT_EQ(t.header()[1], "x");
  ASSERT_EQ(t.rowCount(), 6u);
  // Row 1 of the file: 1  51.68  29.84  2.011  -0.001  3.002
  EXPECT_DOUBLE_EQ(t.number(0, 1), 51.68);
  EXPECT_DOUBLE_EQ(t.number(0, 4), -0.001);
  EXPECT_DOUBLE_EQ(t.number(4, 2), -59.008);
}

// Real data written the German way: the SJTU spindle log with ';' and decimal commas must give the
// numbers of the original comma-separated file.
TEST(CsvDialect, GermanCopyOfARealLogReadsTheSameNumbers) {
  const std::string file =
      test::realData("thermal-spindle-sjtu/thermal_expansion_error_original.csv").string();
  METROFIT_REQUIRE_PATH(file);
  std::istringstream in(test::readText(file));
  std::string line, head, german;
  for (int i = 0; i < 40 && std::getline(in, line); ++i) {
    head += line + "\n";
    for (char& c : line) c = c == ',' ? ';' : c == '.' ? ',' : c;
    german += line + "\r\n";
  }
  const CsvTable a = parseCsv(head, "orig.csv");
  const CsvTable b = parseCsv(german, "de.csv");
  EXPECT_EQ(b.dialect(), (CsvDialect{';', ','}));
  ASSERT_EQ(a.rowCount(), b.rowCount());
  ASSERT_EQ(a.header(), b.header());
  for (std::size_t c = 0; c < a.columnCount(); ++c) EXPECT_EQ(a.numericColumn(c), b.numericColumn(c));
  EXPECT_DOUBLE_EQ(b.number(0, 1), 25.634399);  // first data row, T0, as printed in the file
}

TEST(CsvDialect, MapsColumnsToRoles) {
  CsvReadOptions o;
  o.columnMap = {{"time_min", "Zeit"}, {"disp_z_um", "dZ"}};
  const CsvTable t = parseCsv("Zeit;T1;dZ\n0;20;0\n1;21;-1,5\n2;22;-3\n", "m.csv", o);
  EXPECT_EQ(t.header(), (std::vector<std::string>{"time_min", "T1", "disp_z_um"}));
  const ThermalLog log = thermalLogFromCsv(t);
  EXPECT_EQ(log.timeColumn, "time_min");
  EXPECT_EQ(log.channel("disp_z_um").values[1], -1.5);
}

TEST(CsvDialect, BadMappingsNameTheRole) {
  CsvReadOptions o;
  o.columnMap = {{"time_min", "Time"}};
  std::string m = message([&] { (void)parseCsv("Zeit,a\n1,2\n", "m.csv", o); });
  EXPECT_NE(m.find("m.csv: field 'time_min'"), std::string::npos) << m;
  EXPECT_NE(m.find("'Time'"), std::string::npos) << m;
  o.columnMap = {{"a", "Zeit"}};
  m = message([&] { (void)parseCsv("Zeit,a\n1,2\n", "m.csv", o); });
  EXPECT_NE(m.find("already has a column 'a'"), std::string::npos) << m;
  // Swapping two columns is fine.
  o.columnMap = {{"a", "Zeit"}, {"Zeit", "a"}};
  const CsvTable t = parseCsv("Zeit,a\n1,2\n", "m.csv", o);
  EXPECT_EQ(t.header(), (std::vector<std::string>{"a", "Zeit"}));
}

}  // namespace
}  // namespace metrofit
