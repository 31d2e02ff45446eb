// The inscribed spheres of a rounded body, from which its core is made (doc/physics.md, "Deep overlaps and fast impacts", The core):
// spheres inside the flat mesh, each as large as it can be there (its radius the distance from its centre to the
// surface), chosen one at a time after Ferellec and McDowell, Granular Matter 12 (2010) 459-467, so that their union
// follows the shape: tips and limbs as well as the bulk.
// Candidates: the nodes of a cubic grid, kCellsAcross cells across the mesh's largest extent, inside the mesh, at
// least kMinRadiusCells cells (at most half the largest candidate's radius) from the surface. Surface samples: the
// vertices and the triangles' centroids, weighted by the area each stands for. The gap of a sample is its distance
// to the union's surface, |s - c| - r at best over the chosen spheres; its floor is the best any one candidate gives
// it; its excess is gap - floor. Rule: the first sphere is the largest candidate; then the sample of largest excess
// is the target, and of the candidates whose gap there is within tau = min(spacing, excess) / 2 of its floor (the
// spheres that touch the surface at or next to it), the one covering the most sample area not yet covered (gap within
// floor + tau) is taken, ties to the larger, then the lower index. It stops at kMaxSpheres or when no sample's excess
// exceeds half a cell, the grid's own resolution.
// Output in the mesh's frame: centres [m], radii [m], largest first.
#pragma once

#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class RoundedMesh;

struct InscribedSpheres {
  static constexpr int kCellsAcross = 24;
  static constexpr int kMinRadiusCells = 2;
  static constexpr int kMaxSpheres = 32;

  std::vector<Vector3r> centres;
  std::vector<Real> radii;
  Real reach = 0;                     // the radius of the ball about the origin that holds them [m]
  Eigen::AlignedBox<Real, 3> box;     // the box that holds them [m]
};

InscribedSpheres inscribedSpheres(const RoundedMesh& mesh);

}  // namespace roundedmesh
