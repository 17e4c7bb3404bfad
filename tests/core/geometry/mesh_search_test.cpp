// Closest point on a triangle mesh (core/geometry/mesh_search.h, triangle_mesh.h):
//  * Ericson's closest point on a triangle checked by the projection's optimality condition (for the
//    closest point y of a convex set to x, (x - y) . (z - y) <= 0 for every z of the set; the vertices
//    suffice) on random triangles, and by hand on the seven regions;
//  * the k-d tree search against a brute-force loop over every triangle written here, on random points
//    near and far from a mesh that mixes small facets with two huge ones (the cover-radius bound);
//  * distances against the analytic distance to the true sphere / cylinder / plane the STL tessellates,
//    within the tessellation's chord error (mesh_fixtures.h).
#include "core/geometry/mesh_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/common/rng.h"
#include "core/geometry/stl.h"
#include "mesh_fixtures.h"

namespace metrofit::geometry {
namespace {

TriangleMesh meshOf(const std::vector<test::Facet>& facets, bool binary = false) {
  return parseStl(binary ? test::binaryStl(facets) : test::asciiStl(facets), "test.stl");
}

TEST(ClosestPointOnTriangle, SevenRegionsByHand) {
  const Eigen::Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  struct Case {
    Eigen::Vector3d p, y;
    TriangleFeature f;
  };
  const Case cases[] = {
      {{1, 1, 3}, {1, 1, 0}, TriangleFeature::Face},     {{-1, -1, 2}, {0, 0, 0}, TriangleFeature::VertexA},
      {{6, -1, 0}, {4, 0, 0}, TriangleFeature::VertexB}, {{-1, 6, 0}, {0, 4, 0}, TriangleFeature::VertexC},
      {{2, -3, 1}, {2, 0, 0}, TriangleFeature::EdgeAB},  {{3, 3, 5}, {2, 2, 0}, TriangleFeature::EdgeBC},
      {{-2, 2, 0}, {0, 2, 0}, TriangleFeature::EdgeCA}};
  for (const Case& k : cases) {
    const TrianglePoint r = closestPointOnTriangle(k.p, a, b, c);
    EXPECT_LE((r.point - k.y).norm(), 1e-15) << k.p.transpose();
    EXPECT_EQ(r.feature, k.f) << k.p.transpose();
  }
}

TEST(ClosestPointOnTriangle, OptimalOnRandomTriangles) {
  Rng rng(7);
  auto rnd = [&](double s) {
    return Eigen::Vector3d(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s));
  };
  int faces = 0, edges = 0, vertices = 0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector3d a = rnd(5), b = rnd(5), c = rnd(5), x = rnd(10);
    const TrianglePoint r = closestPointOnTriangle(x, a, b, c);
    // y inside the triangle: barycentric coordinates in [0, 1].
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double area2 = n.squaredNorm();
    if (area2 < 1e-6) continue;
    const double u = (c - b).cross(r.point - b).dot(n) / area2, v = (a - c).cross(r.point - c).dot(n) / area2,
                 w = (b - a).cross(r.point - a).dot(n) / area2;
    EXPECT_GE(std::min({u, v, w}), -1e-12);
    EXPECT_LE(std::abs((r.point - a).dot(n)) / std::sqrt(area2), 1e-12);  // in the plane
    // Optimality of the projection.
    const double scale = (x - r.point).norm() * 10.0 + 1e-300;
    for (const Eigen::Vector3d* z : {&a, &b, &c}) EXPECT_LE((x - r.point).dot(*z - r.point), 1e-12 * scale);
    faces += r.feature == TriangleFeature::Face;
    edges += r.feature == TriangleFeature::EdgeAB || r.feature == TriangleFeature::EdgeBC ||
             r.feature == TriangleFeature::EdgeCA;
    vertices += r.feature == TriangleFeature::VertexA || r.feature == TriangleFeature::VertexB ||
                r.feature == TriangleFeature::VertexC;
  }
  // Every kind of region was exercised.
  EXPECT_GT(faces, 500);
  EXPECT_GT(edges, 500);
  EXPECT_GT(vertices, 500);
}

/// The brute force of this test: every triangle, the smallest distance.
double bruteForceDistance(const TriangleMesh& m, const Eigen::Vector3d& x, std::size_t* triangle) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& v = m.triangles[t].v;
    const double d = (x - closestPointOnTriangle(x, v[0], v[1], v[2]).point).norm();
    if (d < best) {
      best = d;
      *triangle = t;
    }
  }
  return best;
}

TEST(MeshSearch, KdTreeEqualsBruteForce) {
  // Small facets (sphere, cylinder) beside two huge ones (a 400 mm square): the cover radius must
  // stay correct where triangle sizes differ by three orders of magnitude.
  std::vector<test::Facet> f = test::sphereFacets({0, 0, 0}, 20.0, 48, 24);
  for (const auto& c : test::cylinderFacets({40, 0, -20}, {0, 0, 1}, 8.0, 40.0, 64, 2)) f.push_back(c);
  for (const auto& p : test::planeFacets(-200, 200, -200, 200, -40.0, 1, 1)) f.push_back(p);
  const TriangleMesh mesh = meshOf(f);
  const MeshSearch search(mesh);
  EXPECT_GT(search.sampleCount(), mesh.triangles.size());  // the big ones are split
  EXPECT_LE(search.sampleCount(), 4 * mesh.triangles.size());

  Rng rng(11);
  double tested = 0.0;
  const int n = 600;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector3d x;
    if (k % 3 == 0) {  // anywhere, also far outside
      x = {rng.uniform(-300, 300), rng.uniform(-300, 300), rng.uniform(-120, 120)};
    } else if (k % 3 == 1) {  // near the sphere
      const Eigen::Vector3d d = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()).normalized();
      x = d * (20.0 + rng.uniform(-3, 3));
    } else {  // near the cylinder and the plane
      x = {rng.uniform(25, 55), rng.uniform(-15, 15), rng.uniform(-45, 25)};
    }
    std::size_t bt = 0;
    const double brute = bruteForceDistance(mesh, x, &bt);
    const MeshPoint m = search.closest(x);
    ASSERT_EQ(m.distance, brute) << "point " << k << " at " << x.transpose() << ": tree triangle "
                                 << m.triangle << ", brute force " << bt;
    EXPECT_LE((m.point - x).norm() - brute, 1e-12);
    EXPECT_EQ(std::abs(m.signedDistance), m.distance);
    EXPECT_NEAR(m.direction.norm(), 1.0, 1e-12);
    tested += static_cast<double>(m.trianglesTested);
    // The library's own brute force agrees too.
    EXPECT_EQ(search.closestByBruteForce(x).distance, brute);
  }
  // The tree tests a small share of the triangles.
  EXPECT_LT(tested / n, 0.1 * static_cast<double>(mesh.triangles.size()));
}

TEST(MeshSearch, KdTreeEqualsBruteForceOnARandomSoup) {
  // 400 triangles of sizes from 0.01 to 60 mm in random places and orientations (slivers included):
  // the cover radius is doubled until the samples fit, and the search must stay exact.
  Rng rng(21);
  TriangleMesh mesh;
  mesh.source = "soup";
  while (mesh.triangles.size() < 400) {
    const double size = std::pow(10.0, rng.uniform(-2.0, 1.8));
    const Eigen::Vector3d c(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50));
    Triangle t;
    for (auto& v : t.v) v = c + size * Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal());
    const Eigen::Vector3d n = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
    if (n.norm() < 1e-9 * size * size) continue;
    t.normal = n.normalized();
    mesh.triangles.push_back(t);
  }
  const MeshSearch search(mesh);
  for (int k = 0; k < 3000; ++k) {
    const Eigen::Vector3d x(rng.uniform(-80, 80), rng.uniform(-80, 80), rng.uniform(-80, 80));
    std::size_t bt = 0;
    const double brute = bruteForceDistance(mesh, x, &bt);
    ASSERT_EQ(search.closest(x).distance, brute) << "point " << k << ", brute force triangle " << bt;
  }
}

TEST(MeshSearch, SphereWithinChordError) {
  const double R = 10.0;
  const auto f = test::sphereFacets({1, 2, 3}, R, 144, 72);
  const double e = test::sphereChordError(f, R);
  ASSERT_GT(e, 1e-3);  // the check below is not vacuous
  ASSERT_LT(e, 6e-3);
  for (const bool binary : {false, true}) {
    const MeshSearch search(meshOf(f, binary));
    // float32 vertices move the binary surface by < 2e-6 mm.
    const double tol = e + (binary ? 2e-6 : 1e-12);
    Rng rng(3);
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
      const Eigen::Vector3d d = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()).normalized();
      const double r = k % 10 == 0 ? rng.uniform(0.5 * R, 3 * R) : R + rng.uniform(-2.0, 2.0);
      const Eigen::Vector3d x = Eigen::Vector3d(1, 2, 3) + r * d;
      const MeshPoint m = search.closest(x);
      const double analytic = r - R;
      worst = std::max(worst, std::abs(m.signedDistance - analytic));
      ASSERT_LE(std::abs(m.signedDistance - analytic), tol) << x.transpose();
      // The mesh is inside the sphere: it is never nearer to an outside point than the sphere.
      if (analytic > 0) {
        EXPECT_GE(m.signedDistance, analytic - (binary ? 2e-6 : 1e-12));
      }
    }
    EXPECT_GT(worst, 0.3 * e);  // the chord error is really there (the tolerance is not loose)
  }
}

TEST(MeshSearch, CylinderWithinChordError) {
  const double R = 8.0;
  const int nSeg = 200;
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.3, 1.0).normalized(), base(5, -4, 2);
  const MeshSearch search(meshOf(test::cylinderFacets(base, axis, R, 40.0, nSeg, 4)));
  const double e = test::cylinderChordError(R, nSeg);
  Rng rng(5);
  for (int k = 0; k < 2000; ++k) {
    const double h = rng.uniform(8.0, 32.0), ph = rng.uniform(0, 2 * test::kMeshPi);
    const double rho = R + rng.uniform(-1.5, 2.0);
    const Eigen::Vector3d t = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d e1 = (t - t.dot(axis) * axis).normalized(), e2 = axis.cross(e1);
    const Eigen::Vector3d x = base + h * axis + rho * (std::cos(ph) * e1 + std::sin(ph) * e2);
    const MeshPoint m = search.closest(x);
    ASSERT_LE(std::abs(m.signedDistance - (rho - R)), e + 1e-12) << x.transpose();
  }
}

TEST(MeshSearch, PlaneIsExact) {
  const MeshSearch search(meshOf(test::planeFacets(-50, 50, -50, 50, 0.0, 10, 10)));
  Rng rng(9);
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d x(rng.uniform(-49, 49), rng.uniform(-49, 49), rng.uniform(-5, 5));
    const MeshPoint m = search.closest(x);
    EXPECT_NEAR(m.signedDistance, x.z(), 1e-12);
    EXPECT_LE((m.point - Eigen::Vector3d(x.x(), x.y(), 0.0)).norm(), 1e-12);
    EXPECT_EQ(m.normal, Eigen::Vector3d::UnitZ());
    EXPECT_EQ(m.feature == TriangleFeature::Face, m.direction == Eigen::Vector3d::UnitZ());
  }
  // Beyond the edge: distance to the edge, direction from the edge to the point, sign of the normal.
  const MeshPoint m = search.closest({53, 0, 4});
  EXPECT_NEAR(m.distance, 5.0, 1e-12);
  EXPECT_NEAR(m.signedDistance, 5.0, 1e-12);
  EXPECT_LE((m.direction - Eigen::Vector3d(0.6, 0, 0.8)).norm(), 1e-12);
}

TEST(MeshSearch, SignAtSharpEdgesAndVertices) {
  // A flat tetrahedron: dihedral angles far below 90 deg at its rim, so near an edge or a vertex one
  // adjacent triangle's normal can point away from the point's side. Inside / outside is decided here
  // from the four face planes of the convex solid.
  const Eigen::Vector3d P[4] = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {2, 2, 1}};
  const Eigen::Vector3d g = (P[0] + P[1] + P[2] + P[3]) / 4.0;
  std::vector<test::Facet> f;
  for (const auto& idx : {std::array<int, 3>{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}}) {
    test::Facet t{P[idx[0]], P[idx[1]], P[idx[2]]};
    f.push_back(test::oriented(t, (t.a + t.b + t.c) / 3.0 - g));
  }
  const MeshSearch search(meshOf(f));
  Rng rng(13);
  int checked = 0, oneNormalWrong = 0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector3d x(rng.uniform(-2, 12), rng.uniform(-2, 12), rng.uniform(-1.5, 2.5));
    bool inside = true;
    for (const test::Facet& t : f) inside = inside && t.normal().dot(x - t.a) < 0.0;
    const MeshPoint m = search.closest(x);
    if (m.distance < 1e-9) continue;
    ++checked;
    ASSERT_EQ(m.signedDistance < 0.0, inside) << x.transpose() << " feature " << static_cast<int>(m.feature);
    // The sign from the closest triangle's own normal alone would be wrong here:
    oneNormalWrong += ((x - m.point).dot(m.normal) < 0.0) != inside;
    // The direction points from the surface towards x (outside) or away from it (inside).
    EXPECT_NEAR(m.direction.dot(x - m.point), m.signedDistance, 1e-9);
  }
  EXPECT_GT(checked, 19000);
  EXPECT_GT(oneNormalWrong, 10);  // the case is real
}

TEST(MeshSearch, EmptyMeshIsRefused) {
  TriangleMesh m;
  m.source = "none.stl";
  EXPECT_THROW(MeshSearch{m}, ValidationError);
}

}  // namespace
}  // namespace metrofit::geometry
