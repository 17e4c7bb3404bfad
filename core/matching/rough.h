#pragma once
// Rough matching by local coordinate systems (Jiang et al., Mech. Sci. 9, 267-2018, Section 2.1-2.2).
//
// Three reference pairs (Q0, P0), (Q1, P1), (Q2, P2) of the theoretical (nominal) set Q and the actual
// (measured) set P span one local frame each, Eq. (3):
//   i = (X2 - X0) / |X2 - X0|,   k = (X1 - X0) x i / |(X1 - X0) x i|,   j = i x k      (X = Q or P)
// The printed Eq. (3) has lost the normalisation of k (|(X1 - X0) x i| = |X1 - X0| sin(angle) != 1);
// it is restored here. j = i x k makes (i, j, k) left-handed; both frames are built alike, so the
// handedness cancels in R0 below and R0 is a proper rotation (det +1).
//
// Eq. (4): [i_t j_t k_t]^T = [i_a j_a k_a]^T R0 (row vectors, P' = P R0 + T0, Eq. 1). In column
// vectors with F_t = [i_t j_t k_t], F_a = [i_a j_a k_a] (columns) the alignment A0 = R0^T maps the
// actual frame onto the theoretical one: A0 F_a = F_t, so A0 = F_t F_a^T.
// Eq. (5): the angles of R0 = (Rz(gamma0) Ry(beta0) Rx(alpha0))^T, i.e. (alpha0, beta0, gamma0) =
// eulerZyx(A0) (pose.h; atan2 instead of the printed arctan).
// Eq. (6): T0 = mean(Q) - A0 mean(P) (column form of T0 = (1/n) sum Q_i - (1/n) sum P_i R0): the
// frames' rotation is applied about the centroids, the translation comes from all points, not only
// from the three references.
// Eq. (7): PE0 = [alpha0 beta0 gamma0 tx0 ty0 tz0].
// The rough posture (the match result's convention, pose.h): R = A0^T, t = -A0^T T0.
//
// Reference choice ("far apart, non-collinear, outside the other points", Section 2.1): given ids, or
// automatically the triangle of nominal points with (locally) maximal area: start from the point
// farthest from the centroid, the point farthest from it and the point farthest from their line, then
// exchange one vertex at a time for the point that enlarges the area most until no exchange helps.
// O(n) per sweep, so it scales to large sets; X0-X2 is the longest side (i along it), X1 the vertex
// opposite, which keeps the frame well conditioned.
#include <array>
#include <string>
#include <vector>

#include "core/matching/pose.h"
#include "core/matching/probe_points.h"

namespace metrofit::matching {

struct LocalFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();    ///< X0
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns i, j, k of Eq. (3)
};

struct RoughResult {
  std::array<std::size_t, 3> reference{};                          ///< point indices of (X0, X1, X2)
  LocalFrame theoretical, actual;                                  ///< Eq. (3) on Q and on P
  Eigen::Matrix3d alignment = Eigen::Matrix3d::Identity();         ///< A0 = R0^T (column form)
  Eigen::Vector3d alignmentTranslation = Eigen::Vector3d::Zero();  ///< T0, Eq. (6)
  std::array<double, 6> pe0{};  ///< Eq. (7): alpha0, beta0, gamma0 (deg), tx0, ty0, tz0 (mm)
  Pose posture;                 ///< R = A0^T, t = -A0^T T0
};

/// Three reference points chosen automatically (see above), ordered (X0, X1, X2). ValidationError
/// naming the file when fewer than three points or all nominal points are collinear.
std::array<std::size_t, 3> chooseReferencePoints(const ProbePointSet& set);
/// Indices of three reference points given by id. ValidationError naming the id (field "reference")
/// when an id is unknown or repeated, or when the three points are collinear (nominal or measured).
std::array<std::size_t, 3> referencePointsById(const ProbePointSet& set, const std::vector<std::string>& ids);

/// Eq. (3) for three points: ValidationError-free; returns false when they are (nearly) collinear.
bool localFrame(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                LocalFrame* frame);

/// Rough matching with the given reference indices (Eq. 3-7).
RoughResult roughMatch(const ProbePointSet& set, const std::array<std::size_t, 3>& reference);
/// Rough matching with references by id, or chosen automatically when `referenceIds` is empty.
RoughResult roughMatch(const ProbePointSet& set, const std::vector<std::string>& referenceIds = {});

}  // namespace metrofit::matching
