// A closed RoundedMesh ready to be a rigid body: moved into its principal frame (centre of mass at the
// origin, principal axes of inertia along x, y, z) as YADE's aspherical bodies require, together with
// its mass properties at unit density, the curvature its radii came from, and the pose that puts it back
// where it was given:
//   input-frame point = inputOrientation * body-frame point + inputCentroid.
// Throws std::invalid_argument if the surface is not a valid outward one (SurfaceRepair.hpp).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pkg/shape/MassProperties.hpp"
#include "pkg/shape/RoundedMesh.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

enum class CurvatureSource { Computed, Prescribed };

// Signed mean curvature of each triangle [1/m] (< 0 concave) and the radius that caps flat and concave
// triangles in contact (Curvature.hpp: contactRadii).
struct SurfaceCurvature {
  std::vector<Real> meanCurvatures;
  CurvatureSource source;
  Real maxRadius;  // [m]
};

// The default cap: 100 volume-equivalent radii. Against a convex partner of radius r, a flat triangle with
// this radius is softer than a truly flat one by a factor sqrt(1 + r / maxRadius): 0.5 % for r = r_eq.
Real defaultMaxRadius(Real volume);

class BodyMesh {
 public:
  // A body from a valid, outward surface: with the mean curvatures given (prescribed), or computed from the
  // mesh by Eq. 1 (Curvature.hpp) when prescribedCurvatures is empty; maxRadius defaults to defaultMaxRadius.
  // Principal curvatures (PrincipalCurvature.hpp): those given, else, with prescribed mean curvatures H, both
  // equal to H, else computed from the mesh (Rusinkiewicz's estimate).
  BodyMesh(const TriangleSurface& inputFrameSurface, const std::optional<std::vector<Real>>& prescribedCurvatures,
           std::optional<Real> maxRadius = std::nullopt,
           std::optional<std::vector<PrincipalCurvature>> prescribedPrincipal = std::nullopt);
  // A body whose radii are given: prescribed curvature 1/R.
  explicit BodyMesh(const RoundedMesh& inputFrameMesh);
  // Restores a mesh that is already in its principal frame (as saved with a scene), without moving it;
  // the principal moments are the inertia tensor's diagonal. Throws std::invalid_argument if it is not in
  // its principal frame: centre of mass off the origin, or off-diagonal inertia, above 1e-6 of the size
  // (round-off of a saved mesh is about 1e-15).
  BodyMesh(const RoundedMesh& bodyFrameMesh, const Vector3r& inputCentroid, const Quaternionr& inputOrientation,
           SurfaceCurvature curvature);

  const RoundedMesh& shape() const { return *shape_; }
  std::shared_ptr<const RoundedMesh> sharedShape() const { return shape_; }
  const SurfaceCurvature& curvature() const { return curvature_; }
  Real volume() const { return volume_; }
  const Vector3r& principalMoments() const { return principalMoments_; }  // [m^5], unit density
  const Vector3r& inputCentroid() const { return inputCentroid_; }
  const Quaternionr& inputOrientation() const { return inputOrientation_; }
  // The surface in the frame it was given in.
  TriangleSurface inputFrameSurface() const;

 private:
  void placeInPrincipalFrame(const RoundedMesh& inputFrameMesh, const MassProperties& mass);

  std::shared_ptr<const RoundedMesh> shape_;
  SurfaceCurvature curvature_;
  Real volume_;
  Vector3r principalMoments_;
  Vector3r inputCentroid_;
  Quaternionr inputOrientation_;
};

}  // namespace roundedmesh
