#pragma once
// Contact-probed point pairs (docs/file-formats.md#contact-probed-points):
//   id,surface,qx,qy,qz,nx,ny,nz,px,py,pz
// q = nominal point, n = nominal unit normal (out of the material), p = measured point, in mm.
// Lighter forms: without nx,ny,nz every point is position-only (deviation = whole distance);
// without qz,pz the data are planar (z = 0).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/io/csv.h"

namespace metrofit {
class CsvTable;

struct ProbePoint {
  std::string id;
  std::string surface;
  Eigen::Vector3d nominal = Eigen::Vector3d::Zero();   ///< q
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();    ///< n (zero when the set has no normals)
  Eigen::Vector3d measured = Eigen::Vector3d::Zero();  ///< p
};

struct ProbePointSet {
  std::string source;
  bool hasNormals = false;
  bool planar = false;
  std::vector<ProbePoint> points;

  /// Deviation of point i with respect to a transformed nominal: along the normal when the set has
  /// normals, else the full distance |p - q'| (always >= 0 then).
  double deviation(std::size_t i, const Eigen::Vector3d& transformedNominal,
                   const Eigen::Vector3d& transformedNormal) const;
  /// Deviations with the identity transform (the "before" state).
  std::vector<double> deviations() const;
};

/// Reads a probe point table; validates duplicate ids, non-finite numbers, zero / non-unit normals
/// (|n| must be within 1e-3 of 1) and at least `minPoints` points.
ProbePointSet probePointsFromCsv(const CsvTable& table, std::size_t minPoints = 3);
ProbePointSet readProbePoints(const std::string& path, std::size_t minPoints = 3,
                              const CsvReadOptions& csv = {});
std::string probePointsToCsv(const ProbePointSet& set);

}  // namespace metrofit
