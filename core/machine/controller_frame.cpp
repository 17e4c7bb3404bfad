#include "core/machine/controller_frame.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <Eigen/LU>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/run.h"
#include "core/io/nc_program.h"

namespace metrofit::machine {
namespace {

constexpr double kRadToDeg = 57.295779513082320876798154814105;
/// Below this |sin| of the middle angle the first angle is set to 0 (gimbal lock); the last angle
/// is then computed from what remains, so the written angles rebuild R whatever the branch.
constexpr double kGimbal = 1e-12;

std::string number(double v, int decimals, bool plus) {
  const double scale = std::pow(10.0, decimals);
  double r = std::round(v * scale) / scale;
  if (r == 0.0) r = 0.0;  // no "-0"
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, plus ? "%+.*f" : "%.*f", decimals, r);
  return buf;
}

std::string printable(const std::string& text, bool upper) {
  std::string out;
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (u < 32 || u > 126) ch = ' ';
    if (upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    out += ch;
  }
  return out;
}

std::string fanucComment(const std::string& text) {
  std::string s = printable(text, true);
  for (char& ch : s) {
    if (ch == '(') ch = '[';
    if (ch == ')') ch = ']';
  }
  return "(" + s + ")";
}

}  // namespace

std::vector<std::string> frameFormatNames() {
  return {"heidenhain", "siemens", "fanuc"};
}

FrameFormat parseFrameFormat(const std::string& name, const std::string& field) {
  if (name == "heidenhain") return FrameFormat::Heidenhain;
  if (name == "siemens") return FrameFormat::Siemens;
  if (name == "fanuc") return FrameFormat::Fanuc;
  throw OptionsError(ErrorContext{{}, 0, 0, field},
                     "unknown frame format '" + name + "' (one of heidenhain, siemens, fanuc)");
}

const char* toString(FrameFormat f) {
  switch (f) {
    case FrameFormat::Heidenhain:
      return "heidenhain";
    case FrameFormat::Siemens:
      return "siemens";
    case FrameFormat::Fanuc:
      return "fanuc";
  }
  return "?";
}

std::array<double, 3> spatialAnglesDeg(const Eigen::Matrix3d& R) {
  // R = Rz(c) Ry(b) Rx(a): first column (cb cc, cb sc, -sb).
  const double h = std::hypot(R(0, 0), R(1, 0));  // |cos b|, taken >= 0: b in [-90, 90]
  const double c = h < kGimbal ? 0.0 : std::atan2(R(1, 0), R(0, 0));
  const double sc = std::sin(c), cc = std::cos(c);
  // Rz(c)^T R = Ry(b) Rx(a) = [[cb, sb sa, sb ca], [0, ca, -sa], [-sb, cb sa, cb ca]].
  const double b = std::atan2(-R(2, 0), cc * R(0, 0) + sc * R(1, 0));
  const double a = std::atan2(sc * R(0, 2) - cc * R(1, 2), cc * R(1, 1) - sc * R(0, 1));
  return {a * kRadToDeg, b * kRadToDeg, c * kRadToDeg};
}

std::array<double, 3> eulerZxzAnglesDeg(const Eigen::Matrix3d& R) {
  // R = Rz(i) Rx(j) Rz(k): third column (si sj, -ci sj, cj).
  const double h = std::hypot(R(0, 2), R(1, 2));  // sin j >= 0: j in [0, 180]
  const double i = h < kGimbal ? 0.0 : std::atan2(R(0, 2), -R(1, 2));
  const double si = std::sin(i), ci = std::cos(i);
  // Rz(i)^T R = Rx(j) Rz(k) = [[ck, -sk, 0], [cj sk, cj ck, -sj], [sj sk, sj ck, cj]].
  const double j = std::atan2(si * R(0, 2) - ci * R(1, 2), R(2, 2));
  const double k = std::atan2(-(ci * R(0, 1) + si * R(1, 1)), ci * R(0, 0) + si * R(1, 0));
  return {i * kRadToDeg, j * kRadToDeg, k * kRadToDeg};
}

bool FrameOptions::isValid(std::string* why) const {
  if (decimals < 0 || decimals > 12) {
    if (why) *why = "the number of decimals must be in 0..12";
    return false;
  }
  const bool nameOk =
      !programName.empty() && programName.size() <= 32 &&
      programName.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-") ==
          std::string::npos;
  if (!nameOk) {
    if (why)
      *why = "the HEIDENHAIN program name '" + programName + "' must be 1..32 letters, digits, '_' or '-'";
    return false;
  }
  return fanucProgramNumberOk(programNumber, why);
}

std::string frameProgramName(const std::string& file) {
  std::string stem = std::filesystem::path(file).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return stem.empty() ? FrameOptions{}.programName : stem.substr(0, 32);
}

namespace {

void requireProperPosture(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  const ErrorContext ctx{{}, 0, 0, "posture"};
  if (!R.allFinite() || !t.allFinite()) throw ValidationError(ctx, "the posture has a non-finite value");
  const double orth = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orth > 1e-9 || R.determinant() < 0.0) {
    throw ValidationError(
        ctx, "the rotation is not a proper rotation (|R^T R - I| = " + number(orth, 12, false) + ", det " +
                 number(R.determinant(), 6, false) + ")");
  }
}

/// The blocks that set the frame (no block numbers), unchecked.
std::vector<std::string> frameBlocks(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, FrameFormat format,
                                     int d) {
  switch (format) {
    case FrameFormat::Heidenhain: {
      const auto a = spatialAnglesDeg(R);
      return {"CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X" + number(t.x(), d, true),
              "CYCL DEF 7.2 Y" + number(t.y(), d, true), "CYCL DEF 7.3 Z" + number(t.z(), d, true),
              "PLANE SPATIAL SPA" + number(a[0], d, true) + " SPB" + number(a[1], d, true) + " SPC" +
                  number(a[2], d, true) + " STAY"};
    }
    case FrameFormat::Siemens: {
      const auto a = spatialAnglesDeg(R);
      return {"TRANS X=" + number(t.x(), d, false) + " Y=" + number(t.y(), d, false) +
                  " Z=" + number(t.z(), d, false),
              "AROT Z=" + number(a[2], d, false), "AROT Y=" + number(a[1], d, false),
              "AROT X=" + number(a[0], d, false)};
    }
    case FrameFormat::Fanuc: {
      const auto e = eulerZxzAnglesDeg(R);
      return {"G68.2 X" + number(t.x(), d, false) + " Y" + number(t.y(), d, false) + " Z" +
              number(t.z(), d, false) + " I" + number(e[0], d, false) + " J" + number(e[1], d, false) + " K" +
              number(e[2], d, false)};
    }
  }
  return {};
}

}  // namespace

std::vector<std::string> controllerFrameBlocks(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                                               FrameFormat format, int decimals) {
  FrameOptions o;
  o.decimals = decimals;
  requireValid(o, "frame options");
  requireProperPosture(R, t);
  return frameBlocks(R, t, format, decimals);
}

std::string writeControllerFrame(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, FrameFormat format,
                                 const FrameOptions& options) {
  requireValid(options, "frame options");
  requireProperPosture(R, t);
  const int d = options.decimals;
  const std::vector<std::string> blocks = frameBlocks(R, t, format, d);
  const std::string title = printable(options.title, false);
  std::string out;
  auto line = [&](const std::string& s) { out += s + "\n"; };

  switch (format) {
    case FrameFormat::Heidenhain: {
      int n = 0;
      auto block = [&](const std::string& s) { line(std::to_string(n++) + " " + s); };
      block("BEGIN PGM " + options.programName + " MM");
      block("; Metrofit posture correction as a tilted working plane" + (title.empty() ? "" : ": " + title));
      block("; Datum shift (mm) then PLANE SPATIAL: R = Rz(SPC) Ry(SPB) Rx(SPA), rotations about");
      block("; the non-tilted X, Y, Z in the order A, B, C; positive by the right-hand rule.");
      block("; CALL PGM after the preset of the part is active; the shift and the plane stay");
      block("; active. STAY: the rotary axes are not moved. Reset: PLANE RESET STAY, datum shift 0.");
      block("; The scale of a fit is not applied.");
      for (const std::string& b : blocks) block(b);
      block("END PGM " + options.programName + " MM");
      break;
    }
    case FrameFormat::Siemens: {
      line("; Metrofit posture correction as a programmable frame" + (title.empty() ? "" : ": " + title));
      line("; TRANS (mm) on top of the active settable frame, then AROT about the rotated Z, Y', X''");
      line("; (one axis per block, independent of MD 10600 $MN_FRAME_ANGLE_INPUT_MODE):");
      line("; R = Rz(Z) Ry(Y) Rx(X), positive by the right-hand rule. Call after G54 ...; the frame");
      line("; stays active after M17; TRANS without values resets it. The tool is not oriented:");
      line("; use CYCLE800 or TRAORI for that. The scale of a fit is not applied.");
      for (const std::string& b : blocks) line(b);
      line("M17");
      break;
    }
    case FrameFormat::Fanuc: {
      std::string o = std::to_string(options.programNumber);
      o = std::string(o.size() < 4 ? 4 - o.size() : 0, '0') + o;
      line("%");
      line("O" + o + " " + fanucComment("METROFIT POSTURE FRAME"));
      if (!title.empty()) line(fanucComment(title));
      line(fanucComment("G68.2 EULER ANGLES: I ABOUT Z, J ABOUT NEW X, K ABOUT NEW Z, DEG"));
      line(fanucComment("X Y Z: ORIGIN IN THE CURRENT WORK OFFSET, MM. CANCEL WITH G69"));
      line(fanucComment("G53.1 NOT WRITTEN: IT MOVES THE ROTARY AXES. SCALE NOT APPLIED"));
      line("G21");
      for (const std::string& b : blocks) line(b);
      line("M99");
      line("%");
      break;
    }
  }
  return out;
}

}  // namespace metrofit::machine
