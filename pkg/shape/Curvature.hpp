// Mean curvature of a triangulated surface (Section 2.1, Eq. 1; Meyer et al. 2003).
// At node i the discrete Laplace-Beltrami operator with cotangent weights over the mixed Voronoi area A_i,
//   K(x_i) = 1/(2 A_i) sum_j (cot alpha_ij + cot beta_ij) (x_i - x_j),
// points outward on a convex surface and |K| = 2H. The node's mean curvature is H_i = |K|/2, signed by
// K . n_i (n_i: area-weighted normal), so concave regions get H < 0. A triangle's curvature is the mean of
// its three nodes' curvatures weighted by each node's mixed Voronoi area inside that triangle.
// Inputs: a closed, outward-oriented surface [m]. Outputs: H per node and per triangle [1/m].
#pragma once

#include <array>
#include <vector>

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

struct MeanCurvature {
  std::vector<Real> nodes;      // [1/m], one per vertex
  std::vector<Real> triangles;  // [1/m], one per triangle
};

MeanCurvature meanCurvature(const TriangleSurface& surface);

// The three corners' shares of a triangle's area in the mixed Voronoi regions of Meyer et al. [m^2]: the
// Voronoi share for a non-obtuse triangle, (|x_i - x_k|^2 cot(angle at j) + |x_i - x_j|^2 cot(angle at k)) / 8;
// for an obtuse one, half the area to the obtuse corner and a quarter to each other corner.
std::array<Real, 3> mixedVoronoiShares(const std::array<Vector3r, 3>& corners);

// The radius of curvature a triangle of mean curvature H uses in contact [m]: 1/H, except that flat and
// concave triangles (H <= 1/maxRadius) use maxRadius. The contact model needs a finite, positive radius
// (Eq. 5: a = sqrt(delta R)); a concave triangle treated as almost flat gives a slightly softer contact
// than the true conformal one, never a NaN or an infinite force. See doc/physics.md.
std::vector<Real> contactRadii(const std::vector<Real>& meanCurvatures, Real maxRadius);

}  // namespace roundedmesh
