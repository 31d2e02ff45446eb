// The batched quadrature points (FanQuadrature.hpp) are the reference's bit for bit: every point and weight of 10^5
// random polygons of 3 to 10 corners, against Law2's quadrature written one Eigen expression per triangle of the fan
// (the code it replaced), with contact circles from inside the polygon's corners to well beyond them, so that points
// outside the circle (shape 0) and inside are both common. No tolerance: the same operations in the same order round
// the same way on any vector unit: each instruction set the processor has and the build compiled is run in turn (on
// an AVX-512 machine: AVX3, AVX2, SSE4, SSSE3 and Highway's scalar fallback). The fan's integral of the shape is also
// checked against the closed form over a polygon that holds the whole circle, within the rule's own error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pkg/law/FanQuadrature.hpp"
#include "pkg/math/DunavantRule.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

using test::sameBits;

// A convex polygon of 3 to 10 corners around the origin: a random triangle, clipped by another (up to 6 corners)
// and by a square (up to 10) some of the time, or a regular polygon of 3 to 10 corners turned and moved at random.
ConvexPolygon randomPolygon(test::RandomSource& random, Real size) {
  auto point = [&] { return Vector2r(random.uniform(-size, size), random.uniform(-size, size)); };
  if (random.uniform(0, 1) < 0.2) {
    const int corners = 3 + static_cast<int>(random.uniform(0, 8));
    const Real turn = random.uniform(0, 2 * M_PI), radius = random.uniform(0.1, 1) * size;
    const Vector2r centre = 0.5 * point();
    ConvexPolygon p;
    for (int k = 0; k < corners; ++k) {
      const Real angle = turn + 2 * M_PI * k / corners;
      p.push(centre + radius * Vector2r(std::cos(angle), std::sin(angle)));
    }
    return p;
  }
  for (;;) {
    ConvexPolygon p = ConvexPolygon::triangle(point(), point(), point());
    if (random.uniform(0, 1) < 0.7) p = p.intersection(ConvexPolygon::triangle(point(), point(), point()));
    if (random.uniform(0, 1) < 0.5)
      p = p.intersection(ConvexPolygon::rectangle(Vector2r::Zero(), 0.5 * size, 0.5 * size));
    if (!p.empty()) return p;
  }
}

TEST(FanQuadrature, RandomPolygonsGiveTheReferencePointsBitForBit) {
  const QuadratureColumns& q = dunavant8Columns();
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(4139);
    long lanes = 0, outside = 0, inside = 0;
    int largest = 0;
    for (long trial = 0; trial < 100000; ++trial) {
      const Real size = std::exp(random.uniform(std::log(1e-6), std::log(1.0)));
      const ConvexPolygon s = randomPolygon(random, size);
      const Real a = size * random.uniform(0.05, 2.0);
      FanQuadrature batched;
      fanQuadrature(s, a * a, batched);
      ASSERT_EQ(batched.triangles, s.size() - 2);
      largest = std::max(largest, s.size());
      for (int j = 1; j + 1 < s.size(); ++j) {
        const Vector2r &p0 = s[0], &p1 = s[j], &p2 = s[j + 1];
        const Real area = 0.5 * cross2(p1 - p0, p2 - p0);
        const QuadratureColumn x = q.l1 * p0.x() + q.l2 * p1.x() + q.l3 * p2.x();
        const QuadratureColumn y = q.l1 * p0.y() + q.l2 * p1.y() + q.l3 * p2.y();
        const QuadratureColumn dG = area * q.weight * (a * a - (x.square() + y.square())).max(Real(0)).sqrt();
        for (int i = 0; i < FanQuadrature::kPoints; ++i) {
          const int at = FanQuadrature::kPoints * (j - 1) + i;
          ASSERT_TRUE(sameBits(batched.x[at], x[i]) && sameBits(batched.y[at], y[i]) && sameBits(batched.dG[at], dG[i]))
              << "trial " << trial << ", triangle " << j << ", point " << i << ": " << batched.dG[at] << " vs "
              << dG[i];
          ++lanes;
          (dG[i] == 0 ? outside : inside) += 1;
        }
      }
    }
    EXPECT_EQ(largest, ConvexPolygon::kCapacity);  // every fan length up to the capacity was drawn
    EXPECT_GT(outside, lanes / 10);
    EXPECT_GT(inside, lanes / 10);
  });
}

// Over a square that holds the circle, the shape's integral is 2 pi a^3 / 3 (the Hertz pressure's volume over its
// amplitude). The rule is exact to degree 8 and sqrt(a^2 - r^2) is not a polynomial (its slope is infinite at the
// rim): on this fan of 2 triangles the error is a few per cent (measured 3.9 %); 5 % bounds it, and the moment of a
// centred circle is 0 to rounding.
TEST(FanQuadrature, ShapeIntegralOverTheWholeCircle) {
  const Real a = 0.3;
  FanQuadrature points;
  fanQuadrature(ConvexPolygon::rectangle(Vector2r::Zero(), a, a), a * a, points);
  ASSERT_EQ(points.triangles, 2);
  Real integral = 0, momentX = 0;
  for (int i = 0; i < 2 * FanQuadrature::kPoints; ++i) {
    integral += points.dG[i];
    momentX += points.dG[i] * points.x[i];
  }
  EXPECT_NEAR(integral, 2 * M_PI * a * a * a / 3, 0.05 * 2 * M_PI * a * a * a / 3);
  EXPECT_NEAR(momentX, 0, 1e-12 * integral * a);
}

}  // namespace
}  // namespace roundedmesh
