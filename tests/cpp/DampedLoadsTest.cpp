// The damping and the node forces in lanes (DampedLoads.hpp) are dampedLoad's and nodeForces' bit for bit, on every
// instruction set the processor has and the build compiled:
//   - the triangle contacts of random body pairs of the library (grazing to deep, moving at up to 1 m/s and 10 rad/s),
//     their elastic loads in batches of 1 to 16, for the paper's circles and the principal curvatures' ellipses, the
//     quadrature and exact regimes, and a damping A from none to large enough that separating contacts lose all
//     pressure (Eq. 7's factor clamped at zero);
//   - made-up loads at the edges: zero and negative forces, NaN and infinite ones, a triangle edge-on (no area), a
//     centre of pressure outside the triangle (a weight clamped at zero);
// the node forces of the damping part alone (the energy law's) likewise, every other batch; and the engine's pair
// load gives each contact that load and those node forces (pairLoad's listing). No tolerance:
// the lanes run the reference's operations in its order.
#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "hwy/targets.h"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/law/DampedLoads.hpp"
#include "pkg/law/NodeForces.hpp"
#include "pkg/law/PairLaw.hpp"
#include "pkg/math/DiskPolygonBatch.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

using test::sameBits;

struct Tally {
  long lanes = 0, clamped = 0, unloaded = 0, edgeOn = 0, weightClamped = 0, dampingParts = 0;
};

// Every field of a NormalLoad bit for bit (the regime equal), naming the first that differs.
::testing::AssertionResult sameLoad(const NormalLoad& got, const NormalLoad& expected) {
  if (!sameBits(got.force, expected.force))
    return ::testing::AssertionFailure() << "force " << got.force << " against " << expected.force;
  if (!sameBits(got.moment, expected.moment)) return ::testing::AssertionFailure() << "moment";
  if (got.regime != expected.regime) return ::testing::AssertionFailure() << "regime";
  if (!sameBits(got.elasticForce, expected.elasticForce)) return ::testing::AssertionFailure() << "elastic force";
  if (!sameBits(got.elasticMoment, expected.elasticMoment)) return ::testing::AssertionFailure() << "elastic moment";
  if (!sameBits(got.overlapRate, expected.overlapRate)) return ::testing::AssertionFailure() << "approach rate";
  if (!sameBits(got.elasticEnergy, expected.elasticEnergy)) return ::testing::AssertionFailure() << "elastic energy";
  return ::testing::AssertionSuccess();
}

// Each lane of `batch` (filled from `elastic` and `geoms`) against dampedLoad and nodeForces, of the damped load and
// (every other batch) of its damping part.
void checkBatch(const std::vector<NormalLoad>& elastic, const std::vector<PressureGeom>& geoms, const HertzPhys& phys,
                const std::string& where, Tally& tally) {
  DampedLoads batch;
  batch.damping = phys.damping;
  int batches = 0;
  const int count = static_cast<int>(geoms.size());
  for (int first = 0, size = 1; first < count; first += size, size = size % DampedLoads::kCapacity + 1) {
    batch.size = std::min(size, count - first);
    batch.withDamping = ++batches % 2 == 0;
    for (int k = 0; k < batch.size; ++k) batch.set(k, elastic[first + k], geoms[first + k]);
    dampLoads(batch);
    for (int k = 0; k < batch.size; ++k) {
      const std::string at = where + ", contact " + std::to_string(first + k);
      const NormalLoad expected = dampedLoad(elastic[first + k], geoms[first + k], phys);
      const NormalLoad lanes = batch.load(k);
      ASSERT_TRUE(sameLoad(lanes, expected)) << at;
      const std::array<Real, 3> forces = nodeForces(geoms[first + k].nodes, expected);
      ASSERT_TRUE(sameBits(batch.nodeForces(k), forces)) << at;
      if (batch.withDamping) {
        const NormalLoad damping{expected.force - expected.elasticForce, expected.moment - expected.elasticMoment,
                                 expected.regime};
        ASSERT_TRUE(sameBits(batch.dampingNodeForces(k), nodeForces(geoms[first + k].nodes, damping))) << at;
        ++tally.dampingParts;
      }
      ++tally.lanes;
      tally.clamped += expected.elasticForce > 0 && expected.force == 0;
      tally.unloaded += expected.force == 0 || !std::isfinite(expected.force);
    }
  }
}

TEST(DampedLoads, EveryLaneOfLibraryContactsIsTheReferenceBitForBit) {
  test::forEachInstructionSet([&](int64_t target) {
    test::RandomSource random(3511);
    test::BodyLibrary library(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
    Tally tally;
    long exact = 0, elliptical = 0;
    for (int bodyPair = 0; bodyPair < 400 && !::testing::Test::HasFatalFailure(); ++bodyPair) {
      test::BodyPairCase c = test::randomBodyPair(random, library);
      PressureOptions& options = c.model.options.pressure;
      options.regime = bodyPair % 3 == 2 ? RegimeChoice::Exact : RegimeChoice::Auto;
      options.curvature = bodyPair % 4 == 3 ? CurvatureModel::Principal : CurvatureModel::Mean;
      std::vector<PressureGeom> geoms;
      ContactStatistics statistics;
      pairGeometry(c.model, c.data, {0, 1}, geoms, statistics);
      HertzPhys phys = PairLaw(c.model.bodies[0].material, c.model.bodies[1].material, options,
                               c.model.options.friction).phys;
      // A from none to 10 s: at 1 m/s the largest makes any separating contact shallower than 10 m lose its pressure.
      phys.damping = bodyPair % 5 == 0 ? 0 : std::exp(random.uniform(std::log(1e-6), std::log(10.0)));
      std::vector<NormalLoad> elastic;
      for (const PressureGeom& geom : geoms) {
        elastic.push_back(elasticLoad(geom, phys, options));
        exact += elastic.back().regime == Regime::Exact;
        elliptical += geom.elliptical;
      }
      checkBatch(elastic, geoms, phys, "body pair " + std::to_string(bodyPair), tally);
    }
    EXPECT_GT(tally.lanes, 3000);
    EXPECT_GT(tally.clamped, 100);
    EXPECT_GT(tally.dampingParts, 1000);
    EXPECT_GT(exact, 500);
    EXPECT_GT(elliptical, 300);
    std::cout << hwy::TargetName(target) << ": " << tally.lanes << " contacts, " << exact << " exact, " << elliptical
              << " elliptical, " << tally.clamped << " whose damping took all pressure\n";
  });
}

TEST(DampedLoads, EveryLaneOfLoadsAtTheEdgesIsTheReferenceBitForBit) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  const std::vector<Real> forces = {0.0, -0.0, 1.5, -2.0, nan, inf, -inf, 1e-300, 3e300};
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(77);
    const HertzPhys phys{1e6, 1e-3};
    std::vector<PressureGeom> geoms;
    std::vector<NormalLoad> elastic;
    Tally tally;
    for (int trial = 0; trial < 2000; ++trial) {
      PressureGeom geom;
      for (Vector2r& node : geom.nodes) node = Vector2r(random.uniform(-1, 1), random.uniform(-1, 1));
      if (trial % 7 == 0) geom.nodes = {geom.nodes[0], geom.nodes[0], geom.nodes[0]};  // edge-on: no area
      geom.overlapRate = random.uniform(-2, 2);
      geom.overlapRateSlope = Vector2r(random.uniform(-5, 5), random.uniform(-5, 5));
      geom.sphereOverlap = std::exp(random.uniform(std::log(1e-9), std::log(1e-2)));
      const Real force = trial % 3 == 0 ? forces[trial / 3 % forces.size()] : random.uniform(0, 10);
      // A centre of pressure anywhere within twice the triangles' reach: outside the triangle some of the time.
      const Vector2r centre(random.uniform(-2, 2), random.uniform(-2, 2));
      elastic.push_back({force, force * Vector2r(centre.y(), -centre.x()), Regime::Quadrature});
      geoms.push_back(geom);
      const Real twiceArea = cross2(geom.nodes[1] - geom.nodes[0], geom.nodes[2] - geom.nodes[0]);
      // Counted where Eq. 15 runs at all: a damped force finite and other than zero (the damping scales the force and
      // the moment alike, and leaves the centre where it is).
      const Real damped = dampedLoad(elastic.back(), geom, phys).force;
      const bool loaded = damped != 0 && std::isfinite(damped);
      tally.edgeOn += loaded && twiceArea == 0;
      tally.weightClamped += loaded && twiceArea != 0 &&
                             !ConvexPolygon::triangle(geom.nodes[0], geom.nodes[1], geom.nodes[2]).contains(centre);
    }
    checkBatch(elastic, geoms, phys, "made-up loads", tally);
    EXPECT_EQ(tally.lanes, 2000);
    EXPECT_GT(tally.dampingParts, 600);
    EXPECT_GT(tally.unloaded, 300);
    EXPECT_GT(tally.edgeOn, 80);
    EXPECT_GT(tally.weightClamped, 700);
  });
}

// The engine's wiring: pairLoad lists each contact with Law2's load and Eq. 15's node forces (its own triangle's and
// its partner's), on the processor's own instruction set, under both normal laws, for pairs of more contacts than a
// batch holds too. Under the energy law and in the exact regime (on ellipses too) Law2 integrates in closed form, in
// lanes (DiskPolygonBatch.hpp, against the scalar closed forms in DiskPolygonBatchTest): each contact's load is its
// lane's, whichever lane of a batch it had.
TEST(DampedLoads, PairLoadGivesEachContactLaw2sLoadAndNodeForces) {
  test::RandomSource random(902);
  test::BodyLibrary library(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
  long contacts = 0, energyLaw = 0, exactEllipses = 0;
  size_t most = 0;
  for (int bodyPair = 0; bodyPair < 150; ++bodyPair) {
    test::BodyPairCase c = test::randomBodyPair(random, library);
    // The paper's law, the energy law, and the paper's law in the exact regime on the principal curvatures' ellipses.
    if (bodyPair % 3 == 1) c.model.options.pressure.normal = NormalLaw::Energy;
    if (bodyPair % 3 == 2) {
      c.model.options.pressure.regime = RegimeChoice::Exact;
      c.model.options.pressure.curvature = CurvatureModel::Principal;
    }
    std::vector<PressureGeom> geoms;
    ContactStatistics statistics;
    pairGeometry(c.model, c.data, {0, 1}, geoms, statistics);
    std::vector<TriangleContact> listed;
    pairLoad(c.model, c.data, {0, 1}, geoms, &listed);
    ASSERT_EQ(listed.size(), geoms.size());
    const PairLaw law(c.model.bodies[0].material, c.model.bodies[1].material, c.model.options.pressure,
                      c.model.options.friction);
    for (size_t k = 0; k < geoms.size(); ++k) {
      // The energy law's loads are integrated in closed form in lanes: a batch of this contact alone gives its lane's.
      DiskPolygonBatch alone;
      alone.add(geoms[k].contactRadius, circlePolygon(geoms[k]));
      integrateDiskPolygons(alone);
      const NormalLoad expected =
          law.integratesExactly()
              ? dampedLoad(law.exactLoad(alone.integrals(0), geoms[k]), geoms[k], law.phys)
              : Law2_PressureGeom_HertzPhys_IntegratedPressure(geoms[k], law.phys, law.pressure);
      const std::string at = "body pair " + std::to_string(bodyPair) + ", contact " + std::to_string(k);
      ASSERT_TRUE(sameLoad(listed[k].load, expected)) << at;
      ASSERT_TRUE(sameBits(listed[k].nodeForces, nodeForces(geoms[k].nodes, expected))) << at;
      if (geoms[k].partnerTriangle >= 0) {
        ASSERT_TRUE(sameBits(listed[k].partnerNodeForces, nodeForces(geoms[k].partnerNodes, expected))) << at;
      }
      ++contacts;
      energyLaw += bodyPair % 3 == 1;
      exactEllipses += bodyPair % 3 == 2 && geoms[k].elliptical;
    }
    most = std::max(most, geoms.size());
  }
  EXPECT_GT(contacts, 1000);
  EXPECT_GT(energyLaw, 300);
  EXPECT_GT(exactEllipses, 100);
  EXPECT_GT(most, 2 * static_cast<size_t>(DampedLoads::kCapacity));  // a pair that fills two batches and more
}

}  // namespace
}  // namespace roundedmesh
