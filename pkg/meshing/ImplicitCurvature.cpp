#include "pkg/meshing/ImplicitCurvature.hpp"

namespace roundedmesh {

SurfaceCurvatures implicitSurfaceCurvatures(const ImplicitSolid& solid, const TriangleSurface& scaledSurface,
                                            Real scale, Real step) {
  SurfaceCurvatures out;
  for (int t = 0; t < static_cast<int>(scaledSurface.triangles.size()); ++t) {
    const Triangle& corners = scaledSurface.triangles[t];
    const Vector3r x = projectOnSurface(solid, (scaledSurface.vertices[corners[0]] + scaledSurface.vertices[corners[1]] +
                                                scaledSurface.vertices[corners[2]]) / (3 * scale));
    Vector3r gradient;
    Matrix3r hessian;
    const Real centre = solid.f(x);
    for (int i = 0; i < 3; ++i) {
      const Vector3r ei = step * Vector3r::Unit(i);
      const Real plus = solid.f(x + ei), minus = solid.f(x - ei);
      gradient[i] = (plus - minus) / (2 * step);
      hessian(i, i) = (plus - 2 * centre + minus) / (step * step);
      for (int j = 0; j < i; ++j) {
        const Vector3r ej = step * Vector3r::Unit(j);
        hessian(i, j) = hessian(j, i) =
            (solid.f(x + ei + ej) - solid.f(x + ei - ej) - solid.f(x - ei + ej) + solid.f(x - ei - ej)) / (4 * step * step);
      }
    }
    const PrincipalCurvature k = implicitPrincipalCurvature(gradient, hessian, triangleNormal(scaledSurface, t), scale);
    out.principal.push_back(k);
    out.mean.push_back(k.mean());
  }
  return out;
}

}  // namespace roundedmesh
