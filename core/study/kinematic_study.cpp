#include "core/study/kinematic_study.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"

namespace metrofit {

namespace {
/// "xy" -> "XY".
std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// The "subgroup" of an SPC block (default: the options' own), checked against the chart's range
/// with the field named.
int subgroupSetting(const JsonReader& block, int defaultSize) {
  const long n = block.has("subgroup") ? block.integer("subgroup") : defaultSize;
  if (n < kMinSubgroupSize || n > kMaxSubgroupSize) block.fail("must be between 2 and 25", "subgroup");
  return static_cast<int>(n);
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
    k.options.subgroupSize = subgroupSetting(spc, k.options.subgroupSize);
    if (spc.has("lsl") != spc.has("usl"))
      spc.fail("give lsl and usl together", spc.has("lsl") ? "usl" : "lsl");
    if (spc.has("lsl")) {
      k.options.lsl = spc.number("lsl");
      k.options.usl = spc.number("usl");
      if (!(*k.options.lsl < *k.options.usl)) spc.fail("must be below usl", "lsl");
    }
    if (spc.has("nominal")) k.options.nominal = spc.number("nominal");
    k.options.coverageFactor = spc.number("coverage", k.options.coverageFactor);
    std::string why;
    if (!k.options.isValid(&why)) spc.fail(why);
    s.spc = k;
  }
  if (study.has("from_spc")) {
    const JsonReader f = study.object("from_spc");
    KinematicFromSpcSettings k;
    // Each edge is optional here (the page chooses them one at a time); loadKinematicStudy says which
    // one is missing.
    k.xDataset = f.string("x_dataset", "");
    k.yDataset = f.string("y_dataset", "");
    k.positionColumn = f.string("position_column", k.positionColumn);
    k.deviationColumn = f.string("deviation_column", k.deviationColumn);
    k.xNominalY = f.number("x_nominal_y", 0.0);
    k.yNominalX = f.number("y_nominal_x", 0.0);
    k.options.subgroupSize = subgroupSetting(f, k.options.subgroupSize);
    k.options.coverageFactor = f.number("coverage", k.options.coverageFactor);
    std::string why;
    if (!k.options.isValid(&why)) f.fail(why);
    s.fromSpc = k;
  }
  if (study.has("planes")) {
    const JsonReader p = study.object("planes");
    std::array<std::string, 3> ids;
    for (const TestPlane plane : kTestPlanes)
      ids[static_cast<std::size_t>(plane)] = p.string(planeName(plane), "");
    s.planes = ids;
  }
  return s;
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
      series.values = readFeatureTable(file, sref->csv).numericColumn(k.column);
      series.result = analyseSpc(series.values, k.options, ErrorContext{file, 0, 0, k.column});
      d.spc = std::move(series);
    } catch (const std::exception& e) {
      d.spcError = e.what();
    }
  }
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

CompensationPreview compensateStudy(const KinematicStudyData& study) {
  return previewCompensation(study.measured, study.analysis, study.identification.errors,
                             study.settings.simulatedMachine, &study.applied);
}

}  // namespace metrofit
