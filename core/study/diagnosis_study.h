#pragma once
// The project's "diagnosis" study, shared by the GUI's diagnosis page and the report:
//
//   "diagnosis": {
//     "thermal":   {"dataset": ID, "target": COL, "inputs": [COL, ...], "train_fraction": 0.5},
//     "kinematic": {"dataset": ID, "feed_mm_per_min": 1000},
//     "setup":     {"model": SETUP_MODEL_ID, "dataset": CMM_REPORT_ID},
//     "matching":  {"dataset": ID, "tolerance_mm": 0.035},
//     "<domain>":  {..., "applied": [{"name": EFFECT, "parameters": {NAME: VALUE}}]}
//   }
//
// The keys, their defaults and their checks have one owner, DiagnosisDomainSettings
// (core/study/study_settings.h); diagnosisSettings reads the block through it and resolves the
// datasets. A missing, ill-typed or out-of-range key gives a ValidationError whose message names the
// field ("studies.diagnosis.thermal.train_fraction"), never a crash and never a default in its place.
// "applied" holds the effects the user added to the domain's model with Apply (diagnosis page, undoable).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/diagnose/thermal_diagnosis.h"
#include "core/project/project.h"
#include "core/study/study_settings.h"

namespace metrofit {

enum class DiagnosisDomain { Thermal, Kinematic, Setup, Matching };
inline constexpr DiagnosisDomain kDiagnosisDomains[] = {DiagnosisDomain::Thermal, DiagnosisDomain::Kinematic,
                                                        DiagnosisDomain::Setup, DiagnosisDomain::Matching};

/// "thermal", "kinematic", "setup", "matching" (the CLI's and the study block's names).
const char* diagnosisDomainKey(DiagnosisDomain domain);

struct DiagnosisSettings {
  DiagnosisDomain domain = DiagnosisDomain::Thermal;
  std::string datasetId;
  std::string datasetPath;                ///< resolved against the project file's folder
  std::vector<std::string> datasetPaths;  ///< every file (a DMIS series: several; core/project/project.h)
  CsvReadOptions csv;       ///< the dataset's dialect and column mapping (core/project/datasets.h)
  setup::DmisOptions dmis;  ///< how the dataset's DMIS TA(label) values are read (its "dmis" key)
  /// matching: where the measured points' nominals come from (core/project/nominals.h), and the
  /// reference measurement's file (resolved) and reading when they come from one.
  NominalSource nominals;
  std::string referencePath;
  CsvReadOptions referenceCsv;
  std::string target;  ///< thermal
  std::vector<std::string> inputs;
  double trainFraction = DiagnosisDomainSettings{}.trainFraction;
  std::string modelId;  ///< setup
  std::string modelPath;
  double toleranceMm = DiagnosisDomainSettings{}.toleranceMm;    ///< matching
  double feedMmPerMin = DiagnosisDomainSettings{}.feedMmPerMin;  ///< kinematic
  nlohmann::json applied = nlohmann::json::array();              ///< effects added with Apply
};

/// A text that is equal for two settings exactly when runDiagnosis gives the same result for both
/// (domain, data and how it is read, target, inputs, fraction, model, tolerance, feed), e.g. to reuse a
/// result.
std::string diagnosisSettingsKey(const DiagnosisSettings& settings);

/// True when studies.diagnosis.<domain> exists (it may still be invalid).
bool hasDiagnosisSettings(const Project& project, DiagnosisDomain domain);
/// Reads studies.diagnosis.<domain>. ValidationError naming the field (source = projectPath) when the
/// block or a key is missing or has the wrong type, or a dataset id is not in the project.
DiagnosisSettings diagnosisSettings(const Project& project, const std::string& projectPath,
                                    DiagnosisDomain domain);
/// Reads the data and runs the domain's loop (core/diagnose/*_diagnosis.h). Core's InputError when
/// the data cannot be read or do not fit the declared model.
diagnose::Diagnosis runDiagnosis(const DiagnosisSettings& settings, Observer* observer = nullptr);

/// True when Apply can add the accepted effect `c` of a diagnosis of `domain` ("thermal", ...) to its
/// study's model: the study's applied-effects parser (core/diagnose/thermal_applied.h,
/// core/diagnose/applied_kinematic.h, core/diagnose/applied_setup_matching.h) knows it. The catalogue's
/// named effects: yes. A generic effect `unexplained:<against>` (Candidate::generic): in the thermal
/// study (its basis columns are refitted by every model), the kinematic one (a displacement with the
/// diagnosis's coefficients, core/diagnose/applied_kinematic.h) and the matching one (the deformation
/// of the nominal points with the diagnosis's coefficients, projected off the posture and the named
/// effects as the loop fitted it: core/diagnose/matching_diagnosis.h matchingGenericDisplacement) and
/// the setup one when it predicts the next part (against time, datum:<id> or dimension:<id>:
/// core/diagnose/applied_setup_matching.h); a setup effect of the row, the part or the dimension
/// category is reported (candidate table, residual check, report) but not applied.
bool canApplyEffect(const std::string& domain, const diagnose::Candidate& c);

/// The accepted effects Apply can add (canApplyEffect) as stored under "applied":
/// [{"name": ..., "parameters": {name: value}}], a generic effect with its "shape"
/// (core/diagnose/applied_entries.h genericShapeJson) and, in kinematic, matching and setup, its
/// "coefficients".
nlohmann::json appliedEffects(const diagnose::Diagnosis& diagnosis);

/// A parameter's value as text ("12.3" or the text value), `digits` significant digits.
std::string formatParameterValue(const diagnose::Parameter& parameter, int digits = 4);

}  // namespace metrofit
