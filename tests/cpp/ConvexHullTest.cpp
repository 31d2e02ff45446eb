// convexHull (ConvexHull.hpp) against what a hull is: counter-clockwise, convex, holding every point, its corners
// among the points, no corner on a straight stretch.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "pkg/math/ConvexHull.hpp"

namespace roundedmesh {
namespace {

TEST(ConvexHull, HoldsEveryPointWithCornersAmongThemTurningLeft) {
  std::mt19937 random(4);
  std::normal_distribution<Real> normal;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vector2r> points;
    for (int i = 0; i < 40; ++i) points.emplace_back(normal(random), normal(random));
    const std::vector<Vector2r> hull = convexHull(points);
    ASSERT_GE(hull.size(), 3u);
    const int n = static_cast<int>(hull.size());
    for (int i = 0; i < n; ++i) {
      const Vector2r &a = hull[i], &b = hull[(i + 1) % n], &c = hull[(i + 2) % n];
      EXPECT_GT(cross2(b - a, c - b), 0);  // a strict left turn at every corner
      EXPECT_NE(std::find(points.begin(), points.end(), a), points.end());
      for (const Vector2r& p : points) EXPECT_GE(cross2(b - a, p - a), -1e-12);  // every point on the left
    }
  }
}

TEST(ConvexHull, DropsCornersOnAStraightStretch) {
  // A square with points along its sides and inside: the hull is its four corners.
  std::vector<Vector2r> points{{0, 0}, {0.5, 0}, {1, 0}, {1, 0.25}, {1, 1}, {0.3, 1}, {0, 1}, {0, 0.7}, {0.4, 0.6}};
  const std::vector<Vector2r> hull = convexHull(points);
  ASSERT_EQ(hull.size(), 4u);
  Real twiceArea = 0;
  for (int i = 0; i < 4; ++i) twiceArea += cross2(hull[i], hull[(i + 1) % 4]);
  EXPECT_DOUBLE_EQ(0.5 * twiceArea, 1.0);  // counter-clockwise, the unit square
}

}  // namespace
}  // namespace roundedmesh
