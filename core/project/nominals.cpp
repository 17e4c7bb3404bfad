#include "core/project/nominals.h"

#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/geometry/point_table.h"
#include "core/geometry/stl.h"
#include "core/io/file_io.h"
#include "core/matching/cad_match.h"
#include "core/matching/hole_table.h"

namespace metrofit {
namespace {

[[noreturn]] void bad(const std::string& field, const std::string& what) {
  throw ValidationError(ErrorContext{{}, 0, 0, "nominals." + field}, what);
}

geometry::ElementKind elementOf(const NominalSource& n) {
  geometry::ElementKind kind{};
  geometry::parseElementKind(n.element, &kind);
  return kind;
}

geometry::ElementFitResult fit(const geometry::PointSet& points, const NominalSource& n, Observer* observer) {
  geometry::ElementFitOptions o;
  o.element = elementOf(n);
  if (n.criterion == "minimax") o.criterion = geometry::FitCriterion::Minimax;
  o.fixedRadiusMm = n.radiusMm;
  o.robust = n.robust;
  return geometry::fitElement(points, o, observer);
}

}  // namespace

void checkNominalSource(const NominalSource& n) {
  if (n.from.empty()) {
    if (!(n == NominalSource{}))
      bad("from", "is missing: say where the nominals come from (element or reference)");
    return;
  }
  if (n.from != "element" && n.from != "reference" && n.from != "cad")
    bad("from", "must be 'element', 'reference' or 'cad', got '" + n.from + "'");
  if (n.from == "cad") {
    if (n.cad.empty()) bad("cad", "is missing: the dataset of the CAD part");
    NominalSource only;
    only.from = n.from;
    only.cad = n.cad;
    only.pair = n.pair;
    if (!(n == only)) bad("from", "nominals from a CAD part take no element, fit or reference options");
    return;
  }
  if (!n.cad.empty()) bad("cad", "is only for nominals from a CAD part");
  geometry::ElementKind kind{};
  if (!n.element.empty() && !geometry::parseElementKind(n.element, &kind))
    bad("element", "must be plane, line, circle, sphere, cylinder or cone, got '" + n.element + "'");
  if (n.from == "element" && n.element.empty())
    bad("element", "is missing: which element the nominals lie on");
  if (!n.criterion.empty() && n.criterion != "ls" && n.criterion != "minimax")
    bad("criterion", "must be 'ls' or 'minimax', got '" + n.criterion + "'");
  if (!std::isfinite(n.radiusMm) || n.radiusMm < 0.0) bad("radius_mm", "must be a positive length in mm");
  if (n.radiusMm > 0.0 && (n.element.empty() || !geometry::takesFixedRadius(kind)))
    bad("radius_mm", "a fixed radius is for a sphere, circle or cylinder");
  if (n.from == "reference") {
    if (n.reference.empty()) bad("reference", "is missing: the dataset of the second measurement");
    if (n.pair != "id" && n.pair != "order") bad("pair", "must be 'id' or 'order', got '" + n.pair + "'");
  } else if (!n.reference.empty()) {
    bad("reference", "is only for nominals from a reference measurement");
  }
}

NominalsOutcome nominalsFor(const geometry::PointSet& measured, const NominalSource& n,
                            const geometry::PointSet* reference, Observer* observer) {
  checkNominalSource(n);
  if (n.from.empty()) bad("from", "is missing: say where the nominals come from (element or reference)");
  NominalsOutcome out;
  ProbePointSet& set = out.set;
  set.source = measured.source;
  const double sign = n.inner ? -1.0 : 1.0;
  const auto idOf = [&](std::size_t i) {
    return measured.ids.empty() ? std::to_string(i + 1) : measured.ids[i];
  };
  if (n.from == "element") {
    out.fit = fit(measured, n, observer);
    set.hasNormals = out.fit->element.kind != geometry::ElementKind::Line;
    for (std::size_t i = 0; i < measured.points.size(); ++i) {
      const geometry::ElementFoot f = geometry::footOnElement(out.fit->element, measured.points[i]);
      ProbePoint p;
      p.id = idOf(i);
      p.surface = n.element;
      p.nominal = f.point;
      p.normal = f.hasNormal ? Eigen::Vector3d(sign * f.normal) : Eigen::Vector3d::Zero();
      p.measured = measured.points[i];
      set.points.push_back(std::move(p));
    }
    return out;
  }
  // A second measurement.
  if (!reference) bad("reference", "names no dataset that could be read");
  std::vector<std::size_t> partner(measured.points.size());
  if (n.pair == "order") {
    if (reference->points.size() != measured.points.size())
      throw ValidationError(ErrorContext{measured.source, 0, 0, "nominals.pair"},
                            "has " + std::to_string(measured.points.size()) + " points and the reference " +
                                reference->source + " " + std::to_string(reference->points.size()) +
                                ": pairing by order needs the same number");
    for (std::size_t i = 0; i < partner.size(); ++i) partner[i] = i;
  } else {
    if (measured.ids.empty() || reference->ids.empty())
      throw ValidationError(
          ErrorContext{measured.ids.empty() ? measured.source : reference->source, 0, 0, "id"},
          "has no id column: pair the points by order instead");
    std::map<std::string, std::size_t> at;
    for (std::size_t i = 0; i < reference->ids.size(); ++i) at[reference->ids[i]] = i;
    std::vector<std::string> missing;
    for (std::size_t i = 0; i < partner.size(); ++i) {
      const auto it = at.find(measured.ids[i]);
      if (it == at.end())
        missing.push_back(measured.ids[i]);
      else
        partner[i] = it->second;
    }
    if (!missing.empty()) {
      std::string list;
      for (std::size_t k = 0; k < missing.size() && k < 5; ++k) list += (k ? ", " : "") + missing[k];
      if (missing.size() > 5) list += ", ...";
      throw ValidationError(ErrorContext{measured.source, 0, 0, "id"},
                            std::to_string(missing.size()) + " point(s) have no point of the same id in " +
                                reference->source + ": " + list);
    }
  }
  if (!n.element.empty()) out.fit = fit(*reference, n, observer);
  set.hasNormals = out.fit && out.fit->element.kind != geometry::ElementKind::Line;
  for (std::size_t i = 0; i < measured.points.size(); ++i) {
    const Eigen::Vector3d& q = reference->points[partner[i]];
    ProbePoint p;
    p.id = idOf(i);
    p.surface = n.element.empty() ? std::string("reference") : n.element;
    p.nominal = q;
    if (set.hasNormals) p.normal = sign * geometry::footOnElement(out.fit->element, q).normal;
    p.measured = measured.points[i];
    set.points.push_back(std::move(p));
  }
  return out;
}

ProbePointSet readProbePointDataset(const DatasetRef& dataset, const DatasetRef* reference,
                                    std::size_t minPoints) {
  if (dataset.nominals.empty())
    return readProbePointsAnyFormat(dataset.path, minPoints, dataset.csv, dataset.part);
  const geometry::PointSet measured = geometry::readPointTable(dataset.path, dataset.csv);
  std::optional<geometry::PointSet> ref;
  if (dataset.nominals.from == "cad") {
    if (!reference)
      throw ValidationError(ErrorContext{dataset.path, 0, 0, "nominals.cad"},
                            "dataset '" + dataset.nominals.cad + "' is not in the project");
    // The closest points of the part at the identity posture (the points are measured in the part's
    // coordinate system); the matching study re-projects them at each posture (cad_match.h).
    ProbePointSet set = matching::projectToCad(cadMeasuredPoints(measured), *readCadModel(*reference), {});
    if (set.points.size() < minPoints)
      throw ValidationError(ErrorContext{set.source, 0, 0, {}}, "has " + std::to_string(set.points.size()) +
                                                                    " points, at least " +
                                                                    std::to_string(minPoints) + " needed");
    return set;
  }
  if (dataset.nominals.from == "reference") {
    if (!reference)
      throw ValidationError(ErrorContext{dataset.path, 0, 0, "nominals.reference"},
                            "dataset '" + dataset.nominals.reference + "' is not in the project");
    ref = geometry::readPointTable(reference->path, reference->csv);
  }
  ProbePointSet set = nominalsFor(measured, dataset.nominals, ref ? &*ref : nullptr).set;
  if (set.points.size() < minPoints)
    throw ValidationError(ErrorContext{set.source, 0, 0, {}}, "has " + std::to_string(set.points.size()) +
                                                                  " points, at least " +
                                                                  std::to_string(minPoints) + " needed");
  return set;
}

ProbePointSet cadMeasuredPoints(const geometry::PointSet& measured) {
  ProbePointSet set;
  set.source = measured.source;
  for (std::size_t i = 0; i < measured.points.size(); ++i) {
    ProbePoint p;
    p.id = measured.ids.empty() ? std::to_string(i + 1) : measured.ids[i];
    p.surface = "cad";
    p.measured = measured.points[i];
    set.points.push_back(std::move(p));
  }
  return set;
}

std::shared_ptr<const geometry::MeshSearch> readCadModel(const DatasetRef& cad) {
  return std::make_shared<const geometry::MeshSearch>(geometry::readStl(cad.path));
}

const DatasetRef* nominalReference(const Project& project, const DatasetRef& dataset) {
  if (dataset.nominals.from == "cad") {
    const DatasetRef* c = project.dataset(dataset.nominals.cad);
    if (!c || c->kind != dataset_kind::kCadModel)
      throw ValidationError(ErrorContext{{}, 0, 0, "nominals.cad"},
                            "dataset '" + dataset.id + "': '" + dataset.nominals.cad +
                                "' is not a CAD part (cad_model dataset) of the project");
    return c;
  }
  if (dataset.nominals.from != "reference") return nullptr;
  const DatasetRef* r = project.dataset(dataset.nominals.reference);
  if (!r || r->kind != dataset_kind::kProbePoints || r->id == dataset.id)
    throw ValidationError(ErrorContext{{}, 0, 0, "nominals.reference"},
                          "dataset '" + dataset.id + "': '" + dataset.nominals.reference +
                              "' is not another probe-point dataset of the project");
  return r;
}

ProbePointSet readProjectProbePoints(const Project& project, const std::string& projectPath,
                                     const DatasetRef& dataset, std::size_t minPoints) {
  DatasetRef d = dataset;
  d.path = resolveDatasetPath(projectPath, dataset);
  std::optional<DatasetRef> r;
  if (const DatasetRef* ref = nominalReference(project, dataset)) {
    r = *ref;
    r->path = resolveDatasetPath(projectPath, *ref);
  }
  return readProbePointDataset(d, r ? &*r : nullptr, minPoints);
}

}  // namespace metrofit
