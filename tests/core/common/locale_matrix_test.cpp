// The locale matrix of the files core writes and reads (issue 27; core/common/numformat.h).
//
// A Qt program runs with the user's whole C locale (QApplication calls setlocale(LC_ALL, "") on Unix).
// Under de_DE.UTF-8 and pl_PL.UTF-8 printf's "%f" writes a decimal comma, so `G10 L2 P1 Z0,013` went to
// the control (notes/gui-run.md F1). Here every writer runs with the process locale set to C.UTF-8,
// de_DE.UTF-8 and pl_PL.UTF-8 in turn:
//  * the output is byte for byte the same under the three;
//  * it is read back by a reader written here from the control's or format's own syntax (FANUC G10 /
//    G68.2 address words, HEIDENHAIN table columns and PLANE SPATIAL, SINUMERIK frame assignments,
//    ISO 6983 G01 words, ISO 10303-21 CARTESIAN_POINT, AQDEF K-fields), not by the project's reader,
//    and gives the values that were written;
//  * the readers (Part 21, HEIDENHAIN tables, hole tables, CSV, projects) read the same values under
//    the three locales.
// The locales must exist (packaging/install-deps.sh generates them): a missing one fails the test by
// name rather than passing it in the C locale unnoticed.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdio>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/dfq.h"
#include "core/kinematics/export.h"
#include "core/kinematics/part21.h"
#include "core/machine/controller_frame.h"
#include "core/matching/hole_table.h"
#include "core/project/project.h"
#include "core/setup/export.h"
#include "core/setup/model.h"

namespace metrofit {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kLocales[] = {"C.UTF-8", "de_DE.UTF-8", "pl_PL.UTF-8"};

/// Runs `f` with the process locale set to `name` (all categories), then back to "C". Fails the test
/// when the locale is not installed.
template <class F>
auto underLocale(const char* name, F f) {
  if (std::setlocale(LC_ALL, name) == nullptr) {
    ADD_FAILURE() << "locale " << name
                  << " is not installed; packaging/install-deps.sh generates it (localedef -i "
                  << std::string(name).substr(0, 5) << " -f UTF-8 " << name << ")";
  }
  struct Restore {
    ~Restore() { std::setlocale(LC_ALL, "C"); }
  } restore;
  return f();
}

/// The output of `write` under each locale; expects them byte for byte equal and returns the first.
std::string sameUnderEveryLocale(const std::function<std::string()>& write, const std::string& what) {
  std::vector<std::string> out;
  for (const char* l : kLocales) out.push_back(underLocale(l, write));
  for (std::size_t i = 1; i < out.size(); ++i)
    EXPECT_EQ(out[i], out[0]) << what << ": the file under " << kLocales[i] << " differs from "
                              << kLocales[0];
  return out[0];
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

/// A number as the controls' manuals write it: optional sign, digits, '.', digits (no comma, no
/// exponent). Read with a parser of our own (digits and powers of ten), not strtod.
const std::string kNum = "([+-]?[0-9]+\\.[0-9]+)";
double manualNumber(const std::string& s) {
  double sign = 1.0;
  std::size_t i = 0;
  if (s[i] == '+' || s[i] == '-') sign = s[i++] == '-' ? -1.0 : 1.0;
  double v = 0.0, scale = 0.0;
  for (; i < s.size(); ++i) {
    if (s[i] == '.') {
      scale = 1.0;
      continue;
    }
    v = v * 10.0 + (s[i] - '0');
    if (scale > 0.0) scale *= 10.0;
  }
  return sign * (scale > 0.0 ? v / scale : v);
}

/// No number with a decimal comma in an NC text: digits, ',', digits after an address letter, '=',
/// a sign or a blank ("Z0,013", "=+0,013", " 0,5"); SINUMERIK's indices "$TC_DP12[5,1]" are not numbers.
void expectNoDecimalComma(const std::string& text, const std::string& what) {
  EXPECT_FALSE(std::regex_search(text, std::regex("(^|[ A-Z=+-])[0-9]+,[0-9]"))) << what << ":\n" << text;
}

TEST(LocaleMatrix, TheLocalesAreInstalledAndChangePrintf) {
  // The matrix means something only when printf really writes a comma under de_DE / pl_PL.
  for (const char* l : {"de_DE.UTF-8", "pl_PL.UTF-8"}) {
    const std::string s = underLocale(l, [] {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3f", 0.013);  // NOLINT: the locale-dependent call under test
      return std::string(buf);
    });
    EXPECT_EQ(s, "0,013") << l;
  }
}

TEST(LocaleMatrix, NumformatIsTheCLocaleEverywhere) {
  for (const char* l : kLocales) {
    underLocale(l, [&] {
      EXPECT_EQ(num::fixed(0.013, 3), "0.013") << l;
      EXPECT_EQ(num::fixedSigned(0.013, 4), "+0.0130") << l;
      EXPECT_EQ(num::fixedSigned(-1.73, 4), "-1.7300") << l;
      EXPECT_EQ(num::general(1234567.0, 4), "1.235e+06") << l;
      EXPECT_EQ(num::general(0.05), "0.05") << l;
      EXPECT_EQ(num::shortest(0.1), "0.1") << l;
      EXPECT_EQ(num::toString(0.05), "0.050000") << l;
      EXPECT_EQ(cformat("X%+.3f Y%.1f N%d", 1.5, -2.25, 7), "X+1.500 Y-2.2 N7") << l;
      EXPECT_EQ(num::parseDouble("-0.25"), -0.25) << l;
      EXPECT_EQ(num::parseDouble("+1.5e-3"), 1.5e-3) << l;
      EXPECT_FALSE(num::parseDouble("0,25").has_value()) << l;
      EXPECT_FALSE(num::parseDouble(" 1").has_value()) << l;
      char* end = nullptr;
      const char* text = "85.125 rest";
      EXPECT_EQ(num::strtodC(text, &end), 85.125) << l;
      EXPECT_EQ(end, text + 6) << l;
      return 0;
    });
  }
}

// ---- setup corrections (FANUC G10, HEIDENHAIN, SINUMERIK, CSV) -------------------------------------

setup::Model exportModel() {
  nlohmann::json j{{"name", "Locale matrix"}, {"step_mm", 0.001}, {"bounds_mm", {-0.1, 0.1}}};
  j["setup"] = {
      {{"id", "W1"}, {"kind", "wks"}}, {{"id", "W7"}, {"kind", "wks"}}, {{"id", "T5"}, {"kind", "tool"}}};
  j["features"] = {{{"id", "F1"}}};
  j["dimensions"] = {{{"id", "D1"}, {"lower", -0.1}, {"upper", 0.1}}};
  j["arcs"] = nlohmann::json::array();
  for (const char* s : {"W1", "W7", "T5"}) j["arcs"].push_back({{"from", s}, {"to", "F1"}, {"weight", 1}});
  j["arcs"].push_back({{"from", "F1"}, {"to", "D1"}, {"weight", 1}});
  return setup::modelFromJson(j, "locale.json");
}
const std::vector<double> kCorrections{0.013, -0.021, 0.007};

TEST(LocaleMatrix, FanucG10) {
  const std::string nc = sameUnderEveryLocale(
      [] { return setup::exportCorrections(exportModel(), kCorrections, setup::ControllerFormat::Fanuc); },
      "fanuc");
  expectNoDecimalComma(nc, "fanuc");
  // FANUC: G10 L2 P<n> <axis><value> (work offset), G10 L20 P<n> (G54.1), G10 L11 P<tool> R<value>.
  std::vector<double> got;
  std::smatch m;
  for (const std::string& l : lines(nc)) {
    if (l.rfind("G10", 0) != 0) continue;
    ASSERT_TRUE(std::regex_search(l, m, std::regex("^G10 L(2|20|10|11) P([0-9]+) [XYZR]" + kNum + "( |$)")))
        << l;
    got.push_back(manualNumber(m[3]));
  }
  ASSERT_EQ(got.size(), kCorrections.size()) << nc;
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], kCorrections[i], 5e-4) << i;
}

TEST(LocaleMatrix, HeidenhainListingAndSiemensFrames) {
  const std::string h = sameUnderEveryLocale(
      [] {
        return setup::exportCorrections(exportModel(), kCorrections, setup::ControllerFormat::Heidenhain);
      },
      "heidenhain");
  expectNoDecimalComma(h, "heidenhain");
  // Rows "NR DOC Z" / "T NAME DL": the last column is the increment with its sign.
  std::vector<double> got;
  std::smatch m;
  for (const std::string& l : lines(h))
    if (std::regex_match(l, m, std::regex("^[0-9]+ +[A-Z0-9]+ +([+-][0-9]+\\.[0-9]+)$")))
      got.push_back(manualNumber(m[1]));
  ASSERT_EQ(got.size(), 3u) << h;
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(got[i], kCorrections[i], 5e-4);

  const std::string s = sameUnderEveryLocale(
      [] { return setup::exportCorrections(exportModel(), kCorrections, setup::ControllerFormat::Siemens); },
      "siemens");
  expectNoDecimalComma(s, "siemens");
  // $P_UIFR[n,Z,FI]=$P_UIFR[n,Z,FI]+x and $TC_DP12[t,d]=$TC_DP12[t,d]+x.
  got.clear();
  for (const std::string& l : lines(s))
    if (std::regex_search(
            l, m, std::regex("^(\\$P_UIFR|\\$TC_DP12)\\[[^\\]]+\\]=\\1\\[[^\\]]+\\]([+-][0-9]+\\.[0-9]+)")))
      got.push_back(manualNumber(m[2]));
  ASSERT_EQ(got.size(), 3u) << s;
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(got[i], kCorrections[i], 5e-4);

  const std::string csv = sameUnderEveryLocale(
      [] { return setup::exportCorrections(exportModel(), kCorrections, setup::ControllerFormat::Csv); },
      "csv");
  EXPECT_NE(csv.find("W1,wks,1,Z,0.013\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("W7,wks,7,Z,-0.021\n"), std::string::npos) << csv;
}

TEST(LocaleMatrix, HeidenhainPresetTableIsReadAndWrittenWithPoints) {
  // The control's table, written here in the TNC's layout (BEGIN line, column names, rows, [END]).
  const std::string table =
      "BEGIN PRESET.PR MM\n"
      "NR      DOC              X              Y              Z\n"
      "1       vise left        -250.1234      +112.5         -412.8765\n"
      "7       fixture 7        +10            +20            -398.25\n"
      "[END]\n";
  const std::string out = sameUnderEveryLocale(
      [&] { return setup::updateHeidenhainTable(exportModel(), kCorrections, table, "PRESET.PR").text; },
      "preset table");
  // Column Z starts where its name starts; the cell reads back to the old value plus the increment.
  const auto l = lines(out);
  ASSERT_GE(l.size(), 4u) << out;
  const std::size_t z = l[1].find('Z');
  EXPECT_NEAR(manualNumber(l[2].substr(z, l[2].find_first_of(" ", z) - z)), -412.8765 + 0.013, 1e-9) << out;
  EXPECT_NEAR(manualNumber(l[3].substr(z, l[3].find_first_of(" ", z) - z)), -398.25 - 0.021, 1e-9) << out;
  EXPECT_EQ(l[2].substr(0, z), "1       vise left        -250.1234      +112.5         ")
      << "only the Z cell changes";
}

// ---- controller frames: HEIDENHAIN PLANE SPATIAL, SINUMERIK TRANS/AROT, FANUC G68.2 ----------------

Eigen::Matrix3d rotX(double deg) {
  return Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitX()).matrix();
}
Eigen::Matrix3d rotY(double deg) {
  return Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitY()).matrix();
}
Eigen::Matrix3d rotZ(double deg) {
  return Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitZ()).matrix();
}

double word(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern + kNum))) {
    ADD_FAILURE() << "no '" << pattern << "<number>' in\n" << text;
    return NAN;
  }
  return manualNumber(m[1]);
}

TEST(LocaleMatrix, ControllerFramesRebuildThePosture) {
  const Eigen::Matrix3d R = rotZ(12.5) * rotY(-0.2884) * rotX(0.75);
  const Eigen::Vector3d t(1.73, -0.0125, 0.5);
  for (const auto format :
       {machine::FrameFormat::Heidenhain, machine::FrameFormat::Siemens, machine::FrameFormat::Fanuc}) {
    const std::string name = machine::toString(format);
    const std::string f =
        sameUnderEveryLocale([&] { return machine::writeControllerFrame(R, t, format); }, name);
    expectNoDecimalComma(f, name);
    Eigen::Matrix3d back;
    Eigen::Vector3d tb;
    if (format == machine::FrameFormat::Heidenhain) {
      // TNC user's manual: CYCL DEF 7.1 X / 7.2 Y / 7.3 Z; PLANE SPATIAL: R = Rz(SPC) Ry(SPB) Rx(SPA).
      tb = {word(f, "CYCL DEF 7\\.1 X"), word(f, "CYCL DEF 7\\.2 Y"), word(f, "CYCL DEF 7\\.3 Z")};
      back = rotZ(word(f, " SPC")) * rotY(word(f, " SPB")) * rotX(word(f, "PLANE SPATIAL SPA"));
    } else if (format == machine::FrameFormat::Siemens) {
      // Programming manual: TRANS X= Y= Z=, then AROT about the current frame's axes in block order.
      tb = {word(f, "TRANS X="), word(f, "TRANS X=\\S+ Y="), word(f, "TRANS X=\\S+ Y=\\S+ Z=")};
      back.setIdentity();
      std::smatch m;
      for (const std::string& l : lines(f)) {
        if (!std::regex_search(l, m, std::regex("^(?:N[0-9]+ )?AROT ([XYZ])=" + kNum))) continue;
        const double a = manualNumber(m[2]);
        back = back * (m[1] == "X" ? rotX(a) : m[1] == "Y" ? rotY(a) : rotZ(a));
      }
    } else {
      // G68.2 X Y Z I J K: Euler Z-X-Z, R = Rz(I) Rx(J) Rz(K).
      tb = {word(f, "G68\\.2 X"), word(f, "G68\\.2 X\\S+ Y"), word(f, "G68\\.2 X\\S+ Y\\S+ Z")};
      back = rotZ(word(f, " I")) * rotX(word(f, " J")) * rotZ(word(f, " K"));
    }
    EXPECT_LT((tb - t).cwiseAbs().maxCoeff(), 0.5e-4 + 1e-12) << name << "\n" << f;
    EXPECT_LT((back - R).cwiseAbs().maxCoeff(), 2e-6) << name << "\n" << f;
  }
}

// ---- compensated path: G-code and STEP-NC Part 21 ---------------------------------------------------

const std::vector<Eigen::Vector2d> kPath{{49.996, -0.0058}, {-5.5, 20.0}, {0.00012345, 1234.5678}};

TEST(LocaleMatrix, CompensatedGcode) {
  ActuatorErrors2 e;
  e.originMm = {0.012, -0.008};
  e.xAxisAngleDeg = 0.01;
  const std::string g = sameUnderEveryLocale([&] { return compensatedPathToGcode(kPath, e); }, "gcode");
  expectNoDecimalComma(g, "gcode");
  std::vector<Eigen::Vector2d> got;
  std::smatch m;
  for (const std::string& l : lines(g))
    if (std::regex_search(l, m, std::regex("^G01 X" + kNum + " Y" + kNum)))
      got.emplace_back(manualNumber(m[1]), manualNumber(m[2]));
  ASSERT_EQ(got.size(), kPath.size()) << g;
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_LT((got[i] - kPath[i]).cwiseAbs().maxCoeff(), 0.5e-4 + 1e-12) << i;
}

TEST(LocaleMatrix, StepNcPart21) {
  ActuatorErrors2 e;
  e.originMm = {0.012, -0.008};
  const std::string p21 = sameUnderEveryLocale([&] { return compensatedPathToStepNc(kPath, e); }, "step-nc");
  // ISO 10303-21: a REAL has a '.', an optional exponent 'E'; CARTESIAN_POINT('',(x,y,z)).
  const std::string real = "([+-]?[0-9]+\\.[0-9]*(?:E[+-]?[0-9]+)?)";
  std::vector<Eigen::Vector2d> got;
  std::smatch m;
  for (const std::string& l : lines(p21))
    if (std::regex_search(
            l, m, std::regex("CARTESIAN_POINT\\('[^']*',\\(" + real + "," + real + "," + real + "\\)\\)")))
      got.emplace_back(num::parseDouble(m[1].str() + (m[1].str().back() == '.' ? "0" : "")).value_or(NAN),
                       num::parseDouble(m[2].str() + (m[2].str().back() == '.' ? "0" : "")).value_or(NAN));
  // The path points are among the points (the security-plane points are the others).
  for (const auto& p : kPath) {
    bool found = false;
    for (const auto& q : got) found = found || q == p;  // shortest round-trip reals: exact
    EXPECT_TRUE(found) << p.transpose() << "\n" << p21;
  }
  // And the project's own reader gives the same doubles under every locale.
  for (const char* l : kLocales) {
    underLocale(l, [&] {
      const StepNcToolpath tp = stepNcToolpath(parsePart21(p21, "compensated.p21"));
      EXPECT_FALSE(tp.points.empty()) << l;
      bool all = true;
      for (const auto& p : kPath) {
        bool found = false;
        for (const auto& q : tp.points) found = found || (q.x() == p.x() && q.y() == p.y());
        all = all && found;
      }
      EXPECT_TRUE(all) << l;
      return 0;
    });
  }
}

// ---- Q-DAS DFQ ---------------------------------------------------------------------------------------

TEST(LocaleMatrix, DfqValues) {
  DfqPart part;
  part.number = "P1";
  part.description = "bore";
  DfqCharacteristic c;
  c.number = "1";
  c.description = "D1";
  c.nominal = 12.5;
  c.lowerLimit = 12.487;
  c.upperLimit = 12.513;
  c.values = {12.4995, 12.5013, 12.49};
  part.characteristics.push_back(c);
  const std::string d = sameUnderEveryLocale([&] { return writeDfq(part); }, "dfq");
  // AQDEF: "K2101/1 12.5"; K0001 values, one line per part, "K0001/1 <value>" or the compact form.
  EXPECT_NEAR(word(d, "K2101(?:/1)? "), 12.5, 0.0);
  EXPECT_NEAR(word(d, "K2110(?:/1)? "), 12.487, 0.0);
  EXPECT_NEAR(word(d, "K2111(?:/1)? "), 12.513, 0.0);
  std::vector<double> got;
  std::smatch m;
  for (const std::string& l : lines(d))
    if (std::regex_search(l, m, std::regex("^K0001(?:/1)? " + kNum))) got.push_back(manualNumber(m[1]));
  ASSERT_EQ(got.size(), 3u) << d;
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(got[i], c.values[i]);
}

// ---- readers ---------------------------------------------------------------------------------------

TEST(LocaleMatrix, ReadersReadPointsUnderEveryLocale) {
  const std::string holes =
      "    Meas X    Meas Y     Nom X     Nom Y  Meas D   Nom D\n"
      "    11.610   -10.090    11.650   -10.184   3.265   2.845\n"
      "    -0.207   162.841    -0.079   162.760   2.174   2.167\n"
      "   210.177    72.484   210.257    72.308   2.174   2.167\n";
  const std::string csv = "time_min,T1_degC,disp_um\n0,20.5,0.125\n1.5,20.75,-1.5e-3\n";
  for (const char* l : kLocales) {
    underLocale(l, [&] {
      const HoleTable t = holeTableFromText(holes, "holes.txt");
      EXPECT_EQ(t.points.points[0].measured.x(), 11.610) << l;
      EXPECT_EQ(t.points.points[1].nominal.y(), 162.760) << l;
      EXPECT_EQ(t.measuredDiameterMm[0], 3.265) << l;
      const CsvTable c = parseCsv(csv, "log.csv");
      EXPECT_EQ(c.numericColumn("T1_degC")[1], 20.75) << l;
      EXPECT_EQ(c.numericColumn("disp_um")[1], -1.5e-3) << l;
      return 0;
    });
  }
}

TEST(LocaleMatrix, ProjectFileIsTheSameBytes) {
  Project p;
  p.name = "Locale";
  p.studies["matching"] = {{"tolerance_mm", 0.05}, {"seed", 3}};
  p.studies["thermal"] = {{"train_fraction", 0.625}};
  const std::string text = sameUnderEveryLocale([&] { return p.toJson().dump(); }, "project");
  EXPECT_NE(text.find("\"tolerance_mm\":0.05"), std::string::npos) << text;
  for (const char* l : kLocales) {
    underLocale(l, [&] {
      const Project back = Project::fromJson(nlohmann::json::parse(text), "p.metrofit");
      EXPECT_EQ(back.studies["thermal"]["train_fraction"].get<double>(), 0.625) << l;
      return 0;
    });
  }
}

}  // namespace
}  // namespace metrofit
