#include "core/sim/effects_matching.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

bool MatchingEffects::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!std::isfinite(scalePpm)) return no("the scale must be finite");
  if (!std::isfinite(distortionPpm) || !std::isfinite(distortionAngleDeg))
    return no("the distortion must be finite");
  for (const auto& [surface, mm] : surfaceOffsetsMm)
    if (!std::isfinite(mm)) return no("surface offsets must be finite");
  return true;
}

Eigen::Vector3d effectDisplacement(const MatchingEffects& e, const ProbePoint& point) {
  const Eigen::Vector3d& q = point.nominal;
  Eigen::Vector3d d = 1e-6 * e.scalePpm * q;
  for (const auto& [surface, mm] : e.surfaceOffsetsMm)
    if (surface == point.surface) d += mm * point.normal;
  if (e.distortionPpm != 0.0) {
    const double a = 2.0 * e.distortionAngleDeg * std::numbers::pi / 180.0;
    const double c = e.distortionPpm * std::cos(a), s = e.distortionPpm * std::sin(a);
    d.x() += 1e-6 * (c * q.x() + s * q.y());
    d.y() += 1e-6 * (s * q.x() - c * q.y());
  }
  return d;
}

void addMatchingEffects(ProbePointSet& set, const Eigen::Matrix3d& R, const MatchingEffects& effects) {
  requireValid(effects, "matching effects");
  std::set<std::string> surfaces;
  for (const ProbePoint& p : set.points) surfaces.insert(p.surface);
  for (const auto& [surface, mm] : effects.surfaceOffsetsMm) {
    if (!set.hasNormals)
      throw OptionsError(ErrorContext{{}, 0, 0, "surface_offset:" + surface},
                         "surface offsets need points with normals");
    if (!surfaces.count(surface))
      throw OptionsError(ErrorContext{{}, 0, 0, "surface_offset:" + surface},
                         "the point set has no surface '" + surface + "'");
  }
  for (ProbePoint& p : set.points) {
    Eigen::Vector3d d = effectDisplacement(effects, p);
    if (set.planar) d.z() = 0.0;
    p.measured += R * d;
  }
}

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
    std::snprintf(id, sizeof id, "H%03d", i + 1);
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
