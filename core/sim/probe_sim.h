#pragma once
// Simulated contact probing of a prismatic workpiece (the simulator plays machine and probe).
//
// A block of size L x W x H (mm) with its origin at a corner, probed on the top face (+Z normal),
// the front face (-Y), the right face (+X) and the left face (-X) on regular grids. The workpiece's
// actual posture is p = R q + t with R = Rz(rz) Ry(ry) Rx(rx) (CONTRACT.md "match"), plus form /
// probing noise along the nominal normal (sigma in mm). Deterministic by seed.
#include <cstdint>

#include "core/matching/probe_points.h"

namespace metrofit {

struct ProbeSimOptions {
  double length = 200.0, width = 120.0, height = 60.0;  ///< block size, mm
  double rotationDeg[3] = {0.02, -0.015, 0.05};         ///< rx, ry, rz of the actual posture
  double translationMm[3] = {0.12, -0.08, 0.05};        ///< t of the actual posture
  double noiseMm = 0.002;                               ///< along the normal, 1 sigma
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

/// Rotation R = Rz(rz) Ry(ry) Rx(rx) from angles in degrees.
Eigen::Matrix3d rotationFromDeg(double rxDeg, double ryDeg, double rzDeg);

ProbePointSet simulateProbing(const ProbeSimOptions& options);

}  // namespace metrofit
