#include "pkg/shape/BodyMesh.hpp"

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
  const PrincipalAxes axes = principalAxes(mass.inertia);
  if (mass.centroid.norm() > 1e-9 * boundingBox(bodyFrameMesh.vertices()).diagonal().norm() ||
      !axes.orientation.coeffs().isApprox(Quaternionr::Identity().coeffs()))
    throw std::invalid_argument("mesh: the vertices are not in the principal frame of the mesh");
  volume_ = mass.volume;
  principalMoments_ = axes.moments;
}

}  // namespace roundedmesh
