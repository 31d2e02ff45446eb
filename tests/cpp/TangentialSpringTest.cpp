// The tangential spring of a body pair (pkg/law/TangentialSpring.hpp): the law on its own against hand-written
// integrations (stick, Coulomb cap and reset, the frame carried with the normal and the spin, twist and the
// elliptic cap, the dissipated power), then through the engine: Mindlin's stiffness 8 G* a for a meshed sphere on
// a plane, the spring kept between steps and let go when the pair separates, saved and restored bit for bit, the
// damping c applied whatever the pose, and the stability limit with the spring.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/law/TangentialSpring.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

HertzPhys phys(Real mu, Real c) {
  HertzPhys p{1e6, 0, mu, c, 0.75};
  return p;
}

SpringContact flat(const Vector3r& slip, Real normalForce, Real stiffness) {
  SpringContact contact;
  contact.normal = Vector3r::UnitZ();
  contact.slip = slip;
  contact.normalForce = normalForce;
  contact.stiffness = stiffness;
  return contact;
}

// A constant slip loads the spring by v dt per step: F = -k n v dt - c v while |F| < mu N (sticking), then the
// force stays at mu N against the slip and the spring holds just that (reset to the cap). Tolerance: round-off.
TEST(TangentialSpring, SticksUntilCoulombThenSlidesAtTheCap) {
  const Real k = 2000, c = 3, mu = 0.4123, N = 2, dt = 1e-4;
  const Vector3r v(3e-3, -4e-3, 0);
  TangentialSpring spring;
  const HertzPhys p = phys(mu, c);
  int slidFrom = -1;
  for (int n = 1; n <= 2000; ++n) {
    const SpringLoad load = tangentialSpring(flat(v, N, k), p, dt, spring);
    const Vector3r stuck = -k * (n * dt) * v - c * v;
    if (stuck.norm() <= mu * N) {
      EXPECT_FALSE(load.sliding) << n;
      EXPECT_LT((load.force - stuck).norm(), 1e-12 * stuck.norm()) << n;
      EXPECT_LT((spring.displacement - n * dt * v).norm(), 1e-12 * n * dt * v.norm()) << n;
    } else {
      if (slidFrom < 0) slidFrom = n;
      EXPECT_TRUE(load.sliding) << n;
      EXPECT_LT((load.force + mu * N * v.normalized()).norm(), 1e-12 * mu * N) << n;
      // Reset: the spring alone holds the capped force.
      EXPECT_LT((-k * spring.displacement - load.force).norm(), 1e-12 * mu * N) << n;
    }
  }
  EXPECT_GT(slidFrom, 1);
  EXPECT_EQ(spring.normal, Vector3r::UnitZ());
  EXPECT_DOUBLE_EQ(spring.energy, 0.5 * k * spring.displacement.squaredNorm());
}

// Released after sticking, the spring keeps its force (no creep): with zero slip the load is -k u, step after step.
TEST(TangentialSpring, HoldsItsLoadWithoutSlip) {
  const Real k = 2000, mu = 0.5, N = 1;
  TangentialSpring spring;
  const HertzPhys p = phys(mu, 10);
  tangentialSpring(flat(Vector3r(1e-2, 0, 0), N, k), p, 1e-2, spring);
  const Vector3r held = -k * Vector3r(1e-4, 0, 0);
  for (int n = 0; n < 100; ++n) {
    const SpringLoad load = tangentialSpring(flat(Vector3r::Zero(), N, k), p, 1e-2, spring);
    EXPECT_EQ(load.force, held);
    EXPECT_FALSE(load.sliding);
    EXPECT_EQ(load.dissipatedPower, 0);
  }
}

// The displacement turns with the contact: tilting the normal by an angle about an axis turns u by the same
// rotation (u stays in the contact plane, its length kept), and the contact frame's spin about n turns it about n.
TEST(TangentialSpring, IsCarriedByTheNormalAndTheFrameSpin) {
  const Real k = 1000;
  const HertzPhys p = phys(1, 0);
  TangentialSpring spring;
  tangentialSpring(flat(Vector3r(2e-3, 1e-3, 0), 10, k), p, 1.0, spring);
  const Vector3r u0 = spring.displacement;
  const Eigen::AngleAxis<Real> tilt(0.3, Vector3r(1, 2, 0).normalized());
  SpringContact turned = flat(Vector3r::Zero(), 10, k);
  turned.normal = tilt * Vector3r::UnitZ();
  tangentialSpring(turned, p, 1.0, spring);
  EXPECT_LT((spring.displacement - tilt * u0).norm(), 1e-15);
  EXPECT_EQ(spring.normal, turned.normal);
  // Spun about the (new) normal at w for dt: turned by w dt about it.
  const Vector3r u1 = spring.displacement;
  turned.frameSpin = 0.7;
  tangentialSpring(turned, p, 0.5, spring);
  EXPECT_LT((spring.displacement - Eigen::AngleAxis<Real>(0.35, turned.normal) * u1).norm(), 1e-15);
  // A normal turned round (the bodies passed through each other) leaves nothing to carry.
  turned.normal = -turned.normal;
  turned.frameSpin = 0;
  tangentialSpring(turned, p, 0.5, spring);
  EXPECT_TRUE(spring.displacement.isZero(0));
}

// The twist: torque -k J theta - c J spin about n, and Coulomb's ellipse (|F| / mu N)^2 + (M / mu N rho)^2 <= 1
// with both scaled back onto it when outside.
TEST(TangentialSpring, TwistsAndCapsOnTheEllipse) {
  const Real k = 1000, c = 2, mu = 0.5, N = 4, J = 1e-4, rho = 8e-3, dt = 1e-3;
  const HertzPhys p = phys(mu, c);
  SpringContact contact = flat(Vector3r::Zero(), N, k);
  contact.polarMoment = J;
  contact.meanRadius = rho;
  contact.spin = 0.3;
  TangentialSpring spring;
  SpringLoad load = tangentialSpring(contact, p, dt, spring);
  EXPECT_NEAR(load.torque, -k * J * 0.3 * dt - c * J * 0.3, 1e-16);
  EXPECT_TRUE(load.force.isZero(0));
  EXPECT_FALSE(load.sliding);
  // Slip and spin together past the ellipse.
  contact.slip = Vector3r(5, 0, 0);
  contact.spin = 500;
  load = tangentialSpring(contact, p, dt, spring);
  EXPECT_TRUE(load.sliding);
  const Real onEllipse = std::pow(load.force.norm() / (mu * N), 2) + std::pow(load.torque / (mu * N * rho), 2);
  EXPECT_NEAR(onEllipse, 1, 1e-12);
  EXPECT_NEAR(k * J * spring.twist, -load.torque, 1e-12 * std::abs(load.torque));
  // No normal force: nothing holds, the spring lets go.
  contact.normalForce = 0;
  load = tangentialSpring(contact, p, dt, spring);
  EXPECT_TRUE(load.force.isZero(0));
  EXPECT_EQ(load.torque, 0);
  EXPECT_TRUE(spring.displacement.isZero(0));
  EXPECT_EQ(spring.twist, 0);
}

// Dissipation: while sticking under a constant slip, what the bodies lose beyond what the spring stores is the
// dashpot's c |v|^2; what the spring stores is its energy (1/2) k |u|^2.
TEST(TangentialSpring, DissipatesTheDashpotsPowerWhileSticking) {
  const Real k = 500, c = 4, dt = 1e-3;
  const Vector3r v(1e-3, 0, 0);
  TangentialSpring spring;
  for (int n = 1; n < 10; ++n) {
    const SpringLoad load = tangentialSpring(flat(v, 100, k), phys(1, c), dt, spring);
    // -F.v - dE/dt = (k u + c v).v - k (u - v dt/2).v = c v^2 + k v^2 dt / 2 (the step's own share).
    EXPECT_NEAR(load.dissipatedPower, c * v.squaredNorm() + 0.5 * k * dt * v.squaredNorm(), 1e-15);
  }
}

// --- through the engine -----------------------------------------------------------------------------------

const HertzMaterial kSoft{1e6, 0.4, 2000, 0, 0.5, 0};
const HertzMaterial kHard{5e6, 0.3, 2000, 0, 0.5, 0};

// A 2562-node sphere of prescribed curvature pressed delta into a fixed plane, in the direct regime (whose
// triangles tile the contact circle exactly, so that the normal stiffness is Hertz's 2 E* a), moved along x at
// v for n steps: F_t = -k_t n v dt with Mindlin's k_t = 8 G* a, a = sqrt(R delta). Tolerance: round-off.
TEST(TangentialSpringInEngine, StiffnessIsMindlinsForAMeshedSphere) {
  const Real radius = 0.025, overlap = 5e-4, dt = 1e-5;
  ContactModel model;
  model.bodies.push_back(roundedBody(0, BodyMesh(icosphere(radius, 4)), kSoft));
  model.partners.push_back({1, Plane{Vector3r::Zero(), Vector3r::UnitZ()}, kHard});
  model.options.pressure.regime = RegimeChoice::Direct;
  ContactData data;
  data.resize(model);
  data.timeStep = dt;
  data.bodyStates[0] = test::at(Vector3r(0, 0, radius - overlap));
  data.bodyStates[0].velocity = Vector3r(2e-3, 0, 0);  // the plane slips by -v under the body
  const Real shear = 1 / (kSoft.shearCompliance() + kHard.shearCompliance());
  const Real stiffness = 8 * shear * std::sqrt(radius * overlap);
  for (int n = 1; n <= 5; ++n) {
    contactForces(model, data);
    const Vector3r friction = data.bodyWrenches[0].force - data.bodyWrenches[0].force.z() * Vector3r::UnitZ();
    EXPECT_NEAR(friction.x(), -stiffness * n * dt * 2e-3, 1e-9 * stiffness * n * dt * 2e-3) << n;
    EXPECT_NEAR(friction.y(), 0, 1e-12 * std::abs(friction.x()));
  }
  ASSERT_EQ(data.springs.size(), 1u);
  EXPECT_TRUE(data.springs[0].active());
  // Lifted off: the spring lets go, and the next contact starts from zero.
  data.bodyStates[0].position.z() = radius + 1e-4;
  contactForces(model, data);
  ASSERT_EQ(data.springs.size(), 1u);
  EXPECT_FALSE(data.springs[0].active());
  data.bodyStates[0].position.z() = radius - overlap;
  data.bodyStates[0].velocity.setZero();
  contactForces(model, data);
  EXPECT_NEAR(data.bodyWrenches[0].force.x(), 0, 1e-12 * data.bodyWrenches[0].force.z());
}

// A sphere body on a Wall: one contact circle, so the spring's stiffness is Mindlin's 8 G* a exactly, from the
// Hertz stiffness 2 E* a of Eq. 7 (the direct regime over the whole circle). Tolerance: round-off.
TEST(TangentialSpringInEngine, SphereBodyStiffnessIsMindlins) {
  const Real radius = 0.01, overlap = 2e-4, dt = 1e-5, speed = 3e-3;
  ContactModel model;
  model.partners.push_back({0, Sphere{radius}, kSoft, true});
  model.partners.push_back({1, Wall{2, 1}, kHard, false});
  ContactData data;
  data.resize(model);
  data.timeStep = dt;
  data.partnerStates[0] = test::at(Vector3r(0, 0, radius - overlap));
  data.partnerStates[0].velocity = Vector3r(0, speed, 0);
  data.partnerStates[1] = test::at(Vector3r::Zero());
  const Real stiffness = 8 * std::sqrt(radius * overlap) / (kSoft.shearCompliance() + kHard.shearCompliance());
  for (int n = 1; n <= 4; ++n) {
    contactForces(model, data);
    const Wrench& onSphere = data.partnerWrenches[0];
    EXPECT_NEAR(onSphere.force.y(), -stiffness * n * dt * speed, 1e-10 * stiffness * n * dt * speed) << n;
    EXPECT_NEAR(onSphere.force.x(), 0, 1e-14);
    // At the contact point, (r - delta) below the centre: the moment turns the sphere.
    EXPECT_NEAR(onSphere.torque.x(), (radius - overlap) * onSphere.force.y(),
                1e-12 * std::abs(onSphere.force.y()) * radius);
  }
}

// Pairs of rounded bodies against each other and against a Box, sliding and turning: a run whose springs are saved
// (activeSprings) and restored into new data mid-way goes on bit for bit as the uninterrupted run.
TEST(TangentialSpringInEngine, SavedAndRestoredSpringsContinueBitForBit) {
  const BodyMesh mesh(icosphere(0.02, 2));
  ContactModel model;
  for (int b = 0; b < 3; ++b) model.bodies.push_back(roundedBody(b, mesh, kSoft));
  model.partners.push_back({3, Box{Vector3r(0.2, 0.2, 0.05)}, kHard});
  auto states = [](int n) {
    std::vector<BodyState> s(3);
    for (int b = 0; b < 3; ++b) {
      const Real t = n * 1e-4;
      s[b] = test::at(Vector3r(0.039 * b + 0.002 * t, 0.001 * b * t, 0.0698 - 0.0001 * b),
                      Quaternionr(Eigen::AngleAxis<Real>(0.3 * b + 2 * t, Vector3r(1, b, 2).normalized())));
      s[b].velocity = Vector3r(0.002, 0.001 * b, 0);
      s[b].angularVelocity = Vector3r(0, 0, 2);
    }
    return s;
  };
  auto runFrom = [&](ContactData& data, int first, int last, std::vector<Wrench>& out) {
    for (int n = first; n < last; ++n) {
      data.bodyStates = states(n);
      data.partnerStates[0] = test::at(Vector3r::Zero());
      contactForces(model, data);
      out.insert(out.end(), data.bodyWrenches.begin(), data.bodyWrenches.end());
    }
  };
  ContactData whole;
  whole.resize(model);
  whole.timeStep = 1e-4;
  std::vector<Wrench> uninterrupted, resumed;
  runFrom(whole, 0, 40, uninterrupted);
  ContactData first;
  first.resize(model);
  first.timeStep = 1e-4;
  runFrom(first, 0, 20, resumed);
  const auto saved = first.activeSprings();
  ASSERT_GE(saved.size(), 3u);
  ContactData second;
  second.resize(model);
  second.timeStep = 1e-4;
  second.restoreSprings(saved);
  runFrom(second, 20, 40, resumed);
  ASSERT_EQ(resumed.size(), uninterrupted.size());
  for (size_t k = 0; k < resumed.size(); ++k) {
    EXPECT_EQ(resumed[k].force, uninterrupted[k].force) << k;
    EXPECT_EQ(resumed[k].torque, uninterrupted[k].torque) << k;
  }
  // Without the springs the same run goes otherwise.
  ContactData restarted;
  restarted.resize(model);
  restarted.timeStep = 1e-4;
  std::vector<Wrench> fresh;
  runFrom(restarted, 20, 21, fresh);
  EXPECT_NE(fresh[0].force, uninterrupted[3 * 20].force);
}

// The triangle contacts' shares of the spring's load (listed for rm.triangle_contacts and the export) sum, with their
// normal forces, to the force on the pair, and each stays within its own Coulomb limit mu Fn_i. Bodies pressed
// together, sliding and spinning, some steps in. Tolerance: round-off.
TEST(TangentialSpringInEngine, TriangleSharesSumToThePairsForce) {
  const BodyMesh mesh(icosphere(0.02, 3));
  ContactModel model;
  for (int b = 0; b < 2; ++b) model.bodies.push_back(roundedBody(b, mesh, kSoft));
  ContactData data;
  data.resize(model);
  data.timeStep = 1e-4;
  data.keepTriangleContacts = true;
  data.bodyStates[0] = test::at(Vector3r::Zero());
  data.bodyStates[1] = test::at(Vector3r(0.0395, 0.002, 0.001),
                                Quaternionr(Eigen::AngleAxis<Real>(0.7, Vector3r(1, 2, 3).normalized())));
  data.bodyStates[1].velocity = Vector3r(0, 0.01, 0.002);
  data.bodyStates[1].angularVelocity = Vector3r(3, 0, 0);
  for (int n = 0; n < 5; ++n) contactForces(model, data);
  ASSERT_EQ(data.pairs.size(), 1u);
  const std::vector<TriangleContact>& contacts = data.pairContacts[0];
  ASSERT_GT(contacts.size(), 3u);
  Vector3r onOther = Vector3r::Zero(), friction = Vector3r::Zero();
  for (const TriangleContact& c : contacts) {
    onOther += c.load.force * c.normal + c.friction.force;
    friction += c.friction.force;
    EXPECT_LE(c.friction.force.norm(), 0.5 * c.load.force * (1 + 1e-12));
  }
  ASSERT_GT(friction.norm(), 1e-3 * data.pairResults[0].onOther.force.norm());
  EXPECT_LT((onOther - data.pairResults[0].onOther.force).norm(), 1e-12 * onOther.norm());
}

// The stability limit with friction is the smaller of the normal contact's and the tangential one's: for a sphere,
// m_t = m / 3.5 (a force at the surface of a sphere moves it as a mass m / (1 + r^2 / (2/5 r^2))), k_t = (k_t/k_n) k,
// damping c; for a sphere body against the Wall and against another like it (m/2, R* = r/2). With the viscous law,
// k_t = 0; without friction, the normal limits alone.
TEST(TangentialSpringInEngine, StabilityLimitHasTheTangentialContact) {
  const Real r = 0.01, m = 0.004;
  const Vector3r inertia = Vector3r::Constant(0.4 * m * r * r);
  HertzMaterial ball = kSoft;
  ball.tangentialDamping = 2;
  ball.damping = 1e-3;
  ContactModel model;
  model.partners.push_back({1, Sphere{r}, ball, true});
  model.partners.push_back({2, Wall{2, 1}, kHard, false});
  const HertzPhys wall = Ip2_HertzMaterial_HertzMaterial_HertzPhys(ball, kHard);
  const HertzPhys same = Ip2_HertzMaterial_HertzMaterial_HertzPhys(ball, ball);
  const Real normal = std::min(criticalTimeStep(m, wall.effectiveModulus, r, wall.damping, r / 10),
                               criticalTimeStep(m / 2, same.effectiveModulus, r / 2, same.damping, r / 10));
  const Real kWall = 2 * wall.effectiveModulus * std::sqrt(r * r / 10);
  const Real kSame = 2 * same.effectiveModulus * std::sqrt(r / 2 * r / 10);
  const Real spring = std::min(leapFrogLimit(m / 3.5, wall.stiffnessRatio * kWall, wall.tangentialDamping),
                               leapFrogLimit(m / 7, same.stiffnessRatio * kSame, same.tangentialDamping));
  auto limit = [&]() { return stabilityLimit(model, {}, {m, 0}, {}, {inertia, Vector3r::Zero()}); };
  EXPECT_NEAR(limit().timeStep, std::min(normal, spring), 1e-12 * normal);
  EXPECT_LT(spring, normal) << "c = 2 N s/m on a 4 g sphere is meant to set the limit";
  EXPECT_TRUE(limit().tangential);
  model.options.friction = FrictionLaw::Viscous;
  EXPECT_NEAR(limit().timeStep,
              std::min({normal, 2 * (m / 3.5) / wall.tangentialDamping, 2 * (m / 7) / same.tangentialDamping}),
              1e-12 * normal);
  model.partners[0].material.friction = 0;
  EXPECT_DOUBLE_EQ(limit().timeStep, normal);
  EXPECT_FALSE(limit().tangential);
}

// leapFrogLimit against the leap-frog's amplification matrix for x'' = -(k x + c v) / m with forces from x(t) and
// v(t - dt/2): its spectral radius crosses 1 at the limit, also for a pure dashpot (k = 0: 2 m / c) and for a
// heavily overdamped spring.
TEST(TangentialSpringInEngine, LeapFrogLimitIsTheSpectralLimit) {
  const Real m = 0.02;
  for (const auto& spring : {std::pair<Real, Real>{0, 100}, {5000, 0}, {5000, 10}, {5000, 100}, {5000, 1000}}) {
    const Real k = spring.first, c = spring.second;  // not a structured binding: C++17 does not let a lambda capture one
    const Real dtCrit = leapFrogLimit(m, k, c);
    auto spectralRadius = [&](Real dt) {
      Eigen::Matrix2d step;  // (v_{n-1/2}, x_n) -> (v_{n+1/2}, x_{n+1})
      step << 1 - c * dt / m, -k * dt / m, dt * (1 - c * dt / m), 1 - k * dt * dt / m;
      return step.eigenvalues().cwiseAbs().maxCoeff();
    };
    EXPECT_LE(spectralRadius(0.999 * dtCrit), 1 + 1e-12) << k << " " << c;
    EXPECT_GT(spectralRadius(1.001 * dtCrit), 1 + 1e-6) << k << " " << c;
  }
}

}  // namespace
}  // namespace roundedmesh
