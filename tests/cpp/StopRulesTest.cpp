// Deep overlaps and fast impacts (StopRules.hpp, CriticalTimeStep.hpp, doc/physics.md "Deep overlaps and fast
// impacts"): a body whose centre passes through a Wall, a Facet or into a Box, or whose overlap grows past the
// stop fraction, stops the run, and only then; a step that stops is not kept; the impact time step resolves an
// impact's energy where the stability limit alone does not; a Facet holds a body at any depth, as its plane does.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/engine/StopRules.hpp"
#include "pkg/phys/HertzPhys.hpp"
#include "pkg/meshing/BodyMesh.hpp"
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

}  // namespace
}  // namespace roundedmesh
