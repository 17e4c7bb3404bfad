#include "core/sim/probe_sim.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

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

ProbePointSet simulateProbing(const ProbeSimOptions& o) {
  requireValid(o, "probe simulation");
  Rng rng(o.seed);
  ProbePointSet set;
  set.source = "simulated probing";
  set.hasNormals = true;
  const Eigen::Matrix3d R = rotationFromDeg(o.rotationDeg[0], o.rotationDeg[1], o.rotationDeg[2]);
  const Eigen::Vector3d t(o.translationMm[0], o.translationMm[1], o.translationMm[2]);
  int counter = 0;
  auto add = [&](const char* surface, const Eigen::Vector3d& q, const Eigen::Vector3d& n) {
    ProbePoint p;
    char id[16];
    std::snprintf(id, sizeof id, "P%03d", ++counter);
    p.id = id;
    p.surface = surface;
    p.nominal = q;
    p.normal = n;
    p.measured = R * q + t + n * rng.normal(0.0, o.noiseMm);
    set.points.push_back(std::move(p));
  };
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
  return set;
}

}  // namespace metrofit
