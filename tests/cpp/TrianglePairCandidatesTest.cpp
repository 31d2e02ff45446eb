// The candidate lists' promise (TrianglePairCandidates.hpp): a list built at one pose for a skin and a depth holds
// every triangle pair in contact with an effective overlap of at most that depth, at every pose that moves no point
// of mesh 2 by more than the skin. Checked against brute force (Appendix B over every triangle pair) on pairs of gummy
// bears touching in S1's settled packing, moved to random poses at the skin's very edge, in the directions that
// strain the filters most: turns (the sphere centres of flat and concave triangles, 100 r_eq behind them, swing
// far on the slightest one) and slides; and on two of those pairs pushed past the Hertz range, whose lists hold every
// contact the bodies can have.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

#include "bench/RecordedScene.hpp"
#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/engine/CandidateLists.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {
namespace {

// Every pair of `all` in contact by Appendix B (and, past `shallow`, the deep-contact criterion, as the engine's lists
// promise) with an effective overlap of at most `depth`, and that overlap.
std::map<TrianglePair, Real> contactsWithin(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                            const Matrix3r& rotation, const Vector3r& translation,
                                            const std::vector<TrianglePair>& all, Real depth, Real shallow) {
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_RoundedMesh_PressureGeom(mesh1, mesh2, rotation, translation, all, shallow, RelativeMotion(), geoms);
  std::map<TrianglePair, Real> found;
  for (const PressureGeom& g : geoms)
    if (g.effectiveOverlap <= depth) found[{g.triangle, g.partnerTriangle}] = g.effectiveOverlap;
  return found;
}

struct Checked {
  long contacts = 0, newContacts = 0, deeperThanShallow = 0;
};

// For the engine's largest candidate skin, the near lists' (five times larger), and one larger still that strains
// every slack of the filters: the near list and the candidate list built at the pair's pose must hold every contact
// within `depth` at three random poses at the skin's very edge.
void checkAtTheSkinsEdge(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Quaternionr& rotation0,
                         const Vector3r& translation0, Real radius, Real depth, Real shallow, std::mt19937& rng,
                         Checked& checked) {
  std::uniform_real_distribution<Real> unit(0, 1);
  std::normal_distribution<Real> normal;
  auto direction = [&]() { return Vector3r(normal(rng), normal(rng), normal(rng)).normalized(); };
  std::vector<TrianglePair> all;
  for (int s = 0; s < mesh1.triangleCount(); ++s)
    for (int t = 0; t < mesh2.triangleCount(); ++t) all.push_back({s, t});
  const Matrix3r matrix0 = rotation0.toRotationMatrix();
  const std::map<TrianglePair, Real> before = contactsWithin(mesh1, mesh2, matrix0, translation0, all, depth, shallow);
  for (const Real skin : {0.01 * radius, 0.05 * radius, 0.2 * radius}) {
    std::vector<TrianglePair> near, candidates;
    nearTrianglePairs(mesh1, mesh2, matrix0, translation0, skin, depth, shallow, near);
    touchableTrianglePairs(mesh1, mesh2, matrix0, translation0, skin, depth, all, candidates);
    const std::set<TrianglePair> inNear(near.begin(), near.end()), inCandidates(candidates.begin(), candidates.end());
    for (int pose = 0; pose < 3; ++pose) {
      // Mesh 2's points move by at most |offset| + 2 sin(angle / 2) r2 (CandidateLists.cpp, motionBound): spend
      // 0.999 of the skin, a random share of it on the turn (all of it on the first pose).
      const Real turnShare = pose == 0 ? 1 : unit(rng);
      const Real angle = 2 * std::asin(0.999 * turnShare * skin / (2 * mesh2.sphereBoundRadius()));
      const Quaternionr rotation = rotation0 * Quaternionr(Eigen::AngleAxis<Real>(angle, direction()));
      const Vector3r translation = translation0 + 0.999 * (1 - turnShare) * skin * direction();
      for (const auto& [st, overlap] :
           contactsWithin(mesh1, mesh2, rotation.toRotationMatrix(), translation, all, depth, shallow)) {
        EXPECT_TRUE(inCandidates.count(st)) << "candidates, skin " << skin / radius << " r, pose " << pose
                                            << ", triangles " << st[0] << "-" << st[1];
        EXPECT_TRUE(inNear.count(st)) << "near list, skin " << skin / radius << " r, pose " << pose << ", triangles "
                                      << st[0] << "-" << st[1];
        ++checked.contacts;
        checked.newContacts += !before.count(st);
        checked.deeperThanShallow += overlap > shallow;
      }
    }
  }
}

// The relative pose of a pair of the recorded settled packing, and the smaller equivalent radius.
struct PairPose {
  const RoundedMesh *mesh1, *mesh2;
  Quaternionr rotation;
  Vector3r translation;
  Real radius;
};

// Four touching pairs of bodies of S1's settled packing, spread over its pairs.
std::vector<PairPose> touchingPairs(const RecordedScene& scene, ContactData& data) {
  scene.setStates(data);
  contactForces(scene.model, data);
  std::vector<PairPose> poses;
  for (size_t k = 0; k < data.pairs.size() && poses.size() < 4; k += 97) {
    const BodyPair& pair = data.pairs[k];
    if (pair.other >= static_cast<int>(scene.model.bodies.size()) || data.pairResults[k].statistics.contacts() == 0) continue;
    const RoundedBody &a = scene.model.bodies[pair.body], &b = scene.model.bodies[pair.other];
    const BodyState &s1 = data.bodyStates[pair.body], &s2 = data.bodyStates[pair.other];
    poses.push_back({a.mesh.get(), b.mesh.get(), s1.orientation.conjugate() * s2.orientation,
                     s1.orientation.conjugate() * (s2.position - s1.position),
                     std::min(a.equivalentRadius, b.equivalentRadius)});
  }
  return poses;
}

// Four touching pairs of S1's settled packing, and the tally of contacts checked.
class TrianglePairCandidates : public ::testing::Test {
 protected:
  void SetUp() override {
    pairs = touchingPairs(scene, data);
    ASSERT_EQ(pairs.size(), 4u);
  }
  const RecordedScene scene = loadRecordedScene();
  ContactData data;
  std::vector<PairPose> pairs;
  Checked checked;
};

TEST_F(TrianglePairCandidates, ListsHoldEveryContactWithinTheirSkin) {
  std::mt19937 rng(7);
  for (const PairPose& p : pairs) {
    const Real depth = kDeepestOverlap * p.radius;
    checkAtTheSkinsEdge(*p.mesh1, *p.mesh2, p.rotation, p.translation, p.radius, depth, depth, rng, checked);
  }
  EXPECT_GT(checked.contacts, 500);
  EXPECT_GT(checked.newContacts, 20);  // the moves make contacts the first pose did not have
}

// Past the Hertz range a list holds every contact the bodies can have (deepestPossible), and its near list takes the
// pairs deeper than the Hertz range from the triangles whose caps reach the other body, through all five filters
// (TrianglePairCandidates.hpp): two of the pairs above pushed 0.3 r_eq into each other along the line of their
// centres. Their searches filter the pairs of reaching triangles in chunks of 65,536: 37 full chunks in all.
TEST_F(TrianglePairCandidates, DeepListsHoldEveryContactWithinTheirSkin) {
  std::mt19937 rng(11);
  for (size_t k = 0; k < 2; ++k) {
    const PairPose& p = pairs[k];
    const Vector3r pushed = p.translation - 0.3 * p.radius * p.translation.normalized();
    const Real shallow = kDeepestOverlap * p.radius, depth = deepestPossible(*p.mesh1, *p.mesh2);
    ASSERT_GT(depth, 2 * shallow);  // the deep lists' search
    checkAtTheSkinsEdge(*p.mesh1, *p.mesh2, p.rotation, pushed, p.radius, depth, shallow, rng, checked);
  }
  // 4,637 contacts checked (1,037 made by the moves), 4,450 of them deeper than the Hertz range.
  EXPECT_GT(checked.contacts, 2000);
  EXPECT_GT(checked.newContacts, 100);
  EXPECT_GT(checked.deeperThanShallow, 1000);  // contacts only the deep search finds
}

}  // namespace
}  // namespace roundedmesh
