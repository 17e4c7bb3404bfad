#pragma once
// What every posture fit needs from a probe point set: the free parameters after the implicit locks,
// the validation that the points determine them, and centred coordinates.
//
// Free parameters: the six of the posture (rx, ry, rz, x, y, z) minus the locks, plus the scale s
// with --allow-scale. Planar data (no qz/pz) fix rx, ry and z at 0 implicitly: z = 0 for every point,
// so those three are not observable and a fit must not invent them.
//
// Determinability: the fit's Jacobian at the nominal posture (d(sRq + t)/d(parameters) per point, or
// for a minimax fit on points with normals d(deviation)/d(parameters) = [(q x n)^T, n^T, q.n]) must
// have full column rank, judged on unit-normalised columns (smallest / largest singular value
// > 1e-9). When it has not, the error names the cause a person can fix: too few points, coincident or
// collinear points, normals that leave a parameter undetermined (e.g. all normals parallel).
#include <optional>
#include <string>
#include <utility>

#include <Eigen/Core>

#include "core/common/error.h"
#include "core/matching/pose.h"
#include "core/matching/probe_points.h"

namespace metrofit::matching {

/// The kind of objective a fit minimises.
enum class FitKind {
  LeastSquares,  ///< sum of squared residual distances (closed form, rough + SADE / GA-simplex)
  Minimax,       ///< largest |deviation| (along the normal where the set has normals)
  PointToPlane,  ///< sum of squared deviations along the normals (cad_match.h)
};

/// Locks implied by the data: planar sets lock rx, ry and z at 0.
DofLocks implicitLocks(const ProbePointSet& set);
/// User locks merged with the implicit ones.
DofLocks effectiveLocks(const ProbePointSet& set, const DofLocks& userLocks);

/// Throws ValidationError (file = set.source) when the points cannot determine the free parameters
/// of the fit (see above); `method` names the fit in the message ("closed-form fit", ...).
void requireDeterminable(const ProbePointSet& set, const DofLocks& locks, bool allowScale, FitKind kind,
                         const std::string& method);

/// requireDeterminable's error for a parameter the points leave undetermined, with that parameter:
/// a Dof index 0-5, or kDofCount for the scale.
class UndeterminedParameterError : public ValidationError {
 public:
  UndeterminedParameterError(ErrorContext context, std::string what, int parameter)
      : ValidationError(std::move(context), std::move(what)), parameter_(parameter) {}
  int parameter() const noexcept { return parameter_; }

 private:
  int parameter_;
};

/// The user locks `locks` plus the ones (at 0) that make the fit determinable: each parameter
/// requireDeterminable finds undetermined is locked in turn (a sphere's points lock rx, ry, rz).
/// `locks` itself when nothing is missing; nullopt when no lock helps (too few points, an undetermined
/// scale, collinear measured points): requireDeterminable's error says why.
std::optional<DofLocks> locksToDetermine(const ProbePointSet& set, const DofLocks& locks, bool allowScale,
                                         FitKind kind);

/// Centred coordinates: qc_i = q_i - mean(q), pc_i = p_i - mean(p) (two passes, no cancellation of
/// large coordinates) and the moments the fits use.
struct CentredPoints {
  std::size_t n = 0;
  Eigen::Vector3d qMean = Eigen::Vector3d::Zero(), pMean = Eigen::Vector3d::Zero();
  Eigen::Matrix3Xd qc, pc;
  Eigen::Matrix3d crossCovariance = Eigen::Matrix3d::Zero();  ///< K = sum pc_i qc_i^T
  double sqq = 0.0, spp = 0.0;                                ///< sum |qc|^2, sum |pc|^2
};
CentredPoints centredPoints(const ProbePointSet& set);

/// Least-squares translation and scale for a given rotation, with locks (exact, from the centred
/// moments): free components t_j = (mean(p) - s R mean(q))_j, locked ones keep their value; with
/// allowScale s minimises the sum of squares for that R and those translations (else s = 1).
/// Returns the full pose and writes the sum of squared residual distances to *sumSquares.
Pose optimalTranslationScale(const CentredPoints& c, const Eigen::Matrix3d& R, const DofLocks& locks,
                             bool allowScale, double* sumSquares = nullptr);

}  // namespace metrofit::matching
