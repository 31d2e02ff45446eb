// Section 2.6 on the contacts of a meshed sphere resting on a plane: Eq. 20 (no slip), Eq. 19 (sliding) and
// the switch of Eq. 21, each against its formula, and the sums over a body's contact against Eq. 18.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/law/CoulombFriction.hpp"
#include "pkg/law/HertzPressure.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

// A unit icosphere resting 3 % deep on the plane z = 0, the plane sliding under it at v along x.
std::vector<PressureGeom> slidingContact(const RoundedMesh& sphere, const Vector3r& v) {
  RelativeMotion motion;
  motion.linear = v;
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_Plane_PressureGeom(sphere, Plane{Vector3r(0, 0, -0.97), Vector3r::UnitZ()}, motion, geoms);
  return geoms;
}

HertzPhys phys(Real mu, Real c) { return {1.0, 0.0, mu, c}; }

NormalLoad normalLoad(const PressureGeom& g, const HertzPhys& p) {
  return Law2_PressureGeom_HertzPhys_IntegratedPressure(g, p, PressureOptions());
}

TEST(CoulombFriction, NothingWithoutFrictionOrDamping) {
  const RoundedMesh sphere = icosphere(1.0, 3);
  for (const PressureGeom& g : slidingContact(sphere, Vector3r(1, 0, 0))) {
    const TangentialLoad t = coulombFriction(g, normalLoad(g, phys(0, 0)), phys(0, 0));
    EXPECT_TRUE(t.force.isZero(0));
    EXPECT_FALSE(t.sliding);
  }
}

// Slow slip, c |v| below mu F_Hertz: every triangle is in the no-slip regime, Ft = -c fraction v (Eq. 20),
// and the fractions of the circle in each S sum to 1 (the projected triangles tile the disc), so the body's
// total is -c v (Eq. 18). Tolerance: round-off of the exact area fractions.
TEST(CoulombFriction, NoSlipIsViscousAndSumsToEq18) {
  const RoundedMesh sphere = icosphere(1.0, 3);
  const Vector3r v(1e-4, 2e-4, 0);
  const HertzPhys p = phys(0.5, 2.0);
  Vector3r total = Vector3r::Zero();
  for (const PressureGeom& g : slidingContact(sphere, v)) {
    const TangentialLoad t = coulombFriction(g, normalLoad(g, p), p);
    EXPECT_FALSE(t.sliding);
    EXPECT_TRUE(t.force.cross(v).isZero(1e-15));
    EXPECT_LT(t.force.dot(v), 0);
    total += t.force;
  }
  EXPECT_LT((total + p.tangentialDamping * v).norm(), 1e-12 * p.tangentialDamping * v.norm());
}

// Fast slip: Eq. 21 holds for every triangle (they share the sphere, so the same F_Hertz), Ft = -mu Fn v/|v|
// with each triangle's own Fn (Eq. 19), and the total is mu times the total normal force.
TEST(CoulombFriction, SlidingIsCoulombWithEachTrianglesNormalForce) {
  const RoundedMesh sphere = icosphere(1.0, 3);
  const Vector3r v(3, -4, 0);
  const HertzPhys p = phys(0.4, 1e-3);
  Real normal = 0;
  Vector3r total = Vector3r::Zero();
  for (const PressureGeom& g : slidingContact(sphere, v)) {
    const NormalLoad load = normalLoad(g, p);
    const TangentialLoad t = coulombFriction(g, load, p);
    EXPECT_TRUE(t.sliding);
    EXPECT_TRUE(t.force.isApprox(-p.friction * load.force * v.normalized(), 1e-14));
    normal += load.force;
    total += t.force;
  }
  EXPECT_NEAR(total.norm(), p.friction * normal, 1e-12 * normal);
}

// The switch sits at c |v| = mu F_Hertz(delta_s) (Eq. 21, Eq. 7): just below it no contact slides, just above
// every one does.
TEST(CoulombFriction, SwitchAtTheSphereSphereHertzForce) {
  const RoundedMesh sphere = icosphere(1.0, 3);
  const HertzPhys p = phys(0.3, 5.0);
  const Real hertz = 4.0 / 3.0 * std::pow(0.03, 1.5);  // E* = 1, R = 1, delta = 0.03, no damping
  const Real vSwitch = p.friction * hertz / p.tangentialDamping;
  for (Real factor : {0.999, 1.001})
    for (const PressureGeom& g : slidingContact(sphere, Vector3r(factor * vSwitch, 0, 0)))
      EXPECT_EQ(coulombFriction(g, normalLoad(g, p), p).sliding, factor > 1);
}

}  // namespace
}  // namespace roundedmesh
