#pragma once
// The kinematics & SPC study of a project, as the page and the report run it. Settings
// (project "studies" -> "kinematics", every key optional):
//   "dataset": "<id of a circular_test dataset>"          (default: the first of that kind)
//   "simulated_machine": {"origin_mm": [x, y], "x_axis_angle_deg": a, "y_axis_angle_deg": b}
//        the true errors when the study's circular test ("dataset") was simulated: compensated
//        references are then also run through that machine (the simulator plays the machine)
//   "spc": {"dataset": "<id>", "column": "diameter_mm", "subgroup": 5, "lsl": L, "usl": U,
//           "nominal": V, "coverage": k}
//        the feature series charted on the SPC view (a CSV dataset, rows in production order)
//   "from_spc": {"x_dataset": "<id>", "y_dataset": "<id>", "position_column": "position_mm",
//                "deviation_column": "deviation_mm", "x_nominal_y": 0, "y_nominal_x": 0,
//                "subgroup": 5, "coverage": 2}
//        the kinematic-compensation paper's chain from SPC to compensation (core/kinematics/spc_actuator.h):
//        the edges machined along X and Y, their regression offset angles -> actuator errors -> Eq. 15
//        references for the study's nominal circle. Either edge may be missing (the page chooses them
//        one at a time): the chain then reports the missing one as its error; without both it is not run
//   "planes": {"xy": "<id>", "yz": "<id>", "zx": "<id>"}
//        circular tests in three planes for the three-axis identification
//        (core/kinematics/identification3.h; YZ / ZX files have the plane's columns); a missing plane
//        is the identification's error, none at all: not run
// The keys, their defaults and checks: KinematicsSettings (core/study/study_settings.h). A wrong type or
// value is a ValidationError naming the field (studies.kinematics.spc.subgroup).
//
// Applied effects: the effects added with Apply on the diagnosis page
// (studies.diagnosis.kinematic.applied, core/diagnose/applied_kinematic.h) belong to the machine model of
// the circular test the diagnosis ran on (studies.diagnosis.kinematic.dataset, where they were
// estimated): for that test the identification, the compensation and its exports include them
// (undoing the Apply gives the declared model again); other tests keep the declared model.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnose/applied_kinematic.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/identification3.h"
#include "core/kinematics/measured_path.h"
#include "core/kinematics/spc_actuator.h"
#include "core/project/project.h"
#include "core/spc/spc.h"
#include "core/study/circular_analysis.h"
#include "core/study/study_settings.h"

namespace metrofit {

// The study's values as the methods take them, converted from KinematicsSettings
// (core/study/study_settings.h), the one owner of the keys, their defaults and checks.
struct KinematicSpcSettings {
  std::string dataset;
  std::string column;
  SpcOptions options;
};

struct KinematicFromSpcSettings {
  std::string xDataset, yDataset;
  std::string positionColumn, deviationColumn;
  double xNominalY = 0.0, yNominalX = 0.0;
  SpcActuatorOptions options;
};

struct KinematicStudySettings {
  std::string dataset;  ///< empty: the first circular_test dataset
  std::optional<ActuatorErrors2> simulatedMachine;
  std::optional<KinematicSpcSettings> spc;
  std::optional<KinematicFromSpcSettings> fromSpc;
  std::optional<std::array<std::string, 3>> planes;  ///< dataset ids, index TestPlane
};

/// The study's settings as KinematicsSettings reads them (ValidationError naming source "project" and
/// the field), converted for the methods.
KinematicStudySettings kinematicStudySettings(const KinematicsSettings& settings);
KinematicStudySettings kinematicStudySettings(const Project& project);

/// The unit at the end of a column name ("diameter_mm" -> "mm", "dev_um" -> "µm"; else empty).
std::string columnUnit(const std::string& column);

struct KinematicSpcSeries {
  DatasetRef dataset;
  std::string column, unit;
  std::vector<double> values;
  SpcResult result;
};

struct KinematicStudyData {
  KinematicStudySettings settings;
  DatasetRef dataset;  ///< the circular test
  std::string path;    ///< its resolved file
  MeasuredPath measured;
  CircularAnalysis analysis;
  IdentifyResult identification;         ///< with the applied effects, when any
  AxisEffects applied;                   ///< the applied effects the model includes (empty: none)
  std::optional<double> declaredRmseMm;  ///< rmse of the declared model alone, when effects are applied
  std::optional<KinematicSpcSeries> spc;
  std::string spcError;  ///< why the SPC series could not be charted (empty when it was)

  /// The kinematic-compensation paper's chain from SPC (settings "from_spc"): the derived errors, and their
  /// Eq. 15 references for the study's nominal circle (the circular test's commands) judged by the circular
  /// test's identified model, an independent estimate of the same machine.
  std::optional<SpcActuatorResult> fromSpc;
  std::vector<AxisFeatureSeries> fromSpcEdges;  ///< the X and Y edges as read (with fromSpc)
  std::string fromSpcError;
  double fromSpcLargestCorrectionMm = 0.0;  ///< max |reference - nominal|
  double fromSpcModelBeforeMm = 0.0;        ///< identified model on the nominal commands: max |P - nominal|
  double fromSpcModelAfterMm = 0.0;         ///< identified model on the SPC references
  /// Three-axis identification (settings "planes").
  std::optional<Identify3Result> threeAxis;
  std::string threeAxisError;
};

/// The SPC series of the study's "spc" settings read and analysed (no circular test needed: a shop's
/// part series is charted on its own); nullopt with `error` set when it cannot be charted.
std::optional<KinematicSpcSeries> chartKinematicSpc(
    const Project& project, const KinematicSpcSettings& spc,
    const std::function<std::string(const DatasetRef&)>& resolve, std::string* error = nullptr);

/// The circular_test datasets of the project, in project order.
std::vector<DatasetRef> circularTestDatasets(const Project& project);

/// Reads the circular test `datasetId` (empty: the study's dataset), analyses and identifies it, and
/// charts the SPC series when the study names one (a bad series sets spcError, it does not throw).
/// `resolve` gives the file of a dataset. Throws InputError for a missing or unreadable test, and
/// std::runtime_error when the identification fails.
KinematicStudyData loadKinematicStudy(const Project& project,
                                      const std::function<std::string(const DatasetRef&)>& resolve,
                                      const std::string& datasetId = {});

/// The study's circular test (`datasetId`, else the study's) when it is radial-only (a ballbar export:
/// angle and radial deviation, no x/y), which loadKinematicStudy refuses: its trace and analysis (loops,
/// ISO 230-4 results). nullopt for an x/y test. Throws as loadKinematicStudy for a missing dataset or an
/// unreadable file.
struct RadialStudyTest {
  DatasetRef dataset;
  CircularTrace trace;
  CircularAnalysis analysis;
};
std::optional<RadialStudyTest> radialStudyTest(const Project& project,
                                               const std::function<std::string(const DatasetRef&)>& resolve,
                                               const std::string& datasetId = {});

/// The applied kinematic effects of a project that apply to the circular test `datasetId`: the list
/// studies.diagnosis.kinematic.applied when the test is the one the kinematic diagnosis ran on
/// (studies.diagnosis.kinematic.dataset: the effects and their sizes were estimated on it, so the
/// kinematics study includes them when it identifies and compensates that test), read with that
/// diagnosis's feed (feed_mm_per_min). The block is read through its one owner,
/// DiagnosisDomainSettings (study_settings.h): its keys, defaults and checks. No effects when nothing
/// is applied or another test is named. ValidationError naming `source` and the field when the block
/// or an entry is bad (core/diagnose/applied_kinematic.h).
AxisEffects projectAxisEffects(const Project& project, const std::string& datasetId,
                               const std::string& source = {});

/// Compensation preview of the study's circular test (the simulated machine when the settings give one).
CompensationPreview compensateStudy(const KinematicStudyData& study);

/// What the figures of a result of the circular test `datasetId` depend on, stored with it
/// (results.kinematics.<dataset>, core/project/stored_results.h): {"study": the study's settings
/// (KinematicsSettings::toJson, only what differs from the defaults), "applied": the applied effects of
/// that test (text, "" for none)}. ValidationError for bad settings.
nlohmann::json kinematicStoredSettings(const Project& project, const std::string& datasetId);

/// The figures of a compensated study as the project stores them: {"points", "identified": {"origin_x_mm",
/// "origin_y_mm", "x_axis_angle_deg", "y_axis_angle_deg", "squareness_deg", "rmse_mm"}, "compensation":
/// {"max_before_mm", "max_model_mm", "max_expected_mm", "rms_before_mm", "rms_expected_mm",
/// "largest_correction_mm"[, "max_simulated_mm"]}}.
nlohmann::json kinematicResultJson(const KinematicStudyData& study, const CompensationPreview& compensation);

}  // namespace metrofit
