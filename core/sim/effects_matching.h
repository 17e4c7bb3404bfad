#pragma once
// Simulated probe point sets with matching effects the declared model (a rigid posture error) lacks
// (issue 8 item 4): the test data of the matching diagnosis (core/diagnose/matching_diagnosis.h).
//
// The effects deform the part in its own (nominal) frame before the posture p = R q + t acts:
//   p = R (q + d(q)) + t + noise,
//   scale                     d = 1e-6 ppm q                 (isotropic, about the part's origin)
//   surface_offset:<surface>  d = mm n  on that surface      (along the nominal normal n, + = outward)
//   distortion                d = 1e-6 ppm (c x - ... )      in-plane: a stretch by +ppm along
//                             angle_deg and -ppm across it, D = ppm [[cos 2a, sin 2a], [sin 2a, -cos 2a]]
//                             acting on (x, y), z unchanged (a drilling machine's four-lobed error).
// Two sources of points:
//   * simulateProbingWithEffects composes core/sim/probe_sim.h: simulateProbing (block or S-piece,
//     posture, noise along the normal) and then adds R d(q) to every measured point;
//   * simulateHolePlate makes a planar, position-only hole pattern like a drilled plate (e.g. the
//     SDSS plug plates: holes uniform in a disc), posture rz, (tx, ty), isotropic noise per axis.
// Deterministic by seed.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/matching/probe_points.h"
#include "core/sim/probe_sim.h"

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

/// simulateProbing(base) plus the effects.
ProbePointSet simulateProbingWithEffects(const ProbeSimOptions& base, const MatchingEffects& effects);

struct HolePlateSimOptions {
  int holes = 600;                          ///< hole count
  double radiusMm = 300.0;                  ///< holes uniform in the disc of this radius about 0
  double rotationDeg = 0.01;                ///< rz of the posture
  double translationMm[2] = {0.05, -0.03};  ///< tx, ty
  double noiseMm = 0.006;                   ///< per axis, 1 sigma
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

/// A planar, position-only set (ids H001..., surface "hole").
ProbePointSet simulateHolePlate(const HolePlateSimOptions& options, const MatchingEffects& effects);

}  // namespace metrofit
