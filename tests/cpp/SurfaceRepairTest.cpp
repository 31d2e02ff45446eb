// repairedSurface: what it repairs silently (welding, quads, mixed orientation, inside-out) and what it refuses, with the
// defect and its place in the message. The Python suite checks the same on broken files.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/MassProperties.hpp"
#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

PolygonSoup soupOf(const TriangleSurface& s) {
  PolygonSoup soup{s.vertices, {}};
  for (const Triangle& t : s.triangles) soup.polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  return soup;
}

std::string messageOf(const PolygonSoup& soup) {
  try {
    repairedSurface(soup);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// A unit cube as six quads, counter-clockwise seen from outside.
PolygonSoup cube() {
  return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
          {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
}

TEST(SurfaceRepair, TriangulatesQuads) {
  const TriangleSurface s = repairedSurface(cube());
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_NEAR(massProperties(s.vertices, s.triangles).volume, 1.0, 1e-14);
}

TEST(SurfaceRepair, WeldsDuplicateVerticesAndDropsUnusedOnes) {
  // Every triangle with its own three corners, as STL stores them, plus one stray point.
  const TriangleSurface sphere = icosphereSurface(1.0, 1);
  PolygonSoup soup;
  for (const Triangle& t : sphere.triangles) {
    soup.polygons.push_back({soup.points.size(), soup.points.size() + 1, soup.points.size() + 2});
    for (int corner : t) soup.points.push_back(sphere.vertices[corner]);
  }
  soup.points.emplace_back(9, 9, 9);
  const TriangleSurface s = repairedSurface(soup);
  EXPECT_EQ(s.vertices.size(), sphere.vertices.size());
  EXPECT_EQ(s.triangles.size(), sphere.triangles.size());
}

TEST(SurfaceRepair, ReversesAnInsideOutSurface) {
  TriangleSurface inverted = icosphereSurface(1.0, 1);
  for (Triangle& t : inverted.triangles) std::swap(t[1], t[2]);
  const TriangleSurface s = repairedSurface(soupOf(inverted));
  EXPECT_GT(massProperties(s.vertices, s.triangles).volume, 0);
}

// The same triangle, whatever corner it starts from.
bool sameTurn(const Triangle& a, const Triangle& b) {
  for (int shift = 0; shift < 3; ++shift)
    if (a[0] == b[shift] && a[1] == b[(shift + 1) % 3] && a[2] == b[(shift + 2) % 3]) return true;
  return false;
}

// Two separate spheres, a third of their triangles turned the other way (what some STL writers produce; YADE's
// examples/rod-penetration/rod-fine.stl has 86 such edges), the second sphere also inside-out on the whole: every
// triangle comes back as it was, counter-clockwise seen from outside, and no vertex moves.
TEST(SurfaceRepair, TurnsNeighboursOfOppositeOrientationToAgree) {
  TriangleSurface twoSpheres = icosphereSurface(1.0, 2);
  const TriangleSurface second = icosphereSurface(1.0, 2);
  const int offset = static_cast<int>(twoSpheres.vertices.size());
  for (const Vector3r& x : second.vertices) twoSpheres.vertices.push_back(x + Vector3r(3, 0, 0));
  for (const Triangle& t : second.triangles) twoSpheres.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  PolygonSoup mixed = soupOf(twoSpheres);
  for (std::size_t f = 0; f < mixed.polygons.size(); f += 3) std::swap(mixed.polygons[f][1], mixed.polygons[f][2]);
  const TriangleSurface s = repairedSurface(mixed);
  ASSERT_EQ(s.vertices, twoSpheres.vertices);
  ASSERT_EQ(s.triangles.size(), twoSpheres.triangles.size());
  const std::size_t half = second.triangles.size();
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    Triangle outward = twoSpheres.triangles[t];
    if (t >= half) std::swap(outward[1], outward[2]);  // the second sphere was given inside-out
    EXPECT_TRUE(sameTurn(s.triangles[t], outward)) << "triangle " << t;
  }
}

// The real projective plane's six-vertex triangulation: closed, every edge between two triangles, and no way to turn
// its triangles so that neighbours agree. It is refused, naming the edges that disagree, as before the repair.
TEST(SurfaceRepair, RefusesASurfaceThatCannotBeOriented) {
  const PolygonSoup plane{{{0, 0, 1}, {1, 0, 0.2}, {0.3, 1, -0.1}, {-1, 0.4, 0.3}, {-0.2, -1, 0}, {0.6, -0.5, -0.8}},
                          {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1}, {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2},
                           {5, 1, 3}}};
  const std::string message = messageOf(plane);
  EXPECT_NE(message.find("edges between triangles of opposite orientation"), std::string::npos) << message;
}

// The unit cube without its top: refused as it is; asked to, the flat square hole is closed by a fan from its centre,
// and the volume is the cube's to round-off.
TEST(SurfaceRepair, FillsAFlatHoleOnlyWhenAsked) {
  PolygonSoup open = cube();
  open.polygons.erase(open.polygons.begin() + 1);  // the top, z = 1
  EXPECT_NE(messageOf(open).find("4 boundary edges (the surface is not closed)"), std::string::npos);
  const TriangleSurface s = repairedSurface(open, RepairOptions{true});
  EXPECT_EQ(s.triangles.size(), 10u + 4u);
  EXPECT_EQ(s.vertices.back(), Vector3r(0.5, 0.5, 1));
  EXPECT_NEAR(massProperties(s.vertices, s.triangles).volume, 1.0, 1e-14);
}

// A hole that is not flat (the six neighbours of a vertex of a subdivided icosphere lie on the sphere, not in a
// plane) is refused, named, even when filling is asked for.
TEST(SurfaceRepair, RefusesToFillAHoleThatIsNotFlat) {
  const TriangleSurface sphere = icosphereSurface(1.0, 2);
  int vertex = -1;  // a vertex with six triangles
  for (int v = 0; v < static_cast<int>(sphere.vertices.size()) && vertex < 0; ++v) {
    int around = 0;
    for (const Triangle& t : sphere.triangles) around += std::count(t.begin(), t.end(), v);
    if (around == 6) vertex = v;
  }
  ASSERT_GE(vertex, 0);
  PolygonSoup holed{sphere.vertices, {}};
  for (const Triangle& t : sphere.triangles)
    if (std::count(t.begin(), t.end(), vertex) == 0)
      holed.polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  std::string message;
  try {
    repairedSurface(holed, RepairOptions{true});
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the hole of 6 edges through vertex"), std::string::npos) << message;
  EXPECT_NE(message.find("is not flat"), std::string::npos) << message;
}

TEST(SurfaceRepair, NamesEachDefect) {
  const TriangleSurface sphere = icosphereSurface(1.0, 1);
  auto expectMessage = [](const PolygonSoup& soup, const std::string& text) {
    const std::string message = messageOf(soup);
    EXPECT_NE(message.find(text), std::string::npos) << "expected '" << text << "' in: " << message;
  };
  PolygonSoup open = soupOf(sphere);
  open.polygons.pop_back();
  expectMessage(open, "3 boundary edges (the surface is not closed), first at the edge from vertex");

  PolygonSoup doubled = soupOf(sphere);
  doubled.polygons.push_back(doubled.polygons.front());
  expectMessage(doubled, "non-manifold edges");

  PolygonSoup notFinite = soupOf(sphere);
  notFinite.points[5].y() = NAN;
  expectMessage(notFinite, "1 vertex with a non-finite coordinate, first vertex 5 (");

  PolygonSoup flat{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}};
  expectMessage(flat, "encloses no volume");

  PolygonSoup outOfRange = soupOf(sphere);
  outOfRange.polygons[3][1] = 999;
  expectMessage(outOfRange, "face 3 refers to vertex 999");

  expectMessage(PolygonSoup{}, "the mesh is empty");
}

// A closed surface with one zero-area triangle: edge 0-1 of a tetrahedron split at its midpoint 4, the
// triangle (0, 1, 4) closing the seam.
TEST(SurfaceRepair, NamesADegenerateTriangle) {
  const PolygonSoup soup{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 0, 0}},
                         {{0, 2, 4}, {4, 2, 1}, {0, 4, 3}, {4, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  EXPECT_EQ(messageOf(soup), "");  // the valid split tetrahedron
  PolygonSoup degenerate = soup;
  degenerate.polygons[2] = {0, 1, 3};   // the face 0-1-3 unsplit ...
  degenerate.polygons[3] = {1, 4, 0};   // ... and the sliver 1-4-0 on the other side of the seam
  const std::string message = messageOf(degenerate);
  EXPECT_NE(message.find("1 degenerate (zero-area) triangle, first face 3 at vertex 1 (2, 0, 0), vertex 4 (1, 0, 0), "
                         "vertex 0 (0, 0, 0)"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace roundedmesh
