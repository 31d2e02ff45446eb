#include "pkg/shape/CapTolerance.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace roundedmesh {

namespace {

// The circumradius rho and the half-width w of triangle t [m].
struct CapBase {
  Real rho, w;
};

CapBase capBase(const TriangleSurface& surface, std::size_t t) {
  const Triangle& c = surface.triangles[t];
  const Vector3r &a = surface.vertices[c[0]], &b = surface.vertices[c[1]], &d = surface.vertices[c[2]];
  const Real rho = (a - circumcentre(a, b, d)).norm();
  std::array<Real, 3> squared{(b - a).squaredNorm(), (d - b).squaredNorm(), (a - d).squaredNorm()};
  std::sort(squared.begin(), squared.end());
  const bool obtuse = squared[2] > squared[0] + squared[1];
  return {rho, obtuse ? std::sqrt(squared[2]) / 2 : rho};
}

Real capHeight(Real radius, const CapBase& base) {
  const Real centreDepthSq = std::max(radius * radius - base.rho * base.rho, Real(0));
  return std::sqrt(centreDepthSq + base.w * base.w) - std::sqrt(centreDepthSq);
}

}  // namespace

std::vector<Real> capHeights(const TriangleSurface& surface, const std::vector<Real>& radii) {
  std::vector<Real> heights(surface.triangles.size());
  for (std::size_t t = 0; t < heights.size(); ++t) heights[t] = capHeight(radii[t], capBase(surface, t));
  return heights;
}

int boundCapHeights(const TriangleSurface& surface, Real maxHeight, std::vector<Real>& radii,
                    std::vector<PrincipalCurvature>& principal) {
  int raised = 0;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const CapBase base = capBase(surface, t);
    if (capHeight(radii[t], base) <= maxHeight) continue;
    const Real centreDepth = std::max((base.w * base.w - maxHeight * maxHeight) / (2 * maxHeight), Real(0));
    radii[t] = std::sqrt(centreDepth * centreDepth + base.rho * base.rho);
    if (!principal.empty()) {
      principal[t].k1 = std::min(principal[t].k1, 1 / radii[t]);
      principal[t].k2 = std::min(principal[t].k2, 1 / radii[t]);
    }
    ++raised;
  }
  return raised;
}

}  // namespace roundedmesh
