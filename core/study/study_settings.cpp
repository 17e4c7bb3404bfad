#include "core/study/study_settings.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification3.h"
#include "core/matching/pose.h"
#include "core/project/project.h"
#include "core/spc/control_chart.h"

namespace metrofit {
namespace {

using json = nlohmann::json;

// ---- value checks (the messages the validator has always given) ---------------------------------------

std::function<std::string(const json&)> text() {
  return [](const json& v) {
    return v.is_string() && !v.get<std::string>().empty() ? std::string() : "must be a non-empty text";
  };
}

std::function<std::string(const json&)> seedValue() {
  return [](const json& v) {
    return v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0)
               ? std::string()
               : "must be an integer >= 0";
  };
}

/// A finite number in the open interval (lo, hi).
std::function<std::string(const json&)> numberIn(double lo, double hi, std::string range) {
  return [lo, hi, range](const json& v) {
    const bool ok =
        v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() > lo && v.get<double>() < hi;
    return ok ? std::string() : "must be a number " + range;
  };
}

std::function<std::string(const json&)> columnNames() {
  return [](const json& v) {
    bool ok = v.is_array() && !v.empty();
    if (ok)
      for (const auto& e : v) ok = ok && e.is_string() && !e.get<std::string>().empty();
    return ok ? std::string() : "must be a non-empty list of column names";
  };
}

std::function<std::string(const json&)> oneOf(std::vector<std::string> names) {
  return [names](const json& v) {
    if (v.is_string() && std::find(names.begin(), names.end(), v.get<std::string>()) != names.end())
      return std::string();
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    return "must be one of " + list;
  };
}

std::string joinKeys(const std::vector<SettingField>& fields) {
  std::vector<std::string> keys;
  for (const SettingField& f : fields) keys.push_back(f.key);
  std::sort(keys.begin(), keys.end());
  std::string s;
  for (const std::string& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

SettingField datasetField(std::string key, std::string kind) {
  SettingField f;
  f.key = std::move(key);
  f.dataset = true;
  f.datasetKind = std::move(kind);
  return f;
}

SettingField valueField(std::string key, std::function<std::string(const json&)> check = {}) {
  SettingField f;
  f.key = std::move(key);
  f.check = std::move(check);
  return f;
}

SettingField blockField(std::string key, const std::vector<SettingField>* block, bool perEntry = false) {
  SettingField f;
  f.key = std::move(key);
  f.block = block;
  f.blockPerEntry = perEntry;
  return f;
}

[[noreturn]] void throwFirst(const std::vector<SettingIssue>& issues, const std::string& source) {
  throw ValidationError(ErrorContext{source, 0, 0, issues.front().field}, issues.front().message);
}

/// The study block of `study` checked against `fields` (without the project: dataset references are
/// only checked to be texts); ValidationError for the first issue.
void requireValid(const json& study, const char* name, const std::vector<SettingField>& fields,
                  const std::string& source) {
  if (study.is_null()) return;
  std::vector<SettingIssue> issues;
  checkSettingsBlock(study, std::string("studies.") + name, fields, issues);
  if (!issues.empty()) throwFirst(issues, source);
}

bool invalid(std::string* field, std::string* why, const char* study, const std::string& key,
             const std::string& message) {
  if (field) *field = std::string("studies.") + study + "." + key;
  if (why) *why = message;
  return false;
}

const std::vector<std::string>& matchMethodNames() {
  static const std::vector<std::string> names = {"sade", "ga-simplex", "closed-form", "minimax"};
  return names;
}

}  // namespace

void checkSettingsBlock(const json& j, const std::string& prefix, const std::vector<SettingField>& fields,
                        std::vector<SettingIssue>& issues, const DatasetCheck& dataset) {
  if (!j.is_object()) {
    issues.push_back({prefix, "must be an object of settings"});
    return;
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string field = prefix + "." + it.key();
    if (it.key() == "notes") continue;
    const auto known =
        std::find_if(fields.begin(), fields.end(), [&](const SettingField& f) { return f.key == it.key(); });
    if (known == fields.end()) {
      issues.push_back({field, "is not a setting of this study (known: " + joinKeys(fields) + ", notes)"});
      continue;
    }
    if (known->dataset) {
      if (!it->is_string() || it->get<std::string>().empty())
        issues.push_back({field, "must be the id of a dataset of the project"});
      else if (dataset)
        dataset(*it, field, known->datasetKind);
    } else if (known->block != nullptr && known->blockPerEntry) {
      if (!it->is_object()) {
        issues.push_back({field, "must be an object: a module's name -> {\"dataset\": ID}"});
        continue;
      }
      for (auto m = it->begin(); m != it->end(); ++m)
        checkSettingsBlock(*m, field + "." + m.key(), *known->block, issues, dataset);
    } else if (known->block != nullptr) {
      checkSettingsBlock(*it, field, *known->block, issues, dataset);
    } else if (known->check) {
      if (std::string message = known->check(*it); !message.empty()) issues.push_back({field, message});
    }
  }
}

// ---- setup --------------------------------------------------------------------------------------------

const std::vector<SettingField>& SetupSettings::fields() {
  static const std::vector<SettingField> f = {
      datasetField("model", dataset_kind::kSetupModel), datasetField("dataset", dataset_kind::kCmmReport),
      valueField("method", oneOf(setup::setupMethodNames())),
      valueField("budget", numberIn(0.0, 1e12, "> 0 (solutions)")), valueField("seed", seedValue())};
  return f;
}

SetupSettings SetupSettings::fromJson(const json& j, const std::string& source) {
  requireValid(j, kStudy, fields(), source);
  SetupSettings s;
  if (!j.is_object()) return s;
  s.model = j.value("model", std::string());
  s.dataset = j.value("dataset", std::string());
  s.method = j.value("method", s.method);
  if (const auto b = j.find("budget"); b != j.end()) s.budget = static_cast<long>(b->get<double>());
  if (const auto v = j.find("seed"); v != j.end()) s.seed = v->get<std::uint64_t>();
  return s;
}

json SetupSettings::toJson() const {
  const SetupSettings d;
  json j = json::object();
  if (!model.empty()) j["model"] = model;
  if (!dataset.empty()) j["dataset"] = dataset;
  if (method != d.method) j["method"] = method;
  if (budget != d.budget) j["budget"] = budget;
  if (seed != d.seed) j["seed"] = seed;
  return j;
}

bool SetupSettings::isValid(std::string* field, std::string* why) const {
  const auto names = setup::setupMethodNames();
  if (std::find(names.begin(), names.end(), method) == names.end())
    return invalid(field, why, kStudy, "method", oneOf(names)(json()));
  if (budget <= 0) return invalid(field, why, kStudy, "budget", "must be a number > 0 (solutions)");
  return true;
}

// ---- matching -----------------------------------------------------------------------------------------

const std::vector<SettingField>& MatchingSettings::fields() {
  static const std::vector<SettingField> f = {
      datasetField("dataset", dataset_kind::kProbePoints),
      valueField("tolerance_mm",
                 [](const json& v) {
                   return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= 0.0
                              ? std::string()
                              : "must be a number >= 0 (mm)";
                 }),
      valueField("method",
                 [](const json& v) -> std::string {
                   if (!v.is_string()) return "must be one of sade, ga-simplex, closed-form, minimax";
                   if (oneOf(matchMethodNames())(v).empty()) return {};
                   return "unknown matching method '" + v.get<std::string>() +
                          "' (one of sade, ga-simplex, closed-form, minimax)";
                 }),
      valueField("allow_scale",
                 [](const json& v) { return v.is_boolean() ? std::string() : "must be true or false"; }),
      valueField("seed", seedValue()),
      valueField("locks",
                 [](const json& v) -> std::string {
                   if (!v.is_string()) return "must be a list of rx, ry, rz, x, y, z (string, e.g. \"rz,z\")";
                   try {
                     matching::DofLocks::parse(v.get<std::string>(), "locks");
                   } catch (const Error& e) {
                     return e.detail();
                   }
                   return {};
                 }),
      valueField("machine"),  // project.h matchingMachine checks it (Project::fromJson)
      valueField("frame", oneOf(machine::frameFormatNames())),
      valueField("frame_decimals", [](const json& v) {
        return v.is_number_integer() && v.get<long long>() >= 0 && v.get<long long>() <= 12
                   ? std::string()
                   : "must be an integer in 0..12";
      })};
  return f;
}

MatchingSettings MatchingSettings::fromJson(const json& j, const std::string& source) {
  requireValid(j, kStudy, fields(), source);
  MatchingSettings s;
  if (!j.is_object()) return s;
  s.dataset = j.value("dataset", std::string());
  if (const auto v = j.find("tolerance_mm"); v != j.end()) s.toleranceMm = v->get<double>();
  if (const auto v = j.find("method"); v != j.end())
    s.method = matching::parseMatchMethod(v->get<std::string>(), std::string("studies.matching.method"));
  s.allowScale = j.value("allow_scale", false);
  if (const auto v = j.find("seed"); v != j.end()) s.seed = v->get<std::uint64_t>();
  s.locks = j.value("locks", std::string());
  if (const auto v = j.find("frame"); v != j.end())
    s.frame = machine::parseFrameFormat(v->get<std::string>(), "studies.matching.frame");
  if (const auto v = j.find("frame_decimals"); v != j.end()) s.frameDecimals = v->get<int>();
  return s;
}

json MatchingSettings::toJson() const {
  const MatchingSettings d;
  json j = json::object();
  if (!dataset.empty()) j["dataset"] = dataset;
  if (toleranceMm != d.toleranceMm) j["tolerance_mm"] = toleranceMm;
  if (method != d.method) j["method"] = matching::toString(method);
  if (allowScale) j["allow_scale"] = true;
  if (seed != d.seed) j["seed"] = seed;
  if (!locks.empty()) j["locks"] = locks;
  if (frame != d.frame) j["frame"] = machine::toString(frame);
  if (frameDecimals != d.frameDecimals) j["frame_decimals"] = frameDecimals;
  return j;
}

bool MatchingSettings::isValid(std::string* field, std::string* why) const {
  if (!(toleranceMm >= 0.0) || !std::isfinite(toleranceMm))
    return invalid(field, why, kStudy, "tolerance_mm", "must be a number >= 0 (mm)");
  if (frameDecimals < 0 || frameDecimals > 12)
    return invalid(field, why, kStudy, "frame_decimals", "must be an integer in 0..12");
  try {
    matching::DofLocks::parse(locks, "locks");
  } catch (const Error& e) {
    return invalid(field, why, kStudy, "locks", e.detail());
  }
  return true;
}

// ---- kinematics ---------------------------------------------------------------------------------------

namespace {

std::string finiteNumber(const json& v, const std::string& what) {
  return v.is_number() && std::isfinite(v.get<double>()) ? std::string() : "must be " + what;
}

/// "subgroup" of the SPC blocks: the range of the A2/D3/D4 table.
std::string subgroupCheck(const json& v) {
  return v.is_number_integer() && v.get<long long>() >= kMinSubgroupSize &&
                 v.get<long long>() <= kMaxSubgroupSize
             ? std::string()
             : "must be an integer between 2 and 25 (the range of the A2/D3/D4 table)";
}

std::string coverageCheck(const json& v) {
  return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() > 0.0
             ? std::string()
             : "must be a number > 0 (the coverage factor k)";
}

std::string angleCheck(const json& v) {
  const double limit = ActuatorErrors2::kMaxAngleDeg;
  return v.is_number() && std::isfinite(v.get<double>()) && std::abs(v.get<double>()) <= limit
             ? std::string()
             : "must be a number within +-45 deg (an orientation error of the actuator)";
}

std::string originCheck(const json& v) {
  const bool ok = v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() &&
                  std::isfinite(v[0].get<double>()) && std::isfinite(v[1].get<double>());
  return ok ? std::string() : "must be [x, y] in mm";
}

const char* const kKinematicsPrefix = "studies.kinematics";

}  // namespace

const std::vector<SettingField>& KinematicsSettings::fields() {
  static const std::vector<SettingField> machine = {valueField("origin_mm", originCheck),
                                                    valueField("x_axis_angle_deg", angleCheck),
                                                    valueField("y_axis_angle_deg", angleCheck)};
  static const std::vector<SettingField> spc = {
      datasetField("dataset", ""),
      valueField("column", text()),
      valueField("subgroup", subgroupCheck),
      valueField("lsl",
                 [](const json& v) { return finiteNumber(v, "a number (the lower specification limit)"); }),
      valueField("usl",
                 [](const json& v) { return finiteNumber(v, "a number (the upper specification limit)"); }),
      valueField("nominal", [](const json& v) { return finiteNumber(v, "a number (the desired value)"); }),
      valueField("coverage", coverageCheck)};
  static const std::vector<SettingField> fromSpc = {
      datasetField("x_dataset", ""),
      datasetField("y_dataset", ""),
      valueField("position_column", text()),
      valueField("deviation_column", text()),
      valueField("x_nominal_y", [](const json& v) { return finiteNumber(v, "a number (mm)"); }),
      valueField("y_nominal_x", [](const json& v) { return finiteNumber(v, "a number (mm)"); }),
      valueField("subgroup", subgroupCheck),
      valueField("coverage", coverageCheck)};
  /// Any CSV dataset: the YZ and ZX tests have their plane's columns, not a circular_test's.
  static const std::vector<SettingField> planes = {datasetField("xy", ""), datasetField("yz", ""),
                                                   datasetField("zx", "")};
  static const std::vector<SettingField> f = {
      datasetField("dataset", dataset_kind::kCircularTest), blockField("simulated_machine", &machine),
      blockField("spc", &spc), blockField("from_spc", &fromSpc), blockField("planes", &planes)};
  return f;
}

void KinematicsSettings::checkBlock(const json& j, std::vector<SettingIssue>& issues) {
  if (!j.is_object()) return;
  const std::string prefix = kKinematicsPrefix;
  if (const auto m = j.find("simulated_machine"); m != j.end() && m->is_object()) {
    for (const char* key : {"origin_mm", "x_axis_angle_deg", "y_axis_angle_deg"})
      if (!m->contains(key)) issues.push_back({prefix + ".simulated_machine." + key, "missing"});
  }
  if (const auto spc = j.find("spc"); spc != j.end() && spc->is_object()) {
    for (const char* key : {"dataset", "column"})
      if (!spc->contains(key)) issues.push_back({prefix + ".spc." + key, "missing"});
    const bool lsl = spc->contains("lsl"), usl = spc->contains("usl");
    if (lsl != usl) {
      issues.push_back({prefix + ".spc." + (lsl ? "usl" : "lsl"), "give lsl and usl together"});
    } else if (lsl && (*spc)["lsl"].is_number() && (*spc)["usl"].is_number() &&
               !((*spc)["lsl"].get<double>() < (*spc)["usl"].get<double>())) {
      issues.push_back({prefix + ".spc.lsl", "must be below usl"});
    }
  }
}

KinematicsSettings KinematicsSettings::fromJson(const json& j, const std::string& source) {
  requireValid(j, kStudy, fields(), source);
  std::vector<SettingIssue> issues;
  checkBlock(j, issues);
  if (!issues.empty()) throwFirst(issues, source);
  KinematicsSettings s;
  if (!j.is_object()) return s;
  s.dataset = j.value("dataset", std::string());
  if (const auto m = j.find("simulated_machine"); m != j.end()) {
    SimulatedMachine machine;
    machine.originXMm = (*m)["origin_mm"][0].get<double>();
    machine.originYMm = (*m)["origin_mm"][1].get<double>();
    machine.xAxisAngleDeg = (*m)["x_axis_angle_deg"].get<double>();
    machine.yAxisAngleDeg = (*m)["y_axis_angle_deg"].get<double>();
    s.simulatedMachine = machine;
  }
  if (const auto b = j.find("spc"); b != j.end()) {
    Spc spc;
    spc.dataset = (*b)["dataset"].get<std::string>();
    spc.column = (*b)["column"].get<std::string>();
    spc.subgroup = b->value("subgroup", spc.subgroup);
    if (b->contains("lsl")) spc.lsl = (*b)["lsl"].get<double>();
    if (b->contains("usl")) spc.usl = (*b)["usl"].get<double>();
    if (b->contains("nominal")) spc.nominal = (*b)["nominal"].get<double>();
    spc.coverage = b->value("coverage", spc.coverage);
    s.spc = spc;
  }
  if (const auto b = j.find("from_spc"); b != j.end()) {
    FromSpc f;
    f.xDataset = b->value("x_dataset", std::string());
    f.yDataset = b->value("y_dataset", std::string());
    f.positionColumn = b->value("position_column", f.positionColumn);
    f.deviationColumn = b->value("deviation_column", f.deviationColumn);
    f.xNominalY = b->value("x_nominal_y", f.xNominalY);
    f.yNominalX = b->value("y_nominal_x", f.yNominalX);
    f.subgroup = b->value("subgroup", f.subgroup);
    f.coverage = b->value("coverage", f.coverage);
    s.fromSpc = f;
  }
  if (const auto b = j.find("planes"); b != j.end()) {
    std::array<std::string, 3> ids;
    for (const TestPlane plane : kTestPlanes)
      ids[static_cast<std::size_t>(plane)] = b->value(planeName(plane), std::string());
    s.planes = ids;
  }
  return s;
}

json KinematicsSettings::toJson() const {
  json j = json::object();
  if (!dataset.empty()) j["dataset"] = dataset;
  if (simulatedMachine) {
    // The three keys together (the block has no defaults).
    j["simulated_machine"] = {{"origin_mm", {simulatedMachine->originXMm, simulatedMachine->originYMm}},
                              {"x_axis_angle_deg", simulatedMachine->xAxisAngleDeg},
                              {"y_axis_angle_deg", simulatedMachine->yAxisAngleDeg}};
  }
  if (spc) {
    const Spc d;
    json b = {{"dataset", spc->dataset}, {"column", spc->column}};
    if (spc->subgroup != d.subgroup) b["subgroup"] = spc->subgroup;
    if (spc->lsl) b["lsl"] = *spc->lsl;
    if (spc->usl) b["usl"] = *spc->usl;
    if (spc->nominal) b["nominal"] = *spc->nominal;
    if (spc->coverage != d.coverage) b["coverage"] = spc->coverage;
    j["spc"] = std::move(b);
  }
  if (fromSpc) {
    const FromSpc d;
    json b = json::object();
    if (!fromSpc->xDataset.empty()) b["x_dataset"] = fromSpc->xDataset;
    if (!fromSpc->yDataset.empty()) b["y_dataset"] = fromSpc->yDataset;
    if (fromSpc->positionColumn != d.positionColumn) b["position_column"] = fromSpc->positionColumn;
    if (fromSpc->deviationColumn != d.deviationColumn) b["deviation_column"] = fromSpc->deviationColumn;
    if (fromSpc->xNominalY != d.xNominalY) b["x_nominal_y"] = fromSpc->xNominalY;
    if (fromSpc->yNominalX != d.yNominalX) b["y_nominal_x"] = fromSpc->yNominalX;
    if (fromSpc->subgroup != d.subgroup) b["subgroup"] = fromSpc->subgroup;
    if (fromSpc->coverage != d.coverage) b["coverage"] = fromSpc->coverage;
    j["from_spc"] = std::move(b);
  }
  if (planes) {
    json b = json::object();
    for (const TestPlane plane : kTestPlanes)
      if (const std::string& id = (*planes)[static_cast<std::size_t>(plane)]; !id.empty())
        b[planeName(plane)] = id;
    j["planes"] = std::move(b);
  }
  return j;
}

bool KinematicsSettings::isValid(std::string* field, std::string* why) const {
  // The same per-key checks as fields() and the same rules between keys as checkBlock, on the JSON the
  // values write: one place knows them.
  const json j = toJson();
  std::vector<SettingIssue> issues;
  checkSettingsBlock(j, kKinematicsPrefix, fields(), issues);
  if (issues.empty()) checkBlock(j, issues);
  if (issues.empty()) return true;
  if (field) *field = issues.front().field;
  if (why) *why = issues.front().message;
  return false;
}

// ---- thermal ------------------------------------------------------------------------------------------

const std::vector<SettingField>& ThermalSettings::fields() {
  /// studies.thermal.modules.<module>: the test the module is identified on.
  static const std::vector<SettingField> module = {datasetField("dataset", dataset_kind::kThermalLog)};
  static const std::vector<SettingField> f = {
      datasetField("dataset", dataset_kind::kThermalLog),
      valueField("target", text()),
      valueField("inputs", columnNames()),
      valueField("train_fraction", numberIn(0.0, 1.0, "between 0 and 1 (the fitted share of the rows)")),
      valueField("seed", seedValue()),
      blockField("modules", &module, true)};
  return f;
}

ThermalSettings ThermalSettings::fromJson(const json& j, const std::string& source) {
  requireValid(j, kStudy, fields(), source);
  ThermalSettings s;
  if (!j.is_object()) return s;
  s.dataset = j.value("dataset", std::string());
  s.target = j.value("target", std::string());
  if (const auto v = j.find("inputs"); v != j.end()) s.inputs = v->get<std::vector<std::string>>();
  if (const auto v = j.find("train_fraction"); v != j.end()) s.trainFraction = v->get<double>();
  if (const auto v = j.find("seed"); v != j.end()) s.seed = v->get<std::uint64_t>();
  if (const auto m = j.find("modules"); m != j.end())
    for (auto it = m->begin(); it != m->end(); ++it)
      s.modules[it.key()] = it->value("dataset", std::string());
  return s;
}

json ThermalSettings::toJson() const {
  const ThermalSettings d;
  json j = json::object();
  if (!dataset.empty()) j["dataset"] = dataset;
  if (!target.empty()) j["target"] = target;
  if (!inputs.empty()) j["inputs"] = inputs;
  if (trainFraction != d.trainFraction) j["train_fraction"] = trainFraction;
  if (seed != d.seed) j["seed"] = seed;
  for (const auto& [module, id] : modules) j["modules"][module] = {{"dataset", id}};
  return j;
}

bool ThermalSettings::isValid(std::string* field, std::string* why) const {
  if (!(trainFraction > 0.0 && trainFraction < 1.0))
    return invalid(field, why, kStudy, "train_fraction",
                   "must be a number between 0 and 1 (the fitted share of the rows)");
  for (const std::string& in : inputs)
    if (in.empty()) return invalid(field, why, kStudy, "inputs", "must be a non-empty list of column names");
  return true;
}

// ---- diagnosis ----------------------------------------------------------------------------------------

namespace {

/// A finite number in the closed interval [lo, hi].
std::function<std::string(const json&)> numberWithin(double lo, double hi, std::string range) {
  return [lo, hi, range](const json& v) {
    const bool ok =
        v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= lo && v.get<double>() <= hi;
    return ok ? std::string() : "must be a number " + range;
  };
}

constexpr double kMinDiagnosisTrainFraction = 0.05, kMaxDiagnosisTrainFraction = 0.95;
const char* const kTrainFractionRange = "between 0.05 and 0.95 (the fitted share of the rows)";
const char* const kFeedRange = "> 0 (mm/min)";
const char* const kToleranceRange = "> 0 (mm)";

std::function<std::string(const json&)> positive(const char* range) {
  return [range](const json& v) {
    return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() > 0.0
               ? std::string()
               : std::string("must be a number ") + range;
  };
}

std::function<std::string(const json&)> appliedList() {
  return [](const json& v) {
    return v.is_array() ? std::string()
                        : std::string("must be a list of effects ([{\"name\": ..., \"parameters\": {...}}])");
  };
}

std::string diagnosisPrefix(const std::string& domain) {
  return std::string("studies.") + DiagnosisStudySettings::kStudy + "." + domain;
}

}  // namespace

const std::vector<std::string>& DiagnosisDomainSettings::domainNames() {
  static const std::vector<std::string> names = {"thermal", "kinematic", "setup", "matching"};
  return names;
}

const std::vector<SettingField>& DiagnosisDomainSettings::fields(const std::string& domain) {
  static const std::map<std::string, std::vector<SettingField>> d = {
      {"thermal",
       {datasetField("dataset", dataset_kind::kThermalLog), valueField("target", text()),
        valueField("inputs", columnNames()),
        valueField("train_fraction",
                   numberWithin(kMinDiagnosisTrainFraction, kMaxDiagnosisTrainFraction, kTrainFractionRange)),
        valueField("applied", appliedList())}},
      {"kinematic",
       {datasetField("dataset", dataset_kind::kCircularTest),
        valueField("feed_mm_per_min", positive(kFeedRange)), valueField("applied", appliedList())}},
      {"setup",
       {datasetField("dataset", dataset_kind::kCmmReport), datasetField("model", dataset_kind::kSetupModel),
        valueField("applied", appliedList())}},
      {"matching",
       {datasetField("dataset", dataset_kind::kProbePoints),
        valueField("tolerance_mm", positive(kToleranceRange)), valueField("applied", appliedList())}},
  };
  static const std::vector<SettingField> none;
  const auto it = d.find(domain);
  return it == d.end() ? none : it->second;
}

DiagnosisDomainSettings DiagnosisDomainSettings::fromJson(const json& block, const std::string& domain,
                                                          const std::string& source) {
  const std::string prefix = diagnosisPrefix(domain);
  const auto& names = domainNames();
  if (std::find(names.begin(), names.end(), domain) == names.end())
    throw ValidationError(ErrorContext{source, 0, 0, prefix},
                          "is not a domain of the diagnosis (known: kinematic, matching, setup, thermal)");
  std::vector<SettingIssue> issues;
  checkSettingsBlock(block, prefix, fields(domain), issues);
  if (!issues.empty()) throwFirst(issues, source);
  const auto required = [&](const char* key) {
    if (!block.contains(key))
      throw ValidationError(ErrorContext{source, 0, 0, prefix + "." + key}, "is missing");
    return block.at(key).get<std::string>();
  };
  DiagnosisDomainSettings s;
  s.domain = domain;
  s.dataset = required("dataset");
  if (domain == "thermal") {
    s.target = required("target");
    if (!block.contains("inputs"))
      throw ValidationError(ErrorContext{source, 0, 0, prefix + ".inputs"}, "is missing");
    s.inputs = block.at("inputs").get<std::vector<std::string>>();
    if (const auto v = block.find("train_fraction"); v != block.end()) s.trainFraction = v->get<double>();
  } else if (domain == "kinematic") {
    if (const auto v = block.find("feed_mm_per_min"); v != block.end()) s.feedMmPerMin = v->get<double>();
  } else if (domain == "setup") {
    s.model = required("model");
  } else if (const auto v = block.find("tolerance_mm"); v != block.end()) {
    s.toleranceMm = v->get<double>();
  }
  if (const auto a = block.find("applied"); a != block.end()) s.applied = *a;
  return s;
}

bool DiagnosisDomainSettings::appliesEffects(const json& block) {
  if (!block.is_object()) return false;
  const auto a = block.find("applied");
  return a != block.end() && !a->is_null();
}

json DiagnosisDomainSettings::toJson() const {
  const DiagnosisDomainSettings d;
  json j = json::object();
  if (!dataset.empty()) j["dataset"] = dataset;
  if (domain == "thermal") {
    if (!target.empty()) j["target"] = target;
    if (!inputs.empty()) j["inputs"] = inputs;
    if (trainFraction != d.trainFraction) j["train_fraction"] = trainFraction;
  } else if (domain == "kinematic") {
    if (feedMmPerMin != d.feedMmPerMin) j["feed_mm_per_min"] = feedMmPerMin;
  } else if (domain == "setup") {
    if (!model.empty()) j["model"] = model;
  } else if (domain == "matching") {
    if (toleranceMm != d.toleranceMm) j["tolerance_mm"] = toleranceMm;
  }
  if (applied.is_array() && !applied.empty()) j["applied"] = applied;
  return j;
}

bool DiagnosisDomainSettings::isValid(std::string* field, std::string* why) const {
  const std::string study = std::string(DiagnosisStudySettings::kStudy) + "." + domain;
  const auto& names = domainNames();
  if (std::find(names.begin(), names.end(), domain) == names.end()) {
    if (field) *field = diagnosisPrefix(domain);
    if (why) *why = "is not a domain of the diagnosis (known: kinematic, matching, setup, thermal)";
    return false;
  }
  if (dataset.empty()) return invalid(field, why, study.c_str(), "dataset", "is missing");
  if (domain == "thermal") {
    if (target.empty()) return invalid(field, why, study.c_str(), "target", "is missing");
    if (inputs.empty() || std::any_of(inputs.begin(), inputs.end(), [](const auto& i) { return i.empty(); }))
      return invalid(field, why, study.c_str(), "inputs", "must be a non-empty list of column names");
    if (!(trainFraction >= kMinDiagnosisTrainFraction && trainFraction <= kMaxDiagnosisTrainFraction))
      return invalid(field, why, study.c_str(), "train_fraction",
                     std::string("must be a number ") + kTrainFractionRange);
  } else if (domain == "kinematic") {
    if (!(feedMmPerMin > 0.0) || !std::isfinite(feedMmPerMin))
      return invalid(field, why, study.c_str(), "feed_mm_per_min",
                     std::string("must be a number ") + kFeedRange);
  } else if (domain == "setup") {
    if (model.empty()) return invalid(field, why, study.c_str(), "model", "is missing");
  } else if (!(toleranceMm > 0.0) || !std::isfinite(toleranceMm)) {
    return invalid(field, why, study.c_str(), "tolerance_mm",
                   std::string("must be a number ") + kToleranceRange);
  }
  if (!applied.is_array()) return invalid(field, why, study.c_str(), "applied", appliedList()(applied));
  return true;
}

const std::map<std::string, std::vector<SettingField>>& DiagnosisStudySettings::domains() {
  static const std::map<std::string, std::vector<SettingField>> d = [] {
    std::map<std::string, std::vector<SettingField>> m;
    for (const std::string& name : DiagnosisDomainSettings::domainNames())
      m[name] = DiagnosisDomainSettings::fields(name);
    return m;
  }();
  return d;
}

const std::vector<StudyType>& studyTypes() {
  static const std::vector<StudyType> types = {
      {SetupSettings::kStudy, &SetupSettings::fields(), nullptr},
      {MatchingSettings::kStudy, &MatchingSettings::fields(), nullptr},
      {KinematicsSettings::kStudy, &KinematicsSettings::fields(), nullptr, &KinematicsSettings::checkBlock},
      {ThermalSettings::kStudy, &ThermalSettings::fields(), nullptr},
      {DiagnosisStudySettings::kStudy, nullptr, &DiagnosisStudySettings::domains()}};
  return types;
}

}  // namespace metrofit
