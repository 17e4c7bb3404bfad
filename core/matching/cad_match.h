#pragma once
// Posture matching against a CAD nominal (issue 30 item 3): measured points (no nominal pairs) matched
// to a triangle mesh (core/geometry/stl.h, mesh_search.h), in the posture convention of pose.h,
// p = s R q + t, q on the CAD surface.
//
// Iterative closest point with point-to-plane steps (Y. Chen and G. Medioni, "Object modelling by
// registration of multiple range images", Image Vision Comput. 10(3), 1992; the ICP loop of P. J. Besl
// and N. D. McKay, IEEE PAMI 14(2), 1992). From the current posture P_k (the identity at the start: the
// points are measured in the part's coordinate system, as a probing program does; locked parameters at
// their lock values):
//   1. re-project: for every measured p_i the closest point q_i of the mesh to P_k^-1(p_i) (exact,
//      mesh_search.h) and the unit direction n_i of its signed distance (the facet normal in a face);
//      this is a probe point set with normals (probe_points.h), the nominal of the existing matching;
//   2. fit: the posture over the free parameters (the DOF locks of pose.h, the scale with allowScale)
//      that minimises, with q_i and n_i held,
//        closed-form  sum_i d_i^2   (least squares)        d_i = (p_i - (s R q_i + t)) . (R n_i),
//        minimax      max_i |d_i|   (minimax.h, started from P_k),
//      where d_i is the deviation of evaluation.h. The least-squares step is the constrained fit of
//      closed_form.h with the point-to-plane residual: Gauss-Newton with the Levenberg-Marquardt
//      safeguard of core/optim/least_squares.h, started from P_k, Jacobian
//        dd/d(angle_j) = -s (dR_j q) . (R n) + (p - s R q - t) . (dR_j n),  dd/dt = -R n,  dd/ds = -q . n;
//   3. stop when the largest displacement of a nominal point between P_k and P_k+1,
//      max_i |P_k+1(q_i) - P_k(q_i)|, is at most convergenceMm (Converged), after maxIterations
//      (MaxIterations), or when the observer says Stop (Cancelled, with the last posture).
// The point-to-plane residual is the first-order model of the distance to the surface, so near the
// solution the loop converges much faster than point-to-point ICP (Chen-Medioni; Rusinkiewicz and
// Levoy 2001). Nothing is random: the same input gives the same trace (no seed is needed).
//
// After the loop the points are re-projected once more at the final posture: `after` holds the
// closest points, and its evaluation's deviations are the signed point-to-surface distances
// (mesh_search.h: +outside along the outward facet normal), scaled by s; `before` is the same at the
// identity posture. The determinability check of fit_input.h (deviations along the normals) runs on
// the first projection: a plane alone cannot fix an in-plane shift or a sphere alone a rotation, and
// the error says which parameter to lock.
#include <nlohmann/json_fwd.hpp>

#include "core/common/run.h"
#include "core/geometry/mesh_search.h"
#include "core/matching/matching.h"

namespace metrofit::matching {

struct CadMatchOptions {
  MatchMethod method = MatchMethod::ClosedForm;  ///< ClosedForm (least squares) or Minimax
  double toleranceMm = kDefaultToleranceMm;      ///< of the before/after evaluation (>= 0)
  bool allowScale = false;
  DofLocks locks;
  int maxIterations = 100;      ///< closest-point iterations (>= 1)
  double convergenceMm = 1e-7;  ///< posture change that ends the loop (> 0, mm)
  int fitIterations = 100;      ///< Gauss-Newton iterations of one least-squares step (>= 1)
  MinimaxOptions minimax;       ///< allowScale / locks are taken from this struct's own fields
  bool keepTrace = true;

  bool isValid(std::string* why) const;
};

struct CadMatchResult {
  MatchResult match;  ///< method, pose, locks, before/after evaluations, run (one trace entry per iteration)
  ProbePointSet before;  ///< closest points at the identity posture (nominal = closest point, normal = n_i)
  ProbePointSet after;   ///< closest points at the final posture
  std::vector<geometry::MeshPoint> closestAfter;  ///< the mesh answers behind `after`
  std::string cadSource;
  std::size_t triangles = 0;
  std::size_t windingDisagreements = 0;  ///< geometry::TriangleMesh::windingDisagreements
  double maxDistanceMm = 0.0;  ///< largest |p_i - P(q_i)| after the fit (the point-to-surface distance)
};

/// Matches `measured` (only ProbePoint::measured, id and surface are used) to the mesh. OptionsError
/// for a method other than closed-form / minimax or invalid options; ValidationError (naming
/// measured.source) when the points cannot determine the free parameters.
CadMatchResult matchToCad(const ProbePointSet& measured, const geometry::MeshSearch& cad,
                          const CadMatchOptions& options, Observer* observer = nullptr);

/// The closest points of the mesh to P^-1(p_i) as a probe point set with normals (step 1 above).
ProbePointSet projectToCad(const ProbePointSet& measured, const geometry::MeshSearch& cad, const Pose& pose,
                           std::vector<geometry::MeshPoint>* answers = nullptr);

/// The deviation each triangle of the part shows in a view coloured by deviation ("the part coloured
/// by deviation", issue 30): that of the measured point whose closest point on the part (`closest`,
/// in the part's frame) lies nearest to the triangle's centroid, when it is within `radiusMm` of it;
/// NaN (not measured there) otherwise. radiusMm <= 0: 1.5 times the median distance between
/// neighbouring closest points (at least 1e-3 of the part's size). Linear in the triangles (a grid of
/// cells of the radius).
std::vector<double> triangleDeviations(const geometry::TriangleMesh& mesh, const ProbePointSet& closest,
                                       const std::vector<double>& deviations, double radiusMm = 0.0);

/// The match JSON (matching.h toJson of the result and `after`: method, rotation_deg, translation_mm,
/// rmse_mm, max_abs_mm, out_of_tolerance, per_point, trace, ...) plus "cad": {file, triangles,
/// max_distance_mm, fit, winding_disagreements (facets whose stored normal contradicts their winding)}.
nlohmann::json toJson(const CadMatchResult& result);

/// Measured points only (`match --cad`): columns `id,px,py,pz` or `id,x_mm,y_mm,z_mm` (an optional
/// `surface`; without `id` the points are numbered 1, 2, ... in file order). ValidationError / ParseError
/// naming the file, line and column for a missing column, a bad number, an empty or duplicate id.
ProbePointSet measuredPointsFromCsv(const CsvTable& table);
ProbePointSet readMeasuredPoints(const std::string& path, const CsvReadOptions& csv = {});

}  // namespace metrofit::matching
