#pragma once
// Circular tests and measured paths with undeclared effects, for the closed loop: the declared
// model is the Cartesian machine of cartesian_model.h (actuator origin and orientation errors); the
// simulator adds the axis effects of core/kinematics/effects.h (backlash, scale, cyclic, servo lag)
// and white noise:  P = o + ir(a) x_eff + jr(b) y_eff + N(0, noise^2) per coordinate.
// Deterministic by seed.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/measured_path.h"
#include "core/sim/circular_sim.h"

namespace metrofit {

struct KinematicEffectsOptions {
  CircularSimOptions circle;  ///< test geometry, declared actuator errors, noise, seed
  KinematicEffects effects;

  bool isValid(std::string* why) const;
};

/// Runs commands through the machine with the effects (no noise when noiseMm = 0).
std::vector<Eigen::Vector2d> simulateMachineWithEffects(const ActuatorErrors2& errors,
                                                        const KinematicEffects& effects,
                                                        const std::vector<Eigen::Vector2d>& commands,
                                                        double noiseMm, std::uint64_t seed);

/// The circular test of circular_sim.h (CCW loop then CW loop) with the effects added.
MeasuredPath simulateCircularTestWithEffects(const KinematicEffectsOptions& options);

}  // namespace metrofit
