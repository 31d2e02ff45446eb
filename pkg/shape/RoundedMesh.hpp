// Shape: a triangulated rounded body (Section 2.1). Each triangle carries a radius of curvature R and its
// encompassing sphere: the sphere of radius R through the triangle's three corners with its centre on the
// inner side. Everything is stored in the body frame and precomputed once, so that the contact pipeline
// only reads it.
// Inputs: vertices [m], triangles (corner indices, counter-clockwise seen from outside), one radius per
// triangle [m]. A radius smaller than the triangle's circumradius is raised to the circumradius (no
// sphere through the corners is smaller); radii() reports the radius actually used. Optionally both principal
// curvatures per triangle (PrincipalCurvature.hpp), for the elliptical contact; without them each triangle is
// taken as isotropic with curvature 1/R.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "pkg/shape/TriangleTree.hpp"
#include "pkg/common/Types.hpp"
#include "pkg/shape/InscribedSpheres.hpp"
#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/shape/SolidDistance.hpp"
#include "pkg/shape/TriangleColumns.hpp"
#include "pkg/shape/TriangleExits.hpp"

namespace roundedmesh {

using Triangle = std::array<int, 3>;

struct RoundedTriangle {
  Vector3r normal;        // outward unit normal of the flat triangle
  Real area;              // [m^2]
  Real radius;            // radius of curvature R of the encompassing sphere [m]
  Vector3r sphereCentre;  // centre of the encompassing sphere [m], body frame
  Vector3r circumcentre;  // centre of the circle through the corners [m], body frame
  Real circumradius;      // its radius [m]; the triangle lies inside that circle
  Real capHeight;         // height of the sphere's cap over that circle, R - sqrt(R^2 - rho^2) [m]
};

class RoundedMesh {
 public:
  // Throws std::invalid_argument naming the offending vertex, triangle or radius.
  RoundedMesh(std::vector<Vector3r> vertices, std::vector<Triangle> triangles, const std::vector<Real>& radii,
              std::vector<PrincipalCurvature> principal = {});

  const std::vector<Vector3r>& vertices() const { return vertices_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const RoundedTriangle& rounded(int t) const { return rounded_[t]; }
  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  std::vector<Real> radii() const;
  const PrincipalCurvature& principal(int t) const { return principal_[t]; }
  const std::vector<PrincipalCurvature>& principalCurvatures() const { return principal_; }
  // Radius of the ball around the body-frame origin that holds every triangle's cap (the part of its
  // encompassing sphere beyond the triangle's plane, where all contact pressure acts): no partner outside
  // it can touch the body. Bounded even for the huge radii of nearly flat triangles.
  Real sphereBoundRadius() const { return sphereBoundRadius_; }
  // The hierarchy of the triangles' cap boxes (TriangleTree.hpp), body frame.
  const TriangleTree& tree() const { return tree_; }
  // The triangles' data the candidate lists test, as columns (TriangleColumns.hpp).
  const TriangleColumns& columns() const { return columns_; }
  // The tallest cap: no point of the rounded surface lies farther than this outside the flat mesh's solid [m].
  Real maxCapHeight() const { return maxCapHeight_; }
  // The distance from the flat mesh's solid (SolidDistance.hpp), built on first use (thread-safe): grid spacing
  // half the mean circumradius (at least 1/100 of the mesh's extent), band four mean circumradii and two spacings.
  const SolidDistance& solidDistance() const;
  // The spheres inscribed in the flat mesh that its core is made of (InscribedSpheres.hpp), built on first use
  // (thread-safe).
  const InscribedSpheres& inscribedSpheres() const;
  // Where a line entering the flat solid through a triangle can leave it (TriangleExits.hpp), within a tenth of
  // sphereBoundRadius (at least a tenth of the volume-equivalent radius: the Hertz range); built on first use
  // (thread-safe).
  const TriangleExits& exits() const;
  // The same mesh moved rigidly: x -> rotation * x + translation.
  RoundedMesh transformed(const Matrix3r& rotation, const Vector3r& translation) const;

 private:
  std::vector<Vector3r> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<RoundedTriangle> rounded_;
  std::vector<PrincipalCurvature> principal_;
  Real sphereBoundRadius_ = 0;
  Real maxCapHeight_ = 0;
  TriangleTree tree_;
  TriangleColumns columns_;
  struct Lazy {
    std::once_flag distanceBuilt, spheresBuilt, exitsBuilt;
    std::unique_ptr<const SolidDistance> distance;
    InscribedSpheres spheres;
    TriangleExits exits;
  };
  std::shared_ptr<Lazy> lazy_ = std::make_shared<Lazy>();  // copies share the same geometry
};

}  // namespace roundedmesh
