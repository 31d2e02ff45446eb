// Deep overlaps and fast impacts (StopRules.hpp, CriticalTimeStep.hpp, doc/physics.md "Deep overlaps and fast
// impacts"): a body whose centre passes through a Wall, a Facet or into a Box, or whose overlap grows past the
// stop fraction, stops the run, and only then; a step that stops is not kept; the impact time step resolves an
// impact's energy where the stability limit alone does not; a Facet holds a body at any depth, as its plane does.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/engine/StopRules.hpp"
#include "pkg/phys/HertzPhys.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kRubber{1e6, 0.4, 2000};
const Real kRadius = 0.025;

const BodyMesh& ball() {
  static const BodyMesh mesh(icosphere(kRadius, 3));
  return mesh;
}

// One 642-node ball and one partner at the origin.
struct Scene {
  explicit Scene(const PartnerShape& partner) {
    model.bodies.push_back(roundedBody(0, ball(), kRubber));
    model.partners.push_back({1, partner, kRubber});
    data.resize(model);
  }
  // A contact step (ContactStep.hpp) with the ball's centre at `centre`: kept if nothing stops it.
  const std::vector<StopReason>& step(const Vector3r& centre) {
    data.bodyStates[0] = at(centre);
    data.partnerStates[0] = at(Vector3r::Zero());
    report = contactStep(model, data);
    return report.stops;
  }
  ContactModel model;
  ContactData data;
  StepReport report;
};

const Facet kFacet{{Vector3r(-1, -1, 0), Vector3r(1, -1, 0), Vector3r(0, 1.5, 0)}, nullptr};

TEST(StopRules, ACentreThroughAWallStops) {
  for (int sense : {0, 1}) {
    Scene scene(Wall{2, sense});
    EXPECT_TRUE(scene.step(Vector3r(0, 0, 0.02)).empty());
    // Crossings come first; a one-sided Wall now also overlaps the ball by more than its radius.
    const std::vector<StopReason>& stops = scene.step(Vector3r(0, 0, -0.02));
    ASSERT_GE(stops.size(), 1u) << "sense " << sense;
    EXPECT_EQ(stops[0].cause, StopCause::CentreCrossed);
    EXPECT_EQ(stops[0].body, 0);
    EXPECT_EQ(stops[0].other, 1);
  }
}

// Through the facet's triangle it stops; past its edge (a body falling off a facet floor's rim) it does not.
TEST(StopRules, AFacetStopsOnlyACentreThroughItsTriangle) {
  Scene through(kFacet);
  EXPECT_TRUE(through.step(Vector3r(0, 0, 0.02)).empty());
  ASSERT_GE(through.step(Vector3r(0, 0, -0.005)).size(), 1u);
  EXPECT_EQ(through.report.stops[0].cause, StopCause::CentreCrossed);

  Scene beside(kFacet);
  EXPECT_TRUE(beside.step(Vector3r(0.99, -0.99, 0.02)).empty());
  EXPECT_TRUE(beside.step(Vector3r(1.03, -1.03, -0.02)).empty());
}

TEST(StopRules, ACentreIntoABoxStops) {
  Scene scene(Box{Vector3r(0.1, 0.1, 0.1)});
  EXPECT_TRUE(scene.step(Vector3r(0, 0, 0.12)).empty());
  const std::vector<StopReason>& stops = scene.step(Vector3r(0, 0, 0.09));
  ASSERT_FALSE(stops.empty());
  EXPECT_EQ(stops[0].cause, StopCause::CentreCrossed);
}

// Past stopOverlap (0.5 r_eq) a growing overlap stops the run; one that started that deep and shrinks does not, and
// the first step, with nothing kept to compare with, never does (the scene warns of bodies that start overlapped).
TEST(StopRules, AGrowingDeepOverlapStops) {
  Scene scene(Wall{2, 1});
  const Real r = scene.model.bodies[0].equivalentRadius;
  EXPECT_TRUE(scene.step(Vector3r(0, 0, kRadius - 0.6 * r)).empty());  // first step
  EXPECT_TRUE(scene.step(Vector3r(0, 0, kRadius - 0.55 * r)).empty());  // shrinking
  const std::vector<StopReason>& stops = scene.step(Vector3r(0, 0, kRadius - 0.56 * r));
  ASSERT_EQ(stops.size(), 1u);
  EXPECT_EQ(stops[0].cause, StopCause::Overlap);
  EXPECT_NEAR(stops[0].overlap, 0.56 * r, 1e-9);
  EXPECT_EQ(stops[0].size, r);

  Scene shallow(Wall{2, 1});
  for (Real overlap : {0.0, 0.1, 0.3, 0.45, 0.49}) EXPECT_TRUE(shallow.step(Vector3r(0, 0, kRadius - overlap * r)).empty());
  shallow.model.options.stopOverlap = std::numeric_limits<Real>::infinity();
  EXPECT_TRUE(shallow.step(Vector3r(0, 0, kRadius - 0.9 * r)).empty());
}

// A step that stops is not kept: redoing it stops again, whatever the user changes in between but the states.
TEST(StopRules, AStepThatStopsIsNotKept) {
  Scene scene(kFacet);
  EXPECT_TRUE(scene.step(Vector3r(0, 0, 0.02)).empty());
  EXPECT_FALSE(scene.step(Vector3r(0, 0, -0.02)).empty());
  EXPECT_FALSE(scene.step(Vector3r(0, 0, -0.02)).empty());
  EXPECT_TRUE(scene.step(Vector3r(0, 0, 0.021)).empty());
}

TEST(StopRules, FastestBodyMovesItsSpeedTimesTheStep) {
  Scene scene(Wall{2, 1});
  scene.data.bodyStates[0] = at(Vector3r(0, 0, 1));
  scene.data.bodyStates[0].velocity = Vector3r(0, 3, -4);
  const FastBody fastest = fastestBody(scene.model, scene.data, 1e-4);
  EXPECT_EQ(fastest.body, 0);
  EXPECT_DOUBLE_EQ(fastest.speed, 5);
  EXPECT_DOUBLE_EQ(fastest.fraction, 5 * 1e-4 / (kDeepestOverlap * scene.model.bodies[0].equivalentRadius));
}

// A Facet is the plane it lies in while the body stays over it, at any depth: it used to look for triangles only
// within 0.1 r_eq of its plane and let go of a ball pressed deeper (26 N at 2.5 mm, 13 N at 5 mm, none at 15 mm).
TEST(StopRules, AFacetHoldsABallAtAnyDepthAsItsPlaneDoes) {
  for (Real overlap : {0.001, 0.0025, 0.005, 0.01, 0.015, 0.02}) {
    Scene facet(kFacet), wall(Wall{2, 1});
    facet.step(Vector3r(0.1, 0.2, kRadius - overlap));
    wall.step(Vector3r(0.1, 0.2, kRadius - overlap));
    EXPECT_NEAR(facet.data.bodyWrenches[0].force.z(), wall.data.bodyWrenches[0].force.z(),
                1e-9 * wall.data.bodyWrenches[0].force.z())
        << "overlap " << overlap;
  }
}

// The leap-frog (forces from positions at t, velocities at t - dt/2) on an undamped Hertz impact F = k x^3/2 at
// speed v: the kinetic energy after the rebound over that before, worst over 40 phases of the step at which the
// contact starts.
Real worstEnergyError(Real mass, Real k, Real speed, Real dt) {
  Real worst = 0;
  for (int phase = 0; phase < 40; ++phase) {
    Real x = -phase / 40.0 * speed * dt, v = speed;
    for (int n = 0; n < 1000000; ++n) {
      v -= k * std::pow(std::max(x, Real(0)), 1.5) / mass * dt;
      x += v * dt;
      if (x < 0 && v < 0) break;
    }
    worst = std::max(worst, std::abs(v * v / (speed * speed) - 1));
  }
  return worst;
}

// impactTimeStep moves the bodies a tenth of the impact's depth per step: the rebound keeps its energy within 0.03 %;
// at the stability limit, an impact at a few times the speed that reaches the Hertz depth is not resolved at all.
TEST(CriticalTimeStep, TheImpactStepResolvesAnImpact) {
  const Real m = 0.131, E = 0.99e9, R = 0.025, hertzDepth = kDeepestOverlap * R;
  const Real k = 4.0 / 3.0 * E * std::sqrt(R);
  for (Real speed : {0.3, 3.0, 30.0, 300.0}) {
    const Real depth = std::pow(15 * m * speed * speed / (16 * E * std::sqrt(R)), 0.4);
    const Real dt = impactTimeStep(m, E, R, hertzDepth, speed);
    EXPECT_NEAR(speed * dt, kImpactFraction * std::min(depth, hertzDepth), 1e-12) << speed;
    EXPECT_LT(worstEnergyError(m, k, speed, dt), 3e-4) << speed;
  }
  EXPECT_EQ(impactTimeStep(m, E, R, hertzDepth, 0), std::numeric_limits<Real>::infinity());
  // 30 m/s is 1.9 times the speed at which an impact reaches the Hertz depth: at the stability limit it gains energy.
  const Real limit = criticalTimeStep(m, E, R, 0, hertzDepth);
  EXPECT_GT(worstEnergyError(m, k, 30.0, limit), 0.5);
}

// The scene's limit for an impact speed is the smallest impact step of the pairs a body can form: here against the
// Wall and against a body like itself (reduced mass m/2, R* = r/2), below the stability limit for any speed above
// a micrometre a second (the stability limit alone lets an impact penetrate about 1.5 times its depth per step).
TEST(CriticalTimeStep, TheSceneLimitForAnImpactSpeed) {
  Scene scene(Wall{2, 1});
  const Real m = 0.131;
  const StabilityLimit plain = stabilityLimit(scene.model, {m}, {0});
  EXPECT_EQ(stabilityLimit(scene.model, {m}, {0}, {}, {}, 0).timeStep, plain.timeStep);
  const Real E = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kRubber, kRubber).effectiveModulus;
  const Real r = scene.model.bodies[0].equivalentRadius, depth = kDeepestOverlap * r;
  for (Real speed : {1e-7, 1e-3, 0.3, 30.0}) {
    const Real expected = std::min({plain.timeStep, impactTimeStep(m, E, r, depth, speed),
                                    impactTimeStep(m / 2, E, r / 2, depth, speed)});
    EXPECT_DOUBLE_EQ(stabilityLimit(scene.model, {m}, {0}, {}, {}, speed).timeStep, expected) << speed;
  }
  EXPECT_EQ(stabilityLimit(scene.model, {m}, {0}, {}, {}, 1e-7).timeStep, plain.timeStep);
  EXPECT_LT(stabilityLimit(scene.model, {m}, {0}, {}, {}, 1e-5).timeStep, plain.timeStep);
}

// A normal force at a point x off the line through the centre of mass along the normal also turns the body: the
// point moves as a mass m_n = 1 / (1/m + L^2 / I), L the distance of that line from the centre. The leap-frog of the
// body's translation and turn together, pushed by the damped contact at that point (F = -(k s + c ds/dt), s = y + L
// theta), has its spectral radius cross 1 at criticalTimeStep(m_n): for a horse's limb in the new user's drum
// (newuser_drum.py, m = 4.3 g, I = 1.44e-7 kg m^2, A = 0.05 s) 13 times below the limit of its translation alone.
TEST(CriticalTimeStep, ANormalContactAlsoTurnsTheBody) {
  const Real m = 0.0043, I = 1.44e-7, E = 5.95e5, R = 0.0047, overlap = 0.00095;
  for (Real A : {0.0, 0.05})
    for (Real L : {0.0, 0.005, 0.025}) {
      const Real normalMass = 1 / (1 / m + L * L / I);
      const Real dtCrit = criticalTimeStep(normalMass, E, R, A, overlap);
      const Real k = 2 * E * std::sqrt(R * overlap), c = 2.0 / 3 * A * k;
      auto spectralRadius = [&](Real dt) {
        // (v, w) at n - 1/2 and (y, theta) at n -> the same a step later; F from s and ds/dt as a row over them.
        const Eigen::RowVector4d force(-c, -c * L, -k, -k * L);
        Eigen::Matrix4d velocities = Eigen::Matrix4d::Identity(), positions = Eigen::Matrix4d::Identity();
        velocities.row(0) += dt / m * force;
        velocities.row(1) += dt * L / I * force;
        positions(2, 0) = positions(3, 1) = dt;
        return (positions * velocities).eigenvalues().cwiseAbs().maxCoeff();
      };
      // The free turn about the contact's line is a double eigenvalue 1 (a Jordan block), found to about 1e-8.
      EXPECT_LE(spectralRadius(0.999 * dtCrit), 1 + 1e-6) << "A = " << A << ", L = " << L;
      EXPECT_GT(spectralRadius(1.001 * dtCrit), 1 + 1e-4) << "A = " << A << ", L = " << L;
    }
  EXPECT_LT(13 * criticalTimeStep(1 / (1 / m + 0.025 * 0.025 / I), E, R, 0.05, overlap),
            criticalTimeStep(m, E, R, 0.05, overlap));
}

// normalLever of a meshed prolate spheroid (a = 2b, 3000 nodes) is the exact spheroid's max over its surface of
// |I^-1/2 (x cross n)|^2 (I its exact moments; by symmetry a meridian, sampled every 1e-5 rad), within what the mesh
// changes: sqrt(lever) moves by at most (|x| eps + h) / sqrt(I_min), eps the largest angle between a cap's normal
// and the spheroid's at the same point, h the tallest cap (its apex lies that far off the surface). A sphere's
// normals pass through its centre: an icosphere's lever is 0 to round-off.
TEST(CriticalTimeStep, TheNormalLeverOfARoundedBody) {
  const Real a = 0.02, b = 0.01, density = 2000;
  const BodyMesh body(spheroidSurface(a, b, 3000), std::nullopt);
  const RoundedMesh& mesh = body.shape();
  // The principal frame puts the long axis where the vertices reach farthest.
  Vector3r reach = Vector3r::Zero();
  for (const Vector3r& x : mesh.vertices()) reach = reach.cwiseMax(x.cwiseAbs());
  int axis;
  reach.maxCoeff(&axis);
  Vector3r semiAxes = Vector3r::Constant(b);
  semiAxes[axis] = a;
  const Real m = density * 4 * M_PI / 3 * a * b * b;
  Vector3r inertia = Vector3r::Constant(m * (a * a + b * b) / 5);
  inertia[axis] = 2 * m * b * b / 5;
  Real exact = 0;
  for (Real phi = 0; phi <= M_PI; phi += 1e-5) {
    const Real x = b * std::sin(phi), z = a * std::cos(phi);
    const Vector2r n = Vector2r(std::sin(phi) / b, std::cos(phi) / a).normalized();
    exact = std::max(exact, std::pow(z * n.x() - x * n.y(), 2) / inertia[(axis + 1) % 3]);
  }
  auto spheroidNormal = [&](const Vector3r& x) { return x.cwiseQuotient(semiAxes.cwiseAbs2()).normalized(); };
  Real eps = 0, far = 0;
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const RoundedTriangle& cap = mesh.rounded(t);
    const Vector3r apex = cap.sphereCentre + cap.radius * cap.normal;
    eps = std::max(eps, std::acos(std::min(Real(1), cap.normal.dot(spheroidNormal(apex)))));
    for (int corner : mesh.triangles()[t]) {
      const Vector3r& x = mesh.vertices()[corner];
      eps = std::max(eps, std::acos(std::min(Real(1), (x - cap.sphereCentre).normalized().dot(spheroidNormal(x)))));
      far = std::max(far, x.norm());
    }
  }
  const Real tolerance = (far * eps + mesh.maxCapHeight()) / std::sqrt(inertia.minCoeff());
  const Real lever = normalLever(mesh, inertia);
  EXPECT_NEAR(std::sqrt(lever), std::sqrt(exact), tolerance);  // 63.9 against 59.7 [1/kg]; eps = 2.5 deg
  EXPECT_LT(tolerance, 0.2 * std::sqrt(exact)) << "the mesh is meant to resolve the lever";
  EXPECT_NEAR(exact, 1 / m, 1e-6 / m) << "for a = 2b the largest normal lever turns the spheroid as much as it moves it";
  const Real ballMass = kRubber.density * 4 * M_PI / 3 * std::pow(kRadius, 3);
  EXPECT_LT(normalLever(ball().shape(), Vector3r::Constant(0.4 * ballMass * kRadius * kRadius)), 1e-12 / ballMass);
}

}  // namespace
}  // namespace roundedmesh
