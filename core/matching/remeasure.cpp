#include "core/matching/remeasure.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/rng.h"

namespace metrofit::matching {
namespace {

double roundTo(double v, double step) {
  return step > 0.0 ? std::round(v / step) * step : v;
}

}  // namespace

MeasureFunction simulatedCell(const ProbePointSet& nominal, const Pose& truePosture, double noiseMm,
                              std::uint64_t seed) {
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm))
    throw OptionsError(ErrorContext{{}, 0, 0, "noise"}, "the probing noise must be >= 0 mm");
  ProbePointSet base = nominal;
  return [base, truePosture, noiseMm, seed](const Pose& wcs, int round) {
    Rng rng(seed + static_cast<std::uint64_t>(round));
    ProbePointSet set = base;
    set.source = base.source.empty() ? "simulated cell" : base.source;
    const Pose posture = wcs.inverse().compose(truePosture);
    for (auto& p : set.points) {
      Eigen::Vector3d direction;
      if (set.hasNormals) {
        direction = posture.rotation * p.normal;
      } else {
        direction = Eigen::Vector3d(rng.normal(), rng.normal(), set.planar ? 0.0 : rng.normal());
        direction =
            direction.norm() > 0.0 ? Eigen::Vector3d(direction.normalized()) : Eigen::Vector3d::UnitX();
      }
      p.measured = posture.apply(p.nominal) + direction * rng.normal(0.0, noiseMm);
      if (set.planar) p.measured.z() = 0.0;
    }
    return set;
  };
}

bool RemeasureOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (maxAdjustments < 1) return no("the remeasure loop needs at least one adjustment round");
  if (!(linearResolutionMm >= 0.0) || !(rotaryResolutionDeg >= 0.0) || !std::isfinite(linearResolutionMm) ||
      !std::isfinite(rotaryResolutionDeg))
    return no("axis resolutions must be finite and >= 0");
  std::string w;
  if (!match.isValid(&w)) return no(w);
  if (!machine.isValid(&w)) return no(w);
  return true;
}

RemeasureResult remeasureLoop(const MeasureFunction& measure, const RemeasureOptions& o, Observer* observer) {
  requireValid(o, "remeasure loop options");
  RemeasureResult res;
  res.run.termination = Termination::MaxIterations;
  res.run.message = "still out of tolerance after " + std::to_string(o.maxAdjustments) + " adjustments";
  Pose wcs;  // the original WCS
  long evaluations = 0;
  for (int round = 0; round <= o.maxAdjustments; ++round) {
    RemeasureRound r;
    r.round = round;
    r.wcs = wcs;
    const ProbePointSet set = measure(wcs, round);
    r.measured = evaluateTolerance(set, Pose{}, o.match.toleranceMm);
    const bool done = r.measured.overall.outOfTolerance == 0;
    if (done) {
      res.inTolerance = true;
      res.run.termination = Termination::Converged;
      res.run.message = "every point within tolerance after " + std::to_string(round) + " adjustment" +
                        (round == 1 ? "" : "s");
    } else if (round < o.maxAdjustments) {
      MatchOptions mo = o.match;
      mo.seed = o.match.seed + static_cast<std::uint64_t>(round);
      r.match = matchPosture(set, mo);
      evaluations += r.match->run.evaluations;
      Pose rigid = r.match->pose;
      rigid.scale = 1.0;
      const Pose target = wcs.compose(rigid);
      machine::Adjustment a = machine::adjustmentFor(o.machine, target.rotation, target.translation);
      for (int k = 0; k < 3; ++k) a.linearMm(k) = roundTo(a.linearMm(k), o.linearResolutionMm);
      for (double& v : a.rotaryDeg) v = roundTo(v, o.rotaryResolutionDeg);
      a.frameRotationDeg = roundTo(a.frameRotationDeg, o.rotaryResolutionDeg);
      const machine::Frame f = machine::realisedFrame(o.machine, a);
      r.adjustment = a;
      r.nextWcs.rotation = f.rotation;
      r.nextWcs.translation = f.origin;
      wcs = r.nextWcs;
    }
    res.rounds.push_back(r);
    IterationSummary s;
    s.iteration = round;
    s.evaluations = evaluations;
    s.best = r.measured.overall.maxAbsMm;
    s.components = {{"out_of_tolerance", static_cast<double>(r.measured.overall.outOfTolerance)},
                    {"rmse_mm", r.measured.overall.rmseMm}};
    if (notify(observer, res.run, s, true)) break;
    if (done) break;
  }
  res.run.evaluations = evaluations;
  return res;
}

}  // namespace metrofit::matching
