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

// What is done to a mesh whose curvature is computed from it and whose caps (CapTolerance.hpp) rise beyond
// `tolerance` of its volume-equivalent radius: remeshed finer, same shape, sharp edges kept (MeshPreparation.hpp) if
// `remesh`; then any cap still beyond it bounded (boundCapHeights). Prescribed curvatures are the caller's and are
// never touched.
struct CapPolicy {
  Real tolerance;
  bool remesh;
};

// The default tolerance, 0.05 r_eq: half the Hertz depth of 0.1 r_eq (doc/physics.md). The meshes the project
// validates stay within it with the curvature computed from them (tallest caps: the 554-node gummy bear 0.045 r_eq,
// the 150-node pear 0.041, the 162-node icosphere 0.018), so they load unchanged.
constexpr Real kDefaultCapTolerance = 0.05;

class BodyMesh {
 public:
  // A body from a valid, outward surface: with the mean curvatures given (prescribed), or computed from the
  // mesh by Eq. 1 (Curvature.hpp) when prescribedCurvatures is empty; maxRadius defaults to defaultMaxRadius.
  // Principal curvatures (PrincipalCurvature.hpp): those given, else, with prescribed mean curvatures H, both
  // equal to H, else computed from the mesh (Rusinkiewicz's estimate).
  // caps: what is done where the computed curvature's caps rise beyond a tolerance (CapPolicy); none by default.
  BodyMesh(const TriangleSurface& inputFrameSurface, const std::optional<std::vector<Real>>& prescribedCurvatures,
           std::optional<Real> maxRadius = std::nullopt,
           std::optional<std::vector<PrincipalCurvature>> prescribedPrincipal = std::nullopt,
           std::optional<CapPolicy> caps = std::nullopt);
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
  // What the CapPolicy did (0 for a restored mesh): remeshing passes, their last target edge length [m], and how
  // many triangles' radii were then raised to keep their caps within the tolerance.
  int remeshPasses() const { return remeshPasses_; }
  Real remeshEdgeLength() const { return remeshEdgeLength_; }
  int boundedCaps() const { return boundedCaps_; }
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
  int remeshPasses_ = 0;
  Real remeshEdgeLength_ = 0;
  int boundedCaps_ = 0;
  Real volume_;
  Vector3r principalMoments_;
  Vector3r inputCentroid_;
  Quaternionr inputOrientation_;
};

}  // namespace roundedmesh
