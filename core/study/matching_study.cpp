#include "core/study/matching_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/axis_ticks.h"
#include "core/common/error.h"
#include "core/project/project.h"

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

MatchingStudyResult runMatchingStudy(const ProbePointSet& input, const MatchingStudyOptions& o,
                                     Observer* observer) {
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
  const MatchResult* primary = res.of(o.primary);
  if (primary == nullptr) return res;  // stopped before the primary method ran
  res.adjustment = machine::adjustmentFor(o.machine, primary->pose.rotation, primary->pose.translation);
  if (o.remeasure && primary->run.termination != Termination::Cancelled) {
    RemeasureOptions ro;
    ro.match.method = o.primary;
    ro.match.toleranceMm = o.toleranceMm;
    ro.match.locks = o.locks;
    ro.match.seed = o.seed;
    ro.machine = o.machine;
    res.remeasure =
        remeasureLoop(simulateCell(partAsMeasured(set), o.remeasureNoiseMm, o.seed), ro, observer);
  }
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
  if (j.contains("tolerance_mm")) {
    if (!j["tolerance_mm"].is_number() || !(j["tolerance_mm"].get<double>() >= 0.0) ||
        !std::isfinite(j["tolerance_mm"].get<double>()))
      fail("tolerance_mm", "must be a number >= 0 (mm)");
    s.options.toleranceMm = j["tolerance_mm"].get<double>();
  }
  if (j.contains("method")) {
    if (!j["method"].is_string()) fail("method", "must be one of sade, ga-simplex, closed-form, minimax");
    s.options.primary = parseMatchMethod(j["method"].get<std::string>(), prefix + "method");
  }
  if (j.contains("allow_scale")) {
    if (!j["allow_scale"].is_boolean()) fail("allow_scale", "must be true or false");
    s.options.allowScale = j["allow_scale"].get<bool>();
  }
  if (j.contains("seed")) {
    if (!j["seed"].is_number_integer() || j["seed"].get<long long>() < 0)
      fail("seed", "must be an integer >= 0");
    s.options.seed = j["seed"].get<std::uint64_t>();
  }
  if (j.contains("locks")) {  // "rz,z": the degrees of freedom held at 0, as the CLI's --lock
    if (!j["locks"].is_string())
      fail("locks", "must be a list of rx, ry, rz, x, y, z (string, e.g. \"rz,z\")");
    s.options.locks = DofLocks::parse(j["locks"].get<std::string>(), prefix + "locks");
  }
  if (j.contains("frame")) {
    if (!j["frame"].is_string()) fail("frame", "must be one of heidenhain, siemens, fanuc");
    const std::string name = j["frame"].get<std::string>();
    const std::vector<std::string> names = machine::frameFormatNames();
    if (std::find(names.begin(), names.end(), name) == names.end())
      fail("frame", "must be one of heidenhain, siemens, fanuc");
    s.frame = machine::parseFrameFormat(name, prefix + "frame");
  }
  if (j.contains("frame_decimals")) {
    if (!j["frame_decimals"].is_number_integer() || j["frame_decimals"].get<long long>() < 0 ||
        j["frame_decimals"].get<long long>() > 12)
      fail("frame_decimals", "must be an integer in 0..12");
    s.frameDecimals = j["frame_decimals"].get<int>();
  }
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
