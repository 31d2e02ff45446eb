// The batched candidate lists (BatchedCandidates.hpp) are the reference's (touchableTrianglePairs), pair for pair and
// in the same order: for 10^5 random triangle pairs of every kind of the robustness suite (general, coplanar, edge on
// edge), each filling whole vectors and a tail; for the near lists of random body pairs of the library (icospheres,
// a distorted icosphere, a spheroid, 1 mm to 1 m), at the pose the near list was built at and moved within its skin;
// and (RecordedSceneTest) for every list of S1's recorded shaking. The near search's filters 2-4 (passesFilters2to4),
// batched, keep what the reference keeps, on the same random triangle pairs and on the pairs of the library's body
// pairs' trees, on every instruction set the processor has and the build compiled. A deep list's shell, batched, is the
// reference's shell (each triangle of body 1 whose box meets the outer box and not the inner one, as
// AlignedBox3r::intersects decides, through touchablePair) for two gummy bears at random poses. No tolerance: the batches decide a pair only by a
// margin, and the pairs within it go to the reference's own test; that these are few is checked too, or the batches
// would only be a detour to the reference.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/RecordedScene.hpp"
#include "pkg/bound/BatchedCandidates.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

using Pairs = std::vector<TrianglePair>;

// A rotation by up to `angle` [rad] about a random axis.
Matrix3r randomTurn(test::RandomSource& random, Real angle) {
  return Eigen::AngleAxis<Real>(random.uniform(0, angle), random.direction()).toRotationMatrix();
}

// A body pair of the library: its meshes, the smaller volume-equivalent radius, and body 2's pose in body 1's frame.
struct BodyPairPose {
  const RoundedMesh &mesh1, &mesh2;
  Real radius;
  Matrix3r rotation;
  Vector3r translation;
  explicit BodyPairPose(const test::BodyPairCase& c)
      : mesh1(*c.model.bodies[0].mesh),
        mesh2(*c.model.bodies[1].mesh),
        radius(std::min(c.model.bodies[0].equivalentRadius, c.model.bodies[1].equivalentRadius)),
        rotation((c.data.bodyStates[0].orientation.conjugate() * c.data.bodyStates[1].orientation).toRotationMatrix()),
        translation(c.data.bodyStates[0].orientation.conjugate() *
                    (c.data.bodyStates[1].position - c.data.bodyStates[0].position)) {}
};

// A random triangle pair of the robustness suite's kind for `trial`, body 2 as given or turned about body 1's origin by
// up to 0.1 rad and moved by up to a tenth of the size; a skin from 1e-5 to 0.1 and a depth up to 0.1 of the size.
struct TrianglePairCase {
  test::TrianglePair pair;
  Matrix3r rotation = Matrix3r::Identity();
  Vector3r translation = Vector3r::Zero();
  Real skin = 0, depth = 0;
};

TrianglePairCase randomCase(test::RandomSource& random, long trial) {
  TrianglePairCase c{test::randomTrianglePair(random, test::pairKind(trial))};
  if (trial % 2) {
    c.rotation = randomTurn(random, 0.1);
    c.translation = random.uniform(0, 0.1) * c.pair.size * random.direction();
  }
  c.skin = c.pair.size * std::exp(random.uniform(std::log(1e-5), std::log(0.1)));
  c.depth = c.pair.size * random.uniform(0, 0.1);
  return c;
}

// More copies of the pair than the widest vector holds, and not a multiple of it: whole vectors and a tail.
const Pairs kCopies(2 * 8 + 3, TrianglePair{0, 0});

TEST(BatchedCandidates, RandomTrianglePairsGiveTheReferenceDecision) {
  test::RandomSource random(20261127);
  const Pairs& near = kCopies;
  long kept = 0, rejected = 0;
  for (long trial = 0; trial < 100000; ++trial) {
    const TrianglePairCase c = randomCase(random, trial);
    const test::TrianglePair& pair = c.pair;
    Pairs reference, batched;
    touchableTrianglePairs(pair.p, pair.q, c.rotation, c.translation, c.skin, c.depth, near, reference);
    touchableTrianglePairsBatched(pair.p, pair.q, c.rotation, c.translation, c.skin, c.depth, near, batched);
    ASSERT_EQ(batched, reference) << "trial " << trial;
    (reference.empty() ? rejected : kept) += 1;
  }
  // Both outcomes are common, so a pass that rejected or kept too much would show.
  EXPECT_GT(kept, 10000);
  EXPECT_GT(rejected, 10000);
}

TEST(BatchedCandidates, RandomBodyPairsGiveTheReferenceLists) {
  test::RandomSource random(38);
  test::BodyLibrary library(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
  long scanned = 0, candidates = 0, undecided = 0;
  int bodyPairs = 0;
  while (scanned < 50000) {
    ASSERT_LT(++bodyPairs, 5000) << "too few near pairs";
    const test::BodyPairCase c = test::randomBodyPair(random, library);
    const BodyPairPose pose(c);
    const RoundedMesh &mesh1 = pose.mesh1, &mesh2 = pose.mesh2;
    const Real radius = pose.radius;
    const Matrix3r& rotation = pose.rotation;
    const Vector3r& translation = pose.translation;
    // The engine's skins (0.001 to 0.01 r_eq, the near list's five times larger) and depths (shallow, or twice).
    const Real skin = radius * std::exp(random.uniform(std::log(1e-3), std::log(1e-2)));
    const Real shallow = kDeepestOverlap * radius;
    const Real depth = shallow * (bodyPairs % 3 == 0 ? 2 : random.uniform(0.01, 1));
    Pairs near;
    nearTrianglePairs(mesh1, mesh2, rotation, translation, 5 * skin, depth + 5 * skin, shallow, near);
    // At the near list's pose, and with body 2 moved by up to 4 skins (turned about its centre and shifted).
    const Matrix3r turn = randomTurn(random, 2 * skin / mesh2.sphereBoundRadius());
    const Vector3r shift = random.uniform(0, 2) * skin * random.direction();
    for (const auto& [r, x] : {std::pair<Matrix3r, Vector3r>(rotation, translation),
                               std::pair<Matrix3r, Vector3r>(rotation * turn, translation + shift)}) {
      Pairs reference, batched;
      touchableTrianglePairs(mesh1, mesh2, r, x, skin, depth, near, reference);
      undecided += static_cast<long>(touchableTrianglePairsBatched(mesh1, mesh2, r, x, skin, depth, near, batched));
      ASSERT_EQ(batched, reference) << "body pair " << bodyPairs;
      scanned += static_cast<long>(near.size());
      candidates += static_cast<long>(reference.size());
    }
  }
  EXPECT_GT(candidates, 1000);
  EXPECT_LT(candidates, scanned);
  // The library's bodies' pairs are decided by the batches (none of 53,728 left to the reference here); the random
  // triangle pairs above are not counted: their radii reach 10^6 times their size, so that the margin, 1e-9 of the
  // largest radius, is as large as the triangles.
  EXPECT_LT(undecided, 1e-3 * scanned);
}

// passesFilters2to4 on each pair, one at a time.
Pairs passingFilters2to4(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                         const Vector3r& translation, Real skin, Real reach, const Pairs& pairs) {
  Pairs kept;
  for (const auto& [s, t] : pairs)
    if (passesFilters2to4(mesh1, s, mesh2, t, rotation, translation, skin, reach)) kept.push_back({s, t});
  return kept;
}

TEST(BatchedCandidates, NearFiltersOfRandomTrianglePairsAreTheReferences) {
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(20261206);
    long kept = 0, rejected = 0;
    for (long trial = 0; trial < 20000; ++trial) {
      const TrianglePairCase c = randomCase(random, trial);
      const RoundedMesh &p = c.pair.p, &q = c.pair.q;
      Pairs batched = kCopies;
      keepPassingFilters2to4Batched(p, q, c.rotation, c.translation, c.skin, c.depth + c.skin, batched);
      ASSERT_EQ(batched, passingFilters2to4(p, q, c.rotation, c.translation, c.skin, c.depth + c.skin, kCopies))
          << "trial " << trial;
      (batched.empty() ? rejected : kept) += 1;
    }
    EXPECT_GT(kept, 2000);
    EXPECT_GT(rejected, 2000);
  });
}

TEST(BatchedCandidates, NearFiltersOfBodyPairsTreesAreTheReferences) {
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(61);
    test::BodyLibrary library(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
    long inBoxes = 0, kept = 0, undecided = 0;
    for (int bodyPair = 0; bodyPair < 300; ++bodyPair) {
      const test::BodyPairCase c = test::randomBodyPair(random, library);
      const BodyPairPose p(c);
      // A near list's skin (five times the engine's 0.001 to 0.01 r_eq) and a depth up to twice the Hertz range.
      const Real skin = 5 * p.radius * std::exp(random.uniform(std::log(1e-3), std::log(1e-2)));
      const Real reach = skin + 2 * kDeepestOverlap * p.radius * random.uniform(0, 1);
      Pairs boxes;
      TriangleTree::queryPairs(p.mesh1.tree(), p.mesh2.tree(), p.rotation, p.translation, reach,
                               [&boxes](int s, int t) { boxes.push_back({s, t}); });
      Pairs batched = boxes;
      undecided += static_cast<long>(
          keepPassingFilters2to4Batched(p.mesh1, p.mesh2, p.rotation, p.translation, skin, reach, batched));
      ASSERT_EQ(batched, passingFilters2to4(p.mesh1, p.mesh2, p.rotation, p.translation, skin, reach, boxes))
          << "body pair " << bodyPair;
      inBoxes += static_cast<long>(boxes.size());
      kept += static_cast<long>(batched.size());
    }
    EXPECT_GT(kept, 10000);
    EXPECT_LT(kept, inBoxes);
    EXPECT_LT(undecided, 1e-3 * inBoxes);
  });
}

// A deep list's shell about a bear and a bear of 0.8 times its size (two meshes, so that their columns, bounds and
// margins are not taken for each other's), 150 random poses from interpenetrating to just apart: random subsets of
// their triangles (a fifth to all, in a random order, which the pairs must follow) as those that reach into the other,
// a depth up to half the bound radius and an inner box's margin up to the depth (the Hertz range's, whose pairs the
// trees' search found).
TEST(BatchedCandidates, DeepShellPairsOfTwoBearsAreTheReferences) {
  static const RecordedScene scene = loadRecordedScene();
  const RoundedMesh& mesh = *scene.model.bodies[0].mesh;
  std::vector<Vector3r> vertices = mesh.vertices();
  for (Vector3r& v : vertices) v *= 0.8;
  std::vector<Real> radii = mesh.radii();
  for (Real& r : radii) r *= 0.8;
  const RoundedMesh small(std::move(vertices), mesh.triangles(), radii);
  const Real bound = mesh.sphereBoundRadius();
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(9);
    long found = 0, cutByInner = 0;
    for (int trial = 0; trial < 150; ++trial) {
      const Matrix3r rotation = randomTurn(random, M_PI);
      const Vector3r translation = random.uniform(0, 1.5) * bound * random.direction();
      const Real skin = bound * std::exp(random.uniform(std::log(1e-5), std::log(1e-2)));
      const Real depth = random.uniform(0, 0.5) * bound;
      const Real inner = random.uniform(0, 1) * (depth + skin);
      auto subset = [&]() {
        std::vector<int> triangles;
        const Real share = random.uniform(0.2, 1);
        for (int t = 0; t < mesh.triangleCount(); ++t)
          if (random.uniform(0, 1) < share) triangles.push_back(t);
        for (size_t k = triangles.size(); k > 1; --k)
          std::swap(triangles[k - 1], triangles[static_cast<size_t>(random.uniform(0, static_cast<Real>(k)))]);
        return triangles;
      };
      const std::vector<int> reaching1 = subset(), reaching2 = subset();  // the meshes share their triangles' order
      Pairs expected;
      const Matrix3r absRotation = rotation.cwiseAbs();
      for (const int t : reaching2) {
        const AlignedBox3r outer = transformedBox(small.tree().triangleBox(t), rotation, translation, depth + skin);
        const AlignedBox3r within = transformedBox(small.tree().triangleBox(t), rotation, translation, inner);
        for (const int s : reaching1) {
          const AlignedBox3r& box = mesh.tree().triangleBox(s);
          if (!box.intersects(outer)) continue;
          if (box.intersects(within)) {
            ++cutByInner;
            continue;
          }
          if (touchablePair(mesh, s, small, t, rotation, absRotation, translation, skin, depth)) expected.push_back({s, t});
        }
      }
      Pairs batched{{-1, -1}};  // appended to
      appendTouchableShellPairsBatched(mesh, small, rotation, translation, skin, depth, inner, reaching1, reaching2,
                                       batched);
      ASSERT_EQ(Pairs(batched.begin() + 1, batched.end()), expected) << "trial " << trial;
      found += static_cast<long>(expected.size());
    }
    EXPECT_GT(found, 10000);
    EXPECT_GT(cutByInner, 10000);
  });
}

}  // namespace
}  // namespace roundedmesh
