#include "core/io/csv.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "testsupport.h"

namespace metrofit {
namespace {

/// Parses and expects a ParseError whose message contains every fragment.
void expectParseError(const std::string& text, std::initializer_list<std::string> fragments) {
  try {
    (void)parseCsv(text, "in.csv");
    FAIL() << "no error for: " << text.substr(0, 80);
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << "message must be one line: " << what;
    for (const auto& f : fragments)
      EXPECT_NE(what.find(f), std::string::npos) << "'" << f << "' not in: " << what;
  }
}

TEST(Csv, ReadsHeaderRowsAndNumbers) {
  const CsvTable t = parseCsv("time_min,T1,disp_z_um\n0,20.5,0\n1,20.75,-1.25e-1\n", "a.csv");
  ASSERT_EQ(t.columnCount(), 3u);
  ASSERT_EQ(t.rowCount(), 2u);
  EXPECT_EQ(t.header()[1], "T1");
  EXPECT_EQ(t.number(1, 2), -0.125);
  EXPECT_EQ(t.lineOf(1), 3);
  EXPECT_EQ(t.numericColumn("T1"), (std::vector<double>{20.5, 20.75}));
}

TEST(Csv, AcceptsBomCrlfCommentsBlankLinesAndQuotes) {
  const std::string text =
      "\xEF\xBB\xBF# machine: DMU 50\r\n# operator: K.\r\n\r\nid,surface,note\r\n"
      "P1,top,\"a, \"\"quoted\"\" note\"\r\n\r\nP2,\"side\",\"two\nlines\"\r\n";
  const CsvTable t = parseCsv(text, "b.csv");
  ASSERT_EQ(t.comments().size(), 2u);
  EXPECT_EQ(t.comments()[0], " machine: DMU 50");
  EXPECT_EQ(t.header()[0], "id");  // BOM stripped
  ASSERT_EQ(t.rowCount(), 2u);
  EXPECT_EQ(t.cell(0, 2), "a, \"quoted\" note");
  EXPECT_EQ(t.cell(1, 1), "side");
  EXPECT_EQ(t.cell(1, 2), "two\nlines");
  EXPECT_EQ(t.lineOf(0), 5);
  EXPECT_EQ(t.lineOf(1), 7);
}

TEST(Csv, TrimsBlanksAroundUnquotedFields) {
  const CsvTable t = parseCsv("a, b\n 1 , 2\n", "c.csv");
  EXPECT_EQ(t.header()[1], "b");
  EXPECT_EQ(t.number(0, 0), 1.0);
}

TEST(Csv, HeaderOnlyIsATableWithoutRows) {
  const CsvTable t = parseCsv("a,b\n", "h.csv");
  EXPECT_EQ(t.rowCount(), 0u);
  try {
    t.requireRows(1);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "h.csv: has 0 data rows, at least 1 needed");
  }
}

TEST(Csv, MalformedInputsGiveOneLineErrorsWithLocation) {
  expectParseError("", {"in.csv", "empty"});
  expectParseError("\n\n  \n", {"empty"});
  expectParseError("# only a comment\n", {"no header row"});
  expectParseError(std::string("\xFF\xFE"
                               "a\0,\0b\0",
                               8),
                   {"in.csv:1", "UTF-16"});
  expectParseError(std::string("a,b\n1,\0\n", 8), {"in.csv:2:2", "NUL"});
  expectParseError(
      "a,b\n1,\xB0"
      "C\n",
      {"in.csv:2:2", "invalid UTF-8 byte 0xB0"});
  expectParseError("a,b\n1,\"open\n2,3\n", {"in.csv:2:2", "unterminated quoted field"});
  expectParseError("a,b\n1,\"x\"y\n", {"in.csv:2:2", "after the closing quote"});
  expectParseError("a,b\n1,ab\"c\n", {"in.csv:2:2", "quote inside an unquoted field"});
  expectParseError("a,b,c\n1,2,3\n4,5\n", {"in.csv:3", "row has 2 fields", "header (line 1) has 3"});
  expectParseError("a,b\n1,2,3\n", {"in.csv:2:3", "row has 3 fields"});
  expectParseError("a,,c\n1,2,3\n", {"in.csv:1:2", "empty column name"});
  expectParseError("a,b,a\n1,2,3\n", {"in.csv:1:3", "duplicate column name 'a'"});
  expectParseError("a\n" + std::string(CsvTable::kMaxFieldBytes + 10, 'x') + "\n",
                   {"in.csv:2:1", "longer than"});
}

TEST(Csv, NumbersAreStrictAndErrorsNameTheCell) {
  const CsvTable t = parseCsv("a,b\n1,abc\n2,\n3,nan\n4,inf\n5,\"1,5\"\n6,1.5x\n7,1e999\n", "n.csv");
  auto msg = [&](std::size_t r) {
    try {
      (void)t.number(r, 1);
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(msg(0), "n.csv:2:2: field 'b': 'abc' is not a number");
  EXPECT_EQ(msg(1), "n.csv:3:2: field 'b': empty value where a number is expected");
  EXPECT_EQ(msg(2), "n.csv:4:2: field 'b': 'nan' is not a finite number");
  EXPECT_EQ(msg(3), "n.csv:5:2: field 'b': 'inf' is not a finite number");
  EXPECT_EQ(msg(4), "n.csv:6:2: field 'b': '1,5' is not a number (use '.' as the decimal point)");
  EXPECT_EQ(msg(5), "n.csv:7:2: field 'b': '1.5x' is not a number");
  EXPECT_EQ(msg(6), "n.csv:8:2: field 'b': '1e999' is not a number");
}

TEST(Csv, ParseNumberAcceptsOnlyWholeFiniteNumbers) {
  double v = 0;
  EXPECT_TRUE(parseNumber("-0.001", &v));
  EXPECT_EQ(v, -0.001);
  EXPECT_TRUE(parseNumber("+2E3", &v));
  EXPECT_EQ(v, 2000.0);
  EXPECT_TRUE(parseNumber(" 7 ", &v));
  for (const char* bad : {"", " ", "1,5", "1.2.3", "0x10", "nan", "inf", "-", "1e", "++1"}) {
    EXPECT_FALSE(parseNumber(bad, &v)) << bad;
  }
}

TEST(Csv, MissingColumnListsWhatTheFileHas) {
  const CsvTable t = parseCsv("time_min,T1\n0,1\n", "m.csv");
  try {
    (void)t.requireColumn("disp_z_um");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "m.csv: field 'disp_z_um': missing column (the file has: time_min, T1)");
  }
}

TEST(Csv, WriterRoundTripsAwkwardFields) {
  CsvWriter w;
  w.comment("made by a test");
  w.row({"id", "note"});
  w.row({"#1", "a, \"b\"\nc"});
  w.row({" pad ", CsvWriter::formatNumber(0.1 + 0.2)});
  const CsvTable t = parseCsv(w.text(), "w.csv");
  ASSERT_EQ(t.rowCount(), 2u);
  EXPECT_EQ(t.comments()[0], " made by a test");
  EXPECT_EQ(t.cell(0, 0), "#1");
  EXPECT_EQ(t.cell(0, 1), "a, \"b\"\nc");
  EXPECT_EQ(t.cell(1, 0), " pad ");
  EXPECT_EQ(t.number(1, 1), 0.1 + 0.2);  // shortest round-trip formatting
  EXPECT_EQ(CsvWriter::formatNumber(1.0 / 3.0, 4), "0.3333");
}

TEST(Csv, ReadsFilesAndReportsMissingOnes) {
  test::TempDir dir;
  test::writeText(dir.file("x.csv"), "a\n1\n");
  EXPECT_EQ(readCsvFile(dir.file("x.csv")).rowCount(), 1u);
  try {
    (void)readCsvFile(dir.file("nope.csv"));
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.csv: cannot open file (it does not exist)"),
              std::string::npos);
  }
  EXPECT_THROW((void)readCsvFile(dir.path().string()), FileError);
}

TEST(Csv, RealCaiviacLogParses) {
  const auto path = test::sourceDir() / "resources/demo/data/thermal_caiviac.csv";
  const CsvTable t = readCsvFile(path.string());
  EXPECT_EQ(t.rowCount(), 11115u);
  EXPECT_EQ(t.columnCount(), 23u);
  EXPECT_EQ(t.header().front(), "time_s");
  EXPECT_EQ(t.number(1, 0), 15.0);
}

}  // namespace
}  // namespace metrofit
