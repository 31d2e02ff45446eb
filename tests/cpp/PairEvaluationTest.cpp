// One contact evaluated once (PairEvaluation.hpp, behind rm.plane_contact, rm.sphere_contact, rm.body_contact):
// the same wrench as the engine's step on the same scene, Newton's third law when the bodies swap sides, a
// listing whose normal forces add up to the wrench, and bad materials refused by name.
#include <gtest/gtest.h>

#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3};

// Bitwise: both run resolvePair on the same model and states.
TEST(PairEvaluation, PlaneContactIsTheEnginesStep) {
  const BodyMesh mesh(icosphere(0.025, 3));
  const BodyState state = at(Vector3r(0.001, 0.002, 0.024), Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r::UnitX())));
  const Plane floor{Vector3r::Zero(), Vector3r::UnitZ()};
  const PairEvaluation once = planeContact(roundedBody(0, mesh, kRubber), state, floor, kRubber, EngineOptions());
  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, kRubber));
  model.partners.push_back({1, floor, kRubber});
  ContactData data;
  data.resize(model);
  data.bodyStates[0] = state;
  contactForces(model, data);
  EXPECT_GT(once.onFirst.force.z(), 0.1);
  EXPECT_EQ(once.onFirst.force, data.bodyWrenches[0].force);
  EXPECT_EQ(once.onFirst.torque, data.bodyWrenches[0].torque);
}

// Action and reaction (round-off, 1e-12 of the force); the listed normal forces, frictionless, add up to the
// force on the second body (round-off of the sum). Swapping the bodies integrates over the same S with its fan
// from another corner and in another tangent frame: the same force up to the quadrature's error, 1 % here.
TEST(PairEvaluation, BodyContactKeepsNewtonsThirdLawAndListsItsForces) {
  const BodyMesh mesh(icosphere(0.025, 2));
  const RoundedBody a = roundedBody(0, mesh, kRubber), b = roundedBody(1, mesh, kRubber);
  const BodyState sa = at(Vector3r::Zero()), sb = at(Vector3r(0.003, -0.002, 0.049), Quaternionr(0.9, 0.1, 0.3, 0.2).normalized());
  const PairEvaluation ab = bodyContact(a, sa, b, sb, EngineOptions(), true);
  const PairEvaluation ba = bodyContact(b, sb, a, sa, EngineOptions(), true);
  const Real scale = ab.onFirst.force.norm();
  ASSERT_GT(scale, 0.01);
  EXPECT_LT((ab.onFirst.force + ab.onSecond.force).norm(), 1e-12 * scale);
  EXPECT_LT((ab.onFirst.force - ba.onSecond.force).norm(), 0.01 * scale);
  ASSERT_GT(ab.contacts.size(), 3u);
  Vector3r listed = Vector3r::Zero();
  for (const TriangleContact& c : ab.contacts) listed += c.load.force * c.normal;
  EXPECT_LT((listed - ab.onSecond.force).norm(), 1e-12 * scale);
}

TEST(PairEvaluation, BadMaterialIsRefusedByName) {
  const BodyMesh mesh(icosphere(0.025, 1));
  HertzMaterial bad = kRubber;
  bad.young = -1;
  try {
    sphereContact(roundedBody(0, mesh, kRubber), at(Vector3r::Zero()), Sphere{0.01}, at(Vector3r(0, 0, 0.03)), bad,
                  EngineOptions());
    FAIL() << "a negative modulus was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("young"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace roundedmesh
