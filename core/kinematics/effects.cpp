#include "core/kinematics/effects.h"

#include <cmath>
#include <numbers>

namespace metrofit {

PathMotion pathMotion(const std::vector<Eigen::Vector2d>& c) {
  const std::size_t n = c.size();
  PathMotion m;
  m.direction.assign(n, Eigen::Vector2d(1.0, 1.0));
  m.tangent.assign(n, Eigen::Vector2d::Zero());
  if (n < 2) return m;
  // Axis directions: sign of the last non-zero move; before the first move, that move's sign.
  for (int axis = 0; axis < 2; ++axis) {
    double first = 0.0;
    for (std::size_t k = 1; k < n && first == 0.0; ++k) {
      const double d = c[k](axis) - c[k - 1](axis);
      if (d != 0.0) first = d > 0.0 ? 1.0 : -1.0;
    }
    double cur = first == 0.0 ? 1.0 : first;
    m.direction[0](axis) = cur;
    for (std::size_t k = 1; k < n; ++k) {
      const double d = c[k](axis) - c[k - 1](axis);
      if (d != 0.0) cur = d > 0.0 ? 1.0 : -1.0;
      m.direction[k](axis) = cur;
    }
  }
  auto unit = [](const Eigen::Vector2d& v) -> Eigen::Vector2d {
    const double len = v.norm();
    return len > 0.0 ? Eigen::Vector2d(v / len) : Eigen::Vector2d::Zero();
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d in = k > 0 ? Eigen::Vector2d(c[k] - c[k - 1]) : Eigen::Vector2d::Zero();
    const Eigen::Vector2d out = k + 1 < n ? Eigen::Vector2d(c[k + 1] - c[k]) : Eigen::Vector2d::Zero();
    if (k == 0)
      m.tangent[k] = unit(out);
    else if (k + 1 == n)
      m.tangent[k] = unit(in);
    else if (in.dot(out) < 0.0)
      m.tangent[k] = unit(in);
    else
      m.tangent[k] = unit(unit(in) + unit(out));
  }
  return m;
}

bool KinematicEffects::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  for (double v :
       {backlashXMm, backlashYMm, scaleXPpm, scaleYPpm, cyclicAmplitudeMm, cyclicPhaseDeg, servoLagS})
    if (!std::isfinite(v)) return no("effect parameters must be finite");
  if (cyclicAxis != 'x' && cyclicAxis != 'y') return no("cyclic axis must be 'x' or 'y'");
  if (!(cyclicPeriodMm > 0.0) || !std::isfinite(cyclicPeriodMm)) return no("cyclic period must be positive");
  if (!(feedMmPerMin > 0.0) || !std::isfinite(feedMmPerMin)) return no("feed must be positive");
  return true;
}

Eigen::Vector2d KinematicEffects::effectiveJoints(const Eigen::Vector2d& c, const Eigen::Vector2d& d,
                                                  const Eigen::Vector2d& t) const {
  const double v = feedMmPerMin / 60.0;
  Eigen::Vector2d e;
  e.x() = c.x() * (1.0 + scaleXPpm * 1e-6) - d.x() * backlashXMm / 2.0 - servoLagS * v * t.x();
  e.y() = c.y() * (1.0 + scaleYPpm * 1e-6) - d.y() * backlashYMm / 2.0 - servoLagS * v * t.y();
  if (cyclicAmplitudeMm != 0.0) {
    const int a = cyclicAxis == 'x' ? 0 : 1;
    e(a) += cyclicAmplitudeMm * std::sin(2.0 * std::numbers::pi * c(a) / cyclicPeriodMm +
                                         cyclicPhaseDeg * std::numbers::pi / 180.0);
  }
  return e;
}

}  // namespace metrofit
