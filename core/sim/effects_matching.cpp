#include "core/sim/effects_matching.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

ProbePointSet simulateProbingWithEffects(const ProbeSimOptions& base, const MatchingEffects& effects) {
  ProbePointSet set = simulateProbing(base);
  addMatchingEffects(set, rotationFromDeg(base.rotationDeg[0], base.rotationDeg[1], base.rotationDeg[2]),
                     effects);
  return set;
}

bool HolePlateSimOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (holes < 3 || holes > 1000000) return no("the hole count must be in 3..1000000");
  if (!(radiusMm > 0.0) || !std::isfinite(radiusMm)) return no("the plate radius must be positive");
  if (!std::isfinite(rotationDeg) || std::abs(rotationDeg) > 45.0)
    return no("the rotation must be within +-45 deg");
  if (!std::isfinite(translationMm[0]) || !std::isfinite(translationMm[1]))
    return no("the translation must be finite");
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm)) return no("the noise must be >= 0");
  return true;
}

ProbePointSet simulateHolePlate(const HolePlateSimOptions& o, const MatchingEffects& effects) {
  requireValid(o, "hole plate simulation");
  requireValid(effects, "matching effects");
  Rng rng(o.seed);
  ProbePointSet set;
  set.source = "simulated hole plate";
  set.planar = true;
  set.hasNormals = false;
  const Eigen::Matrix3d R = rotationFromDeg(0.0, 0.0, o.rotationDeg);
  const Eigen::Vector3d t(o.translationMm[0], o.translationMm[1], 0.0);
  for (int i = 0; i < o.holes; ++i) {
    const double r = o.radiusMm * std::sqrt(rng.uniform());
    const double phi = 2.0 * std::numbers::pi * rng.uniform();
    ProbePoint p;
    char id[16];
    metrofit::c_snprintf(id, sizeof id, "H%03d", i + 1);
    p.id = id;
    p.surface = "hole";
    // Drill-file coordinates to 0.001 mm.
    p.nominal = Eigen::Vector3d(std::round(r * std::cos(phi) * 1000.0) / 1000.0,
                                std::round(r * std::sin(phi) * 1000.0) / 1000.0, 0.0);
    p.measured = R * p.nominal + t;
    set.points.push_back(std::move(p));
  }
  addMatchingEffects(set, R, effects);
  for (ProbePoint& p : set.points) {
    p.measured.x() += rng.normal(0.0, o.noiseMm);
    p.measured.y() += rng.normal(0.0, o.noiseMm);
  }
  return set;
}

}  // namespace metrofit
