#include "core/study/study_check.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/project/datasets.h"

namespace metrofit {
const std::vector<std::string>& knownDatasetKinds() {
  // The project file's spelling of the kinds core/project/datasets.h reads: one list.
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> out;
    for (const std::string& name : datasetKindNames()) out.push_back(datasetKindFromName(name));
    return out;
  }();
  return kinds;
}

std::vector<StudyIssue> checkStudies(const Project& project) {
  std::vector<StudyIssue> issues;
  const auto& kinds = knownDatasetKinds();
  for (std::size_t i = 0; i < project.datasets.size(); ++i) {
    const std::string& kind = project.datasets[i].kind;
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
      std::string list;
      for (const auto& k : kinds) list += (list.empty() ? "" : ", ") + k;
      issues.push_back({"datasets[" + std::to_string(i) + "].kind",
                        "'" + kind + "' (dataset '" + project.datasets[i].id +
                            "') is not a dataset kind (one of: " + list + ")"});
    }
  }
  if (!project.studies.is_object()) {
    issues.push_back({"studies", "must be an object"});
    return issues;
  }
  // A dataset reference names a dataset of the project, of the field's kind when it has one.
  const DatasetCheck dataset = [&](const nlohmann::json& v, const std::string& field,
                                   const std::string& kind) {
    const std::string id = v.get<std::string>();
    const DatasetRef* d = project.dataset(id);
    if (d == nullptr) {
      issues.push_back({field, "names the dataset '" + id + "', which the project does not have"});
    } else if (!kind.empty()) {
      const std::vector<std::string> serving = datasetKindsServing(kind);
      if (std::find(serving.begin(), serving.end(), d->kind) == serving.end()) {
        std::string also;
        for (std::size_t k = 1; k < serving.size(); ++k) also += (k > 1 ? ", " : " (or ") + serving[k];
        if (!also.empty()) also += ")";
        issues.push_back({field, "names '" + id + "', a " + d->kind + " dataset; it must be a " + kind +
                                     also + " dataset"});
      }
    }
  };
  const auto& types = studyTypes();
  for (auto it = project.studies.begin(); it != project.studies.end(); ++it) {
    const std::string prefix = "studies." + it.key();
    const auto type =
        std::find_if(types.begin(), types.end(), [&](const StudyType& t) { return it.key() == t.name; });
    if (type == types.end()) {
      issues.push_back({prefix, "is not a study (one of: setup, matching, kinematics, thermal, diagnosis)"});
    } else if (type->fields != nullptr) {
      const std::size_t before = issues.size();
      checkSettingsBlock(*it, prefix, *type->fields, issues, dataset);
      // The rules between keys, on keys that are good each (one issue at a time: no echo of a bad key).
      if (issues.size() == before && type->checkBlock != nullptr) type->checkBlock(*it, issues);
    } else if (!it->is_object()) {
      issues.push_back({prefix, "must be an object of settings"});
    } else {
      for (auto d = it->begin(); d != it->end(); ++d) {
        if (d.key() == "notes") continue;
        const auto keys = type->domains->find(d.key());
        if (keys == type->domains->end()) {
          issues.push_back({prefix + "." + d.key(),
                            "is not a diagnosis domain (one of: kinematic, matching, setup, thermal)"});
          continue;
        }
        checkSettingsBlock(*d, prefix + "." + d.key(), keys->second, issues, dataset);
      }
    }
  }
  return issues;
}

std::vector<StudyIssue> checkStudyColumns(const Project& project, const DatasetColumns& columns) {
  std::vector<StudyIssue> issues;
  if (!columns || !project.studies.is_object()) return issues;
  // target / inputs of a block naming a dataset: each must be a column of it.
  const auto checkBlock = [&](const nlohmann::json& j, const std::string& prefix,
                              std::initializer_list<const char*> keys, const std::string& datasetKey) {
    if (!j.is_object()) return;
    const auto d = j.find(datasetKey);
    if (d == j.end() || !d->is_string()) return;
    const std::vector<std::string>* cols = columns(d->get<std::string>());
    if (cols == nullptr) return;
    std::string have;
    for (const auto& c : *cols) have += (have.empty() ? "" : ", ") + c;
    for (const char* key : keys) {
      const auto v = j.find(key);
      if (v == j.end()) continue;
      std::vector<std::string> named;
      if (v->is_string()) named.push_back(v->get<std::string>());
      if (v->is_array())
        for (const auto& e : *v)
          if (e.is_string()) named.push_back(e.get<std::string>());
      for (const std::string& n : named) {
        if (std::find(cols->begin(), cols->end(), n) == cols->end()) {
          issues.push_back({prefix + "." + key, "names the column '" + n + "', which '" +
                                                    d->get<std::string>() +
                                                    "' does not have (it has: " + have + ")"});
        }
      }
    }
  };
  const nlohmann::json& s = project.studies;
  if (const auto t = s.find(study::kThermal); t != s.end())
    checkBlock(*t, std::string("studies.") + study::kThermal, {"target", "inputs"}, "dataset");
  if (const auto d = s.find(study::kDiagnosis); d != s.end() && d->is_object())
    if (const auto t = d->find("thermal"); t != d->end())
      checkBlock(*t, std::string("studies.") + study::kDiagnosis + ".thermal", {"target", "inputs"},
                 "dataset");
  if (const auto k = s.find(study::kKinematics); k != s.end() && k->is_object())
    if (const auto spc = k->find("spc"); spc != k->end())
      checkBlock(*spc, std::string("studies.") + study::kKinematics + ".spc", {"column"}, "dataset");
  return issues;
}

void validateStudies(const Project& project, const std::string& source, const DatasetColumns& columns) {
  std::vector<StudyIssue> issues = checkStudies(project);
  if (issues.empty() && columns) issues = checkStudyColumns(project, columns);
  if (!issues.empty())
    throw ValidationError(ErrorContext{source, 0, 0, issues.front().field}, issues.front().message);
}

}  // namespace metrofit
