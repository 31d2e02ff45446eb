// Sphere bodies (pkg/engine/SpherePair.hpp) through the whole engine step: the normal force against the damped
// Hertz law of Eq. 7 written out here, F = (4/3) E* sqrt(R*) (delta^3/2 + A ddelta/dt delta^1/2), with E*
// (Eq. 3) and A = (A1 + A2)/2 computed here from the materials; R* for unequal radii and R* = r against a
// Wall, a Box and a Facet; equal and opposite wrenches; the friction's direction, its viscous value (Eq. 20)
// and its Coulomb cap (Eq. 19); clump members; the time-step limit of a sphere pair.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

const HertzMaterial kSoft{1e6, 0.4, 1000, 2e-3};
const HertzMaterial kStiff{5e6, 0.25, 3000, 6e-3};

Real effectiveModulus(const HertzMaterial& a, const HertzMaterial& b) {
  return 1 / ((1 - a.poisson * a.poisson) / a.young + (1 - b.poisson * b.poisson) / b.young);
}

// Eq. 7 written out.
Real hertzForce(const HertzMaterial& a, const HertzMaterial& b, Real radius, Real overlap, Real rate) {
  return 4.0 / 3 * effectiveModulus(a, b) * std::sqrt(radius) *
         (std::pow(overlap, 1.5) + 0.5 * (a.damping + b.damping) * rate * std::sqrt(overlap));
}

struct Scene {
  ContactModel model;
  ContactData data;

  int add(PartnerShape shape, const HertzMaterial& material, const BodyState& state, bool sphereBody) {
    model.partners.push_back({static_cast<int>(model.partners.size()), shape, material, sphereBody});
    states.push_back(state);
    return static_cast<int>(model.partners.size()) - 1;
  }
  void step() {
    data.resize(model);
    data.partnerStates = states;
    contactForces(model, data);
  }
  const Wrench& wrench(int p) const { return data.partnerWrenches[p]; }

  std::vector<BodyState> states;
};

BodyState moving(const Vector3r& position, const Vector3r& velocity, const Vector3r& angularVelocity = Vector3r::Zero()) {
  BodyState s = test::at(position);
  s.velocity = velocity;
  s.angularVelocity = angularVelocity;
  return s;
}

// Unequal radii and materials, at several overlaps along an oblique line of centres. The engine's force is the
// same expression up to round-off (the direct regime's area fraction is the whole circle's area over itself, a
// few ulps from 1), except that delta = R1 + R2 - |x2 - x1| cancels: positions of size |x| carry errors of
// about 4 eps |x| into delta, which the force takes 1.5 times. Tolerance: that, times 4, plus 1e-12.
TEST(SpherePair, SphereSphereForceIsEq7WithCombinedRadius) {
  const Real r1 = 0.01, r2 = 0.03;
  const Vector3r n = Vector3r(1, 2, -2).normalized();
  for (Real overlap : {1e-6, 1e-5, 1e-4, 1e-3}) {
    Scene scene;
    scene.add(Sphere{r1}, kSoft, test::at(Vector3r(0.1, 0.2, 0.3)), true);
    scene.add(Sphere{r2}, kStiff, test::at(Vector3r(0.1, 0.2, 0.3) + (r1 + r2 - overlap) * n), true);
    scene.step();
    const Real expected = hertzForce(kSoft, kStiff, r1 * r2 / (r1 + r2), overlap, 0);
    const Real cancellation = 1.5 * 4 * std::numeric_limits<Real>::epsilon() * 0.4 / overlap;
    EXPECT_NEAR(scene.wrench(1).force.dot(n), expected, (1e-12 + 4 * cancellation) * expected) << overlap;
    EXPECT_LT((scene.wrench(1).force - scene.wrench(1).force.dot(n) * n).norm(), 1e-12 * expected);
    EXPECT_TRUE((scene.wrench(0).force + scene.wrench(1).force).isZero(1e-15 * expected));
    EXPECT_LT(scene.wrench(0).torque.norm() + scene.wrench(1).torque.norm(), 1e-15 * expected * r2);
    EXPECT_EQ(scene.data.statistics.sphereContacts, 1);
  }
}

// The damping term: approaching at rate v adds (4/3) E* sqrt(R*) A v sqrt(delta), A the mean of the two
// materials' constants; receding fast enough, the force is clamped at zero (the pressure never pulls).
TEST(SpherePair, DampingIsEq7sTermWithMeanConstant) {
  const Real r1 = 0.02, r2 = 0.005, overlap = 2e-4, rate = 0.3;
  auto force = [&](Real approach) {
    Scene scene;
    scene.add(Sphere{r1}, kSoft, moving(Vector3r::Zero(), Vector3r(approach, 0, 0)), true);
    scene.add(Sphere{r2}, kStiff, test::at(Vector3r(r1 + r2 - overlap, 0, 0)), true);
    scene.step();
    return scene.wrench(1).force.x();
  };
  const Real radius = r1 * r2 / (r1 + r2);
  const Real term = hertzForce(kSoft, kStiff, radius, overlap, rate) - hertzForce(kSoft, kStiff, radius, overlap, 0);
  EXPECT_NEAR(force(rate) - force(0), term, 1e-11 * term);
  EXPECT_NEAR(term / (4.0 / 3 * effectiveModulus(kSoft, kStiff) * std::sqrt(radius) * rate * std::sqrt(overlap)),
              0.5 * (kSoft.damping + kStiff.damping), 1e-12);
  EXPECT_EQ(force(-1e3), 0);
}

// Against a Wall, a Box (face, rounded edge) and a Facet the combined radius is the sphere's own: F = (4/3) E* sqrt(r)
// delta^3/2 along the line from the nearest point of the partner. Tolerance as above.
TEST(SpherePair, FlatPartnersUseTheSphereRadius) {
  const Real r = 0.01, overlap = 3e-4;
  const Real expected = hertzForce(kSoft, kStiff, r, overlap, 0);
  auto check = [&](PartnerShape shape, const BodyState& partner, const Vector3r& centre, const Vector3r& n) {
    Scene scene;
    scene.add(Sphere{r}, kSoft, test::at(centre), true);
    scene.add(shape, kStiff, partner, false);
    scene.step();
    EXPECT_LT((scene.wrench(0).force - expected * n).norm(), 1e-12 * expected) << scene.wrench(0).force.transpose();
    EXPECT_TRUE((scene.wrench(0).force + scene.wrench(1).force).isZero(1e-15 * expected));
  };
  check(Wall{2, 1}, test::at(Vector3r(0, 0, -0.5)), Vector3r(3, 4, -0.5 + r - overlap), Vector3r::UnitZ());
  check(Wall{0, -1}, test::at(Vector3r(1, 0, 0)), Vector3r(1 - r + overlap, 4, 5), -Vector3r::UnitX());
  const Quaternionr turn(Eigen::AngleAxisd(0.3, Vector3r(1, 1, 0).normalized()));
  const Box box{Vector3r(0.1, 0.2, 0.05)};
  // Over the middle of the top face, and beyond an edge (the nearest point on the edge, along the diagonal).
  check(box, test::at(Vector3r(1, 1, 1), turn), Vector3r(1, 1, 1) + turn * Vector3r(0, 0, 0.05 + r - overlap),
        turn * Vector3r::UnitZ());
  // The edge is rounded by a tenth of the sphere's radius (edgeRadiusFor): its nearest point lies rho beyond the axis
  // of the rounding, rho behind both faces.
  const Vector3r diagonal = Vector3r(1, 0, 1).normalized();
  const Real rho = kDeepestOverlap * r;
  check(box, test::at(Vector3r(1, 1, 1), turn),
        Vector3r(1, 1, 1) + turn * (Vector3r(0.1 - rho, 0, 0.05 - rho) + (rho + r - overlap) * diagonal),
        turn * diagonal);
  const Facet facet{{Vector3r(-0.1, -0.1, 0), Vector3r(0.1, -0.1, 0), Vector3r(0, 0.1, 0)}, nullptr};
  check(facet, test::at(Vector3r(0, 0, 2)), Vector3r(0.01, 0, 2 - r + overlap), -Vector3r::UnitZ());
}

// Two partners neither of which is a sphere body, and two members of one clump, are left alone.
TEST(SpherePair, OnlySphereBodiesAndNotWithinAClump) {
  Scene scene;
  scene.add(Sphere{0.01}, kSoft, test::at(Vector3r::Zero()), false);
  scene.add(Sphere{0.01}, kSoft, test::at(Vector3r(0.019, 0, 0)), false);
  scene.step();
  EXPECT_EQ(scene.data.statistics.bodyPairs, 0);
  scene.model.partners[1].sphereBody = true;
  scene.data = ContactData();  // a new model starts with new lists, as the Python side does
  scene.step();
  EXPECT_EQ(scene.data.statistics.sphereContacts, 1);
  scene.data.partnerClumps = {7, 7};
  contactForces(scene.model, scene.data);
  EXPECT_EQ(scene.data.statistics.bodyPairs, 0);
  EXPECT_TRUE(scene.wrench(0).force.isZero(0));
}

// Friction on a sphere resting on a Wall while the sphere slides along x and spins: the slip at the contact
// point c = (0, 0, -(r - delta)) from the centre is v + w x c. Slow slip: F_t = -c_t v_slip (Eq. 20, the whole
// circle in S); fast slip: F_t = -mu F_n v_slip / |v_slip| (Eq. 19). The torque on the sphere is c x F_t. The same
// for the spring in a first step (no displacement yet: its dashpot alone, capped at mu F_n).
// Tolerance 1e-12 relative (round-off).
class SpherePairFriction : public testing::TestWithParam<FrictionLaw> {};

INSTANTIATE_TEST_SUITE_P(Laws, SpherePairFriction, testing::Values(FrictionLaw::Viscous, FrictionLaw::Spring));

TEST_P(SpherePairFriction, OpposesTheSlipAndIsCappedByCoulomb) {
  const Real r = 0.01, overlap = 2e-4;
  HertzMaterial ball = kSoft, floor = kStiff;
  ball.friction = 0.5;
  floor.friction = 0.3;
  ball.tangentialDamping = 0.02;
  floor.tangentialDamping = 0.04;
  const Real mu = 0.3, c = 0.03;
  const Real normal = hertzForce(ball, floor, r, overlap, 0);
  const Vector3r lever(0, 0, -(r - overlap));
  for (Real speed : {1e-3, 10.0}) {
    const Vector3r v(speed, 0, 0), w(0, 0.3 * speed / r, 0);
    Scene scene;
    scene.model.options.friction = GetParam();
    scene.add(Sphere{r}, ball, moving(Vector3r(0, 0, r - overlap), v, w), true);
    scene.add(Wall{2, 1}, floor, test::at(Vector3r::Zero()), false);
    scene.step();
    const Vector3r slip = v + w.cross(lever);  // of the sphere over the floor
    const bool sliding = c * slip.norm() > mu * normal;
    EXPECT_EQ(sliding, speed > 1) << "the speeds are meant to fall on either side of Eq. 21";
    const Vector3r friction = sliding ? Vector3r(-mu * normal * slip.normalized()) : Vector3r(-c * slip);
    const Wrench& onBall = scene.wrench(0);
    EXPECT_NEAR(onBall.force.z(), normal, 1e-12 * normal);
    EXPECT_LT((onBall.force - normal * Vector3r::UnitZ() - friction).norm(), 1e-12 * normal);
    EXPECT_LT((onBall.torque - lever.cross(friction)).norm(), 1e-12 * friction.norm() * r);
    EXPECT_EQ(scene.data.statistics.slidingContacts, sliding ? 1 : 0);
    EXPECT_LE(Vector3r(onBall.force.x(), onBall.force.y(), 0).norm(), mu * normal * (1 + 1e-12));
  }
}

// Equal and opposite wrenches of an oblique, damped (approaching), frictional sphere-sphere contact: forces sum to zero and
// the torques about a common point too (the reaction acts at the same point). Tolerance: round-off.
TEST(SpherePair, WrenchesAreEqualAndOpposite) {
  HertzMaterial a = kSoft, b = kStiff;
  a.friction = b.friction = 0.4;
  a.tangentialDamping = b.tangentialDamping = 0.05;
  Scene scene;
  const Vector3r x1(0.3, -0.2, 0.1), x2 = x1 + Vector3r(0.012, 0.01, -0.005);
  scene.add(Sphere{0.01}, a, moving(x1, Vector3r(0.2, -0.1, 0.3), Vector3r(5, -3, 2)), true);
  scene.add(Sphere{0.007}, b, moving(x2, Vector3r(-0.3, -0.4, 0), Vector3r(-1, 8, 4)), true);
  scene.step();
  const Wrench &w1 = scene.wrench(0), &w2 = scene.wrench(1);
  ASSERT_GT(w1.force.norm(), 0);
  EXPECT_TRUE((w1.force + w2.force).isZero(1e-14 * w1.force.norm()));
  EXPECT_LT((w1.torque + x1.cross(w1.force) + w2.torque + x2.cross(w2.force)).norm(), 1e-14 * w1.force.norm());
  EXPECT_GT(w1.torque.norm(), 0);
}

// The limit of two equal sphere bodies is criticalTimeStep at the reduced mass m/2, R* = r/2 and an overlap of
// r/10 (CriticalTimeStep.hpp), against a Wall at m and R* = r: the smaller of the two. A fixed sphere body
// (mass 0) against a Wall puts no limit.
TEST(SpherePair, StabilityLimitCoversSphereBodies) {
  ContactModel model;
  const Real r = 0.01, m = 0.004;
  model.partners.push_back({1, Sphere{r}, kSoft, true});
  model.partners.push_back({2, Sphere{r}, kSoft, true});
  model.partners.push_back({3, Wall{2, 1}, kStiff, false});
  const HertzPhys same = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kSoft, kSoft);
  const HertzPhys wall = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kSoft, kStiff);
  const Real pair = criticalTimeStep(m / 2, same.effectiveModulus, r / 2, same.damping, r / 10);
  const Real onWall = criticalTimeStep(m, wall.effectiveModulus, r, wall.damping, r / 10);
  const StabilityLimit limit = stabilityLimit(model, {}, {m, m, 0});
  EXPECT_DOUBLE_EQ(limit.timeStep, std::min(pair, onWall));
  EXPECT_EQ(stabilityLimit(model, {}, {0, 0, 0}).timeStep, std::numeric_limits<Real>::infinity());
}

}  // namespace
}  // namespace roundedmesh
