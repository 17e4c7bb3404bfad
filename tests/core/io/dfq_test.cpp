// The Q-DAS DFQ writer (core/io/dfq.h) read back by a parser written here from the AQDEF K-field
// description, not from our writer: the field list of the Q-DAS ASCII transfer format as the open readers
// document it (pypi.org/project/aqdefreader: "parts (Teiletyp) and characteristics (Merkmale) ... measured
// values (Messwerte)"; pypi.org/project/qdas-parser: "Q-DAS ASCII Transfer Format (V12) ... K-Field
// metadata"), and a DFQ field table (K0001 values, K1002 part description, K2002/X characteristic name,
// K2101/X nominal, K2110/X / K2111/X lower / upper tolerance limit, K2142/X unit): one field per line, the
// key, "/" and the 1-based characteristic index, one space, the value; K0100 the number of characteristics;
// K0004 the date/time of a value as DD.MM.YYYY/HH:MM:SS.
#include <gtest/gtest.h>

#include <charconv>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/dfq.h"

namespace metrofit {
namespace {

struct ReadCharacteristic {
  std::map<std::string, std::string> fields;  // K2001, K2002, ... -> text
  std::vector<double> values;
  std::vector<std::string> times;
};

struct ReadDfq {
  int count = -1;  // K0100
  std::map<std::string, std::string> part;
  std::map<int, ReadCharacteristic> characteristics;
  bool crlf = true;
};

/// The number a field holds; a field that is not a whole number (or out of range) fails the test and
/// reads as NaN, so no comparison with it can pass.
double toDouble(const std::string& s) {
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  const bool whole = res.ec == std::errc() && res.ptr == s.data() + s.size() && !s.empty();
  EXPECT_TRUE(whole) << "'" << s << "' is not a number";
  return whole ? v : std::numeric_limits<double>::quiet_NaN();
}

ReadDfq parse(const std::string& text) {
  ReadDfq d;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
    } else {
      d.crlf = false;
    }
    if (line.empty()) continue;
    const std::size_t space = line.find(' ');
    EXPECT_NE(space, std::string::npos) << line;
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    EXPECT_EQ(key[0], 'K') << line;
    const std::size_t slash = key.find('/');
    const std::string field = key.substr(0, slash);
    const int index = slash == std::string::npos ? 0 : std::stoi(key.substr(slash + 1));
    if (field == "K0100") {
      d.count = std::stoi(value);
    } else if (field[1] == '1') {  // K1xxx: the part
      d.part[field] = value;
    } else if (field == "K0001") {
      d.characteristics[index].values.push_back(toDouble(value));
    } else if (field == "K0004") {
      d.characteristics[index].times.push_back(value);
    } else {
      d.characteristics[index].fields[field] = value;
    }
  }
  return d;
}

TEST(Dfq, ReadsBackCountsValuesLimitsAndUnits) {
  DfqPart part;
  part.number = "bores";
  part.description = "bore diameters\nline two";
  DfqCharacteristic d;
  d.number = "diameter_mm";
  d.description = "diameter";
  d.nominal = 20.0;
  d.lowerLimit = 19.95;
  d.upperLimit = 20.05;
  d.unit = "mm";
  d.values = {20.0031, 19.9987, 20.1, 0.1 + 0.2};
  d.times = {"03.05.2024/10:15:00", "03.05.2024/10:16:00", "03.05.2024/10:17:30", "04.05.2024/00:00:00"};
  DfqCharacteristic e;
  e.number = "flatness_um";
  e.description = "flatness";
  e.unit = "um";
  e.values = {3.5, -1e-7};
  part.characteristics = {d, e};
  const std::string text = writeDfq(part);
  const ReadDfq r = parse(text);
  EXPECT_TRUE(r.crlf);
  EXPECT_EQ(r.count, 2);
  EXPECT_EQ(r.part.at("K1001"), "bores");
  EXPECT_EQ(r.part.at("K1002"), "bore diameters line two");
  ASSERT_EQ(r.characteristics.size(), 2u);
  const ReadCharacteristic& c1 = r.characteristics.at(1);
  EXPECT_EQ(c1.fields.at("K2001"), "diameter_mm");
  EXPECT_EQ(c1.fields.at("K2002"), "diameter");
  EXPECT_EQ(toDouble(c1.fields.at("K2101")), 20.0);
  EXPECT_EQ(toDouble(c1.fields.at("K2110")), 19.95);
  EXPECT_EQ(toDouble(c1.fields.at("K2111")), 20.05);
  EXPECT_EQ(c1.fields.at("K2142"), "mm");
  EXPECT_EQ(c1.values, d.values);  // shortest round trip: the same doubles
  EXPECT_EQ(c1.times, d.times);
  const ReadCharacteristic& c2 = r.characteristics.at(2);
  EXPECT_EQ(c2.fields.at("K2142"), "um");
  EXPECT_EQ(c2.fields.count("K2101"), 0u);  // no nominal, no limits: left out
  EXPECT_EQ(c2.fields.count("K2110"), 0u);
  EXPECT_EQ(c2.values, e.values);
  EXPECT_TRUE(c2.times.empty());
  // The values of part 1 of both characteristics come before part 2's.
  EXPECT_LT(text.find("K0001/2 3.5"), text.find("K0001/1 19.9987"));
  EXPECT_EQ(text.rfind("K0100 2\r\n", 0), 0u);
}

TEST(Dfq, RefusesWhatAnSpcPackageCouldNotRead) {
  DfqPart part;
  EXPECT_THROW((void)writeDfq(part), ValidationError);
  DfqCharacteristic c;
  c.number = "x";
  part.characteristics = {c};
  EXPECT_THROW((void)writeDfq(part), ValidationError);  // no values
  part.characteristics[0].values = {1.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW((void)writeDfq(part), ValidationError);
  part.characteristics[0].values = {1.0, 2.0};
  part.characteristics[0].lowerLimit = 3.0;
  part.characteristics[0].upperLimit = 2.0;
  EXPECT_THROW((void)writeDfq(part), ValidationError);
  part.characteristics[0].upperLimit = 4.0;
  part.characteristics[0].times = {"01.01.2024/00:00:00"};
  try {
    (void)writeDfq(part);
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()), "field 'dfq': characteristic 1 (x): give one time per value or none");
  }
}

TEST(Dfq, DateTimesInTheQdasForm) {
  EXPECT_EQ(qdasDateTime("2024-05-03T10:15:07"), "03.05.2024/10:15:07");
  EXPECT_EQ(qdasDateTime("2024-12-31 23:59"), "31.12.2024/23:59:00");
  EXPECT_FALSE(qdasDateTime("2024-13-01T00:00"));
  EXPECT_FALSE(qdasDateTime("03.05.2024"));
  EXPECT_FALSE(qdasDateTime("2024-05-03T10:15:07Z"));
  EXPECT_FALSE(qdasDateTime(""));
}

}  // namespace
}  // namespace metrofit
