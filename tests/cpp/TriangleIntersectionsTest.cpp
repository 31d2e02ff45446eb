// The polygons S clipped in lanes (TriangleIntersections.hpp) are ConvexPolygon's bit for bit: for 2 x 10^5 random
// triangle pairs, every lane's corners (their number, order and bits) and its point closest to the origin against
// ConvexPolygon::intersection and closestPoint, on every instruction set the processor has and the build compiled (on
// an AVX-512 machine: AVX3, AVX2, SSE4, SSSE3 and Highway's scalar fallback). No tolerance: the lanes run the
// reference's operations in its order. The pairs are those a narrow phase meets (Q is P turned a little and moved by
// up to its size) and harder ones: unrelated triangles from far apart to one inside the other, pairs sharing a corner
// or an edge exactly, corners on the other's edge lines, slivers, and sizes from 1e-6 to 1; batches of 1 to 16 lanes.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/math/TriangleIntersections.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh {
namespace {

using test::sameBits;

struct TrianglePairInPlane {
  ConvexPolygon p, q;
};

TrianglePairInPlane randomPair(test::RandomSource& random) {
  const Real size = std::exp(random.uniform(std::log(1e-6), std::log(1.0)));
  auto point = [&](Real spread) { return Vector2r(random.uniform(-spread, spread), random.uniform(-spread, spread)); };
  const Vector2r a = point(size), b = point(size), c = point(size);
  const Real kind = random.uniform(0, 1);
  if (kind < 0.5) {  // touching surfaces: Q is P turned by up to 30 degrees and moved by up to half its size
    const Matrix2r turn = Eigen::Rotation2D<Real>(random.uniform(-0.5, 0.5)).toRotationMatrix();
    const Vector2r shift = point(0.5 * size);
    return {ConvexPolygon::triangle(a, b, c), ConvexPolygon::triangle(turn * a + shift, turn * b + shift, turn * c + shift)};
  }
  if (kind < 0.7) {  // unrelated: apart, crossing, or one inside the other
    const Real spread = size * random.uniform(0.1, 3);
    return {ConvexPolygon::triangle(a, b, c), ConvexPolygon::triangle(point(spread), point(spread), point(spread))};
  }
  if (kind < 0.8)  // a shared corner
    return {ConvexPolygon::triangle(a, b, c), ConvexPolygon::triangle(a, point(size), point(size))};
  if (kind < 0.9)  // a shared edge, from either side
    return {ConvexPolygon::triangle(a, b, c), ConvexPolygon::triangle(b, a, point(size))};
  // Q's corners on the lines of P's edges (rounded onto them), and a sliver
  const Vector2r onAB = a + random.uniform(-0.5, 1.5) * (b - a), onBC = b + random.uniform(-0.5, 1.5) * (c - b);
  return {ConvexPolygon::triangle(a, b, c), ConvexPolygon::triangle(onAB, onBC, onAB + 1e-9 * (onBC - onAB) + point(1e-12))};
}

// The engine's narrow phase takes the lanes where the vector unit holds 4 doubles or more (AVX2, AVX-512), where
// they take about 30 % off it, and not on units of 2 (SSE4, SSSE3), where they save nothing (doc/benchmarks.md,
// Speed III, step 11).
TEST(TriangleIntersections, LanesRunWhereTheVectorUnitHoldsFourDoubles) {
  test::forEachInstructionSet([](int64_t target) {
    const bool fourOrMore = (target & (HWY_AVX2 | HWY_AVX3 | HWY_AVX3_DL)) != 0;
    EXPECT_EQ(triangleIntersectionsPay(), fourOrMore);
  });
}

TEST(TriangleIntersections, EveryLaneIsConvexPolygonsBitForBit) {
  test::forEachInstructionSet([&](int64_t) {
    test::RandomSource random(5821);
    long lanes = 0, empty = 0, clipped = 0, overflowed = 0;
    TriangleIntersections batch;
    std::vector<TrianglePairInPlane> pairs;
    while (lanes < 200000) {
      batch.size = 1 + static_cast<int>(random.uniform(0, TriangleIntersections::kCapacity));
      batch.size = std::min(batch.size, TriangleIntersections::kCapacity);
      pairs.clear();
      for (int k = 0; k < batch.size; ++k) {
        pairs.push_back(randomPair(random));
        batch.set(k, pairs[k].p, pairs[k].q);
      }
      intersectTriangles(batch);
      for (int k = 0; k < batch.size; ++k, ++lanes) {
        if (batch.overflowed(k)) {
          ++overflowed;
          continue;
        }
        const ConvexPolygon reference = pairs[k].p.intersection(pairs[k].q), lane = batch.polygon(k);
        ASSERT_EQ(lane.size(), reference.size()) << "lane " << lanes;
        for (int i = 0; i < lane.size(); ++i) ASSERT_TRUE(sameBits(lane[i], reference[i])) << "lane " << lanes;
        if (reference.empty()) {
          ++empty;
          continue;
        }
        ASSERT_TRUE(sameBits(batch.closestPoint(k), reference.closestPoint(Vector2r::Zero()))) << "lane " << lanes;
        clipped += reference.size() > 3;
      }
    }
    // Both outcomes common; a lane left to ConvexPolygon (rounding making a sliver look non-convex) is rare.
    EXPECT_GT(empty, 10000);
    EXPECT_GT(clipped, 50000);
    EXPECT_LT(overflowed, 1e-3 * lanes);
  });
}

}  // namespace
}  // namespace roundedmesh
