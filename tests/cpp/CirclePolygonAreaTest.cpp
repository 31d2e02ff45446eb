// A(S n Omega) of Eqs. 14 and 20: the closed form against analytic cases and against an independent
// slice integration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pkg/math/CirclePolygonArea.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

ConvexPolygon polygonOf(std::initializer_list<Vector2r> corners) {
  ConvexPolygon p;
  for (const Vector2r& c : corners) p.push(c);
  return p;
}

TEST(CirclePolygonArea, CircleInsidePolygonGivesTheDisc) {
  const ConvexPolygon square = ConvexPolygon::rectangle(Vector2r(0.1, -0.2), 5, 5);
  EXPECT_NEAR(circlePolygonArea(1.5, square), M_PI * 1.5 * 1.5, 1e-13);
}

TEST(CirclePolygonArea, PolygonInsideCircleGivesThePolygon) {
  const ConvexPolygon t = ConvexPolygon::triangle({0.1, 0.1}, {0.5, -0.2}, {-0.3, 0.4});
  EXPECT_NEAR(circlePolygonArea(2.0, t), t.area(), 1e-15);
}

TEST(CirclePolygonArea, PolygonOutsideCircleGivesZero) {
  const ConvexPolygon t = ConvexPolygon::triangle({3, 0}, {4, 0}, {3, 1});
  EXPECT_NEAR(circlePolygonArea(1.0, t), 0.0, 1e-15);
}

// A half-plane at distance d from the centre cuts a circular segment of area a^2 acos(d/a) - d sqrt(a^2-d^2).
TEST(CirclePolygonArea, HalfPlaneCutGivesTheCircularSegment) {
  const Real a = 1.3, d = 0.4;
  const ConvexPolygon beyond = polygonOf({{d, -5}, {10, -5}, {10, 5}, {d, 5}});
  EXPECT_NEAR(circlePolygonArea(a, beyond), a * a * std::acos(d / a) - d * std::sqrt(a * a - d * d), 1e-13);
}

// Tolerance 1e-7 relative: the slice reference is accurate to about 1e-9 relative (see above).
TEST(CirclePolygonArea, CrossingCasesAgreeWithSliceIntegration) {
  const Real a = 1.0;
  const ConvexPolygon cases[] = {
      ConvexPolygon::triangle({-0.2, -0.1}, {1.4, 0.3}, {0.2, 1.5}),       // two corners outside
      ConvexPolygon::triangle({-2, -0.5}, {2, -0.5}, {0, 3}),              // circle pokes out of three edges
      ConvexPolygon::triangle({0.9, -0.9}, {2.0, 0.0}, {0.9, 0.9}),        // corner region only
      ConvexPolygon::rectangle({0.5, 0.5}, 0.7, 0.3),                      // rectangle across the rim
      ConvexPolygon::triangle({1.0, 0.0}, {2.0, 1.0}, {0.0, 2.0}),         // a corner exactly on the circle
      ConvexPolygon::triangle({-1.0, 1.0}, {1.0, 1.0}, {0.0, 3.0}),        // edge tangent to the circle
      ConvexPolygon::triangle({0.0, 0.0}, {1.5, 0.2}, {0.3, 1.1}),         // a corner at the centre
      polygonOf({{-0.8, -0.8}, {0.3, -1.2}, {1.2, -0.1}, {0.9, 0.9}, {-0.4, 1.1}, {-1.3, 0.2}}),  // hexagon
  };
  for (const ConvexPolygon& p : cases) {
    const Real reference = test::sliceIntegratedArea(a, p);
    EXPECT_NEAR(circlePolygonArea(a, p), reference, 1e-7 * std::max(reference, 1e-3));
  }
}

// Wedges around a corner at the centre, displaced by round-off (1e-17): each is the sector of its angle,
// and mirror images agree. (An angle between two vectors of length 1e-17 would be arbitrary.)
TEST(CirclePolygonArea, CornerAtTheCentreUpToRoundOffGivesTheSector) {
  const Real a = 0.03;
  const Vector2r nearCentre(-1.3e-17, 4e-18);
  const ConvexPolygon right = ConvexPolygon::triangle(nearCentre, {0.0822, -0.1331}, {0.1380, 0.0});
  const ConvexPolygon left = ConvexPolygon::triangle(nearCentre, {-0.1380, 0.0}, {-0.0822, -0.1331});
  const Real angle = std::atan2(0.1331, 0.0822);
  EXPECT_NEAR(circlePolygonArea(a, right), 0.5 * a * a * angle, 1e-14 * a * a);
  EXPECT_NEAR(circlePolygonArea(a, left), 0.5 * a * a * angle, 1e-14 * a * a);
}

TEST(CirclePolygonArea, DegenerateInputsGiveZero) {
  EXPECT_EQ(circlePolygonArea(1.0, ConvexPolygon()), 0.0);
  EXPECT_EQ(circlePolygonArea(0.0, ConvexPolygon::rectangle({0, 0}, 1, 1)), 0.0);
  EXPECT_NEAR(circlePolygonArea(1.0, ConvexPolygon::triangle({0, 0}, {1, 0}, {2, 0})), 0.0, 1e-15);
}

}  // namespace
}  // namespace roundedmesh
