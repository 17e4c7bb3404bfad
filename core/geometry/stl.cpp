#include "core/geometry/stl.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/io/file_io.h"

namespace metrofit::geometry {
namespace {

constexpr std::size_t kHeaderBytes = 84;
constexpr std::size_t kRecordBytes = 50;

bool equalsNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

bool startsWithSolid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  return bytes.size() - i >= 5 && equalsNoCase(bytes.substr(i, 5), "solid");
}

/// Builds the triangle from its vertices and the stored normal (see triangle_mesh.h); an error
/// message when it has zero area, else empty.
std::string makeTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& stored, Triangle* t, bool* disagrees) {
  const Eigen::Vector3d cross = (b - a).cross(c - a);
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  const double area2 = cross.norm();
  if (!(area2 > 1e-12 * longest) || longest == 0.0)
    return "zero area (coincident or collinear vertices), so it has no normal";
  t->v = {a, b, c};
  t->normal = cross / area2;
  *disagrees = false;
  if (stored.squaredNorm() > 0.0 && stored.dot(t->normal) < 0.0) {
    t->normal = -t->normal;
    *disagrees = true;
  }
  return {};
}

std::uint32_t u32le(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

float f32le(const unsigned char* p) {
  const std::uint32_t u = u32le(p);
  float f;
  static_assert(sizeof f == sizeof u, "float32 expected");
  std::memcpy(&f, &u, sizeof f);
  return f;
}

TriangleMesh parseBinary(std::string_view bytes, const std::string& source, std::uint64_t count) {
  TriangleMesh mesh;
  mesh.source = source;
  if (count == 0) throw ParseError(ErrorContext{source, 0, 0, {}}, "binary STL with 0 triangles");
  mesh.triangles.reserve(static_cast<std::size_t>(count));
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::size_t offset = kHeaderBytes + static_cast<std::size_t>(k) * kRecordBytes;
    const unsigned char* rec = data + offset;
    Eigen::Vector3d v[4];
    for (int j = 0; j < 4; ++j) {
      for (int c = 0; c < 3; ++c) {
        const double x = f32le(rec + 4 * (3 * j + c));
        if (!std::isfinite(x)) {
          throw ParseError(ErrorContext{source, 0, 0, {}},
                           "triangle " + std::to_string(k + 1) + " (byte " + std::to_string(offset) +
                               "): " + (j == 0 ? std::string("normal") : "vertex " + std::to_string(j)) +
                               " has a non-finite coordinate");
        }
        v[j](c) = x;
      }
    }
    Triangle t;
    bool disagrees = false;
    const std::string why = makeTriangle(v[1], v[2], v[3], v[0], &t, &disagrees);
    if (!why.empty()) {
      throw ParseError(ErrorContext{source, 0, 0, {}}, "triangle " + std::to_string(k + 1) + " (byte " +
                                                           std::to_string(offset) + "): " + why);
    }
    mesh.windingDisagreements += disagrees ? 1 : 0;
    mesh.triangles.push_back(t);
  }
  return mesh;
}

/// Whitespace-separated tokens with their line numbers.
class Tokens {
 public:
  Tokens(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  /// The next token, or empty at the end of the text.
  std::string_view next() {
    skipSpace();
    tokenLine_ = line_;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  /// Skips the rest of the current line (a solid's name).
  void skipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  long line() const { return tokenLine_; }

  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(ErrorContext{source_, tokenLine_, 0, {}}, what);
  }
  void expect(std::string_view keyword, const std::string& where) {
    const std::string_view t = next();
    if (t.empty()) fail("unexpected end of file: expected '" + std::string(keyword) + "' " + where);
    if (!equalsNoCase(t, keyword))
      fail("expected '" + std::string(keyword) + "' " + where + ", found '" + std::string(t) + "'");
  }
  double number(const std::string& what) {
    std::string_view t = next();
    if (t.empty()) fail("unexpected end of file: expected a number (" + what + ")");
    const std::string_view written = t;
    if (t.front() == '+') t.remove_prefix(1);
    double v = 0.0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || res.ec != std::errc() || res.ptr != t.data() + t.size())
      fail("'" + std::string(written) + "' is not a number (" + what + ")");
    if (!std::isfinite(v)) fail("'" + std::string(written) + "' is not a finite number (" + what + ")");
    return v;
  }

 private:
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  long line_ = 1, tokenLine_ = 1;
};

TriangleMesh parseAscii(std::string_view text, const std::string& source) {
  TriangleMesh mesh;
  mesh.source = source;
  Tokens tok(text, source);
  tok.expect("solid", "at the start of an ASCII STL");
  tok.skipLine();
  for (;;) {
    const std::string_view t = tok.next();
    if (t.empty()) tok.fail("unexpected end of file: expected 'facet' or 'endsolid'");
    if (equalsNoCase(t, "endsolid")) {
      tok.skipLine();
      const std::string_view after = tok.next();
      if (after.empty()) break;
      if (!equalsNoCase(after, "solid"))
        tok.fail("expected 'solid' or the end of the file after 'endsolid', found '" + std::string(after) +
                 "'");
      tok.skipLine();
      continue;
    }
    if (!equalsNoCase(t, "facet")) tok.fail("expected 'facet' or 'endsolid', found '" + std::string(t) + "'");
    const std::string which = "triangle " + std::to_string(mesh.triangles.size() + 1);
    const long facetLine = tok.line();
    tok.expect("normal", "after 'facet' (" + which + ")");
    Eigen::Vector3d n;
    for (int c = 0; c < 3; ++c) n(c) = tok.number(which + ", normal");
    tok.expect("outer", "(" + which + ")");
    tok.expect("loop", "after 'outer' (" + which + ")");
    Eigen::Vector3d v[3];
    for (int j = 0; j < 3; ++j) {
      tok.expect("vertex", "(" + which + ", vertex " + std::to_string(j + 1) + ")");
      for (int c = 0; c < 3; ++c) v[j](c) = tok.number(which + ", vertex " + std::to_string(j + 1));
    }
    tok.expect("endloop", "after three vertices (" + which + ")");
    tok.expect("endfacet", "(" + which + ")");
    Triangle tri;
    bool disagrees = false;
    const std::string why = makeTriangle(v[0], v[1], v[2], n, &tri, &disagrees);
    if (!why.empty()) throw ParseError(ErrorContext{source, facetLine, 0, {}}, which + ": " + why);
    mesh.windingDisagreements += disagrees ? 1 : 0;
    mesh.triangles.push_back(tri);
  }
  if (mesh.triangles.empty()) throw ParseError(ErrorContext{source, 0, 0, {}}, "ASCII STL without a facet");
  return mesh;
}

}  // namespace

TriangleMesh parseStl(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw ParseError(ErrorContext{source, 0, 0, {}}, "empty file (not an STL)");
  std::uint64_t count = 0;
  std::uint64_t expected = 0;
  if (bytes.size() >= kHeaderBytes) {
    count = u32le(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    expected = kHeaderBytes + kRecordBytes * count;
    if (expected == bytes.size()) return parseBinary(bytes, source, count);
  }
  const std::string binaryNote =
      bytes.size() >= kHeaderBytes
          ? "a binary STL whose header says " + std::to_string(count) + " triangles needs " +
                std::to_string(expected) + " bytes, the file has " + std::to_string(bytes.size())
          : "too short for a binary STL (" + std::to_string(bytes.size()) + " bytes, the header alone is 84)";
  if (startsWithSolid(bytes)) {
    // Text, unless it holds control bytes no ASCII STL has (a binary file with "solid" in its header:
    // its triangle count and coordinates bring NULs). Bytes >= 128 are allowed (a UTF-8 solid name).
    bool text = true;
    for (const char ch : bytes.substr(0, std::min<std::size_t>(bytes.size(), 512))) {
      const auto u = static_cast<unsigned char>(ch);
      if (u == 0 || (u < 32 && !std::isspace(u)) || u == 127) {
        text = false;
        break;
      }
    }
    if (text) return parseAscii(bytes, source);
    throw ParseError(ErrorContext{source, 0, 0, {}},
                     "starts with 'solid' but is not text; as binary STL: " + binaryNote + " (truncated?)");
  }
  throw ParseError(ErrorContext{source, 0, 0, {}},
                   "not an ASCII STL (does not start with 'solid') and not a binary one: " + binaryNote +
                       (bytes.size() >= kHeaderBytes ? " (truncated?)" : ""));
}

TriangleMesh readStl(const std::string& path) {
  return parseStl(readFile(path), displayPath(path));
}

}  // namespace metrofit::geometry
