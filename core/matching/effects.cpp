#include "core/matching/effects.h"

#include <cmath>
#include <numbers>
#include <set>

#include "core/common/error.h"
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

}  // namespace metrofit
