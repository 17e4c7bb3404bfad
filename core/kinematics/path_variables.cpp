#include "core/kinematics/path_variables.h"

#include <cmath>
#include <numbers>

#include "core/kinematics/effects.h"

namespace metrofit {

const std::vector<double>* PathVariables::find(const std::string& name) const {
  if (name == "row") return &row;
  if (name == "angle") return &angle;
  if (name == "direction") return &direction;
  if (name == "reversal") return &reversal;
  if (name == "x") return &x;
  if (name == "y") return &y;
  return nullptr;
}

PathVariables pathVariables(const std::vector<Eigen::Vector2d>& commands) {
  PathVariables v;
  const std::size_t n = commands.size();
  if (n == 0) return v;
  const PathMotion motion = pathMotion(commands);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : commands) c += p;
  c /= static_cast<double>(n);
  long since[2] = {0, 0};
  bool ccw = false, cw = false;
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d d = commands[k] - c;
    const Eigen::Vector2d u = d.norm() > 0.0 ? Eigen::Vector2d(d / d.norm()) : Eigen::Vector2d::UnitX();
    v.radial.push_back(u);
    v.row.push_back(static_cast<double>(k + 1));
    double a = std::atan2(u.y(), u.x()) / (std::numbers::pi / 180.0);
    if (a < 0.0) a += 360.0;
    v.angle.push_back(a);
    const Eigen::Vector2d& t = motion.tangent[k];
    const double cross = u.x() * t.y() - u.y() * t.x();
    v.direction.push_back(cross >= 0.0 ? 0.0 : 1.0);
    (cross >= 0.0 ? ccw : cw) = true;
    for (int axis = 0; axis < 2; ++axis) {
      if (k > 0 && motion.direction[k](axis) != motion.direction[k - 1](axis))
        since[axis] = 0;
      else if (k > 0)
        ++since[axis];
    }
    // Signed and on a log scale: a reversal glitch decays within a few samples and its sign follows
    // the new direction of the axis that reversed last.
    const int last = since[0] <= since[1] ? 0 : 1;
    v.reversal.push_back(motion.direction[k](last) * std::log1p(static_cast<double>(since[last])));
    v.x.push_back(commands[k].x());
    v.y.push_back(commands[k].y());
  }
  v.bothDirections = ccw && cw;
  return v;
}

}  // namespace metrofit
