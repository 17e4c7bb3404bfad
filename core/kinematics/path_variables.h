#pragma once
// The variables a kinematic residual may depend on (docs/file-formats.md#residual_check, `against`), on every
// point of a path of commands. The closed loop (core/diagnose/kinematic_diagnosis.h) tests its residual
// against them and fits generic effects of them; an applied generic effect (applied_kinematic.h) is
// evaluated on them, so both see the same values:
//   row        1-based point number (path order)
//   angle      path angle about the commands' centroid, degrees in [0, 360)
//   direction  0 where the motion turns counter-clockwise about the centroid (CCW), 1 clockwise (CW)
//   reversal   sign(new direction) ln(1 + samples since the axis that reversed last reversed)
//   x, y       the commanded coordinates (mm)
#include <string>
#include <vector>

#include <Eigen/Core>

namespace metrofit {

struct PathVariables {
  std::vector<double> row, angle, direction, reversal, x, y;
  std::vector<Eigen::Vector2d> radial;  ///< unit vectors from the centroid (the angle's direction)
  bool bothDirections = false;          ///< the path runs both CCW and CW

  /// The values of `name` (one of the names above), or nullptr for another name.
  const std::vector<double>* find(const std::string& name) const;
};

/// The variables of a path (empty for an empty path).
PathVariables pathVariables(const std::vector<Eigen::Vector2d>& commands);

}  // namespace metrofit
