// Ig2 functor: the triangles of a rounded body against a YADE Facet, a finite plane of zero thickness (Section 2.3):
// the contact plane is the facet's, on the side of the body's centre, and S is the projected triangle clipped to
// the facet (trianglePlaneGeom). A facet is a sheet (faceGeometry): a cap behind its plane touches it only where the
// facet's point under the cap lies inside the body, so that a body resting on one face of a ridge of Facets (a
// drum's lifter) is not pushed by the ridge's other face, whose plane it crosses beyond the ridge.
// A welded facet (FacetSurface.hpp) is a member of a panel of coplanar facets: S is clipped to the panel's outline,
// so that a body across a flat seam meets one plane, and the facet keeps the contacts whose c_eff it holds (the
// panel's other members keep the rest); a seam where the surface goes on toward the body is no edge a cap can come
// round. An edge between panels that is convex from the body's side (a lifter's ridge, a box's edge seen from
// outside) is rounded by edgeRadius rho: the faces stop rho tan(theta / 2) short of it (theta the angle between their
// normals) and the cylinder strip between them pushes (TriangleEdgeGeom.hpp), computed by the facet that owns it. A
// free edge (a plate's rim) is rounded as a 90-degree edge whose second face is the plane across the rim: a lip of
// radius rho on each side of the sheet, within its outline. The corners of a facet surface stay sharp.
// Inputs in body 1's frame: the facet placed there, and the facet's motion relative to body 1.
#pragma once

#include <array>
#include <vector>

#include "pkg/geom/FacetCandidates.hpp"
#include "pkg/geom/TrianglePlaneGeom.hpp"
#include "pkg/shape/Facet.hpp"

namespace roundedmesh {

// Makes `candidates` (FacetCandidates.hpp) for the body on `side` of the facet, with a margin [m].
void facetCandidates(const RoundedMesh& mesh, const PlacedFacet& facet, int side, Real edgeRadius, Real margin,
                     FacetCandidates& candidates);

// With `candidates`, made for this facet, the body on their side and a margin the motion since has not exceeded:
// only those triangles are tested, and the Ig2 finds exactly what it finds over the whole tree.
void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const PlacedFacet& facet, Real edgeRadius,
                                        const RelativeMotion& motion, GeomOutput out,
                                        CurvatureModel model = CurvatureModel::Mean,
                                        const FacetCandidates* candidates = nullptr);

// The side of the facet (FacetWeld's side 0: that of the normal (c1 - c0) x (c2 - c0), 1 the other) the body whose
// centre is the frame's origin is on: its plane's side, or for a welded facet the surface's, which outside a ridge
// (above a lifter's apex, past the plane's reach) is the other. With `clearance`, also how far [m] the centre may move
// relative to the facet before its side can change: its distance to the nearest plane the side is decided by.
int facetSide(const PlacedFacet& facet, Real* clearance = nullptr);

// Whether point p of the facet's plane, in the coordinates `inPlane` gives, belongs to the facet among its panel's
// members: inside it, or on an edge or at a corner it owns (FacetWeld). Within a billionth of the facet's size of an
// edge or corner, the point is taken to be on it, so that every member decides alike despite round-off.
bool facetOwns(const std::array<Vector2r, 3>& corners, const FacetWeld& weld, const Vector2r& p);

}  // namespace roundedmesh
