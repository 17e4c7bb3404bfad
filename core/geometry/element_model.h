#pragma once
// Internal to core/geometry: the parametrised element in a local frame (element_fit.h explains it).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/geometry/element_fit.h"

namespace metrofit::geometry::detail {

/// One element kind with its parameters x in a local frame: q = F^T (p - o).
///   plane    (a, b, d)                 n = (a, b, 1)/|.|, d_i = n.q - d
///   line     (x0, y0, a, b)            axis through (x0, y0, 0) along u = (a, b, 1)/|.|
///   circle   (x0, y0[, r])             in the local xy plane (the least-squares plane)
///   sphere   (cx, cy, cz[, r])
///   cylinder (x0, y0, a, b[, r])
///   cone     (x0, y0, a, b, r0, psi)   radius r0 + h tan psi at height h above (x0, y0, 0)
class ElementModel {
 public:
  ElementModel(ElementKind kind, double fixedRadius, const std::vector<Eigen::Vector3d>& points,
               const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, double lengthScale);

  ElementKind kind() const { return kind_; }
  bool fixedRadius() const { return fixedR_ > 0.0; }
  int size() const;
  /// The signed residual of input point i.
  double residual(const Eigen::VectorXd& x, std::size_t i) const;
  /// mm of movement per unit of parameter j (1 for lengths, the RMS radius of the points for slopes
  /// and angles), so that x_j * scale(j) is a length.
  double scale(int j) const;
  /// "centre", "axis direction", "radius", "half angle", "offset".
  std::string role(int j) const;
  FittedElement element(const Eigen::VectorXd& x) const;
  bool oneSided() const { return kind_ == ElementKind::Line; }
  double lengthScale() const { return L_; }
  std::size_t pointCount() const { return q_.size(); }

 private:
  ElementKind kind_;
  double fixedR_;
  std::vector<Eigen::Vector3d> q_;
  Eigen::Vector3d o_;
  Eigen::Matrix3d F_;
  double L_;
};

/// The minimum-zone fit of the points `idx` from x (element_fit.h): sequential LP with a trust region
/// and the certificate at the end. `observer` sees one summary per LP iteration.
struct MinimumZoneOutcome {
  Eigen::VectorXd x;
  MinimaxCertificate certificate;
  int lpSolves = 0;
  Termination termination = Termination::Converged;
  std::string message;
};
MinimumZoneOutcome minimumZone(const ElementModel& model, Eigen::VectorXd x,
                               const std::vector<std::size_t>& idx, int maxIterations, Observer* observer);

}  // namespace metrofit::geometry::detail
