// GTS files (pkg/io/GtsFile.hpp): the orientation convention on our own octahedron and on YADE's example files,
// exact round trips through the writer, and every malformed input refused with the path and the line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "pkg/io/GtsFile.hpp"
#include "pkg/io/MeshFile.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

const std::string kData = ROUNDEDMESH_TEST_DATA "/";
// Debian's yade package installs YADE's examples here (gts-horse/horse.coarse.gts and others).
const std::string kYadeExamples = "/usr/share/doc/yade/examples/";

// The octahedron of tests/data/make_meshes.py (semi-axes 1.5, 1, 0.75), corners counter-clockwise seen from outside.
const std::vector<Vector3r> kOctahedronVertices = {{1.5, 0, 0}, {-1.5, 0, 0}, {0, 1, 0},
                                                   {0, -1, 0},  {0, 0, 0.75}, {0, 0, -0.75}};
const std::vector<std::vector<std::size_t>> kOctahedronTriangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

// Signed volume of a soup of triangles [m^3]: positive when every triangle is counter-clockwise seen from outside.
Real signedVolume(const PolygonSoup& soup) {
  Real volume = 0;
  for (const auto& p : soup.polygons) volume += soup.points[p[0]].dot(soup.points[p[1]].cross(soup.points[p[2]])) / 6;
  return volume;
}

// A file of this process's own in the temporary directory (ctest runs the tests side by side).
std::string temporaryPath(const std::string& name) {
  const std::string own = "roundedmesh_gts_test_" + std::to_string(::getpid()) + "_" + name;
  return (std::filesystem::temp_directory_path() / own).string();
}

// A temporary file holding `text`, removed when it goes out of scope.
struct Written {
  Written(const std::string& name, const std::string& text) : path(temporaryPath(name)) {
    std::ofstream(path, std::ios::binary) << text;
  }
  ~Written() { std::remove(path.c_str()); }
  Written(const Written&) = delete;
  Written& operator=(const Written&) = delete;
  operator const std::string&() const { return path; }
  const std::string path;
};

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

using test::refusal;

// The unit right tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), volume 1/6: the base the refusals change.
// Edges 12, 23, 31, 14, 24, 34; faces 132, 124, 143, 234 counter-clockwise seen from outside.
const std::string kTetrahedronHeader = "4 6 4 GtsSurface GtsFace GtsEdge GtsVertex\n";
const std::string kTetrahedronVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string kTetrahedronEdges = "1 2\n2 3\n3 1\n1 4\n2 4\n3 4\n";
const std::string kTetrahedronFaces = "3 2 1\n1 5 4\n4 6 3\n2 6 5\n";
const std::string kTetrahedron = kTetrahedronHeader + kTetrahedronVertices + kTetrahedronEdges + kTetrahedronFaces;

TEST(GtsFile, OctahedronIsReadOutwardWithTheCornersOfItsEdges) {
  // octahedron.gts lists each face from a different edge and its edges in both directions (make_meshes.py).
  const PolygonSoup soup = readGtsSoup(kData + "octahedron.gts");
  EXPECT_EQ(soup.points, kOctahedronVertices);
  ASSERT_EQ(soup.polygons.size(), 8u);
  for (std::size_t f = 0; f < 8; ++f) {
    // The same cycle as the reference triangle, from whichever corner.
    const auto& p = soup.polygons[f];
    const auto& q = kOctahedronTriangles[f];
    const bool sameCycle = (p == q) || (p == std::vector<std::size_t>{q[1], q[2], q[0]}) ||
                           (p == std::vector<std::size_t>{q[2], q[0], q[1]});
    EXPECT_TRUE(sameCycle) << "face " << f;
  }
  EXPECT_DOUBLE_EQ(signedVolume(soup), 4.0 / 3 * 1.5 * 1 * 0.75);
  const TriangleSurface gts = readMeshFile(kData + "octahedron.gts");
  const TriangleSurface obj = readMeshFile(kData + "octahedron.obj");
  EXPECT_EQ(gts.vertices, obj.vertices);
}

TEST(GtsFile, FacesListedBackwardsAreInsideOutAndRepairedLikeAnyFormat) {
  // The same faces with their edges in the opposite order: every triangle turns round.
  const Written path("backwards.gts", kTetrahedronHeader + kTetrahedronVertices + kTetrahedronEdges +
                                         "1 2 3\n4 5 1\n3 6 4\n5 6 2\n");
  EXPECT_NEAR(signedVolume(readGtsSoup(path)), -1.0 / 6, 1e-15);
  const TriangleSurface surface = readMeshFile(path);
  PolygonSoup repaired{surface.vertices, {}};
  for (const Triangle& t : surface.triangles)
    repaired.polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  EXPECT_NEAR(signedVolume(repaired), 1.0 / 6, 1e-15);
  EXPECT_NEAR(signedVolume(readGtsSoup(Written("forwards.gts", kTetrahedron))), 1.0 / 6, 1e-15);
}

// YADE's own example surfaces, written by libgts: read outward (positive signed volume, before any repair) and
// accepted. The horse's volume is libgts's own figure (gts_surface_volume through YADE's gts module,
// 0.0002634182601804985 m^3) and its counts those of the file's first line.
TEST(GtsFile, YadeExampleSurfacesAreReadOutward) {
  const std::string horse = kYadeExamples + "gts-horse/horse.coarse.gts";
  if (!std::filesystem::exists(horse))
    GTEST_SKIP() << horse << " is not installed (Debian's yade package installs YADE's examples there)";
  const PolygonSoup soup = readGtsSoup(horse);
  EXPECT_EQ(soup.points.size(), 336u);
  EXPECT_EQ(soup.polygons.size(), 668u);
  EXPECT_NEAR(signedVolume(soup), 0.0002634182601804985, 1e-12 * 0.0002634182601804985);
  const TriangleSurface surface = readMeshFile(horse);
  EXPECT_EQ(surface.vertices.size(), 336u);
  EXPECT_EQ(surface.triangles.size(), 668u);
  for (const std::string example : {"pfacet/box.gts", "pfacet/sphere.gts", "pfacet/octahedron.gts",
                                    "jointedCohesiveFrictionalPM/parallellepiped.gts"}) {
    if (!std::filesystem::exists(kYadeExamples + example)) continue;
    EXPECT_GT(signedVolume(readGtsSoup(kYadeExamples + example)), 0) << example;
    EXPECT_NO_THROW(readMeshFile(kYadeExamples + example)) << example;
  }
}

// Written with 17 significant digits and read back bit for bit, corners in the same order; deterministic.
TEST(GtsFile, WriteThenReadIsExact) {
  TriangleSurface sphere = icosphereSurface(0.0123456789, 2);
  for (Vector3r& v : sphere.vertices) v += Vector3r(1.0 / 3, -2e-7, 1e5 / 7);
  sphere.vertices[0].x() = std::nextafter(sphere.vertices[0].x(), 1.0);
  const std::string path = temporaryPath("sphere.gts");
  writeMeshFile(path, sphere);
  const PolygonSoup soup = readGtsSoup(path);
  EXPECT_EQ(soup.points, sphere.vertices);
  ASSERT_EQ(soup.polygons.size(), sphere.triangles.size());
  for (std::size_t t = 0; t < soup.polygons.size(); ++t)
    EXPECT_EQ(soup.polygons[t], (std::vector<std::size_t>{std::size_t(sphere.triangles[t][0]),
                                                          std::size_t(sphere.triangles[t][1]),
                                                          std::size_t(sphere.triangles[t][2])}));
  const std::string text = contents(path);
  // 162 vertices, 480 edges, 320 faces: each edge once.
  EXPECT_EQ(text.rfind("162 480 320 GtsSurface GtsFace GtsEdge GtsVertex\n", 0), 0u) << text.substr(0, 80);
  writeMeshFile(path, sphere);
  EXPECT_EQ(contents(path), text);
  const TriangleSurface again = readMeshFile(path);
  EXPECT_EQ(again.vertices, sphere.vertices);

  // Extreme magnitudes, a subnormal number and a signed zero survive too.
  TriangleSurface tetrahedron;
  tetrahedron.vertices = {
      {-0.0, 0, 0}, {1e300, 0, 0}, {0, 1e-300, std::numeric_limits<Real>::denorm_min()}, {0, 0, 0.1}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  writeGtsFile(path, tetrahedron);
  const PolygonSoup extreme = readGtsSoup(path);
  EXPECT_EQ(extreme.points, tetrahedron.vertices);
  EXPECT_TRUE(std::signbit(extreme.points[0].x()));
  std::remove(path.c_str());
  EXPECT_EQ(refusal([&] { writeMeshFile("/nonexistent-directory/mesh.gts", tetrahedron); }),
            "/nonexistent-directory/mesh.gts: cannot be written");
}

TEST(GtsFile, CommentsBlankLinesCarriageReturnsAndSignsAreRead) {
  const std::string text = "# a comment\n\n4 6 4   # counts\r\n+0 0 0\r\n1 0 0 # x\n\t0 1 0\n0 0 1.0e0\n"
                           "# edges\n" + kTetrahedronEdges + "\n" + kTetrahedronFaces + "# end\n\n";
  const PolygonSoup soup = readGtsSoup(Written("comments.gts", text));
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_NEAR(signedVolume(soup), 1.0 / 6, 1e-15);
  // The last line without its line break.
  std::string unterminated = kTetrahedron;
  unterminated.pop_back();
  EXPECT_EQ(readGtsSoup(Written("unterminated.gts", unterminated)).polygons.size(), 4u);
}

struct Malformed {
  const char* what;
  std::string text;
  std::string message;  // after "PATH: "
};

TEST(GtsFile, MalformedFilesAreRefusedWithThePathAndTheLine) {
  const std::string h = kTetrahedronHeader, v = kTetrahedronVertices, e = kTetrahedronEdges, f = kTetrahedronFaces;
  const std::vector<Malformed> cases = {
      {"only comments", "# nothing\n\n", "line 2: the file holds no data"},
      {"two counts", "4 6\n" + v + e + f, "line 1: the first line must start with the numbers of vertices, edges and "
                                          "faces (NV NE NF); it holds 2 entries"},
      {"a word for a count", "4 six 4\n" + v + e + f, "line 1: the number of edges on the first line, 'six', is not"},
      {"a negative count", "-4 6 4\n" + v + e + f, "line 1: the number of vertices on the first line, '-4', is not"},
      {"a fractional count", "4 6 4.0\n" + v + e + f, "line 1: the number of faces on the first line, '4.0', is not"},
      {"a count beyond the file", "4 6 40\n" + v + e + f, "line 1: the counts declare 4 vertices, 6 edges and 40 "
                                                          "faces, more than a file of"},
      {"a huge count", "18446744073709551615 6 4\n" + v + e + f, "line 1: the counts declare 18446744073709551615 "
                                                                  "vertices, 6 edges and 4 faces, more than a file"},
      {"a count beyond 64 bits", "4 6 18446744073709551616\n" + v + e + f, "line 1: the number of faces on the "
                                                                           "first line, '18446744073709551616', is "
                                                                           "not a whole number"},
      {"a number after the counts", "4 6 4 5\n" + v + e + f, "line 1: unexpected '5' after the numbers of vertices"},
      {"a vertex short of a coordinate", h + "0 0 0\n1 0\n0 1 0\n0 0 1\n" + e + f,
       "line 3: vertex 2 has 2 entries; its line must hold 3 coordinates (x y z)"},
      {"a vertex with extra data", h + "0 0 0\n1 0 0 7\n0 1 0\n0 0 1\n" + e + f,
       "line 3: vertex 2: unexpected '7' after its 3 coordinates (x y z); the data of GTS classes"},
      {"a word for a coordinate", h + "0 0 0\n1 0 0\n0 one 0\n0 0 1\n" + e + f,
       "line 4: vertex 3: the coordinate 'one' is not a number"},
      {"a hexadecimal coordinate", h + "0 0 0\n0x1 0 0\n0 1 0\n0 0 1\n" + e + f,
       "line 3: vertex 2: the coordinate '0x1' is not a number"},
      {"two signs", h + "0 0 0\n+-1 0 0\n0 1 0\n0 0 1\n" + e + f,
       "line 3: vertex 2: the coordinate '+-1' is not a number"},
      {"a NaN", h + "0 0 0\n1 0 0\n0 nan 0\n0 0 1\n" + e + f, "line 4: vertex 3 has a non-finite coordinate 'nan'"},
      {"an infinity", h + "0 0 0\n1 0 0\n0 1 0\n0 0 -inf\n" + e + f,
       "line 5: vertex 4 has a non-finite coordinate '-inf'"},
      {"a coordinate beyond double", h + "0 0 0\n1e999 0 0\n0 1 0\n0 0 1\n" + e + f,
       "line 3: vertex 2: the coordinate '1e999' is out of the range of a double"},
      {"an unprintable byte", h + "0 0 0\n1 0 0\n0 1 0\n0 0 1\x01\n" + e + f,
       "line 5: vertex 4: the coordinate '1\\x01' is not a number"},
      {"vertex number 0", h + v + "1 2\n2 3\n3 1\n1 4\n0 4\n3 4\n" + f,
       "line 10: edge 5: '0' is not a vertex number from 1 to 4"},
      {"a vertex number beyond the vertices", h + v + "1 2\n2 3\n3 1\n1 4\n2 5\n3 4\n" + f,
       "line 10: edge 5: '5' is not a vertex number from 1 to 4"},
      {"a negative vertex number", h + v + "1 -2\n2 3\n3 1\n1 4\n2 4\n3 4\n" + f,
       "line 6: edge 1: '-2' is not a vertex number from 1 to 4"},
      {"a fractional vertex number", h + v + "1 2\n2 3.0\n3 1\n1 4\n2 4\n3 4\n" + f,
       "line 7: edge 2: '3.0' is not a vertex number from 1 to 4"},
      {"a vertex number beyond 64 bits", h + v + "1 2\n2 3\n3 999999999999999999999999999999\n1 4\n2 4\n3 4\n" + f,
       "line 8: edge 3: '999999999999999999999999...' is not a vertex number from 1 to 4"},
      {"an edge with one vertex", h + v + "1 2\n2 3\n3\n1 4\n2 4\n3 4\n" + f,
       "line 8: edge 3 has 1 entry; its line must hold 2 vertex numbers (v1 v2, counted from 1)"},
      {"an edge from a vertex to itself", h + v + "1 2\n2 3\n3 1\n4 4\n2 4\n3 4\n" + f,
       "line 9: edge 4 joins vertex 4 to itself"},
      {"an edge number beyond the edges", h + v + e + "3 2 1\n1 5 4\n4 6 3\n2 6 7\n",
       "line 15: face 4: '7' is not an edge number from 1 to 6"},
      {"a face with two edges", h + v + e + "3 2 1\n1 5\n4 6 3\n2 6 5\n",
       "line 13: face 2 has 2 entries; its line must hold 3 edge numbers (e1 e2 e3, counted from 1)"},
      {"a face with four edges", h + v + e + "3 2 1\n1 5 4 2\n4 6 3\n2 6 5\n",
       "line 13: face 2: unexpected '2' after its 3 edge numbers"},
      {"a face using an edge twice", h + v + e + "3 2 1\n1 5 4\n4 4 3\n2 6 5\n",
       "line 14: face 3's edges 4 (vertices 1, 4), 4 (vertices 1, 4) and 3 (vertices 3, 1) do not close into a "
       "triangle"},
      {"a face of disjoint edges", h + v + e + "3 2 1\n1 6 4\n4 6 3\n2 6 5\n",
       "line 13: face 2's edges 1 (vertices 1, 2), 6 (vertices 3, 4) and 4 (vertices 1, 4) do not close"},
      {"a face whose third edge does not close it", h + v + e + "3 2 1\n1 5 3\n4 6 3\n2 6 5\n",
       "line 13: face 2's edges 1 (vertices 1, 2), 5 (vertices 2, 4) and 3 (vertices 3, 1) do not close"},
      {"a face with no edges to use", "4 0 1\n" + v + "1 2 3\n", "line 6: face 1: '1' is not an edge number "
                                                                 "(there are none)"},
      // (A comment makes the file long enough for its counts: a shorter one is refused as "a count beyond the file".)
      {"the end within the vertices", h + "0 0 0\n1 0 0\n# the rest of the file is missing, as after a failed copy\n",
       "line 4: the file ends after 2 of the 4 vertices that its first line declares (truncated?)"},
      {"the end within the edges", h + v + "1 2\n2 3\n\n# more\n", "line 9: the file ends after 2 of the 6 edges"},
      {"the end within the faces", h + v + e + "3 2 1\n", "line 12: the file ends after 1 of the 4 faces"},
      {"data after the last face", kTetrahedron + "# fine\n1 2 3\n",
       "line 17: unexpected '1' after the 4 faces that the first line declares"},
      {"a word after the last face", kTetrahedron + "end", "line 16: unexpected 'end' after the 4 faces"},
  };
  for (const Malformed& c : cases) {
    const Written file("malformed.gts", c.text);
    const std::string message = refusal([&] { readMeshFile(file); });
    EXPECT_EQ(message.rfind(file.path + ": " + c.message, 0), 0u) << c.what << ":\n  " << message;
  }
}

// The broken files of tests/data (also gts_reader_fuzzer's seeds), and a well-formed GTS file whose surface is
// refused by the repair like any format's.
TEST(GtsFile, BrokenDataFilesAreRefusedByName) {
  for (const auto& [file, message] : std::vector<std::pair<std::string, std::string>>{
           {"truncated.gts", "line 29: the file ends after 6 of the 8 faces"},
           {"trailing_data.gts", "line 32: unexpected '1' after the 8 faces"},
           {"edge_out_of_range.gts", "line 14: edge 4: '7' is not a vertex number from 1 to 6"},
           {"degenerate_edge.gts", "line 12: edge 2 joins vertex 3 to itself"},
           {"unclosed_face.gts", "line 27: face 4's edges 8 (vertices 4, 1), 8 (vertices 4, 1) and 7 (vertices 4, 5) "
                                 "do not close into a triangle"}}) {
    const std::string text = refusal([&] { readMeshFile(kData + file); });
    EXPECT_EQ(text.rfind(kData + file + ": " + message, 0), 0u) << text;
  }
  const std::string threeFaces = "4 6 3\n" + kTetrahedronVertices + kTetrahedronEdges + "3 2 1\n1 5 4\n4 6 3\n";
  const Written open("open.gts", threeFaces);
  const std::string text = refusal([&] { readMeshFile(open); });
  EXPECT_EQ(text.rfind(open.path + ": 3 boundary edges (the surface is not closed)", 0), 0u) << text;
}

}  // namespace
}  // namespace roundedmesh
