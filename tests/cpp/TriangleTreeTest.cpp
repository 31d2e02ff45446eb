// The hierarchy finds exactly the triangles (pairs) a brute-force loop over all boxes finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

#include "pkg/shape/TriangleTree.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

Matrix3r randomRotation(std::mt19937& rng) {
  std::normal_distribution<Real> normal;
  return Quaternionr(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
}

TEST(TriangleTree, CapBoxesHoldCornersAndCap) {
  const RoundedMesh mesh = icosphere(1.0, 2);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const AlignedBox3r& box = mesh.tree().triangleBox(t);
    for (int corner : mesh.triangles()[t]) EXPECT_TRUE(box.contains(mesh.vertices()[corner]));
    // The cap's top: the sphere's point above the circumcentre.
    const RoundedTriangle& r = mesh.rounded(t);
    EXPECT_TRUE(box.contains(r.sphereCentre + r.radius * r.normal)) << t;
  }
}

TEST(TriangleTree, QueryFindsWhatBruteForceFinds) {
  const RoundedMesh mesh = icosphere(1.0, 3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> uniform(-1.2, 1.2);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3r centre(uniform(rng), uniform(rng), uniform(rng));
    const AlignedBox3r probe(centre.array() - 0.2, centre.array() + 0.2);
    std::set<int> expected, found;
    for (int t = 0; t < mesh.triangleCount(); ++t)
      if (mesh.tree().triangleBox(t).intersects(probe)) expected.insert(t);
    mesh.tree().query([&](const AlignedBox3r& b) { return b.intersects(probe); }, [&](int t) { found.insert(t); });
    EXPECT_EQ(found, expected);
  }
}

// Against two partners in turn, a coarse and a fine one, at random poses: a query's boxes placed in a's frame (kept
// between the node pairs that meet them) carry over neither to the next pose nor to the other partner.
TEST(TriangleTree, PairQueryFindsWhatBruteForceFinds) {
  const RoundedMesh a = icosphere(1.0, 3), coarse = icosphere(0.7, 2), fine = icosphere(0.5, 3);
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> uniform(-1.8, 1.8);
  int nonEmpty = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const RoundedMesh& b = trial % 3 == 1 ? fine : coarse;
    const Matrix3r rotation = randomRotation(rng);
    const Vector3r translation(uniform(rng), uniform(rng), uniform(rng));
    std::set<std::pair<int, int>> expected, found;
    for (int s = 0; s < a.triangleCount(); ++s)
      for (int t = 0; t < b.triangleCount(); ++t)
        if (a.tree().triangleBox(s).intersects(transformedBox(b.tree().triangleBox(t), rotation, translation, 0.05)))
          expected.insert({s, t});
    TriangleTree::queryPairs(a.tree(), b.tree(), rotation, translation, 0.05, [&](int s, int t) {
      EXPECT_TRUE(found.insert({s, t}).second) << "pair visited twice";
    });
    EXPECT_EQ(found, expected);
    nonEmpty += !expected.empty();
  }
  EXPECT_GT(nonEmpty, 5);
}

}  // namespace
}  // namespace roundedmesh
