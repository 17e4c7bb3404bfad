#pragma once
// Nominals for measured points (issue 28 item 4): a probe-point dataset whose file holds measured points
// only (raw CMM points: id,x,y,z, or px,py,pz) takes its nominal points and normals from
//   - an element fitted to the points themselves (core/geometry/element_fit.h): the nominal of point p
//     is its foot on the element, the normal the element's normal there (footOnElement), reversed for
//     an inner element (a bore: the material is outside it). The deviation along the normal is then
//     the element's signed residual, so the per-point deviations are the fit's residuals (+ = more
//     material for an outer element);
//   - a second measurement of the same part (another probe-point dataset's measured points), paired
//     by id or by order: the nominal of p is the reference point; normals from an element fitted to
//     the reference points (its normal at each reference point's foot), or none (position-only points:
//     the deviation is the whole distance).
// The recipe is the dataset's "nominals" key (core/project/project.h NominalSource); every reader of a
// probe-point dataset (the Matching page, the diagnosis, the report, `project list`) goes through
// readProbePointDataset, so they all see the same points.
#include <memory>
#include <optional>
#include <string>

#include "core/common/run.h"
#include "core/geometry/element_fit.h"
#include "core/geometry/mesh_search.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"

namespace metrofit {

/// ValidationError naming the field ("nominals.element", ...) for a recipe that cannot work: `from`
/// not "element" or "reference", an unknown element or criterion, a radius that is negative, not finite
/// or given for an element without one, "element" without an element, "reference" without a dataset id,
/// `pair` not "id" or "order". A recipe with `from` empty must be empty.
void checkNominalSource(const NominalSource& n);

struct NominalsOutcome {
  ProbePointSet set;
  /// The element fitted (to the measured points for "element", to the reference points for "reference"
  /// with an element); empty otherwise.
  std::optional<geometry::ElementFitResult> fit;
};

/// Makes the probe points of `measured` with the nominals of `n` (checked first). `reference` is the
/// second measurement for "reference" (ignored otherwise). Pairing by id needs ids in both sets and
/// every measured id in the reference (ValidationError naming the first unpaired ids); by order the same
/// number of points. `observer` sees the element fit.
NominalsOutcome nominalsFor(const geometry::PointSet& measured, const NominalSource& n,
                            const geometry::PointSet* reference, Observer* observer = nullptr);

/// Measured points as the CAD matching takes them (core/matching/cad_match.h): ids (1, 2, ... without an
/// id column), surface "cad", no nominals.
ProbePointSet cadMeasuredPoints(const geometry::PointSet& measured);
/// The CAD part of a cad_model dataset (path resolved), ready for closest-point queries.
std::shared_ptr<const geometry::MeshSearch> readCadModel(const DatasetRef& cad);

/// Reads a probe-point dataset the way the project says: the file's own nominals, or (with `nominals`)
/// its measured points with nominals made by nominalsFor. `dataset.path` and `reference->path` are
/// readable as they are (resolved); `reference` is the dataset nominals.reference or nominals.cad names
/// (nullptr when the recipe needs none). ValidationError when a needed reference is missing.
ProbePointSet readProbePointDataset(const DatasetRef& dataset, const DatasetRef* reference,
                                    std::size_t minPoints = 3);
/// The same for a dataset of `project` saved at `projectPath` (paths relative to its folder); the
/// reference looked up in the project (ValidationError naming "nominals.reference" when it is not there
/// or not a probe-point dataset).
ProbePointSet readProjectProbePoints(const Project& project, const std::string& projectPath,
                                     const DatasetRef& dataset, std::size_t minPoints = 3);
/// The dataset `dataset`'s recipe names in `project`: the second measurement ("reference") or the CAD
/// part ("cad"); nullptr when the recipe names none. ValidationError as above.
const DatasetRef* nominalReference(const Project& project, const DatasetRef& dataset);

}  // namespace metrofit
