// The stages of a contact step that StopRulesTest does not cover (ContactStep.hpp): the time-step check (1), which
// computes nothing above the limit and checks again when the time step or a mass changes, and the report of a kept
// step (7): the energies summed over the pairs, the pairs that start deeper than a Hertz contact (first step only)
// and the fastest body; and which pairs a process computes under YADE's MPI decomposition.
#include <gtest/gtest.h>

#include <tuple>
#include <utility>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kRubber{1e6, 0.4, 2000, 1e-3};
const Real kRadius = 0.025;

// Two 162-node balls, the second `overlap` [m] into the first along z, with their masses and inertias.
struct TwoBalls {
  explicit TwoBalls(Real overlap) {
    static const BodyMesh mesh(icosphere(kRadius, 2));
    for (int id : {0, 1}) model.bodies.push_back(roundedBody(id, mesh, kRubber));
    data.resize(model);
    data.bodyStates[0] = at(Vector3r::Zero());
    data.bodyStates[1] = at(Vector3r(0, 0, 2 * kRadius - overlap));
    for (int b : {0, 1}) {
      data.bodyMasses[b] = kRubber.density * mesh.volume();
      data.bodyInertias[b] = kRubber.density * mesh.principalMoments();
    }
  }
  Real limit() const {
    return stabilityLimit(model, data.bodyMasses, data.partnerMasses, data.bodyInertias, data.partnerInertias).timeStep;
  }
  ContactModel model;
  ContactData data;
};

TEST(ContactStep, AStepAboveTheStabilityLimitComputesNothing) {
  TwoBalls scene(1e-4);
  scene.data.timeStep = 1.01 * scene.limit();
  const StepReport above = contactStep(scene.model, scene.data);
  ASSERT_TRUE(above.unstable);
  EXPECT_EQ(above.unstable->timeStep, scene.limit());
  EXPECT_FALSE(above.kept());
  EXPECT_TRUE(scene.data.pairs.empty());
  EXPECT_TRUE(scene.data.bodyWrenches[0].force.isZero(0));
  EXPECT_FALSE(scene.data.kept);

  scene.data.timeStep = 0.99 * scene.limit();
  const StepReport within = contactStep(scene.model, scene.data);
  EXPECT_TRUE(within.kept());
  EXPECT_LT(scene.data.bodyWrenches[0].force.z(), 0);  // pushed away from the other ball

  // The limit itself, and the limit's rounding in another process (a restored mesh), are within it.
  scene.data.timeStep = (1 + 1e-12) * scene.limit();
  EXPECT_TRUE(contactStep(scene.model, scene.data).kept());
  scene.data.timeStep = (1 + 1e-7) * scene.limit();
  EXPECT_TRUE(contactStep(scene.model, scene.data).unstable);
  scene.data.timeStep = 0.99 * scene.limit();

  // A lighter body lowers the limit: checked again, with the same time step.
  scene.data.bodyMasses[1] *= 0.5;
  const StepReport lighter = contactStep(scene.model, scene.data);
  ASSERT_TRUE(lighter.unstable);
  EXPECT_LT(lighter.unstable->timeStep, scene.data.timeStep);
}

TEST(ContactStep, TheReportSumsTheEnergiesAndNamesDeepStartsOnce) {
  const Real size = kRadius;  // the icosphere's volume-equivalent radius is within 1 % of it
  TwoBalls scene(0.15 * size);
  const StepReport first = contactStep(scene.model, scene.data);
  ASSERT_TRUE(first.kept());
  ASSERT_EQ(first.deepStarts.size(), 1u);
  EXPECT_EQ(first.deepStarts[0].body, 0);
  EXPECT_EQ(first.deepStarts[0].other, 1);
  EXPECT_NEAR(first.deepStarts[0].overlap, 0.15 * size, 0.02 * size);
  EXPECT_EQ(first.deepStarts[0].size, scene.model.bodies[0].equivalentRadius);
  const PairSummary& pair = scene.data.pairResults[0].summary;
  EXPECT_EQ(first.energy.elastic, pair.elasticEnergy);
  EXPECT_GT(first.energy.elastic, 0);
  EXPECT_TRUE(contactStep(scene.model, scene.data).deepStarts.empty());  // warned of once

  // Two contact depths per step: reported, with the impact time step for its speed (a tenth of the Hertz depth
  // per step at most, CriticalTimeStep.hpp).
  scene.data.timeStep = 0.5 * scene.limit();
  const Real speed = 2 * kDeepestOverlap * scene.model.bodies[1].equivalentRadius / scene.data.timeStep;
  scene.data.bodyStates[1].velocity = speed * Vector3r(0, 0.6, -0.8);
  const StepReport moving = contactStep(scene.model, scene.data);
  ASSERT_TRUE(moving.kept());
  EXPECT_EQ(moving.fastest.body, 1);
  EXPECT_NEAR(moving.fastest.speed, speed, 1e-12 * speed);
  EXPECT_NEAR(moving.fastest.fraction, 2, 1e-12);
  EXPECT_DOUBLE_EQ(moving.fastest.depth, kDeepestOverlap * scene.model.bodies[1].equivalentRadius);
  EXPECT_GT(moving.fastTimeStep, 0);
  EXPECT_LE(moving.fastTimeStep, 0.05 * scene.data.timeStep * (1 + 1e-12));
}

// Under YADE's MPI decomposition (ContactData::residences): a pair is computed where one side is this process's own
// and neither is absent; its wrench applies to Own and Master bodies; a pair with another worker's body (an Image),
// computed on both workers, gives each half its energy; the fastest body is among the process's own.
TEST(ContactStep, AProcessComputesThePairsOfItsOwnBodiesOnly) {
  auto stepAs = [](Residence body, Residence other) {
    TwoBalls scene(1e-3);
    scene.data.residences = {body, other};
    scene.data.timeStep = 0.5 * scene.limit();
    scene.data.bodyStates[0].velocity = Vector3r(0, 0, 0.01);
    scene.data.bodyStates[1].velocity = Vector3r(0, 0, -0.1);  // the fastest, where it is reported
    const StepReport report = contactStep(scene.model, scene.data);
    EXPECT_TRUE(report.kept());
    return std::make_tuple(scene.data.pairs.size(), report, std::move(scene.data));
  };
  const auto [wholePairs, whole, wholeData] = stepAs(Residence::Own, Residence::Own);  // one process
  ASSERT_EQ(wholePairs, 1u);
  ASSERT_GT(whole.energy.elastic, 0);
  EXPECT_EQ(whole.fastest.body, 1);
  const Wrench onBody = wholeData.bodyWrenches[0], onOther = wholeData.bodyWrenches[1];
  const auto [ownImagePairs, ownImage, ownImageData] = stepAs(Residence::Own, Residence::Image);
  ASSERT_EQ(ownImagePairs, 1u);
  EXPECT_EQ(ownImageData.bodyWrenches[0].force, onBody.force);  // the same pair, the same operations
  EXPECT_EQ(ownImageData.bodyWrenches[1].force, onOther.force);
  EXPECT_TRUE(ownImageData.appliesWrench(0) && !ownImageData.appliesWrench(1));
  EXPECT_EQ(ownImage.energy.elastic, 0.5 * whole.energy.elastic);
  EXPECT_EQ(ownImage.fastest.body, 0);  // body 1 moves faster, but another process reports it

  const auto [masterPairs, master, masterData] = stepAs(Residence::Master, Residence::Own);
  ASSERT_EQ(masterPairs, 1u);
  EXPECT_TRUE(masterData.appliesWrench(0) && masterData.appliesWrench(1));
  EXPECT_EQ(master.energy.elastic, whole.energy.elastic);  // computed here alone
  EXPECT_EQ(master.fastest.body, 1);

  for (auto [body, other] : {std::pair{Residence::Image, Residence::Image}, std::pair{Residence::Own, Residence::Absent},
                             std::pair{Residence::Master, Residence::Image}}) {
    const auto [pairs, report, data] = stepAs(body, other);
    EXPECT_EQ(pairs, 0u);
    EXPECT_EQ(report.energy.elastic, 0);
    EXPECT_TRUE(data.bodyWrenches[0].force.isZero(0) && data.bodyWrenches[1].force.isZero(0));
  }
}

}  // namespace
}  // namespace roundedmesh
