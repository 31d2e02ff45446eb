// The candidate lists' promise (TrianglePairCandidates.hpp): a list built at one pose for a skin and a depth holds
// every triangle pair in contact with an effective overlap of at most that depth, at every pose that moves no point
// of mesh 2 by more than the skin. Checked against brute force (Appendix B over every triangle pair) on pairs of gummy
// bears touching in S1's settled packing, moved to random poses at the skin's very edge, in the directions that
// strain the filters most: turns (the sphere centres of flat and concave triangles, 100 r_eq behind them, swing
// far on the slightest one) and slides.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "bench/RecordedScene.hpp"
#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {
namespace {

// Every pair of `all` in contact by Appendix B alone (no deep-contact criterion) with an effective overlap of at
// most `depth`.
std::set<TrianglePair> contactsWithin(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                      const Vector3r& translation, const std::vector<TrianglePair>& all, Real depth) {
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_RoundedMesh_PressureGeom(mesh1, mesh2, rotation, translation, all, INFINITY, RelativeMotion(), geoms);
  std::set<TrianglePair> found;
  for (const PressureGeom& g : geoms)
    if (g.effectiveOverlap <= depth) found.insert({g.triangle, g.partnerTriangle});
  return found;
}

TEST(TrianglePairCandidates, ListsHoldEveryContactWithinTheirSkin) {
  const RecordedScene scene = loadRecordedScene();
  ContactData data;
  scene.setStates(data);
  contactForces(scene.model, data);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> unit(0, 1);
  std::normal_distribution<Real> normal;
  auto direction = [&]() { return Vector3r(normal(rng), normal(rng), normal(rng)).normalized(); };
  int pairs = 0;
  long checked = 0, newContacts = 0;
  for (size_t k = 0; k < data.pairs.size() && pairs < 4; k += 97) {
    const BodyPair& pair = data.pairs[k];
    if (pair.other >= static_cast<int>(scene.model.bodies.size()) || data.pairResults[k].statistics.contacts() == 0) continue;
    ++pairs;
    const RoundedBody &a = scene.model.bodies[pair.body], &b = scene.model.bodies[pair.other];
    const RoundedMesh &mesh1 = *a.mesh, &mesh2 = *b.mesh;
    const BodyState &s1 = data.bodyStates[pair.body], &s2 = data.bodyStates[pair.other];
    const Quaternionr rotation0 = s1.orientation.conjugate() * s2.orientation;
    const Vector3r translation0 = s1.orientation.conjugate() * (s2.position - s1.position);
    const Real radius = std::min(a.equivalentRadius, b.equivalentRadius);
    const Real depth = kDeepestOverlap * radius;
    std::vector<TrianglePair> all;
    for (int s = 0; s < mesh1.triangleCount(); ++s)
      for (int t = 0; t < mesh2.triangleCount(); ++t) all.push_back({s, t});
    // The engine's largest candidate skin, the near lists' (five times larger), and one larger still that strains
    // every slack of the filters.
    const Matrix3r matrix0 = rotation0.toRotationMatrix();
    const std::set<TrianglePair> before = contactsWithin(mesh1, mesh2, matrix0, translation0, all, depth);
    for (const Real skin : {0.01 * radius, 0.05 * radius, 0.2 * radius}) {
      std::vector<TrianglePair> near, candidates;
      nearTrianglePairs(mesh1, mesh2, matrix0, translation0, skin, depth, depth, near);
      touchableTrianglePairs(mesh1, mesh2, matrix0, translation0, skin, depth, all, candidates);
      const std::set<TrianglePair> inNear(near.begin(), near.end()), inCandidates(candidates.begin(), candidates.end());
      for (int pose = 0; pose < 3; ++pose) {
        // Mesh 2's points move by at most |offset| + 2 sin(angle / 2) r2 (CandidateLists.cpp, motionBound): spend
        // 0.999 of the skin, a random share of it on the turn (all of it on the first pose).
        const Real turnShare = pose == 0 ? 1 : unit(rng);
        const Real angle = 2 * std::asin(0.999 * turnShare * skin / (2 * mesh2.sphereBoundRadius()));
        const Quaternionr rotation = rotation0 * Quaternionr(Eigen::AngleAxis<Real>(angle, direction()));
        const Vector3r translation = translation0 + 0.999 * (1 - turnShare) * skin * direction();
        for (const TrianglePair& st : contactsWithin(mesh1, mesh2, rotation.toRotationMatrix(), translation, all, depth)) {
          EXPECT_TRUE(inCandidates.count(st)) << "candidates, bodies " << pair.body << "-" << pair.other << ", skin "
                                              << skin / radius << " r, pose " << pose << ", triangles " << st[0] << "-" << st[1];
          EXPECT_TRUE(inNear.count(st)) << "near list, bodies " << pair.body << "-" << pair.other << ", skin "
                                        << skin / radius << " r, pose " << pose << ", triangles " << st[0] << "-" << st[1];
          ++checked;
          newContacts += !before.count(st);
        }
      }
    }
  }
  EXPECT_EQ(pairs, 4);
  EXPECT_GT(checked, 500);
  EXPECT_GT(newContacts, 20);  // the moves make contacts the first pose did not have
}

}  // namespace
}  // namespace roundedmesh
