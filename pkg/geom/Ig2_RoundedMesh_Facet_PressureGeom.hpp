// Ig2 functor: the triangles of a rounded body against a YADE Facet, a finite plane of zero thickness (Section 2.3):
// the contact plane is the facet's, on the side of the body's centre, and S is the projected triangle clipped to
// the facet (trianglePlaneGeom). A facet is a sheet (faceGeometry): a cap behind its plane touches it only where the
// facet's point under the cap lies inside the body, so that a body resting on one face of a ridge of Facets (a
// drum's lifter) is not pushed by the ridge's other face, whose plane it crosses beyond the ridge.
// Inputs in body 1's frame: the facet's corners, and the facet's motion relative to body 1.
#pragma once

#include <array>
#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const std::array<Vector3r, 3>& corners,
                                        const RelativeMotion& motion, GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
