#pragma once
// One owner per study's settings (DESIGN.md, third round): for each study of a project one type with
// its keys (as the project file spells them under "studies.<study>"), its defaults, fromJson / toJson
// and isValid naming the field. The project validator (core/study/study_check.h) iterates these
// types; the pages, the CLI's option defaults and the report read the same types. A bad value is
// refused with the field named ("studies.thermal.train_fraction: must be a number between 0 and 1"),
// never replaced by a default.
//
// What each key means and how the study uses it: core/study/setup_study.h, matching_study.h,
// kinematic_study.h, thermal_comparison.h, diagnosis_study.h. Every key is optional; a missing key
// takes the default written here (a dataset id left empty: the study uses the project's first
// dataset of the kind).
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/kinematics/effects.h"
#include "core/kinematics/spc_actuator.h"
#include "core/machine/controller_frame.h"
#include "core/matching/matching.h"
#include "core/setup/methods.h"
#include "core/spc/spc.h"
#include "core/thermal/thermal_model.h"

namespace metrofit {

/// One key of a study's settings block: its name, the dataset kind it names when it is a dataset
/// reference ("" = any kind), and the check of its value (nullptr = any value; the message of a bad
/// value, "" when good). A block inside the study ("spc", "modules.<name>") has `block` set: the keys
/// of the block (for "modules": of every entry).
struct SettingField {
  std::string key;
  bool dataset = false;
  std::string datasetKind;
  std::function<std::string(const nlohmann::json&)> check;
  const std::vector<SettingField>* block = nullptr;
  bool blockPerEntry = false;  ///< the value is an object of blocks (studies.thermal.modules)
};

/// A bad setting: the field as the project file spells it and what is wrong.
struct SettingIssue {
  std::string field;
  std::string message;
  bool operator==(const SettingIssue&) const = default;
};

/// The issues of a settings block `j` at `prefix` ("studies.setup") against `fields`: not an object,
/// unknown keys (every key but "notes" must be a field), values the field's check refuses, dataset
/// references that are not a text. Dataset existence and kind need the project: `dataset` (optional)
/// checks a dataset reference (the value, the field's path, the kind) and adds its issues.
using DatasetCheck =
    std::function<void(const nlohmann::json& value, const std::string& field, const std::string& kind)>;
void checkSettingsBlock(const nlohmann::json& j, const std::string& prefix,
                        const std::vector<SettingField>& fields, std::vector<SettingIssue>& issues,
                        const DatasetCheck& dataset = {});

/// studies.setup (core/study/setup_study.h).
struct SetupSettings {
  static constexpr const char* kStudy = "setup";
  std::string model;             ///< "model": a setup_model dataset id ("" = the first)
  std::string dataset;           ///< "dataset": a cmm_report dataset id ("" = the first report or DMIS file)
  std::string method = "exact";  ///< "method": one of setup::setupMethodNames()
  long budget = setup::kPaperBudget;  ///< "budget": solutions of a metaheuristic (> 0)
  std::uint64_t seed = 1;             ///< "seed"

  static const std::vector<SettingField>& fields();
  /// ValidationError naming `source` and the field of the first bad value.
  static SetupSettings fromJson(const nlohmann::json& study, const std::string& source = {});
  /// Only the keys that differ from the defaults.
  nlohmann::json toJson() const;
  /// False with the field ("studies.setup.budget") and what is wrong.
  bool isValid(std::string* field, std::string* why) const;
  bool operator==(const SetupSettings&) const = default;
};

/// studies.matching (core/study/matching_study.h). "machine" is read by project.h matchingMachine.
struct MatchingSettings {
  static constexpr const char* kStudy = "matching";
  std::string dataset;  ///< "dataset": a probe_points dataset id ("" = the first)
  double toleranceMm = matching::kDefaultToleranceMm;             ///< "tolerance_mm" (>= 0)
  matching::MatchMethod method = matching::MatchMethod::Sade;     ///< "method": the primary method
  bool allowScale = false;                                        ///< "allow_scale"
  std::uint64_t seed = 1;                                         ///< "seed"
  std::string locks;                                              ///< "locks": "rz,z" (DofLocks::parse)
  machine::FrameFormat frame = machine::FrameFormat::Heidenhain;  ///< "frame": the controller frame's control
  int frameDecimals = machine::FrameOptions{}.decimals;           ///< "frame_decimals" (0..12)

  static const std::vector<SettingField>& fields();
  static MatchingSettings fromJson(const nlohmann::json& study, const std::string& source = {});
  nlohmann::json toJson() const;
  bool isValid(std::string* field, std::string* why) const;
  bool operator==(const MatchingSettings&) const = default;
};

/// studies.kinematics (core/study/kinematic_study.h: what each key does; kinematicStudySettings converts
/// these values for the study). The CLI's `spc` and `kinematic from-spc` option defaults are the blocks'.
struct KinematicsSettings {
  static constexpr const char* kStudy = "kinematics";

  /// "simulated_machine": the true errors of the simulated circular test ("origin_mm": [x, y],
  /// "x_axis_angle_deg", "y_axis_angle_deg", all required when the block is given; |angle| <= 45).
  struct SimulatedMachine {
    double originXMm = 0.0, originYMm = 0.0;
    double xAxisAngleDeg = 0.0, yAxisAngleDeg = 0.0;
    bool operator==(const SimulatedMachine&) const = default;
  };
  /// "spc": the feature series charted on the SPC view ("dataset" and "column" required).
  struct Spc {
    std::string dataset;                            ///< "dataset": a CSV dataset id
    std::string column;                             ///< "column"
    int subgroup = SpcOptions{}.subgroupSize;       ///< "subgroup" (2..25)
    std::optional<double> lsl, usl;                 ///< "lsl", "usl": both or neither, lsl < usl
    std::optional<double> nominal;                  ///< "nominal"
    double coverage = SpcOptions{}.coverageFactor;  ///< "coverage" (> 0)
    bool operator==(const Spc&) const = default;
  };
  /// "from_spc": the chain from the SPC regression of two machined edges to the actuator errors.
  struct FromSpc {
    static constexpr const char* kPositionColumn = "position_mm";
    static constexpr const char* kDeviationColumn = "deviation_mm";
    std::string xDataset, yDataset;                         ///< "x_dataset", "y_dataset" ("" = not chosen)
    std::string positionColumn = kPositionColumn;           ///< "position_column"
    std::string deviationColumn = kDeviationColumn;         ///< "deviation_column"
    double xNominalY = 0.0;                                 ///< "x_nominal_y" (mm)
    double yNominalX = 0.0;                                 ///< "y_nominal_x" (mm)
    int subgroup = SpcActuatorOptions{}.subgroupSize;       ///< "subgroup" (2..25)
    double coverage = SpcActuatorOptions{}.coverageFactor;  ///< "coverage" (> 0)
    bool operator==(const FromSpc&) const = default;
  };

  std::string dataset;  ///< "dataset": a circular_test dataset id ("" = the first)
  std::optional<SimulatedMachine> simulatedMachine;
  std::optional<Spc> spc;
  std::optional<FromSpc> fromSpc;  ///< given (possibly with no edge chosen yet) or not
  /// "planes": {"xy", "yz", "zx"} circular tests ("" = not chosen), index TestPlane; given or not.
  std::optional<std::array<std::string, 3>> planes;

  static const std::vector<SettingField>& fields();
  /// The rules between keys of a block (lsl with usl, lsl < usl, spc's dataset and column, the simulated
  /// machine's three keys and its angles) for a block whose keys fields() accepts; the validator runs
  /// them too.
  static void checkBlock(const nlohmann::json& study, std::vector<SettingIssue>& issues);
  static KinematicsSettings fromJson(const nlohmann::json& study, const std::string& source = {});
  nlohmann::json toJson() const;
  bool isValid(std::string* field, std::string* why) const;
  bool operator==(const KinematicsSettings&) const = default;
};

/// studies.thermal (core/study/thermal_comparison.h).
struct ThermalSettings {
  static constexpr const char* kStudy = "thermal";
  std::string dataset;              ///< "dataset": a thermal_log dataset id ("" = the first)
  std::string target;               ///< "target": a column of the log ("" = the study's default choice)
  std::vector<std::string> inputs;  ///< "inputs": columns of the log
  double trainFraction = thermal::kDefaultTrainFraction;  ///< "train_fraction" in (0, 1)
  std::uint64_t seed = 1;                                 ///< "seed"
  std::map<std::string, std::string> modules;             ///< "modules": {MODULE: {"dataset": ID}}

  static const std::vector<SettingField>& fields();
  static ThermalSettings fromJson(const nlohmann::json& study, const std::string& source = {});
  nlohmann::json toJson() const;
  bool isValid(std::string* field, std::string* why) const;
  bool operator==(const ThermalSettings&) const = default;
};

/// studies.diagnosis.<domain>, one domain's block (core/study/diagnosis_study.h: diagnosisSettings reads
/// it through this type and resolves the datasets). The defaults are those of the closed loops' options
/// (core/diagnose: ThermalDiagnosisOptions, KinematicDiagnosisOptions, MatchingDiagnosisOptions use the
/// same constants; tests/core/study/study_settings_test.cpp checks they agree). "dataset" (every domain),
/// "target" and "inputs" (thermal) and "model" (setup) are required: fromJson refuses a block without
/// them ("is missing").
struct DiagnosisDomainSettings {
  std::string domain = "thermal";   ///< the block's name: "thermal", "kinematic", "setup" or "matching"
  std::string dataset;              ///< "dataset": thermal_log, circular_test, cmm_report or probe_points id
  std::string target;               ///< thermal "target": the log's column the declared model predicts
  std::vector<std::string> inputs;  ///< thermal "inputs": the declared inputs
  double trainFraction = thermal::kDefaultTrainFraction;  ///< thermal "train_fraction" in [0.05, 0.95]
  std::string model;                                      ///< setup "model": a setup_model dataset id
  double feedMmPerMin = kDefaultFeedMmPerMin;             ///< kinematic "feed_mm_per_min" (> 0)
  double toleranceMm = matching::kDefaultToleranceMm;     ///< matching "tolerance_mm" (> 0)
  nlohmann::json applied = nlohmann::json::array();       ///< "applied": effects added with Apply

  /// The domains' names in the order of the diagnosis page ("thermal", "kinematic", "setup", "matching").
  static const std::vector<std::string>& domainNames();
  /// The keys of `domain`'s block (empty for an unknown domain).
  static const std::vector<SettingField>& fields(const std::string& domain);
  /// ValidationError naming `source` and the field ("studies.diagnosis.thermal.train_fraction") of the
  /// first bad value or missing required key; an unknown domain names "studies.diagnosis.<domain>".
  static DiagnosisDomainSettings fromJson(const nlohmann::json& block, const std::string& domain,
                                          const std::string& source = {});
  /// The domain's keys that differ from the defaults (the required ones when set).
  nlohmann::json toJson() const;
  /// Whether a domain's block applies effects ("applied" present and not null), without reading the
  /// rest: a study below the diagnosis reads the block (fromJson) only then.
  static bool appliesEffects(const nlohmann::json& block);
  /// False with the field ("studies.diagnosis.matching.tolerance_mm") and what is wrong.
  bool isValid(std::string* field, std::string* why) const;
  bool operator==(const DiagnosisDomainSettings&) const = default;
};

/// studies.diagnosis: a block per domain (DiagnosisDomainSettings).
struct DiagnosisStudySettings {
  static constexpr const char* kStudy = "diagnosis";
  /// The keys of each domain's block ("thermal", "kinematic", "setup", "matching").
  static const std::map<std::string, std::vector<SettingField>>& domains();
};

/// The studies a project may hold, in the order of study::kAll, and how each is checked: the keys
/// (SettingField) of a plain study, the domains of the diagnosis.
struct StudyType {
  const char* name;
  const std::vector<SettingField>* fields;                          ///< nullptr: the diagnosis
  const std::map<std::string, std::vector<SettingField>>* domains;  ///< the diagnosis's blocks
  /// The rules between keys (nullptr: none), run on a block whose keys are all good.
  void (*checkBlock)(const nlohmann::json& study, std::vector<SettingIssue>& issues) = nullptr;
};
const std::vector<StudyType>& studyTypes();

}  // namespace metrofit
