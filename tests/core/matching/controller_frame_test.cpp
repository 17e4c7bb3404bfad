// The posture as a controller frame (core/machine/controller_frame.h), checked independently: the
// written blocks are parsed back from the text and the rotation rebuilt here, with each control's
// convention as its documentation states it (not with our own angle functions):
//  * HEIDENHAIN PLANE SPATIAL (TNC 620 user's manual, "Defining the working plane with the spatial
//    angle": rotations about the non-tilted axes "A, then B, then C", SPA about X, SPB about Y, SPC
//    about Z):  R = Rz(SPC) Ry(SPB) Rx(SPA), fixed axes, applied right to left.
//  * SINUMERIK AROT: additive rotation of the current frame about its own axes, blocks in order
//    Z, Y, X:  R = Rz(Z) * Ry(Y) * Rx(X) (each new rotation multiplies on the right).
//  * FANUC G68.2 I J K (Euler angles): I about Z, J about the new X, K about the new Z:
//    R = Rz(I) Rx(J) Rz(K).
// The elementary rotations are the right-hand ones, written out element by element below.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/machine/controller_frame.h"

namespace metrofit::machine {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d Rx(double deg) {
  const double c = std::cos(deg * kPi / 180), s = std::sin(deg * kPi / 180);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Eigen::Matrix3d Ry(double deg) {
  const double c = std::cos(deg * kPi / 180), s = std::sin(deg * kPi / 180);
  Eigen::Matrix3d m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}
Eigen::Matrix3d Rz(double deg) {
  const double c = std::cos(deg * kPi / 180), s = std::sin(deg * kPi / 180);
  Eigen::Matrix3d m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

double word(const std::string& text, const std::string& re) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(re))) {
    ADD_FAILURE() << "no match of " << re << " in\n" << text;
    return NAN;
  }
  return std::stod(m[1].str());
}

const std::string kNum = "([-+]?[0-9]+\\.[0-9]+)";

/// Parses the HEIDENHAIN program: rotation and datum shift.
void parseHeidenhain(const std::string& text, Eigen::Matrix3d* R, Eigen::Vector3d* t) {
  *t = {word(text, "CYCL DEF 7\\.1 X" + kNum), word(text, "CYCL DEF 7\\.2 Y" + kNum),
        word(text, "CYCL DEF 7\\.3 Z" + kNum)};
  const double a = word(text, "PLANE SPATIAL SPA" + kNum), b = word(text, " SPB" + kNum),
               c = word(text, " SPC" + kNum);
  *R = Rz(c) * Ry(b) * Rx(a);
}

void parseSiemens(const std::string& text, Eigen::Matrix3d* R, Eigen::Vector3d* t) {
  *t = {word(text, "TRANS X=" + kNum), word(text, "TRANS X=\\S+ Y=" + kNum),
        word(text, "TRANS X=\\S+ Y=\\S+ Z=" + kNum)};
  *R = Eigen::Matrix3d::Identity();
  // Each AROT block rotates the current frame about its own axis: right multiplication, in file order.
  for (const std::string& l : lines(text)) {
    std::smatch m;
    if (std::regex_match(l, m, std::regex("AROT ([XYZ])=" + kNum))) {
      const double v = std::stod(m[2].str());
      *R = *R * (m[1] == "X" ? Rx(v) : m[1] == "Y" ? Ry(v) : Rz(v));
    }
  }
}

void parseFanuc(const std::string& text, Eigen::Matrix3d* R, Eigen::Vector3d* t) {
  const std::string g =
      "G68\\.2 X" + kNum + " Y" + kNum + " Z" + kNum + " I" + kNum + " J" + kNum + " K" + kNum;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(g))) << text;
  *t = {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
  *R = Rz(std::stod(m[4])) * Rx(std::stod(m[5])) * Rz(std::stod(m[6]));
}

void parse(FrameFormat f, const std::string& text, Eigen::Matrix3d* R, Eigen::Vector3d* t) {
  if (f == FrameFormat::Heidenhain) parseHeidenhain(text, R, t);
  if (f == FrameFormat::Siemens) parseSiemens(text, R, t);
  if (f == FrameFormat::Fanuc) parseFanuc(text, R, t);
}

/// Rotations to check: a nontrivial 3-angle one, the gimbal-lock cases of both conventions and their
/// neighbourhoods, and random ones.
std::vector<Eigen::Matrix3d> rotations() {
  std::vector<Eigen::Matrix3d> out = {
      Eigen::Matrix3d::Identity(),
      Rz(37.5) * Ry(-22.25) * Rx(61.0),   // nontrivial, all three angles
      Rz(-150.0) * Rx(100.0) * Rz(75.0),  // nontrivial Z-X-Z
      Rz(30.0),                           // Euler J = 0 exactly: only I + K defined
      Rz(10.0) * Rx(180.0) * Rz(25.0),    // Euler J = 180
      Rz(10.0) * Rx(1e-9) * Rz(25.0),     // Euler J next to 0
      Rz(10.0) * Rx(180.0 - 1e-9) * Rz(25.0),
      Rz(20.0) * Ry(90.0) * Rx(5.0),  // SPB = +90: only SPA - SPC defined
      Rz(20.0) * Ry(-90.0) * Rx(5.0),
      Rz(20.0) * Ry(90.0 - 1e-9) * Rx(5.0),
      Rx(180.0),
      Ry(180.0),
  };
  Rng rng(4);
  for (int k = 0; k < 30; ++k)
    out.push_back(Rz(rng.uniform(-180, 180)) * Rx(rng.uniform(-180, 180)) * Rz(rng.uniform(-180, 180)));
  return out;
}

class FrameRoundTrip : public ::testing::TestWithParam<FrameFormat> {};

TEST_P(FrameRoundTrip, WrittenAnglesRebuildTheRotationWithin1e9) {
  const Eigen::Vector3d t(12.345678901234, -0.000987654321, 250.5);
  FrameOptions o;
  o.decimals = 12;  // the test's precision; the default is 4 (see RoundingOfTheDefaultDecimals)
  for (const Eigen::Matrix3d& R : rotations()) {
    const std::string text = writeControllerFrame(R, t, GetParam(), o);
    EXPECT_EQ(text.find("nan"), std::string::npos) << text;
    EXPECT_EQ(text.find("inf"), std::string::npos) << text;
    Eigen::Matrix3d Rb;
    Eigen::Vector3d tb;
    parse(GetParam(), text, &Rb, &tb);
    EXPECT_LT((Rb - R).cwiseAbs().maxCoeff(), 1e-9) << text << "\nR =\n" << R;
    EXPECT_LT((tb - t).cwiseAbs().maxCoeff(), 1e-9) << text;
  }
}

TEST_P(FrameRoundTrip, RoundingOfTheDefaultDecimals) {
  // 4 decimals: each angle within 5e-5 deg, so every element of R within 3 * 5e-5 deg = 2.6e-6.
  const Eigen::Matrix3d R = Rz(37.123456) * Ry(-22.654321) * Rx(61.987654);
  const std::string text = writeControllerFrame(R, Eigen::Vector3d(1.0, 2.0, 3.0), GetParam());
  Eigen::Matrix3d Rb;
  Eigen::Vector3d tb;
  parse(GetParam(), text, &Rb, &tb);
  EXPECT_LT((Rb - R).cwiseAbs().maxCoeff(), 3 * 5e-5 * kPi / 180) << text;
  EXPECT_GT((Rb - R).cwiseAbs().maxCoeff(), 0.0) << "the default rounds to 4 decimals";
}

INSTANTIATE_TEST_SUITE_P(Controllers, FrameRoundTrip,
                         ::testing::Values(FrameFormat::Heidenhain, FrameFormat::Siemens, FrameFormat::Fanuc),
                         [](const auto& info) { return std::string(toString(info.param)); });

TEST(ControllerFrame, GimbalLockWritesFirstAngleZero) {
  // Euler J = 180: I is set to 0 and K carries K - I of the input (Rz(10) Rx(180) = Rx(180) Rz(-10), so
  // Rz(10) Rx(180) Rz(25) = Rx(180) Rz(15)).
  FrameOptions o;
  o.decimals = 6;
  const std::string f =
      writeControllerFrame(Rz(10.0) * Rx(180.0) * Rz(25.0), Eigen::Vector3d::Zero(), FrameFormat::Fanuc, o);
  EXPECT_NE(f.find("G68.2 X0.000000 Y0.000000 Z0.000000 I0.000000 J180.000000 K15.000000\n"),
            std::string::npos)
      << f;
  // SPB = +90: SPC = 0, SPA = 5 - 20 (Rz(20) Ry(90) Rx(5) = Ry(90) Rx(-15)).
  const std::string h = writeControllerFrame(Rz(20.0) * Ry(90.0) * Rx(5.0), Eigen::Vector3d::Zero(),
                                             FrameFormat::Heidenhain, o);
  EXPECT_NE(h.find(" PLANE SPATIAL SPA-15.000000 SPB+90.000000 SPC+0.000000 STAY\n"), std::string::npos) << h;
}

TEST(ControllerFrame, HeidenhainProgramLayout) {
  // Block by block against the TNC conversational layout: numbered blocks from 0, BEGIN PGM / END PGM
  // with the same name and unit, ";" comments, CYCL DEF 7.0-7.3 datum shift before PLANE SPATIAL.
  const std::string text =
      writeControllerFrame(Rz(30.0), Eigen::Vector3d(1.5, -2.25, 0.0), FrameFormat::Heidenhain);
  const auto l = lines(text);
  ASSERT_EQ(l.size(), 13u) << text;
  for (std::size_t i = 0; i < l.size(); ++i) EXPECT_EQ(l[i].rfind(std::to_string(i) + " ", 0), 0u) << l[i];
  EXPECT_EQ(l.front(), "0 BEGIN PGM METROFIT_FRAME MM");
  EXPECT_EQ(l.back(), "12 END PGM METROFIT_FRAME MM");
  for (std::size_t i = 1; i <= 6; ++i) EXPECT_EQ(l[i].substr(l[i].find(' ') + 1, 1), ";") << l[i];
  EXPECT_EQ(l[7], "7 CYCL DEF 7.0 DATUM SHIFT");
  EXPECT_EQ(l[8], "8 CYCL DEF 7.1 X+1.5000");
  EXPECT_EQ(l[9], "9 CYCL DEF 7.2 Y-2.2500");
  EXPECT_EQ(l[10], "10 CYCL DEF 7.3 Z+0.0000");
  EXPECT_EQ(l[11], "11 PLANE SPATIAL SPA+0.0000 SPB+0.0000 SPC+30.0000 STAY");
  FrameOptions o;
  o.programName = "PART_17";
  const auto named =
      lines(writeControllerFrame(Rz(30.0), Eigen::Vector3d::Zero(), FrameFormat::Heidenhain, o));
  EXPECT_EQ(named.front(), "0 BEGIN PGM PART_17 MM");
  EXPECT_EQ(named.back(), "12 END PGM PART_17 MM");
  o.programName = "part 17";
  EXPECT_THROW((void)writeControllerFrame(Rz(30.0), Eigen::Vector3d::Zero(), FrameFormat::Heidenhain, o),
               OptionsError);
}

TEST(ControllerFrame, SiemensAndFanucLayout) {
  const Eigen::Vector3d t(1.5, -2.25, 0.0);
  const auto s = lines(writeControllerFrame(Rz(30.0), t, FrameFormat::Siemens));
  ASSERT_EQ(s.size(), 11u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(s[i].rfind("; ", 0), 0u) << s[i];
  EXPECT_EQ(s[6], "TRANS X=1.5000 Y=-2.2500 Z=0.0000");
  EXPECT_EQ(s[7], "AROT Z=30.0000");
  EXPECT_EQ(s[8], "AROT Y=0.0000");
  EXPECT_EQ(s[9], "AROT X=0.0000");
  EXPECT_EQ(s[10], "M17");

  FrameOptions o;
  o.decimals = 3;
  o.title = "Part (A)";
  const auto f = lines(writeControllerFrame(Rz(30.0), t, FrameFormat::Fanuc, o));
  ASSERT_EQ(f.size(), 10u);
  EXPECT_EQ(f[0], "%");
  EXPECT_EQ(f[1], "O7101 (METROFIT POSTURE FRAME)");
  EXPECT_EQ(f[2], "(PART [A])");
  for (std::size_t i = 2; i < 6; ++i) EXPECT_EQ(f[i].front(), '(') << f[i];
  EXPECT_EQ(f[6], "G21");
  // Rz(30) alone is J = 0 (gimbal lock): I = 0, K = 30.
  EXPECT_EQ(f[7], "G68.2 X1.500 Y-2.250 Z0.000 I0.000 J0.000 K30.000");
  EXPECT_EQ(f[8], "M99");
  EXPECT_EQ(f[9], "%");
}

// The frame's blocks alone (what the report prints) are the program's command blocks, in order.
TEST(ControllerFrame, BlocksAreTheProgramsCommandBlocks) {
  const Eigen::Vector3d t(1.5, -2.25, 0.0);
  const auto h = lines(writeControllerFrame(Rz(30.0), t, FrameFormat::Heidenhain));
  EXPECT_EQ(controllerFrameBlocks(Rz(30.0), t, FrameFormat::Heidenhain),
            (std::vector<std::string>{"CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+1.5000",
                                      "CYCL DEF 7.2 Y-2.2500", "CYCL DEF 7.3 Z+0.0000",
                                      "PLANE SPATIAL SPA+0.0000 SPB+0.0000 SPC+30.0000 STAY"}));
  EXPECT_EQ(h[11], "11 PLANE SPATIAL SPA+0.0000 SPB+0.0000 SPC+30.0000 STAY");
  EXPECT_EQ(controllerFrameBlocks(Rz(30.0), t, FrameFormat::Fanuc, 3),
            std::vector<std::string>{"G68.2 X1.500 Y-2.250 Z0.000 I0.000 J0.000 K30.000"});
  const auto s = controllerFrameBlocks(Rz(30.0), t, FrameFormat::Siemens);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0], "TRANS X=1.5000 Y=-2.2500 Z=0.0000");
  EXPECT_EQ(s[1], "AROT Z=30.0000");
  Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
  bad(0, 0) = -1.0;  // a reflection
  EXPECT_THROW((void)controllerFrameBlocks(bad, t, FrameFormat::Fanuc), ValidationError);
}

// The TNC lists a program under its file name (BEGIN PGM <name>): the name of the file the frame goes
// to, made a valid program name (letters, digits, '_', '-'; at most 32), as the CLI and the GUI write it.
TEST(ControllerFrame, ProgramNameIsTheFileNameMadeValid) {
  EXPECT_EQ(frameProgramName("/tmp/out/POSTURE.h"), "POSTURE");
  EXPECT_EQ(frameProgramName("cell 3/my frame.v2.H"), "my_frame_v2");
  EXPECT_EQ(frameProgramName("FRAME-7"), "FRAME-7");
  EXPECT_EQ(frameProgramName(std::string(40, 'A') + ".h"), std::string(32, 'A'));
  EXPECT_EQ(frameProgramName("Lage\xc3\xa4.h"), "Lage__");  // UTF-8 bytes are no TNC name characters
  EXPECT_EQ(frameProgramName(""), FrameOptions{}.programName);
  for (const char* file : {"/tmp/out/POSTURE.h", "cell 3/my frame.v2.H", "x y z.h", "\xc3\xa4\xc3\xb6.h"}) {
    FrameOptions o;
    o.programName = frameProgramName(file);
    std::string why;
    EXPECT_TRUE(o.isValid(&why)) << file << ": " << why;
  }
}

TEST(ControllerFrame, Errors) {
  Eigen::Matrix3d notRotation = Eigen::Matrix3d::Identity();
  notRotation(0, 0) = -1.0;  // a reflection
  EXPECT_THROW((void)writeControllerFrame(notRotation, Eigen::Vector3d::Zero(), FrameFormat::Fanuc),
               ValidationError);
  EXPECT_THROW((void)writeControllerFrame(2.0 * Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                          FrameFormat::Siemens),
               ValidationError);
  EXPECT_THROW((void)writeControllerFrame(Eigen::Matrix3d::Identity(), Eigen::Vector3d(NAN, 0, 0),
                                          FrameFormat::Heidenhain),
               ValidationError);
  FrameOptions o;
  o.programNumber = 9001;
  try {
    (void)writeControllerFrame(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), FrameFormat::Fanuc, o);
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("parameter 3202 bit 4 (NE9)"), std::string::npos) << e.what();
  }
  o.programNumber = 8500;
  try {
    (void)writeControllerFrame(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), FrameFormat::Fanuc, o);
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_NE(std::string(e.what()).find("parameter 3202 bit 0 (NE8)"), std::string::npos) << e.what();
  }
  try {
    (void)parseFrameFormat("haas", "--frame");
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(),
                 "field '--frame': unknown frame format 'haas' (one of heidenhain, siemens, fanuc)");
  }
}

}  // namespace
}  // namespace metrofit::machine
