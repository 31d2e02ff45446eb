#include "pkg/meshing/RoundedTetrahedron.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace roundedmesh {

std::array<Vector3r, 4> tetrahedronFaceNormals() {
  const Real k = 1 / std::sqrt(Real(3));
  return {Vector3r(k, k, k), Vector3r(k, -k, -k), Vector3r(-k, k, -k), Vector3r(-k, -k, k)};
}

ImplicitSolid implicitSolid(const RoundedTetrahedron& t) {
  if (!(std::isfinite(t.inradius) && t.inradius > 0))
    throw std::invalid_argument("rounded tetrahedron inradius must be positive and finite, got " +
                                std::to_string(t.inradius));
  // Along a corner's direction f = s ln(3 e^(u/3s) + e^(-u/s)) - h > s ln 3 - h at u = 0: beyond h / ln 3 the
  // corners are gone and the solid is no longer a tetrahedron's.
  if (!(std::isfinite(t.rounding) && t.rounding > 0 && t.rounding < t.inradius / std::log(Real(3))))
    throw std::invalid_argument("rounded tetrahedron rounding must be in (0, inradius / ln 3) = (0, " +
                                std::to_string(t.inradius / std::log(Real(3))) + "), got " + std::to_string(t.rounding));
  const std::array<Vector3r, 4> normals = tetrahedronFaceNormals();
  return {[t, normals](const Vector3r& x) {
            std::array<Real, 4> heights;
            for (int i = 0; i < 4; ++i) heights[i] = normals[i].dot(x) / t.rounding;
            const Real top = *std::max_element(heights.begin(), heights.end());  // log-sum-exp without overflow
            Real sum = 0;
            for (Real h : heights) sum += std::exp(h - top);
            return t.rounding * (top + std::log(sum)) - t.inradius;
          },
          Vector3r::Zero(), 3 * t.inradius, 2 * std::min(t.inradius, 3 * t.rounding)};
}

}  // namespace roundedmesh
