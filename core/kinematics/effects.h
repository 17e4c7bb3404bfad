#pragma once
// Effects of the axes themselves on a Cartesian machine, beyond the actuator origin and orientation
// errors of cartesian_model.h; they act on the joint (actuator) coordinates before the machine's
// geometry (lengths mm, times s, feed mm/min):
//   x_eff = x (1 + sx 1e-6) - d_x bx / 2 - tau v_x + [axis x] A sin(2 pi x / p + phi)
//   y_eff = y (1 + sy 1e-6) - d_y by / 2 - tau v_y + [axis y] A sin(2 pi y / p + phi)
// with
//   `backlash` bx, by: the full lost motion at a reversal; d = +1 / -1 is the direction of the
//          axis' last move (a point reached moving in +x lags by bx / 2),
//   `scale`   sx, sy in ppm (scale error of the axis' measuring system),
//   `cyclic`  on one axis: period p (mm, e.g. the ball-screw lead) and amplitude A (mm), phase phi,
//   `servo_lag` tau (s): the steady-state first-order servo response P_cmd - tau dP_cmd/dt to first
//          order in omega tau, with the commanded velocity v = feed / 60 along the path tangent.
// Direction and velocity of every point come from the command sequence alone (pathMotion), so the
// simulator (core/sim/effects_kinematic.h), the closed loop and an applied effect read a path alike.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace metrofit {

/// The feed of a circular test when none is given (mm/min): the simulator, the effects, the exports and
/// the closed loop all start from it.
inline constexpr double kDefaultFeedMmPerMin = 1000.0;

/// Per point of a command path: the direction of each axis' last move (+1 / -1; the first point
/// takes the direction of the first move of the axis) and the unit tangent of the motion through it
/// (central difference; the incoming move at a reversal of the path, where the incoming and
/// outgoing moves point against each other; a one-sided difference at the ends).
struct PathMotion {
  std::vector<Eigen::Vector2d> direction;  ///< d_x, d_y in {-1, +1}
  std::vector<Eigen::Vector2d> tangent;    ///< unit vectors (zero where the tool does not move)
};
PathMotion pathMotion(const std::vector<Eigen::Vector2d>& commands);

struct KinematicEffects {
  double backlashXMm = 0.0, backlashYMm = 0.0;  ///< `backlash`: full lost motion
  double scaleXPpm = 0.0, scaleYPpm = 0.0;      ///< `scale`
  char cyclicAxis = 'x';                        ///< `cyclic`: 'x' or 'y'
  double cyclicPeriodMm = 10.0;
  double cyclicAmplitudeMm = 0.0;  ///< 0: no cyclic error
  double cyclicPhaseDeg = 0.0;
  double servoLagS = 0.0;  ///< `servo_lag` tau
  double feedMmPerMin = kDefaultFeedMmPerMin;

  bool isValid(std::string* why) const;
  /// The joint coordinates the axes actually reach (see the header comment) for command k.
  Eigen::Vector2d effectiveJoints(const Eigen::Vector2d& command, const Eigen::Vector2d& direction,
                                  const Eigen::Vector2d& tangent) const;
};

}  // namespace metrofit
