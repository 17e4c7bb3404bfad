#include "core/study/study_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/machine/controller_frame.h"

namespace metrofit {
namespace {

/// What a study (or a block inside one) may hold: key -> the dataset kind it names ("" when the key
/// is not a dataset reference).
using Keys = std::map<std::string, std::string>;

const Keys kSetupKeys = {{"model", dataset_kind::kSetupModel},
                         {"dataset", dataset_kind::kCmmReport},
                         {"method", ""},
                         {"budget", ""},
                         {"seed", ""}};
const Keys kMatchingKeys = {{"dataset", dataset_kind::kProbePoints},
                            {"tolerance_mm", ""},
                            {"method", ""},
                            {"allow_scale", ""},
                            {"seed", ""},
                            {"locks", ""},
                            {"machine", ""},
                            {"frame", ""},
                            {"frame_decimals", ""}};
const Keys kKinematicsKeys = {{"dataset", dataset_kind::kCircularTest},
                              {"simulated_machine", ""},
                              {"spc", ""},
                              {"from_spc", ""},
                              {"planes", ""}};
const Keys kFromSpcKeys = {{"x_dataset", ""},        {"y_dataset", ""},   {"position_column", ""},
                           {"deviation_column", ""}, {"x_nominal_y", ""}, {"y_nominal_x", ""},
                           {"subgroup", ""},         {"coverage", ""}};
/// Any CSV dataset: the YZ and ZX tests have their plane's columns, not a circular_test's.
const Keys kPlanesKeys = {{"xy", ""}, {"yz", ""}, {"zx", ""}};
const Keys kSpcKeys = {{"dataset", ""}, {"column", ""},  {"subgroup", ""}, {"lsl", ""},
                       {"usl", ""},     {"nominal", ""}, {"coverage", ""}};
const Keys kThermalKeys = {{"dataset", dataset_kind::kThermalLog},
                           {"target", ""},
                           {"inputs", ""},
                           {"train_fraction", ""},
                           {"seed", ""},
                           {"modules", ""}};
/// studies.thermal.modules.<module>: the test the module is identified on (core/study/thermal_comparison.h).
const Keys kThermalModuleKeys = {{"dataset", dataset_kind::kThermalLog}};
const std::map<std::string, Keys> kDiagnosisKeys = {
    {"thermal",
     {{"dataset", dataset_kind::kThermalLog},
      {"target", ""},
      {"inputs", ""},
      {"train_fraction", ""},
      {"applied", ""}}},
    {"kinematic", {{"dataset", dataset_kind::kCircularTest}, {"feed_mm_per_min", ""}, {"applied", ""}}},
    {"setup", {{"dataset", dataset_kind::kCmmReport}, {"model", dataset_kind::kSetupModel}, {"applied", ""}}},
    {"matching", {{"dataset", dataset_kind::kProbePoints}, {"tolerance_mm", ""}, {"applied", ""}}},
};

std::string joinKeys(const Keys& keys) {
  std::string s;
  for (const auto& [k, kind] : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

class Checker {
 public:
  explicit Checker(const Project& p) : project_(p) {}
  std::vector<StudyIssue> issues;

  void add(const std::string& field, const std::string& message) { issues.push_back({field, message}); }

  /// Unknown keys, dataset references of `block` (an object) at `prefix`.
  void block(const nlohmann::json& j, const std::string& prefix, const Keys& keys) {
    if (!j.is_object()) {
      add(prefix, "must be an object of settings");
      return;
    }
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string field = prefix + "." + it.key();
      if (it.key() == "notes") continue;
      const auto known = keys.find(it.key());
      if (known == keys.end()) {
        add(field, "is not a setting of this study (known: " + joinKeys(keys) + ", notes)");
        continue;
      }
      if (!known->second.empty() || it.key() == "dataset") dataset(*it, field, known->second);
    }
  }

  void dataset(const nlohmann::json& v, const std::string& field, const std::string& kind) {
    if (!v.is_string() || v.get<std::string>().empty()) {
      add(field, "must be the id of a dataset of the project");
      return;
    }
    const std::string id = v.get<std::string>();
    const DatasetRef* d = project_.dataset(id);
    if (d == nullptr) {
      add(field, "names the dataset '" + id + "', which the project does not have");
    } else if (!kind.empty() && d->kind != kind) {
      add(field, "names '" + id + "', a " + d->kind + " dataset; it must be a " + kind + " dataset");
    }
  }

  void number(const nlohmann::json& j, const std::string& key, const std::string& prefix, double lo,
              double hi, const std::string& range) {
    const auto it = j.find(key);
    if (it == j.end()) return;
    if (!it->is_number() || !std::isfinite(it->get<double>()) || !(it->get<double>() > lo) ||
        !(it->get<double>() < hi))
      add(prefix + "." + key, "must be a number " + range);
  }

  void seed(const nlohmann::json& j, const std::string& prefix) {
    const auto it = j.find("seed");
    if (it != j.end() && !it->is_number_unsigned()) add(prefix + ".seed", "must be an integer >= 0");
  }

  void text(const nlohmann::json& j, const std::string& key, const std::string& prefix) {
    const auto it = j.find(key);
    if (it != j.end() && (!it->is_string() || it->get<std::string>().empty()))
      add(prefix + "." + key, "must be a non-empty text");
  }

  /// studies.matching.frame (a control of core/machine/controller_frame.h) and .frame_decimals (0..12):
  /// the control and decimals of the matching page's controller frame and of the report's frame listing.
  void frame(const nlohmann::json& j, const std::string& prefix) {
    if (const auto it = j.find("frame"); it != j.end()) {
      std::string names;
      bool known = false;
      for (const std::string& n : machine::frameFormatNames()) {
        names += (names.empty() ? "" : ", ") + n;
        known = known || (it->is_string() && it->get<std::string>() == n);
      }
      if (!known) add(prefix + ".frame", "must be one of " + names);
    }
    if (const auto it = j.find("frame_decimals"); it != j.end()) {
      if (!it->is_number_integer() || it->get<long long>() < 0 || it->get<long long>() > 12)
        add(prefix + ".frame_decimals", "must be an integer in 0..12");
    }
  }

  void names(const nlohmann::json& j, const std::string& key, const std::string& prefix) {
    const auto it = j.find(key);
    if (it == j.end()) return;
    bool ok = it->is_array() && !it->empty();
    if (ok)
      for (const auto& v : *it) ok = ok && v.is_string() && !v.get<std::string>().empty();
    if (!ok) add(prefix + "." + key, "must be a non-empty list of column names");
  }

 private:
  const Project& project_;
};

}  // namespace

const std::vector<std::string>& knownDatasetKinds() {
  static const std::vector<std::string> kinds = {dataset_kind::kThermalLog,
                                                 dataset_kind::kProbePoints,
                                                 dataset_kind::kCircularTest,
                                                 dataset_kind::kCmmReport,
                                                 dataset_kind::kSetupModel,
                                                 dataset_kind::kFeatureSeries,
                                                 "dmis",
                                                 "hole_table"};
  return kinds;
}

std::vector<StudyIssue> checkStudies(const Project& project) {
  Checker c(project);
  const auto& kinds = knownDatasetKinds();
  for (std::size_t i = 0; i < project.datasets.size(); ++i) {
    const std::string& kind = project.datasets[i].kind;
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
      std::string list;
      for (const auto& k : kinds) list += (list.empty() ? "" : ", ") + k;
      c.add("datasets[" + std::to_string(i) + "].kind", "'" + kind + "' (dataset '" + project.datasets[i].id +
                                                            "') is not a dataset kind (one of: " + list +
                                                            ")");
    }
  }
  if (!project.studies.is_object()) {
    c.add("studies", "must be an object");
    return c.issues;
  }
  for (auto it = project.studies.begin(); it != project.studies.end(); ++it) {
    const std::string name = it.key();
    const std::string prefix = "studies." + name;
    const nlohmann::json& s = *it;
    if (name == study::kSetup) {
      c.block(s, prefix, kSetupKeys);
      if (!s.is_object()) continue;
      c.text(s, "method", prefix);
      c.number(s, "budget", prefix, 0.0, 1e12, "> 0 (solutions)");
      c.seed(s, prefix);
    } else if (name == study::kMatching) {
      c.block(s, prefix, kMatchingKeys);  // values: core/study/matching_study.cpp checks them in full
      if (!s.is_object()) continue;
      c.frame(s, prefix);
    } else if (name == study::kKinematics) {
      c.block(s, prefix, kKinematicsKeys);
      if (s.is_object() && s.contains("spc")) {
        c.block(s["spc"], prefix + ".spc", kSpcKeys);
        if (s["spc"].is_object()) c.text(s["spc"], "column", prefix + ".spc");
      }
      if (s.is_object() && s.contains("from_spc")) {
        c.block(s["from_spc"], prefix + ".from_spc", kFromSpcKeys);
        if (s["from_spc"].is_object()) {
          for (const char* key : {"x_dataset", "y_dataset"}) {
            if (s["from_spc"].contains(key)) c.dataset(s["from_spc"][key], prefix + ".from_spc." + key, "");
          }
        }
      }
      if (s.is_object() && s.contains("planes")) {
        c.block(s["planes"], prefix + ".planes", kPlanesKeys);
        if (s["planes"].is_object()) {
          for (const char* key : {"xy", "yz", "zx"}) {
            if (s["planes"].contains(key)) c.dataset(s["planes"][key], prefix + ".planes." + key, "");
          }
        }
      }
    } else if (name == study::kThermal) {
      c.block(s, prefix, kThermalKeys);
      if (!s.is_object()) continue;
      c.text(s, "target", prefix);
      c.names(s, "inputs", prefix);
      c.number(s, "train_fraction", prefix, 0.0, 1.0, "between 0 and 1 (the fitted share of the rows)");
      c.seed(s, prefix);
      if (const auto modules = s.find("modules"); modules != s.end()) {
        if (!modules->is_object()) {
          c.add(prefix + ".modules", "must be an object: a module's name -> {\"dataset\": ID}");
        } else {
          for (auto m = modules->begin(); m != modules->end(); ++m)
            c.block(*m, prefix + ".modules." + m.key(), kThermalModuleKeys);
        }
      }
    } else if (name == study::kDiagnosis) {
      if (!s.is_object()) {
        c.add(prefix, "must be an object of settings");
        continue;
      }
      for (auto d = s.begin(); d != s.end(); ++d) {
        if (d.key() == "notes") continue;
        const auto keys = kDiagnosisKeys.find(d.key());
        if (keys == kDiagnosisKeys.end()) {
          c.add(prefix + "." + d.key(),
                "is not a diagnosis domain (one of: kinematic, matching, setup, thermal)");
          continue;
        }
        c.block(*d, prefix + "." + d.key(), keys->second);
      }
    } else {
      c.add(prefix, "is not a study (one of: setup, matching, kinematics, thermal, diagnosis)");
    }
  }
  return c.issues;
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
