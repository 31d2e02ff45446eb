// Two rounded bodies (and bodies against spheres and facets) through the whole engine: Newton's third law
// with friction, body 2's own node forces (Eq. 15 with n21 = -n12), Hertz for meshed spheres, the broad
// phase against brute force, and the same result on any number of threads.
#include <gtest/gtest.h>


#include <cmath>
#include <random>
#include <set>

#include "pkg/engine/BroadPhase.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3, 0.5, 20};

BodyState at(const Vector3r& position, const Quaternionr& orientation = Quaternionr::Identity()) {
  BodyState s;
  s.position = position;
  s.orientation = orientation;
  return s;
}

Quaternionr turn(Real angle, const Vector3r& axis) { return Quaternionr(Eigen::AngleAxis<Real>(angle, axis.normalized())); }

ContactModel twoSpheres(int subdivisions, Real radius = 0.025, const HertzMaterial& material = kRubber) {
  const BodyMesh mesh(icosphere(radius, subdivisions));
  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, material));
  model.bodies.push_back(roundedBody(1, mesh, material));
  return model;
}

ContactData run(const ContactModel& model, const std::vector<BodyState>& bodies, const std::vector<BodyState>& partners = {}) {
  ContactData data;
  data.resize(model);
  data.bodyStates = bodies;
  for (size_t p = 0; p < partners.size(); ++p) data.partnerStates[p] = partners[p];
  contactForces(model, data);
  return data;
}

// An off-centre, sliding, spinning contact of two turned meshes.
std::vector<BodyState> obliqueCollision() {
  BodyState a = at(Vector3r(0.001, -0.002, 0.0), turn(0.7, Vector3r(1, 2, 3)));
  BodyState b = at(Vector3r(0.012, 0.004, 0.0455), turn(-1.3, Vector3r(-2, 1, 0.5)));
  a.velocity = Vector3r(0.1, 0.0, 0.3);
  a.angularVelocity = Vector3r(2, -1, 5);
  b.velocity = Vector3r(-0.2, 0.1, -0.4);
  b.angularVelocity = Vector3r(-3, 0, 1);
  return {a, b};
}

// Forces cancel, and torques about a common point cancel (angular momentum is kept). Tolerance: round-off,
// 1e-12 of the force (and of force x size for torques).
TEST(BodyContact, ActionEqualsReactionWithFriction) {
  const ContactModel model = twoSpheres(3);
  const std::vector<BodyState> states = obliqueCollision();
  const ContactData data = run(model, states);
  const Wrench &w1 = data.bodyWrenches[0], &w2 = data.bodyWrenches[1];
  ASSERT_GT(w1.force.norm(), 0.1);
  ASSERT_GT(data.statistics.quadratureContacts + data.statistics.directContacts, 3);
  // Friction is on: the force is not along the centre line.
  const Vector3r line = (states[1].position - states[0].position).normalized();
  EXPECT_GT((w1.force - w1.force.dot(line) * line).norm(), 1e-3 * w1.force.norm());
  EXPECT_LT((w1.force + w2.force).norm(), 1e-12 * w1.force.norm());
  const Vector3r total = w1.torque + states[0].position.cross(w1.force) + w2.torque + states[1].position.cross(w2.force);
  EXPECT_LT(total.norm(), 1e-12 * w1.force.norm() * 0.05);
}

// Section 2.5 applied to body 2 with n21 = -n12: node forces on its own triangle's corners give the same
// wrench as the opposite of body 1's at the same points (both reproduce Fn and the centre of pressure).
// Tolerance: round-off of sums of ~50 terms.
TEST(BodyContact, Body2sOwnNodeForcesGiveTheTransferredWrench) {
  ContactModel model = twoSpheres(3);
  model.bodies[0].material.friction = model.bodies[1].material.friction = 0;
  model.bodies[0].material.tangentialDamping = model.bodies[1].material.tangentialDamping = 0;
  ContactData data;
  data.resize(model);
  data.bodyStates = obliqueCollision();
  std::vector<PressureGeom> scratch;
  std::vector<TriangleContact> contacts;
  const PairResult result = resolvePair(model, data, {0, 1}, scratch, &contacts);
  ASSERT_GT(contacts.size(), 3u);
  const BodyState &s1 = data.bodyStates[0], &s2 = data.bodyStates[1];
  const RoundedMesh& mesh2 = *model.bodies[1].mesh;
  Wrench own;
  for (const TriangleContact& c : contacts) {
    const Triangle& q = mesh2.triangles()[c.geom.partnerTriangle];
    for (int i = 0; i < 3; ++i) {
      const Vector3r corner = s2.position + s2.orientation * mesh2.vertices()[q[i]];
      const Vector3r force = c.partnerNodeForces[i] * c.normal;  // along n12 on body 2
      own.force += force;
      own.torque += (corner - s2.position).cross(force);
    }
    // Each node-force set alone carries the triangle's Fn.
    EXPECT_NEAR(c.partnerNodeForces[0] + c.partnerNodeForces[1] + c.partnerNodeForces[2], c.load.force, 1e-12 * c.load.force);
  }
  (void)s1;
  EXPECT_LT((own.force - result.onOther.force).norm(), 1e-12 * own.force.norm());
  EXPECT_LT((own.torque - result.onOther.torque).norm(), 1e-12 * own.force.norm() * 0.025);
}

// Two meshed spheres of radius R pressed by delta: Hertz with R* = R/2 (Eq. 7), both bodies' caps given the
// sphere's radius. Tolerance 1 % at 2562 nodes and 5 % overlap (the plane case at this refinement errs by
// 0.1 %, doc/validation.md; the pair adds a second mesh).
TEST(BodyContact, MeshedSpheresFollowHertz) {
  const ContactModel model = twoSpheres(4, 1.0, HertzMaterial{1, 0, 1});
  for (Real delta : {0.01, 0.03, 0.05}) {
    const ContactData data = run(model, {at(Vector3r::Zero(), turn(0.3, Vector3r(1, 1, 0))),
                                         at(Vector3r(0, 0, 2 - delta), turn(1.1, Vector3r(0, 1, 2)))});
    const Real hertz = 4.0 / 3.0 * 0.5 * std::sqrt(0.5) * std::pow(delta, 1.5);
    EXPECT_NEAR(data.bodyWrenches[1].force.z(), hertz, 0.01 * hertz) << delta;
  }
}

// Every pair whose bounding spheres (or a partner's box) overlap, and no other: against all pairs.
TEST(BodyContact, BroadPhaseFindsExactlyTheOverlappingBounds) {
  const BodyMesh mesh(icosphere(0.025, 1));
  ContactModel model;
  for (int b = 0; b < 60; ++b) model.bodies.push_back(roundedBody(b, mesh, kRubber));
  model.partners.push_back({100, Wall{2, 1}, kRubber});
  model.partners.push_back({101, Sphere{0.03}, kRubber});
  ContactData data;
  data.resize(model);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> uniform(0, 0.3);
  for (BodyState& s : data.bodyStates) s = at(Vector3r(uniform(rng), uniform(rng), uniform(rng)));
  data.partnerStates[0] = at(Vector3r(0, 0, 0.05));
  data.partnerStates[1] = at(Vector3r(0.15, 0.15, 0.15));
  broadPhase(model, data);
  std::set<std::pair<int, int>> found, expected;
  for (const BodyPair& p : data.pairs) EXPECT_TRUE(found.insert({p.body, p.other}).second);
  const Real r = model.bodies[0].mesh->sphereBoundRadius();
  for (int i = 0; i < 60; ++i) {
    const Vector3r& x = data.bodyStates[i].position;
    for (int j = i + 1; j < 60; ++j)
      if ((x - data.bodyStates[j].position).norm() < 2 * r) expected.insert({i, j});
    if (std::abs(x.z() - 0.05) <= r) expected.insert({i, 60});
    if (((x - Vector3r::Constant(0.15)).cwiseAbs().array() <= r + 0.03).all()) expected.insert({i, 61});
  }
  EXPECT_EQ(found, expected);
  EXPECT_GT(expected.size(), 20u);
}

// Pairs are resolved in parallel and summed in a fixed order: bitwise the same on 1 and 2 threads, under both normal
// laws (the energy law's closed forms in lanes, a batch per thread).
TEST(BodyContact, SameResultOnAnyNumberOfThreads) {
  for (const NormalLaw law : {NormalLaw::Pressure, NormalLaw::Energy}) {
    SCOPED_TRACE(law == NormalLaw::Energy ? "energy law" : "the paper's law");
    const BodyMesh mesh(icosphere(0.025, 2));
    ContactModel model;
    std::vector<BodyState> states;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        model.bodies.push_back(roundedBody(4 * i + j, mesh, kRubber));
        BodyState s = at(Vector3r(0.048 * i, 0.048 * j + 0.003 * i, 0), turn(i + 0.3 * j, Vector3r(1, j, 2)));
        s.velocity = Vector3r(0.1 * i, -0.1 * j, 0);
        states.push_back(s);
      }
    model.options.pressure.normal = law;
    model.options.threads = 1;
    const ContactData one = run(model, states);
    model.options.threads = 2;
    const ContactData two = run(model, states);
    ASSERT_GT(one.statistics.bodyPairs, 10);
    for (size_t b = 0; b < states.size(); ++b) {
      EXPECT_EQ(one.bodyWrenches[b].force, two.bodyWrenches[b].force);
      EXPECT_EQ(one.bodyWrenches[b].torque, two.bodyWrenches[b].torque);
    }
  }
}

// A meshed sphere on a YADE Sphere and on a Facet: Hertz with R* = R1 R2 / (R1 + R2) and with R* = R1,
// the Facet acting as the plane it lies in while the body stays inside it. Tolerance 1 % as above.
TEST(BodyContact, SphereAndFacetPartners) {
  const BodyMesh mesh(icosphere(1.0, 4));
  const HertzMaterial unit{1, 0, 1};
  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, unit));
  model.partners.push_back({1, Sphere{2.0}, unit});
  const Real delta = 0.04;
  ContactData onSphere = run(model, {at(Vector3r::Zero(), turn(0.4, Vector3r(2, 1, 0)))}, {at(Vector3r(0, 3 - delta, 0))});
  const Real sphereHertz = 4.0 / 3.0 * 0.5 * std::sqrt(2.0 / 3.0) * std::pow(delta, 1.5);
  EXPECT_NEAR(onSphere.partnerWrenches[0].force.y(), sphereHertz, 0.01 * sphereHertz);

  model.partners[0].shape = Facet{{Vector3r(-3, -3, 0), Vector3r(3, -3, 0), Vector3r(0, 4, 0)}, nullptr};
  const ContactData onFacet = run(model, {at(Vector3r(0.1, 0.2, 1 - delta))}, {at(Vector3r::Zero())});
  const Real planeHertz = 4.0 / 3.0 * 0.5 * std::pow(delta, 1.5);
  EXPECT_NEAR(onFacet.bodyWrenches[0].force.z(), planeHertz, 0.01 * planeHertz);
  // From below, the facet pushes the other way.
  const ContactData below = run(model, {at(Vector3r(0.1, 0.2, -1 + delta))}, {at(Vector3r::Zero())});
  EXPECT_NEAR(below.bodyWrenches[0].force.z(), -planeHertz, 0.01 * planeHertz);
}

}  // namespace
}  // namespace roundedmesh
