#include "core/sim/circular_sim.h"

#include <cmath>
#include <numbers>

#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

ActuatorErrors2 CircularSimOptions::defaultErrors() {
  ActuatorErrors2 e;
  e.originMm = Eigen::Vector2d(0.004, -0.003);
  e.xAxisAngleDeg = 0.0006;
  e.yAxisAngleDeg = -0.0020;
  return e;
}

bool CircularSimOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(radiusMm > 0.0) || !std::isfinite(radiusMm)) return no("radius must be positive");
  if (!centreMm.allFinite()) return no("centre must be finite");
  if (pointsPerLoop < 3 || pointsPerLoop > 1000000)
    return no("points per loop must be between 3 and 1000000");
  if (!std::isfinite(startAngleDeg)) return no("start angle must be finite");
  std::string bad;
  if (!errors.isValid(&bad)) return no(bad);
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm)) return no("noise must be finite and not negative");
  return true;
}

std::vector<Eigen::Vector2d> circularTestCommands(const CircularSimOptions& o) {
  requireValid(o, "circular test simulation");
  const double t0 = o.startAngleDeg * std::numbers::pi / 180.0;
  const double step = 2.0 * std::numbers::pi / o.pointsPerLoop;
  std::vector<Eigen::Vector2d> out;
  out.reserve(2 * static_cast<std::size_t>(o.pointsPerLoop));
  for (const double dir : {1.0, -1.0}) {
    for (int k = 0; k < o.pointsPerLoop; ++k) {
      const double t = t0 + dir * step * k;
      out.push_back(o.centreMm + o.radiusMm * Eigen::Vector2d(std::cos(t), std::sin(t)));
    }
  }
  return out;
}

std::vector<Eigen::Vector2d> simulateMachine(const ActuatorErrors2& errors,
                                             const std::vector<Eigen::Vector2d>& commands, double noiseMm,
                                             std::uint64_t seed) {
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm)) {
    throw OptionsError(ErrorContext{{}, 0, 0, "machine simulation"}, "noise must be finite and not negative");
  }
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(errors);
  Rng rng(seed);
  std::vector<Eigen::Vector2d> out;
  out.reserve(commands.size());
  for (const auto& c : commands) {
    Eigen::Vector2d p = machine.forward(c);
    if (noiseMm > 0.0) {
      const double nx = rng.normal(0.0, noiseMm);
      const double ny = rng.normal(0.0, noiseMm);
      p += Eigen::Vector2d(nx, ny);
    }
    out.push_back(p);
  }
  return out;
}

MeasuredPath simulateCircularTest(const CircularSimOptions& o) {
  MeasuredPath p;
  p.source = "simulated circular test";
  p.command = circularTestCommands(o);
  p.measured = simulateMachine(o.errors, p.command, o.noiseMm, o.seed);
  return p;
}

}  // namespace metrofit
