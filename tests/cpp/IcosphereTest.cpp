// The icosphere generator of Section 3.1 and its rounded triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

TEST(Icosphere, NodeAndTriangleCountsFollowTheSubdivision) {
  const int nodes[] = {12, 42, 162, 642, 2562};
  for (int k = 0; k <= 4; ++k) {
    const RoundedMesh m = icosphere(1.0, k);
    EXPECT_EQ(static_cast<int>(m.vertices().size()), nodes[k]);
    EXPECT_EQ(m.triangleCount(), 20 << (2 * k));
  }
}

TEST(Icosphere, NodesLieOnTheSphereAndNormalsPointOutward) {
  const RoundedMesh m = icosphere(2.5, 3);
  for (const Vector3r& v : m.vertices()) EXPECT_NEAR(v.norm(), 2.5, 1e-14);
  for (int t = 0; t < m.triangleCount(); ++t) {
    const Triangle& tri = m.triangles()[t];
    const Vector3r centroid = (m.vertices()[tri[0]] + m.vertices()[tri[1]] + m.vertices()[tri[2]]) / 3;
    EXPECT_GT(m.rounded(t).normal.dot(centroid.normalized()), 0.99);
  }
}

// Closed and consistently oriented: every directed edge appears once, and its reverse once.
TEST(Icosphere, IsClosedAndConsistentlyOriented) {
  const RoundedMesh m = icosphere(1.0, 2);
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : m.triangles())
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
}

// With the sphere's radius prescribed, every encompassing sphere is the sphere itself.
TEST(Icosphere, EncompassingSpheresAreTheSphere) {
  const RoundedMesh m = icosphere(0.7, 2);
  for (int t = 0; t < m.triangleCount(); ++t) {
    EXPECT_NEAR(m.rounded(t).radius, 0.7, 1e-15);
    EXPECT_LT(m.rounded(t).sphereCentre.norm(), 1e-12);
  }
  EXPECT_NEAR(m.sphereBoundRadius(), 0.7, 1e-12);
}

TEST(Icosphere, RejectsBadArguments) {
  EXPECT_THROW(icosphere(-1.0, 2), std::invalid_argument);
  EXPECT_THROW(icosphere(std::nan(""), 2), std::invalid_argument);
  EXPECT_THROW(icosphere(1.0, -1), std::invalid_argument);
  EXPECT_THROW(icosphere(1.0, 9), std::invalid_argument);
}

}  // namespace
}  // namespace roundedmesh
