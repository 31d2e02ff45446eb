// The contact step: action and reaction, frame invariance, Walls and Boxes, broad phase, stability limit.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3, 0};
const HertzMaterial kBoxMaterial{5e6, 0.4, 2000, 1e-3, 0};

ContactModel sphereAgainst(PartnerShape shape, int subdivisions = 3, Real radius = 0.025) {
  const BodyMesh mesh(icosphere(radius, subdivisions));
  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, kRubber));
  model.partners.push_back({1, shape, kBoxMaterial});
  return model;
}

ContactData run(const ContactModel& model, const BodyState& body, const BodyState& partner = BodyState()) {
  ContactData data;
  data.resize(model);
  data.bodyStates[0] = body;
  data.partnerStates[0] = partner;
  contactForces(model, data);
  return data;
}

BodyState at(const Vector3r& position, const Quaternionr& orientation = Quaternionr::Identity()) {
  BodyState s;
  s.position = position;
  s.orientation = orientation;
  return s;
}

// Newton's third law for the whole pair: forces cancel, and so do torques about a common point.
// Tolerance: round-off relative to the force and lever sizes.
TEST(ContactForces, ActionEqualsReaction) {
  const ContactModel model = sphereAgainst(Box{Vector3r(0.2, 0.1, 0.05)});
  BodyState body = at(Vector3r(0.19, 0.05, 0.05 + 0.024), Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r::UnitY())));
  body.velocity = Vector3r(0.1, 0, -0.2);
  body.angularVelocity = Vector3r(1, 2, 3);
  BodyState box = at(Vector3r::Zero(), Quaternionr(Eigen::AngleAxis<Real>(0.05, Vector3r::UnitX())));
  box.velocity = Vector3r(0, 0, 0.3);
  const ContactData data = run(model, body, box);
  const Wrench &b = data.bodyWrenches[0], &p = data.partnerWrenches[0];
  ASSERT_GT(b.force.norm(), 0.1);
  EXPECT_LT((b.force + p.force).norm(), 1e-12 * b.force.norm());
  const Vector3r totalTorque = b.torque + body.position.cross(b.force) + p.torque + box.position.cross(p.force);
  EXPECT_LT(totalTorque.norm(), 1e-12 * b.force.norm() * 0.2);
}

// The same contact seen in a rotated and shifted global frame gives the rotated wrench.
TEST(ContactForces, IsFrameInvariant) {
  const Quaternionr q(Eigen::AngleAxis<Real>(1.1, Vector3r(1, 2, -1).normalized()));
  const Vector3r shift(3, -2, 1);
  const Quaternionr bodyOri(Eigen::AngleAxis<Real>(0.3, Vector3r::UnitZ()));
  const ContactData reference =
      run(sphereAgainst(Plane{Vector3r::Zero(), Vector3r::UnitZ()}), at(Vector3r(0.002, 0, 0.0235), bodyOri));
  const ContactData rotated = run(sphereAgainst(Plane{shift, q * Vector3r::UnitZ()}),
                                  at(shift + q * Vector3r(0.002, 0, 0.0235), q * bodyOri));
  EXPECT_TRUE(rotated.bodyWrenches[0].force.isApprox(q * reference.bodyWrenches[0].force, 1e-11));
  EXPECT_LT((rotated.bodyWrenches[0].torque - q * reference.bodyWrenches[0].torque).norm(),
            1e-11 * reference.bodyWrenches[0].force.norm() * 0.025);
}

// The engine's relative motion: a box turning about its own x axis at w lifts the point of its top face
// at distance y from that axis at w y, by hand; the contact then feels the same damping as with a box
// translating upward at w y. A body spinning about its own vertical axis adds nothing.
TEST(ContactForces, RelativeMotionIncludesBothBodiesRotation) {
  const ContactModel model = sphereAgainst(Box{Vector3r(0.2, 0.2, 0.05)});
  const Real w = 3.0, y = 0.08;
  const BodyState body = at(Vector3r(0, y, 0.05 + 0.0245));
  BodyState turning = at(Vector3r::Zero());
  turning.angularVelocity = Vector3r(w, 0, 0);
  BodyState rising = at(Vector3r::Zero());
  rising.velocity = Vector3r(0, 0, w * y);
  const Real turned = run(model, body, turning).bodyWrenches[0].force.z();
  const Real lifted = run(model, body, rising).bodyWrenches[0].force.z();
  const Real resting = run(model, body).bodyWrenches[0].force.z();
  EXPECT_GT(turned, 1.05 * resting);  // the damping term matters here
  EXPECT_NEAR(turned, lifted, 1e-12 * lifted);
  BodyState spinning = body;
  spinning.angularVelocity = Vector3r(0, 0, 40);
  EXPECT_NEAR(run(model, spinning).bodyWrenches[0].force.z(), resting, 1e-12 * resting);
}

// A YADE Wall is the plane through its position normal to its axis, on the side of the body (sense 0)
// or on the side it names.
TEST(ContactForces, WallActsAsThePlaneOnTheBodysSide) {
  const Vector3r wallPosition(0, 0, 0.5);
  const ContactData plane = run(sphereAgainst(Plane{wallPosition, -Vector3r::UnitZ()}), at(Vector3r(0, 0, 0.4765)));
  const ContactData wall = run(sphereAgainst(Wall{2, 0}), at(Vector3r(0, 0, 0.4765)), at(wallPosition));
  EXPECT_LT(plane.bodyWrenches[0].force.z(), -0.1);
  EXPECT_TRUE(wall.bodyWrenches[0].force.isApprox(plane.bodyWrenches[0].force, 1e-14));
  // sense +1: the solid lies on the negative side, so a body sunk into it is pushed back to the positive
  // side, as YADE's Ig2_Wall_Sphere_ScGeom does; beyond reach there is no contact.
  const ContactData sunk = run(sphereAgainst(Wall{2, 1}), at(Vector3r(0, 0, 0.4765)), at(wallPosition));
  EXPECT_GT(sunk.bodyWrenches[0].force.z(), 0);
  const ContactData beyond = run(sphereAgainst(Wall{2, 1}), at(Vector3r(0, 0, 0.474)), at(wallPosition));
  EXPECT_EQ(beyond.statistics.bodyPairs, 0);
}

// Far from its edges, a Box's face acts as the plane it lies in; near an edge the face is clipped and
// carries less.
TEST(ContactForces, BoxFaceActsAsAFinitePlane) {
  const Box box{Vector3r(0.2, 0.2, 0.05)};
  const Vector3r onTop(0.01, -0.02, 0.05 + 0.024);
  const ContactData plane = run(sphereAgainst(Plane{Vector3r(0, 0, 0.05), Vector3r::UnitZ()}), at(onTop));
  const ContactData face = run(sphereAgainst(box), at(onTop));
  EXPECT_GT(plane.bodyWrenches[0].force.z(), 0.1);
  EXPECT_TRUE(face.bodyWrenches[0].force.isApprox(plane.bodyWrenches[0].force, 1e-13));
  const ContactData edge = run(sphereAgainst(box), at(Vector3r(0.2, 0, 0.05 + 0.024)));
  EXPECT_LT(edge.bodyWrenches[0].force.z(), 0.7 * plane.bodyWrenches[0].force.z());
  EXPECT_GT(edge.bodyWrenches[0].force.z(), 0.3 * plane.bodyWrenches[0].force.z());
}

// A body whose centre has sunk into a Box is still pushed out through the face it is nearest to.
TEST(ContactForces, BodySunkIntoABoxIsPushedOutThroughTheNearestFace) {
  const ContactData data = run(sphereAgainst(Box{Vector3r(0.2, 0.2, 0.05)}), at(Vector3r(0, 0, 0.045)));
  EXPECT_GT(data.bodyWrenches[0].force.z(), 0);
  EXPECT_LT(std::abs(data.bodyWrenches[0].force.x()), 1e-9 * data.bodyWrenches[0].force.z());
}

TEST(ContactForces, BroadPhaseSkipsDistantPartners) {
  const ContactData far = run(sphereAgainst(Box{Vector3r(0.1, 0.1, 0.1)}), at(Vector3r(0, 0, 0.126)));
  EXPECT_EQ(far.statistics.bodyPairs, 0);
  EXPECT_TRUE(far.bodyWrenches[0].force.isZero(0));
  const ContactData near = run(sphereAgainst(Box{Vector3r(0.1, 0.1, 0.1)}), at(Vector3r(0, 0, 0.1249)));
  EXPECT_EQ(near.statistics.bodyPairs, 1);
}

// criticalTimeStep against the leap-frog's amplification matrix for the linearised contact
// x'' = -(k x + c v) / m with forces from x(t) and v(t - dt/2), as in YADE's NewtonIntegrator: its spectral
// radius crosses 1 at dt_crit.
TEST(CriticalTimeStep, IsTheLeapFrogStabilityLimitOfTheLinearisedContact) {
  const Real m = 0.13, E = 0.99e6, R = 0.025, overlap = 0.0025;
  for (Real A : {0.0, 1e-3, 1e-2, 0.1}) {
    const Real dtCrit = criticalTimeStep(m, E, R, A, overlap);
    const Real k = 2 * E * std::sqrt(R * overlap), c = 2.0 / 3 * A * k;
    auto spectralRadius = [&](Real dt) {
      Eigen::Matrix2d step;  // (v_{n-1/2}, x_n) -> (v_{n+1/2}, x_{n+1})
      step << 1 - c * dt / m, -k * dt / m, dt * (1 - c * dt / m), 1 - k * dt * dt / m;
      return step.eigenvalues().cwiseAbs().maxCoeff();
    };
    EXPECT_LE(spectralRadius(0.999 * dtCrit), 1 + 1e-12) << "A = " << A;
    EXPECT_GT(spectralRadius(1.001 * dtCrit), 1 + 1e-6) << "A = " << A;
  }
}

}  // namespace
}  // namespace roundedmesh
