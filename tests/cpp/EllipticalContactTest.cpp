// Hertz's elliptical contact (EllipticalHertz.hpp), the ellipse of a triangle contact (EllipticalContact.hpp) and
// its pressure integrated by Law2 (curvature='principal'), against Hertz's equations solved here independently
// (bisection on the axis ratio b/a) and against direct integration of the elliptical pressure.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/geom/EllipticalContact.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/geom/EllipticalHertz.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

// Hertz's ellipse from lambdaA <= lambdaB and delta, solved by bisection on k = b/a (Johnson Section 4.2):
// lambdaB/lambdaA = (E/k^2 - K)/(K - E) at modulus e = sqrt(1 - k^2); a^2 = 2 delta (K - E)/(K e^2 lambdaA);
// p0/E* = delta/(b K).
HertzEllipse solvedEllipse(Real lambdaA, Real lambdaB, Real delta) {
  Real low = 1e-9, high = 1;
  for (int i = 0; i < 200; ++i) {
    const Real k = 0.5 * (low + high), e = std::sqrt(1 - k * k);
    const Real K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    ((E / (k * k) - K) / (K - E) > lambdaB / lambdaA ? low : high) = k;
  }
  const Real k = 0.5 * (low + high), e2 = 1 - k * k, e = std::sqrt(e2);
  const Real K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
  const Real a = std::sqrt(2 * delta * (K - E) / (K * e2 * lambdaA));
  return {a, k * a, delta / (k * a * K)};
}

TEST(EllipticalHertz, EqualCurvaturesGiveTheCircleOfEqs5And9) {
  const Real R = 0.02, delta = 1e-4;
  const HertzEllipse e = hertzEllipse(1 / R, 1 / R, delta);
  EXPECT_DOUBLE_EQ(e.a, std::sqrt(delta * R));
  EXPECT_DOUBLE_EQ(e.b, std::sqrt(delta * R));
  EXPECT_DOUBLE_EQ(e.peakPerModulus, 2 * std::sqrt(delta * R) / (M_PI * R));
}

// The table's linear interpolation over ln(ratio) in 2048 steps: measured relative errors below 2e-6; bound 1e-5.
TEST(EllipticalHertz, TableSolvesHertzsEquations) {
  const Real delta = 1e-3, lambdaA = 2.0;
  for (Real ratio : {1.001, 1.3, 2.0, 4.0, 9.0, 16.0, 37.0, 99.0}) {
    const HertzEllipse table = hertzEllipse(lambdaA, ratio * lambdaA, delta);
    const HertzEllipse solved = solvedEllipse(lambdaA, ratio * lambdaA, delta);
    EXPECT_NEAR(table.a / solved.a, 1, 1e-5) << "ratio " << ratio;
    EXPECT_NEAR(table.b / solved.b, 1, 1e-5) << "ratio " << ratio;
    EXPECT_NEAR(table.peakPerModulus / solved.peakPerModulus, 1, 1e-5) << "ratio " << ratio;
    EXPECT_LE(table.b, table.a);
  }
}

// A flat direction: the two-dimensional Hertz strip, whose force per unit length (pi/2) b p0 is Eq. 27's
// (pi/4) E* delta, whatever lambdaA below lambdaB / kLineContactRatio (also a concave one).
TEST(EllipticalHertz, LineContactCarriesEq27) {
  const Real delta = 2e-3, lambdaB = 2.0;
  for (Real lambdaA : {0.0, -0.5, lambdaB / (2 * kLineContactRatio)}) {
    const HertzEllipse e = hertzEllipse(lambdaA, lambdaB, delta);
    EXPECT_NEAR(M_PI / 2 * e.b * e.peakPerModulus, M_PI / 4 * delta, 1e-15);
    EXPECT_DOUBLE_EQ(e.b * e.b, delta / lambdaB);
    EXPECT_DOUBLE_EQ(e.a, kLineLength * e.b);
  }
}

// From kEllipseLimit to kLineContactRatio the ellipse passes to the line contact without a jump: each value on
// either side of both ends, 1e-9 apart in ratio, within 1e-6.
TEST(EllipticalHertz, PassesToTheLineContactContinuously) {
  const Real delta = 1e-3, lambdaB = 5.0;
  for (Real ratio : {kEllipseLimit, kLineContactRatio}) {
    const HertzEllipse below = hertzEllipse(lambdaB / (ratio * (1 - 1e-9)), lambdaB, delta);
    const HertzEllipse above = hertzEllipse(lambdaB / (ratio * (1 + 1e-9)), lambdaB, delta);
    EXPECT_NEAR(below.a / above.a, 1, 1e-6) << "ratio " << ratio;
    EXPECT_NEAR(below.b / above.b, 1, 1e-6) << "ratio " << ratio;
    EXPECT_NEAR(below.peakPerModulus / above.peakPerModulus, 1, 1e-6) << "ratio " << ratio;
  }
}

// A flat square patch of side L facing down, both triangles with the prescribed principal curvatures k1 along x
// and k2 along y and the sphere radius 1/H (so that the quadric and the sphere meet at the cap's top, above the
// shared circumcentre, the square's centre).
RoundedMesh curvedPatch(Real L, Real k1, Real k2) {
  const Real h = L / 2, R = 2 / (k1 + k2);
  const std::vector<PrincipalCurvature> principal(2, PrincipalCurvature{k1, k2, Vector3r::UnitX()});
  return RoundedMesh({{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}}, {{0, 2, 1}, {0, 3, 2}}, {R, R}, principal);
}

Plane floorBelow(const RoundedMesh& patch, Real delta) {
  const RoundedTriangle& t = patch.rounded(0);
  return {Vector3r(0, 0, t.sphereCentre.z() - t.radius + delta), Vector3r(0, 0, 1)};
}

NormalLoad patchLoad(const RoundedMesh& patch, Real delta, Real E, RegimeChoice regime) {
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_Plane_PressureGeom(patch, floorBelow(patch, delta), RelativeMotion(), geoms,
                                     CurvatureModel::Principal);
  PressureOptions options;
  options.regime = regime;
  options.curvature = CurvatureModel::Principal;
  NormalLoad total{0, Vector2r::Zero(), Regime::Quadrature};
  for (const PressureGeom& g : geoms) {
    EXPECT_TRUE(g.elliptical);
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, HertzPhys{E, 0}, options);
    total.force += load.force;
    total.moment += load.moment;
  }
  return total;
}

// A patch much larger than its ellipse on a plane carries Hertz's whole elliptical force (2 pi / 3) a b p0, in the
// direct regime that Eq. 14 chooses for it (the ellipse lies inside S). Tolerance: the table's 1e-5.
TEST(EllipticalContact, PatchOnAPlaneCarriesHertzsEllipticalForce) {
  const Real E = 1e6, delta = 1e-5, k2 = 10.0;
  for (Real ratio : {1.0, 4.0, 16.0}) {
    const RoundedMesh patch = curvedPatch(0.01, ratio * k2, k2);
    const HertzEllipse hertz = solvedEllipse(k2, ratio * k2, delta);
    const Real reference = 2 * M_PI / 3 * hertz.a * hertz.b * hertz.peakPerModulus * E;
    const NormalLoad direct = patchLoad(patch, delta, E, RegimeChoice::Direct);
    EXPECT_NEAR(direct.force, reference, 2e-5 * reference) << "ratio " << ratio;
    EXPECT_EQ(patchLoad(patch, delta, E, RegimeChoice::Auto).force, direct.force) << "ratio " << ratio;
    EXPECT_LT(direct.moment.norm(), 1e-12 * direct.force * 0.01) << "centred on the square";
  }
}

// Flat on flat: a flat patch (k1 = k2 = 0, its spheres of radius R_max) on a plane has nothing Hertzian to resolve
// and keeps the paper's circle: the same force under both models.
TEST(EllipticalContact, FlatOnFlatKeepsThePapersCircle) {
  const Real E = 1e6, delta = 1e-6, maxRadius = 2.5;
  const std::vector<PrincipalCurvature> flat(2, PrincipalCurvature{0, 0, Vector3r::UnitX()});
  const RoundedMesh patch({{-0.01, -0.01, 0}, {0.01, -0.01, 0}, {0.01, 0.01, 0}, {-0.01, 0.01, 0}},
                          {{0, 2, 1}, {0, 3, 2}}, {maxRadius, maxRadius}, flat);
  std::vector<PressureGeom> circles, ellipses;
  Ig2_RoundedMesh_Plane_PressureGeom(patch, floorBelow(patch, delta), RelativeMotion(), circles);
  Ig2_RoundedMesh_Plane_PressureGeom(patch, floorBelow(patch, delta), RelativeMotion(), ellipses,
                                     CurvatureModel::Principal);
  ASSERT_EQ(circles.size(), 2u);
  ASSERT_EQ(ellipses.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_FALSE(ellipses[i].elliptical);
    EXPECT_EQ(Law2_PressureGeom_HertzPhys_IntegratedPressure(circles[i], HertzPhys{E, 0}, PressureOptions()).force,
              Law2_PressureGeom_HertzPhys_IntegratedPressure(ellipses[i], HertzPhys{E, 0}, PressureOptions()).force);
  }
}

// A strip across the ellipse's long axis, narrower than it: the force is the elliptical pressure integrated over
// the strip (40 x 40 Gauss-Legendre on each side of the ellipse's edge is not needed: the strip lies inside the
// ellipse along y and is cut by it along x; 200 points per direction, error below 1e-5 measured on the circle).
// The strip along the short axis carries less, by the ellipse's shape. Tolerance 0.5 %: the 16-point rule on the
// kinked integrand.
TEST(EllipticalContact, StripCarriesThePressureOverItsArea) {
  const Real E = 1e6, delta = 1e-5, k2 = 10.0, k1 = 40.0;
  const HertzEllipse hertz = solvedEllipse(k2, k1, delta);  // a along y (curvature k2), b along x
  const Real p0 = hertz.peakPerModulus * E;
  auto pressure = [&](Real x, Real y) {
    return p0 * std::sqrt(std::max(1 - x * x / (hertz.b * hertz.b) - y * y / (hertz.a * hertz.a), Real(0)));
  };
  const Real w = 0.3 * hertz.b, long_ = 4 * hertz.a;
  // Two triangles making the rectangle [-w, w] x [-long_, long_] (x, y), facing down.
  const std::vector<PrincipalCurvature> principal(2, PrincipalCurvature{k1, k2, Vector3r::UnitX()});
  const Real R = 2 / (k1 + k2);
  const RoundedMesh strip({{-w, -long_, 0}, {w, -long_, 0}, {w, long_, 0}, {-w, long_, 0}}, {{0, 2, 1}, {0, 3, 2}},
                          {R, R}, principal);
  const Real reference = test::integrateRectangle(pressure, -w, w, -long_, long_, 200);
  const NormalLoad load = patchLoad(strip, delta, E, RegimeChoice::Quadrature);
  EXPECT_NEAR(load.force, reference, 0.005 * reference);
}

// Two meshed spheres with their exact curvature: every triangle is isotropic with k = 1/R, every correction
// vanishes, and each triangle contact is the paper's circle; the loads are the same to round-off (1e-12).
TEST(EllipticalContact, IsotropicTrianglesGiveThePapersCircle) {
  const Real R = 0.02;
  const RoundedMesh lower = icosphere(R, 3);
  const Vector3r shift(0.0011, -0.0007, 2 * R - 4e-4);
  const HertzPhys phys{1e6, 1e-3};
  PressureOptions mean, principal;
  principal.curvature = CurvatureModel::Principal;
  int contacts = 0;
  for (int s = 0; s < lower.triangleCount(); ++s)
    for (int t = 0; t < lower.triangleCount(); ++t) {
      const ContactSphere partner = contactSphere(lower, t, Matrix3r::Identity(), shift);
      PressureGeom circle, ellipse;
      const RelativeMotion motion{Vector3r(0, 0, -0.01), Vector3r::Zero()};
      const GeomTest first = triangleSphereGeom(lower, s, partner, motion, circle);
      const GeomTest second = triangleSphereGeom(lower, s, partner, motion, ellipse, CurvatureModel::Principal);
      const bool touches = static_cast<bool>(first);
      ASSERT_EQ(touches, static_cast<bool>(second)) << "triangles " << s << ", " << t;
      if (!touches) continue;
      ++contacts;
      const NormalLoad a = Law2_PressureGeom_HertzPhys_IntegratedPressure(circle, phys, mean);
      const NormalLoad b = Law2_PressureGeom_HertzPhys_IntegratedPressure(ellipse, phys, principal);
      EXPECT_NEAR(a.force, b.force, 1e-12 * a.force);
      EXPECT_NEAR((a.moment - b.moment).norm(), 0, 1e-12 * a.force * R);
      EXPECT_NEAR((circle.effectivePoint - ellipse.effectivePoint).norm(), 0, 1e-15);
    }
  EXPECT_GT(contacts, 10);
}

// The moment of an off-centre ellipse about c is x* x F (the pressure is symmetric about x*): exact in the direct
// regime, within the quadrature's error (1e-3 of F |x*|) otherwise.
TEST(EllipticalContact, MomentActsAtTheEllipsesCentre) {
  PressureGeom geom;
  geom.polygon = ConvexPolygon::rectangle(Vector2r::Zero(), 1, 1);
  geom.elliptical = true;
  geom.ellipseCentre = Vector2r(0.1, -0.05);
  const Vector2r u = Vector2r(1, 2).normalized(), v(-u.y(), u.x());
  const Real a = 0.2, b = 0.05, rho = std::sqrt(a * b);
  geom.toCircle = rho / a * u * u.transpose() + rho / b * v * v.transpose();
  geom.contactRadius = rho;
  geom.radius = 0.3;
  geom.sphereOverlap = 1e-3;
  geom.overlapRate = 0;
  geom.effectivePoint = geom.ellipseCentre;
  for (RegimeChoice regime : {RegimeChoice::Direct, RegimeChoice::Quadrature}) {
    PressureOptions options;
    options.regime = regime;
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, HertzPhys{1e6, 0}, options);
    const Vector2r expected(geom.ellipseCentre.y() * load.force, -geom.ellipseCentre.x() * load.force);
    EXPECT_NEAR((load.moment - expected).norm(), 0,
                (regime == RegimeChoice::Direct ? 1e-14 : 1e-3) * load.force * geom.ellipseCentre.norm());
  }
}

}  // namespace
}  // namespace roundedmesh
