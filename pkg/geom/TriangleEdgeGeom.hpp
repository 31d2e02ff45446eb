// Contact geometry of one rounded triangle against a rounded edge or corner of a partner (doc/physics.md, "What each
// partner's surface is"). A convex edge rounded by a radius rho is a strip of the cylinder of radius rho whose axis
// runs at distance rho behind both faces; a corner where convex edges meet is a patch of the sphere of radius rho
// about the point at distance rho behind its faces. The strip (patch) is the part of the cylinder (sphere) whose
// outward normals lie between those of the faces it joins, so that faces trimmed where they meet it, strips and
// patches cover the rounded partner once. For the triangle's sphere (s, R):
//   n12       from s to its foot q on the axis (the centre), perpendicular to the axis
//   overlap   delta_s = R + rho - |q - s|,  c on the line from s along n12 where the two surfaces cross (as for two
//             spheres, TriangleSphereGeom.hpp)
//   polygon S the projected triangle clipped to the projected strip (patch)
//   ellipse   Hertz's contact of the triangle's cap (its sphere, or its principal curvatures with
//             curvature='principal') with the cylinder (curvature 1/rho across the axis, 0 along it) or the sphere
//             (EllipticalContact.hpp), whatever the engine's curvature model: a cylinder is not a sphere.
// Rejects the candidate unless the ellipse meets S.
#pragma once

#include <vector>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

// A rounded edge (start != end) or corner (start == end) in body 1's frame: the axis segment or centre [m], the
// radius rho [m], and the outward normals of the faces it joins (two for an edge, in either order, with an angle
// below 180 degrees between them; those of the corner's faces for a corner, in order round it, whose patch is the
// cone they span: its projection is taken at the normals' tips and the midpoints of the arcs between them).
struct RoundedFeature {
  Vector3r start, end;
  Real radius;
  std::vector<Vector3r> faceNormals;
};

GeomTest triangleFeatureGeom(const RoundedMesh& mesh, int triangle, const RoundedFeature& feature,
                             const RelativeMotion& motion, PressureGeom& geom,
                             CurvatureModel model = CurvatureModel::Mean);

// How far from a feature's axis segment (or centre) a cap can touch it [m]: its radius, plus how deep behind a cap a
// swallowed axis may lie (triangleFeatureGeom).
Real featureReach(const RoundedMesh& mesh, Real radius);

// triangleFeatureGeom for every triangle whose cap box comes within featureReach of the feature's axis segment; with
// `candidates`, for those of them (featureCandidates), in their order.
void featureGeometry(const RoundedMesh& mesh, const RoundedFeature& feature, const RelativeMotion& motion,
                     GeomOutput out, CurvatureModel model = CurvatureModel::Mean,
                     const std::vector<int>* candidates = nullptr);

// The triangles whose cap boxes come within featureReach + margin [m] of the feature's axis segment, in the order of
// the tree's query: while no point of the body's tree moves by more than the margin relative to the feature, they
// hold every triangle featureGeometry tests.
void featureCandidates(const RoundedMesh& mesh, const RoundedFeature& feature, Real margin,
                       std::vector<int>& triangles);

}  // namespace roundedmesh
