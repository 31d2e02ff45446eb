// Shared helpers of the GoogleTest suite: independent reference computations that do not use the code
// under test.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "pkg/engine/BodyState.hpp"
#include "pkg/engine/ContactModel.hpp"
#include "pkg/math/ConvexPolygon.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh::test {

// The message of the std::invalid_argument that `read` throws, or "accepted" if it throws none.
template <class Read>
std::string refusal(Read read) {
  try {
    read();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// Torus with tube radius r around a circle of radius R in the xy plane: a regular (u, v) grid, each quad
// split in two. v = 0 on the outer equator. Principal curvatures 1/r around the tube and cos v / (R + r cos v)
// around the axis (negative on the inner side); mean curvature H = (R + 2 r cos v) / (2 r (R + r cos v)).
inline TriangleSurface torus(Real R, Real r, int around, int tube) {
  TriangleSurface s;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const Real u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
      s.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto node = [&](int i, int j) { return (i % around) * tube + (j % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      s.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      s.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  return s;
}

// A body state at `position` turned by `orientation`, at rest.
inline BodyState at(const Vector3r& position, const Quaternionr& orientation = Quaternionr::Identity()) {
  BodyState s;
  s.position = position;
  s.orientation = orientation;
  return s;
}

// Facets with these corners (in the world's frame: each facet's state is at(0)) as one body's partners of `material`,
// their ids their indices, for surfaceContact, which welds them into surfaces.
inline std::vector<Partner> facetPartners(const std::vector<std::array<Vector3r, 3>>& facets,
                                          const HertzMaterial& material) {
  std::vector<Partner> partners;
  for (size_t f = 0; f < facets.size(); ++f) partners.push_back({static_cast<int>(f), Facet{facets[f], nullptr}, material});
  return partners;
}

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

// Independent reference: integrate, over x, the length of the vertical chord shared by the disc and the
// convex polygon (the polygon's chord from its edges, the disc's from sqrt(a^2 - x^2)). Midpoint rule with
// n slices; the integrand is continuous with square-root ends, so the error is O(n^-1.5): about 1e-9
// relative for n = 2e6.
inline Real sliceIntegratedArea(Real a, const ConvexPolygon& polygon, int n = 2000000) {
  Real area = 0;
  const Real h = 2 * a / n;
  for (int i = 0; i < n; ++i) {
    const Real x = -a + (i + 0.5) * h;
    Real lo = -std::sqrt(std::max(a * a - x * x, Real(0))), hi = -lo;
    Real polyLo = std::numeric_limits<Real>::infinity(), polyHi = -polyLo;
    for (int k = 0; k < polygon.size(); ++k) {
      const Vector2r p = polygon[k], q = polygon[(k + 1) % polygon.size()];
      if ((p.x() - x) * (q.x() - x) > 0 || p.x() == q.x()) continue;
      const Real y = p.y() + (x - p.x()) / (q.x() - p.x()) * (q.y() - p.y());
      polyLo = std::min(polyLo, y);
      polyHi = std::max(polyHi, y);
    }
    if (polyLo > polyHi) continue;
    area += std::max(std::min(hi, polyHi) - std::max(lo, polyLo), Real(0)) * h;
  }
  return area;
}

}  // namespace roundedmesh::test
