// Exports of compensated paths: G-code text, STEP-NC Part 21 text, and the Part 21 reader
// (round trip, syntax, references, errors).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/kinematics/export.h"
#include "core/kinematics/part21.h"
#include "metrofit/version.h"
#include "testsupport.h"

namespace metrofit {
namespace {

ActuatorErrors2 someErrors() {
  ActuatorErrors2 e;
  e.originMm = Eigen::Vector2d(0.004, -0.003);
  e.xAxisAngleDeg = 0.0006;
  e.yAxisAngleDeg = -0.002;
  return e;
}

TEST(Gcode, ExactTextOfASmallPath) {
  const std::vector<Eigen::Vector2d> path = {{0.0, 0.0}, {10.12346, -0.00001}, {-5.5, 20.0}};
  const std::string expected =
      "%\n"
      "(Metrofit " +
      std::string(kVersion) +
      ": compensated path)\n"
      "(machine: Cartesian XY, X actuator carries Y, kinematic-compensation paper Section IV)\n"
      "(model: P = origin + X [cos a, sin a] + Y [-sin b, cos b], Eq. 9)\n"
      "(errors: origin_mm = [0.004000, -0.003000], x_axis_angle_deg a = 0.000600, y_axis_angle_deg b = "
      "-0.002000, squareness b - a = -0.002600 deg)\n"
      "(sign convention: angles counter-clockwise positive; b - a > 0 opens the XY angle beyond 90 deg)\n"
      "(blocks are compensated references Pr = [ir jr]^-1 [P - origin], Eq. 15: the machine lands on the "
      "nominal path)\n"
      "(points: 3, mm, absolute)\n"
      "G21 G90 G17\n"
      "G01 X0.0000 Y0.0000 F1000\n"
      "G01 X10.1235 Y0.0000\n"
      "G01 X-5.5000 Y20.0000\n"
      "M30\n"
      "%\n";
  EXPECT_EQ(compensatedPathToGcode(path, someErrors()), expected);
}

TEST(Gcode, OptionsAndCommentSafety) {
  GcodeOptions o;
  o.programName = "part (rev 2)\nnext";
  o.decimals = 3;
  o.feedMmPerMin = 250.0;
  const std::string g = compensatedPathToGcode({{1.23456, 2.0}}, someErrors(), o);
  EXPECT_NE(g.find("(Metrofit " + std::string(kVersion) + ": part [rev 2] next)\n"), std::string::npos) << g;
  EXPECT_NE(g.find("G01 X1.235 Y2.000 F250\n"), std::string::npos) << g;
  // Every comment line has exactly one '(' and one ')'.
  std::size_t pos = 0;
  while ((pos = g.find('\n', pos)) != std::string::npos) {
    const std::size_t start = g.rfind('\n', pos - 1) == std::string::npos ? 0 : g.rfind('\n', pos - 1) + 1;
    const std::string line = g.substr(start, pos - start);
    if (!line.empty() && line.front() == '(') {
      EXPECT_EQ(std::count(line.begin(), line.end(), '('), 1) << line;
      EXPECT_EQ(std::count(line.begin(), line.end(), ')'), 1) << line;
      EXPECT_EQ(line.back(), ')') << line;
    }
    ++pos;
  }
  o.feedMmPerMin = 0.0;
  EXPECT_THROW(compensatedPathToGcode({{0, 0}}, someErrors(), o), OptionsError);
  EXPECT_THROW(compensatedPathToGcode({{NAN, 0}}, someErrors()), InputError);
}

TEST(Part21, RealsAndStrings) {
  EXPECT_EQ(part21Real(1.0), "1.");
  EXPECT_EQ(part21Real(0.0), "0.");
  EXPECT_EQ(part21Real(-0.25), "-0.25");
  EXPECT_EQ(part21Real(1.5e-7), "1.5E-07");
  EXPECT_EQ(part21Real(2e20), "2.E+20");
  EXPECT_EQ(part21String("it's a\\b"), "'it''s a\\\\b'");
  EXPECT_EQ(part21String("\xC3\xA9t\xC3\xA9"),
            "'?"
            "?t?"
            "?'");  // split: no trigraphs
}

TEST(Part21, StepNcRoundTripGivesTheSamePointsExactly) {
  std::vector<Eigen::Vector2d> path;
  for (int k = 0; k < 50; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 50.0;
    path.emplace_back(100.0 * std::cos(t) + 1e-7 * k, 100.0 * std::sin(t) - 0.004);
  }
  path.emplace_back(-0.0, 123.456789012345);
  StepNcOptions o;
  o.fileName = "circle.p21";
  o.timestamp = "2024-05-01T12:00:00";
  o.zMm = -1.25;
  const std::string text = compensatedPathToStepNc(path, someErrors(), o);
  EXPECT_EQ(text.rfind("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(", 0), 0u);
  EXPECT_EQ(text.substr(text.size() - 26), "ENDSEC;\nEND-ISO-10303-21;\n");

  const P21File f = parsePart21(text, "circle.p21");
  EXPECT_EQ(f.schemas(), std::vector<std::string>{"MACHINING_SCHEMA"});
  const P21Entity* name = f.headerEntity("FILE_NAME");
  ASSERT_NE(name, nullptr);
  EXPECT_EQ(name->params.at(0).text, "circle.p21");
  EXPECT_EQ(name->params.at(1).text, "2024-05-01T12:00:00");
  EXPECT_EQ(f.ofType("CARTESIAN_POINT").size(), path.size() + 2);
  EXPECT_EQ(f.ofType("MACHINING_WORKINGSTEP").size(), 1u);
  // The project points at the workplan, the workplan at the workingstep.
  const P21Entity& project = f.entity(1);
  EXPECT_EQ(project.type, "PROJECT");
  ASSERT_EQ(project.params.at(1).kind, P21Value::Kind::Reference);
  EXPECT_EQ(f.entity(project.params[1].reference).type, "WORKPLAN");

  const StepNcToolpath tp = stepNcToolpath(f);
  EXPECT_EQ(tp.workplan, "main workplan");
  EXPECT_EQ(tp.workingsteps, std::vector<std::string>{"compensated path"});
  ASSERT_EQ(tp.points.size(), path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    EXPECT_EQ(tp.points[k].x(), path[k].x()) << k;  // bit for bit
    EXPECT_EQ(tp.points[k].y(), path[k].y()) << k;
    EXPECT_EQ(tp.points[k].z(), -1.25);
  }
  EXPECT_THROW(compensatedPathToStepNc({{0, 0}}, someErrors()), InputError);
}

const char* const kHeader =
    "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\nFILE_NAME('a','b',(''),(''),'','','');\n"
    "FILE_SCHEMA(('S'));\nENDSEC;\n";

TEST(Part21, ReaderHandlesTheSyntax) {
  const std::string text = std::string(kHeader) +
                           "DATA;\n"
                           "/* a comment\n over lines */\n"
                           "#1 = THING('it''s', (1, -2.5, 3.E-2, +4.), $, *, .T., .ENUM_1., #2,\n"
                           "  MEASURE(2.), ((#2), ()));\n"
                           "#2=OTHER('a\\\\b');\n"
                           "ENDSEC;\nDATA(('second section'));\n#10=LAST();\nENDSEC;\nEND-ISO-10303-21;\n";
  const P21File f = parsePart21(text, "t.p21");
  ASSERT_EQ(f.data.size(), 3u);
  const P21Entity& e = f.entity(1);
  EXPECT_EQ(e.type, "THING");
  EXPECT_EQ(e.line, 10);  // header 1-6, DATA 7, comment 8-9
  ASSERT_EQ(e.params.size(), 9u);
  EXPECT_EQ(e.params[0].text, "it's");
  ASSERT_EQ(e.params[1].items.size(), 4u);
  EXPECT_EQ(e.params[1].items[0].kind, P21Value::Kind::Integer);
  EXPECT_EQ(e.params[1].items[1].number, -2.5);
  EXPECT_EQ(e.params[1].items[2].number, 0.03);
  EXPECT_EQ(e.params[1].items[3].kind, P21Value::Kind::Real);
  EXPECT_EQ(e.params[2].kind, P21Value::Kind::Unset);
  EXPECT_EQ(e.params[3].kind, P21Value::Kind::Derived);
  EXPECT_EQ(e.params[4].text, "T");
  EXPECT_EQ(e.params[5].kind, P21Value::Kind::Enum);
  EXPECT_EQ(e.params[5].text, "ENUM_1");
  EXPECT_EQ(e.params[6].reference, 2);
  EXPECT_EQ(e.params[7].kind, P21Value::Kind::Typed);
  EXPECT_EQ(e.params[7].text, "MEASURE");
  EXPECT_EQ(e.params[7].items.at(0).number, 2.0);
  EXPECT_EQ(e.params[8].items.at(0).items.at(0).reference, 2);
  EXPECT_TRUE(e.params[8].items.at(1).items.empty());
  EXPECT_EQ(f.entity(2).params[0].text, "a\\b");
  EXPECT_EQ(f.entity(10).params.size(), 0u);
  EXPECT_EQ(f.ofType("OTHER").size(), 1u);
  EXPECT_THROW(f.entity(3), ParseError);
}

std::string p21Error(const std::string& data) {
  try {
    parsePart21(std::string(kHeader) + data, "t.p21");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Part21, ReaderErrorsNameLineAndCause) {
  EXPECT_EQ(p21Error("DATA;\n#1=A(#5);\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8: #1 A refers to #5, which is not defined");
  EXPECT_EQ(p21Error("DATA;\n#1=A();\n#1=B();\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:9: #1 is defined twice (first on line 8)");
  EXPECT_EQ(p21Error("DATA;\n#1=A('abc);\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8: unterminated string '...");
  EXPECT_EQ(p21Error("DATA;\n#1=(A()B());\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8:4: complex entity instances #1=(...) are not supported");
  EXPECT_EQ(p21Error("DATA;\n#1=A(1 2);\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8:8: expected ',' or ')', found '2'");
  EXPECT_EQ(p21Error("DATA;\n#1=A(1.2.3);\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8:6: malformed number '1.2.'");
  EXPECT_EQ(p21Error("DATA;\n#1=A();\nENDSEC;\n"), "t.p21:10:1: the file ends before END-ISO-10303-21;");
  EXPECT_EQ(p21Error("DATA;\n#1=A();\nENDSEC;\nEND-ISO-10303-21;\nmore"),
            "t.p21:11:1: text after END-ISO-10303-21;");
  EXPECT_EQ(p21Error("DATA;\n/* open\n"), "t.p21:8: unterminated comment /* ...");
  EXPECT_EQ(p21Error("DATA;\n#1=A(\"0FF\");\nENDSEC;\nEND-ISO-10303-21;\n"),
            "t.p21:8:6: binary values \"...\" are not supported");
  try {
    parsePart21(
        "ISO-10303-21;\nHEADER;\nFILE_NAME('a','b',(''),(''),'','','');\nENDSEC;\nDATA;\nENDSEC;\n"
        "END-ISO-10303-21;\n",
        "h.p21");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()), "h.p21: field 'FILE_DESCRIPTION': missing in the HEADER section");
  }
  EXPECT_THROW(parsePart21("ISO-10303-22;", "x"), ParseError);
  EXPECT_THROW(parsePart21("", "x"), ParseError);
}

TEST(Part21, ToolpathChainErrorsNameTheEntity) {
  const std::string noOp = std::string(kHeader) +
                           "DATA;\n#1=WORKPLAN('w',(#2),$,$,$);\n#2=MACHINING_WORKINGSTEP('ws',$,$,#3,$);\n"
                           "#3=FREEFORM_OPERATION($,$,'op',$,$,$,$,$,$,$,$,$);\nENDSEC;\nEND-ISO-10303-21;\n";
  try {
    stepNcToolpath(parsePart21(noOp, "n.p21"));
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()), "n.p21:9: #2 MACHINING_WORKINGSTEP: no operation with a TOOLPATH_LIST");
  }
  const std::string noPlan = std::string(kHeader) + "DATA;\n#1=A();\nENDSEC;\nEND-ISO-10303-21;\n";
  EXPECT_THROW(stepNcToolpath(parsePart21(noPlan, "n.p21")), ValidationError);
}

}  // namespace
}  // namespace metrofit
