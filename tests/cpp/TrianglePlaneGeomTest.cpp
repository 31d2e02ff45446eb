// Appendix B against a plane (R2 -> infinity): overlap, contact circle, polygon S, effective overlap and
// point, facing check, overlap rate.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/geom/TrianglePlaneGeom.hpp"

namespace roundedmesh {
namespace {

// A downward-facing triangle (normal -z) of radius R around the origin, and the plane z = height below.
RoundedMesh downwardTriangle(Real R) {
  return RoundedMesh({{0.0, 0.0, 0.0}, {0.0, 0.3, 0.05}, {0.3, 0.0, 0.02}}, {{0, 1, 2}}, {R});
}

ContactFace floorAt(Real height) {
  ContactFace face;
  face.origin = Vector3r(0, 0, height);
  face.normal = Vector3r(0, 0, -1);  // n12: from the triangle into the floor
  face.tangent1 = Vector3r(0, 1, 0);
  face.tangent2 = Vector3r(1, 0, 0);  // t1 x t2 = -z = n12
  return face;
}

TEST(TrianglePlaneGeom, OverlapCircleAndCentreFollowTheEncompassingSphere) {
  const RoundedMesh mesh = downwardTriangle(1.0);
  ASSERT_LT(mesh.rounded(0).normal.z(), 0);
  const Vector3r s = mesh.rounded(0).sphereCentre;
  const Real floor = s.z() - 1.0 + 0.004;  // the sphere dips 4 mm below the floor
  PressureGeom g;
  ASSERT_TRUE(trianglePlaneGeom(mesh, 0, floorAt(floor), RelativeMotion(), g));
  EXPECT_NEAR(g.sphereOverlap, 0.004, 1e-14);
  EXPECT_NEAR(g.contactRadius, std::sqrt(0.004 * 1.0), 1e-14);
  EXPECT_TRUE(g.centre.isApprox(Vector3r(s.x(), s.y(), floor), 1e-14));
  EXPECT_EQ(g.radius, 1.0);
  // S is the projected triangle; nodes keep the mesh's order.
  EXPECT_EQ(g.polygon.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const Vector3r v = mesh.vertices()[i] - g.centre;
    EXPECT_TRUE(g.nodes[i].isApprox(Vector2r(v.y(), v.x()), 1e-14));
  }
}

// delta_eff (Eq. B.4) is the depth below the plane of the sphere's surface point straight above c_eff,
// computed here by intersecting that vertical line with the sphere. The triangle is tilted 15 degrees, so
// its sphere's lowest point (above c) lies about 0.2 m beside it: c is outside S.
TEST(TrianglePlaneGeom, EffectiveOverlapIsTheSphereDepthAboveTheEffectivePoint) {
  const RoundedMesh tilted({{0, 0, 0}, {0, 0.1, 0}, {0.1, 0, 0.1 * std::tan(M_PI / 12)}}, {{0, 1, 2}}, {1.0});
  ASSERT_LT(tilted.rounded(0).normal.z(), 0);
  const Vector3r s = tilted.rounded(0).sphereCentre;
  const Real floor = s.z() - 1.0 + 0.06;
  PressureGeom g;
  ASSERT_TRUE(trianglePlaneGeom(tilted, 0, floorAt(floor), RelativeMotion(), g));
  ASSERT_GT(g.effectivePoint.norm(), 0.1);
  const Vector3r foot = g.centre + g.effectivePoint.x() * g.tangent1 + g.effectivePoint.y() * g.tangent2;
  const Real lowest = s.z() - std::sqrt(1.0 - (foot - s).head<2>().squaredNorm());
  EXPECT_NEAR(g.effectiveOverlap, floor - lowest, 1e-13);
  EXPECT_LT(g.effectiveOverlap, g.sphereOverlap);
  EXPECT_TRUE(g.polygon.contains(g.effectivePoint));
}

TEST(TrianglePlaneGeom, TrianglesThatDoNotFaceThePlaneAreSkipped) {
  const RoundedMesh mesh = downwardTriangle(1.0);
  ContactFace ceiling = floorAt(mesh.rounded(0).sphereCentre.z() + 0.999);
  ceiling.normal = -ceiling.normal;
  std::swap(ceiling.tangent1, ceiling.tangent2);
  PressureGeom g;
  EXPECT_FALSE(trianglePlaneGeom(mesh, 0, ceiling, RelativeMotion(), g));
}

TEST(TrianglePlaneGeom, NoContactWithoutOverlap) {
  const RoundedMesh mesh = downwardTriangle(1.0);
  PressureGeom g;
  EXPECT_FALSE(trianglePlaneGeom(mesh, 0, floorAt(mesh.rounded(0).sphereCentre.z() - 1.001), RelativeMotion(), g));
}

TEST(TrianglePlaneGeom, OverlapRateIsTheApproachSpeed) {
  const RoundedMesh mesh = downwardTriangle(1.0);
  RelativeMotion motion;
  motion.linear = Vector3r(0.3, -0.1, 0.7);  // the floor rises at 0.7 m/s relative to the triangle
  PressureGeom g;
  ASSERT_TRUE(trianglePlaneGeom(mesh, 0, floorAt(mesh.rounded(0).sphereCentre.z() - 0.99), motion, g));
  EXPECT_NEAR(g.overlapRate, 0.7, 1e-15);
  motion.angular = Vector3r(0, 0, 2.0);  // spin about the normal does not change the overlap
  ASSERT_TRUE(trianglePlaneGeom(mesh, 0, floorAt(mesh.rounded(0).sphereCentre.z() - 0.99), motion, g));
  EXPECT_NEAR(g.overlapRate, 0.7, 1e-15);
  // Spin about a horizontal axis through the body's origin: the floor's point under c moves vertically
  // at (w x c).z = w_x c_y - w_y c_x, by hand.
  motion.angular = Vector3r(1.5, -0.8, 0);
  ASSERT_TRUE(trianglePlaneGeom(mesh, 0, floorAt(mesh.rounded(0).sphereCentre.z() - 0.99), motion, g));
  EXPECT_NEAR(g.overlapRate, 0.7 + 1.5 * g.centre.y() + 0.8 * g.centre.x(), 1e-14);
  EXPECT_GT(std::abs(1.5 * g.centre.y() + 0.8 * g.centre.x()), 0.01);
}

}  // namespace
}  // namespace roundedmesh
