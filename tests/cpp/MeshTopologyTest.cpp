// findEdgeDefects: a closed, manifold, consistently oriented surface has none; each defect is counted and
// its first edge named.
#include <gtest/gtest.h>

#include <algorithm>

#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/MeshTopology.hpp"

namespace roundedmesh {
namespace {

TEST(MeshTopology, AClosedOrientedSurfaceHasNoDefects) {
  const EdgeDefects defects = findEdgeDefects(icosphere(1.0, 2).triangles());
  EXPECT_EQ(defects.boundary.count + defects.nonManifold.count + defects.misoriented.count, 0);
}

TEST(MeshTopology, CountsTheThreeEdgesOfAHole) {
  std::vector<Triangle> t = icosphere(1.0, 1).triangles();
  const Triangle removed = t[7];
  t.erase(t.begin() + 7);
  const EdgeDefects defects = findEdgeDefects(t);
  EXPECT_EQ(defects.boundary.count, 3);
  EXPECT_EQ(defects.nonManifold.count + defects.misoriented.count, 0);
  EXPECT_TRUE(std::find(removed.begin(), removed.end(), defects.boundary.first[0]) != removed.end());
}

TEST(MeshTopology, CountsTheThreeEdgesOfAFlippedTriangle) {
  std::vector<Triangle> t = icosphere(1.0, 1).triangles();
  std::swap(t[12][1], t[12][2]);
  const EdgeDefects defects = findEdgeDefects(t);
  EXPECT_EQ(defects.misoriented.count, 3);
  EXPECT_EQ(defects.boundary.count + defects.nonManifold.count, 0);
}

TEST(MeshTopology, FindsAnEdgeOfThreeTriangles) {
  // A tetrahedron with a fin on edge 0-1: three triangles border that edge.
  const std::vector<Triangle> t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {1, 0, 4}};
  const EdgeDefects defects = findEdgeDefects(t);
  EXPECT_EQ(defects.nonManifold.count, 1);
  EXPECT_EQ(defects.nonManifold.first, (std::array<int, 2>{0, 1}));
}

}  // namespace
}  // namespace roundedmesh
