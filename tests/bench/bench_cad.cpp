// metrofit-bench --cad (bench_cad.h). Protocol: a UV sphere of radius 20 mm tessellated into n
// triangles (every vertex on the sphere) for n from about 2k to 130k; 2000 query points within +-2 mm
// of the sphere (seed 1). The k-d tree (MeshSearch, built once; the build time is reported
// separately) and MeshSearch::closestByBruteForce answer every query; the answers must agree (the tree is
// exact; the largest difference is reported), the figure is the median time per query and the ratio brute
// force / tree. Then matchToCad of 1000 points on the largest mesh (posture 0.5 deg, 0.3 mm; rotations
// locked, the sphere fixes only the translation).
#include "bench_cad.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/common/rng.h"
#include "core/geometry/mesh_search.h"
#include "core/matching/cad_match.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;

geometry::TriangleMesh uvSphere(double R, int nLon, int nLat) {
  constexpr double kPi = 3.14159265358979323846;
  auto V = [&](int i, int j) {
    const double th = kPi * i / nLat, ph = 2.0 * kPi * j / nLon;
    const double s = (i == 0 || i == nLat) ? 0.0 : std::sin(th);
    const double c = i == 0 ? 1.0 : i == nLat ? -1.0 : std::cos(th);
    return Eigen::Vector3d(R * s * std::cos(ph), R * s * std::sin(ph), R * c);
  };
  geometry::TriangleMesh m;
  m.source = "uv-sphere";
  auto add = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    geometry::Triangle t;
    t.v = {a, b, c};
    t.normal = (b - a).cross(c - a).normalized();
    if (t.normal.dot(a + b + c) < 0.0) {
      std::swap(t.v[1], t.v[2]);
      t.normal = -t.normal;
    }
    m.triangles.push_back(t);
  };
  for (int i = 0; i < nLat; ++i)
    for (int j = 0; j < nLon; ++j) {
      if (i > 0) add(V(i, j), V(i + 1, j), V(i, j + 1));
      if (i + 1 < nLat) add(V(i + 1, j), V(i + 1, j + 1), V(i, j + 1));
    }
  return m;
}

template <class F>
double medianSeconds(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < repeat; ++i) {
    const auto a = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

nlohmann::json benchCad(int repeat) {
  nlohmann::json out = nlohmann::json::array();
  Rng rng(1);
  std::vector<Eigen::Vector3d> queries;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d d = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()).normalized();
    queries.push_back(d * (20.0 + rng.uniform(-2.0, 2.0)));
  }
  std::printf("cad: closest point on a tessellated sphere, 2000 queries, k-d tree vs brute force\n");
  std::printf("  %9s %10s %12s %14s %9s\n", "triangles", "build_ms", "tree_us/q", "brute_us/q", "ratio");
  geometry::TriangleMesh largest;
  for (const int nLon : {48, 96, 192, 384}) {
    const geometry::TriangleMesh mesh = uvSphere(20.0, nLon, nLon / 2);
    const auto b0 = Clock::now();
    const geometry::MeshSearch search(mesh);
    const double buildS = std::chrono::duration<double>(Clock::now() - b0).count();
    std::vector<double> tree(queries.size()), brute(queries.size());
    const double treeS = medianSeconds(repeat, [&] {
      for (std::size_t k = 0; k < queries.size(); ++k) tree[k] = search.closest(queries[k]).distance;
    });
    const int bruteRepeat = std::max(1, std::min(repeat, mesh.triangles.size() > 20000 ? 1 : repeat));
    const double bruteS = medianSeconds(bruteRepeat, [&] {
      for (std::size_t k = 0; k < queries.size(); ++k)
        brute[k] = search.closestByBruteForce(queries[k]).distance;
    });
    double worst = 0.0;
    for (std::size_t k = 0; k < queries.size(); ++k) worst = std::max(worst, std::abs(tree[k] - brute[k]));
    if (worst > 1e-9) throw std::runtime_error("cad bench: the k-d tree and brute force disagree");
    const double q = static_cast<double>(queries.size());
    std::printf("  %9zu %10.2f %12.2f %14.1f %9.0f\n", mesh.triangles.size(), buildS * 1e3, treeS / q * 1e6,
                bruteS / q * 1e6, bruteS / treeS);
    out.push_back({{"triangles", mesh.triangles.size()},
                   {"build_s", buildS},
                   {"tree_s_per_query", treeS / q},
                   {"brute_s_per_query", bruteS / q},
                   {"ratio", bruteS / treeS},
                   {"max_difference_mm", worst}});
    largest = mesh;
  }
  // One posture match on the largest mesh.
  const geometry::MeshSearch search(largest);
  const matching::Pose truth = matching::Pose::fromAnglesDeg({0, 0, 0}, {0.3, -0.2, 0.1});
  ProbePointSet points;
  points.source = "bench";
  for (int k = 0; k < 1000; ++k) {
    ProbePoint p;
    p.id = std::to_string(k + 1);
    const Eigen::Vector3d d = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()).normalized();
    p.measured = truth.apply(20.0 * d + 0.001 * rng.normal() * d);
    points.points.push_back(p);
  }
  matching::CadMatchOptions o;
  o.locks = matching::DofLocks::parse("rx,ry,rz", "locks");
  matching::CadMatchResult r;
  const double matchS = medianSeconds(repeat, [&] { r = matching::matchToCad(points, search, o); });
  const double err = (r.match.pose.translation - truth.translation).norm();
  std::printf(
      "  matchToCad: 1000 points, %zu triangles: %.1f ms, %ld iterations, translation error %.2g mm\n",
      largest.triangles.size(), matchS * 1e3, r.match.run.iterations, err);
  return {{"closest_point", out},
          {"match",
           {{"points", 1000},
            {"triangles", largest.triangles.size()},
            {"seconds", matchS},
            {"iterations", r.match.run.iterations},
            {"translation_error_mm", err}}}};
}

}  // namespace metrofit::bench
