#pragma once
// Closest point on a triangle mesh: the exact closest triangle, found with a k-d tree (nanoflann,
// J. L. Blanco and P. K. Rai, https://github.com/jlblanco07/nanoflann; Debian libnanoflann-dev).
//
// The tree holds sample points of the triangles, not the triangles. Every triangle is covered by
// samples: a triangle whose circumscribing radius about its centroid r_t (the largest vertex distance
// from the centroid) is at most the cover radius H has one sample, its centroid, with radius h = r_t;
// a larger one is split regularly into m^2 similar sub-triangles, m = ceil(r_t / H), each sample the
// centroid of one sub-triangle with h = r_t / m <= H. So every point of a triangle lies within h <= H
// of one of its samples. H starts at the median r_t and is doubled until there are at most 4 samples
// per triangle (a tessellation with a few long slivers, common in CAD exports, keeps small triangles
// cheap without exploding the sample count).
//
// Search (exact, not approximate): let d* be the distance from x to the mesh, y* a closest point and
// s* the sample of the sub-triangle holding y*; then |x - s*| <= d* + h(s*) <= d* + H. The search keeps
// the best exact distance found so far, best >= d*, and asks the tree for every sample within best + H
// (a nanoflann result set whose radius shrinks as best does): s* is always inside that ball, and its
// triangle is tested exactly (closestPointOnTriangle, Ericson's region method) unless the
// sub-triangle's own bound |x - s| - h already reaches best. Hence the result is the closest triangle
// (ties between triangles that share the closest point, e.g. at an edge, are broken arbitrarily).
//
// Signed distance: +|x - y| when x lies outside, (x - y) . N >= 0, -|x - y| else, with N the
// pseudonormal of the feature y lies in (J. A. Baerentzen and H. Aanaes, "Signed distance computation
// using the angle weighted pseudonormal", IEEE TVCG 11(3), 2005): the triangle's normal in a face, the
// sum of the normals of the two triangles sharing an edge, the angle-weighted sum of the normals of the
// triangles around a vertex (vertices welded where their coordinates are identical, as STL repeats
// them). For a closed, consistently oriented mesh this sign is right everywhere, also at sharp edges
// and vertices where one triangle's normal would give the wrong side. `direction` is the unit vector
// along which the distance is measured, out of the material: the triangle normal when y is inside the
// face (then x - y is parallel to it) or x is on the surface, else sign * (x - y) / |x - y| (y on an
// edge or a vertex). It is the gradient of the signed distance, which point-to-plane matching needs
// (cad_match.h).
#include <cstddef>
#include <memory>

#include "core/geometry/triangle_mesh.h"

namespace metrofit::geometry {

struct MeshPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< closest point y on the mesh
  std::size_t triangle = 0;                             ///< index into TriangleMesh::triangles
  TriangleFeature feature = TriangleFeature::Face;      ///< where y lies on that triangle
  double distance = 0.0;                                ///< |x - y| (mm)
  double signedDistance = 0.0;                          ///< +-distance (see the header)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();     ///< the triangle's outward unit normal
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< unit direction of the signed distance
  std::size_t trianglesTested = 0;                      ///< exact triangle tests this query took
};

class MeshSearch {
 public:
  /// Builds the tree; the mesh is copied. ValidationError naming mesh.source when it has no triangles.
  explicit MeshSearch(TriangleMesh mesh);
  ~MeshSearch();
  MeshSearch(MeshSearch&&) noexcept;
  MeshSearch& operator=(MeshSearch&&) noexcept;
  MeshSearch(const MeshSearch&) = delete;
  MeshSearch& operator=(const MeshSearch&) = delete;

  /// The closest point of the mesh to x (exact; see the header). x must be finite.
  MeshPoint closest(const Eigen::Vector3d& x) const;
  /// The same answer by testing every triangle (for benchmarks and checks).
  MeshPoint closestByBruteForce(const Eigen::Vector3d& x) const;

  const TriangleMesh& mesh() const;
  std::size_t sampleCount() const;
  double coverRadiusMm() const;  ///< H

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace metrofit::geometry
