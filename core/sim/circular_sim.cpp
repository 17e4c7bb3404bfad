#include "core/sim/circular_sim.h"

#include <cmath>
#include <numbers>

#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/io/csv.h"
#include "core/sim/effects_kinematic.h"

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
  // The machine without axis effects: the joints reach the commands exactly.
  return simulateMachineWithEffects(errors, KinematicEffects{}, commands, noiseMm, seed);
}

MeasuredPath simulateCircularTest(const CircularSimOptions& o) {
  MeasuredPath p;
  p.source = "simulated circular test";
  p.command = circularTestCommands(o);
  p.measured = simulateMachine(o.errors, p.command, o.noiseMm, o.seed);
  return p;
}

MeasuredPath simulatePlaneCircularTest(const ActuatorErrors3& errors, TestPlane plane,
                                       const CircularSimOptions& o) {
  std::string why;
  if (!errors.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "three-axis machine"}, why);
  MeasuredPath p;
  p.source = std::string("simulated ") + planeName(plane) + " circular test";
  p.command = circularTestCommands(o);
  const CartesianMachine3 machine = errors.machine();  // Eq. 9 in three axes
  const auto ax = planeAxes(plane);
  Rng rng(o.seed);
  p.measured.reserve(p.command.size());
  for (const auto& c : p.command) {
    Eigen::Vector3d pr = Eigen::Vector3d::Zero();
    pr(ax[0]) = c.x();
    pr(ax[1]) = c.y();
    const Eigen::Vector3d pos = machine.forward(pr);
    Eigen::Vector2d m(pos(ax[0]), pos(ax[1]));
    if (o.noiseMm > 0.0) {
      const double nu = rng.normal(0.0, o.noiseMm);
      const double nv = rng.normal(0.0, o.noiseMm);
      m += Eigen::Vector2d(nu, nv);
    }
    p.measured.push_back(m);
  }
  return p;
}

bool EdgeSimOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (axis != 'x' && axis != 'y') return no("axis must be x or y");
  if (!std::isfinite(startMm) || !(lengthMm > 0.0) || !std::isfinite(lengthMm))
    return no("start must be finite and length positive");
  if (points < 3 || points > 1000000) return no("points must be between 3 and 1000000");
  if (!std::isfinite(nominalCrossMm)) return no("nominal cross coordinate must be finite");
  std::string bad;
  if (!errors.isValid(&bad)) return no(bad);
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm)) return no("noise must be finite and not negative");
  return true;
}

AxisFeatureSeries simulateAxisFeature(const EdgeSimOptions& o) {
  requireValid(o, "edge simulation");
  std::vector<Eigen::Vector2d> commands;
  for (int k = 0; k < o.points; ++k) {
    const double s = o.startMm + o.lengthMm * k / (o.points - 1);
    commands.push_back(o.axis == 'x' ? Eigen::Vector2d(s, o.nominalCrossMm)
                                     : Eigen::Vector2d(o.nominalCrossMm, s));
  }
  const auto measured = simulateMachine(o.errors, commands, o.noiseMm, o.seed);
  AxisFeatureSeries f;
  f.source = std::string("simulated ") + o.axis + " edge";
  f.nominalCrossMm = o.nominalCrossMm;
  const int along = o.axis == 'x' ? 0 : 1;
  for (const auto& m : measured) {
    f.positionMm.push_back(m(along));
    f.deviationMm.push_back(m(1 - along) - o.nominalCrossMm);
  }
  return f;
}

std::string axisFeatureToCsv(const AxisFeatureSeries& f) {
  CsvWriter w;
  w.row({"position_mm", "deviation_mm"});
  for (std::size_t i = 0; i < f.positionMm.size(); ++i) {
    w.row({CsvWriter::formatNumber(f.positionMm[i]), CsvWriter::formatNumber(f.deviationMm[i])});
  }
  return w.text();
}

}  // namespace metrofit
