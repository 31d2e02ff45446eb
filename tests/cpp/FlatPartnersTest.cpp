// Every flat partner is a plane where the contact lies inside it (faceGeometry, doc/physics.md "What each partner's
// surface is"): a Box's faces whatever its thickness, and a Facet, a sheet that touches a body only where the body
// reaches it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3, 0};
const HertzMaterial kFloor{5e6, 0.4, 2000, 1e-3, 0};

Wrench against(const BodyMesh& mesh, const BodyState& state, const PartnerShape& partner,
               const BodyState& partnerState = BodyState()) {
  return partnerContact(roundedBody(0, mesh, kRubber), state, partner, partnerState, kFloor, EngineOptions()).onFirst;
}

// A ball 1 mm into a Box whose top is z = 0, from 1 mm to 1 m thick, tilted and off-centre: the Wall's force in the
// top's plane, to round-off (the two compute the same contacts with the same in-plane axes; 1e-12 of the force). It
// used to fall with the thickness: the upward-facing triangles, whose spheres' centres lay below the Box, took its
// bottom face, 'behind' them, for theirs.
TEST(FlatPartners, ABoxOfAnyThicknessActsAsTheWallOfItsFace) {
  const BodyMesh ball(icosphere(0.025, 3));
  const BodyState body = at(Vector3r(0.03, -0.02, 0.024), Quaternionr(Eigen::AngleAxis<Real>(0.3, Vector3r(1, 2, 3).normalized())));
  const Wrench wall = against(ball, body, Wall{2, 1}, at(Vector3r::Zero()));
  ASSERT_GT(wall.force.z(), 0.1);
  for (Real half : {0.0005, 0.01, 0.1, 0.5}) {
    const Wrench box = against(ball, body, Box{Vector3r(0.3, 0.2, half)}, at(Vector3r(0.01, 0, -half)));
    EXPECT_LT((box.force - wall.force).norm(), 1e-12 * wall.force.norm()) << half;
    EXPECT_LT((box.torque - wall.torque).norm(), 1e-12 * wall.force.norm() * 0.025) << half;
  }
}

// The Box's edges sharp (rounding 0), as a Box's faces alone make them.
Wrench againstSharp(const BodyMesh& mesh, const BodyState& state, const PartnerShape& partner) {
  Partner sharp{0, partner, kFloor};
  sharp.edgeRadius = 0;
  return surfaceContact(roundedBody(0, mesh, kRubber), state, {sharp}, {at(Vector3r::Zero())}, EngineOptions()).onFirst;
}

// Beyond a sharp Box edge the body meets two faces, each over its own rectangle; above the top, the side faces do not
// touch it, however close its centre comes to their planes.
TEST(FlatPartners, ABoxMeetsTheFacesItsCentreIsOutside) {
  const BodyMesh ball(icosphere(0.025, 3));
  const Box box{Vector3r(0.1, 0.1, 0.1)};
  // Centre above the top, 1 mm inside the +x side's plane: the top alone, as a Wall.
  const BodyState above = at(Vector3r(0.099, 0, 0.124));
  const Wrench top = againstSharp(ball, above, box);
  EXPECT_GT(top.force.z(), 0.1);
  EXPECT_NEAR(top.force.x(), 0, 1e-9 * top.force.norm());
  // Beyond the edge at 45 degrees, 5 mm deep: both faces push alike, within 1 % (the icosphere's triangles are not
  // symmetric about the edge's bisector). An edge is sharp: a face pushes once its contact circle reaches it, here past
  // 3.2 mm (doc/physics.md).
  const Vector3r edge(0.1, 0, 0.1), out = Vector3r(1, 0, 1).normalized();
  const Wrench both = againstSharp(ball, at(edge + 0.02 * out), box);
  EXPECT_GT(both.force.x(), 0.01);
  EXPECT_NEAR(both.force.x(), both.force.z(), 0.01 * both.force.norm());
}

// A sheet touches a body only where the body reaches it. A ring (a torus standing on its rim) around a small Facet
// that lies across its hole, 1 mm below the ring's centre: the ring's lower arc lies behind the facet's plane, right
// under the facet, yet the facet touches nothing. As a plane clipped to the facet (no sheet rule), the same face
// finds contacts centimetres deep there: the phantom overlaps that stopped drums of Facets at their lifter ridges.
TEST(FlatPartners, AFacetPushesOnlyWhereTheBodyReachesIt) {
  const BodyMesh ring(test::torus(0.03, 0.008, 96, 24), std::nullopt);
  int axis = 0;  // the ring's axis: its largest principal moment
  for (int i = 1; i < 3; ++i)
    if (ring.principalMoments()[i] > ring.principalMoments()[axis]) axis = i;
  const Vector3r up = Vector3r::Unit((axis + 1) % 3), across = Vector3r::Unit((axis + 2) % 3),
                 along = Vector3r::Unit(axis);
  const std::array<Vector3r, 3> corners = {-0.001 * up - 0.01 * across - 0.005 * along,
                                           -0.001 * up + 0.01 * across - 0.005 * along, -0.001 * up + 0.006 * along};
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_Facet_PressureGeom(ring.shape(), PlacedFacet{corners, {}, {}, {}, nullptr}, 0, RelativeMotion(),
                                     GeomOutput(geoms));
  EXPECT_TRUE(geoms.empty());

  ContactFace face;
  face.origin = corners[0];
  face.normal = -up;
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  const ConvexPolygon triangle = ConvexPolygon::triangle(
      faceCoordinates(face, corners[0]), faceCoordinates(face, corners[1]), faceCoordinates(face, corners[2]));
  const FaceOutline outline({triangle[0], triangle[1], triangle[2]});
  face.faceOutline = &outline;
  faceGeometry(ring.shape(), face, RelativeMotion(), GeomOutput(geoms));
  ASSERT_FALSE(geoms.empty());
  Real deepest = 0;
  for (const PressureGeom& g : geoms) deepest = std::max(deepest, g.effectiveOverlap);
  EXPECT_GT(deepest, 0.01);
}

// A Facet larger than the body acts as the plane it lies in, to round-off, pressed in up to a tenth of the radius: its
// plane comes from its corners, whose cross product rounds differently from a unit normal, and a contact at the edge of
// its circle (h close to a) magnifies that; 1e-9 of the force (measured worst 4e-12).
TEST(FlatPartners, ALargeFacetActsAsItsPlane) {
  const BodyMesh ball(icosphere(0.025, 3));
  const Facet facet{{Vector3r(-1, -1, 0), Vector3r(1.5, -1, 0), Vector3r(0, 1.5, 0)}, nullptr};
  for (Real depth : {1e-5, 1e-4, 1e-3, 2.5e-3}) {
    const BodyState body = at(Vector3r(0.01, 0.02, 0.025 - depth), Quaternionr(Eigen::AngleAxis<Real>(1.1, Vector3r(3, 1, 2).normalized())));
    const Wrench plane = against(ball, body, Plane{Vector3r::Zero(), Vector3r::UnitZ()});
    const Wrench onFacet = against(ball, body, facet, at(Vector3r::Zero()));
    ASSERT_GT(plane.force.z(), 0);
    EXPECT_LT((onFacet.force - plane.force).norm(), 1e-9 * plane.force.norm()) << depth;
  }
}

}  // namespace
}  // namespace roundedmesh
