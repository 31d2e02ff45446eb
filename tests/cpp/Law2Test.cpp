// Law2_PressureGeom_HertzPhys_IntegratedPressure: quadrature regime (Eqs. 11-13), direct regime (Eq. 14),
// and the switch between them, on geometry built by the engine's own Ig2 from a flat patch over a plane.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/math/CirclePolygonArea.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

// A flat square patch of side L in the plane z = 0, facing down (two triangles sharing the diagonal, so
// both have the same encompassing sphere of radius R, centred above the square's centre).
RoundedMesh squarePatch(Real L, Real R) {
  const Real h = L / 2;
  return RoundedMesh({{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}}, {{0, 2, 1}, {0, 3, 2}}, {R, R});
}

// The plane that makes the patch's encompassing sphere overlap it by `delta`.
Plane floorFor(const RoundedMesh& patch, Real delta) {
  const RoundedTriangle& t = patch.rounded(0);
  return {Vector3r(0, 0, t.sphereCentre.z() - t.radius + delta), Vector3r(0, 0, 1)};
}

std::vector<PressureGeom> geomsOf(const RoundedMesh& mesh, const Plane& plane, const RelativeMotion& motion = {}) {
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_Plane_PressureGeom(mesh, plane, motion, geoms);
  return geoms;
}

NormalLoad totalLoad(const std::vector<PressureGeom>& geoms, const HertzPhys& phys, const PressureOptions& options) {
  NormalLoad total{0, Vector2r::Zero(), Regime::Quadrature};
  for (const PressureGeom& g : geoms) {
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, phys, options);
    total.force += load.force;
    total.moment += load.moment;
    total.regime = load.regime;
  }
  return total;
}

// A flat patch inside the contact circle carries the pressure of Eq. 9 integrated over its area: compared
// with a 40 x 40 Gauss-Legendre product rule over the square (exact to round-off for this analytic
// integrand). Tolerance 1e-8 relative: on the patch r <= 0.35 a, where sqrt(a^2 - r^2) is smooth enough for
// the degree-8 rule to err by 3e-10 (measured).
TEST(Law2IntegratedPressure, FlatPatchCarriesThePressureIntegratedOverItsArea) {
  const Real L = 0.01, R = 1.0, delta = 4e-4, E = 1e6;  // a = 0.02 m = 2 L
  const RoundedMesh patch = squarePatch(L, R);
  const std::vector<PressureGeom> geoms = geomsOf(patch, floorFor(patch, delta));
  ASSERT_EQ(geoms.size(), 2u);
  const NormalLoad load = totalLoad(geoms, HertzPhys{E, 0}, PressureOptions());
  EXPECT_EQ(load.regime, Regime::Quadrature);

  const Real a = std::sqrt(delta * R);
  const Real reference = test::integrateRectangle(
      [&](Real x, Real y) { return 2 * E / (M_PI * R) * std::sqrt(a * a - x * x - y * y); }, -L / 2, L / 2, -L / 2,
      L / 2, 40);
  EXPECT_NEAR(load.force, reference, 1e-8 * reference);
  // Eq. 29, F = 2 Omega E* / pi sqrt(delta / R), is the leading term in r^2/a^2; the first correction is
  // -L^2 / (12 a^2) = -2.1 %, so 2.5 % bounds the difference.
  EXPECT_NEAR(load.force, 2 * L * L * E / M_PI * std::sqrt(delta / R), 0.025 * reference);
  // The pressure is symmetric about the patch's centre: no moment.
  EXPECT_LT(load.moment.norm(), 1e-12 * load.force * L);
}

// Direct regime: a contact circle wholly inside S gets exactly Eq. 7, at c.
TEST(Law2IntegratedPressure, DirectRegimeGivesEq7WhenTheCircleIsInsideS) {
  const Real L = 1.0, R = 2.0, delta = 1e-5, E = 3e6, A = 0.02, rate = 0.01;
  const RoundedMesh patch = squarePatch(L, R);
  RelativeMotion motion;
  motion.linear = Vector3r(0, 0, rate);  // the floor rises toward the patch: the overlap grows at `rate`
  const std::vector<PressureGeom> geoms = geomsOf(patch, floorFor(patch, delta), motion);
  const NormalLoad load = totalLoad(geoms, HertzPhys{E, A}, PressureOptions());
  EXPECT_EQ(load.regime, Regime::Direct);
  // delta_s = R - d loses about eps R / delta = 4e-11 of itself to cancellation; the law is checked with
  // the geometry's own delta_s, which must match the intended overlap to that round-off.
  const Real d = geoms[0].sphereOverlap;
  EXPECT_NEAR(d, delta, 1e-14);
  EXPECT_NEAR(geoms[0].overlapRate, rate, 1e-15);
  const Real eq7 = 4.0 / 3 * E * std::sqrt(R) * (std::pow(d, 1.5) + A * rate * std::sqrt(d));
  EXPECT_NEAR(load.force, eq7, 1e-12 * eq7);
  EXPECT_LT(load.moment.norm(), 1e-12 * eq7);
}

// Eq. 7's damping on a turning contact: the floor tilts about an axis through c, so the sides approach at c at
// zero rate while one triangle of the patch goes in and the other comes out. Each triangle's load is its elastic load
// times 1 + A ddelta/dt / delta, ddelta/dt taken where that load acts: the centre of pressure, found from the
// undamped load and its velocity from the rigid motion in space, not from the geometry's slope. So each damping part
// pushes where the sides approach and dissipates, (F - F_el) ddelta/dt > 0; at c (the paper's point) neither would be
// damped. Tolerance 1e-12 relative: the same integrals, scaled.
TEST(Law2IntegratedPressure, DampingTakesTheRateWhereTheLoadActs) {
  const Real L = 0.01, R = 1.0, delta = 4e-4, E = 1e6, A = 0.02;
  const RoundedMesh patch = squarePatch(L, R);
  RelativeMotion motion;
  motion.angular = Vector3r(2, 1, 0);  // about an axis in the patch's plane, through the origin above c [rad/s]
  const std::vector<PressureGeom> geoms = geomsOf(patch, floorFor(patch, delta), motion);
  ASSERT_EQ(geoms.size(), 2u);
  Real power = 0;
  for (const PressureGeom& g : geoms) {
    EXPECT_NEAR(g.overlapRate, 0, 1e-15);
    const NormalLoad elastic = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, HertzPhys{E, 0}, PressureOptions());
    const NormalLoad damped = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, HertzPhys{E, A}, PressureOptions());
    const Real rate = -g.normal.dot(motion.at(planePoint(g, centreOfPressure(elastic))));
    ASSERT_GT(A * std::abs(rate) / delta, 0.1);  // the damping is a tenth of the force or more
    EXPECT_NEAR(damped.overlapRate, rate, 1e-12 * std::abs(rate));
    EXPECT_NEAR(damped.force, elastic.force * (1 + A * rate / g.sphereOverlap), 1e-12 * elastic.force);
    EXPECT_NEAR(damped.elasticForce, elastic.force, 1e-12 * elastic.force);
    EXPECT_TRUE(centreOfPressure(damped).isApprox(centreOfPressure(elastic), 1e-12));
    EXPECT_GT((damped.force - damped.elasticForce) * rate, 0);
    power += (damped.force - damped.elasticForce) * rate;
  }
  EXPECT_GT(power, 0);
}

// Eq. 14 decides per triangle contact: pi a^2 < gamma A_S / (N_S N_Q) selects the direct regime.
TEST(Law2IntegratedPressure, Eq14SelectsTheRegime) {
  const Real L = 0.1, R = 1.0;
  const RoundedMesh patch = squarePatch(L, R);
  const Real triangleArea = L * L / 2, gamma = 10;
  const Real threshold = gamma * triangleArea / 16 / (M_PI * R);  // delta at which pi a^2 = gamma A / N_Q
  PressureOptions options;
  options.gamma = gamma;
  const HertzPhys phys{1e6, 0};
  EXPECT_EQ(totalLoad(geomsOf(patch, floorFor(patch, 0.99 * threshold)), phys, options).regime, Regime::Direct);
  EXPECT_EQ(totalLoad(geomsOf(patch, floorFor(patch, 1.01 * threshold)), phys, options).regime, Regime::Quadrature);
  options.regime = RegimeChoice::Quadrature;
  EXPECT_EQ(totalLoad(geomsOf(patch, floorFor(patch, 0.5 * threshold)), phys, options).regime, Regime::Quadrature);
  options.regime = RegimeChoice::Direct;
  EXPECT_EQ(totalLoad(geomsOf(patch, floorFor(patch, 2 * threshold)), phys, options).regime, Regime::Direct);
}

// Direct regime with c outside S: the force is Eq. 7 scaled by A(S n Omega) / A(Omega), the area taken
// from an independent slice integration (1e-9 accurate, so 1e-7 relative), and acts at c_eff.
TEST(Law2IntegratedPressure, DirectRegimeScalesByTheAreaFractionAndActsAtTheEffectivePoint) {
  const RoundedMesh patch = squarePatch(0.02, 1.0);
  // Floor tilted so that the circle's centre falls beside the patch.
  const RoundedTriangle& t = patch.rounded(0);
  const Vector3r normal = Vector3r(0.012, 0, 1).normalized();
  const Plane floor{t.sphereCentre - (t.radius - 1e-4) * normal, normal};
  const std::vector<PressureGeom> geoms = geomsOf(patch, floor);
  ASSERT_EQ(geoms.size(), 2u);
  PressureOptions direct;
  direct.regime = RegimeChoice::Direct;
  for (const PressureGeom& g : geoms) {
    ASSERT_FALSE(g.polygon.contains(Vector2r::Zero()));  // c lies outside S
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, HertzPhys{1e6, 0}, direct);
    const Real eq7 = 4.0 / 3 * 1e6 * std::sqrt(g.radius) * std::pow(g.sphereOverlap, 1.5);
    const Real a = g.contactRadius;
    EXPECT_NEAR(load.force, eq7 * test::sliceIntegratedArea(a, g.polygon) / (M_PI * a * a), 1e-7 * eq7);
    ASSERT_GT(load.force, 0);
    const Vector2r centreOfPressure(-load.moment.y() / load.force, load.moment.x() / load.force);
    EXPECT_TRUE(centreOfPressure.isApprox(g.effectivePoint, 1e-12));
  }
}

// Eq. 13, a moment that is not zero: a floor tilted by 4 mrad puts the circle's centre c 4 mm beside the
// patch's centre, the patch still wholly inside the circle, where the integrand is smooth and the rule
// nearly exact. Reference: a 40 x 40 Gauss-Legendre sum over the patch of the 3D moment r x (p dA n12), each
// patch point projected onto the floor (area scaled by the cosine between the two normals), taken to plane
// coordinates only at the end, so that the plane-coordinate convention r x n12 = (r_y, -r_x) is checked, not
// assumed. Tolerance 1e-7 relative: the rule's error on this integrand (r <= 0.6 a; 3e-10 for the force).
TEST(Law2IntegratedPressure, MomentOfAnOffCentreContactMatchesTheIntegratedMoment) {
  const Real L = 0.01, R = 1.0, delta = 4e-4, E = 1e6;  // a = 0.02 m
  const RoundedMesh patch = squarePatch(L, R);
  const RoundedTriangle& t = patch.rounded(0);
  const Vector3r n = Vector3r(0.004, 0, 1).normalized();
  const std::vector<PressureGeom> geoms = geomsOf(patch, Plane{t.sphereCentre - (t.radius - delta) * n, n});
  ASSERT_EQ(geoms.size(), 2u);
  const NormalLoad load = totalLoad(geoms, HertzPhys{E, 0}, PressureOptions());
  ASSERT_EQ(load.regime, Regime::Quadrature);

  const PressureGeom& g = geoms[0];
  const Real a = g.contactRadius, cosine = std::abs(n.z());
  Vector3r moment3d = Vector3r::Zero();
  for (int component = 0; component < 3; ++component)
    moment3d[component] = test::integrateRectangle(
        [&](Real x, Real y) {
          const Vector3r point(x, y, 0);
          const Vector3r r = point - g.centre - (point - g.centre).dot(g.normal) * g.normal;
          const Real p = 2 * E / (M_PI * R) * std::sqrt(std::max(a * a - r.squaredNorm(), Real(0)));
          return r.cross(p * cosine * g.normal)[component];
        },
        -L / 2, L / 2, -L / 2, L / 2, 40);
  const Vector2r reference(moment3d.dot(g.tangent1), moment3d.dot(g.tangent2));
  ASSERT_GT(reference.norm(), 0.1 * load.force * 0.004);  // a lever of about 4 mm
  EXPECT_LT((load.moment - reference).norm(), 1e-7 * reference.norm());
  EXPECT_NEAR(moment3d.dot(g.normal), 0, 1e-12 * reference.norm());
}

}  // namespace
}  // namespace roundedmesh

namespace roundedmesh {
namespace {

// The exact regime (closed forms of DiskPolygonIntegrals.hpp): on the flat patch it carries the same integral as
// the 40 x 40 Gauss-Legendre reference above (1e-12: both exact to round-off), its moment is the quadrature's
// (1e-8 of F L: the degree-8 rule's error), and its elastic energy is the energy density integrated over the same
// region, whose derivative in delta_s at fixed S (central differences, step 1e-4 delta: error ~1e-8) is the
// elastic force. Over a whole circle the energy is Hertz's potential (8/15) E* sqrt(R*) delta^(5/2).
TEST(Law2IntegratedPressure, ExactRegimeIntegratesInClosedForm) {
  const Real L = 0.01, R = 1.0, delta = 4e-4, E = 1e6;
  const RoundedMesh patch = squarePatch(L, R);
  PressureOptions exact, quadrature;
  exact.regime = RegimeChoice::Exact;
  quadrature.regime = RegimeChoice::Quadrature;
  const HertzPhys phys{E, 0};
  const Real a = std::sqrt(delta * R);
  const Real reference = test::integrateRectangle(
      [&](Real x, Real y) { return 2 * E / (M_PI * R) * std::sqrt(a * a - x * x - y * y); }, -L / 2, L / 2, -L / 2,
      L / 2, 40);
  const NormalLoad load = totalLoad(geomsOf(patch, floorFor(patch, delta)), phys, exact);
  EXPECT_EQ(load.regime, Regime::Exact);
  EXPECT_NEAR(load.force, reference, 1e-12 * reference);
  // A floor tilted by a few milliradians moves the circle's centre (R = 1 m) off the patch's by 0.3 L and 0.2 L:
  // the moment is not zero by symmetry.
  const RoundedTriangle& t = patch.rounded(0);
  const Vector3r normal = Vector3r(-0.3 * L, 0.2 * L, 1).normalized();
  const Plane tilted{t.sphereCentre - (t.radius - delta) * normal, normal};
  for (const PressureGeom& g : geomsOf(patch, tilted)) {
    const NormalLoad e = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, phys, exact);
    const NormalLoad q = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, phys, quadrature);
    ASSERT_GT(q.moment.norm(), 0.1 * q.force * L);
    EXPECT_NEAR(e.force, q.force, 1e-8 * q.force);
    EXPECT_NEAR((e.moment - q.moment).norm(), 0, 1e-8 * q.force * L);
    EXPECT_EQ(e.elasticForce, e.force);  // no damping here
    // dU/d(delta_s) at fixed S: the contact radius follows delta_s (a^2 = R delta_s), S does not move.
    PressureGeom deeper = g, shallower = g;
    const Real step = 1e-4 * g.sphereOverlap;
    for (auto [geom, sign] : {std::pair<PressureGeom*, Real>{&deeper, 1}, {&shallower, -1}}) {
      geom->sphereOverlap += sign * step;
      geom->contactRadius = std::sqrt(geom->sphereOverlap * geom->radius);
    }
    const Real slope = (Law2_PressureGeom_HertzPhys_IntegratedPressure(deeper, phys, exact).elasticEnergy -
                        Law2_PressureGeom_HertzPhys_IntegratedPressure(shallower, phys, exact).elasticEnergy) /
                       (2 * step);
    EXPECT_NEAR(slope, e.elasticForce, 1e-7 * e.elasticForce);
  }
  // A contact circle wholly inside S: Hertz's force and potential.
  const RoundedMesh large = squarePatch(1.0, 2.0);
  const std::vector<PressureGeom> whole = geomsOf(large, floorFor(large, 1e-5));
  Real force = 0, energy = 0;
  for (const PressureGeom& g : whole) {
    const NormalLoad e = Law2_PressureGeom_HertzPhys_IntegratedPressure(g, phys, exact);
    force += e.force;
    energy += e.elasticEnergy;
  }
  const Real d = whole[0].sphereOverlap;
  EXPECT_NEAR(force, 4.0 / 3 * E * std::sqrt(2.0) * std::pow(d, 1.5), 1e-12 * force);
  EXPECT_NEAR(energy, 8.0 / 15 * E * std::sqrt(2.0) * std::pow(d, 2.5), 1e-12 * energy);
}

}  // namespace
}  // namespace roundedmesh
