// Facets welded into surfaces (FacetSurface.hpp, WeldedFacets.hpp): what lies beyond each edge, panels of coplanar
// facets, one owner for every point of a panel, and a body across a seam meeting the plane.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "bench/RecordedScene.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/FacetSurface.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;
using Corners = std::array<Vector3r, 3>;

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3, 0};
const HertzMaterial kFloor{5e6, 0.4, 2000, 1e-3, 0};

std::vector<FacetWeld> weld(const std::vector<Corners>& facets) { return weldFacets(facets, weldTolerance(facets)); }

// The square [0, n]^2 (z = 0) of n x n cells, each split along a random diagonal, corners in random order: 2 n^2
// facets, half with their normal up, half down.
std::vector<Corners> tiledSquare(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Corners> facets;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vector3r a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
      const bool other = random() % 2;
      for (Corners f : {other ? Corners{a, b, d} : Corners{a, b, c}, other ? Corners{b, c, d} : Corners{a, c, d}}) {
        if (random() % 2) std::swap(f[1], f[2]);
        facets.push_back(f);
      }
    }
  return facets;
}

Real outlineArea(const std::vector<Vector3r>& outline, const Vector3r& normal) {
  Vector3r twice = Vector3r::Zero();
  for (size_t i = 0; i < outline.size(); ++i) twice += outline[i].cross(outline[(i + 1) % outline.size()]);
  return 0.5 * twice.dot(normal);
}

Vector3r normalOf(const Corners& c) { return (c[1] - c[0]).cross(c[2] - c[0]).normalized(); }

TEST(FacetSurface, TheTwoHalvesOfASquareAreOnePanel) {
  const std::vector<Corners> facets{{Vector3r(0, 0, 0), Vector3r(1, 0, 0), Vector3r(1, 1, 0)},
                                    {Vector3r(0, 0, 0), Vector3r(0, 1, 0), Vector3r(1, 1, 0)}};  // normal down
  const std::vector<FacetWeld> w = weld(facets);
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(w[f].panel, 0);
    EXPECT_EQ(w[f].panelSize, 2);
    ASSERT_EQ(w[f].outline.size(), 4u);
    // Counter-clockwise about each member's own normal, the square's area.
    EXPECT_NEAR(outlineArea(w[f].outline, normalOf(facets[f])), 1, 1e-12);
    for (const SidePair& side : w[f].outlineClosed) EXPECT_FALSE(side[0] || side[1]);  // free all round
  }
  // The diagonal (edge 2 of the first, 2 of the second) is flat: closed on both sides; the first facet keeps it.
  EXPECT_TRUE(w[0].edgeClosed[2][0] && w[0].edgeClosed[2][1]);
  EXPECT_TRUE(w[0].ownsEdge[2]);
  EXPECT_FALSE(w[1].ownsEdge[2]);
  EXPECT_FALSE(w[0].edgeClosed[0][0] || w[0].edgeClosed[0][1]);
}

TEST(FacetSurface, AFacetWithoutAreaIsWeldedToNothing) {
  // A square of two facets, and a sliver with collinear corners along its diagonal (as CAD exports leave some): the
  // square is still one panel, the sliver its own, and a ball over the diagonal meets the Wall's plane (1e-12).
  const std::vector<Corners> facets{{Vector3r(0, 0, 0), Vector3r(1, 0, 0), Vector3r(1, 1, 0)},
                                    {Vector3r(0, 0, 0), Vector3r(1, 1, 0), Vector3r(0, 1, 0)},
                                    {Vector3r(0, 0, 0), Vector3r(0.5, 0.5, 0), Vector3r(1, 1, 0)}};
  const std::vector<FacetWeld> w = weld(facets);
  EXPECT_EQ(w[0].panelSize, 2);
  EXPECT_EQ(w[1].panel, w[0].panel);
  EXPECT_EQ(w[2].panelSize, 1);
  EXPECT_EQ(w[2].outline.size(), 3u);
  const BodyMesh ball(icosphere(0.025, 3));
  std::vector<Corners> scaled = facets;
  for (Corners& c : scaled)
    for (Vector3r& x : c) x = 0.2 * x - Vector3r(0.1, 0.1, 0);
  const BodyState body = at(Vector3r(0.001, 0, 0.024), Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r(1, 2, 3).normalized())));
  std::vector<Partner> partners;
  for (size_t f = 0; f < scaled.size(); ++f) partners.push_back({static_cast<int>(f), Facet{scaled[f], nullptr}, kFloor});
  const Wrench surface = surfaceContact(roundedBody(0, ball, kRubber), body, partners,
                                        std::vector<BodyState>(3, at(Vector3r::Zero())), EngineOptions()).onFirst;
  const Wrench wall = partnerContact(roundedBody(0, ball, kRubber), body, Wall{2, 1}, at(Vector3r::Zero()), kFloor,
                                     EngineOptions()).onFirst;
  EXPECT_LT((surface.force - wall.force).norm(), 1e-12 * wall.force.norm());
}

TEST(FacetSurface, AFoldIsClosedOnTheSideItTurnsTo) {
  // Edge 0 of the first facet runs along y at x = 0; the second rises toward the first's normal (+z) beyond it.
  const std::vector<Corners> facets{{Vector3r(0, 0, 0), Vector3r(0, 1, 0), Vector3r(-1, 0.5, 0)},
                                    {Vector3r(0, 0, 0), Vector3r(0, 1, 0), Vector3r(1, 0.5, 0.3)}};
  ASSERT_GT(normalOf(facets[0]).z(), 0);
  const std::vector<FacetWeld> w = weld(facets);
  EXPECT_TRUE(w[0].edgeClosed[0][0]);   // concave for a body above
  EXPECT_FALSE(w[0].edgeClosed[0][1]);  // convex for a body below
  EXPECT_NE(w[0].panel, w[1].panel);
  // A facet whose corner misses the vertex by more than the tolerance is not welded.
  std::vector<Corners> apart = facets;
  apart[1][0] += Vector3r(0, 0, 1e-3);
  const std::vector<FacetWeld> loose = weld(apart);
  EXPECT_FALSE(loose[0].edgeClosed[0][0] || loose[0].edgeClosed[0][1]);
}

TEST(FacetSurface, TheFacesOfAClosedBoxAreClosedInsideAndOpenOutside) {
  // A unit cube of 12 facets, normals outward (as geom.facetBox orders them, up to order): from inside every edge is
  // concave, from outside convex.
  std::vector<Corners> facets;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      auto corner = [&](Real a, Real b) {
        Vector3r x;
        x[axis] = 0.5 * sign;
        x[u] = a;
        x[v] = b;
        return x;
      };
      Corners f1{corner(-0.5, -0.5), corner(0.5, -0.5), corner(0.5, 0.5)};
      Corners f2{corner(-0.5, -0.5), corner(0.5, 0.5), corner(-0.5, 0.5)};
      if (sign < 0) {
        std::swap(f1[1], f1[2]);
        std::swap(f2[1], f2[2]);
      }
      facets.push_back(f1);
      facets.push_back(f2);
    }
  const std::vector<FacetWeld> w = weld(facets);
  for (size_t f = 0; f < facets.size(); ++f) {
    ASSERT_GT(normalOf(facets[f]).dot(facets[f][0]), 0);  // outward
    EXPECT_EQ(w[f].panelSize, 2);
    ASSERT_EQ(w[f].outline.size(), 4u);
    for (const SidePair& side : w[f].outlineClosed) {
      EXPECT_FALSE(side[0]);  // outside (the normal's side): convex edges
      EXPECT_TRUE(side[1]);   // inside: concave
    }
  }
}

TEST(FacetSurface, PanelsAreConvexAndCoverTheSurface) {
  // An L of three unit squares: not convex, so it splits into convex panels that together cover it once.
  std::vector<Corners> facets;
  for (const Vector3r& o : {Vector3r(0, 0, 0), Vector3r(1, 0, 0), Vector3r(0, 1, 0)}) {
    facets.push_back({o, o + Vector3r(1, 0, 0), o + Vector3r(1, 1, 0)});
    facets.push_back({o, o + Vector3r(1, 1, 0), o + Vector3r(0, 1, 0)});
  }
  const std::vector<FacetWeld> w = weld(facets);
  Real covered = 0;
  int panels = 0;
  for (size_t f = 0; f < facets.size(); ++f) {
    Real members = 0;
    for (size_t g = 0; g < facets.size(); ++g)
      if (w[g].panel == w[f].panel) members += 0.5;
    EXPECT_NEAR(outlineArea(w[f].outline, normalOf(facets[f])), members, 1e-12) << f;  // convex: hull = union
    if (w[f].panel == static_cast<int>(f)) {
      ++panels;
      covered += members;
    }
  }
  EXPECT_GE(panels, 2);
  EXPECT_NEAR(covered, 3, 1e-12);
}

TEST(FacetSurface, EveryPointOfAPanelHasExactlyOneOwner) {
  // 32 facets tiling a square, in random orientations: random points inside, on the seams and at every vertex
  // belong to exactly one member (a point on a seam or at a vertex is held by several triangles).
  const std::vector<Corners> facets = tiledSquare(4, 7);
  const std::vector<FacetWeld> w = weld(facets);
  for (const FacetWeld& f : w) ASSERT_EQ(f.panelSize, 32);
  auto owners = [&](const Vector3r& x) {
    int count = 0;
    for (size_t f = 0; f < facets.size(); ++f) {
      const Corners& c = facets[f];
      const std::array<Vector2r, 3> corners{c[0].head<2>(), c[1].head<2>(), c[2].head<2>()};
      count += facetOwns(corners, w[f], x.head<2>());
    }
    return count;
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<Real> along(0, 4);
  for (int k = 0; k < 2000; ++k) EXPECT_EQ(owners(Vector3r(along(random), along(random), 0)), 1);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      EXPECT_EQ(owners(Vector3r(i, j, 0)), 1) << i << " " << j;
      const Real t = along(random) / 4;
      if (i < 4) {
        EXPECT_EQ(owners(Vector3r(i + t, j, 0)), 1);
      }
      if (j < 4) {
        EXPECT_EQ(owners(Vector3r(i, j + t, 0)), 1);
      }
      if (i < 4 && j < 4) {
        EXPECT_EQ(owners(Vector3r(i + t, j + t, 0)), 1);
        EXPECT_EQ(owners(Vector3r(i + t, j + 1 - t, 0)), 1);
      }
    }
}

Wrench onSurface(const RoundedBody& body, const BodyState& state, const std::vector<Corners>& facets) {
  return surfaceContact(body, state, test::facetPartners(facets, kFloor),
                        std::vector<BodyState>(facets.size(), at(Vector3r::Zero())), EngineOptions())
      .onFirst;
}

Wrench onWall(const RoundedBody& body, const BodyState& state) {
  return partnerContact(body, state, Wall{2, 1}, at(Vector3r::Zero()), kFloor, EngineOptions()).onFirst;
}

// The square [-0.1, 0.1]^2 m of 32 facets, cells 0.05 m wide.
std::vector<Corners> tiledFloor(unsigned seed) {
  std::vector<Corners> facets = tiledSquare(4, seed);
  for (Corners& c : facets)
    for (Vector3r& x : c) x = 0.05 * x - Vector3r(0.1, 0.1, 0);
  return facets;
}

TEST(FacetSurface, ABallAcrossSeamsMeetsThePlane) {
  // A 642-node ball 1 mm into a square of 32 facets, its contact over seams and vertices: the Wall's force and
  // torque to round-off (the panel computes the plane's contacts; 1e-12 of the force).
  const RoundedBody ball = roundedBody(0, BodyMesh(icosphere(0.025, 3)), kRubber);
  const std::vector<Corners> facets = tiledFloor(11);
  for (const Vector3r& centre : {Vector3r(0, 0, 0.024), Vector3r(0.05, 0.0123, 0.0245), Vector3r(-0.05, 0.05, 0.024)}) {
    const BodyState body = at(centre, Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r(1, 2, 3).normalized())));
    const Wrench wall = onWall(ball, body);
    ASSERT_GT(wall.force.z(), 0.05);
    const Wrench surface = onSurface(ball, body, facets);
    EXPECT_LT((surface.force - wall.force).norm(), 1e-12 * wall.force.norm()) << centre.transpose();
    EXPECT_LT((surface.torque - wall.torque).norm(), 1e-12 * wall.force.norm() * 0.025) << centre.transpose();
  }
}

TEST(FacetSurface, AGummyBearAcrossSeamsMeetsThePlane) {
  // S1's gummy bear (554 nodes, a body far from a ball) in 20 random orientations and places, pressed 2 mm (0.08 r_eq)
  // into the square of 32 facets, its contacts over seams and vertices: the Wall's force and torque to round-off.
  // Each of the panel's members culls the bear's triangle tree by the part of the panel it keeps (a triangle by its
  // box's projection): no contact the Wall finds is lost, none counted twice.
  const RoundedBody bear = loadRecordedScene().model.bodies[0];
  const std::vector<Corners> facets = tiledFloor(5);
  std::mt19937 random(17);
  std::normal_distribution<Real> normal;
  std::uniform_real_distribution<Real> across(-0.05, 0.05);
  for (int trial = 0; trial < 20; ++trial) {
    const Quaternionr orientation =
        Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
    BodyState body = at(Vector3r(across(random), across(random), 0.08), orientation);
    while (onWall(bear, body).force.z() == 0) body.position.z() -= 2.5e-4;  // first touch, within 0.25 mm
    body.position.z() -= 0.002;
    const Wrench wall = onWall(bear, body), surface = onSurface(bear, body, facets);
    ASSERT_GT(wall.force.z(), 0.01) << "trial " << trial;
    EXPECT_LT((surface.force - wall.force).norm(), 1e-12 * wall.force.norm()) << "trial " << trial;
    EXPECT_LT((surface.torque - wall.torque).norm(), 1e-12 * wall.force.norm() * bear.mesh->sphereBoundRadius())
        << "trial " << trial;
  }
}

TEST(FacetSurface, AnAlmostFlatConcaveSeamPushesAsThePlane) {
  // Two facets meeting under the ball at a concave angle of 1e-3 rad: not one panel, each pushes on its side of
  // the seam. The planes part from the flat one by at most 1e-3 x 5 mm (the contact's radius) against a 1 mm
  // overlap, so the force is the plane's within 1 %: nothing is lost at the seam, nothing counted twice. (The
  // sheet rule used to drop every cap within its overlap of the seam.)
  const BodyMesh ball(icosphere(0.025, 3));
  const Real rise = std::tan(1e-3);
  const std::vector<Corners> facets{
      {Vector3r(0, -0.2, 0), Vector3r(0, 0.2, 0), Vector3r(-0.2, 0, 0.2 * rise)},
      {Vector3r(0, -0.2, 0), Vector3r(0, 0.2, 0), Vector3r(0.2, 0, 0.2 * rise)}};
  const BodyState body = at(Vector3r(0.001, 0, 0.024), Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r(1, 2, 3).normalized())));
  const RoundedBody rounded = roundedBody(0, ball, kRubber);
  const Wrench wall = onWall(rounded, body);
  const Wrench seam = onSurface(rounded, body, facets);
  EXPECT_NEAR(seam.force.z(), wall.force.z(), 0.01 * wall.force.z());
}

}  // namespace
}  // namespace roundedmesh
