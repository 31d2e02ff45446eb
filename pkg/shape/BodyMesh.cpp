#include "pkg/shape/BodyMesh.hpp"

#include "pkg/shape/MeshTopology.hpp"

#include <stdexcept>
#include <string>

namespace roundedmesh {
namespace {

Eigen::AlignedBox<Real, 3> boundingBox(const std::vector<Vector3r>& vertices) {
  Eigen::AlignedBox<Real, 3> box;
  for (const Vector3r& v : vertices) box.extend(v);
  return box;
}

MassProperties solidMassProperties(const RoundedMesh& mesh) {
  requireClosedOrientedSurface(mesh.triangles());
  const MassProperties mass = massProperties(mesh.vertices(), mesh.triangles());
  if (!(mass.volume > 1e-9 * boundingBox(mesh.vertices()).volume()))
    throw std::invalid_argument("mesh: the enclosed volume is " + std::to_string(mass.volume) +
                                " m^3; a body needs a closed, outward-oriented surface with positive volume");
  return mass;
}

}  // namespace

BodyMesh::BodyMesh(const RoundedMesh& inputFrameMesh) {
  const MassProperties mass = solidMassProperties(inputFrameMesh);
  const PrincipalAxes axes = principalAxes(mass.inertia);
  volume_ = mass.volume;
  principalMoments_ = axes.moments;
  inputCentroid_ = mass.centroid;
  inputOrientation_ = axes.orientation;
  const Matrix3r toBody = axes.orientation.conjugate().toRotationMatrix();
  shape_ = std::make_shared<const RoundedMesh>(inputFrameMesh.transformed(toBody, -toBody * mass.centroid));
}

BodyMesh::BodyMesh(const RoundedMesh& bodyFrameMesh, const Vector3r& inputCentroid,
                   const Quaternionr& inputOrientation)
    : shape_(std::make_shared<const RoundedMesh>(bodyFrameMesh)),
      inputCentroid_(inputCentroid),
      inputOrientation_(inputOrientation.normalized()) {
  const MassProperties mass = solidMassProperties(bodyFrameMesh);
  const Matrix3r offDiagonal = mass.inertia - Matrix3r(mass.inertia.diagonal().asDiagonal());
  if (mass.centroid.norm() > 1e-6 * boundingBox(bodyFrameMesh.vertices()).diagonal().norm() ||
      offDiagonal.norm() > 1e-6 * mass.inertia.trace())
    throw std::invalid_argument("mesh: the vertices are not in the principal frame of the mesh");
  volume_ = mass.volume;
  principalMoments_ = mass.inertia.diagonal();
}

}  // namespace roundedmesh
