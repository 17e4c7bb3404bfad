#pragma once
// STL reader (issue 30 item 3: a CAD part as the nominal of posture matching). STL carries no unit:
// coordinates are read as millimetres.
//
// Formats (the de-facto specification: 3D Systems, "StereoLithography Interface Specification", 1989;
// also Burns, "Automated Fabrication", 1993, Section 6.5):
//   binary  80-byte header, uint32 triangle count n (little endian), then n records of 50 bytes:
//           normal, vertex 1, vertex 2, vertex 3 (12 float32, little endian) and a uint16 attribute.
//   ASCII   solid NAME / facet normal ni nj nk / outer loop / vertex x y z (three times) / endloop /
//           endfacet ... endsolid NAME; keywords in any case, any white space; several solids in one
//           file are read one after the other.
// Detection: a file of exactly 84 + 50 n bytes (n from its header) is binary, even when its header
// starts with "solid" (many binary writers put "solid" there); otherwise a file starting with "solid"
// is ASCII; anything else is a binary file of the wrong size (truncated or padded).
//
// Refused with a ParseError whose message names the file and the line (ASCII) or the triangle and its
// byte offset (binary): an empty file, a truncated or padded binary file, an unknown or missing
// keyword, a malformed or non-finite number (no NaN or infinity enters the mesh), a file without
// triangles, and a triangle of zero area (coincident or collinear vertices: |(b - a) x (c - a)| <=
// 1e-12 L^2, L its longest edge), which has no normal.
#include <string>
#include <string_view>

#include "core/geometry/triangle_mesh.h"

namespace metrofit::geometry {

/// Parses STL bytes (binary or ASCII, detected as above); `source` names the file in messages.
TriangleMesh parseStl(std::string_view bytes, const std::string& source);
/// Reads an STL file (FileError when it cannot be read; "-" is standard input).
TriangleMesh readStl(const std::string& path);

}  // namespace metrofit::geometry
