// The engine on scene S1 as recorded (bench/data: 250 gummy bears settled, then shaken): with its lists kept
// between steps it finds, step after step, exactly the triangle contacts that a brute-force search over every
// triangle pair finds with the same criterion (Appendix B's tests; past kDeepestOverlap of the smaller body, both
// caps reaching into the other body), with the same forces; and it gives the same result on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <string>

#include "bench/RecordedScene.hpp"
#include "hwy/targets.h"
#include "pkg/bound/BatchedCandidates.hpp"
#include "pkg/bound/CapReach.hpp"
#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/engine/CandidateLists.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"
#include "tests/support/HighwayTargets.hpp"

namespace roundedmesh {
namespace {

const RecordedScene& scene() {
  static const RecordedScene loaded = loadRecordedScene();
  return loaded;
}

// Every triangle pair of two bodies tested, in the order (s, t).
std::vector<PressureGeom> bruteForce(const ContactModel& model, const ContactData& data, const BodyPair& pair) {
  const RoundedBody &a = model.bodies[pair.body], &b = model.bodies[pair.other];
  std::vector<TrianglePair> all;
  for (int s = 0; s < a.mesh->triangleCount(); ++s)
    for (int t = 0; t < b.mesh->triangleCount(); ++t) all.push_back({s, t});
  const BodyPairFrame frame = bodyPairFrame(model, data, pair);
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_RoundedMesh_PressureGeom(*a.mesh, *b.mesh, frame.rotation, frame.translation, all, frame.shallow,
                                           frame.motion, geoms);
  return geoms;
}

std::set<TrianglePair> triangles(const std::vector<PressureGeom>& geoms) {
  std::set<TrianglePair> found;
  for (const PressureGeom& g : geoms) found.insert({g.triangle, g.partnerTriangle});
  return found;
}

// Steps through the first 60 recorded steps of shaking; at steps 0, 20, 40 and 59 compares, for 12 pairs of
// bears in contact and 4 whose bounds overlap without contact, the engine's contacts with brute force.
// Forces: tolerance 1e-12 of the pair's force, the round-off of summing the same terms in another order.
TEST(RecordedScene, EngineFindsWhatBruteForceFinds) {
  const ContactModel& model = scene().model;
  ContactData data;
  int compared = 0, touching = 0;
  for (int step = 0; step < 60; ++step) {
    scene().setStates(data, scene().shaking, step);
    contactForces(model, data);
    if (step % 20 != 0 && step != 59) continue;
    int inContact = 0, apart = 0;
    for (size_t k = 0; k < data.pairs.size() && (inContact < 12 || apart < 4); k += 7) {
      const BodyPair& pair = data.pairs[k];
      if (pair.other >= static_cast<int>(model.bodies.size())) continue;
      std::vector<PressureGeom> engine;
      ContactStatistics statistics;
      pairGeometry(model, data, pair, engine, statistics, &data.candidateLists[pair.neighbour]);
      if (engine.empty() ? apart++ >= 4 : inContact++ >= 12) continue;
      const std::vector<PressureGeom> reference = bruteForce(model, data, pair);
      EXPECT_EQ(triangles(engine), triangles(reference)) << "step " << step << ", bodies " << pair.body << " and " << pair.other;
      const PairResult a = pairLoad(model, data, pair, engine), b = pairLoad(model, data, pair, reference);
      const Real scale = std::max(b.onBody.force.norm(), Real(1e-300));
      EXPECT_LT((a.onBody.force - b.onBody.force).norm(), 1e-12 * scale);
      EXPECT_LT((a.onBody.torque - b.onBody.torque).norm(), 1e-12 * scale * 0.1);
      ++compared;
      touching += !engine.empty();
    }
  }
  EXPECT_EQ(compared, 64);
  EXPECT_EQ(touching, 48);
}

// The same contacts and bitwise the same wrenches on 1 and 2 threads, over steps that rebuild lists.
TEST(RecordedScene, SameResultOnAnyNumberOfThreads) {
  std::vector<ContactData> runs(2);
  for (int n = 1; n <= 2; ++n) {
    ContactModel model = scene().model;
    model.options.threads = n;
    for (int step = 0; step < 10; ++step) {
      scene().setStates(runs[n - 1], scene().shaking, step);
      contactForces(model, runs[n - 1]);
    }
  }
  ASSERT_GT(runs[0].statistics.contacts(), 20000);
  EXPECT_EQ(runs[0].statistics.contacts(), runs[1].statistics.contacts());
  for (size_t b = 0; b < runs[0].bodyWrenches.size(); ++b) {
    EXPECT_EQ(runs[0].bodyWrenches[b].force, runs[1].bodyWrenches[b].force);
    EXPECT_EQ(runs[0].bodyWrenches[b].torque, runs[1].bodyWrenches[b].torque);
  }
}

// The engine's candidate lists, taken from the near lists in batches, are the reference's pair for pair: every list
// of the first 10 recorded steps of shaking and 3 of the landing window (pairs past the Hertz range, whose lists are as
// deep as the bodies), at the pose and for the skin and depth it was built with; and the batches leave few of them
// to the reference's test.
TEST(RecordedScene, BatchedListsAreTheReferenceLists) {
  const ContactModel& model = scene().model;
  long lists = 0, candidates = 0, deepLists = 0, scanned = 0, undecided = 0;
  for (const auto& [trajectory, steps] : {std::pair(&scene().shaking, 10), std::pair(&scene().landing, 3)}) {
    ContactData data;
    for (int step = 0; step < steps; ++step) {
      scene().setStates(data, *trajectory, step);
      contactForces(model, data);
      for (size_t n = 0; n < data.neighbours.size(); ++n) {
        const CandidateList& list = data.candidateLists[n];
        const BodyPair& pair = data.neighbours[n];
        if (!list.built || list.age != 0 || pair.other >= static_cast<int>(model.bodies.size())) continue;
        const RoundedMesh &mesh1 = *model.bodies[pair.body].mesh, &mesh2 = *model.bodies[pair.other].mesh;
        std::vector<TrianglePair> reference;
        touchableTrianglePairs(mesh1, mesh2, list.rotation.toRotationMatrix(), list.translation, list.skin, list.depth,
                               list.near, reference);
        ASSERT_EQ(list.pairs, reference) << "step " << step << ", pair " << pair.body << "-" << pair.other;
        std::vector<TrianglePair> batched;
        undecided += static_cast<long>(touchableTrianglePairsBatched(mesh1, mesh2, list.rotation.toRotationMatrix(),
                                                                     list.translation, list.skin, list.depth, list.near,
                                                                     batched));
        scanned += static_cast<long>(list.near.size());
        ++lists;
        candidates += static_cast<long>(reference.size());
        if (list.deepest > kDeepestOverlap * model.bodies[pair.body].equivalentRadius) ++deepLists;
      }
    }
  }
  EXPECT_GT(lists, 5000);  // about 450 rebuilt per step shaking, more landing
  EXPECT_GT(candidates, 100000);
  EXPECT_GT(deepLists, 10);
  // The batches decide nearly every pair themselves (2 of 5.3 million left to the reference's test here): a pair the
  // reference decides costs about 12 times as much.
  EXPECT_LT(undecided, 1e-4 * scanned);
}

// nearTrianglePairs as it was before its batches (each pair of the trees through passesFilters2to4 as the search meets
// it, a deep pair's shell of box pairs compared one pair at a time, and those through touchableTrianglePairs).
std::vector<TrianglePair> nearPairsOneAtATime(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation, Real skin,
                                              Real depth, Real shallow) {
  std::vector<TrianglePair> pairs;
  const Matrix3r back = rotation.transpose();
  const Vector3r backTranslation = -(back * translation);
  auto reaches1 = [&](int s) { return capReaches(mesh1, s, PlacedMesh{mesh2, rotation, translation}, 2 * skin); };
  auto reaches2 = [&](int t) { return capReaches(mesh2, t, PlacedMesh{mesh1, back, backTranslation}, 2 * skin); };
  auto nearer = [&](int t) { return transformedBox(mesh2.tree().triangleBox(t), rotation, translation, shallow + skin); };
  if (depth <= 2 * shallow) {
    TriangleTree::queryPairs(mesh1.tree(), mesh2.tree(), rotation, translation, depth + skin, [&](int s, int t) {
      if (!passesFilters2to4(mesh1, s, mesh2, t, rotation, translation, skin, depth + skin)) return;
      const bool onlyDeep = depth > shallow && !mesh1.tree().triangleBox(s).intersects(nearer(t));
      if (!onlyDeep || (reaches1(s) && reaches2(t))) pairs.push_back({s, t});
    });
    return pairs;
  }
  TriangleTree::queryPairs(mesh1.tree(), mesh2.tree(), rotation, translation, shallow + skin, [&](int s, int t) {
    if (passesFilters2to4(mesh1, s, mesh2, t, rotation, translation, skin, depth + skin)) pairs.push_back({s, t});
  });
  std::vector<TrianglePair> shell, touchable;
  for (int t = 0; t < mesh2.triangleCount(); ++t) {
    if (!reaches2(t)) continue;
    const AlignedBox3r within = transformedBox(mesh2.tree().triangleBox(t), rotation, translation, depth + skin);
    for (int s = 0; s < mesh1.triangleCount(); ++s) {
      const AlignedBox3r& box1 = mesh1.tree().triangleBox(s);
      if (reaches1(s) && box1.intersects(within) && !box1.intersects(nearer(t))) shell.push_back({s, t});
    }
  }
  touchableTrianglePairs(mesh1, mesh2, rotation, translation, skin, depth, shell, touchable);
  pairs.insert(pairs.end(), touchable.begin(), touchable.end());
  return pairs;
}

// The near searches of every body pair's list in the settled packing and at a step of the landing window (lists as
// deep as the bodies among them), at the pose, skin and depth each near list was built with, and again with every
// list at twice and at three times its depth (between the Hertz range and twice it; past twice it): the batched search
// gives the lists of the search one pair at a time, pair for pair and in the same order.
TEST(RecordedScene, NearSearchIsTheSearchOnePairAtATime) {
  const ContactModel& model = scene().model;
  const int bodyCount = static_cast<int>(model.bodies.size());
  long searches = 0, nearPairs = 0, deep = 0;
  for (int frame = 0; frame < 2; ++frame) {
    ContactData data;
    if (frame == 0)
      scene().setStates(data);
    else
      scene().setStates(data, scene().landing, 10);
    contactForces(model, data);
    for (size_t n = 0; n < data.neighbours.size(); ++n) {
      const CandidateList& list = data.candidateLists[n];
      const BodyPair& pair = data.neighbours[n];
      if (!(list.nearSkin > 0) || pair.other >= bodyCount) continue;
      const RoundedBody &body = model.bodies[pair.body], &other = model.bodies[pair.other];
      const Real shallow = kDeepestOverlap * std::min(body.equivalentRadius, other.equivalentRadius);
      const Matrix3r rotation = list.nearRotation.toRotationMatrix();
      // Every 20th list also deeper, into the other two branches of the search.
      for (const Real scale : {1.0, 2.0, 3.0}) {
        if (scale > 1 && n % 20 != 0) continue;
        const Real depth = scale == 1 ? list.nearDepth : std::max(list.nearDepth, scale * shallow);
        std::vector<TrianglePair> batched;
        nearTrianglePairs(*body.mesh, *other.mesh, rotation, list.nearTranslation, list.nearSkin, depth, shallow, batched);
        ASSERT_EQ(batched, nearPairsOneAtATime(*body.mesh, *other.mesh, rotation, list.nearTranslation, list.nearSkin,
                                               depth, shallow))
            << "frame " << frame << ", pair " << pair.body << "-" << pair.other << ", depth " << depth;
        ++searches;
        nearPairs += static_cast<long>(batched.size());
        deep += depth > 2 * shallow;
      }
    }
  }
  EXPECT_GT(searches, 4000);
  EXPECT_GT(nearPairs, 1000000);
  EXPECT_GT(deep, 200);
}

// The narrow phase clips the polygons S of a pair's candidates in lanes where the vector unit is wide enough for that
// to pay (TriangleIntersections.hpp: 4 doubles or more, AVX2 and AVX-512), one candidate at a time elsewhere; both ways give the same triangle
// contacts bit for bit. Every body pair's candidates in the settled packing and at two steps of the landing window
// (deep pairs) go through Ig2 both ways, on each instruction set the processor has, with the paper's circles and with
// the principal curvatures' ellipses: every contact's geometry and the funnel's counts must be those of one candidate
// at a time on the processor's own instruction set.
bool sameGeometry(const PressureGeom& a, const PressureGeom& b) {
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof(x)) == 0; };
  bool equal = a.triangle == b.triangle && a.partnerTriangle == b.partnerTriangle && same(a.centre, b.centre) &&
               same(a.normal, b.normal) && same(a.tangent1, b.tangent1) && same(a.tangent2, b.tangent2) &&
               same(a.radius, b.radius) && same(a.sphereOverlap, b.sphereOverlap) && same(a.overlapRate, b.overlapRate) &&
               same(a.overlapRateSlope, b.overlapRateSlope) && same(a.contactRadius, b.contactRadius) &&
               same(a.nodes, b.nodes) && same(a.partnerNodes, b.partnerNodes) && same(a.effectivePoint, b.effectivePoint) &&
               same(a.effectiveOverlap, b.effectiveOverlap) && same(a.slip, b.slip) && a.elliptical == b.elliptical &&
               same(a.ellipseCentre, b.ellipseCentre) && same(a.toCircle, b.toCircle) &&
               a.polygon.size() == b.polygon.size();
  for (int i = 0; equal && i < a.polygon.size(); ++i) equal = same(a.polygon[i], b.polygon[i]);
  return equal;
}

bool sameCounts(const NarrowPhaseCounts& a, const NarrowPhaseCounts& b) {
  return a.candidates == b.candidates && a.notFacing == b.notFacing && a.noOverlap == b.noOverlap &&
         a.outsideCircle == b.outsideCircle && a.emptyPolygon == b.emptyPolygon &&
         a.beyondContactCircle == b.beyondContactCircle && a.throughBody == b.throughBody;
}

TEST(RecordedScene, NarrowPhaseInLanesIsOneAtATimeBitForBit) {
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  const ContactModel& model = scene().model;
  const int bodyCount = static_cast<int>(model.bodies.size());
  long contacts = 0, elliptical = 0;
  for (int frame = 0; frame < 3; ++frame) {
    ContactData data;
    if (frame == 0) {
      scene().setStates(data);
    } else {
      scene().setStates(data, scene().landing, frame);
    }
    contactForces(model, data);
    for (const BodyPair& pair : data.pairs) {
      if (pair.other >= bodyCount) continue;
      const CandidateList& list = data.candidateLists[pair.neighbour];
      const RoundedBody &a = model.bodies[pair.body], &b = model.bodies[pair.other];
      const BodyPairFrame placed = bodyPairFrame(model, data, pair);
      for (const CurvatureModel curvature : {CurvatureModel::Mean, CurvatureModel::Principal}) {
        auto narrowPhase = [&](PolygonLanes lanes, std::vector<PressureGeom>& geoms, NarrowPhaseCounts& counts) {
          Ig2_RoundedMesh_RoundedMesh_PressureGeom(*a.mesh, *b.mesh, placed.rotation, placed.translation, list.pairs,
                                                   placed.shallow, placed.motion, GeomOutput(geoms, &counts), curvature,
                                                   lanes);
        };
        std::vector<PressureGeom> reference;
        NarrowPhaseCounts referenceCounts;
        narrowPhase(PolygonLanes::Never, reference, referenceCounts);
        for (const int64_t target : targets) {
          const test::TargetForTest chosen(target);
          for (const PolygonLanes lanes : {PolygonLanes::Always, PolygonLanes::Never}) {
            std::vector<PressureGeom> geoms;
            NarrowPhaseCounts counts;
            narrowPhase(lanes, geoms, counts);
            const std::string where = std::string(hwy::TargetName(target)) +
                                      (lanes == PolygonLanes::Always ? " in lanes" : " one at a time") + ", bodies " +
                                      std::to_string(pair.body) + "-" + std::to_string(pair.other);
            ASSERT_TRUE(sameCounts(counts, referenceCounts)) << where;
            ASSERT_EQ(geoms.size(), reference.size()) << where;
            for (size_t g = 0; g < geoms.size(); ++g)
              ASSERT_TRUE(sameGeometry(geoms[g], reference[g])) << where << ", contact " << g;
          }
        }
        contacts += static_cast<long>(reference.size());
        for (const PressureGeom& geom : reference) elliptical += geom.elliptical;
      }
    }
  }
  EXPECT_GT(contacts, 100000);
  EXPECT_GT(elliptical, 10000);  // the principal curvatures' pass meets ellipses
}

// timing = 'stages' measures the stages inside the pairs and changes nothing else. On one thread the stages lie
// inside the pairs stage, read by another clock: their sum stays below its wall time, up to 50 microseconds of the
// two clocks' disagreement and the pair loop's own work.
TEST(RecordedScene, TimingTheStagesChangesNothing) {
  ContactModel untimed = scene().model;
  untimed.options.threads = 1;
  ContactModel timed = untimed;
  timed.options.timing = Timing::Stages;
  ContactData plain, measured;
  for (int step = 0; step < 4; ++step) {
    scene().setStates(plain, scene().shaking, step);
    scene().setStates(measured, scene().shaking, step);
    contactForces(untimed, plain);
    contactForces(timed, measured);
    const PairStageTimes& none = plain.statistics.cpu;
    EXPECT_EQ(none.lists + none.nearSearch + none.narrowPhase + none.law + none.core, 0);
    const PairStageTimes& cpu = measured.statistics.cpu;
    EXPECT_GT(cpu.narrowPhase, 0);
    EXPECT_GT(cpu.law, 0);
    EXPECT_GE(cpu.lists, cpu.nearSearch);
    EXPECT_LE(cpu.lists + cpu.narrowPhase + cpu.law + cpu.core, measured.times.pairs + 50e-6) << step;
    EXPECT_EQ(plain.statistics.nearPairsScanned, measured.statistics.nearPairsScanned);
    EXPECT_EQ(plain.statistics.contacts(), measured.statistics.contacts());
    for (size_t b = 0; b < plain.bodyWrenches.size(); ++b) {
      EXPECT_EQ(plain.bodyWrenches[b].force, measured.bodyWrenches[b].force);
      EXPECT_EQ(plain.bodyWrenches[b].torque, measured.bodyWrenches[b].torque);
    }
  }
  EXPECT_GT(measured.statistics.nearPairsScanned, 0);  // the shaking rebuilds lists every step
  EXPECT_GT(measured.statistics.cpu.lists, 0);
}

}  // namespace
}  // namespace roundedmesh
