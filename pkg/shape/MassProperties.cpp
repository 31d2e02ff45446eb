#include "pkg/shape/MassProperties.hpp"

#include <Eigen/Eigenvalues>

namespace roundedmesh {

MassProperties massProperties(const std::vector<Vector3r>& vertices, const std::vector<Triangle>& triangles) {
  // Moments are taken about the vertices' mean, not the origin: far from the origin the terms of the sums
  // would be huge and cancel, losing every digit (a 2.5 cm body 100 m away would have a wrong inertia).
  Vector3r reference = Vector3r::Zero();
  for (const Vector3r& v : vertices) reference += v;
  reference /= static_cast<Real>(vertices.size());

  Real volume = 0;
  Vector3r firstMoment = Vector3r::Zero();
  Matrix3r secondMoment = Matrix3r::Zero();  // integral of x x^T over the solid, x from the reference
  for (const Triangle& t : triangles) {
    const Vector3r a = vertices[t[0]] - reference, b = vertices[t[1]] - reference, c = vertices[t[2]] - reference;
    const Real det = a.dot(b.cross(c));  // six times the signed volume of the tetrahedron (0, a, b, c)
    const Vector3r sum = a + b + c;
    volume += det / 6;
    firstMoment += det / 24 * sum;
    secondMoment += det / 120 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  MassProperties p;
  p.volume = volume;
  const Vector3r centroid = firstMoment / volume;
  p.centroid = reference + centroid;
  const Matrix3r central = secondMoment - volume * centroid * centroid.transpose();
  p.inertia = central.trace() * Matrix3r::Identity() - central;
  return p;
}

PrincipalAxes principalAxes(const Matrix3r& inertia) {
  const Matrix3r offDiagonal = inertia - Matrix3r(inertia.diagonal().asDiagonal());
  if (offDiagonal.norm() <= 1e-9 * inertia.trace()) return {Quaternionr::Identity(), inertia.diagonal()};

  const Eigen::SelfAdjointEigenSolver<Matrix3r> solver(inertia);
  Matrix3r axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  return {Quaternionr(axes).normalized(), solver.eigenvalues()};
}

}  // namespace roundedmesh
