#include "core/matching/matching.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/matching/fit_input.h"

namespace metrofit::matching {
namespace {

nlohmann::json vec(const Eigen::Vector3d& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json evaluationJson(const ToleranceEvaluation& ev) {
  nlohmann::json j = toJson(ev.overall);
  nlohmann::json surfaces = nlohmann::json::array();
  for (const auto& s : ev.surfaces) {
    nlohmann::json sj = toJson(s.stats);
    sj["surface"] = s.surface;
    surfaces.push_back(std::move(sj));
  }
  j["surfaces"] = std::move(surfaces);
  return j;
}

std::string methodLabel(MatchMethod m) {
  switch (m) {
    case MatchMethod::Sade:
      return "SADE fine matching";
    case MatchMethod::GaSimplex:
      return "GA-simplex fine matching";
    case MatchMethod::ClosedForm:
      return "closed-form fit";
    case MatchMethod::Minimax:
      return "minimax fit";
  }
  return "fit";
}

}  // namespace

const char* toString(MatchMethod m) {
  switch (m) {
    case MatchMethod::Sade:
      return "sade";
    case MatchMethod::GaSimplex:
      return "ga-simplex";
    case MatchMethod::ClosedForm:
      return "closed-form";
    case MatchMethod::Minimax:
      return "minimax";
  }
  return "?";
}

MatchMethod parseMatchMethod(const std::string& name, const std::string& field) {
  for (MatchMethod m :
       {MatchMethod::Sade, MatchMethod::GaSimplex, MatchMethod::ClosedForm, MatchMethod::Minimax}) {
    if (name == toString(m)) return m;
  }
  throw OptionsError(ErrorContext{{}, 0, 0, field}, "unknown matching method '" + name +
                                                        "' (one of sade, ga-simplex, closed-form, minimax)");
}

optim::Sade::Options paperSadeOptions() {
  optim::Sade::Options o;
  o.populationSize = 30;
  o.f0 = 0.3;
  o.maxGenerations = 200;
  o.crMin = 0.1;
  o.crMax = 0.9;
  // Generation 0 plus Gm generations, and one generation of slack so that the run ends by reaching
  // Gm (Termination::MaxIterations) rather than by the budget.
  o.common.maxEvaluations = 30L * (200 + 2);
  o.common.keepTrace = true;
  return o;
}

optim::GaSimplex::Options comparisonGaSimplexOptions() {
  optim::GaSimplex::Options o;
  o.populationSize = 50;
  o.crossoverProbability = 0.9;
  o.mutationProbability = 0.0;
  o.gaFraction = 0.8;
  o.common.maxEvaluations = paperSadeOptions().common.maxEvaluations;
  o.common.keepTrace = true;
  return o;
}

bool MatchOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(toleranceMm >= 0.0) || !std::isfinite(toleranceMm))
    return no("the tolerance must be a finite number >= 0 mm");
  if (!(boundMarginDeg > 0.0) || !std::isfinite(boundMarginDeg))
    return no("the angle bound margin k must be > 0 deg");
  if (!referenceIds.empty() && referenceIds.size() != 3)
    return no("rough matching takes exactly three reference point ids");
  std::string w;
  if (!locks.isValid(&w)) return no(w);
  if (!sade.isValid(&w)) return no("SADE: " + w);
  if (!gaSimplex.isValid(&w)) return no("GA-simplex: " + w);
  if (!minimax.isValid(&w)) return no(w);
  return true;
}

nlohmann::json toJson(const DeviationStats& s) {
  return {{"points", s.points},
          {"rmse_mm", s.rmseMm},
          {"max_abs_mm", s.maxAbsMm},
          {"out_of_tolerance", s.outOfTolerance},
          {"mean_over_tolerance_mm", s.meanOverToleranceMm}};
}

MatchResult matchPosture(const ProbePointSet& set, const MatchOptions& o, Observer* observer) {
  requireValid(o, "matching options");
  MatchResult res;
  res.method = o.method;
  res.allowScale = o.allowScale;
  res.locks = effectiveLocks(set, o.locks);
  const FitKind kind = o.method == MatchMethod::Minimax ? FitKind::Minimax : FitKind::LeastSquares;
  requireDeterminable(set, res.locks, o.allowScale, kind, methodLabel(o.method));
  res.before = evaluateTolerance(set, Pose{}, o.toleranceMm);

  switch (o.method) {
    case MatchMethod::ClosedForm: {
      ClosedFormOptions co;
      co.allowScale = o.allowScale;
      co.locks = res.locks;
      res.closedForm = closedFormFit(set, co);
      res.pose = res.closedForm->pose;
      res.run.termination = res.closedForm->termination;
      res.run.message = res.closedForm->message;
      res.run.iterations = res.closedForm->iterations;
      res.run.evaluations = res.closedForm->iterations;
      break;
    }
    case MatchMethod::Minimax: {
      ClosedFormOptions co;
      co.allowScale = o.allowScale;
      co.locks = res.locks;
      res.closedForm = closedFormFit(set, co);
      MinimaxOptions mo = o.minimax;
      mo.allowScale = o.allowScale;
      mo.locks = res.locks;
      res.minimax = minimaxFit(set, res.closedForm->pose, mo, observer);
      res.pose = res.minimax->pose;
      res.run = res.minimax->run;
      break;
    }
    case MatchMethod::Sade:
    case MatchMethod::GaSimplex: {
      res.rough = roughMatch(set, o.referenceIds);
      res.roughEvaluation = evaluateTolerance(set, res.rough->posture, o.toleranceMm);
      res.seed = o.seed;
      if (o.method == MatchMethod::Sade) {
        optim::Sade::Options so = o.sade;
        so.common.seed = o.seed;
        const optim::Sade sade(so);
        res.fine = fineMatch(set, *res.rough, sade, res.locks, o.allowScale, o.boundMarginDeg, observer);
      } else {
        optim::GaSimplex::Options go = o.gaSimplex;
        go.common.seed = o.seed;
        const optim::GaSimplex ga(go);
        res.fine = fineMatch(set, *res.rough, ga, res.locks, o.allowScale, o.boundMarginDeg, observer);
      }
      res.pose = res.fine->pose;
      res.run = res.fine->optimisation.run;
      break;
    }
  }
  res.after = evaluateTolerance(set, res.pose, o.toleranceMm);
  return res;
}

nlohmann::json toJson(const MatchResult& r, const ProbePointSet& set) {
  nlohmann::json j;
  j["method"] = toString(r.method);
  j["rotation_deg"] = vec(r.pose.anglesDeg());
  j["translation_mm"] = vec(r.pose.translation);
  if (r.allowScale) j["scale"] = r.pose.scale;
  j["rmse_mm"] = r.after.overall.rmseMm;
  j["max_abs_mm"] = r.after.overall.maxAbsMm;
  j["out_of_tolerance"] = {{"before", r.before.overall.outOfTolerance},
                           {"after", r.after.overall.outOfTolerance}};
  j["tolerance_mm"] = r.after.toleranceMm;
  j["points"] = set.points.size();
  j["normals"] = set.hasNormals;
  j["planar"] = set.planar;
  nlohmann::json locked = nlohmann::json::array();
  for (int d = 0; d < kDofCount; ++d)
    if (r.locks.locked[d]) locked.push_back(dofName(d));
  j["locked"] = std::move(locked);
  j["before"] = evaluationJson(r.before);
  j["after"] = evaluationJson(r.after);
  // Per point after the fit (CloudCompare-style signed deviations): d along the nominal normal (the
  // evaluation's d_i) and the deviation vector p_i - (s R q_i + t).
  nlohmann::json perPoint = nlohmann::json::array();
  for (std::size_t i = 0; i < set.points.size() && i < r.after.residuals.size(); ++i) {
    const Eigen::Vector3d& e = r.after.residuals[i];
    perPoint.push_back({{"id", set.points[i].id},
                        {"d_mm", r.after.deviations[i]},
                        {"dx_mm", e.x()},
                        {"dy_mm", e.y()},
                        {"dz_mm", e.z()}});
  }
  j["per_point"] = std::move(perPoint);
  j["evaluations"] = r.run.evaluations;
  j["iterations"] = r.run.iterations;
  j["termination"] = toString(r.run.termination);
  j["message"] = r.run.message;
  nlohmann::json trace = nlohmann::json::array();
  for (const auto& s : r.run.trace) {
    trace.push_back({{"iteration", s.iteration}, {"evaluations", s.evaluations}, {"best_mm", s.best}});
  }
  j["trace"] = std::move(trace);
  if (r.rough) {
    const RoughResult& rr = *r.rough;
    nlohmann::json ids = nlohmann::json::array();
    for (std::size_t i : rr.reference) ids.push_back(set.points[i].id);
    nlohmann::json rough = {{"reference_ids", ids},
                            {"pe0",
                             {{"alpha0_deg", rr.pe0[0]},
                              {"beta0_deg", rr.pe0[1]},
                              {"gamma0_deg", rr.pe0[2]},
                              {"tx0_mm", rr.pe0[3]},
                              {"ty0_mm", rr.pe0[4]},
                              {"tz0_mm", rr.pe0[5]}}},
                            {"rotation_deg", vec(rr.posture.anglesDeg())},
                            {"translation_mm", vec(rr.posture.translation)}};
    if (r.roughEvaluation) {
      rough["rmse_mm"] = r.roughEvaluation->overall.rmseMm;
      rough["max_abs_mm"] = r.roughEvaluation->overall.maxAbsMm;
      rough["out_of_tolerance"] = r.roughEvaluation->overall.outOfTolerance;
    }
    j["rough"] = std::move(rough);
  }
  if (r.fine) {
    const FineResult& f = *r.fine;
    nlohmann::json bounds = nlohmann::json::array();
    for (std::size_t i = 0; i < f.lowerDeg.size(); ++i) bounds.push_back({f.lowerDeg[i], f.upperDeg[i]});
    j["fine"] = {{"decision", f.paperMode ? "paper angles of R1 (Eq. 9)" : "free posture angles (locks)"},
                 {"variables", f.variables},
                 {"bounds_deg", bounds},
                 {"best_deg", f.bestDeg},
                 {"objective_mm", f.objectiveMm}};
    j["seed"] = r.seed;
  }
  if (r.minimax) {
    const MinimaxResult& m = *r.minimax;
    nlohmann::json active = nlohmann::json::array();
    for (std::size_t i : m.active) active.push_back(set.points[i].id);
    j["minimax"] = {{"start_max_abs_mm", m.startMaxAbsMm},
                    {"active_points", active},
                    {"lp_solves", m.lpSolves},
                    {"final_trust_region_mm", m.finalTrustMm},
                    {"last_predicted_decrease_mm", m.lastPredictedDecreaseMm}};
  }
  return j;
}

}  // namespace metrofit::matching
