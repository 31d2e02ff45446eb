// Eq. 11: the 16-point rule integrates every polynomial of degree <= 8 exactly on a triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/math/DunavantRule.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

Real factorial(int n) { return std::tgamma(n + 1.0); }

// Integral of l1^i l2^j over the reference triangle (0,0), (1,0), (0,1) divided by its area 1/2:
// 2 * i! j! / (i + j + 2)!  (Dirichlet's formula).
Real exactMean(int i, int j) { return 2 * factorial(i) * factorial(j) / factorial(i + j + 2); }

Real ruleMean(int i, int j) {
  Real sum = 0;
  for (const QuadraturePoint& q : kDunavant8) sum += q.weight * std::pow(q.l1, i) * std::pow(q.l2, j);
  return sum;
}

TEST(DunavantRule, WeightsSumToOneAndPointsAreBarycentric) {
  Real total = 0;
  for (const QuadraturePoint& q : kDunavant8) {
    EXPECT_NEAR(q.l1 + q.l2 + q.l3, 1.0, 1e-14);
    EXPECT_GT(q.weight, 0);
    total += q.weight;
  }
  EXPECT_NEAR(total, 1.0, 1e-14);
}

// Tolerance 1e-13: the published weights and points carry 15 significant digits, so a rule that is exact
// in exact arithmetic reproduces the moments to a few 1e-15 (measured: 2e-15 at worst).
TEST(DunavantRule, IntegratesEveryMonomialUpToDegreeEightExactly) {
  for (int degree = 0; degree <= 8; ++degree)
    for (int i = 0; i <= degree; ++i) {
      const int j = degree - i;
      EXPECT_NEAR(ruleMean(i, j), exactMean(i, j), 1e-13 * exactMean(i, j)) << "l1^" << i << " l2^" << j;
    }
}

// The rule is of degree 8 and no more: some degree-9 monomial is off by far more than round-off.
TEST(DunavantRule, IsNotExactAtDegreeNine) {
  Real worst = 0;
  for (int i = 0; i <= 9; ++i) worst = std::max(worst, std::abs(ruleMean(i, 9 - i) / exactMean(i, 9 - i) - 1));
  EXPECT_GT(worst, 1e-5);
}

// Exactness on an arbitrary triangle through the affine map, against a Duffy-collapsed Gauss-Legendre
// product rule: the collapsed integrand of this degree-8 polynomial has degree <= 17 per variable, which
// 10 points per direction integrate exactly. Tolerance 1e-12 relative: round-off of both sums.
TEST(DunavantRule, IsExactOnAGeneralTriangle) {
  const Vector2r p0(0.3, -0.2), p1(1.7, 0.4), p2(0.1, 1.3);
  const Real area = 0.5 * std::abs(cross2(p1 - p0, p2 - p0));
  auto f = [](const Vector2r& x) { return std::pow(x.x(), 3) * std::pow(x.y(), 5) + x.x() * x.y() - 2; };
  Real rule = 0;
  for (const QuadraturePoint& q : kDunavant8) rule += area * q.weight * f(q.l1 * p0 + q.l2 * p1 + q.l3 * p2);

  std::vector<Real> x, w;
  test::gaussLegendre(10, x, w);
  Real reference = 0;
  for (size_t a = 0; a < x.size(); ++a)
    for (size_t b = 0; b < x.size(); ++b) {
      const Real u = 0.5 * (x[a] + 1), v = 0.5 * (x[b] + 1);
      reference += 0.25 * w[a] * w[b] * (1 - u) * f(p0 + u * (p1 - p0) + v * (1 - u) * (p2 - p0));
    }
  reference *= 2 * area;
  EXPECT_NEAR(rule, reference, 1e-12 * std::abs(reference));
}

}  // namespace
}  // namespace roundedmesh
