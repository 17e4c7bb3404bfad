#pragma once
// An axis-parallel box as ASCII STL, written from the format's definition (facet normal, outer loop,
// three vertices, counter-clockwise seen from outside; numbers with '.' whatever the locale), shared by the
// CAD-nominal tests of core and GUI.
#include <Eigen/Geometry>
#include <array>
#include <string>

#include "core/common/numformat.h"

namespace metrofit::test {

/// An axis-parallel box [0,a]x[0,b]x[0,c] as ASCII STL, 12 triangles, outward normals.
inline std::string boxStl(double a, double b, double c) {
  const Eigen::Vector3d v[8] = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                                {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
  // Faces as corner quadruples in counter-clockwise order seen from outside.
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  std::string s = "solid box\n";
  for (const auto& f : faces) {
    for (const auto& tri : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      const Eigen::Vector3d n = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).normalized();
      s += " facet normal " + num::general(n.x(), 17) + " " + num::general(n.y(), 17) + " " +
           num::general(n.z(), 17) + "\n  outer loop\n";
      for (int k : tri) {
        s += "   vertex " + num::general(v[k].x(), 17) + " " + num::general(v[k].y(), 17) + " " +
             num::general(v[k].z(), 17) + "\n";
      }
      s += "  endloop\n endfacet\n";
    }
  }
  return s + "endsolid box\n";
}

}  // namespace metrofit::test
