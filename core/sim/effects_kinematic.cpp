#include "core/sim/effects_kinematic.h"

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

bool KinematicEffectsOptions::isValid(std::string* why) const {
  return circle.isValid(why) && effects.isValid(why);
}

std::vector<Eigen::Vector2d> simulateMachineWithEffects(const ActuatorErrors2& errors,
                                                        const KinematicEffects& fx,
                                                        const std::vector<Eigen::Vector2d>& commands,
                                                        double noiseMm, std::uint64_t seed) {
  requireValid(fx, "kinematic effects");
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm)) {
    throw OptionsError(ErrorContext{{}, 0, 0, "machine simulation"}, "noise must be finite and not negative");
  }
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(errors);
  const PathMotion motion = pathMotion(commands);
  Rng rng(seed);
  std::vector<Eigen::Vector2d> out;
  out.reserve(commands.size());
  for (std::size_t k = 0; k < commands.size(); ++k) {
    Eigen::Vector2d p =
        machine.forward(fx.effectiveJoints(commands[k], motion.direction[k], motion.tangent[k]));
    if (noiseMm > 0.0) {
      const double nx = rng.normal(0.0, noiseMm);
      const double ny = rng.normal(0.0, noiseMm);
      p += Eigen::Vector2d(nx, ny);
    }
    out.push_back(p);
  }
  return out;
}

MeasuredPath simulateCircularTestWithEffects(const KinematicEffectsOptions& o) {
  requireValid(o, "circular test simulation with effects");
  MeasuredPath p;
  p.source = "simulated circular test with undeclared effects";
  p.command = circularTestCommands(o.circle);
  p.measured =
      simulateMachineWithEffects(o.circle.errors, o.effects, p.command, o.circle.noiseMm, o.circle.seed);
  return p;
}

}  // namespace metrofit
