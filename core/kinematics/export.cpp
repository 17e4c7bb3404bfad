#include "core/kinematics/export.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/common/numformat.h"
#include "core/common/run.h"
#include "metrofit/version.h"

namespace metrofit {
namespace {

std::string fixed(double v, int decimals) {
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  // "-0.0000" -> "0.0000"
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string gcodeComment(std::string text) {
  for (char& c : text) {
    if (c == '(')
      c = '[';
    else if (c == ')')
      c = ']';
    else if (c == '\n' || c == '\r' || c == '%')
      c = ' ';
  }
  return "(" + text + ")\n";
}

std::string errorsLine(const ActuatorErrors2& e, int decimals) {
  return "errors: origin_mm = [" + fixed(e.originMm.x(), decimals + 2) + ", " +
         fixed(e.originMm.y(), decimals + 2) + "], x_axis_angle_deg a = " + fixed(e.xAxisAngleDeg, 6) +
         ", y_axis_angle_deg b = " + fixed(e.yAxisAngleDeg, 6) +
         ", squareness b - a = " + fixed(e.squarenessDeg(), 6) + " deg";
}

}  // namespace

bool GcodeOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(feedMmPerMin > 0.0) || !std::isfinite(feedMmPerMin)) return no("feed must be positive");
  if (decimals < 0 || decimals > 6) return no("decimals must be between 0 and 6");
  return true;
}

std::string compensatedPathToGcode(const std::vector<Eigen::Vector2d>& commands,
                                   const ActuatorErrors2& errors, const GcodeOptions& o) {
  requireValid(o, "G-code options");
  requireValid(errors, "actuator errors");
  std::string g = "%\n";
  g += gcodeComment("Metrofit " + std::string(kVersion) + ": " + o.programName);
  g += gcodeComment("machine: Cartesian XY, X actuator carries Y, kinematic-compensation paper Section IV");
  g += gcodeComment("model: P = origin + X (cos a, sin a) + Y (-sin b, cos b), Eq. 9");
  g += gcodeComment(errorsLine(errors, o.decimals));
  g += gcodeComment(
      "sign convention: angles counter-clockwise positive; b - a > 0 opens the XY angle beyond 90 deg");
  g += gcodeComment(
      "blocks are compensated references Pr = [ir jr]^-1 (P - origin), Eq. 15: the machine lands on "
      "the nominal path");
  g += gcodeComment("points: " + std::to_string(commands.size()) + ", mm, absolute");
  g += "G21 G90 G17\n";
  for (std::size_t i = 0; i < commands.size(); ++i) {
    if (!commands[i].allFinite()) {
      throw InputError(ErrorContext{{}, 0, 0, "commands"},
                       "point " + std::to_string(i + 1) + " is not finite");
    }
    g += "G01 X" + fixed(commands[i].x(), o.decimals) + " Y" + fixed(commands[i].y(), o.decimals);
    if (i == 0) g += " F" + fixed(o.feedMmPerMin, 0);
    g += '\n';
  }
  g += "M30\n%\n";
  return g;
}

bool StepNcOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!std::isfinite(zMm) || !std::isfinite(securityPlaneMm))
    return no("z and security plane must be finite");
  if (timestamp.empty()) return no("timestamp must not be empty");
  return true;
}

std::string part21Real(double v) {
  if (v == 0.0) return "0.";
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, res.ptr);
  const auto e = s.find('e');
  std::string mant = e == std::string::npos ? s : s.substr(0, e);
  std::string exp = e == std::string::npos ? std::string() : s.substr(e + 1);
  if (mant.find('.') == std::string::npos) mant += '.';
  return exp.empty() ? mant : mant + "E" + exp;
}

std::string part21String(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\'')
      out += "''";
    else if (c == '\\')
      out += "\\\\";
    else if (u < 32 || u > 126)
      out += '?';
    else
      out += c;
  }
  return out + "'";
}

std::string compensatedPathToStepNc(const std::vector<Eigen::Vector2d>& commands,
                                    const ActuatorErrors2& errors, const StepNcOptions& o) {
  requireValid(o, "STEP-NC options");
  requireValid(errors, "actuator errors");
  if (commands.size() < 2) {
    throw InputError(ErrorContext{{}, 0, 0, "commands"},
                     "a polyline needs at least 2 points, got " + std::to_string(commands.size()));
  }
  auto str = [](const std::string& s) { return part21String(s); };
  auto R = [](double v) { return part21Real(v); };
  std::string s = "ISO-10303-21;\nHEADER;\n";
  s += "FILE_DESCRIPTION((" + str("Metrofit compensated toolpath") + "," +
       str("STEP-NC, ISO 14649-10/-11 information model (AP238 ARM)") + "),'2;1');\n";
  s += "FILE_NAME(" + str(o.fileName) + "," + str(o.timestamp) + ",(" + str("Metrofit") + "),(" + str("") +
       ")," + str("Metrofit " + std::string(kVersion)) + "," + str("Metrofit") + "," + str("") + ");\n";
  s += "FILE_SCHEMA((" + str("MACHINING_SCHEMA") + "));\nENDSEC;\nDATA;\n";
  s += "/* Compensated references Pr = [ir jr]^-1 (P - origin) (kinematic-compensation paper, Eq. 15) */\n";
  s += "/* " + errorsLine(errors, 4) + " */\n";
  s += "/* model P = origin + x (cos a, sin a) + y (-sin b, cos b); angles counter-clockwise positive */\n";
  s += "#1=PROJECT(" + str(o.projectName) + ",#2,(#3),$,$,$);\n";
  s += "#2=WORKPLAN(" + str("main workplan") + ",(#10),$,$,$);\n";
  s += "#3=WORKPIECE(" + str("workpiece") + ",$,$,$,$,$,());\n";
  s += "#10=MACHINING_WORKINGSTEP(" + str("compensated path") + ",#11,#12,#13,$);\n";
  s += "#11=PLANE(" + str("security plane") + ",#20);\n";
  s += "#12=TOOLPATH_FEATURE(" + str("compensated path") + ",#3,(#13),#24);\n";
  s += "#13=FREEFORM_OPERATION(#14,$," + str("compensated references") + ",$,$,$,$,$,$,$,$,$);\n";
  s += "#14=TOOLPATH_LIST((#15));\n";
  s += "#15=CUTTER_LOCATION_TRAJECTORY(.REQUIRED.,.CONTACT.,$,$,$,.T.,#16,$,$,$);\n";
  const long first = 100;
  s += "#16=POLYLINE(" + str("compensated references") + ",(";
  for (std::size_t i = 0; i < commands.size(); ++i) {
    s += (i ? "," : "") + std::string("#") + std::to_string(first + static_cast<long>(i));
    if (i % 16 == 15 && i + 1 < commands.size()) s += "\n  ";
  }
  s += "));\n";
  s += "#20=AXIS2_PLACEMENT_3D(" + str("security plane") + ",#21,#22,#23);\n";
  s += "#21=CARTESIAN_POINT(" + str("") + ",(0.,0.," + R(o.securityPlaneMm) + "));\n";
  s += "#22=DIRECTION(" + str("axis") + ",(0.,0.,1.));\n";
  s += "#23=DIRECTION(" + str("ref_direction") + ",(1.,0.,0.));\n";
  s += "#24=AXIS2_PLACEMENT_3D(" + str("feature placement") + ",#25,#22,#23);\n";
  s += "#25=CARTESIAN_POINT(" + str("") + ",(0.,0.,0.));\n";
  for (std::size_t i = 0; i < commands.size(); ++i) {
    if (!commands[i].allFinite()) {
      throw InputError(ErrorContext{{}, 0, 0, "commands"},
                       "point " + std::to_string(i + 1) + " is not finite");
    }
    s += "#" + std::to_string(first + static_cast<long>(i)) + "=CARTESIAN_POINT(" + str("") + ",(" +
         R(commands[i].x()) + "," + R(commands[i].y()) + "," + R(o.zMm) + "));\n";
  }
  s += "ENDSEC;\nEND-ISO-10303-21;\n";
  return s;
}

}  // namespace metrofit
