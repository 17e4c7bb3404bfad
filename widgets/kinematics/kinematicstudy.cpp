#include "widgets/kinematics/kinematicstudy.h"

#include <stdexcept>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"

namespace metrofit {

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

KinematicStudySettings kinematicStudySettings(const Project& project) {
  KinematicStudySettings s;
  const auto it = project.studies.find(study::kKinematics);
  if (it == project.studies.end() || it->is_null()) return s;
  const JsonReader study(*it, "project", std::string("studies.") + study::kKinematics);
  study.requireObject();
  s.dataset = study.string("dataset", "");
  if (study.has("simulated_machine")) {
    const JsonReader m = study.object("simulated_machine");
    ActuatorErrors2 e;
    const JsonReader origin = m.array("origin_mm");
    if (origin.size() != 2 || !origin.json()[0].is_number() || !origin.json()[1].is_number()) {
      origin.fail("must be [x, y] in mm");
    }
    e.originMm = Eigen::Vector2d(origin.json()[0].get<double>(), origin.json()[1].get<double>());
    e.xAxisAngleDeg = m.number("x_axis_angle_deg");
    e.yAxisAngleDeg = m.number("y_axis_angle_deg");
    std::string why;
    if (!e.isValid(&why)) m.fail(why);
    s.simulatedMachine = e;
  }
  if (study.has("spc")) {
    const JsonReader spc = study.object("spc");
    KinematicSpcSettings k;
    k.dataset = spc.string("dataset");
    k.column = spc.string("column");
    const long n = spc.has("subgroup") ? spc.integer("subgroup") : 5;
    if (n < kMinSubgroupSize || n > kMaxSubgroupSize) spc.fail("must be between 2 and 25", "subgroup");
    k.options.subgroupSize = static_cast<int>(n);
    if (spc.has("lsl") != spc.has("usl"))
      spc.fail("give lsl and usl together", spc.has("lsl") ? "usl" : "lsl");
    if (spc.has("lsl")) {
      k.options.lsl = spc.number("lsl");
      k.options.usl = spc.number("usl");
      if (!(*k.options.lsl < *k.options.usl)) spc.fail("must be below usl", "lsl");
    }
    if (spc.has("nominal")) k.options.nominal = spc.number("nominal");
    k.options.coverageFactor = spc.number("coverage", 2.0);
    std::string why;
    if (!k.options.isValid(&why)) spc.fail(why);
    s.spc = k;
  }
  return s;
}

KinematicStudyData loadKinematicStudy(const Project& project,
                                      const std::function<std::string(const DatasetRef&)>& resolve,
                                      const std::string& datasetId) {
  KinematicStudyData d;
  d.settings = kinematicStudySettings(project);
  const std::string id = datasetId.empty() ? d.settings.dataset : datasetId;
  const DatasetRef* ref = id.empty() ? project.firstOfKind(dataset_kind::kCircularTest) : project.dataset(id);
  if (ref == nullptr) {
    throw ValidationError(ErrorContext{{}, 0, 0, std::string("studies.") + study::kKinematics + ".dataset"},
                          id.empty() ? "the project has no circular_test dataset"
                                     : "names the dataset '" + id + "', which the project does not have");
  }
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
  if (d.settings.spc) {
    const KinematicSpcSettings& k = *d.settings.spc;
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
      series.values = readCsvFile(file, sref->csv).numericColumn(k.column);
      series.result = analyseSpc(series.values, k.options, ErrorContext{file, 0, 0, k.column});
      d.spc = std::move(series);
    } catch (const std::exception& e) {
      d.spcError = e.what();
    }
  }
  return d;
}

CompensationPreview compensateStudy(const KinematicStudyData& study) {
  return previewCompensation(study.measured, study.analysis, study.identification.errors,
                             study.settings.simulatedMachine, &study.applied);
}

}  // namespace metrofit
