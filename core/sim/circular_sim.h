#pragma once
// Simulated circular test on a Cartesian XY machine (the simulator plays machine and measuring
// instrument, e.g. a ballbar or a grid encoder). Lengths in mm, angles in degrees.
//
// Commands: one loop counter-clockwise and then one clockwise (docs/file-formats.md#circular-test), each
// of `pointsPerLoop` points on the circle of radius R about the centre c, without repeating the
// start point:
//   CCW  Pr_k = c + R (cos t_k, sin t_k),  t_k = t0 + 2 pi k / n,  k = 0..n-1
//   CW   Pr_k = c + R (cos t_k, sin t_k),  t_k = t0 - 2 pi k / n,  k = 0..n-1
// Machine: the direct kinematics of the kinematic-compensation paper (IEEE Access, kinematic compensation
// algorithm, Eq. 9) with the actuator errors of docs/file-formats.md#kinematic-identify-result, P = o + (cos
// a, sin a) Pr_x + (-sin b, cos b) Pr_y, and measurement noise N(0, noise^2) added independently to x and y.
// Deterministic by seed (metrofit::Rng).
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification3.h"
#include "core/kinematics/measured_path.h"
#include "core/kinematics/spc_actuator.h"

namespace metrofit {

struct CircularSimOptions {
  double radiusMm = 100.0;
  Eigen::Vector2d centreMm = Eigen::Vector2d::Zero();
  int pointsPerLoop = 360;
  double startAngleDeg = 0.0;  ///< t0
  ActuatorErrors2 errors = defaultErrors();
  double noiseMm = 0.0005;  ///< 1 sigma per coordinate
  std::uint64_t seed = 1;

  /// A plausible machine: origin (4, -3) um, X axis +0.0006 deg (about 2 arcsec), Y axis
  /// -0.0020 deg: squareness b - a = -0.0026 deg (about 45 um/m).
  static ActuatorErrors2 defaultErrors();
  bool isValid(std::string* why) const;
};

/// The commands of the test: one CCW loop, then one CW loop (2 * pointsPerLoop points).
std::vector<Eigen::Vector2d> circularTestCommands(const CircularSimOptions& options);

/// Runs commands through the simulated machine: Eq. 9 with `errors`, plus N(0, noise^2) per
/// coordinate drawn from Rng(seed). noiseMm = 0 gives the modelled path exactly.
std::vector<Eigen::Vector2d> simulateMachine(const ActuatorErrors2& errors,
                                             const std::vector<Eigen::Vector2d>& commands, double noiseMm,
                                             std::uint64_t seed);

/// The whole test: commands and measured positions (source "simulated circular test").
MeasuredPath simulateCircularTest(const CircularSimOptions& options);

/// A circular test in the XY, YZ or ZX plane of the three-axis machine (identification3.h):
/// circularTestCommands(options) taken as the plane's (u, v) commands (third coordinate 0), the
/// machine P = o + [i j k] Pr with `errors` (options.errors is not used), and the measured (u, v)
/// plus N(0, noise^2) per coordinate drawn from Rng(options.seed). Source "simulated <plane>
/// circular test".
MeasuredPath simulatePlaneCircularTest(const ActuatorErrors3& errors, TestPlane plane,
                                       const CircularSimOptions& options);

/// A straight edge machined along one axis and measured (the feature series of spc_actuator.h):
/// commands (s_k, c) for axis 'x' or (c, s_k) for 'y', s_k = startMm + lengthMm k / (points - 1),
/// c = nominalCrossMm, through simulateMachine; position = the measured coordinate along the axis,
/// deviation = the measured cross coordinate - c.
struct EdgeSimOptions {
  char axis = 'x';
  double startMm = -100.0;
  double lengthMm = 200.0;
  int points = 50;
  double nominalCrossMm = 0.0;
  ActuatorErrors2 errors = CircularSimOptions::defaultErrors();
  double noiseMm = 0.0005;
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

AxisFeatureSeries simulateAxisFeature(const EdgeSimOptions& options);
/// CSV position_mm,deviation_mm.
std::string axisFeatureToCsv(const AxisFeatureSeries& series);

}  // namespace metrofit
