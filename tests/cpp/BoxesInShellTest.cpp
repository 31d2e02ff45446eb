// The boxes in a shell, in lanes (BoxesInShell.hpp), are those AlignedBox3r::intersects keeps one box at a time, in
// the same order, on every instruction set the processor has and the build compiled: 0 to 100 random boxes (with
// corners on a coarse grid, so that faces touch exactly, the case `<=` decides; some empty, some NaN) against random
// outer and inner boxes, and the triangles of a gummy bear against shells about the triangles of another turned about
// it, as the deep lists' search asks. No tolerance: the lanes only compare.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "bench/RecordedScene.hpp"
#include "pkg/bound/BoxesInShell.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

std::vector<int64_t> inShellOneAtATime(const std::vector<AlignedBox3r>& boxes, const std::vector<int>& which,
                                       const AlignedBox3r& outer, const AlignedBox3r& inner) {
  std::vector<int64_t> kept;
  for (size_t i = 0; i < which.size(); ++i) {
    const AlignedBox3r& box = boxes[which[i]];
    if (box.intersects(outer) && !box.intersects(inner)) kept.push_back(static_cast<int64_t>(i));
  }
  return kept;
}

// A box with corners on the grid of quarters in [-2, 2]^3: empty (min > max on an axis) one time in ten.
AlignedBox3r gridBox(test::RandomSource& random) {
  auto grid = [&random]() { return std::round(random.uniform(-8, 8)) / 4; };
  Vector3r a(grid(), grid(), grid()), b(grid(), grid(), grid());
  if (random.uniform(0, 1) < 0.9) {
    const Vector3r low = a.cwiseMin(b), high = a.cwiseMax(b);
    a = low;
    b = high;
  }
  return AlignedBox3r(a, b);
}

TEST(BoxesInShell, RandomBoxesAreKeptAsIntersectsKeepsThem) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(5);
    long kept = 0, touching = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const int count = static_cast<int>(random.uniform(0, 101));
      std::vector<AlignedBox3r> boxes;
      for (int i = 0; i < count; ++i) {
        boxes.push_back(gridBox(random));
        if (trial % 5 == 0 && i % 7 == 3) boxes.back().min().x() = nan;
      }
      std::vector<int> which(count);
      for (int i = 0; i < count; ++i) which[i] = count - 1 - i;  // any order: the positions follow it
      BoxColumns columns;
      columns.assign(boxes, which);
      ASSERT_EQ(columns.size(), static_cast<size_t>(count));
      const AlignedBox3r outer = gridBox(random);
      AlignedBox3r inner = gridBox(random);
      if (trial % 3 == 0) inner = AlignedBox3r(outer.center(), outer.center());  // a point inside
      std::vector<int64_t> lanes;
      boxesInShell(columns, outer, inner, lanes);
      ASSERT_EQ(lanes, inShellOneAtATime(boxes, which, outer, inner)) << "trial " << trial;
      kept += static_cast<long>(lanes.size());
      for (const AlignedBox3r& box : boxes)
        touching += box.intersects(outer) && (box.min().array() == outer.max().array()).any();
    }
    EXPECT_GT(kept, 1000);
    EXPECT_GT(touching, 100);  // faces that touch exactly, where <= decides
  });
}

TEST(BoxesInShell, BearTrianglesInShellsAboutAnotherBearsAreThoseOfIntersects) {
  static const RecordedScene scene = loadRecordedScene();
  const RoundedMesh& bear = *scene.model.bodies[0].mesh;
  const TriangleTree& tree = bear.tree();
  std::vector<int> which(bear.triangleCount());
  for (int i = 0; i < bear.triangleCount(); ++i) which[i] = i;
  BoxColumns columns;
  columns.assign(tree.triangleBoxes(), which);
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(8);
    long kept = 0;
    for (int trial = 0; trial < 200; ++trial) {
      const Matrix3r rotation = Quaternionr(Eigen::AngleAxis<Real>(random.uniform(0, M_PI), random.direction())).toRotationMatrix();
      const Vector3r translation = random.uniform(0, 1.5) * bear.sphereBoundRadius() * random.direction();
      const Real shallow = random.uniform(0, 0.05) * bear.sphereBoundRadius();
      const int t = static_cast<int>(random.uniform(0, bear.triangleCount() - 1));
      const AlignedBox3r outer = transformedBox(tree.triangleBox(t), rotation, translation, 10 * shallow);
      const AlignedBox3r inner = transformedBox(tree.triangleBox(t), rotation, translation, shallow);
      std::vector<int64_t> lanes;
      boxesInShell(columns, outer, inner, lanes);
      ASSERT_EQ(lanes, inShellOneAtATime(tree.triangleBoxes(), which, outer, inner)) << "trial " << trial;
      kept += static_cast<long>(lanes.size());
    }
    EXPECT_GT(kept, 500);
  });
}

}  // namespace
}  // namespace roundedmesh
