#include "core/geometry/mesh_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <nanoflann.hpp>

#include "core/common/error.h"

namespace metrofit::geometry {
namespace {

/// nanoflann's dataset interface over the sample points.
struct SampleCloud {
  std::vector<Eigen::Vector3d> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return points[i](static_cast<Eigen::Index>(d)); }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, SampleCloud>,
                                                 SampleCloud, 3, std::size_t>;

/// Pseudonormals of the edges and vertices of every triangle (see the header): vertices welded by
/// identical coordinates, an edge's the sum of the normals of the triangles that share it, a vertex's
/// the sum of its triangles' normals weighted by their angles at it (Baerentzen and Aanaes 2005).
struct Pseudonormals {
  std::vector<std::array<Eigen::Vector3d, 3>> edge;    ///< AB, BC, CA
  std::vector<std::array<Eigen::Vector3d, 3>> vertex;  ///< A, B, C
};

Pseudonormals pseudonormals(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  std::map<std::array<double, 3>, std::size_t> ids;
  std::vector<std::array<std::size_t, 3>> tv(n);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& v = mesh.triangles[t].v[static_cast<std::size_t>(k)];
      tv[t][static_cast<std::size_t>(k)] =
          ids.emplace(std::array<double, 3>{v.x(), v.y(), v.z()}, ids.size()).first->second;
    }
  std::vector<Eigen::Vector3d> vsum(ids.size(), Eigen::Vector3d::Zero());
  std::map<std::pair<std::size_t, std::size_t>, Eigen::Vector3d> esum;
  auto key = [](std::size_t a, std::size_t b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
  for (std::size_t t = 0; t < n; ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (std::size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d e1 = tri.v[(k + 1) % 3] - tri.v[k], e2 = tri.v[(k + 2) % 3] - tri.v[k];
      const double c = std::clamp(e1.dot(e2) / (e1.norm() * e2.norm()), -1.0, 1.0);
      vsum[tv[t][k]] += std::acos(c) * tri.normal;
      auto [it, fresh] = esum.emplace(key(tv[t][k], tv[t][(k + 1) % 3]), Eigen::Vector3d::Zero());
      it->second += tri.normal;
    }
  }
  auto unit = [](const Eigen::Vector3d& v, const Eigen::Vector3d& fallback) {
    const double l = v.norm();
    return l > 0.0 ? Eigen::Vector3d(v / l) : fallback;
  };
  Pseudonormals p;
  p.edge.resize(n);
  p.vertex.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const Eigen::Vector3d& nt = mesh.triangles[t].normal;
    for (std::size_t k = 0; k < 3; ++k) {
      p.vertex[t][k] = unit(vsum[tv[t][k]], nt);
      p.edge[t][k] = unit(esum[key(tv[t][k], tv[t][(k + 1) % 3])], nt);
    }
  }
  return p;
}

/// The normal that decides the sign at the closest point's feature.
const Eigen::Vector3d& signNormal(const TriangleMesh& mesh, const Pseudonormals& pn, std::size_t t,
                                  TriangleFeature f) {
  switch (f) {
    case TriangleFeature::Face:
      return mesh.triangles[t].normal;
    case TriangleFeature::EdgeAB:
      return pn.edge[t][0];
    case TriangleFeature::EdgeBC:
      return pn.edge[t][1];
    case TriangleFeature::EdgeCA:
      return pn.edge[t][2];
    case TriangleFeature::VertexA:
      return pn.vertex[t][0];
    case TriangleFeature::VertexB:
      return pn.vertex[t][1];
    case TriangleFeature::VertexC:
      return pn.vertex[t][2];
  }
  return mesh.triangles[t].normal;
}

/// Fills the answer for triangle `t` at its closest point.
MeshPoint answer(const TriangleMesh& mesh, const Pseudonormals& pn, std::size_t t, const TrianglePoint& tp,
                 const Eigen::Vector3d& x) {
  MeshPoint m;
  m.point = tp.point;
  m.triangle = t;
  m.feature = tp.feature;
  const Eigen::Vector3d r = x - tp.point;
  m.distance = r.norm();
  m.normal = mesh.triangles[t].normal;
  const double sign = r.dot(signNormal(mesh, pn, t, tp.feature)) >= 0.0 ? 1.0 : -1.0;
  m.signedDistance = sign * m.distance;
  m.direction = (tp.feature == TriangleFeature::Face || m.distance == 0.0)
                    ? m.normal
                    : Eigen::Vector3d(sign * r / m.distance);
  return m;
}

}  // namespace

struct MeshSearch::Impl {
  TriangleMesh mesh;
  Pseudonormals pn;
  SampleCloud cloud;
  std::vector<std::size_t> sampleTriangle;
  std::vector<double> sampleRadius;
  double cover = 0.0;
  std::unique_ptr<Tree> tree;

  /// nanoflann result set whose radius is best + H (see the header).
  struct Closest {
    Closest(const Impl& i, const Eigen::Vector3d& p) : impl(i), x(p) {}
    const Impl& impl;
    const Eigen::Vector3d& x;
    double best = std::numeric_limits<double>::infinity();
    double worst2 = std::numeric_limits<double>::infinity();
    std::size_t bestTriangle = 0;
    TrianglePoint bestPoint;
    std::size_t tested = 0;

    std::size_t size() const { return 1; }
    bool full() const { return true; }
    double worstDist() const { return worst2; }
    bool addPoint(double dist2, std::size_t sample) {
      if (std::sqrt(dist2) - impl.sampleRadius[sample] >= best) return true;
      const std::size_t t = impl.sampleTriangle[sample];
      const Triangle& tri = impl.mesh.triangles[t];
      const TrianglePoint tp = closestPointOnTriangle(x, tri.v[0], tri.v[1], tri.v[2]);
      ++tested;
      const double d = (x - tp.point).norm();
      if (d < best) {
        best = d;
        bestTriangle = t;
        bestPoint = tp;
        worst2 = (best + impl.cover) * (best + impl.cover);
      }
      return true;
    }
  };
};

MeshSearch::MeshSearch(TriangleMesh mesh) : impl_(std::make_unique<Impl>()) {
  if (mesh.triangles.empty())
    throw ValidationError(ErrorContext{mesh.source, 0, 0, {}}, "the mesh has no triangles");
  Impl& m = *impl_;
  m.mesh = std::move(mesh);
  m.pn = pseudonormals(m.mesh);
  const std::size_t n = m.mesh.triangles.size();
  std::vector<double> radius(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& v = m.mesh.triangles[t].v;
    const Eigen::Vector3d g = (v[0] + v[1] + v[2]) / 3.0;
    radius[t] = std::max({(v[0] - g).norm(), (v[1] - g).norm(), (v[2] - g).norm()});
  }
  std::vector<double> sorted = radius;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2), sorted.end());
  double H = std::max(sorted[n / 2], std::numeric_limits<double>::min());
  auto splits = [&](double r, double h) { return r <= h ? 1.0 : std::ceil(r / h); };
  for (;;) {
    double count = 0.0;
    for (const double r : radius) count += splits(r, H) * splits(r, H);
    if (count <= 4.0 * static_cast<double>(n)) break;
    H *= 2.0;
  }
  m.cover = H;
  for (std::size_t t = 0; t < n; ++t) {
    const auto& v = m.mesh.triangles[t].v;
    const int k = static_cast<int>(splits(radius[t], H));
    if (k == 1) {
      m.cloud.points.push_back((v[0] + v[1] + v[2]) / 3.0);
      m.sampleTriangle.push_back(t);
      m.sampleRadius.push_back(radius[t]);
      continue;
    }
    // Regular subdivision: P(i, j) = a + (i/k)(b - a) + (j/k)(c - a); k^2 sub-triangles, each similar
    // to the triangle with ratio 1/k (the "down" ones point-reflected), so each has radius r_t / k.
    const Eigen::Vector3d e1 = (v[1] - v[0]) / k, e2 = (v[2] - v[0]) / k;
    auto P = [&](int i, int j) { return Eigen::Vector3d(v[0] + i * e1 + j * e2); };
    const double h = radius[t] / k;
    for (int i = 0; i < k; ++i) {
      for (int j = 0; i + j < k; ++j) {
        m.cloud.points.push_back((P(i, j) + P(i + 1, j) + P(i, j + 1)) / 3.0);
        m.sampleTriangle.push_back(t);
        m.sampleRadius.push_back(h);
        if (i + j + 1 < k) {
          m.cloud.points.push_back((P(i + 1, j) + P(i + 1, j + 1) + P(i, j + 1)) / 3.0);
          m.sampleTriangle.push_back(t);
          m.sampleRadius.push_back(h);
        }
      }
    }
  }
  m.tree = std::make_unique<Tree>(3, m.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
}

MeshSearch::~MeshSearch() = default;
MeshSearch::MeshSearch(MeshSearch&&) noexcept = default;
MeshSearch& MeshSearch::operator=(MeshSearch&&) noexcept = default;

const TriangleMesh& MeshSearch::mesh() const {
  return impl_->mesh;
}
std::size_t MeshSearch::sampleCount() const {
  return impl_->cloud.points.size();
}
double MeshSearch::coverRadiusMm() const {
  return impl_->cover;
}

MeshPoint MeshSearch::closest(const Eigen::Vector3d& x) const {
  Impl::Closest result(*impl_, x);
  const double q[3] = {x.x(), x.y(), x.z()};
  impl_->tree->findNeighbors(result, q, nanoflann::SearchParams());
  MeshPoint m = answer(impl_->mesh, impl_->pn, result.bestTriangle, result.bestPoint, x);
  m.trianglesTested = result.tested;
  return m;
}

MeshPoint MeshSearch::closestByBruteForce(const Eigen::Vector3d& x) const {
  const TriangleMesh& mesh = impl_->mesh;
  double best = std::numeric_limits<double>::infinity();
  std::size_t bestT = 0;
  TrianglePoint bestP;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const TrianglePoint tp = closestPointOnTriangle(x, v[0], v[1], v[2]);
    const double d = (x - tp.point).norm();
    if (d < best) {
      best = d;
      bestT = t;
      bestP = tp;
    }
  }
  MeshPoint m = answer(mesh, impl_->pn, bestT, bestP, x);
  m.trianglesTested = mesh.triangles.size();
  return m;
}

}  // namespace metrofit::geometry
