#include "core/study/diagnosis_study.h"

#include "core/diagnose/applied_setup_matching.h"

#include <cmath>

#include "core/common/error.h"
#include "core/diagnose/applied_entries.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/io/csv.h"
#include "core/kinematics/measured_path.h"
#include "core/matching/hole_table.h"
#include "core/project/nominals.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/study/study_settings.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& field, const std::string& what) {
  throw ValidationError(ErrorContext{source, 0, 0, field}, what);
}

/// The dataset with this id, resolved; ValidationError when the project has none.
const DatasetRef& datasetOf(const Project& project, const std::string& id, const std::string& source,
                            const std::string& field) {
  const DatasetRef* d = project.dataset(id);
  if (!d) fail(source, field, "names the dataset '" + id + "', which the project does not have");
  return *d;
}

}  // namespace

const char* diagnosisDomainKey(DiagnosisDomain domain) {
  switch (domain) {
    case DiagnosisDomain::Thermal:
      return "thermal";
    case DiagnosisDomain::Kinematic:
      return "kinematic";
    case DiagnosisDomain::Setup:
      return "setup";
    case DiagnosisDomain::Matching:
      return "matching";
  }
  return "thermal";
}

std::string diagnosisSettingsKey(const DiagnosisSettings& s) {
  const nlohmann::json key = {
      {"d", diagnosisDomainKey(s.domain)},
      {"p", s.datasetPath},
      {"nom",
       {s.nominals.from, s.nominals.element, s.nominals.criterion, s.nominals.radiusMm, s.nominals.robust,
        s.nominals.inner, s.nominals.reference, s.nominals.pair, s.referencePath, s.referenceCsv.columnMap,
        static_cast<int>(s.referenceCsv.dialect.delimiter), static_cast<int>(s.referenceCsv.dialect.decimal),
        s.referenceCsv.headerLines}},
      {"csv",
       {static_cast<int>(s.csv.dialect.delimiter), static_cast<int>(s.csv.dialect.decimal), s.csv.columnMap,
        s.csv.headerLines, s.csv.commentPrefix, s.csv.skipBadRows}},
      {"dmis", {setup::dmisTaMeaningName(s.dmis.taMeaning), s.dmis.signFollowsNominal}},
      {"t", s.target},
      {"i", s.inputs},
      {"f", s.trainFraction},
      {"m", s.modelPath},
      {"tol", s.toleranceMm},
      {"feed", s.feedMmPerMin}};
  return key.dump();
}

bool hasDiagnosisSettings(const Project& project, DiagnosisDomain domain) {
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object()) return false;
  const auto d = s->find(diagnosisDomainKey(domain));
  return d != s->end() && d->is_object();
}

DiagnosisSettings diagnosisSettings(const Project& project, const std::string& projectPath,
                                    DiagnosisDomain domain) {
  const std::string key = diagnosisDomainKey(domain);
  const std::string prefix = std::string("studies.") + study::kDiagnosis + "." + key + ".";
  const std::string& source = projectPath;
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object())
    fail(source, std::string("studies.") + study::kDiagnosis,
         "is missing: the project has no diagnosis study");
  const auto it = s->find(key);
  if (it == s->end() || !it->is_object())
    fail(source, prefix.substr(0, prefix.size() - 1),
         "is missing: no " + key + " data configured for diagnosis");
  // The keys, their defaults and checks: one owner (core/study/study_settings.h DiagnosisDomainSettings).
  const DiagnosisDomainSettings block = DiagnosisDomainSettings::fromJson(*it, key, source);

  DiagnosisSettings out;
  out.domain = domain;
  out.datasetId = block.dataset;
  const DatasetRef& dataset = datasetOf(project, out.datasetId, source, prefix + "dataset");
  out.datasetPath = resolveDatasetPath(projectPath, dataset);
  out.datasetPaths = resolveDatasetPaths(projectPath, dataset);
  out.csv = dataset.csv;
  out.dmis = dataset.dmis;
  out.nominals = dataset.nominals;
  if (const DatasetRef* reference = nominalReference(project, dataset)) {
    out.referencePath = resolveDatasetPath(projectPath, *reference);
    out.referenceCsv = reference->csv;
  }
  out.target = block.target;
  out.inputs = block.inputs;
  out.trainFraction = block.trainFraction;
  out.feedMmPerMin = block.feedMmPerMin;
  out.toleranceMm = block.toleranceMm;
  if (domain == DiagnosisDomain::Setup) {
    out.modelId = block.model;
    out.modelPath =
        resolveDatasetPath(projectPath, datasetOf(project, out.modelId, source, prefix + "model"));
  }
  out.applied = block.applied;
  return out;
}

diagnose::Diagnosis runDiagnosis(const DiagnosisSettings& s, Observer* observer) {
  switch (s.domain) {
    case DiagnosisDomain::Thermal: {
      const ThermalLog log = readThermalLog(s.datasetPath, 3, s.csv);
      diagnose::ThermalDiagnosisOptions o;
      o.target = s.target;
      o.inputs = s.inputs;
      o.trainFraction = s.trainFraction;
      return diagnose::diagnoseThermal(log, o, observer);
    }
    case DiagnosisDomain::Kinematic: {
      const MeasuredPath path = readMeasuredPath(s.datasetPath, s.csv);
      diagnose::KinematicDiagnosisOptions o;
      o.feedMmPerMin = s.feedMmPerMin;
      return diagnose::diagnoseKinematic(path, o, observer);
    }
    case DiagnosisDomain::Setup: {
      const setup::Model model = setup::readModel(s.modelPath);
      const setup::Measurements m = setup::readMeasurements(
          s.datasetPaths.empty() ? std::vector<std::string>{s.datasetPath} : s.datasetPaths, model, s.csv,
          s.dmis);
      return diagnose::diagnoseSetup(model, m, {}, observer);
    }
    case DiagnosisDomain::Matching: {
      DatasetRef points;
      points.id = s.datasetId;
      points.kind = dataset_kind::kProbePoints;
      points.path = s.datasetPath;
      points.csv = s.csv;
      points.nominals = s.nominals;
      DatasetRef reference;
      reference.id = s.nominals.reference;
      reference.kind = dataset_kind::kProbePoints;
      reference.path = s.referencePath;
      reference.csv = s.referenceCsv;
      const ProbePointSet set =
          readProbePointDataset(points, s.referencePath.empty() ? nullptr : &reference, 3);
      diagnose::MatchingDiagnosisOptions o;
      o.toleranceMm = s.toleranceMm;
      return diagnose::diagnoseMatching(set, o, observer);
    }
  }
  return {};
}

bool canApplyEffect(const std::string& domain, const diagnose::Candidate& c) {
  if (!c.generic.has_value() || domain == "thermal") return true;
  if (c.genericCoefficients.empty()) return false;
  return domain == "kinematic" || domain == "matching" ||
         (domain == "setup" && diagnose::setupGenericPredictsNextPart(c.generic->against));
}

nlohmann::json appliedEffects(const diagnose::Diagnosis& diagnosis) {
  nlohmann::json out = nlohmann::json::array();
  for (const diagnose::Candidate* c : diagnosis.accepted()) {
    if (!canApplyEffect(diagnosis.domain, *c)) continue;
    nlohmann::json params = nlohmann::json::object();
    for (const diagnose::Parameter& p : c->parameters) {
      if (const double* v = std::get_if<double>(&p.value))
        params[p.name] = *v;
      else
        params[p.name] = std::get<std::string>(p.value);
    }
    nlohmann::json entry = {{"name", c->name}, {"parameters", params}};
    if (c->generic) entry["shape"] = diagnose::genericShapeJson(*c->generic);
    if (!c->genericCoefficients.empty()) entry["coefficients"] = c->genericCoefficients;
    out.push_back(std::move(entry));
  }
  return out;
}

std::string formatParameterValue(const diagnose::Parameter& parameter, int digits) {
  if (const double* v = std::get_if<double>(&parameter.value)) return CsvWriter::formatNumber(*v, digits);
  return std::get<std::string>(parameter.value);
}

}  // namespace metrofit
