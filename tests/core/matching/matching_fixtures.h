#pragma once
// Shared test data for the matching tests: simulated probe sets and small hand-built sets.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/matching/pose.h"
#include "core/matching/probe_points.h"
#include "core/sim/probe_sim.h"

namespace metrofit::test {

/// The simulator's block (40 points, 4 faces with normals) with a chosen posture and noise.
inline ProbePointSet simulatedBlock(double rx, double ry, double rz, Eigen::Vector3d t, double noiseMm,
                                    std::uint64_t seed = 1) {
  ProbeSimOptions o;
  o.rotationDeg[0] = rx;
  o.rotationDeg[1] = ry;
  o.rotationDeg[2] = rz;
  o.translationMm[0] = t.x();
  o.translationMm[1] = t.y();
  o.translationMm[2] = t.z();
  o.noiseMm = noiseMm;
  o.seed = seed;
  return simulateProbing(o);
}

/// A set from nominal points with measured = pose(nominal) (+ an optional per-point offset).
inline ProbePointSet setFrom(const std::vector<Eigen::Vector3d>& nominal, const matching::Pose& pose,
                             const std::vector<Eigen::Vector3d>& normals = {},
                             const std::vector<Eigen::Vector3d>& offsets = {}) {
  ProbePointSet s;
  s.source = "test.csv";
  s.hasNormals = !normals.empty();
  for (std::size_t i = 0; i < nominal.size(); ++i) {
    ProbePoint p;
    p.id = "P" + std::to_string(i + 1);
    p.surface = i % 2 ? "odd" : "even";
    p.nominal = nominal[i];
    if (s.hasNormals) p.normal = normals[i];
    p.measured = pose.apply(nominal[i]) + (offsets.empty() ? Eigen::Vector3d::Zero() : offsets[i]);
    s.points.push_back(p);
  }
  return s;
}

/// Removes the position-only information: a copy of `set` without normals.
inline ProbePointSet withoutNormals(ProbePointSet set) {
  set.hasNormals = false;
  for (auto& p : set.points) p.normal = Eigen::Vector3d::Zero();
  return set;
}

/// Largest absolute difference of two rotations' angles (deg) and translations (mm).
inline double poseDistance(const matching::Pose& a, const matching::Pose& b) {
  return std::max((a.anglesDeg() - b.anglesDeg()).cwiseAbs().maxCoeff(),
                  (a.translation - b.translation).cwiseAbs().maxCoeff());
}

}  // namespace metrofit::test
