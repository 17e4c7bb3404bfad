#pragma once
// Effects that deform a part in its own (nominal) frame, beyond the rigid posture error of the
// matching model, before the posture p = R q + t acts:
//   p = R (q + d(q)) + t + noise,
//   scale                     d = 1e-6 ppm q                 (isotropic, about the part's origin)
//   surface_offset:<surface>  d = mm n  on that surface      (along the nominal normal n, + = outward)
//   distortion                d = 1e-6 ppm (c x - ... )      in-plane: a stretch by +ppm along
//                             angle_deg and -ppm across it, D = ppm [[cos 2a, sin 2a], [sin 2a, -cos 2a]]
//                             acting on (x, y), z unchanged (a drilling machine's four-lobed error).
// Used by the simulator (core/sim/effects_matching.h), the closed loop and an applied effect alike.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/matching/probe_points.h"

namespace metrofit {

struct MatchingEffects {
  double scalePpm = 0.0;
  std::vector<std::pair<std::string, double>> surfaceOffsetsMm;  ///< surface -> mm along the normal
  double distortionPpm = 0.0;
  double distortionAngleDeg = 0.0;

  bool isValid(std::string* why) const;
};

/// d(q) of the header for one point (normal may be zero for position-only points).
Eigen::Vector3d effectDisplacement(const MatchingEffects& effects, const ProbePoint& point);

/// Adds R d(q) to every measured point. OptionsError when a surface offset names a surface the set
/// does not have, or the set has no normals.
void addMatchingEffects(ProbePointSet& set, const Eigen::Matrix3d& R, const MatchingEffects& effects);

}  // namespace metrofit
