// The Q-DAS DFQ reader (core/io/dfq.h). The files below are written here from the AQDEF field list
// (Q-DAS ASCII transfer format: K0100 number of characteristics, K1001/K1002 part number and
// description, K2001/K2002 characteristic number and description, K2101 nominal, K2110/K2111 lower and
// upper specification limit, K2022 decimals, K2142 unit, K0001 value, K0002 attribute, K0004 date/time,
// K0014 part ident; "/0" = for all characteristics; the value lines of the DFX form with 0x0F between a
// value's fields and 0x14 between characteristics), not from Metrofit's writer; the expected values are
// read off the texts by hand. The writer is checked separately: its output must read back unchanged.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/dfq.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string crlf(const std::string& lf) {
  std::string out;
  for (char c : lf) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// One part, three characteristics, K-field values; /0 fields before and after the fields they
// complete; a decimal comma inside a text; a removed value (attribute 255); K0014/K0004 for all.
const std::string kFields = crlf(
    "K0100 3\n"
    "K1001/1 4711-A\n"
    "K1002/1 Welle, geschliffen\n"
    "K2142/0 mm\n"
    "K2001/1 1\n"
    "K2002/1 Durchmesser 12,5\n"
    "K2101/1 12.5\n"
    "K2110/1 12.48\n"
    "K2111/1 12.52\n"
    "K2001/2 2\n"
    "K2002/2 L\xC3\xA4nge\n"
    "K2101/2 40\n"
    "K2110/2 39.9\n"
    "K2111/2 40.1\n"
    "K2022/2 2\n"
    "K2001/3 3.1\n"
    "K2002/3 Rundheit\n"
    "K2111/3 0.01\n"
    "K2022/0 3\n"
    "K0001/1 12.501\n"
    "K0002/1 0\n"
    "K0004/1 14.03.2024/08:15:30\n"
    "K0001/2 40.02\n"
    "K0001/3 0.004\n"
    "K0014/0 SN-1\n"
    "K0001/1 12.497\n"
    "K0001/2 40.01\n"
    "K0002/2 255\n"
    "K0001/3 0.006\n"
    "K0004/0 14.03.2024/08:20:00\n");

TEST(DfqRead, FieldsWithAllFieldsAndAttributes) {
  const DfqFile f = dfqFromText(kFields, "w.dfq");
  EXPECT_FALSE(f.eightBit);
  ASSERT_EQ(f.parts.size(), 1u);
  EXPECT_EQ(f.parts[0].number, "4711-A");
  EXPECT_EQ(f.parts[0].description, "Welle, geschliffen");
  ASSERT_EQ(f.characteristics.size(), 3u);
  const auto& d = f.characteristics[0];
  EXPECT_EQ(d.number, "1");
  EXPECT_EQ(d.description, "Durchmesser 12,5");  // a text: the comma stays
  EXPECT_EQ(*d.nominal, 12.5);
  EXPECT_EQ(*d.lowerLimit, 12.48);
  EXPECT_EQ(*d.upperLimit, 12.52);
  EXPECT_EQ(d.unit, "mm");    // K2142/0 before the characteristic's own fields
  EXPECT_EQ(*d.decimals, 3);  // K2022/0 after them
  EXPECT_EQ(f.characteristics[1].description, "L\xC3\xA4nge");
  EXPECT_EQ(*f.characteristics[1].decimals, 2);  // its own K2022 wins over K2022/0
  EXPECT_EQ(f.characteristics[1].unit, "mm");
  EXPECT_EQ(f.characteristics[2].number, "3.1");  // a number as written, a text
  EXPECT_FALSE(f.characteristics[2].nominal.has_value());
  EXPECT_FALSE(f.characteristics[2].lowerLimit.has_value());
  EXPECT_EQ(*f.characteristics[2].upperLimit, 0.01);
  ASSERT_EQ(f.measuredParts(), 2u);
  for (const auto& c : f.characteristics) ASSERT_EQ(c.values.size(), 2u);
  EXPECT_EQ(*d.values[0].value, 12.501);
  EXPECT_EQ(*d.values[1].value, 12.497);
  EXPECT_EQ(d.values[0].time, "14.03.2024/08:15:30");
  // K0014/0 names the part of the first value set, K0004/0 dates the second one, every characteristic.
  for (const auto& c : f.characteristics) {
    EXPECT_EQ(c.values[0].partId, "SN-1");
    EXPECT_EQ(c.values[1].partId, "");
    EXPECT_EQ(c.values[1].time, "14.03.2024/08:20:00");
  }
  // The removed value: read, attribute 255, not valid.
  EXPECT_EQ(*f.characteristics[1].values[1].value, 40.01);
  EXPECT_EQ(f.characteristics[1].values[1].attribute, 255);
  EXPECT_FALSE(f.characteristics[1].values[1].valid());
  EXPECT_TRUE(f.characteristics[1].values[0].valid());
  EXPECT_EQ(*f.characteristics[2].values[1].value, 0.006);
  EXPECT_EQ(f.characteristics[0].values[1].line, 26);
}

// The same kind of file in the DFX value-line form, 8-bit (Windows-1252: ä = E4, Ø = D8), two parts
// (part 2's fields after part 1's characteristics), 0x0F between a value's fields and 0x14 between
// characteristics, an empty value (not measured) and a removed one, numbers repeated across the parts.
std::string valueLineFile(const std::string& field, const std::string& next) {
  return crlf(
             "K0100 4\n"
             "K1001/1 P-100\n"
             "K1002/1 Geh\xE4use\n"
             "K2001/1 10\n"
             "K2002/1 Bohrung \xD8 8,5\n"
             "K2101/1 8.5\n"
             "K2110/1 8.49\n"
             "K2111/1 8.51\n"
             "K2001/2 11\n"
             "K2002/2 Tiefe\n"
             "K2101/2 12\n"
             "K1001/2 P-200\n"
             "K1002/2 Deckel\n"
             "K2001/3 10\n"
             "K2002/3 Bohrung \xD8 6\n"
             "K2101/3 6\n"
             "K2001/4 12\n"
             "K2002/4 Ebenheit\n"
             "K2111/4 0.02\n") +
         "8.502" + field + "0" + field + "14.03.2024/08:15:30" + next + "12.01" + field + "0" + next +
         "6.001" + field + "0" + next + "0.011" + field + "0\r\n" +                                  //
         "8.498" + field + "0" + field + "14.03.2024/08:17:02" + field + "0" + field + "7" + next +  //
         field + next + "6.003" + field + "255" + next + "0.013\r\n" + "K0014/0 SN-2\r\n";
}

void expectValueLineFile(const DfqFile& f) {
  ASSERT_EQ(f.parts.size(), 2u);
  EXPECT_EQ(f.parts[0].number, "P-100");
  EXPECT_EQ(f.parts[0].description, "Geh\xC3\xA4use");  // UTF-8 now
  EXPECT_EQ(f.parts[1].number, "P-200");
  ASSERT_EQ(f.characteristics.size(), 4u);
  EXPECT_EQ(f.characteristics[0].description, "Bohrung \xC3\x98 8,5");
  EXPECT_EQ(f.characteristics[0].part, 1);
  EXPECT_EQ(f.characteristics[1].part, 1);
  EXPECT_EQ(f.characteristics[2].part, 2);
  EXPECT_EQ(f.characteristics[3].part, 2);
  const auto& c = f.characteristics;
  EXPECT_EQ(*c[0].values[0].value, 8.502);
  EXPECT_EQ(*c[0].values[1].value, 8.498);
  EXPECT_EQ(c[0].values[0].time, "14.03.2024/08:15:30");
  EXPECT_EQ(c[0].values[1].time, "14.03.2024/08:17:02");
  EXPECT_EQ(*c[1].values[0].value, 12.01);
  EXPECT_FALSE(c[1].values[1].value.has_value());  // empty: not measured
  EXPECT_FALSE(c[1].values[1].valid());
  EXPECT_EQ(*c[2].values[0].value, 6.001);  // blanks around the value
  EXPECT_EQ(*c[2].values[1].value, 6.003);
  EXPECT_EQ(c[2].values[1].attribute, 255);
  EXPECT_FALSE(c[2].values[1].valid());
  EXPECT_EQ(*c[3].values[1].value, 0.013);  // no attribute field: valid
  EXPECT_TRUE(c[3].values[1].valid());
  for (const auto& ch : c) EXPECT_EQ(ch.values[1].partId, "SN-2");  // a K field after a value line
  EXPECT_EQ(c[3].values[1].line, 21);
}

TEST(DfqRead, ValueLinesEightBitSeveralParts) {
  const DfqFile f = dfqFromText(valueLineFile("\x0F", "\x14"), "p.dfq");
  EXPECT_TRUE(f.eightBit);
  expectValueLineFile(f);
}

TEST(DfqRead, ValueLinesUtf8WithTheSeparatorGlyphs) {
  // A converter wrote the file as UTF-8 with the glyphs U+00A4 and U+00B6 for 0x0F and 0x14; the
  // texts are UTF-8 then too.
  std::string text = valueLineFile("\xC2\xA4", "\xC2\xB6");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"Geh\xE4use", "Geh\xC3\xA4use"},
                                 {"\xD8 8,5", "\xC3\x98 8,5"},
                                 {"\xD8 6", "\xC3\x98 6"}}) {
    text.replace(text.find(from), from.size(), to);
  }
  const DfqFile f = dfqFromText("\xEF\xBB\xBF" + text, "u.dfq");
  EXPECT_FALSE(f.eightBit);
  expectValueLineFile(f);
}

TEST(DfqRead, WriterOutputReadsBackIdentically) {
  DfqPart part;
  part.number = "W-17";
  part.description = "Flansch, Seite A";
  DfqCharacteristic a;
  a.number = "D1";
  a.description = "Durchmesser 12,5";
  a.nominal = 12.5;
  a.lowerLimit = 12.48;
  a.upperLimit = 12.52;
  a.unit = "mm";
  a.values = {12.500999999999999, 12.497, 0.1 + 0.2, -1e-7, 12.5};
  a.times = {"01.02.2024/07:00:00", "01.02.2024/07:05:00", "01.02.2024/07:10:00", "01.02.2024/07:15:00",
             "01.02.2024/07:20:00"};
  DfqCharacteristic b;
  b.number = "7";
  b.description = "Ebenheit";
  b.upperLimit = 0.02;
  b.values = {0.011, 0.0125};  // fewer values: left out of the later value sets
  part.characteristics = {a, b};
  const std::string text = writeDfq(part);
  const DfqFile f = dfqFromText(text, "rt.dfq");
  const std::vector<DfqPart> back = dfqParts(f);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(back[0] == part);
  EXPECT_EQ(back[0].characteristics[0].values, a.values);  // bit for bit
  EXPECT_EQ(back[0].characteristics[1].times.size(), 0u);
  EXPECT_EQ(writeDfq(back[0]), text);
}

TEST(DfqRead, DateTimesAsMinutes) {
  // 2024 is a leap year: 29 February to 1 March is one day; 1970-01-02 00:00 is 1440 minutes.
  EXPECT_EQ(*qdasMinutes("01.03.2024/08:15:30") - *qdasMinutes("29.02.2024/08:15:30"), 1440.0);
  EXPECT_EQ(*qdasMinutes("02.01.1970/00:00:00"), 1440.0);
  EXPECT_EQ(*qdasMinutes("14.03.2024 08:21") - *qdasMinutes("14.03.2024/08:15:30"), 5.5);  // Calypso _hdr
  EXPECT_FALSE(qdasMinutes("2024-03-14T08:21:00").has_value());
  EXPECT_FALSE(qdasMinutes("14.13.2024/08:21:00").has_value());
  EXPECT_FALSE(qdasMinutes("").has_value());
}

TEST(DfqRead, DecimalCommaOnlyInNumbers) {
  const DfqFile f = dfqFromText("K0100 1\nK2001 A\nK2002 Ma\xC3\x9F 3,5\nK2101 3,5\nK0001 3,512\n", "c.dfq");
  EXPECT_EQ(*f.characteristics[0].nominal, 3.5);
  EXPECT_EQ(*f.characteristics[0].values[0].value, 3.512);
  EXPECT_EQ(f.characteristics[0].description, "Ma\xC3\x9F 3,5");
  // No index: index 1.
  EXPECT_EQ(f.characteristics[0].number, "A");
}

std::string errorOf(const std::string& text) {
  try {
    (void)dfqFromText(text, "bad.dfq");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DfqRead, ErrorsNameFileLineAndField) {
  EXPECT_EQ(errorOf("K0100 2\nK2001/3 x\n"),
            "bad.dfq:2: field 'K2001/3': characteristic 3 beyond K0100 = 2 (the number of characteristics in "
            "the file)");
  EXPECT_NE(errorOf("K0100 1\nK0001/1 12.5x\n").find("bad.dfq:2: field 'K0001/1': '12.5x' is not a number"),
            std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0001/1 nan\n").find("bad.dfq:2"), std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0001/1 1,2,5\n").find("is not a number"), std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK2101/1 1.5.2\n").find("bad.dfq:2: field 'K2101/1'"), std::string::npos);
  EXPECT_NE(errorOf("K0100 2\n1\x0F"
                    "0\x14"
                    "2\x14"
                    "3\n")
                .find("bad.dfq:2: the value line has 3"),
            std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK2110/1 2\nK2111/1 1\n").find("bad.dfq:2: field 'K2110/1': lower limit 2"),
            std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0002/1 0\n").find("bad.dfq:2: field 'K0002/1'"), std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0001/1 1\nK0002/1 x\n").find("bad.dfq:3: field 'K0002/1'"), std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0001/0 1\n").find("field 'K0001/0'"), std::string::npos);
  EXPECT_NE(errorOf("hello\nK0100 1\n").find("bad.dfq:1: does not start with a K field"), std::string::npos);
  EXPECT_NE(errorOf("K0100 1\nK0001/ 1\n").find("bad.dfq:2"), std::string::npos);
  EXPECT_NE(errorOf(std::string("K0100 1\n\0\0", 11)).find("binary"), std::string::npos);
  EXPECT_NE(errorOf("K1001 x\n").find("no characteristic"), std::string::npos);
  EXPECT_FALSE(looksLikeDfq("part,value\n1,2\n"));
  EXPECT_TRUE(looksLikeDfq("\xEF\xBB\xBF\r\nK0100 1\r\n"));
}

TEST(DfqRead, CharacteristicChoice) {
  const DfqFile f = dfqFromText(valueLineFile("\x0F", "\x14"), "p.dfq");
  std::vector<std::pair<std::string, std::string>> list;
  for (const auto& c : f.characteristics) list.emplace_back(c.number, c.description);
  EXPECT_EQ(chooseCharacteristic(list, "11", "p.dfq"), 1u);
  EXPECT_EQ(chooseCharacteristic(list, "Ebenheit", "p.dfq"), 3u);
  EXPECT_EQ(chooseCharacteristic(list, " tiefe ", "p.dfq"), 1u);  // case and blanks ignored for names
  EXPECT_EQ(chooseCharacteristic(list, "Bohrung \xC3\x98 6", "p.dfq"), 2u);
  const auto error = [&](const std::string& choice) {
    try {
      (void)chooseCharacteristic(list, choice, "p.dfq");
    } catch (const ValidationError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  // "10" is the number of a characteristic of each part.
  EXPECT_EQ(error("10"),
            "p.dfq: field '--characteristic': '10' is ambiguous: it names 2 characteristics: '10' "
            "(Bohrung \xC3\x98 8,5), '10' (Bohrung \xC3\x98 6); choose one by its description");
  EXPECT_NE(error("99").find("no characteristic '99'"), std::string::npos);
  EXPECT_NE(error("99").find("'12' (Ebenheit)"), std::string::npos);
  EXPECT_NE(error("").find("is required: the file has 4 characteristics"), std::string::npos);
}

TEST(DfqRead, AsACmmReport) {
  const std::string text = valueLineFile("\x0F", "\x14");
  ASSERT_EQ(detectCmmTextReport(text), CmmReportFormat::Dfq);
  const CmmTextReport r = cmmTextReportFromText(text, "p.dfq");
  // Part P-100: two value sets; part P-200: two value sets.
  ASSERT_EQ(r.runs.size(), 4u);
  EXPECT_EQ(r.runs[0].routine, "P-100");
  EXPECT_EQ(r.runs[2].routine, "P-200");
  EXPECT_EQ(r.runs[1].serial, "SN-2");
  ASSERT_EQ(r.runs[0].features.size(), 2u);
  ASSERT_EQ(r.runs[1].features.size(), 1u);  // characteristic 11 not measured
  ASSERT_EQ(r.runs[3].features.size(), 1u);  // characteristic 10 of P-200 removed (attribute 255)
  const CmmFeature& bore = r.runs[0].features[0];
  EXPECT_EQ(bore.featureName, "10");
  EXPECT_EQ(bore.label, "Bohrung \xC3\x98 8,5");
  ASSERT_EQ(bore.values.size(), 1u);
  EXPECT_EQ(*bore.values[0].nominal, 8.5);
  EXPECT_TRUE(test::near(*bore.values[0].lower, -0.01, 1e-12));
  EXPECT_TRUE(test::near(*bore.values[0].upper, 0.01, 1e-12));
  EXPECT_EQ(bore.values[0].actual, 8.502);
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

// A short stand-in for the fuzz targets (fuzz/fuzz_dfq.cpp, fuzz/fuzz_calypso.cpp; built only with
// -DMETROFIT_FUZZ=ON): seeded byte mutations of good files give a value or a typed input error, nothing
// else (no other exception, no crash).
TEST(DfqRead, MutatedFilesGiveValuesOrInputErrors) {
  const std::string seeds[] = {valueLineFile("\x0F", "\x14"), kFields};
  std::uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  const char bytes[] = {'\x0F', '\x14', '/',  ' ',    'K',    '0', '9', ',',
                        '.',    '\n',   '\r', '\xC2', '\xB6', '-', 'e'};
  int errors = 0;
  for (int round = 0; round < 4000; ++round) {
    std::string text = seeds[round % 2];
    for (int k = 0, n = 1 + static_cast<int>(next() % 4); k < n; ++k) {
      const std::size_t at = next() % text.size();
      switch (next() % 3) {
        case 0:
          text[at] = bytes[next() % sizeof bytes];
          break;
        case 1:
          text.erase(at, 1 + next() % 8);
          break;
        default:
          text.insert(at, 1, bytes[next() % sizeof bytes]);
          break;
      }
      if (text.empty()) text = "K";
    }
    try {
      const DfqFile f = dfqFromText(text, "m.dfq");
      (void)cmmReportFeatureTable(dfqCmmReport(f));
      (void)dfqParts(f);
    } catch (const InputError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 100);
}

}  // namespace
}  // namespace metrofit
