// The rounded body within a stated distance of the surface the user gave. A triangle's cap is the part of its
// encompassing sphere (radius R, through its corners, Section 2.1) over the triangle. With rho the circumradius and
// w the half-width of the triangle seen from its circumcentre (w = rho for a triangle that holds its circumcentre,
// half its longest edge for an obtuse one, whose circumcentre lies beyond that edge), the cap rises
//   h(R) = sqrt(R^2 - rho^2 + w^2) - sqrt(R^2 - rho^2)
// over the triangle's plane, and the rounded body (flat solid plus caps) lies within max h of the flat mesh, and the
// flat surface within max h of the rounded one: max h is their two-sided (Hausdorff) distance. Where a mesh is too
// coarse for the curvature computed from it (a sharp edge, a sliver, a coarse scan), R is small against rho, raised to
// rho, and the caps become half spheres that push partners the mesh does not touch. boundCapHeights raises such a
// triangle's radius to the smallest whose cap rises at most hMax,
//   sqrt(R^2 - rho^2) = (w^2 - hMax^2) / (2 hMax)
// and lowers its principal curvatures to at most 1/R, so that the contact there sees the surface the mesh describes
// (nearly flat facets) rather than a curvature the mesh cannot carry. Triangles already within hMax keep their radius
// and curvatures exactly.
// (RoundedTriangle::capHeight, the cap over the whole circumcircle, is the larger bound that the triangles' boxes use;
// for a triangle that holds its circumcentre the two are equal.)
// Inputs: the surface [m], one contact radius per triangle [m] (Curvature.hpp: contactRadii), the principal
// curvatures per triangle [1/m] (may be empty), hMax [m] > 0. Output: how many triangles were raised.
#pragma once

#include <vector>

#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

// Each triangle's cap height h(R) with the given radii [m] (a radius below the circumradius is raised to it).
std::vector<Real> capHeights(const TriangleSurface& surface, const std::vector<Real>& radii);

int boundCapHeights(const TriangleSurface& surface, Real maxHeight, std::vector<Real>& radii,
                    std::vector<PrincipalCurvature>& principal);

}  // namespace roundedmesh
