// The rounded body within a tolerance of the flat mesh (pkg/shape/CapTolerance.hpp, pkg/meshing/SurfaceRemesher.hpp,
// pkg/meshing/MeshPreparation.hpp, BodyMesh's CapPolicy): cap heights against the sphere's height sampled over the
// triangle, the bound met exactly where it acts and nothing touched elsewhere, and coarse meshes remeshed with their
// shape kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "pkg/meshing/MeshPreparation.hpp"
#include "pkg/meshing/SurfaceRemesher.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/CapTolerance.hpp"
#include "pkg/shape/Curvature.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/MassProperties.hpp"

namespace roundedmesh {
namespace {

// The closed box [0, x] x [0, y] x [0, z] of 12 triangles, outward.
TriangleSurface box(Real x, Real y, Real z) {
  TriangleSurface s;
  for (int k = 0; k < 8; ++k) s.vertices.emplace_back(k & 1 ? x : 0, k & 2 ? y : 0, k & 4 ? z : 0);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

// The highest point over triangle t of the sphere of radius R through its corners (centre on the inner side), found
// by sampling the triangle densely: the reference for capHeights.
Real sampledCapHeight(const TriangleSurface& s, int t, Real R) {
  const Vector3r &a = s.vertices[s.triangles[t][0]], &b = s.vertices[s.triangles[t][1]], &c = s.vertices[s.triangles[t][2]];
  const Vector3r centre2d = circumcentre(a, b, c);
  const Real rho = (a - centre2d).norm();
  const Real depth = std::sqrt(std::max(R * R - rho * rho, Real(0)));
  const int steps = 400;
  Real highest = 0;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j) {
      const Vector3r x = a + (b - a) * i / steps + (c - a) * j / steps;
      highest = std::max(highest, std::sqrt(std::max(R * R - (x - centre2d).squaredNorm(), Real(0))) - depth);
    }
  return highest;
}

// An acute, a right and two obtuse triangles (one a sliver); the heights need no closed surface.
TriangleSurface assortedTriangles() {
  TriangleSurface s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0.4, 0.8, 0},   // acute
                {0, 0, 1}, {1, 0, 1}, {0, 1, 1},       // right
                {0, 0, 2}, {1, 0, 2}, {0.3, 0.2, 2},   // obtuse
                {0, 0, 3}, {1, 0, 3}, {0.45, 0.02, 3}}; // sliver, 50:1
  s.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  return s;
}

TEST(CapTolerance, CapHeightIsTheSpheresHighestPointOverTheTriangle) {
  // Tolerance 2e-4 of the edge: the sampling grid's spacing (1/400) squared over the radius bounds its error, far
  // below the difference between the cap over the triangle and over the circumcircle for the obtuse ones (> 0.1).
  const TriangleSurface s = assortedTriangles();
  for (Real R : {0.5, 0.7, 1.0, 3.0, 50.0}) {
    const std::vector<Real> h = capHeights(s, std::vector<Real>(4, R));
    for (int t = 0; t < 4; ++t) {
      const Vector3r &a = s.vertices[s.triangles[t][0]];
      const Real rho = (a - circumcentre(a, s.vertices[s.triangles[t][1]], s.vertices[s.triangles[t][2]])).norm();
      EXPECT_NEAR(h[t], sampledCapHeight(s, t, std::max(R, rho)), 2e-4) << "triangle " << t << ", R " << R;
    }
  }
}

TEST(CapTolerance, BoundMeetsTheToleranceExactlyAndLeavesTheRestAlone) {
  const TriangleSurface s = assortedTriangles();
  const Real hMax = 0.02;
  // Radii: the first triangle's cap is already within (R large), the others' are not.
  std::vector<Real> radii{30.0, 0.1, 0.1, 0.1};
  const std::vector<Real> before = capHeights(s, radii);
  ASSERT_LT(before[0], hMax);
  std::vector<PrincipalCurvature> principal(4, PrincipalCurvature{10.0, -1.0, Vector3r::UnitX()});
  principal[0] = {1 / 30.0, 1 / 30.0, Vector3r::UnitX()};
  EXPECT_EQ(boundCapHeights(s, hMax, radii, principal), 3);
  const std::vector<Real> after = capHeights(s, radii);
  EXPECT_EQ(radii[0], 30.0);  // untouched, exactly
  EXPECT_EQ(principal[0].k1, 1 / 30.0);
  for (int t = 1; t < 4; ++t) {
    EXPECT_NEAR(after[t], hMax, 1e-12) << "triangle " << t;  // the smallest radius that meets it: the cap is hMax
    EXPECT_NEAR(principal[t].k1, 1 / radii[t], 1e-12);         // curvature no larger than the radius allows
    EXPECT_EQ(principal[t].k2, -1.0);                          // concave direction kept
  }
}

TEST(CapTolerance, RemeshingKeepsTheBoxAndItsSharpEdges) {
  const TriangleSurface given = box(0.02, 0.02, 0.05);
  const TriangleSurface fine = remeshedSurface(given, 0.004);
  EXPECT_GT(fine.triangles.size(), 100u);
  // Volume: every node on the box's faces, corners and edges kept: the same box to round-off.
  EXPECT_NEAR(massProperties(fine.vertices, fine.triangles).volume, 0.02 * 0.02 * 0.05, 1e-12 * 2e-5 + 1e-15);
  int corners = 0;
  for (const Vector3r& v : fine.vertices) {
    const Vector3r onFace = v.cwiseMin(Vector3r(0.02, 0.02, 0.05) - v);  // distance to the lower and upper faces
    EXPECT_LT(std::min({std::abs(onFace.x()), std::abs(onFace.y()), std::abs(onFace.z())}), 1e-12);
    corners += (onFace.array().abs() < 1e-12).all();
  }
  EXPECT_EQ(corners, 8);
}

TEST(CapTolerance, ACoarseBarIsPreparedToTheToleranceAndAFineMeshIsLeftAsItIs) {
  const TriangleSurface bar = box(0.02, 0.02, 0.05);
  const Real volume = 2e-5, req = equivalentRadius(volume);
  const BodyMesh asGiven(bar, std::nullopt);
  const BodyMesh prepared(bar, std::nullopt, std::nullopt, std::nullopt, CapPolicy{0.05, true});
  const auto tallest = [](const BodyMesh& m) {
    TriangleSurface s{m.shape().vertices(), m.shape().triangles()};
    const std::vector<Real> h = capHeights(s, m.shape().radii());
    return *std::max_element(h.begin(), h.end());
  };
  EXPECT_GT(tallest(asGiven), 1.5 * req);  // half spheres over the faces: 1.6 r_eq
  EXPECT_LE(tallest(prepared), 0.05 * req * (1 + 1e-9));
  EXPECT_GT(prepared.remeshPasses(), 0);
  EXPECT_NEAR(prepared.volume(), volume, 1e-12 * volume + 1e-18);
  // Bounded only (no remeshing): within the tolerance too, the 12 triangles kept.
  const BodyMesh bounded(bar, std::nullopt, std::nullopt, std::nullopt, CapPolicy{0.05, false});
  EXPECT_EQ(bounded.shape().triangleCount(), 12);
  EXPECT_EQ(bounded.boundedCaps(), 12);
  EXPECT_LE(tallest(bounded), 0.05 * req * (1 + 1e-9));
  // A mesh within the tolerance (an icosphere of 642 nodes: caps 0.0045 r_eq) is left exactly as it is.
  const TriangleSurface sphere = icosphereSurface(0.01, 3);
  const BodyMesh plain(sphere, std::nullopt);
  const BodyMesh policed(sphere, std::nullopt, std::nullopt, std::nullopt, CapPolicy{0.05, true});
  EXPECT_EQ(policed.remeshPasses(), 0);
  EXPECT_EQ(policed.boundedCaps(), 0);
  EXPECT_EQ(policed.shape().vertices(), plain.shape().vertices());
  EXPECT_EQ(policed.shape().radii(), plain.shape().radii());
}

TEST(CapTolerance, PrescribedCurvatureIsNeverChanged) {
  const TriangleSurface bar = box(0.02, 0.02, 0.05);
  const std::vector<Real> curvature(12, 1 / 0.001);  // 1 mm: caps up to the circumradius
  const BodyMesh prescribed(bar, curvature, std::nullopt, std::nullopt, CapPolicy{0.05, true});
  EXPECT_EQ(prescribed.shape().triangleCount(), 12);
  EXPECT_EQ(prescribed.remeshPasses(), 0);
  EXPECT_EQ(prescribed.boundedCaps(), 0);
}

TEST(CapTolerance, RefusesANonPositiveTolerance) {
  EXPECT_THROW(BodyMesh(box(1, 1, 1), std::nullopt, std::nullopt, std::nullopt, CapPolicy{0.0, true}),
               std::invalid_argument);
  EXPECT_THROW(remeshedSurface(box(1, 1, 1), -1), std::invalid_argument);
}

}  // namespace
}  // namespace roundedmesh
