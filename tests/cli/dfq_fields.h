#pragma once
// Reads a Q-DAS DFQ file back by the AQDEF K-field rule (docs/file-formats.md#q-das-dfq-export;
// pypi.org/project/aqdefreader, pypi.org/project/qdas-parser), for the CLI and GUI tests of the DFQ
// exports: "Kxxxx[/i] value" per line, lines ending in CR LF.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "testsupport.h"

namespace metrofit::test {

/// Values K0001/i and times K0004/i collected per characteristic i, every other field keyed "Kxxxx/i".
struct DfqFields {
  std::map<std::string, std::string> fields;
  std::map<int, std::vector<double>> values;
  std::map<int, std::vector<std::string>> times;
};

inline DfqFields readDfq(const std::string& text) {
  DfqFields d;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    EXPECT_FALSE(line.empty());
    EXPECT_EQ(line.back(), '\r');  // CR LF
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    const auto slash = key.find('/');
    const int index = slash == std::string::npos ? 0 : std::stoi(key.substr(slash + 1));
    if (key.rfind("K0001/", 0) == 0) {
      d.values[index].push_back(cnumber(value));  // locale free (testsupport.h)
    } else if (key.rfind("K0004/", 0) == 0) {
      d.times[index].push_back(value);
    } else {
      d.fields[key] = value;
    }
  }
  return d;
}

}  // namespace metrofit::test
