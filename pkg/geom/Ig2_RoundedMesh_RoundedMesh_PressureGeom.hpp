// Ig2 functor: the triangles of two rounded bodies against each other (Appendix B): every candidate pair
// (TrianglePairCandidates.hpp) goes through triangleSphereGeom with body 2's triangle placed in body 1's frame
// (where the vector unit holds 4 doubles or more, in batches of 16 through three stages in lanes: the contact
// planes, TrianglePlanes.hpp; the polygons S, TriangleIntersections.hpp; for the paper's circles the rest,
// PolygonContacts.hpp; the same result bit for bit);
// the segment between the two caps must lie inside both bodies (TriangleExits.hpp, DeepContactCriterion.hpp; the
// distance fields first for a pair deeper than `shallow` [m]).
// Inputs: body 2's pose in body 1's frame (x1 = rotation * x2 + translation), the candidates, and body 2's
// motion relative to body 1. Appends one PressureGeom per triangle pair in contact, in candidate order.
#pragma once

#include <vector>

#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/geom/DeepContactCriterion.hpp"
#include "pkg/geom/TriangleSphereGeom.hpp"

namespace roundedmesh {

// Whether the candidates go through the lanes: where that pays (triangleIntersectionsPay()), or always, or never, for
// tests and benchmarks that compare the two ways on any processor. Both give the same contacts bit for bit.
enum class PolygonLanes { WherePaying, Always, Never };

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out,
                                              CurvatureModel model = CurvatureModel::Mean,
                                              PolygonLanes lanes = PolygonLanes::WherePaying);

}  // namespace roundedmesh
