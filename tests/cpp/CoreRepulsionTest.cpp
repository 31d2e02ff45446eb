// The deep-overlap core (CoreRepulsion.hpp, CorePair.hpp) and the inscribed spheres it is made of
// (InscribedSpheres.hpp): against exact Hertz between two spheres, against the gradient of its own energy, and the
// same on every flat partner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "pkg/engine/CorePair.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/math/ClosestPoint.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kRubber{1e6, 0.4, 2000};
const HertzMaterial kFloor{5e6, 0.4, 2000};

const BodyMesh& ball() {
  static const BodyMesh mesh(icosphere(0.025, 3));
  return mesh;
}

// Aspect 4: a core of many spheres along the axis.
const BodyMesh& cigar() {
  static const BodyMesh mesh(spheroidSurface(0.04, 0.01, 800), std::nullopt);
  return mesh;
}

// The body axis along which the mesh is longest.
int longAxis(const RoundedMesh& mesh) {
  AlignedBox3r extent;
  for (const Vector3r& v : mesh.vertices()) extent.extend(v);
  int axis;
  extent.sizes().maxCoeff(&axis);
  return axis;
}

Real distanceToMesh(const RoundedMesh& mesh, const Vector3r& x) {
  Real best = kInfinity;
  for (const Triangle& t : mesh.triangles())
    best = std::min(best, (x - closestOnTriangle(x, mesh.vertices()[t[0]], mesh.vertices()[t[1]], mesh.vertices()[t[2]])).norm());
  return best;
}

// Each sphere lies inside the flat mesh and touches it: its radius is the distance from its centre to the nearest
// triangle (checked against every triangle, not the tree), and its centre is inside the solid.
TEST(InscribedSpheres, EachIsInsideTheMeshAndTouchesIt) {
  for (const BodyMesh* mesh : {&ball(), &cigar()}) {
    const RoundedMesh& shape = mesh->shape();
    const InscribedSpheres& spheres = shape.inscribedSpheres();
    ASSERT_FALSE(spheres.radii.empty());
    for (size_t i = 0; i < spheres.radii.size(); ++i) {
      EXPECT_NEAR(spheres.radii[i], distanceToMesh(shape, spheres.centres[i]), 1e-15);
      EXPECT_EQ(shape.solidDistance().at(spheres.centres[i]), 0);
      if (i > 0) {
        EXPECT_LE(spheres.radii[i], spheres.radii[i - 1]);  // largest first
      }
    }
  }
}

// A ball needs one sphere, at its centre (the grid is centred on the mesh's box), with the flat mesh's inradius:
// within 1 % of R at 642 nodes. A spheroid of aspect 4 needs a chain along its axis that reaches its tips (within two
// grid cells, the resolution of the candidates) and no wider than b.
TEST(InscribedSpheres, ABallHasOneSphereAndASpheroidAChainAlongItsAxis) {
  const InscribedSpheres& one = ball().shape().inscribedSpheres();
  ASSERT_EQ(one.radii.size(), 1u);
  EXPECT_LT(one.centres[0].norm(), 1e-12);
  EXPECT_GT(one.radii[0], 0.99 * 0.025);
  const InscribedSpheres& chain = cigar().shape().inscribedSpheres();
  EXPECT_GT(chain.radii.size(), 4u);
  Real reach = 0;
  const int axis = longAxis(cigar().shape());
  for (size_t i = 0; i < chain.radii.size(); ++i) {
    reach = std::max(reach, std::abs(chain.centres[i][axis]) + chain.radii[i]);
    EXPECT_LE(chain.radii[i], 0.01 + 1e-12);
  }
  EXPECT_GT(reach, 0.04 - 2 * 0.08 / InscribedSpheres::kCellsAcross);
}

EngineOptions withoutCore() {
  EngineOptions options;
  options.coreInset = 1;
  return options;
}

// Two balls: what the core adds is Hertz's force of two spheres of radius rho = (1 - inset) r0 at distance d,
// (4/3) E* sqrt(rho / 2) (2 rho - d)^3/2 along the line of centres, to round-off; and nothing at all (the same
// wrench, bit for bit) until the cores meet, past 2 inset r0 of approach: the Hertz range of the balls is untouched.
TEST(CoreRepulsion, TwoBallsAddHertzOfTheirCoresAndNothingBefore) {
  const RoundedBody body = roundedBody(0, ball(), kRubber);
  const Real rho = (1 - kCoreInset) * ball().shape().inscribedSpheres().radii[0];
  const Real modulus = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kRubber, kRubber).effectiveModulus;
  const Vector3r u = Vector3r(1, -2, 0.5).normalized();
  for (Real d : {0.049, 0.045, 0.04, 2 * rho + 1e-6, 2 * rho - 1e-3, 0.03, 0.02}) {
    const PairEvaluation with = bodyContact(body, at(Vector3r::Zero()), body, at(d * u), EngineOptions());
    const PairEvaluation without = bodyContact(body, at(Vector3r::Zero()), body, at(d * u), withoutCore());
    const Vector3r core = with.onSecond.force - without.onSecond.force;
    const Real expected = d < 2 * rho ? 4.0 / 3 * modulus * std::sqrt(rho / 2) * std::pow(2 * rho - d, 1.5) : 0;
    if (expected == 0) {
      EXPECT_EQ((with.onSecond.force - without.onSecond.force).norm(), 0) << d;
    } else {
      EXPECT_NEAR(core.dot(u), expected, 1e-9 * expected) << d;
      EXPECT_LT((core - core.dot(u) * u).norm(), 1e-9 * expected) << d;
    }
  }
}

struct CoredPair {
  ContactModel model;
  ContactData data;

  // As for a pair with a triangle contact deeper than any core's onset: the cores are always looked at.
  CoreLoad load() const {
    PairSummary deep;
    deep.triangleContacts = 1;
    deep.deepestOverlap = 1;
    return corePair(model, data, {0, 1}, deep);
  }
};

// The core's force and torque are minus the gradient of its energy (central differences): its forces are central
// between points fixed in the bodies, so it does no work round a loop. Two cigars crossed and pressed 1.2 b deep,
// where several pairs of core spheres touch.
TEST(CoreRepulsion, ItsWrenchIsMinusTheGradientOfItsEnergy) {
  CoredPair pair;
  pair.model.bodies = {roundedBody(0, cigar(), kRubber), roundedBody(1, cigar(), kRubber)};
  pair.data.resize(pair.model);
  std::mt19937 random(3);
  std::normal_distribution<Real> normal;
  for (int trial = 0; trial < 4; ++trial) {
    const Quaternionr q1 = Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
    const Quaternionr q2 = Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
    pair.data.bodyStates[0] = at(Vector3r::Zero(), q1);
    pair.data.bodyStates[1] = at(Vector3r(0.002, -0.001, 0.008), q2);
    const CoreLoad load = pair.load();
    ASSERT_GT(load.contacts, 1) << trial;
    BodyState& moving = pair.data.bodyStates[0];
    const BodyState start = moving;
    const Real dx = 1e-7, dtheta = 1e-6;
    for (int i = 0; i < 3; ++i) {
      moving.position = start.position + dx * Vector3r::Unit(i);
      const Real plus = pair.load().energy;
      moving.position = start.position - dx * Vector3r::Unit(i);
      const Real minus = pair.load().energy;
      moving.position = start.position;
      EXPECT_NEAR(load.force[i], -(plus - minus) / (2 * dx), 1e-5 * load.force.norm()) << trial << " force " << i;
      moving.orientation = Quaternionr(Eigen::AngleAxis<Real>(dtheta, Vector3r::Unit(i))) * start.orientation;
      const Real turnedPlus = pair.load().energy;
      moving.orientation = Quaternionr(Eigen::AngleAxis<Real>(-dtheta, Vector3r::Unit(i))) * start.orientation;
      const Real turnedMinus = pair.load().energy;
      moving.orientation = start.orientation;
      EXPECT_NEAR(load.torque[i], -(turnedPlus - turnedMinus) / (2 * dtheta), 1e-5 * load.force.norm() * 0.04)
          << trial << " torque " << i;
    }
  }
}

// A cigar lying (its axis horizontal) 0.6 b deep in a Wall, in a Box's top and in a single Facet much larger than it:
// the same core (to round-off), each core sphere Hertz's sphere on a plane, R = rho, delta = rho - h. The sheet pushes each core
// sphere on the side its centre is on: a cigar pushed through it from below meets the mirror image of the force
// from above.
TEST(CoreRepulsion, EveryFlatPartnerPushesTheCoreAsAPlaneAndASheetFromBothSides) {
  const RoundedBody body = roundedBody(0, cigar(), kRubber);
  const int axis = longAxis(cigar().shape());
  const Quaternionr lying = Quaternionr::FromTwoVectors(Vector3r::Unit(axis), Vector3r(1, 0.3, 0).normalized());
  const InscribedSpheres& spheres = cigar().shape().inscribedSpheres();
  const Real modulus = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kRubber, kFloor).effectiveModulus;
  const Vector3r position(0.003, -0.002, 0.01 - 0.006);  // every core centre 4 mm above the plane
  Real expected = 0;
  for (size_t i = 0; i < spheres.radii.size(); ++i) {
    const Real rho = (1 - kCoreInset) * spheres.radii[i];
    const Real delta = rho - (position + lying * spheres.centres[i]).z();
    if (delta > 0) expected += 4.0 / 3 * modulus * std::sqrt(rho) * std::pow(delta, 1.5);
  }
  ASSERT_GT(expected, 0);
  auto core = [&](const PartnerShape& partner, const BodyState& partnerState, const BodyState& state) -> Vector3r {
    return partnerContact(body, state, partner, partnerState, kFloor, EngineOptions()).onFirst.force -
           partnerContact(body, state, partner, partnerState, kFloor, withoutCore()).onFirst.force;
  };
  const BodyState above = at(position, lying);
  const Vector3r wall = core(Wall{2, 0}, at(Vector3r::Zero()), above);
  EXPECT_NEAR(wall.z(), expected, 1e-9 * expected);
  EXPECT_LT(wall.head<2>().norm(), 1e-9 * expected);
  const Vector3r box = core(Box{Vector3r(0.5, 0.5, 0.05)}, at(Vector3r(0, 0, -0.05)), above);
  EXPECT_LT((box - wall).norm(), 1e-9 * expected);
  const Facet sheet{{Vector3r(-1, -1, 0), Vector3r(2, -1, 0), Vector3r(-1, 2, 0)}, nullptr};
  const Vector3r front = core(sheet, at(Vector3r::Zero()), above);
  EXPECT_LT((front - wall).norm(), 1e-9 * expected) << front.transpose() << " against " << wall.transpose();
  const Quaternionr mirrored = Quaternionr(Eigen::AngleAxis<Real>(M_PI, Vector3r::UnitX())) * lying;
  const Vector3r back = core(sheet, at(Vector3r::Zero()), at(Vector3r(position.x(), -position.y(), -position.z()), mirrored));
  EXPECT_NEAR(back.z(), -expected, 1e-9 * expected);
}

// A cigar standing on end, pushed 1.5 to 2.5 b into a Facet sheet far from its rim, its lowest core spheres' centres behind
// the sheet: they came through it and are pushed back as by a Wall (delta = rho + their depth), from either side, so
// the core keeps pushing harder along the push (each step's force above the last).
TEST(CoreRepulsion, ACoreThroughASheetIsPushedBackAsByAWall) {
  const RoundedBody body = roundedBody(0, cigar(), kRubber);
  const int axis = longAxis(cigar().shape());
  Real half = 0;
  for (const Vector3r& v : cigar().shape().vertices()) half = std::max(half, std::abs(v[axis]));
  const Facet sheet{{Vector3r(-1, -1, 0), Vector3r(2, -1, 0), Vector3r(-1, 2, 0)}, nullptr};
  for (Real sense : {1.0, -1.0}) {
    const Quaternionr standing = Quaternionr::FromTwoVectors(Vector3r::Unit(axis), sense * Vector3r::UnitZ());
    Real last = 0;
    for (Real depth : {0.015, 0.02, 0.025}) {
      const BodyState state = at(Vector3r(0.001, 0.002, sense * (half - depth)), standing);
      auto core = [&](const PartnerShape& partner) -> Vector3r {
        return partnerContact(body, state, partner, at(Vector3r::Zero()), kFloor, EngineOptions()).onFirst.force -
               partnerContact(body, state, partner, at(Vector3r::Zero()), kFloor, withoutCore()).onFirst.force;
      };
      const Vector3r wall = core(Wall{2, 0}), facet = core(sheet);
      EXPECT_GT(sense * wall.z(), last) << sense << " " << depth;
      EXPECT_LT((facet - wall).norm(), 1e-9 * wall.norm()) << sense << " " << depth;
      last = sense * wall.z();
    }
    EXPECT_GT(last, 0);
  }
}

}  // namespace
}  // namespace roundedmesh
