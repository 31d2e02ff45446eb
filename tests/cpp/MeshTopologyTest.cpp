// requireClosedOrientedSurface: closed, manifold, consistently oriented surfaces pass; each defect is
// named with its edge.
#include <gtest/gtest.h>

#include <string>

#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/MeshTopology.hpp"

namespace roundedmesh {
namespace {

std::string messageOf(const std::vector<Triangle>& triangles) {
  try {
    requireClosedOrientedSurface(triangles);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MeshTopology, AcceptsAClosedOrientedSurface) {
  EXPECT_EQ(messageOf(icosphere(1.0, 2).triangles()), "");
}

TEST(MeshTopology, NamesAnEdgeOfAHole) {
  std::vector<Triangle> t = icosphere(1.0, 1).triangles();
  const Triangle removed = t[7];
  t.erase(t.begin() + 7);
  const std::string message = messageOf(t);
  EXPECT_NE(message.find("not closed"), std::string::npos) << message;
  EXPECT_NE(message.find(std::to_string(removed[0])), std::string::npos) << message;
}

TEST(MeshTopology, NamesAFlippedTriangle) {
  std::vector<Triangle> t = icosphere(1.0, 1).triangles();
  std::swap(t[12][1], t[12][2]);
  const std::string message = messageOf(t);
  EXPECT_NE(message.find("not consistently oriented"), std::string::npos) << message;
  EXPECT_NE(message.find("12"), std::string::npos) << message;
}

TEST(MeshTopology, NamesANonManifoldEdge) {
  // Two tetrahedra sharing edge 0-1 with a third triangle on it: three triangles border that edge.
  const std::vector<Triangle> t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {1, 0, 4}};
  const std::string message = messageOf(t);
  EXPECT_FALSE(message.empty());
}

}  // namespace
}  // namespace roundedmesh
