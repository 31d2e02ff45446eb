#include "pkg/meshing/ImplicitCurvature.hpp"

namespace roundedmesh {

SurfaceCurvatures implicitSurfaceCurvatures(const ImplicitSolid& solid, const TriangleSurface& scaledSurface,
                                            Real scale, Real step) {
  SurfaceCurvatures out;
  for (const Triangle& t : scaledSurface.triangles) {
    const Vector3r &a = scaledSurface.vertices[t[0]], &b = scaledSurface.vertices[t[1]], &c = scaledSurface.vertices[t[2]];
    const Vector3r x = projectOnSurface(solid, (a + b + c) / (3 * scale));
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
    const Vector3r n = gradient.normalized();
    const Matrix3r P = Matrix3r::Identity() - n * n.transpose();
    const Matrix3r shapeOperator = P * hessian * P / (gradient.norm() * scale);
    const PrincipalCurvature k = principalCurvature(shapeOperator, n, (b - a).cross(c - a).normalized());
    out.principal.push_back(k);
    out.mean.push_back(k.mean());
  }
  return out;
}

}  // namespace roundedmesh
