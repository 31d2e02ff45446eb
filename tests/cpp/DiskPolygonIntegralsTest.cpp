// The closed-form integrals of DiskPolygonIntegrals.hpp against the whole disc's closed forms (round-off: 1e-13
// of the disc's value) and against an independent numerical integral over S n Omega: tanh-sinh quadrature in x
// over pieces split where the region's outline bends (corners, crossings of edges and circle, x = +-a), and in y
// between the region's bottom and top at each x; tanh-sinh converges past the square-root edges of the integrand and
// of the circle, to about 1e-13 here, so the tolerance is 1e-11 of the disc's value (the closed form is exact to
// round-off, 1e-15).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "pkg/math/DiskPolygonIntegrals.hpp"

namespace roundedmesh {
namespace {

// Tanh-sinh quadrature over [lo, hi] of f, which returns the four integrands at once.
using Four = Eigen::Array<Real, 4, 1>;
Four tanhSinh(const std::function<Four(Real)>& f, Real lo, Real hi) {
  if (!(hi > lo)) return Four::Zero();
  const Real h = 1.0 / 64, half = (hi - lo) / 2, mid = (hi + lo) / 2;
  Four sum = Four::Zero();
  for (int k = -6 * 64; k <= 6 * 64; ++k) {
    const Real t = k * h, u = M_PI / 2 * std::sinh(t);
    const Real x = std::tanh(u), weight = M_PI / 2 * std::cosh(t) / (std::cosh(u) * std::cosh(u));
    if (weight < 1e-300 || std::abs(x) >= 1) continue;
    sum += weight * f(mid + half * x);
  }
  return sum * h * half;
}

struct Reference {
  Real pressure, momentX, momentY, energy;
};

// The y-interval of the polygon n disc at x, empty if lo > hi.
std::pair<Real, Real> chord(const ConvexPolygon& s, Real a, Real x) {
  Real lo = -std::sqrt(std::max(a * a - x * x, Real(0))), hi = -lo;
  for (int i = 0; i < s.size(); ++i) {
    const Vector2r& p = s[i];
    const Vector2r& q = s[(i + 1) % s.size()];
    if (p.x() == q.x()) {
      if ((q.y() - p.y()) * (x - p.x()) > 0) return {1, -1};  // right of a vertical edge going up: outside
      continue;
    }
    const Real y = p.y() + (q.y() - p.y()) * (x - p.x()) / (q.x() - p.x());
    // Counter-clockwise: an edge going left (q.x < p.x) bounds the region from above, going right from below.
    if (q.x() < p.x()) hi = std::min(hi, y); else lo = std::max(lo, y);
  }
  return {lo, hi};
}

Reference numerically(const ConvexPolygon& s, Real a) {
  std::vector<Real> cuts = {-a, a};
  for (int i = 0; i < s.size(); ++i) {
    const Vector2r& p = s[i];
    const Vector2r& q = s[(i + 1) % s.size()];
    cuts.push_back(p.x());
    const Vector2r d = q - p;  // crossings of the edge and the circle
    const Real A = d.squaredNorm(), B = p.dot(d), C = p.squaredNorm() - a * a, D = B * B - A * C;
    if (A > 0 && D > 0)
      for (Real t : {(-B - std::sqrt(D)) / A, (-B + std::sqrt(D)) / A})
        if (t > 0 && t < 1) cuts.push_back(p.x() + t * d.x());
  }
  std::sort(cuts.begin(), cuts.end());
  Four sum = Four::Zero();
  auto inner = [&](Real x) {
    const auto [lo, hi] = chord(s, a, x);
    return tanhSinh([&](Real y) {
      const Real w = std::sqrt(std::max(a * a - x * x - y * y, Real(0)));
      return Four(w, x * w, y * w, w * w * w);
    }, lo, hi);
  };
  for (size_t k = 0; k + 1 < cuts.size(); ++k) sum += tanhSinh(inner, std::max(cuts[k], -a), std::min(cuts[k + 1], a));
  const Reference r{sum[0], sum[1], sum[2], sum[3]};
  return r;
}

void expectMatches(const ConvexPolygon& s, Real a, const char* what) {
  const DiskPolygonIntegrals exact = diskPolygonIntegrals(a, s);
  const Reference ref = numerically(s, a);
  const Real p = 2 * M_PI / 3 * a * a * a, e = 2 * M_PI / 5 * std::pow(a, 5);
  EXPECT_NEAR(exact.pressure, ref.pressure, 1e-11 * p) << what;
  EXPECT_NEAR(exact.pressureMoment.x(), ref.momentX, 1e-11 * p * a) << what;
  EXPECT_NEAR(exact.pressureMoment.y(), ref.momentY, 1e-11 * p * a) << what;
  EXPECT_NEAR(exact.energy, ref.energy, 1e-11 * e) << what;
}

TEST(DiskPolygonIntegrals, TheWholeDiscGivesHertzsForceAndPotential) {
  for (Real a : {1e-4, 1.0, 3.0}) {
    const DiskPolygonIntegrals whole = diskPolygonIntegrals(a, ConvexPolygon::rectangle(Vector2r(0.1 * a, 0), 2 * a, 3 * a));
    EXPECT_NEAR(whole.pressure, 2 * M_PI / 3 * a * a * a, 1e-13 * a * a * a);
    EXPECT_NEAR(whole.energy, 2 * M_PI / 5 * std::pow(a, 5), 1e-13 * std::pow(a, 5));
    EXPECT_NEAR(whole.pressureMoment.norm(), 0, 1e-13 * std::pow(a, 4));
  }
}

TEST(DiskPolygonIntegrals, HalfDiscAndNothing) {
  const Real a = 2;
  const DiskPolygonIntegrals half = diskPolygonIntegrals(a, ConvexPolygon::rectangle(Vector2r(5, 0), 5, 5));
  EXPECT_NEAR(half.pressure, M_PI / 3 * a * a * a, 1e-13);
  EXPECT_NEAR(half.energy, M_PI / 5 * std::pow(a, 5), 1e-12);
  // First moment of w over the half disc x > 0: integral of r cos(theta) sqrt(a^2 - r^2) r dr dtheta = 2 (pi a^4 / 16).
  EXPECT_NEAR(half.pressureMoment.x(), M_PI * std::pow(a, 4) / 8, 1e-12);
  EXPECT_NEAR(half.pressureMoment.y(), 0, 1e-12);
  const DiskPolygonIntegrals none = diskPolygonIntegrals(a, ConvexPolygon::rectangle(Vector2r(5, 5), 1, 1));
  EXPECT_EQ(none.pressure, 0);
  EXPECT_EQ(none.energy, 0);
  EXPECT_TRUE(none.pressureMoment.isZero(0));
}

TEST(DiskPolygonIntegrals, MatchNumericalIntegration) {
  const Real a = 1;
  // Inside, straddling the circle, around the centre, a corner at the centre, an edge through the centre, and a
  // sliver along a chord.
  expectMatches(ConvexPolygon::triangle({0.1, 0.1}, {0.5, 0.2}, {0.2, 0.6}), a, "inside");
  expectMatches(ConvexPolygon::triangle({0.3, -0.2}, {1.6, 0.4}, {0.5, 1.4}), a, "straddling");
  expectMatches(ConvexPolygon::triangle({-0.9, -0.8}, {1.2, -0.3}, {0.1, 1.3}), a, "around the centre");
  expectMatches(ConvexPolygon::triangle({0, 0}, {1.5, 0.2}, {0.3, 1.1}), a, "corner at the centre");
  expectMatches(ConvexPolygon::triangle({-1.5, 0}, {1.5, 0}, {0.2, 0.8}), a, "edge through the centre");
  expectMatches(ConvexPolygon::triangle({-1.2, 0.7}, {1.2, 0.7}, {0.0, 0.71}), a, "sliver on a chord");
  // A corner at the centre, turned: the edges from it have h = 0 up to round-off of either sign, where the whole
  // angle and the cone's atan2 term must take the same sign to cancel.
  for (int k = 0; k < 12; ++k) {
    const Real turn = 0.37 + k * M_PI / 6;
    auto turned = [&](Real x, Real y) {
      return Vector2r(x * std::cos(turn) - y * std::sin(turn), x * std::sin(turn) + y * std::cos(turn));
    };
    expectMatches(ConvexPolygon::triangle({0, 0}, turned(1.5, 0.2), turned(0.3, 0.7)), a,
                  "corner at the centre, turned");
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> corner(-1.6, 1.6);
  for (int n = 0; n < 24; ++n) {
    ConvexPolygon s = ConvexPolygon::triangle({corner(random), corner(random)}, {corner(random), corner(random)},
                                              {corner(random), corner(random)});
    if (n % 2) s = s.intersection(ConvexPolygon::rectangle({corner(random) / 2, corner(random) / 2}, 0.8, 0.6));
    if (!s.empty()) expectMatches(s, a, "random");
  }
}

// A corner repeated (clipping can leave one) adds nothing, even at the centre with zeros of both signs, whose atan2
// is pi: the same integrals as without it, bit for bit.
TEST(DiskPolygonIntegrals, ARepeatedCornerAddsNothing) {
  ConvexPolygon repeated;
  for (const Vector2r& corner : {Vector2r(0, -0.0), Vector2r(-0.0, 0), Vector2r(0.5, 0.1), Vector2r(0.2, 0.6)})
    repeated.push(corner);
  const DiskPolygonIntegrals with = diskPolygonIntegrals(1, repeated);
  const DiskPolygonIntegrals without = diskPolygonIntegrals(1, ConvexPolygon::triangle({0, 0}, {0.5, 0.1}, {0.2, 0.6}));
  EXPECT_EQ(with.pressure, without.pressure);
  EXPECT_EQ(with.pressureMoment, without.pressureMoment);
  EXPECT_EQ(with.energy, without.energy);
}

// Along an edge P Q, its part inside the disc: the integrals of w^3 ds and lambda w^3 ds (lambda from 0 at P to 1 at
// Q) against tanh-sinh quadrature over that part (1e-12 of a^4: both exact to round-off there). The edges run
// inside, across the circle once or twice, outside, and through the centre.
TEST(DiskPolygonIntegrals, EdgeIntegralsMatchNumericalIntegration) {
  const Real a = 1.3;
  std::mt19937 random(3);
  std::uniform_real_distribution<Real> corner(-2, 2);
  std::vector<std::pair<Vector2r, Vector2r>> edges = {{{-2, 0}, {2, 0}}, {{0.1, 0.2}, {-0.3, 0.5}},
                                                      {{-2, 1.3}, {2, 1.3}}, {{0.2, -0.1}, {1.9, 1.2}}};
  for (int n = 0; n < 40; ++n) edges.push_back({{corner(random), corner(random)}, {corner(random), corner(random)}});
  for (size_t n = 0; n < edges.size(); ++n) {
    const auto& [P, Q] = edges[n];
    const EdgeIntegrals exact = edgeIntegrals(a, P, Q);
    // The part inside: where |P + lambda (Q - P)| < a, lambda in [0, 1].
    const Vector2r d = Q - P;
    const Real qa = d.squaredNorm(), qb = P.dot(d), qc = P.squaredNorm() - a * a, D = qb * qb - qa * qc;
    Four sum = Four::Zero();
    if (D > 0) {
      const Real lo = std::max(Real(0), (-qb - std::sqrt(D)) / qa), hi = std::min(Real(1), (-qb + std::sqrt(D)) / qa);
      sum = tanhSinh([&](Real l) {
        const Real w = std::sqrt(std::max(a * a - (P + l * d).squaredNorm(), Real(0)));
        return Four(w * w * w, l * w * w * w, 0, 0);
      }, lo, hi) * d.norm();
    }
    EXPECT_NEAR(exact.energy, sum[0], 1e-12 * std::pow(a, 4)) << n;
    EXPECT_NEAR(exact.energyMoment, sum[1], 1e-12 * std::pow(a, 4)) << n;
  }
}

}  // namespace
}  // namespace roundedmesh
