#include "core/geometry/triangle_mesh.h"

namespace metrofit::geometry {

Eigen::Vector3d TriangleMesh::boxMin() const {
  if (triangles.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d m = triangles.front().v[0];
  for (const Triangle& t : triangles)
    for (const Eigen::Vector3d& v : t.v) m = m.cwiseMin(v);
  return m;
}

Eigen::Vector3d TriangleMesh::boxMax() const {
  if (triangles.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d m = triangles.front().v[0];
  for (const Triangle& t : triangles)
    for (const Eigen::Vector3d& v : t.v) m = m.cwiseMax(v);
  return m;
}

// Ericson, Real-Time Collision Detection (2005), Section 5.1.5, ClosestPtPointTriangle, with the
// region reported.
TrianglePoint closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, TriangleFeature::VertexA};  // vertex region A

  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, TriangleFeature::VertexB};  // vertex region B

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge region AB
    const double v = d1 / (d1 - d3);
    return {a + v * ab, TriangleFeature::EdgeAB};
  }

  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, TriangleFeature::VertexC};  // vertex region C

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge region AC
    const double w = d2 / (d2 - d6);
    return {a + w * ac, TriangleFeature::EdgeCA};
  }

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge region BC
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), TriangleFeature::EdgeBC};
  }

  // Face region: barycentric coordinates (u, v, w) = (va, vb, vc) / (va + vb + vc).
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + ab * v + ac * w, TriangleFeature::Face};
}

}  // namespace metrofit::geometry
