#pragma once
// Tolerance evaluation of a probe point set under a posture (docs/file-formats.md#match-result).
//
// For a posture p = s R q + t (pose.h) and point i:
//   residual distance  e_i = |p_i - (s R q_i + t)|
//   deviation          d_i = (p_i - (s R q_i + t)) . (R n_i)   where the set has normals,
//                      d_i = e_i                                 else (position-only or planar points)
// and over a group of points (the whole set or one surface):
//   rmse_mm            sqrt(mean e_i^2)          (the objective of the paper's Eq. 8, as an RMS in mm)
//   max_abs_mm         max |d_i|
//   out_of_tolerance   #{ |d_i| > tolerance }
//   mean_over_tolerance_mm  mean of (|d_i| - tolerance) over the out-of-tolerance points, 0 if none
//                      (the paper's Section 4 figure "average over tolerance 1.8797 mm").
// The "before" state is the identity posture (the measured points against the nominal WCS).
#include <string>
#include <vector>

#include "core/matching/pose.h"
#include "core/matching/probe_points.h"

namespace metrofit::matching {

struct DeviationStats {
  std::size_t points = 0;
  double rmseMm = 0.0;
  double maxAbsMm = 0.0;
  std::size_t outOfTolerance = 0;
  double meanOverToleranceMm = 0.0;
};

struct SurfaceStats {
  std::string surface;  ///< as in the file ("" when the file has no surface column)
  DeviationStats stats;
};

struct ToleranceEvaluation {
  double toleranceMm = 0.0;
  DeviationStats overall;
  std::vector<SurfaceStats> surfaces;  ///< in order of first appearance
  std::vector<double> deviations;      ///< d_i per point (signed where the set has normals)
  std::vector<double> distances;       ///< e_i per point
  /// p_i - (s R q_i + t) per point (mm, in the measured frame): the per-point deviation vector that
  /// `match` writes as per_point dx/dy/dz (docs/file-formats.md#match-result).
  std::vector<Eigen::Vector3d> residuals;
  std::size_t worstPoint = 0;  ///< index of the largest |d_i|
};

/// Evaluates `set` under `pose` against a symmetric tolerance (mm, >= 0). ValidationError naming the
/// file for an empty set; OptionsError for a negative or non-finite tolerance.
ToleranceEvaluation evaluateTolerance(const ProbePointSet& set, const Pose& pose, double toleranceMm);

/// The per-point deviations of an evaluation as CSV (`match --per-point FILE`, CloudCompare-style):
/// `id,surface,d_mm,dx_mm,dy_mm,dz_mm` in input order, d_i signed along the nominal normal where the set
/// has normals (else the distance e_i), '.' decimals whatever the locale.
std::string perPointCsv(const ToleranceEvaluation& evaluation, const ProbePointSet& set);

/// max_i |d_i| under `pose` (the minimax objective), without the per-surface bookkeeping.
double maxAbsDeviation(const ProbePointSet& set, const Pose& pose);

}  // namespace metrofit::matching
