#include "pkg/shape/PrincipalCurvature.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

std::vector<Vector3r> vertexNormals(const TriangleSurface& surface) {
  std::vector<Vector3r> normals(surface.vertices.size(), Vector3r::Zero());
  for (const Triangle& t : surface.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vector3r& x = surface.vertices[t[i]];
      const Vector3r e1 = surface.vertices[t[(i + 1) % 3]] - x, e2 = surface.vertices[t[(i + 2) % 3]] - x;
      normals[t[i]] += e1.cross(e2) / (e1.squaredNorm() * e2.squaredNorm());
    }
  for (Vector3r& n : normals) n.normalize();
  return normals;
}

PrincipalCurvature principalCurvature(const Matrix3r& shapeOperator, const Vector3r& normal,
                                      const Vector3r& triangleNormal) {
  const Vector3r u = normal.unitOrthogonal(), v = normal.cross(u);
  const Real e = u.dot(shapeOperator * u), f = 0.5 * (u.dot(shapeOperator * v) + v.dot(shapeOperator * u)),
             g = v.dot(shapeOperator * v);
  // Eigenvalues of [[e, f], [f, g]]: mean +- radius; the larger one's eigenvector at angle theta from u.
  const Real mean = (e + g) / 2, radius = std::hypot((e - g) / 2, f);
  const Real theta = 0.5 * std::atan2(2 * f, e - g);
  const Vector3r d1 = Quaternionr::FromTwoVectors(normal, triangleNormal) * (std::cos(theta) * u + std::sin(theta) * v);
  return {mean + radius, mean - radius, d1.normalized()};
}

PrincipalCurvature implicitPrincipalCurvature(const Vector3r& gradient, const Matrix3r& hessian,
                                              const Vector3r& triangleNormal, Real scale) {
  const Vector3r n = gradient.normalized();
  const Matrix3r P = Matrix3r::Identity() - n * n.transpose();
  return principalCurvature(P * hessian * P / (gradient.norm() * scale), n, triangleNormal);
}

std::vector<PrincipalCurvature> principalCurvatures(const TriangleSurface& surface) {
  const std::vector<Vector3r> normals = vertexNormals(surface);
  std::vector<PrincipalCurvature> out;
  out.reserve(surface.triangles.size());
  for (int face = 0; face < static_cast<int>(surface.triangles.size()); ++face) {
    const Triangle& t = surface.triangles[face];
    const Vector3r n = triangleNormal(surface, face);
    const Vector3r u = (surface.vertices[t[1]] - surface.vertices[t[0]]).normalized(), v = n.cross(u);
    // Unknowns (e, f, g) of II = [[e, f], [f, g]] in the frame (u, v); two equations per edge.
    Eigen::Matrix<Real, 6, 3> A;
    Eigen::Matrix<Real, 6, 1> b;
    for (int i = 0; i < 3; ++i) {
      const int start = t[i], end = t[(i + 1) % 3];
      const Vector3r edge = surface.vertices[end] - surface.vertices[start];
      const Vector3r dn = normals[end] - normals[start];
      const Real eu = edge.dot(u), ev = edge.dot(v);
      A.row(2 * i) << eu, ev, 0;
      A.row(2 * i + 1) << 0, eu, ev;
      b(2 * i) = dn.dot(u);
      b(2 * i + 1) = dn.dot(v);
    }
    const Vector3r efg = (A.transpose() * A).ldlt().solve(A.transpose() * b);
    const Matrix3r shapeOperator = efg(0) * u * u.transpose() + efg(1) * (u * v.transpose() + v * u.transpose()) +
                             efg(2) * v * v.transpose();
    out.push_back(principalCurvature(shapeOperator, n, n));
  }
  return out;
}

}  // namespace roundedmesh
