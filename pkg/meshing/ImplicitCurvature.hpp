// The curvature of a smooth implicit surface f = 0 under each triangle of a mesh of it: what the generators
// prescribe with curvature='exact' for the reference shapes (BlendedShape.hpp). At the point of f = 0 that Newton
// steps along grad f reach from the triangle's centroid, its principal curvatures in the triangle's plane
// (implicitPrincipalCurvature, PrincipalCurvature.hpp) from the gradient and Hessian by central differences of step
// `step` [shape units], and their mean. The mesh may be the surface scaled by `scale` [m per shape unit]:
// curvatures come out in 1/m.
#pragma once

#include <vector>

#include "pkg/meshing/ImplicitSurfaceMesher.hpp"
#include "pkg/shape/PrincipalCurvature.hpp"

namespace roundedmesh {

struct SurfaceCurvatures {
  std::vector<Real> mean;                     // [1/m], one per triangle
  std::vector<PrincipalCurvature> principal;  // [1/m], one per triangle
};

SurfaceCurvatures implicitSurfaceCurvatures(const ImplicitSolid& solid, const TriangleSurface& scaledSurface,
                                            Real scale, Real step);

}  // namespace roundedmesh
