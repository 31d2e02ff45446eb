// Shared helpers of the GoogleTest suite: independent reference computations that do not use the code
// under test.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh::test {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton iteration on the Legendre polynomial).
inline void gaussLegendre(int n, std::vector<Real>& x, std::vector<Real>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    Real z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      Real p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const Real pk = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const Real step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// Integral of f over the rectangle [x0, x1] x [y0, y1] by an n x n Gauss-Legendre product rule.
inline Real integrateRectangle(const std::function<Real(Real, Real)>& f, Real x0, Real x1, Real y0, Real y1, int n) {
  std::vector<Real> x, w;
  gaussLegendre(n, x, w);
  Real sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      sum += w[i] * w[j] * f(0.5 * (x0 + x1) + 0.5 * (x1 - x0) * x[i], 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * x[j]);
  return 0.25 * (x1 - x0) * (y1 - y0) * sum;
}

}  // namespace roundedmesh::test
