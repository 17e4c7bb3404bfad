// STL reader (core/geometry/stl.h): files written by the test from the format's description
// (mesh_fixtures.h), read back exactly (ASCII %.17g) or to float32 (binary); the detection of a binary
// file whose header starts with "solid"; and every malformed input with its one-line message naming
// the file and the line (ASCII) or the triangle and byte (binary).
#include "core/geometry/stl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/common/error.h"
#include "mesh_fixtures.h"
#include "testsupport.h"

namespace metrofit::geometry {
namespace {

using test::Facet;

std::vector<Facet> twoFacets() {
  return {Facet{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}}, Facet{{10, 0, 0}, {10, 10, 0}, {0, 10, 0}}};
}

/// The message of the ParseError that parsing `bytes` throws ("" when none is thrown).
std::string parseError(const std::string& bytes, const std::string& name = "part.stl") {
  try {
    parseStl(bytes, name);
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    EXPECT_EQ(e.context().file, name);
    return e.what();
  }
  ADD_FAILURE() << "no ParseError";
  return {};
}

void expectSameFacets(const TriangleMesh& m, const std::vector<Facet>& f, double tol) {
  ASSERT_EQ(m.triangles.size(), f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_LE((m.triangles[i].v[0] - f[i].a).norm(), tol) << i;
    EXPECT_LE((m.triangles[i].v[1] - f[i].b).norm(), tol) << i;
    EXPECT_LE((m.triangles[i].v[2] - f[i].c).norm(), tol) << i;
    EXPECT_LE((m.triangles[i].normal - f[i].normal()).norm(), 1e-6) << i;
  }
}

TEST(Stl, AsciiReadsExactly) {
  const auto f = test::sphereFacets({1.5, -2.0, 3.25}, 12.0, 24, 12);
  const TriangleMesh m = parseStl(test::asciiStl(f), "sphere.stl");
  EXPECT_EQ(m.source, "sphere.stl");
  expectSameFacets(m, f, 0.0);
  EXPECT_EQ(m.windingDisagreements, 0u);
  EXPECT_NEAR(m.boxMin().z(), 3.25 - 12.0, 1e-12);
  EXPECT_NEAR(m.boxMax().x(), 1.5 + 12.0, 1e-12);
}

TEST(Stl, BinaryReadsToFloatPrecision) {
  const auto f = test::sphereFacets({1.5, -2.0, 3.25}, 12.0, 24, 12);
  const std::string bin = test::binaryStl(f);
  ASSERT_EQ(bin.size(), 84u + 50u * f.size());
  const TriangleMesh m = parseStl(bin, "sphere.stl");
  // float32 keeps 24 bits: |x| < 16 mm is within 16 * 2^-24 = 1e-6 mm.
  expectSameFacets(m, f, 2e-6);
}

TEST(Stl, BinaryWithSolidHeaderIsReadAsBinary) {
  const auto f = twoFacets();
  const std::string bin = test::binaryStl(f, "solid part exported by a CAD system");
  const TriangleMesh m = parseStl(bin, "p.stl");
  expectSameFacets(m, f, 0.0);
}

TEST(Stl, KeywordsInAnyCaseAndSeveralSolids) {
  std::string a = test::asciiStl(twoFacets(), "first");
  std::string upper;
  for (char c : test::asciiStl({Facet{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}}, "second"))
    upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const TriangleMesh m = parseStl("\n  " + a + upper, "two.stl");
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[2].v[0].z(), 5.0);
}

TEST(Stl, Utf8SolidNameAndCrLf) {
  std::string a = test::asciiStl(twoFacets(),
                                 "Teil \xC3\x98"
                                 "20 Flansch");  // "Teil Ø20 Flansch"
  std::string crlf;
  for (char c : a) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const TriangleMesh m = parseStl(crlf, "flansch.stl");
  expectSameFacets(m, twoFacets(), 0.0);
}

TEST(Stl, StoredNormalDecidesTheOutsideWindingOtherwise) {
  // A facet wound clockwise seen from +z (winding normal -z) whose stored normal says +z.
  const std::string flipped =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
      "facet normal 0 0 0\nouter loop\nvertex 0 0 1\nvertex 0 1 1\nvertex 1 0 1\nendloop\nendfacet\nendsolid "
      "s\n";
  const TriangleMesh m = parseStl(flipped, "f.stl");
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_NEAR(m.triangles[0].normal.z(), 1.0, 1e-15);   // the stored normal
  EXPECT_NEAR(m.triangles[1].normal.z(), -1.0, 1e-15);  // no stored normal: the winding
  EXPECT_EQ(m.windingDisagreements, 1u);
}

TEST(Stl, EmptyFile) {
  EXPECT_EQ(parseError(""), "part.stl: empty file (not an STL)");
}

TEST(Stl, TruncatedBinary) {
  const std::string bin = test::binaryStl(test::sphereFacets({0, 0, 0}, 5.0, 8, 4));
  const std::string msg = parseError(bin.substr(0, bin.size() - 7));
  EXPECT_NE(msg.find("part.stl: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("header says 48 triangles needs 2484 bytes, the file has 2477"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
  // With "solid" in the header the message is the binary one too (the bytes are not text).
  const std::string solid = test::binaryStl(test::sphereFacets({0, 0, 0}, 5.0, 8, 4), "solid x");
  const std::string msg2 = parseError(solid.substr(0, solid.size() - 50));
  EXPECT_NE(msg2.find("starts with 'solid' but is not text"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("the file has 2434"), std::string::npos) << msg2;
  // Shorter than the header.
  EXPECT_NE(parseError(std::string(40, '\x01')).find("too short for a binary STL (40 bytes"),
            std::string::npos);
}

TEST(Stl, BadAsciiNumberNamesTheLine) {
  std::string a = test::asciiStl(twoFacets());
  const std::size_t at = a.find("vertex 10 0 0");
  ASSERT_NE(at, std::string::npos);
  a.replace(at, 13, "vertex 10 0,5 0");
  const std::string msg = parseError(a);
  EXPECT_EQ(msg, "part.stl:5: '0,5' is not a number (triangle 1, vertex 2)");
}

TEST(Stl, NonFiniteNumbers) {
  std::string a = test::asciiStl(twoFacets());
  a.replace(a.find("vertex 0 10 0"), 13, "vertex 0 nan 0");
  EXPECT_EQ(parseError(a), "part.stl:6: 'nan' is not a finite number (triangle 1, vertex 3)");

  std::string bin = test::binaryStl(twoFacets());
  // Triangle 2, vertex 1, x: byte 84 + 50 + 12.
  const float nan = std::nanf("");
  std::memcpy(&bin[84 + 50 + 12], &nan, 4);
  EXPECT_EQ(parseError(bin), "part.stl: triangle 2 (byte 134): vertex 1 has a non-finite coordinate");
}

TEST(Stl, ZeroAreaTriangles) {
  std::vector<Facet> f = twoFacets();
  f.push_back(Facet{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});  // collinear
  // ASCII: the facet starts on line 16 (1 solid line + 7 lines per facet).
  EXPECT_EQ(parseError(test::asciiStl(f)),
            "part.stl:16: triangle 3: zero area (coincident or collinear vertices), so it has no normal");
  f.back() = Facet{{5, 5, 5}, {5, 5, 5}, {5, 5, 5}};  // coincident
  EXPECT_EQ(
      parseError(test::binaryStl(f)),
      "part.stl: triangle 3 (byte 184): zero area (coincident or collinear vertices), so it has no normal");
}

TEST(Stl, StructureErrors) {
  EXPECT_EQ(parseError("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"),
            "part.stl:6: expected 'vertex' (triangle 1, vertex 3), found 'endloop'");
  EXPECT_EQ(parseError("solid x\n"), "part.stl:2: unexpected end of file: expected 'facet' or 'endsolid'");
  EXPECT_EQ(parseError("solid x\nendsolid x\n"), "part.stl: ASCII STL without a facet");
  const std::string noEnd =
      test::asciiStl(twoFacets()).substr(0, test::asciiStl(twoFacets()).rfind("endsolid"));
  EXPECT_NE(parseError(noEnd).find("unexpected end of file: expected 'facet' or 'endsolid'"),
            std::string::npos);
  EXPECT_EQ(parseError("hello world, this is not an STL"),
            "part.stl: not an ASCII STL (does not start with 'solid') and not a binary one: too short for a "
            "binary STL (31 bytes, the header alone is 84)");
  std::string bin0 = test::binaryStl({});
  EXPECT_EQ(parseError(bin0), "part.stl: binary STL with 0 triangles");
}

TEST(Stl, ReadsAFileAndNamesAMissingOne) {
  test::TempDir tmp;
  const auto f = twoFacets();
  test::writeText(tmp.file("a.stl"), test::binaryStl(f));
  expectSameFacets(readStl(tmp.file("a.stl")), f, 0.0);
  EXPECT_THROW(readStl(tmp.file("missing.stl")), FileError);
}

}  // namespace
}  // namespace metrofit::geometry
