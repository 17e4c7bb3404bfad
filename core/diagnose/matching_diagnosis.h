#pragma once
// The closed loop for the matching domain (docs/file-formats.md#the-declared-models: a rigid-body
// posture error, rotation and translation, nothing else).
//
// Observations (docs/file-formats.md#match-result: a point's deviation is its residual along the nominal
// normal where the file has normals, else the whole residual):
//   * points with normals: one per point, the deviation along the (rotated) nominal normal,
//       r_i = (R n_i) . (p_i - f(q_i));  the tangential position of a probed point carries no
//       information about the part (the probe is driven there), so it is not fitted;
//   * position-only points: the components of p_i - f(q_i), two per point for planar data (hole
//     tables: x, y), three otherwise.
// Model: f(q) = R (q + sum_k beta_k d_k(q)) + t with the effect displacements d_k in the part's
// frame (the same as core/sim/effects_matching.h, scale and distortion about the centroid of the
// nominal points, which only moves the translation):
//   scale                     1 parameter  ppm        d = 1e-6 (q - mean q)
//   surface_offset:<surface>  1 parameter  mm         d = n on that surface (+ = outward, along the
//                                                     nominal normal); only for sets with normals
//   distortion                2 parameters ppm, angle_deg: D = ppm [[cos 2a, sin 2a], [sin 2a,
//                             -cos 2a]] on (x, y) (stretch +ppm along angle_deg, -ppm across it),
//                             fitted linearly as c = ppm cos 2a, s = ppm sin 2a; ppm = hypot(c, s),
//                             angle = atan2(s, c) / 2 in (-90, 90] deg, standard errors by the delta
//                             method.
// The declared rigid posture is started at the core closed form (closed_form.h, with the implicit
// planar locks) and every model (declared plus effects) is fitted by Gauss-Newton on (rotation
// increment, translation, beta) with a rank-revealing solve (rigid degrees of freedom the normals do
// not determine stay at their closed-form values). Evidence, acceptance and standard errors as
// linear_evidence.h, on the model linearised at the optimum (rigid Jacobian = declared columns).
// An effect whose columns the rigid posture absorbs (e.g. an offset of a single plane, which is a
// translation) is reported as not identifiable and rejected.
//
// rmse / max_abs: rms and largest absolute value of the deviations (along the normal, or the residual
// distances |p - f(q)| for position-only data), mm. Residual plots: scale -> residual along the
// radius (or the normal) against the distance from the centroid; surface_offset -> deviation per
// point against the surface index (ResidualPlot::categories names them); distortion -> radial
// residual against the polar angle (deg), plus the 2D field `vectors` = (x, y, dx, dy) of the
// in-plane residuals before the effect, in the nominal frame.
//
// The open world (docs/file-formats.md#residual_check, residual_check.h): points whose rigid-fit residual has
// a robust z above the outlier threshold are excluded before the loop (residualCheck->outliers, with row and
// id) unless the rest would not determine the posture. Every round also tries the generic effects
// of the current residual's strongest structures (variables: row, nominal x, y, z, the polar angle
// about the centroid, the surface as levels, the normal's nx, ny, nz, and surface:<s> = the
// position along the surface's longest principal direction), as displacements along the normal (or
// per coordinate for position-only data), under the same decision with the search penalty
// 2 ln(tests); the lowest dBIC wins the round, named or generic.
#include <string>

#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/diagnose/linear_evidence.h"
#include "core/matching/matching.h"
#include "core/matching/probe_points.h"

namespace metrofit::diagnose {

struct MatchingDiagnosisOptions {
  /// dBIC < -10 and rmse reduction >= 2 % (acceptance.minAbsoluteReduction applies too).
  AcceptanceOptions acceptance{10.0, 0.02, 0.0};
  /// Symmetric tolerance (mm): an effect must also reduce the rmse by at least
  /// relevantFractionOfTolerance * toleranceMm to be practically relevant.
  double toleranceMm = matching::kDefaultToleranceMm;
  double relevantFractionOfTolerance = 0.01;
  int maxRounds = 10;
  int maxIterations = 50;  ///< Gauss-Newton iterations per fit

  bool isValid(std::string* why) const;
};

/// The displacement (part frame, mm) of every point of `set` of a generic effect
/// `unexplained:<against>` with the coefficients w the diagnosis estimated (Candidate::
/// genericCoefficients): genericBasis(shape) w on the variable `against` of the set (as the loop
/// computes its variables: row, x, y, z, angle, surface, nx, ny, nz, surface:<s>), along the nominal
/// normal where the set has normals, else per coordinate; minus its least-squares projection on what
/// the posture (a rotation and translation about the centroid) and the catalogue's named effects
/// of the loop's run (shape.projectedOff: scale, surface offsets, distortion) can do, observed as
/// the fit observes: the loop fits the
/// generic effect so projected, so it is the part of the deformation no named effect and no posture
/// represents. Empty when the set has no such variable or w does not have one number per column.
std::vector<Eigen::Vector3d> matchingGenericDisplacement(const ProbePointSet& set, const GenericForm& shape,
                                                         const std::vector<double>& coefficients);

/// The loop on a probe point set (any form of probe_points.h). ValidationError when the points do
/// not determine the rigid posture (fit_input.h requireDeterminable). The observer is called after
/// every round and may cancel.
Diagnosis diagnoseMatching(const ProbePointSet& set, const MatchingDiagnosisOptions& options = {},
                           Observer* observer = nullptr);

}  // namespace metrofit::diagnose
