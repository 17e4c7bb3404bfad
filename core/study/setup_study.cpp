#include "core/study/setup_study.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <unordered_map>

#include "core/common/error.h"
#include "core/project/datasets.h"
#include "core/project/project.h"
#include "core/setup/exact.h"
#include "core/setup/methods.h"

namespace metrofit {

namespace {

/// The study's string setting `key` naming a dataset, when it names one of `kinds`; else the first dataset
/// of the first of `kinds` the project has (datasetKindsServing: a DMIS output file, a DFQ file, a Calypso
/// _chr table and a QIF file are CMM reports too).
const DatasetRef* studyDataset(const Project& project, const nlohmann::json* study, const char* key,
                               const std::vector<std::string>& kinds) {
  const auto fits = [&](const DatasetRef* d) {
    return d != nullptr && std::find(kinds.begin(), kinds.end(), d->kind) != kinds.end();
  };
  if (study != nullptr) {
    const auto it = study->find(key);
    if (it != study->end() && it->is_string()) {
      const DatasetRef* d = project.dataset(it->get<std::string>());
      if (fits(d)) return d;
    }
  }
  for (const std::string& k : kinds)
    if (const DatasetRef* d = project.firstOfKind(k)) return d;
  return nullptr;
}

}  // namespace

SetupStudyFiles setupStudyFiles(const Project& project, const std::string& projectPath) {
  SetupStudyFiles files;
  const nlohmann::json* study = nullptr;
  if (const auto it = project.studies.find(study::kSetup); it != project.studies.end() && it->is_object())
    study = &*it;
  if (const DatasetRef* m = studyDataset(project, study, "model", {dataset_kind::kSetupModel})) {
    files.modelId = m->id;
    files.modelPath = resolveDatasetPath(projectPath, *m);
  }
  if (const DatasetRef* r =
          studyDataset(project, study, "dataset", datasetKindsServing(dataset_kind::kCmmReport))) {
    files.reportId = r->id;
    files.reportPath = resolveDatasetPath(projectPath, *r);
    files.reportPaths = resolveDatasetPaths(projectPath, *r);
    files.reportCsv = r->csv;
    files.reportDmis = r->dmis;
  }
  if (study != nullptr) {
    if (const auto it = study->find("method"); it != study->end() && it->is_string()) {
      const std::string method = it->get<std::string>();
      for (const std::string& name : setup::setupMethodNames())
        if (name == method) files.method = method;
    }
    if (const auto it = study->find("budget");
        it != study->end() && it->is_number_integer() && it->get<long>() > 0)
      files.budget = it->get<long>();
    if (const auto it = study->find("seed"); it != study->end() && it->is_number_unsigned())
      files.seed = it->get<std::uint64_t>();
  }
  return files;
}

std::vector<diagnose::AppliedSetupEffect> applyStudyEffects(const Project& project, const std::string& source,
                                                            const std::string& reportId,
                                                            const setup::Model& model,
                                                            setup::Measurements& measurements,
                                                            diagnose::SetupPrediction* prediction,
                                                            diagnose::SetupPrediction* declared) {
  const std::vector<diagnose::AppliedSetupEffect> effects = diagnose::parseAppliedSetupEffects(
      diagnose::projectAppliedEffects(project, study::kSetup, reportId, source), model, source);
  if (declared != nullptr) *declared = diagnose::predictSetupDeviations(model, measurements, {});
  const diagnose::SetupPrediction p = diagnose::applySetupEffects(model, measurements, effects);
  if (prediction != nullptr) *prediction = p;
  return effects;
}

std::vector<double> deviationsFor(const setup::Model& model, const setup::Model& fileModel,
                                  const setup::Measurements& measurements) {
  std::unordered_map<std::string, std::size_t> byId;
  for (std::size_t q = 0; q < fileModel.dimensions.size(); ++q) byId.emplace(fileModel.dimensions[q].id, q);
  std::vector<double> out;
  out.reserve(model.dimensions.size());
  for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
    const auto it = byId.find(model.dimensions[q].id);
    if (it == byId.end() || it->second >= measurements.deviationMm.size() ||
        measurements.samples[it->second] == 0) {
      throw ValidationError(ErrorContext{model.source, 0, 0, "dimensions[" + std::to_string(q) + "]"},
                            "dimension '" + model.dimensions[q].id + "' has no measurement in the report");
    }
    out.push_back(measurements.deviationMm[it->second]);
  }
  return out;
}

SetupTracePoint tracePoint(const IterationSummary& s) {
  SetupTracePoint p;
  p.evaluations = s.evaluations;
  for (const NamedValue& c : s.components) {
    if (c.name == "f1") p.f1 = c.value;
    if (c.name == "f2") p.f2 = c.value;
    if (c.name == "f") p.f = c.value;
  }
  return p;
}

SetupRunOutcome runSetupMethod(const setup::SetupInstance& instance, const std::string& method, long budget,
                               std::uint64_t seed, Observer* observer) {
  SetupRunOutcome out;
  out.method = method;
  out.seed = seed;
  out.budget = budget;
  out.f1Before = instance.f1Before();
  const auto start = std::chrono::steady_clock::now();
  if (method == "exact") {
    setup::ExactOptions options;
    options.keepTrace = false;
    const setup::ExactResult r = setup::solveExact(instance, options, observer);
    out.x = r.x;
    out.evaluations = r.certificate.solverCalls;
    out.termination = r.run.termination;
    out.f1Optimal = r.certificate.f1Optimal;
    out.f2Optimal = r.certificate.f2Optimal;
  } else {
    const setup::SetupProblem problem(instance);
    const auto algorithm = setup::makeSetupAlgorithm(method, budget, seed, true, "method");
    const optim::Result r = algorithm->optimise(problem, observer);
    out.x = r.bestX;
    out.evaluations = r.run.evaluations;
    out.termination = r.run.termination;
    out.trace.reserve(r.run.trace.size());
    for (const IterationSummary& s : r.run.trace) out.trace.push_back(tracePoint(s));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.score = instance.score(out.x);
  return out;
}

SetupPartsSummary partsSummary(const setup::SetupInstance& instance, const setup::Model& fileModel,
                               const setup::Measurements& measurements, const std::vector<double>& x) {
  std::unordered_map<std::string, std::size_t> byId;
  for (std::size_t q = 0; q < instance.dimensions(); ++q) byId.emplace(instance.dimensionIds()[q], q);
  std::vector<double> shift(instance.dimensions(), 0.0);
  if (x.size() == instance.variables()) {
    for (std::size_t q = 0; q < instance.dimensions(); ++q)
      for (const auto& [i, g] : instance.gainRow(q)) shift[q] += g * x[i];
  }
  // Part name -> (in tolerance before, after); a small tolerance absorbs the 0.001 mm grid's noise.
  constexpr double kEps = 1e-9;
  std::map<std::string, std::pair<bool, bool>> state;
  for (const std::string& part : measurements.parts) state.emplace(part, std::make_pair(true, true));
  for (const setup::Measurements::Row& row : measurements.rows) {
    if (row.dimension >= fileModel.dimensions.size()) continue;
    const auto it = byId.find(fileModel.dimensions[row.dimension].id);
    if (it == byId.end()) continue;
    const std::size_t q = it->second;
    const double lo = instance.lowerLimit(q), up = instance.upperLimit(q);
    const double before = row.deviationMm, after = row.deviationMm + shift[q];
    auto& s = state[row.part];
    if (before < lo - kEps || before > up + kEps) s.first = false;
    if (after < lo - kEps || after > up + kEps) s.second = false;
  }
  SetupPartsSummary summary;
  for (const auto& [part, s] : state) {
    ++summary.parts;
    summary.inToleranceBefore += s.first ? 1 : 0;
    summary.inToleranceAfter += s.second ? 1 : 0;
    summary.rescued += (!s.first && s.second) ? 1 : 0;
    summary.lost += (s.first && !s.second) ? 1 : 0;
  }
  return summary;
}

}  // namespace metrofit
