#include "core/study/matching_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/axis_ticks.h"
#include "core/common/error.h"
#include "core/matching/cad_match.h"
#include "core/project/project.h"
#include "core/study/study_settings.h"

namespace metrofit::matching {

const MatchResult* MatchingStudyResult::of(MatchMethod method) const {
  for (const MatchResult& r : runs)
    if (r.method == method) return &r;
  return nullptr;
}

const MatchResult& MatchingStudyResult::primaryRun() const {
  const MatchResult* r = of(primary);
  if (r == nullptr) throw std::logic_error("matching study without its primary run");
  return *r;
}

ProbePointSet studyModelSet(const ProbePointSet& set, const MatchingStudyOptions& options,
                            const std::string& source) {
  return diagnose::applyMatchingEffects(set, options.applied, source);
}

namespace {

/// After the runs: the machine adjustment of the primary run's posture and the remeasure loop on a cell
/// holding the part as measured (`cellSet`: the nominals the primary run matched). Nothing when the
/// primary method did not run (the study was stopped before it).
void finishStudy(MatchingStudyResult& res, const MatchingStudyOptions& o, const ProbePointSet& cellSet,
                 Observer* observer) {
  const MatchResult* primary = res.of(o.primary);
  if (primary == nullptr) return;
  res.adjustment = machine::adjustmentFor(o.machine, primary->pose.rotation, primary->pose.translation);
  if (!o.remeasure || primary->run.termination == Termination::Cancelled) return;
  RemeasureOptions ro;
  ro.match.method = o.primary;
  ro.match.toleranceMm = o.toleranceMm;
  ro.match.locks = o.locks;
  ro.match.seed = o.seed;
  ro.machine = o.machine;
  res.remeasure =
      remeasureLoop(simulateCell(partAsMeasured(cellSet), o.remeasureNoiseMm, o.seed), ro, observer);
}

/// runMatchingStudy with a CAD part (MatchingStudyOptions::cad): closed form and minimax through
/// matchToCad, which re-projects the measured points onto the part at each posture.
MatchingStudyResult runCadStudy(const ProbePointSet& input, const MatchingStudyOptions& o,
                                Observer* observer) {
  const auto local = [](MatchMethod m) { return m == MatchMethod::ClosedForm || m == MatchMethod::Minimax; };
  if (!local(o.primary))
    throw ValidationError(
        ErrorContext{input.source, 0, 0, "studies.matching.method"},
        std::string("nominals from a CAD part are matched by closed-form (least squares) or ") + "minimax; " +
            toString(o.primary) + " needs fixed point pairs");
  if (!o.applied.empty())
    throw ValidationError(
        ErrorContext{input.source, 0, 0, "studies.diagnosis.matching.applied"},
        "effects added to the model (" + o.applied.describe() + ") do not apply to nominals from a CAD part");
  MatchingStudyResult res;
  res.primary = o.primary;
  res.machine = o.machine;
  std::vector<MatchMethod> methods;
  for (MatchMethod m : o.methods)
    if (local(m)) methods.push_back(m);
  if (std::find(methods.begin(), methods.end(), o.primary) == methods.end()) methods.push_back(o.primary);
  const ProbePointSet* primaryAfter = nullptr;
  for (MatchMethod m : methods) {
    CadMatchOptions co;
    co.method = m;
    co.toleranceMm = o.toleranceMm;
    co.allowScale = o.allowScale;
    co.locks = o.locks;
    const auto t0 = std::chrono::steady_clock::now();
    CadMatchResult r = matchToCad(input, *o.cad, co, observer);
    res.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    res.runs.push_back(std::move(r.match));
    res.cadAfter.push_back(std::move(r.after));
    if (res.runs.back().run.termination == Termination::Cancelled) break;
  }
  for (std::size_t k = 0; k < res.runs.size(); ++k)
    if (res.runs[k].method == o.primary) primaryAfter = &res.cadAfter[k];
  // The cell holds the part where the probe found it, its nominals the part's closest points.
  if (primaryAfter) finishStudy(res, o, *primaryAfter, observer);
  return res;
}

}  // namespace

MatchingStudyResult runMatchingStudy(const ProbePointSet& input, const MatchingStudyOptions& o,
                                     Observer* observer) {
  if (o.cad) return runCadStudy(input, o, observer);
  const ProbePointSet set = studyModelSet(input, o);
  MatchingStudyResult res;
  res.primary = o.primary;
  res.machine = o.machine;
  std::vector<MatchMethod> methods = o.methods;
  if (std::find(methods.begin(), methods.end(), o.primary) == methods.end()) methods.push_back(o.primary);
  for (MatchMethod m : methods) {
    MatchOptions mo;
    mo.method = m;
    mo.toleranceMm = o.toleranceMm;
    mo.allowScale = o.allowScale;
    mo.locks = o.locks;
    mo.seed = o.seed;
    const auto t0 = std::chrono::steady_clock::now();
    res.runs.push_back(matchPosture(set, mo, observer));
    res.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (res.runs.back().run.termination == Termination::Cancelled) break;
  }
  finishStudy(res, o, set, observer);
  return res;
}

MatchingStudySettings matchingStudySettings(const Project& project, const std::string& source) {
  MatchingStudySettings s;
  const std::string prefix = std::string("studies.") + study::kMatching + ".";
  auto fail = [&](const std::string& key, const std::string& what) {
    throw ValidationError(ErrorContext{source, 0, 0, prefix + key}, what);
  };
  nlohmann::json j = nlohmann::json::object();
  if (const auto it = project.studies.find(study::kMatching); it != project.studies.end() && it->is_object())
    j = *it;
  if (j.contains("dataset")) {
    if (!j["dataset"].is_string()) fail("dataset", "must be a dataset id (string)");
    s.datasetId = j["dataset"].get<std::string>();
    const DatasetRef* d = project.dataset(s.datasetId);
    if (d == nullptr) fail("dataset", "no dataset '" + s.datasetId + "' in the project");
    if (d->kind != dataset_kind::kProbePoints)
      fail("dataset", "'" + s.datasetId + "' is a " + d->kind + " dataset, not probe_points");
  } else if (const DatasetRef* d = project.firstOfKind(dataset_kind::kProbePoints)) {
    s.datasetId = d->id;
  }
  // The values: the study's settings type (core/study/study_settings.h), refused with the field named.
  const MatchingSettings m = MatchingSettings::fromJson(j, source);
  s.options.toleranceMm = m.toleranceMm;
  s.options.primary = m.method;
  s.options.allowScale = m.allowScale;
  s.options.seed = m.seed;
  s.options.locks = DofLocks::parse(m.locks, prefix + "locks");  // "rz,z", as the CLI's --lock
  s.frame = m.frame;
  s.frameDecimals = m.frameDecimals;
  s.options.applied = diagnose::parseAppliedMatchingEffects(
      diagnose::projectAppliedEffects(project, study::kMatching, s.datasetId, source), source);
  if (!matchingMachine(project, &s.options.machine, source))
    s.options.machine = machine::MachineDefinition::preset(machine::Topology::Xfyzba);
  return s;
}

double deviationMagnification(const ProbePointSet& set, double maxBefore) {
  if (!(maxBefore > 0.0) || set.points.empty()) return 100.0;
  Eigen::Vector3d lo = set.points.front().nominal, hi = lo;
  for (const ProbePoint& p : set.points) {
    lo = lo.cwiseMin(p.nominal);
    hi = hi.cwiseMax(p.nominal);
  }
  const double extent = std::max((hi - lo).maxCoeff(), 1.0);
  return std::clamp(ticks::niceFloor(0.15 * extent / maxBefore), 1.0, 1e5);
}

}  // namespace metrofit::matching
