// The energy law (ContactEnergyGradient.hpp, PressureOptions::normal = NormalLaw::Energy): the wrench the engine
// applies to body 2 is minus the gradient of the pair's elastic energy, the sum over its triangle contacts of the
// energy density integrated over S n Omega (NormalLoad::elasticEnergy), checked by central differences of that energy
// under small translations and rotations of body 2, for two bodies whose triangles have different radii (a distorted
// icosphere and a spheroid, curvature computed from the meshes: the shares of S n Omega change with the pose, so the
// edge forces carry a large part of the gradient), a body on a Wall and a body on a Sphere, and a body over the edges
// of a Box's face and of a Facet (their outlines cut the contact circles, so S has edges of the partner's). Steps of 1e-7 m and
// 1e-6 rad keep the set of triangle contacts unchanged; their truncation error is below 1e-6 of the force, so the
// tolerance is 1e-5 of the force's magnitude. The paper's pressure law misses the gradient by up to 2.4 % in these
// poses (checked: more than 1 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

const HertzMaterial kRubber{1e6, 0.4, 2000};

struct Pair {
  ContactModel model;
  ContactData data;

  // The elastic energy of every triangle contact of body 0 with body 1 (a body or a partner) [J].
  Real energy() {
    std::vector<PressureGeom> geoms;
    ContactStatistics statistics;
    pairGeometry(model, data, {0, 1}, geoms, statistics);
    const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kRubber, kRubber);
    Real sum = 0;
    for (const PressureGeom& g : geoms) sum += Law2_PressureGeom_HertzPhys_IntegratedPressure(g, phys, model.options.pressure).elasticEnergy;
    return sum;
  }
  // The wrench on body 0 or on the other side, torque about its own position.
  Wrench on(bool other) {
    std::vector<PressureGeom> geoms;
    ContactStatistics statistics;
    pairGeometry(model, data, {0, 1}, geoms, statistics);
    const PairResult result = pairLoad(model, data, {0, 1}, geoms);
    return other ? result.onOther : result.onBody;
  }
};

// -grad U by central differences: (force, torque about body 2's position).
Wrench numericalGradient(Pair& pair, BodyState& moving) {
  const Real dx = 1e-7, dtheta = 1e-6;
  Wrench w;
  const BodyState start = moving;
  for (int i = 0; i < 3; ++i) {
    moving.position = start.position + dx * Vector3r::Unit(i);
    const Real plus = pair.energy();
    moving.position = start.position - dx * Vector3r::Unit(i);
    const Real minus = pair.energy();
    moving.position = start.position;
    w.force[i] = -(plus - minus) / (2 * dx);
    moving.orientation = Quaternionr(Eigen::AngleAxis<Real>(dtheta, Vector3r::Unit(i))) * start.orientation;
    const Real turnedPlus = pair.energy();
    moving.orientation = Quaternionr(Eigen::AngleAxis<Real>(-dtheta, Vector3r::Unit(i))) * start.orientation;
    const Real turnedMinus = pair.energy();
    moving.orientation = start.orientation;
    w.torque[i] = -(turnedPlus - turnedMinus) / (2 * dtheta);
  }
  return w;
}

Quaternionr randomRotation(std::mt19937& random) {
  std::normal_distribution<Real> normal;
  return Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
}

const BodyMesh& distortedBall() {
  static const BodyMesh mesh(distortedIcosphereSurface(0.025, 2, 0.5, 3), std::nullopt);
  return mesh;
}

const BodyMesh& spheroid() {
  static const BodyMesh mesh(spheroidSurface(0.035, 0.02, 300), std::nullopt);
  return mesh;
}

// How far along u body 1, at orientation ori, is from body 0 when the two first touch (bisection on the energy) [m].
Real firstTouch(Pair& pair, const Vector3r& u, const Quaternionr& ori) {
  Real lo = 0, hi = 0.1;
  for (int k = 0; k < 60; ++k) {
    const Real mid = (lo + hi) / 2;
    pair.data.bodyStates[1] = test::at(mid * u, ori);
    (pair.energy() > 0 ? lo : hi) = mid;
  }
  return lo;
}

// `moving`: body 0's state (other = false) or the other side's.
void expectGradient(Pair& pair, bool other, BodyState& moving, const char* what) {
  const Wrench analytic = pair.on(other);
  const Wrench numeric = numericalGradient(pair, moving);
  const Real scale = numeric.force.norm();
  ASSERT_GT(scale, 0) << what;
  EXPECT_LT((analytic.force - numeric.force).norm(), 1e-5 * scale) << what << ": " << analytic.force.transpose()
                                                                    << " against " << numeric.force.transpose();
  EXPECT_LT((analytic.torque - numeric.torque).norm(), 1e-5 * scale * 0.03)
      << what << ": " << analytic.torque.transpose() << " against " << numeric.torque.transpose();
}

TEST(ContactEnergy, TheForceBetweenTwoBodiesIsMinusTheEnergysGradient) {
  std::mt19937 random(5);
  Real worstPressureMiss = 0;
  for (int pose = 0; pose < 4; ++pose) {
    Pair pair;
    pair.model.options.pressure.normal = NormalLaw::Energy;
    pair.model.bodies = {roundedBody(0, distortedBall(), kRubber), roundedBody(1, spheroid(), kRubber)};
    pair.data.resize(pair.model);
    pair.data.bodyStates[0] = test::at(Vector3r::Zero(), randomRotation(random));
    // Along a random direction, 1 mm past first touch.
    std::normal_distribution<Real> normal;
    const Vector3r u = Vector3r(normal(random), normal(random), normal(random)).normalized();
    const Quaternionr ori = randomRotation(random);
    pair.data.bodyStates[1] = test::at((firstTouch(pair, u, ori) - 1e-3) * u, ori);
    ASSERT_GT(pair.energy(), 0);
    expectGradient(pair, true, pair.data.bodyStates[1], "two bodies, the second");
    expectGradient(pair, false, pair.data.bodyStates[0], "two bodies, the first");
    // The paper's law, its pressure at each contact's centre of pressure, is not this gradient.
    pair.model.options.pressure.normal = NormalLaw::Pressure;
    pair.model.options.pressure.regime = RegimeChoice::Exact;
    const Wrench pressure = pair.on(true), gradient = numericalGradient(pair, pair.data.bodyStates[1]);
    worstPressureMiss = std::max(worstPressureMiss, (pressure.force - gradient.force).norm() / gradient.force.norm());
  }
  EXPECT_GT(worstPressureMiss, 0.01);
}

// The energy law's damping is the paper's: Eq. 7's term, the elastic pressure times A ddelta/dt / delta at each
// contact's centre of pressure, as node forces. With body 2 approaching or parting at 2 cm/s and turning at 6 rad/s
// (so that some contacts approach while others part), the wrench the damping adds (the damped wrench minus the same
// pose's at rest) is the same under both laws, the paper's integrating exactly as the energy law does; parting, it
// pulls. Tolerance 1e-9 of the damping force: the same integrals, summed in another order.
TEST(ContactEnergy, TheDampingActsAsThePapersWhetherTheSidesApproachOrPart) {
  const HertzMaterial damped{1e6, 0.4, 2000, 0.01};
  std::mt19937 random(5);
  Pair pair;
  pair.model.bodies = {roundedBody(0, distortedBall(), damped), roundedBody(1, spheroid(), damped)};
  pair.data.resize(pair.model);
  pair.data.bodyStates[0] = test::at(Vector3r::Zero(), randomRotation(random));
  std::normal_distribution<Real> normal;
  const Vector3r u = Vector3r(normal(random), normal(random), normal(random)).normalized();
  const Quaternionr ori = randomRotation(random);
  const Real touch = firstTouch(pair, u, ori);
  for (const Real approach : {1.0, -1.0}) {
    BodyState& moving = pair.data.bodyStates[1];
    moving = test::at((touch - 1e-3) * u, ori);
    Wrench added[2];
    for (const NormalLaw law : {NormalLaw::Pressure, NormalLaw::Energy}) {
      pair.model.options.pressure.normal = law;
      pair.model.options.pressure.regime = RegimeChoice::Exact;
      moving.velocity = Vector3r::Zero();
      moving.angularVelocity = Vector3r::Zero();
      const Wrench atRest = pair.on(true);
      moving.velocity = -0.02 * approach * u;
      moving.angularVelocity = Vector3r(4, -2, 4);
      const Wrench moved = pair.on(true);
      added[law == NormalLaw::Energy] = {moved.force - atRest.force, moved.torque - atRest.torque};
    }
    const Real scale = added[0].force.norm();
    ASSERT_GT(scale, 0);
    EXPECT_LT((added[1].force - added[0].force).norm(), 1e-9 * scale) << "approach " << approach;
    EXPECT_LT((added[1].torque - added[0].torque).norm(), 1e-9 * scale * 0.03) << "approach " << approach;
    EXPECT_GT(approach * added[1].force.dot(u), 0) << "the damping pushes body 2 away while it approaches, pulls it back "
                                                      "while it parts";
  }
}

TEST(ContactEnergy, TheForceOnAWallAndOnASphereIsMinusTheEnergysGradient) {
  std::mt19937 random(9);
  for (const PartnerShape& shape : {PartnerShape(Wall{2, 1}), PartnerShape(Sphere{0.01})}) {
    Pair pair;
    pair.model.options.pressure.normal = NormalLaw::Energy;
    pair.model.bodies = {roundedBody(0, spheroid(), kRubber)};
    // Sharp edges (rounding 0): a rounded edge pushes by Hertz's ellipse, whose force is not the gradient of the
    // energy law's circular energy.
    pair.model.partners = {{1, shape, kRubber, false, 0}};
    pair.data.resize(pair.model);
    pair.data.bodyStates[0] = test::at(Vector3r::Zero(), randomRotation(random));
    const bool wall = std::holds_alternative<Wall>(shape);
    Real lo = wall ? -0.1 : 0, hi = wall ? 0 : 0.1;
    for (int k = 0; k < 60; ++k) {
      const Real mid = (lo + hi) / 2;
      pair.data.partnerStates[0] = test::at(Vector3r(0.003, -0.002, mid));
      (pair.energy() > 0) == wall ? (hi = mid) : (lo = mid);
    }
    pair.data.partnerStates[0] = test::at(Vector3r(0.003, -0.002, wall ? lo + 1e-3 : lo - 1e-3));
    // A Wall ignores its orientation and a Sphere's turns change nothing: the body's own gradient is checked.
    expectGradient(pair, false, pair.data.bodyStates[0], wall ? "on a wall" : "on a sphere");
  }
}

TEST(ContactEnergy, TheForceOverTheEdgeOfABoxOrAFacetIsMinusTheEnergysGradient) {
  std::mt19937 random(13);
  const Quaternionr ori = randomRotation(random);
  // The body's lowest point in the plane: the faces' edges pass 1 and 1.5 mm from it, through contact circles of
  // radius about sqrt(1 mm x 20 mm) = 4.5 mm.
  Vector2r lowest = Vector2r::Zero();
  Real bottom = std::numeric_limits<Real>::infinity();
  for (const Vector3r& v : spheroid().shape().vertices()) {
    const Vector3r x = ori * v;
    if (x.z() < bottom) {
      bottom = x.z();
      lowest = x.head<2>();
    }
  }
  const Real half = 0.05;
  const Facet facet{{Vector3r(lowest.x() - 0.001, lowest.y() - 0.05, 0), Vector3r(lowest.x() + 0.08, lowest.y() + 0.0015, 0),
                     Vector3r(lowest.x() - 0.001, lowest.y() + 0.05, 0)}, nullptr};
  for (const PartnerShape& shape : {PartnerShape(Box{Vector3r::Constant(half)}), PartnerShape(facet)}) {
    const bool box = std::holds_alternative<Box>(shape);
    Pair pair;
    pair.model.options.pressure.normal = NormalLaw::Energy;
    pair.model.bodies = {roundedBody(0, spheroid(), kRubber)};
    // Sharp edges (rounding 0): a rounded edge pushes by Hertz's ellipse, whose force is not the gradient of the
    // energy law's circular energy.
    pair.model.partners = {{1, shape, kRubber, false, 0}};
    pair.data.resize(pair.model);
    pair.data.bodyStates[0] = test::at(Vector3r::Zero(), ori);
    // The top of the box or the facet at height z, its corner 1 and 1.5 mm from the lowest point.
    auto place = [&](Real z) {
      pair.data.partnerStates[0] = box ? test::at(Vector3r(lowest.x() + 0.001 - half, lowest.y() + 0.0015 - half, z - half))
                                       : test::at(Vector3r(0, 0, z));
    };
    Real lo = -0.1, hi = 0;
    for (int k = 0; k < 60; ++k) {
      const Real mid = (lo + hi) / 2;
      place(mid);
      (pair.energy() > 0 ? hi : lo) = mid;
    }
    place(lo + 1e-3);
    std::vector<PressureGeom> geoms;
    ContactStatistics statistics;
    pairGeometry(pair.model, pair.data, {0, 1}, geoms, statistics);
    int clipped = 0;  // contacts whose S has an edge of the outline: a corner off the triangle's edges
    for (const PressureGeom& g : geoms)
      clipped += g.polygon.area() < ConvexPolygon::triangle(g.nodes[0], g.nodes[1], g.nodes[2]).area() * (1 - 1e-9);
    ASSERT_GT(clipped, 0) << (box ? "box" : "facet");
    expectGradient(pair, false, pair.data.bodyStates[0], box ? "over a box's edge" : "over a facet's edge");
  }
}

}  // namespace
}  // namespace roundedmesh
