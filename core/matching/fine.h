#pragma once
// Fine matching by a metaheuristic (Jiang et al., Mech. Sci. 9, 2018, Section 2.3): SADE as in the
// paper, GA-simplex as its comparison method; both are optim::Algorithm, the problem is below.
//
// Objective, Eq. (8): f(R1, T1) = (1/n) sum |Q_i - (P'_i R1 + T1)|^2 over the rough-matched actual
// points P' (Eq. 1). Eq. (9) eliminates T1 with the centroids (T1 = mean Q - mean P' R1), leaving the
// three angles (alpha1, beta1, gamma1) of R1. Reported as an RMS in mm, sqrt(f), which has the same
// minimiser and the unit of the paper's "f(R1) = 0.1148 mm" and of the match result's rmse_mm.
//
// Here the objective is evaluated in the posture convention of docs/file-formats.md#match-result (pose.h):
// for decision x the total alignment is A = A1(x) A0 (Eq. 2 prints R = R1 R0, which is this column-vector
// order; in the paper's own row vectors, P'' = (P R0 + T0) R1 + T1, it would read R0 R1), the posture
// rotation R = A^T, and SS = sum |p_i - (s R q_i + t)|^2 with t (and s with --allow-scale) optimal for R
// (fit_input.h optimalTranslationScale: the centroid translation of Eq. 9, extended to locked translation
// components and to the scale). For a rigid fit this equals n f(R1) exactly, since |q - A p - T| = |p - R q -
// t| for R = A^T, t = -A^T T. Eq. (2) as printed (T = T0 + T1) is the first-order form of the composition T =
// A1 T0 + T1; the exact composition is used.
//
// Bounds (Section 2.3.2): alpha1 in [-|alpha0| - k1, |alpha0| + k1], likewise beta1, gamma1, with the
// rough angles of PE0 (Eq. 7) and the margins k (boundMarginDeg, all three alike). Degrees.
//
// With rotation locks (or planar data, which lock rx and ry) the paper's angles of R1 cannot express
// "rx stays 0", so the decision becomes the free posture angles themselves (the result's rx, ry, rz,
// locked ones at their values), bounded by [-|r0_j| - k, |r0_j| + k] around the rough posture's
// angles r0; the translation elimination is the same.
#include <string>
#include <vector>

#include "core/matching/fit_input.h"
#include "core/matching/rough.h"
#include "core/optim/algorithm.h"

namespace metrofit::matching {

class FineMatchingProblem final : public optim::Problem {
 public:
  /// `locks` are the effective locks; marginDeg > 0 is k of Section 2.3.2.
  FineMatchingProblem(const ProbePointSet& set, const RoughResult& rough, const DofLocks& locks,
                      bool allowScale, double marginDeg);

  std::string name() const override { return "posture fine matching (Eq. 9)"; }
  std::size_t dimension() const override { return lower_.size(); }
  double lower(std::size_t i) const override { return lower_[i]; }
  double upper(std::size_t i) const override { return upper_[i]; }
  /// RMS of the residual distances (mm) at the decision x (degrees).
  double evaluate(std::span<const double> x, std::span<double> components) const override;

  /// True when the decision is the paper's (alpha1, beta1, gamma1); false in the locked mode.
  bool paperMode() const { return paperMode_; }
  /// "alpha1", "beta1", "gamma1" or the free ones of "rx", "ry", "rz".
  const std::vector<std::string>& variableNames() const { return names_; }
  /// The posture (with optimal translation / scale) at decision x.
  Pose poseAt(std::span<const double> x) const;
  /// The decision that reproduces the rough posture (0 in paper mode).
  std::vector<double> roughDecision() const;

 private:
  Eigen::Matrix3d rotationAt(std::span<const double> x) const;

  CentredPoints points_;
  Eigen::Matrix3d roughAlignment_;
  DofLocks locks_;
  bool allowScale_;
  bool paperMode_;
  std::vector<int> freeAngles_;  ///< locked mode: indices of the free posture angles
  Eigen::Vector3d roughAnglesDeg_;
  std::vector<std::string> names_;
  std::vector<double> lower_, upper_;
};

struct FineResult {
  bool paperMode = true;
  std::vector<std::string> variables;  ///< names of the decision variables
  std::vector<double> lowerDeg, upperDeg;
  std::vector<double> bestDeg;  ///< best decision
  double objectiveMm = 0.0;     ///< RMS at the best decision
  Pose pose;
  optim::Result optimisation;  ///< trace (one entry per generation / iteration), evaluations, termination
};

/// Runs `algorithm` on the fine-matching problem. When every angle is locked there is nothing to
/// search: the result is the translation of Eq. (9) with an empty trace.
FineResult fineMatch(const ProbePointSet& set, const RoughResult& rough, const optim::Algorithm& algorithm,
                     const DofLocks& locks, bool allowScale, double marginDeg, Observer* observer = nullptr);

}  // namespace metrofit::matching
