#include "core/sim/probe_sim.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

const char* toString(ProbeShape shape) {
  return shape == ProbeShape::SPiece ? "s-piece" : "block";
}

ProbeShape parseProbeShape(const std::string& name, const std::string& field) {
  for (ProbeShape s : {ProbeShape::Block, ProbeShape::SPiece}) {
    if (name == toString(s)) return s;
  }
  throw OptionsError(ErrorContext{{}, 0, 0, field}, "unknown shape '" + name + "' (one of block, s-piece)");
}

ProbeSimOptions ProbeSimOptions::sPieceDefaults() {
  ProbeSimOptions o;
  o.shape = ProbeShape::SPiece;
  o.rotationDeg[0] = -0.29;
  o.rotationDeg[1] = -0.46;
  o.rotationDeg[2] = -0.52;
  o.translationMm[0] = 1.73;
  o.translationMm[1] = -0.23;
  o.translationMm[2] = 1.57;
  o.noiseMm = 0.006;
  return o;
}

bool ProbeSimOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(length > 0.0 && width > 0.0 && height > 0.0)) return no("block dimensions must be positive");
  for (double a : rotationDeg) {
    if (!std::isfinite(a) || std::abs(a) > 45.0)
      return no("rotation angles must be finite and within +-45 deg");
  }
  for (double t : translationMm) {
    if (!std::isfinite(t)) return no("translation must be finite");
  }
  if (!(noiseMm >= 0.0)) return no("noise must not be negative");
  return true;
}

Eigen::Matrix3d rotationFromDeg(double rx, double ry, double rz) {
  const double k = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(rz * k, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(ry * k, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rx * k, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

namespace {

using AddPoint = std::function<void(const char*, const Eigen::Vector3d&, const Eigen::Vector3d&)>;

void probeBlock(const ProbeSimOptions& o, const AddPoint& add) {
  const double L = o.length, W = o.width, H = o.height;
  // Top face: 5 x 3 grid, 10 % margin.
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      add("top", {L * (0.1 + 0.2 * i), W * (0.2 + 0.3 * j), H}, Eigen::Vector3d::UnitZ());
  // Front face (y = 0): 4 x 2.
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 2; ++k)
      add("front", {L * (0.125 + 0.25 * i), 0.0, H * (0.3 + 0.4 * k)}, -Eigen::Vector3d::UnitY());
  // Right face (x = L): 3 x 2.
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 2; ++k)
      add("right", {L, W * (0.2 + 0.3 * j), H * (0.3 + 0.4 * k)}, Eigen::Vector3d::UnitX());
  // Left face (x = 0): 3 x 2.
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 2; ++k)
      add("left", {0.0, W * (0.2 + 0.3 * j), H * (0.3 + 0.4 * k)}, -Eigen::Vector3d::UnitX());
}

// The S-piece geometry of the header comment.
constexpr double kWallHeight = 40.0;
constexpr double kHalfThickness = 1.5;
constexpr double kHoleRadius = 12.0;
constexpr double kHoleProbeZ = -8.0;

double bottomCurve(double x) {
  return 70.0 + 40.0 * std::sin(std::numbers::pi * (x - 160.0) / 100.0);
}
double bottomSlope(double x) {
  return 40.0 * std::numbers::pi / 100.0 * std::cos(std::numbers::pi * (x - 160.0) / 100.0);
}
double topCurve(double x) {
  return 70.0 + 30.0 * std::sin(std::numbers::pi * (x - 160.0) / 100.0 + 0.3);
}
double topSlope(double x) {
  return 30.0 * std::numbers::pi / 100.0 * std::cos(std::numbers::pi * (x - 160.0) / 100.0 + 0.3);
}

void probeSPiece(const AddPoint& add) {
  // Plane: the base's top face, away from the wall and the holes.
  const double plane[8][2] = {{15, 15},  {100, 12},  {200, 12},  {305, 15},
                              {15, 128}, {120, 128}, {220, 128}, {305, 128}};
  for (const auto& xy : plane) add("plane", {xy[0], xy[1], 0.0}, Eigen::Vector3d::UnitZ());
  // Holes: the normal points to the axis (out of the material into the hole).
  const double holes[2][2] = {{35.0, 105.0}, {285.0, 35.0}};
  const char* holeNames[2] = {"hole1", "hole2"};
  for (int h = 0; h < 2; ++h) {
    for (int k = 0; k < 4; ++k) {
      const double a = std::numbers::pi / 4.0 + k * std::numbers::pi / 2.0;
      const Eigen::Vector3d radial(std::cos(a), std::sin(a), 0.0);
      add(holeNames[h], Eigen::Vector3d(holes[h][0], holes[h][1], kHoleProbeZ) + kHoleRadius * radial,
          -radial);
    }
  }
  // Ruled surfaces: the two sides of the twisted S wall.
  const double xs[6] = {75, 110, 145, 175, 210, 245};
  for (int side : {+1, -1}) {
    for (double x : xs) {
      for (double v : {0.3, 0.8}) {
        const double yb = bottomCurve(x), yt = topCurve(x);
        const Eigen::Vector3d point(x, (1.0 - v) * yb + v * yt + side * kHalfThickness, kWallHeight * v);
        const Eigen::Vector3d rx(1.0, (1.0 - v) * bottomSlope(x) + v * topSlope(x), 0.0);
        const Eigen::Vector3d rv(0.0, yt - yb, kWallHeight);
        // r_x x r_v has y component -H < 0: it points to -y; the +y side's outward normal is its negative.
        const Eigen::Vector3d n = -side * rx.cross(rv).normalized();
        add(side > 0 ? "ruled+" : "ruled-", point, n);
      }
    }
  }
}

}  // namespace

ProbePointSet simulateProbing(const ProbeSimOptions& o) {
  requireValid(o, "probe simulation");
  Rng rng(o.seed);
  ProbePointSet set;
  set.source = o.shape == ProbeShape::SPiece ? "simulated probing (S-piece)" : "simulated probing";
  set.hasNormals = true;
  const Eigen::Matrix3d R = rotationFromDeg(o.rotationDeg[0], o.rotationDeg[1], o.rotationDeg[2]);
  const Eigen::Vector3d t(o.translationMm[0], o.translationMm[1], o.translationMm[2]);
  int counter = 0;
  const AddPoint add = [&](const char* surface, const Eigen::Vector3d& q, const Eigen::Vector3d& n) {
    ProbePoint p;
    char id[16];
    metrofit::c_snprintf(id, sizeof id, "P%03d", ++counter);
    p.id = id;
    p.surface = surface;
    p.nominal = q;
    p.normal = n;
    p.measured = R * q + t + n * rng.normal(0.0, o.noiseMm);
    set.points.push_back(std::move(p));
  };
  if (o.shape == ProbeShape::SPiece) {
    probeSPiece(add);
  } else {
    probeBlock(o, add);
  }
  return set;
}

}  // namespace metrofit
