#pragma once
// Analytic surfaces as STL for the CAD-nominal tests (issue 30 item 3), written here from the STL
// format's description (80-byte header, uint32 count, 50-byte little-endian records; the ASCII
// keywords) and not with anything of core: a tessellated sphere, a closed cylinder and a plane, with
// every vertex on the analytic surface, so the tessellation lies inside the convex surface and its
// chord error (sagitta) per facet is R - sqrt(R^2 - rho^2), rho the facet's circumradius (the facet's
// plane is at sqrt(R^2 - rho^2) from the centre; a facet's points are no nearer than its plane).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace metrofit::test {

constexpr double kMeshPi = 3.14159265358979323846;

/// A triangle, counter-clockwise seen from outside.
struct Facet {
  Eigen::Vector3d a, b, c;
  Eigen::Vector3d normal() const { return (b - a).cross(c - a).normalized(); }
  /// Circumradius abc / (4 area).
  double circumradius() const {
    const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
    return la * lb * lc / (2.0 * (b - a).cross(c - a).norm());
  }
};

/// Orients f so that its winding normal points along `outward`.
inline Facet oriented(Facet f, const Eigen::Vector3d& outward) {
  if ((f.b - f.a).cross(f.c - f.a).dot(outward) < 0.0) std::swap(f.b, f.c);
  return f;
}

/// A UV sphere: nLat bands, nLon segments, poles as fans; every vertex on the sphere.
inline std::vector<Facet> sphereFacets(const Eigen::Vector3d& centre, double R, int nLon, int nLat) {
  auto V = [&](int i, int j) {
    const double th = kMeshPi * i / nLat, ph = 2.0 * kMeshPi * j / nLon;
    const double s = (i == 0 || i == nLat) ? 0.0 : std::sin(th);
    const double c = i == 0 ? 1.0 : i == nLat ? -1.0 : std::cos(th);
    return Eigen::Vector3d(centre + R * Eigen::Vector3d(s * std::cos(ph), s * std::sin(ph), c));
  };
  std::vector<Facet> out;
  for (int i = 0; i < nLat; ++i) {
    for (int j = 0; j < nLon; ++j) {
      const Eigen::Vector3d p00 = V(i, j), p10 = V(i + 1, j), p11 = V(i + 1, j + 1), p01 = V(i, j + 1);
      if (i > 0) {
        Facet f{p00, p10, p01};
        out.push_back(oriented(f, (f.a + f.b + f.c) / 3.0 - centre));
      }
      if (i + 1 < nLat) {
        Facet f{p10, p11, p01};
        out.push_back(oriented(f, (f.a + f.b + f.c) / 3.0 - centre));
      }
    }
  }
  return out;
}

/// Largest sagitta of a sphere's facets (see the header).
inline double sphereChordError(const std::vector<Facet>& facets, double R) {
  double e = 0.0;
  for (const Facet& f : facets) {
    const double rho = f.circumradius();
    e = std::max(e, R - std::sqrt(std::max(0.0, R * R - rho * rho)));
  }
  return e;
}

/// A closed cylinder around the axis through `base` along `axis` (unit), radius R, height h: nSeg
/// segments, nRings rings of rectangles (two facets each), caps as fans. Chord error R (1 - cos(pi/nSeg)).
inline std::vector<Facet> cylinderFacets(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double R,
                                         double h, int nSeg, int nRings) {
  const Eigen::Vector3d u = axis.normalized();
  const Eigen::Vector3d t = std::abs(u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (t - t.dot(u) * u).normalized(), e2 = u.cross(e1);
  auto V = [&](int ring, int j) {
    const double ph = 2.0 * kMeshPi * j / nSeg;
    return Eigen::Vector3d(base + h * ring / nRings * u + R * (std::cos(ph) * e1 + std::sin(ph) * e2));
  };
  std::vector<Facet> out;
  for (int r = 0; r < nRings; ++r) {
    for (int j = 0; j < nSeg; ++j) {
      const Eigen::Vector3d p00 = V(r, j), p10 = V(r + 1, j), p11 = V(r + 1, j + 1), p01 = V(r, j + 1);
      const Eigen::Vector3d mid = (p00 + p11) / 2.0;
      const Eigen::Vector3d radial = mid - base - (mid - base).dot(u) * u;
      out.push_back(oriented(Facet{p00, p10, p11}, radial));
      out.push_back(oriented(Facet{p00, p11, p01}, radial));
    }
  }
  const Eigen::Vector3d top = base + h * u;
  for (int j = 0; j < nSeg; ++j) {
    out.push_back(oriented(Facet{base, V(0, j), V(0, j + 1)}, -u));
    out.push_back(oriented(Facet{top, V(nRings, j), V(nRings, j + 1)}, u));
  }
  return out;
}

inline double cylinderChordError(double R, int nSeg) {
  return R * (1.0 - std::cos(kMeshPi / nSeg));
}

/// The rectangle [x0, x1] x [y0, y1] at height z, normal +z, as nx * ny squares of two facets.
inline std::vector<Facet> planeFacets(double x0, double x1, double y0, double y1, double z, int nx, int ny) {
  std::vector<Facet> out;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const double xa = x0 + (x1 - x0) * i / nx, xb = x0 + (x1 - x0) * (i + 1) / nx;
      const double ya = y0 + (y1 - y0) * j / ny, yb = y0 + (y1 - y0) * (j + 1) / ny;
      out.push_back(oriented(Facet{{xa, ya, z}, {xb, ya, z}, {xb, yb, z}}, Eigen::Vector3d::UnitZ()));
      out.push_back(oriented(Facet{{xa, ya, z}, {xb, yb, z}, {xa, yb, z}}, Eigen::Vector3d::UnitZ()));
    }
  }
  return out;
}

/// ASCII STL with %.17g numbers (exact doubles) and the winding normal.
inline std::string asciiStl(const std::vector<Facet>& facets, const std::string& name = "part") {
  std::string s = "solid " + name + "\n";
  char buf[256];
  for (const Facet& f : facets) {
    const Eigen::Vector3d n = f.normal();
    std::snprintf(buf, sizeof buf, "  facet normal %.17g %.17g %.17g\n    outer loop\n", n.x(), n.y(), n.z());
    s += buf;
    for (const Eigen::Vector3d* v : {&f.a, &f.b, &f.c}) {
      std::snprintf(buf, sizeof buf, "      vertex %.17g %.17g %.17g\n", v->x(), v->y(), v->z());
      s += buf;
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid " + name + "\n";
}

inline void appendU32(std::string& s, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}
inline void appendF32(std::string& s, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t u = 0;
  static_assert(sizeof f == sizeof u);
  std::memcpy(&u, &f, sizeof u);
  appendU32(s, u);
}

/// Binary STL (float32, little endian); `header` padded with spaces to 80 bytes.
inline std::string binaryStl(const std::vector<Facet>& facets,
                             std::string header = "binary STL from the test") {
  header.resize(80, ' ');
  std::string s = header;
  appendU32(s, static_cast<std::uint32_t>(facets.size()));
  for (const Facet& f : facets) {
    const Eigen::Vector3d n = f.normal();
    for (const Eigen::Vector3d* v : {&n, &f.a, &f.b, &f.c})
      for (int c = 0; c < 3; ++c) appendF32(s, (*v)(c));
    s.push_back('\0');
    s.push_back('\0');
  }
  return s;
}

}  // namespace metrofit::test
