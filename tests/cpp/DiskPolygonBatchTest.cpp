// The closed forms in lanes (DiskPolygonBatch.hpp) against their scalar reference (DiskPolygonIntegrals.hpp), polygon
// by polygon and edge by edge. The lanes repeat the reference's operations in its order without fused multiply-add;
// only the arctangents differ (Highway's polynomial to 3 ulp against the C library's): at most about 2e-15 rad in
// each of three angles per edge, each multiplied by at most a^3 (a^4 along an edge, a^5 for E) and summed over at
// most ten edges, so the tolerance is 1e-14 of the whole disc's values (on AVX-512 these cases agreed within 1e-15
// when it was written). Polygons: random triangles and their clips (as DiskPolygonIntegralsTest), the cases where
// the reference's angles must cancel (a corner at the centre, an edge through it), a chord that barely cuts the
// circle, the disc inside S, S outside the disc, a repeated corner, and full batches of ten-cornered polygons, on
// every instruction set. The edges' directions are Eigen's, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "pkg/math/DiskPolygonBatch.hpp"
#include "tests/support/HighwayTargets.hpp"

namespace roundedmesh {
namespace {

struct Case {
  Real a;
  ConvexPolygon polygon;
};

void expectLanesMatch(const std::vector<Case>& cases) {
  for (size_t first = 0; first < cases.size(); first += DiskPolygonBatch::kPolygons) {
    DiskPolygonBatch batch;
    const size_t count = std::min<size_t>(DiskPolygonBatch::kPolygons, cases.size() - first);
    for (size_t k = 0; k < count; ++k) batch.add(cases[first + k].a, cases[first + k].polygon);
    integrateDiskPolygons(batch);
    for (size_t k = 0; k < count; ++k) {
      const auto& [a, s] = cases[first + k];
      const DiskPolygonIntegrals lanes = batch.integrals(static_cast<int>(k)), scalar = diskPolygonIntegrals(a, s);
      const Real p = 2 * M_PI / 3 * std::pow(a, 3), e = 2 * M_PI / 5 * std::pow(a, 5);
      const std::string what = "polygon " + std::to_string(first + k);
      EXPECT_NEAR(lanes.pressure, scalar.pressure, 1e-14 * p) << what;
      EXPECT_NEAR(lanes.pressureMoment.x(), scalar.pressureMoment.x(), 1e-14 * p * a) << what;
      EXPECT_NEAR(lanes.pressureMoment.y(), scalar.pressureMoment.y(), 1e-14 * p * a) << what;
      EXPECT_NEAR(lanes.energy, scalar.energy, 1e-14 * e) << what;
      for (int i = 0; i < (s.empty() ? 0 : s.size()); ++i) {
        const EdgeIntegrals lane = batch.edge(static_cast<int>(k), i);
        const EdgeIntegrals reference = edgeIntegrals(a, s[i], s[(i + 1) % s.size()]);
        EXPECT_NEAR(lane.energy, reference.energy, 1e-14 * std::pow(a, 4)) << what << ", edge " << i;
        EXPECT_NEAR(lane.energyMoment, reference.energyMoment, 1e-14 * std::pow(a, 4)) << what << ", edge " << i;
        const Vector2r d = s[(i + 1) % s.size()] - s[i];
        if (a > 0 && d.squaredNorm() > 0) {
          EXPECT_EQ(batch.direction(static_cast<int>(k), i), d.normalized()) << what;
        }
      }
    }
  }
}

ConvexPolygon turned(const ConvexPolygon& s, Real angle) {
  ConvexPolygon out;
  for (int i = 0; i < s.size(); ++i)
    out.push(Vector2r(s[i].x() * std::cos(angle) - s[i].y() * std::sin(angle),
                      s[i].x() * std::sin(angle) + s[i].y() * std::cos(angle)));
  return out;
}

TEST(DiskPolygonBatch, LanesMatchTheScalarClosedForms) {
  std::vector<Case> cases = {
      {1, ConvexPolygon::triangle({0.1, 0.1}, {0.5, 0.2}, {0.2, 0.6})},       // inside
      {1, ConvexPolygon::triangle({0.3, -0.2}, {1.6, 0.4}, {0.5, 1.4})},      // straddling
      {1, ConvexPolygon::triangle({-0.9, -0.8}, {1.2, -0.3}, {0.1, 1.3})},    // around the centre
      {1, ConvexPolygon::triangle({-1.5, 0}, {1.5, 0}, {0.2, 0.8})},          // an edge through the centre
      {1, ConvexPolygon::triangle({-1.2, 0.7}, {1.2, 0.7}, {0.0, 0.71})},     // a sliver on a chord
      {1, ConvexPolygon::triangle({-2, 0.99999}, {2, 0.99999}, {0, 3})},      // a chord that barely cuts the circle
      {1, ConvexPolygon::rectangle({0.1, 0}, 3, 3)},                          // the disc inside S
      {1, ConvexPolygon::rectangle({5, 5}, 1, 1)},                            // S outside the disc
      {1, ConvexPolygon::triangle({0, -0.0}, {-0.0, 0}, {0.5, 0.5})},        // a repeated corner at the centre
      {2e-3, ConvexPolygon::rectangle({1e-3, 0}, 1e-3, 2.5e-3)},              // contact-sized
      {0, ConvexPolygon::rectangle({0, 0}, 1, 1)},                            // no disc
      {1, ConvexPolygon()},                                                   // no polygon
  };
  for (int k = 0; k < 12; ++k)  // a corner at the centre: h = 0 up to round-off of either sign
    cases.push_back({1, turned(ConvexPolygon::triangle({0, 0}, {1.5, 0.2}, {0.3, 0.7}), 0.37 + k * M_PI / 6)});
  std::mt19937 random(11);
  std::uniform_real_distribution<Real> corner(-1.6, 1.6), unit(0, 1);
  for (int n = 0; n < 200; ++n) {
    ConvexPolygon s = ConvexPolygon::triangle({corner(random), corner(random)}, {corner(random), corner(random)},
                                              {corner(random), corner(random)});
    if (n % 2) s = s.intersection(ConvexPolygon::rectangle({corner(random) / 2, corner(random) / 2}, 0.8, 0.6));
    cases.push_back({0.5 + unit(random), s});
  }
  // Full batches: 16 polygons of ten corners, 160 edges.
  for (int n = 0; n < 32; ++n) {
    ConvexPolygon s;
    const Real offset = corner(random) / 2, size = 0.6 + unit(random);
    for (int i = 0; i < ConvexPolygon::kCapacity; ++i) {
      const Real angle = 2 * M_PI * i / ConvexPolygon::kCapacity;
      s.push(Vector2r(offset + size * std::cos(angle), size * std::sin(angle)));
    }
    cases.push_back({1, s});
  }
  test::forEachInstructionSet([&](int64_t) { expectLanesMatch(cases); });
}

}  // namespace
}  // namespace roundedmesh
