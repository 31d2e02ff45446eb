// Appendix B: two rounded triangles (and a triangle and an analytic sphere) against independent
// constructions of the sphere overlap, contact plane, polygon S, c_eff and delta_eff.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/math/CirclePolygonArea.hpp"

namespace roundedmesh {
namespace {

// A one-triangle rounded mesh with corners a, b, c (counter-clockwise seen from outside) and radius R.
RoundedMesh single(const Vector3r& a, const Vector3r& b, const Vector3r& c, Real radius) {
  return RoundedMesh({a, b, c}, {Triangle{0, 1, 2}}, {radius});
}

// Body 1: an upward triangle on the sphere of radius 1 about the origin, around the north pole.
// Body 2: a downward triangle on the sphere of radius 2 about (0, 0, 2.9): spheres overlap by 0.1.
struct Pair {
  RoundedMesh lower = single(Vector3r(0.3, 0, std::sqrt(1 - 0.09)), Vector3r(-0.15, 0.26, std::sqrt(1 - 0.0901)),
                             Vector3r(-0.15, -0.26, std::sqrt(1 - 0.0901)), 1.0);
  RoundedMesh upper = upperAt(Vector3r(0, 0, 2.9), 0.0);

  static RoundedMesh upperAt(const Vector3r& centre, Real turn) {
    const Matrix3r r = Eigen::AngleAxis<Real>(turn, Vector3r::UnitZ()).toRotationMatrix();
    auto onSphere = [&](Real x, Real y) { return Vector3r(centre + r * Vector3r(x, y, -std::sqrt(4 - x * x - y * y))); };
    // Counter-clockwise seen from below (outside of the upper body).
    return single(onSphere(0.4, 0), onSphere(-0.2, -0.35), onSphere(-0.2, 0.35), 2.0);
  }
};

ContactSphere asPartner(const RoundedMesh& mesh) { return contactSphere(mesh, 0, Matrix3r::Identity(), Vector3r::Zero()); }

TEST(TriangleSphereGeom, OverlapPlaneAndCircleOfTwoSpheres) {
  const Pair pair;
  PressureGeom geom;
  ASSERT_TRUE(triangleSphereGeom(pair.lower, 0, asPartner(pair.upper), RelativeMotion(), geom));
  // Sphere centres (0,0,0) radius 1 and (0,0,2.9) radius 2: delta_s = 3 - 2.9 (Eq. 10).
  EXPECT_NEAR(geom.sphereOverlap, 0.1, 1e-12);
  EXPECT_NEAR(geom.radius, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(geom.contactRadius, std::sqrt(0.1 * 2.0 / 3.0), 1e-12);
  EXPECT_TRUE(geom.normal.isApprox(Vector3r::UnitZ(), 1e-14));
  // Radical plane: equal power with respect to both spheres.
  const Vector3r& c = geom.centre;
  EXPECT_NEAR(c.squaredNorm() - 1, (c - Vector3r(0, 0, 2.9)).squaredNorm() - 4, 1e-12);
  EXPECT_NEAR(c.x(), 0, 1e-15);
  EXPECT_NEAR(c.y(), 0, 1e-15);
  // c lies inside both projected triangles here: c_eff = c, h = 0, and delta_eff = delta_s (Eq. B.4).
  EXPECT_NEAR(geom.effectivePoint.norm(), 0, 1e-15);
  EXPECT_NEAR(geom.effectiveOverlap, 0.1, 1e-12);
}

// S is the intersection of the projected triangles: checked by area against an independent clip-free count
// (the projected triangles here are z = const triangles, so S is their xy intersection).
TEST(TriangleSphereGeom, PolygonIsTheIntersectionOfBothProjections) {
  const Pair pair;
  PressureGeom geom;
  ASSERT_TRUE(triangleSphereGeom(pair.lower, 0, asPartner(pair.upper), RelativeMotion(), geom));
  EXPECT_GE(geom.polygon.size(), 3);
  EXPECT_LE(geom.polygon.size(), 6);
  // Monte Carlo-free reference: a fine grid count of points inside both xy triangles. 2000^2 cells over
  // [-0.5, 0.5]^2: error about perimeter * cell = 2 * 5e-4 = 1e-3 of the area.
  auto inside = [](const std::array<Vector2r, 3>& t, const Vector2r& p) {
    Real s[3];
    for (int i = 0; i < 3; ++i) s[i] = cross2(t[(i + 1) % 3] - t[i], p - t[i]);
    return (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
  };
  const int n = 2000;
  int count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vector2r p(-0.5 + (i + 0.5) / n, -0.5 + (j + 0.5) / n);
      count += inside(geom.nodes, p) && inside(geom.partnerNodes, p);
    }
  EXPECT_NEAR(geom.polygon.area(), count / Real(n * n), 2e-3 * geom.polygon.area());
}

// Eq. B.4 with c outside S: triangle 2 is shifted sideways so that c_eff lies on an edge of S.
TEST(TriangleSphereGeom, EffectiveOverlapThroughTheClosestPointOfS) {
  const Pair pair;
  const RoundedMesh shifted = Pair::upperAt(Vector3r(0, 0, 2.9), 0.0).transformed(Matrix3r::Identity(), Vector3r(0.35, 0, 0));
  PressureGeom geom;
  ASSERT_TRUE(triangleSphereGeom(pair.lower, 0, asPartner(shifted), RelativeMotion(), geom));
  const Real h = geom.effectivePoint.norm();
  ASSERT_GT(h, 0.01);
  ASSERT_LT(h, geom.contactRadius);
  const Vector3r s2 = shifted.rounded(0).sphereCentre;
  const Real d = s2.norm(), R1 = 1, R2 = 2;
  EXPECT_NEAR(geom.sphereOverlap, R1 + R2 - d, 1e-12);
  EXPECT_NEAR(geom.effectiveOverlap, (R1 + R2 - d) - R1 - R2 + std::sqrt(R1 * R1 - h * h) + std::sqrt(R2 * R2 - h * h), 1e-12);
  // c_eff is the point of S nearest to c: no point of S is closer (checked on S's corners and edges).
  EXPECT_NEAR(geom.polygon.closestPoint(Vector2r::Zero()).norm(), h, 1e-15);
  EXPECT_FALSE(geom.polygon.contains(Vector2r::Zero()));
}

// Eq. B.5: a triangle turned away from the other sphere is no contact, however deep the overlap.
TEST(TriangleSphereGeom, NonFacingPairsAreDiscarded) {
  const Pair pair;
  PressureGeom geom;
  // The upper body's triangle, flipped (normal pointing up, away from the lower body).
  const RoundedMesh& u = pair.upper;
  const RoundedMesh flipped = single(u.vertices()[0], u.vertices()[2], u.vertices()[1], 2.0);
  EXPECT_FALSE(triangleSphereGeom(pair.lower, 0, asPartner(flipped), RelativeMotion(), geom));
  // The lower triangle seen from a sphere below it.
  ContactSphere below;
  below.centre = Vector3r(0, 0, -1.5);
  below.radius = 1;
  EXPECT_FALSE(triangleSphereGeom(pair.lower, 0, below, RelativeMotion(), geom));
}

// Degenerate placements: identical triangles (all edges parallel and coincident), a corner exactly on
// an edge, one triangle containing the other. S must be the expected polygon, never NaN.
TEST(TriangleSphereGeom, PolygonIsRobustForDegeneratePlacements) {
  // Flat-ish triangles (radius 50) facing each other, exactly coplanar in z = 0: their caps overlap.
  auto lowerTriangle = [](const Vector2r& a, const Vector2r& b, const Vector2r& c) {
    return single(Vector3r(a.x(), a.y(), 0), Vector3r(b.x(), b.y(), 0), Vector3r(c.x(), c.y(), 0), 50);
  };
  auto upperSphere = [](const Vector2r& a, const Vector2r& b, const Vector2r& c) {
    const RoundedMesh m = single(Vector3r(a.x(), a.y(), 0), Vector3r(c.x(), c.y(), 0), Vector3r(b.x(), b.y(), 0), 50);
    return asPartner(m);
  };
  const Vector2r a(0, 0), b(0.1, 0), c(0, 0.1);
  PressureGeom geom;
  // n12 joins the sphere centres, tilted from z when the circumcentres differ: a horizontal area A projects
  // to A n12_z.
  auto projected = [&](Real area) { return area * geom.normal.z(); };
  // Identical projections: S is the triangle itself.
  ASSERT_TRUE(triangleSphereGeom(lowerTriangle(a, b, c), 0, upperSphere(a, b, c), RelativeMotion(), geom));
  EXPECT_NEAR(geom.polygon.area(), 0.005, 1e-15);
  // Containment: a smaller triangle inside the larger one, touching its corner at a.
  const Vector2r b2(0.05, 0), c2(0, 0.05);
  ASSERT_TRUE(triangleSphereGeom(lowerTriangle(a, b, c), 0, upperSphere(a, b2, c2), RelativeMotion(), geom));
  EXPECT_NEAR(geom.polygon.area(), projected(0.00125), 1e-15);
  ASSERT_TRUE(triangleSphereGeom(lowerTriangle(a, b2, c2), 0, upperSphere(a, b, c), RelativeMotion(), geom));
  EXPECT_NEAR(geom.polygon.area(), projected(0.00125), 1e-15);
  // A corner of the upper triangle exactly on the lower one's hypotenuse: S = the part inside.
  const Vector2r onEdge(0.05, 0.05);
  ASSERT_TRUE(triangleSphereGeom(lowerTriangle(a, b, c), 0, upperSphere(Vector2r(0, 0.02), Vector2r(0.02, 0), onEdge),
                                 RelativeMotion(), geom));
  EXPECT_NEAR(geom.polygon.area(), projected(0.5 * std::abs(cross2(Vector2r(0.02, -0.02), Vector2r(0.05, 0.03)))), 1e-15);
  for (int i = 0; i < geom.polygon.size(); ++i) EXPECT_TRUE(geom.polygon[i].allFinite());
  // Triangles sharing only an edge's line, on opposite sides: S has no area, so no contact.
  EXPECT_FALSE(triangleSphereGeom(lowerTriangle(a, b, c), 0, upperSphere(a, b, Vector2r(0, -0.1)), RelativeMotion(), geom));
}

// An analytic sphere partner: S is the projected triangle alone, and the centre of the sphere decides.
TEST(TriangleSphereGeom, AnalyticSphereUsesTheProjectedTriangle) {
  const Pair pair;
  ContactSphere sphere;
  sphere.centre = Vector3r(0, 0, 2.9);
  sphere.radius = 2;
  PressureGeom geom;
  ASSERT_TRUE(triangleSphereGeom(pair.lower, 0, sphere, RelativeMotion(), geom));
  EXPECT_EQ(geom.partnerTriangle, -1);
  EXPECT_NEAR(geom.polygon.area(), std::abs(cross2(geom.nodes[1] - geom.nodes[0], geom.nodes[2] - geom.nodes[0])) / 2,
              1e-15);
  EXPECT_NEAR(geom.sphereOverlap, 0.1, 1e-12);
}

// The relative velocity: approach rate at c and tangential slip at c_eff, from body 2's motion.
TEST(TriangleSphereGeom, OverlapRateAndSlip) {
  const Pair pair;
  RelativeMotion motion;
  motion.linear = Vector3r(0.3, -0.2, -0.5);
  motion.angular = Vector3r(0, 0, 2);
  PressureGeom geom;
  ASSERT_TRUE(triangleSphereGeom(pair.lower, 0, asPartner(pair.upper), motion, geom));
  const Vector3r v = motion.at(geom.centre);
  EXPECT_NEAR(geom.overlapRate, 0.5, 1e-12);
  EXPECT_TRUE(geom.slip.isApprox(Vector3r(v.x(), v.y(), 0), 1e-12));
}

}  // namespace
}  // namespace roundedmesh
