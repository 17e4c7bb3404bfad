#pragma once
// Simulated probe point sets with the matching effects of core/matching/effects.h, which the
// declared model (a rigid posture error) lacks: the test data of the matching diagnosis
// (core/diagnose/matching_diagnosis.h). Two sources of points:
//   * simulateProbingWithEffects composes core/sim/probe_sim.h: simulateProbing (block or S-piece,
//     posture, noise along the normal) and then adds R d(q) to every measured point;
//   * simulateHolePlate makes a planar, position-only hole pattern like a drilled plate (e.g. the
//     SDSS plug plates: holes uniform in a disc), posture rz, (tx, ty), isotropic noise per axis.
// Deterministic by seed.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/matching/effects.h"
#include "core/matching/probe_points.h"
#include "core/sim/probe_sim.h"

namespace metrofit {

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
