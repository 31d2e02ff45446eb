// The polygon S of Section 2.3: construction, clipping, containment and closest point.
#include <gtest/gtest.h>

#include <cstring>

#include "pkg/math/ConvexPolygon.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

TEST(ConvexPolygon, TriangleIsStoredCounterClockwise) {
  const ConvexPolygon clockwise = ConvexPolygon::triangle({0, 0}, {0, 1}, {1, 0});
  EXPECT_NEAR(clockwise.area(), 0.5, 1e-15);
}

TEST(ConvexPolygon, ClippingATriangleByARectangleGivesTheOverlap) {
  // Triangle x, y >= 0, x + y <= 5 against the square [1, 3]^2: the square minus the corner triangle
  // (2,3) (3,3) (3,2) of area 1/2, a pentagon.
  const ConvexPolygon t = ConvexPolygon::triangle({0, 0}, {5, 0}, {0, 5});
  const ConvexPolygon s = t.intersection(ConvexPolygon::rectangle({2, 2}, 1, 1));
  EXPECT_EQ(s.size(), 5);
  EXPECT_NEAR(s.area(), 3.5, 1e-14);
}

TEST(ConvexPolygon, CornersOnTheClipLineAreNotDuplicated) {
  // x + y = 4 runs exactly through the square's corners (1,3) and (3,1): the overlap is their triangle.
  const ConvexPolygon t = ConvexPolygon::triangle({0, 0}, {4, 0}, {0, 4});
  const ConvexPolygon s = t.intersection(ConvexPolygon::rectangle({2, 2}, 1, 1));
  EXPECT_EQ(s.size(), 3);
  EXPECT_NEAR(s.area(), 2.0, 1e-14);
}

// A triangle whose corners all stick out, cutting all four sides of the square: three corners of the
// square survive (one is cut off) and each side contributes crossings, seven corners in all.
TEST(ConvexPolygon, ClippingATriangleByARectangleCanGiveSevenCorners) {
  const ConvexPolygon t = ConvexPolygon::triangle({-1.6, -0.6}, {1.6, -1.4}, {0.3, 1.8});
  const ConvexPolygon s = t.intersection(ConvexPolygon::rectangle({0, 0}, 1, 1));
  EXPECT_EQ(s.size(), 7);
  for (int i = 0; i < s.size(); ++i) {  // every corner in both, up to the round-off of a crossing point
    EXPECT_LT((t.closestPoint(s[i]) - s[i]).norm(), 1e-15);
    EXPECT_LE(s[i].cwiseAbs().maxCoeff(), 1 + 1e-15);
  }
}

TEST(ConvexPolygon, DisjointPolygonsGiveAnEmptyIntersection) {
  const ConvexPolygon t = ConvexPolygon::triangle({0, 0}, {1, 0}, {0, 1});
  EXPECT_TRUE(t.intersection(ConvexPolygon::rectangle({5, 5}, 1, 1)).empty());
}

TEST(ConvexPolygon, ContainsAndClosestPoint) {
  const ConvexPolygon t = ConvexPolygon::triangle({0, 0}, {2, 0}, {0, 2});
  EXPECT_TRUE(t.contains({0.5, 0.5}));
  EXPECT_TRUE(t.contains({1, 0}));  // on an edge
  EXPECT_FALSE(t.contains({1.5, 1.5}));
  EXPECT_TRUE(t.closestPoint({1.5, 1.5}).isApprox(Vector2r(1, 1), 1e-15));
  EXPECT_TRUE(t.closestPoint({-1, -2}).isApprox(Vector2r(0, 0), 1e-15));
  EXPECT_TRUE(t.closestPoint({0.5, 0.5}).isApprox(Vector2r(0.5, 0.5), 1e-15));
}

// clippedToSquare skips the square's edges that every corner is inside of; the result must be intersection's, corner
// for corner and bit for bit: random triangles and their intersections with another, from wholly inside the square to
// wholly outside, and corners exactly on the line of each of the square's four edges.
TEST(ConvexPolygon, ClippingToASquareIsTheIntersectionWithIt) {
  test::RandomSource random(1409);
  int clipped = 0, inside = 0, empty = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const Real h = random.uniform(0.1, 1), spread = random.uniform(0.2, 3) * h;
    auto point = [&] {
      // A corner on the line of one of the square's four edges now and then.
      const Real along = random.uniform(-spread, spread), pick = random.uniform(0, 1);
      if (pick < 0.02) return Vector2r(h, along);
      if (pick < 0.04) return Vector2r(-h, along);
      if (pick < 0.06) return Vector2r(along, h);
      if (pick < 0.08) return Vector2r(along, -h);
      return Vector2r(random.uniform(-spread, spread), random.uniform(-spread, spread));
    };
    ConvexPolygon p = ConvexPolygon::triangle(point(), point(), point());
    if (trial % 2) p = p.intersection(ConvexPolygon::triangle(point(), point(), point()));
    const ConvexPolygon reference = p.intersection(ConvexPolygon::rectangle(Vector2r::Zero(), h, h));
    const ConvexPolygon square = p.clippedToSquare(h);
    ASSERT_EQ(square.size(), reference.size()) << "trial " << trial;
    for (int i = 0; i < square.size(); ++i)
      ASSERT_EQ(std::memcmp(square[i].data(), reference[i].data(), sizeof(Vector2r)), 0) << "trial " << trial;
    if (reference.empty()) ++empty;
    else if (reference.size() == p.size() && reference.area() == p.area()) ++inside;
    else ++clipped;
  }
  // Each case is common: clipped, wholly inside (no clip at all), and empty.
  EXPECT_GT(clipped, 10000);
  EXPECT_GT(inside, 5000);
  EXPECT_GT(empty, 5000);
}

}  // namespace
}  // namespace roundedmesh
