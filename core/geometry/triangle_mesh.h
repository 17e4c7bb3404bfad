#pragma once
// A triangle mesh as a CAD nominal (issue 30 item 3): the triangle soup of an STL file (stl.h), in mm.
//
// Every triangle keeps its three vertices (STL shares none) and its outward unit normal. The normal's
// direction is always the exact one of the vertices' plane, (b - a) x (c - a) normalised; its sense
// (which side is out of the material) follows the facet normal the file stores when that is non-zero,
// else the winding (counter-clockwise seen from outside, the STL convention). A file whose stored
// normals disagree with its winding is thus read as the writer meant it; the number of such facets is
// kept (`windingDisagreements`).
//
// Closest point on a triangle (C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann 2005,
// Section 5.1.5, ClosestPtPointTriangle): the query point's barycentric region is found from six dot
// products (d1..d6 below), the point is projected onto the vertex, the edge or the face of that
// region. Exact up to rounding (no iteration); it also reports which of the seven Voronoi regions
// (face interior, one of three edges, one of three vertices) the closest point lies in.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace metrofit::geometry {

struct Triangle {
  std::array<Eigen::Vector3d, 3> v;                  ///< vertices a, b, c (mm)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< outward unit normal (see the header)
};

struct TriangleMesh {
  std::string source;  ///< the file as the user named it (messages)
  std::vector<Triangle> triangles;
  std::size_t windingDisagreements = 0;  ///< facets whose stored normal points against their winding

  /// Axis-aligned bounding box of the vertices (zero for an empty mesh).
  Eigen::Vector3d boxMin() const;
  Eigen::Vector3d boxMax() const;
};

/// The part of a triangle the closest point lies in (Ericson's Voronoi regions).
enum class TriangleFeature { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

struct TrianglePoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  TriangleFeature feature = TriangleFeature::Face;
};

/// The point of triangle (a, b, c) closest to p (Ericson's region method, see the header). A
/// degenerate triangle (zero area) gives a point of it too, but readers refuse such triangles.
TrianglePoint closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace metrofit::geometry
