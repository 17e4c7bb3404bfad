#include "core/study/circular_analysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/sim/circular_sim.h"

namespace metrofit {

std::vector<RadialPoint> radialDeviations(const std::vector<Eigen::Vector2d>& points,
                                          const Eigen::Vector2d& centreMm, double radiusMm) {
  std::vector<RadialPoint> out;
  out.reserve(points.size());
  for (const auto& p : points) {
    const Eigen::Vector2d d = p - centreMm;
    double angle = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    if (angle < 0.0) angle += 360.0;
    if (angle >= 360.0) angle -= 360.0;
    out.push_back({angle, d.norm() - radiusMm});
  }
  return out;
}

double maxAbsRadialDeviation(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& centreMm,
                             double radiusMm) {
  double m = 0.0;
  for (const auto& p : points) m = std::max(m, std::abs((p - centreMm).norm() - radiusMm));
  return m;
}

CircularAnalysis analyseCircularTest(const MeasuredPath& path) {
  // The checks `metrofit-cli kinematic identify` makes first, so that a path it cannot take (too few
  // points, not finite, identical or collinear points) gets the CLI's message, not one of our own.
  checkIdentifiable(path);
  CircularAnalysis a = analyseCircularTrace(circularTraceOf(path));
  try {
    a.ballbar = ballbarBreakdown(path);
  } catch (const ValidationError& e) {
    a.ballbarUnavailable = e.detail();
  }
  return a;
}

CircularAnalysis analyseCircularTrace(const CircularTrace& t) {
  const std::size_t n = t.size();
  if (n < 3) {
    throw ValidationError(ErrorContext{t.source, 0, 0, t.radialOnly ? "angle_deg" : "x_cmd_mm"},
                          "a circular test needs at least 3 points, got " + std::to_string(n));
  }
  CircularAnalysis a;
  a.radialOnly = t.radialOnly;
  a.centreMm = t.nominalCentreMm;
  a.radiusMm = t.nominalRadiusMm.value_or(0.0);
  a.minDeviationMm = a.maxDeviationMm = t.deviationMm.front();
  for (std::size_t k = 0; k < n; ++k) {
    const bool newRun = !t.run.empty() && k > 0 && t.run[k] != t.run[k - 1];
    if (a.loops.empty() || a.loops.back().counterClockwise != t.counterClockwise[k] || newRun) {
      a.loops.push_back(CircularLoop{t.counterClockwise[k], k, {}});
    }
    a.loops.back().points.push_back({t.angleDeg[k], t.deviationMm[k]});
    a.minDeviationMm = std::min(a.minDeviationMm, t.deviationMm[k]);
    a.maxDeviationMm = std::max(a.maxDeviationMm, t.deviationMm[k]);
    a.maxAbsDeviationMm = std::max(a.maxAbsDeviationMm, std::abs(t.deviationMm[k]));
  }
  a.iso = evaluateIso230_4(t);
  return a;
}

CompensationPreview previewCompensation(const MeasuredPath& path, const CircularAnalysis& analysis,
                                        const ActuatorErrors2& identified,
                                        const std::optional<ActuatorErrors2>& trueMachine,
                                        const AxisEffects* effects) {
  CompensationPreview p;
  const CartesianMachine2 machine = CartesianMachine2::fromErrors(identified);
  p.nominal = path.command;
  const bool withEffects = effects && !effects->empty();
  p.references = withEffects ? compensatePathWithEffects(machine, *effects, p.nominal)
                             : compensatePath(machine, p.nominal);
  p.model = withEffects ? runPathWithEffects(machine, *effects, p.references, p.nominal)
                        : runPath(machine, p.references);
  const std::vector<Eigen::Vector2d> atNominal =
      withEffects ? runPathWithEffects(machine, *effects, p.nominal, p.nominal)
                  : std::vector<Eigen::Vector2d>{};
  const Eigen::Matrix2d axes = machine.directions();
  p.expected.reserve(path.size());
  double sumBefore = 0.0, sumExpected = 0.0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    p.expected.push_back(withEffects
                             ? Eigen::Vector2d(path.measured[k] + p.model[k] - atNominal[k])
                             : Eigen::Vector2d(path.measured[k] + axes * (p.references[k] - p.nominal[k])));
    p.largestCorrectionMm = std::max(p.largestCorrectionMm, (p.references[k] - p.nominal[k]).norm());
    sumBefore += (path.measured[k] - p.nominal[k]).squaredNorm();
    sumExpected += (p.expected[k] - p.nominal[k]).squaredNorm();
  }
  if (path.size() > 0) {
    p.rmsBeforeMm = std::sqrt(sumBefore / static_cast<double>(path.size()));
    p.rmsExpectedMm = std::sqrt(sumExpected / static_cast<double>(path.size()));
  }
  const Eigen::Vector2d& c = analysis.centreMm;
  const double r = analysis.radiusMm;
  p.maxBeforeMm = maxAbsRadialDeviation(path.measured, c, r);
  p.maxModelMm = maxAbsRadialDeviation(p.model, c, r);
  p.maxExpectedMm = maxAbsRadialDeviation(p.expected, c, r);
  if (trueMachine) {
    p.simulated = simulateMachine(*trueMachine, p.references, 0.0, 0);
    p.maxSimulatedMm = maxAbsRadialDeviation(p.simulated, c, r);
  }
  return p;
}

}  // namespace metrofit
