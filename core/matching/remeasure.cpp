#include "core/matching/remeasure.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/matching/closed_form.h"

namespace metrofit::matching {
namespace {

double roundTo(double v, double step) {
  return step > 0.0 ? std::round(v / step) * step : v;
}

}  // namespace

std::vector<Eigen::Vector3d> SimulatedPart::actualPoints() const {
  if (!formErrorMm.empty() && formErrorMm.size() != nominal.points.size())
    throw OptionsError(ErrorContext{nominal.source, 0, 0, "form error"},
                       "the simulated part has " + std::to_string(formErrorMm.size()) +
                           " form error vectors for " + std::to_string(nominal.points.size()) + " points");
  Pose rigid = truePosture;
  rigid.scale = 1.0;
  std::vector<Eigen::Vector3d> a(nominal.points.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    Eigen::Vector3d q = nominal.points[i].nominal;
    if (!formErrorMm.empty()) q += formErrorMm[i];
    a[i] = rigid.apply(q);
    if (nominal.planar) a[i].z() = 0.0;
  }
  return a;
}

SimulatedPart partAsMeasured(const ProbePointSet& measured) {
  SimulatedPart part;
  part.nominal = measured;
  part.truePosture = umeyamaFit(measured, false);
  part.truePosture.scale = 1.0;
  const Pose back = part.truePosture.inverse();
  part.formErrorMm.reserve(measured.points.size());
  for (const auto& p : measured.points) part.formErrorMm.push_back(back.apply(p.measured) - p.nominal);
  return part;
}

SimulatedCell simulateCell(const SimulatedPart& part, double noiseMm, std::uint64_t seed) {
  if (!(noiseMm >= 0.0) || !std::isfinite(noiseMm))
    throw OptionsError(ErrorContext{{}, 0, 0, "noise"}, "the probing noise must be >= 0 mm");
  ProbePointSet base = part.nominal;
  if (base.source.empty()) base.source = "simulated cell";
  const std::vector<Eigen::Vector3d> actual = part.actualPoints();
  Eigen::Matrix3d trueRotation = part.truePosture.rotation;
  // The part in WCS coordinates: measured = W^-1 a_i (noise-free).
  auto inWcs = [base, actual](const Pose& wcs) {
    ProbePointSet set = base;
    const Pose back = wcs.inverse();
    for (std::size_t i = 0; i < set.points.size(); ++i) {
      set.points[i].measured = back.apply(actual[i]);
      if (set.planar) set.points[i].measured.z() = 0.0;
    }
    return set;
  };
  SimulatedCell cell;
  cell.truth = inWcs;
  cell.measure = [inWcs, trueRotation, noiseMm, seed](const Pose& wcs, int round) {
    Rng rng(seed + static_cast<std::uint64_t>(round));
    ProbePointSet set = inWcs(wcs);
    const Eigen::Matrix3d toWcs = wcs.rotation.transpose() * trueRotation;
    for (auto& p : set.points) {
      Eigen::Vector3d direction;
      if (set.hasNormals) {
        direction = toWcs * p.normal;
      } else {
        direction = Eigen::Vector3d(rng.normal(), rng.normal(), set.planar ? 0.0 : rng.normal());
        direction =
            direction.norm() > 0.0 ? Eigen::Vector3d(direction.normalized()) : Eigen::Vector3d::UnitX();
      }
      p.measured += direction * rng.normal(0.0, noiseMm);
      if (set.planar) p.measured.z() = 0.0;
    }
    return set;
  };
  return cell;
}

MeasureFunction simulatedCell(const ProbePointSet& nominal, const Pose& truePosture, double noiseMm,
                              std::uint64_t seed) {
  SimulatedPart part;
  part.nominal = nominal;
  part.truePosture = truePosture;
  return simulateCell(part, noiseMm, seed).measure;
}

const char* toString(RemeasureOutcome outcome) {
  switch (outcome) {
    case RemeasureOutcome::InTolerance:
      return "in_tolerance";
    case RemeasureOutcome::FormError:
      return "form_error";
    case RemeasureOutcome::BeyondTravel:
      return "beyond_travel";
    case RemeasureOutcome::NotConverged:
      return "not_converged";
    case RemeasureOutcome::Cancelled:
      return "cancelled";
  }
  return "?";
}

const ToleranceEvaluation* RemeasureResult::trueRemaining() const {
  if (rounds.empty() || !rounds.back().truth) return nullptr;
  return &*rounds.back().truth;
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

RemeasureResult remeasureLoop(const MeasureFunction& measure, const RemeasureOptions& o, Observer* observer,
                              const TruthFunction& truth) {
  requireValid(o, "remeasure loop options");
  RemeasureResult res;
  res.outcome = RemeasureOutcome::NotConverged;
  res.run.termination = Termination::MaxIterations;
  res.run.message = "still out of tolerance after " + std::to_string(o.maxAdjustments) + " adjustments";
  Pose wcs;  // the original WCS
  long evaluations = 0;
  std::size_t fitLeftOut = 0;  // points the previous round's best fit left out of tolerance
  for (int round = 0; round <= o.maxAdjustments; ++round) {
    RemeasureRound r;
    r.round = round;
    r.wcs = wcs;
    r.nextWcs = wcs;
    const ProbePointSet set = measure(wcs, round);
    r.measured = evaluateTolerance(set, Pose{}, o.match.toleranceMm);
    if (truth) r.truth = evaluateTolerance(truth(wcs), Pose{}, o.match.toleranceMm);
    const std::size_t out = r.measured.overall.outOfTolerance;
    bool stop = false;
    if (out == 0) {
      res.inTolerance = true;
      res.outcome = RemeasureOutcome::InTolerance;
      res.run.termination = Termination::Converged;
      res.run.message = "every point within tolerance after " + std::to_string(round) + " adjustment" +
                        (round == 1 ? "" : "s");
      stop = true;
    } else if (fitLeftOut > 0) {
      res.outcome = RemeasureOutcome::FormError;
      res.run.termination = Termination::Failed;
      res.run.message = "FAILED: the best fit leaves " + std::to_string(fitLeftOut) +
                        " points out of tolerance (form error larger than the tolerance); after the " +
                        "adjustment " + std::to_string(out) +
                        " points are still out, no WCS can bring them in";
      stop = true;
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
      r.adjustment = a;
      if (!a.withinTravel) {
        res.outcome = RemeasureOutcome::BeyondTravel;
        res.run.termination = Termination::Failed;
        res.run.message = "FAILED: the adjustment is beyond the machine's travel (" + a.travelMessage +
                          "); the WCS was not moved and " + std::to_string(out) +
                          " points stay out of tolerance";
        stop = true;
      } else {
        const machine::Frame f = machine::realisedFrame(o.machine, a);
        r.nextWcs.rotation = f.rotation;
        r.nextWcs.translation = f.origin;
        wcs = r.nextWcs;
        fitLeftOut = r.match->after.overall.outOfTolerance;
      }
    }
    res.rounds.push_back(r);
    IterationSummary s;
    s.iteration = round;
    s.evaluations = evaluations;
    s.best = r.measured.overall.maxAbsMm;
    s.components = {{"out_of_tolerance", static_cast<double>(out)}, {"rmse_mm", r.measured.overall.rmseMm}};
    if (r.truth) s.components.push_back({"true_max_abs_mm", r.truth->overall.maxAbsMm});
    if (notify(observer, res.run, s, true)) {
      if (!stop) res.outcome = RemeasureOutcome::Cancelled;
      break;
    }
    if (stop) break;
  }
  res.run.evaluations = evaluations;
  return res;
}

RemeasureResult remeasureLoop(const SimulatedCell& cell, const RemeasureOptions& options,
                              Observer* observer) {
  return remeasureLoop(cell.measure, options, observer, cell.truth);
}

nlohmann::json toJson(const RemeasureResult& result) {
  nlohmann::json rounds = nlohmann::json::array();
  int adjustments = 0;
  for (const RemeasureRound& r : result.rounds) {
    nlohmann::json e{{"round", r.round}, {"measured", toJson(r.measured.overall)}};
    if (r.truth) e["true"] = toJson(r.truth->overall);
    const Eigen::Vector3d ang = r.wcs.anglesDeg();
    e["wcs"] = {{"rotation_deg", {ang.x(), ang.y(), ang.z()}},
                {"translation_mm", {r.wcs.translation.x(), r.wcs.translation.y(), r.wcs.translation.z()}}};
    if (r.match) e["fit_out_of_tolerance"] = r.match->after.overall.outOfTolerance;
    if (r.adjustment) {
      e["adjustment"] = machine::adjustmentToJson(*r.adjustment);
      if (r.adjustment->withinTravel) ++adjustments;
    }
    rounds.push_back(std::move(e));
  }
  nlohmann::json j{{"outcome", toString(result.outcome)},
                   {"in_tolerance", result.inTolerance},
                   {"message", result.run.message},
                   {"adjustments", adjustments},
                   {"rounds", std::move(rounds)}};
  if (const ToleranceEvaluation* t = result.trueRemaining()) j["true_remaining"] = toJson(t->overall);
  return j;
}

}  // namespace metrofit::matching
