#include "core/study/kinematic_study.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"

namespace metrofit {

namespace {
/// "xy" -> "XY".
std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<DatasetRef> circularTestDatasets(const Project& project) {
  std::vector<DatasetRef> out;
  for (const DatasetRef& d : project.datasets) {
    if (d.kind == dataset_kind::kCircularTest) out.push_back(d);
  }
  return out;
}

std::string columnUnit(const std::string& column) {
  const auto pos = column.rfind('_');
  if (pos == std::string::npos) return {};
  const std::string u = column.substr(pos + 1);
  if (u == "um") return "µm";
  if (u == "mm" || u == "deg" || u == "s" || u == "min" || u == "ppm") return u;
  return {};
}

KinematicStudySettings kinematicStudySettings(const KinematicsSettings& k) {
  KinematicStudySettings s;
  s.dataset = k.dataset;
  if (k.simulatedMachine) {
    ActuatorErrors2 e;
    e.originMm = Eigen::Vector2d(k.simulatedMachine->originXMm, k.simulatedMachine->originYMm);
    e.xAxisAngleDeg = k.simulatedMachine->xAxisAngleDeg;
    e.yAxisAngleDeg = k.simulatedMachine->yAxisAngleDeg;
    s.simulatedMachine = e;
  }
  if (k.spc) {
    KinematicSpcSettings spc;
    spc.dataset = k.spc->dataset;
    spc.column = k.spc->column;
    spc.options.subgroupSize = k.spc->subgroup;
    spc.options.lsl = k.spc->lsl;
    spc.options.usl = k.spc->usl;
    spc.options.nominal = k.spc->nominal;
    spc.options.coverageFactor = k.spc->coverage;
    s.spc = spc;
  }
  if (k.fromSpc) {
    // Each edge is optional here (the page chooses them one at a time); loadKinematicStudy says which
    // one is missing.
    KinematicFromSpcSettings f;
    f.xDataset = k.fromSpc->xDataset;
    f.yDataset = k.fromSpc->yDataset;
    f.positionColumn = k.fromSpc->positionColumn;
    f.deviationColumn = k.fromSpc->deviationColumn;
    f.xNominalY = k.fromSpc->xNominalY;
    f.yNominalX = k.fromSpc->yNominalX;
    f.options.subgroupSize = k.fromSpc->subgroup;
    f.options.coverageFactor = k.fromSpc->coverage;
    s.fromSpc = f;
  }
  s.planes = k.planes;
  return s;
}

KinematicStudySettings kinematicStudySettings(const Project& project) {
  const auto it = project.studies.find(study::kKinematics);
  if (it == project.studies.end()) return {};
  return kinematicStudySettings(KinematicsSettings::fromJson(*it, "project"));
}

namespace {
/// The circular test the study uses (`datasetId`, else the study's "dataset", else the first one).
const DatasetRef* studyCircularTest(const Project& project, const KinematicStudySettings& settings,
                                    const std::string& datasetId) {
  const std::string id = datasetId.empty() ? settings.dataset : datasetId;
  const DatasetRef* ref = id.empty() ? project.firstOfKind(dataset_kind::kCircularTest) : project.dataset(id);
  if (ref == nullptr) {
    throw ValidationError(ErrorContext{{}, 0, 0, std::string("studies.") + study::kKinematics + ".dataset"},
                          id.empty() ? "the project has no circular_test dataset"
                                     : "names the dataset '" + id + "', which the project does not have");
  }
  return ref;
}
}  // namespace

std::optional<RadialStudyTest> radialStudyTest(const Project& project,
                                               const std::function<std::string(const DatasetRef&)>& resolve,
                                               const std::string& datasetId) {
  const DatasetRef* ref = studyCircularTest(project, kinematicStudySettings(project), datasetId);
  const CsvTable table = readCsvFile(resolve(*ref), ref->csv);
  if (!isRadialCircularTest(table)) return std::nullopt;
  RadialStudyTest t;
  t.dataset = *ref;
  t.trace = radialTraceFromCsv(table);
  t.analysis = analyseCircularTrace(t.trace);
  return t;
}

std::optional<KinematicSpcSeries> chartKinematicSpc(
    const Project& project, const KinematicSpcSettings& k,
    const std::function<std::string(const DatasetRef&)>& resolve, std::string* error) {
  try {
    const DatasetRef* sref = project.dataset(k.dataset);
    if (sref == nullptr) {
      throw ValidationError(
          ErrorContext{{}, 0, 0, std::string("studies.") + study::kKinematics + ".spc.dataset"},
          "names the dataset '" + k.dataset + "', which the project does not have");
    }
    KinematicSpcSeries series;
    series.dataset = *sref;
    series.column = k.column;
    series.unit = columnUnit(k.column);
    const std::string file = resolve(*sref);
    series.values = readFeatureTable(file, sref->csv).numericColumn(k.column);
    series.result = analyseSpc(series.values, k.options, ErrorContext{file, 0, 0, k.column});
    return series;
  } catch (const std::exception& e) {
    if (error) *error = e.what();
    return std::nullopt;
  }
}

KinematicStudyData loadKinematicStudy(const Project& project,
                                      const std::function<std::string(const DatasetRef&)>& resolve,
                                      const std::string& datasetId) {
  KinematicStudyData d;
  d.settings = kinematicStudySettings(project);
  const DatasetRef* ref = studyCircularTest(project, d.settings, datasetId);
  d.dataset = *ref;
  // The simulated machine belongs to the study's own circular test, not to any other one.
  if (!d.settings.dataset.empty() && d.settings.dataset != ref->id) d.settings.simulatedMachine.reset();
  d.path = resolve(*ref);
  d.measured = readMeasuredPath(d.path, ref->csv);
  d.analysis = analyseCircularTest(d.measured);
  d.applied = projectAxisEffects(project, ref->id);
  if (d.applied.empty()) {
    d.identification = identifyActuatorErrors(d.measured);
  } else {
    d.declaredRmseMm = identifyActuatorErrors(d.measured).rmseMm;
    d.identification = identifyActuatorErrors(withEffectiveJoints(d.measured, d.applied));
  }
  if (d.identification.run.termination == Termination::Failed) {
    throw std::runtime_error("identification failed on " + d.path + ": " + d.identification.run.message);
  }
  if (d.settings.spc) d.spc = chartKinematicSpc(project, *d.settings.spc, resolve, &d.spcError);
  if (d.settings.fromSpc &&
      (!d.settings.fromSpc->xDataset.empty() || !d.settings.fromSpc->yDataset.empty())) {
    const KinematicFromSpcSettings& k = *d.settings.fromSpc;
    try {
      AxisFeatureSeries series[2];
      const std::string ids[2] = {k.xDataset, k.yDataset};
      for (int i = 0; i < 2; ++i) {
        if (ids[i].empty()) {
          throw ValidationError(ErrorContext{{},
                                             0,
                                             0,
                                             std::string("studies.") + study::kKinematics + ".from_spc." +
                                                 (i == 0 ? "x_dataset" : "y_dataset")},
                                i == 0 ? "missing: choose the edge machined along X"
                                       : "missing: choose the edge machined along Y");
        }
        const DatasetRef* ref = project.dataset(ids[i]);
        if (ref == nullptr) {
          throw ValidationError(ErrorContext{{},
                                             0,
                                             0,
                                             std::string("studies.") + study::kKinematics + ".from_spc." +
                                                 (i == 0 ? "x_dataset" : "y_dataset")},
                                "names the dataset '" + ids[i] + "', which the project does not have");
        }
        series[i] = axisFeatureFromCsv(readFeatureTable(resolve(*ref), ref->csv), k.positionColumn,
                                       k.deviationColumn);
      }
      series[0].nominalCrossMm = k.xNominalY;
      series[1].nominalCrossMm = k.yNominalX;
      SpcActuatorResult r = actuatorErrorsFromSpc(series[0], series[1], k.options);
      const auto& nominal = d.measured.command;
      const auto refs = compensatePath(CartesianMachine2::fromErrors(r.errors), nominal);
      const CartesianMachine2 model = CartesianMachine2::fromErrors(d.identification.errors);
      for (std::size_t i = 0; i < nominal.size(); ++i) {
        d.fromSpcLargestCorrectionMm = std::max(d.fromSpcLargestCorrectionMm, (refs[i] - nominal[i]).norm());
        d.fromSpcModelBeforeMm =
            std::max(d.fromSpcModelBeforeMm, (model.forward(nominal[i]) - nominal[i]).norm());
        d.fromSpcModelAfterMm = std::max(d.fromSpcModelAfterMm, (model.forward(refs[i]) - nominal[i]).norm());
      }
      d.fromSpc = std::move(r);
      d.fromSpcEdges = {std::move(series[0]), std::move(series[1])};
    } catch (const std::exception& e) {
      d.fromSpcError = e.what();
    }
  }
  if (d.settings.planes && std::any_of(d.settings.planes->begin(), d.settings.planes->end(),
                                       [](const std::string& id) { return !id.empty(); })) {
    try {
      std::array<MeasuredPath, 3> tests;
      for (const TestPlane plane : kTestPlanes) {
        const std::string& id = (*d.settings.planes)[static_cast<std::size_t>(plane)];
        if (id.empty()) {
          throw ValidationError(
              ErrorContext{
                  {}, 0, 0, std::string("studies.") + study::kKinematics + ".planes." + planeName(plane)},
              std::string("missing: choose the circular test in the ") + upper(planeName(plane)) + " plane");
        }
        const DatasetRef* ref = project.dataset(id);
        if (ref == nullptr) {
          throw ValidationError(
              ErrorContext{
                  {}, 0, 0, std::string("studies.") + study::kKinematics + ".planes." + planeName(plane)},
              "names the dataset '" + id + "', which the project does not have");
        }
        tests[static_cast<std::size_t>(plane)] = readPlanePath(resolve(*ref), plane, ref->csv);
      }
      Identify3Result r = identifyActuatorErrors3(tests);
      if (r.run.termination == Termination::Failed) throw std::runtime_error(r.run.message);
      d.threeAxis = std::move(r);
    } catch (const std::exception& e) {
      d.threeAxisError = e.what();
    }
  }
  return d;
}

AxisEffects projectAxisEffects(const Project& project, const std::string& datasetId,
                               const std::string& source) {
  const auto diag = project.studies.find(study::kDiagnosis);
  if (diag == project.studies.end() || !diag->is_object()) return {};
  const std::string domain = "kinematic";
  const auto block = diag->find(domain);
  // A block that applies nothing (the page's controls set before a run) matters only to the diagnosis,
  // which reads and refuses it itself: a missing dataset there must not stop the kinematics study.
  if (block == diag->end() || !DiagnosisDomainSettings::appliesEffects(*block)) return {};
  const DiagnosisDomainSettings settings = DiagnosisDomainSettings::fromJson(*block, domain, source);
  if (settings.dataset != datasetId) return {};
  return axisEffectsFromApplied(settings.applied, settings.feedMmPerMin);
}

CompensationPreview compensateStudy(const KinematicStudyData& study) {
  return previewCompensation(study.measured, study.analysis, study.identification.errors,
                             study.settings.simulatedMachine, &study.applied);
}

nlohmann::json kinematicStoredSettings(const Project& project, const std::string& datasetId) {
  const auto it = project.studies.find(study::kKinematics);
  const KinematicsSettings settings =
      it == project.studies.end() ? KinematicsSettings{} : KinematicsSettings::fromJson(*it, "project");
  return {{"study", settings.toJson()}, {"applied", projectAxisEffects(project, datasetId).text()}};
}

nlohmann::json kinematicResultJson(const KinematicStudyData& study, const CompensationPreview& c) {
  const IdentifyResult& r = study.identification;
  nlohmann::json compensation = {
      {"max_before_mm", c.maxBeforeMm},     {"max_model_mm", c.maxModelMm},
      {"max_expected_mm", c.maxExpectedMm}, {"rms_before_mm", c.rmsBeforeMm},
      {"rms_expected_mm", c.rmsExpectedMm}, {"largest_correction_mm", c.largestCorrectionMm}};
  if (c.maxSimulatedMm) compensation["max_simulated_mm"] = *c.maxSimulatedMm;
  return {{"points", study.measured.size()},
          {"identified",
           {{"origin_x_mm", r.errors.originMm.x()},
            {"origin_y_mm", r.errors.originMm.y()},
            {"x_axis_angle_deg", r.errors.xAxisAngleDeg},
            {"y_axis_angle_deg", r.errors.yAxisAngleDeg},
            {"squareness_deg", r.errors.squarenessDeg()},
            {"rmse_mm", r.rmseMm}}},
          {"compensation", std::move(compensation)}};
}

}  // namespace metrofit
