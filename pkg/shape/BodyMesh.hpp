// A closed RoundedMesh ready to be a rigid body: moved into its principal frame (centre of mass at the
// origin, principal axes of inertia along x, y, z) as YADE's aspherical bodies require, together with
// its mass properties at unit density and the pose that puts it back where it was given:
//   input-frame point = inputOrientation * body-frame point + inputCentroid.
// Throws std::invalid_argument if the surface is not closed and consistently oriented (see
// MeshTopology.hpp) or if the enclosed volume is not positive (inside-out or flat).
#pragma once

#include <memory>

#include "pkg/shape/MassProperties.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

class BodyMesh {
 public:
  explicit BodyMesh(const RoundedMesh& inputFrameMesh);
  // Restores a mesh that is already in its principal frame (as saved with a scene), without moving it;
  // the principal moments are the inertia tensor's diagonal. Throws std::invalid_argument if it is not in
  // its principal frame: centre of mass off the origin, or off-diagonal inertia, above 1e-6 of the size
  // (round-off of a saved mesh is about 1e-15).
  BodyMesh(const RoundedMesh& bodyFrameMesh, const Vector3r& inputCentroid, const Quaternionr& inputOrientation);

  const RoundedMesh& shape() const { return *shape_; }
  std::shared_ptr<const RoundedMesh> sharedShape() const { return shape_; }
  Real volume() const { return volume_; }
  const Vector3r& principalMoments() const { return principalMoments_; }  // [m^5], unit density
  const Vector3r& inputCentroid() const { return inputCentroid_; }
  const Quaternionr& inputOrientation() const { return inputOrientation_; }

 private:
  std::shared_ptr<const RoundedMesh> shape_;
  Real volume_;
  Vector3r principalMoments_;
  Vector3r inputCentroid_;
  Quaternionr inputOrientation_;
};

}  // namespace roundedmesh
