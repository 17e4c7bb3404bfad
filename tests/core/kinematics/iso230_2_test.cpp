// ISO 230-2:2014 positioning evaluation (core/kinematics/iso230_2.h) against values worked out by hand
// from the standard's definitions on a constructed test, and against the same definitions written
// again here (independently of the core) on the real ESS axis test
// (../shared/data/real/axis-positioning-ess, read here by a parser of its own; no licence: read in
// place, never copied). Also the readers' errors and the compensation tables, locale-proof.
#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/kinematics/iso230_2.h"
#include "testsupport.h"

namespace metrofit {
namespace {

// Three targets, three cycles: the approaches are mean + {-d, 0, +d}, so x̄ = mean and s = d exactly.
struct Known {
  double target, upMean, upD, downMean, downD;
};
const Known kKnown[] = {{0.0, 0.010, 0.001, 0.004, 0.002},
                        {100.0, 0.020, 0.002, 0.008, 0.001},
                        {200.0, -0.005, 0.001, -0.011, 0.003}};

std::string knownCsv(bool measured) {
  std::string csv =
      std::string("target_mm,direction,cycle,") + (measured ? "measured_mm" : "deviation_mm") + "\n";
  for (int c = 1; c <= 3; ++c) {
    for (const Known& k : kKnown) {
      const double off = (c - 2);
      for (const bool up : {true, false}) {
        const double dev = up ? k.upMean + off * k.upD : k.downMean + off * k.downD;
        csv += CsvWriter::formatNumber(k.target) + "," + (up ? "+" : "-") + "," + std::to_string(c) + "," +
               CsvWriter::formatNumber(measured ? k.target + dev : dev) + "\n";
      }
    }
  }
  return csv;
}

PositioningResult evaluateText(const std::string& text, const std::string& name = "t.csv") {
  if (isKeyValuePositioningTest(text)) return evaluateIso230_2(positioningTestFromKeyValue(text, name));
  return evaluateIso230_2(positioningTestFromCsv(parseCsv(text, name)));
}

TEST(Iso230_2, KnownValuesWorkedOutByHand) {
  for (const bool measured : {false, true}) {
    const PositioningResult r = evaluateText(knownCsv(measured));
    const double tol = measured ? 1e-12 : 1e-15;
    ASSERT_EQ(r.targets.size(), 3u);
    EXPECT_NEAR(r.targets[1].meanUpMm, 0.020, tol);
    EXPECT_NEAR(r.targets[1].sUpMm, 0.002, tol);
    EXPECT_NEAR(r.targets[2].sDownMm, 0.003, tol);
    // Bi = 0.006, 0.012, 0.006
    EXPECT_NEAR(r.B, 0.012, tol);
    EXPECT_NEAR(r.Bmean, 0.008, tol);
    // Ri↑ = 0.004, 0.008, 0.004; Ri↓ = 0.008, 0.004, 0.012; Ri = 0.012, 0.018, 0.014
    EXPECT_NEAR(r.Rup, 0.008, tol);
    EXPECT_NEAR(r.Rdown, 0.012, tol);
    EXPECT_NEAR(r.R, 0.018, tol);
    // E↑ = 0.020 - (-0.005), E↓ = 0.008 - (-0.011), E = 0.020 - (-0.011)
    EXPECT_NEAR(r.Eup, 0.025, tol);
    EXPECT_NEAR(r.Edown, 0.019, tol);
    EXPECT_NEAR(r.E, 0.031, tol);
    // x̄i = 0.007, 0.014, -0.008
    EXPECT_NEAR(r.M, 0.022, tol);
    // A↑ = 0.024 - (-0.007), A↓ = 0.010 - (-0.017), A = 0.024 - (-0.017)
    EXPECT_NEAR(r.Aup, 0.031, tol);
    EXPECT_NEAR(r.Adown, 0.027, tol);
    EXPECT_NEAR(r.A, 0.041, tol);
  }
}

TEST(Iso230_2, JsonHasTheContractKeys) {
  const nlohmann::json j = iso230_2ToJson(evaluateText(knownCsv(false)));
  for (const char* k : {"B_mm", "B_mean_mm", "E_up_mm", "E_down_mm", "E_mm", "M_mm", "R_up_mm", "R_down_mm",
                        "R_mm", "A_up_mm", "A_down_mm", "A_mm", "targets"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j.size(), 13u);
  ASSERT_EQ(j["targets"].size(), 3u);
  for (const char* k : {"target_mm", "x_up_mm", "x_down_mm", "s_up_mm", "s_down_mm", "B_mm"})
    EXPECT_TRUE(j["targets"][0].contains(k)) << k;
  EXPECT_EQ(j["targets"][0].size(), 6u);
  EXPECT_NEAR(j["targets"][1]["B_mm"].get<double>(), 0.012, 1e-15);
}

// ---- the real ESS test, evaluated by a second implementation written here ----
struct Raw {
  std::map<int, double> target;
  std::map<std::pair<int, int>, double> fwd, bwd;
};

Raw readRaw(const std::string& path) {
  std::ifstream in(path);
  Raw raw;
  const std::regex tgt(R"(^TGT_DATA\[(\d+)\]=(\S+)\s*$)"),
      ref(R"(^REF_DATA_(FWD|BWD)\[(\d+),(\d+)\]=(\S+)\s*$)");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, tgt)) {
      raw.target[std::stoi(m[1])] = test::cnumber(m[2]);
    } else if (std::regex_match(line, m, ref)) {
      (m[1] == "FWD" ? raw.fwd : raw.bwd)[{std::stoi(m[2]), std::stoi(m[3])}] = test::cnumber(m[4]);
    }
  }
  return raw;
}

TEST(Iso230_2, RealEssAxisAgainstTheStandardWrittenAgain) {
  const auto path = test::realData("axis-positioning-ess/example_data_ISO230_2.dat");
  METROFIT_REQUIRE_PATH(path);
  const Raw raw = readRaw(path.string());
  ASSERT_EQ(raw.target.size(), 5u);
  ASSERT_EQ(raw.fwd.size(), 25u);
  ASSERT_EQ(raw.bwd.size(), 25u);
  struct T {
    double up, down, su, sd;
  };
  std::vector<T> t;
  for (const auto& [i, p] : raw.target) {
    std::vector<double> u, d;
    for (int j = 1; j <= 5; ++j) {
      u.push_back(raw.fwd.at({i, j}) - p);
      d.push_back(raw.bwd.at({i, j}) - p);
    }
    auto mean = [](const std::vector<double>& v) {
      double s = 0;
      for (double x : v) s += x;
      return s / v.size();
    };
    auto sdev = [&](const std::vector<double>& v) {
      const double mu = mean(v);
      double s = 0;
      for (double x : v) s += (x - mu) * (x - mu);
      return std::sqrt(s / (v.size() - 1));
    };
    t.push_back({mean(u), mean(d), sdev(u), sdev(d)});
  }
  double B = 0, Bsum = 0, Rup = 0, Rdown = 0, R = 0;
  std::vector<double> ups, downs, both, means, hiUp, loUp, hiDown, loDown;
  for (const T& x : t) {
    const double b = x.up - x.down;
    B = std::max(B, std::abs(b));
    Bsum += b;
    Rup = std::max(Rup, 4 * x.su);
    Rdown = std::max(Rdown, 4 * x.sd);
    R = std::max({R, 2 * x.su + 2 * x.sd + std::abs(b), 4 * x.su, 4 * x.sd});
    ups.push_back(x.up);
    downs.push_back(x.down);
    both.push_back(x.up);
    both.push_back(x.down);
    means.push_back((x.up + x.down) / 2);
    hiUp.push_back(x.up + 2 * x.su);
    loUp.push_back(x.up - 2 * x.su);
    hiDown.push_back(x.down + 2 * x.sd);
    loDown.push_back(x.down - 2 * x.sd);
  }
  auto range = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  auto mx = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  auto mn = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };

  const PositioningResult r = evaluateIso230_2(readPositioningTest(path.string()));
  ASSERT_EQ(r.targets.size(), 5u);
  const double tol = 1e-12;
  EXPECT_NEAR(r.B, B, tol);
  EXPECT_NEAR(r.Bmean, Bsum / 5, tol);
  EXPECT_NEAR(r.Rup, Rup, tol);
  EXPECT_NEAR(r.Rdown, Rdown, tol);
  EXPECT_NEAR(r.R, R, tol);
  EXPECT_NEAR(r.Eup, range(ups), tol);
  EXPECT_NEAR(r.Edown, range(downs), tol);
  EXPECT_NEAR(r.E, range(both), tol);
  EXPECT_NEAR(r.M, range(means), tol);
  EXPECT_NEAR(r.Aup, mx(hiUp) - mn(loUp), tol);
  EXPECT_NEAR(r.Adown, mx(hiDown) - mn(loDown), tol);
  EXPECT_NEAR(r.A, std::max(mx(hiUp), mx(hiDown)) - std::min(mn(loUp), mn(loDown)), tol);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(r.targets[i].meanUpMm, t[i].up, tol);
    EXPECT_NEAR(r.targets[i].sDownMm, t[i].sd, tol);
  }
  // A real axis: accuracy of some micrometres, above the repeatability's share.
  EXPECT_GT(r.A, 0.001);
  EXPECT_LT(r.A, 0.05);
  EXPECT_GE(r.A, r.E);
}

// ---- bad input: one error naming the file, the line and the field ----
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Iso230_2, BadCsvIsNamedByFileLineAndField) {
  const std::string head = "target_mm,direction,cycle,deviation_mm\n";
  EXPECT_EQ(errorOf([&] { evaluateText(head + "0,+,1,0.001\n0,up,2,0.002\n"); }),
            "t.csv:3:2: field 'direction': 'up' is not a direction (+ or -)");
  EXPECT_NE(
      errorOf([&] { evaluateText(head + "0,+,1,0.001\n0,+,x,0.002\n"); }).find("t.csv:3:3: field 'cycle'"),
      std::string::npos);
  EXPECT_NE(errorOf([&] {
              evaluateText(head + "0,+,1,0.001\n0,+,1,0.002\n");
            }).find("given twice (first on line 2)"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { evaluateText(head + "0,+,1,0.001\n0,+,2,abc\n"); }).find("t.csv:3:4"),
            std::string::npos);
  const std::string one = errorOf([&] { evaluateText(head + "0,+,1,0.001\n0,+,2,0.002\n0,-,1,0.001\n"); });
  EXPECT_NE(one.find("t.csv:2: field 'direction': target 0 mm has 1 approach in the negative (-) direction"),
            std::string::npos)
      << one;
  EXPECT_NE(errorOf([&] { evaluateText("target_mm,direction,cycle\n0,+,1\n"); }).find("deviation_mm"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              evaluateText("target_mm,direction,cycle,deviation_mm,measured_mm\n0,+,1,0,0\n");
            }).find("not both"),
            std::string::npos);
}

TEST(Iso230_2, BadKeyValueIsNamedByFileLineAndKey) {
  const std::string ok =
      "UNIT=mm\nCYCLES=2\nPOSITIONS=1\nTGT_DATA[1]=10\nREF_DATA_FWD[1,1]=10.001\n"
      "REF_DATA_FWD[1,2]=10.002\nREF_DATA_BWD[1,1]=9.999\nREF_DATA_BWD[1,2]=10.000\n";
  const PositioningResult r = evaluateText(ok, "k.dat");
  EXPECT_NEAR(r.targets[0].meanUpMm, 0.0015, 1e-12);
  EXPECT_NEAR(r.targets[0].reversalMm, 0.002, 1e-12);
  EXPECT_EQ(errorOf([&] { evaluateText("UNIT=mm\nTGT_DATA[1]=1O\n", "k.dat"); }),
            "k.dat:2: field 'TGT_DATA[1]': '1O' is not a number");
  EXPECT_EQ(errorOf([&] { evaluateText("UNIT=inch\n", "k.dat"); }),
            "k.dat:1: field 'UNIT': unit 'inch' is not mm or um");
  EXPECT_NE(errorOf([&] {
              evaluateText(ok + "REF_DATA_BWD[1]=3\n", "k.dat");
            }).find("k.dat:9: field 'REF_DATA_BWD[1]'"),
            std::string::npos);
  std::string missing = ok;
  missing.erase(missing.find("REF_DATA_BWD[1,2]"));
  EXPECT_NE(errorOf([&] { evaluateText(missing, "k.dat"); }).find("field 'REF_DATA_BWD[1,2]': missing"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { evaluateText(ok + "garbage line\n", "k.dat"); }).find("k.dat:9:"),
            std::string::npos);
}

// ---- compensation tables ----
TEST(Iso230_2, CompensationIsMinusTheMeanBidirectionalDeviation) {
  const PositioningResult r = evaluateText(knownCsv(false));
  const std::vector<double> c = compensationMm(r);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0], -0.007, 1e-15);
  EXPECT_NEAR(c[1], -0.014, 1e-15);
  EXPECT_NEAR(c[2], 0.008, 1e-15);
  EXPECT_EQ(pitchCompensationTable(r, PitchTableFormat::Csv),
            "target_mm,compensation_mm\n0,-0.007000\n100,-0.014000\n200,0.008000\n");
  const std::string siemens = pitchCompensationTable(r, PitchTableFormat::Siemens);
  EXPECT_NE(siemens.find("%_N_AX_EEC_INI\n"), std::string::npos);
  EXPECT_NE(siemens.find("$AA_ENC_COMP[0,0,X1]=-0.007000\n$AA_ENC_COMP[0,1,X1]=-0.014000\n"
                         "$AA_ENC_COMP[0,2,X1]=0.008000\n$AA_ENC_COMP_STEP[0,X1]=100.000000\n"
                         "$AA_ENC_COMP_MIN[0,X1]=0.000000\n$AA_ENC_COMP_MAX[0,X1]=200.000000\n"
                         "$AA_ENC_COMP_IS_MODULO[0,X1]=0\nM17\n"),
            std::string::npos)
      << siemens;
  // Fanuc: increments in 1 um detection units, referred to the first target: 0, -7, +22.
  PitchTableOptions z;
  z.axis = 'Z';
  EXPECT_EQ(
      pitchCompensationTable(r, PitchTableFormat::Fanuc, z),
      "%\nN3620A3P1\nN3621A3P1\nN3622A3P3\nN3623A3P1\nN3624A3P100000\nN10001P0\nN10002P-7\nN10003P22\n%\n");
  const std::string heid = pitchCompensationTable(r, PitchTableFormat::Heidenhain);
  EXPECT_EQ(heid.substr(0, heid.find('\n')), "BEGIN X.COM MM");
  EXPECT_NE(heid.find("\n2      +200.0000      +0.00800"), std::string::npos) << heid;
  EXPECT_EQ(heid.substr(heid.size() - 6), "[END]\n");
}

TEST(Iso230_2, UnequalTargetsAreInterpolatedOntoAnEquidistantGrid) {
  const std::string head = "target_mm,direction,cycle,deviation_mm\n";
  std::string csv = head;
  for (const auto& [t, d] : std::vector<std::pair<double, double>>{{0, 0.0}, {10, 0.010}, {40, 0.040}})
    for (int c = 1; c <= 2; ++c)
      for (const char* s : {"+", "-"})
        csv += CsvWriter::formatNumber(t) + "," + s + "," + std::to_string(c) + "," +
               CsvWriter::formatNumber(d) + "\n";
  const std::string s = pitchCompensationTable(evaluateText(csv), PitchTableFormat::Siemens);
  EXPECT_NE(s.find("$AA_ENC_COMP[0,1,X1]=-0.020000\n"), std::string::npos) << s;  // at 20 mm
  EXPECT_NE(s.find("$AA_ENC_COMP_STEP[0,X1]=20.000000\n"), std::string::npos);
}

TEST(Iso230_2, TablesAreByteIdenticalUnderEveryLocale) {
  const PositioningResult r = evaluateText(knownCsv(false));
  std::vector<std::string> first;
  for (const char* loc : {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"}) {
    if (!std::setlocale(LC_ALL, loc)) {
      ADD_FAILURE() << "locale " << loc << " is not installed";
      continue;
    }
    std::vector<std::string> now;
    for (const auto f : {PitchTableFormat::Fanuc, PitchTableFormat::Siemens, PitchTableFormat::Heidenhain,
                         PitchTableFormat::Csv})
      now.push_back(pitchCompensationTable(r, f));
    // The locale's own decimal mark would be ',' here: the tables never show it.
    EXPECT_EQ(now[0].find(','), std::string::npos);
    EXPECT_EQ(now[2].find(','), std::string::npos);
    if (first.empty())
      first = now;
    else
      EXPECT_EQ(now, first) << loc;
  }
  std::setlocale(LC_ALL, "C");
}

}  // namespace
}  // namespace metrofit
