// Facets welded into surfaces (doc/physics.md, "What each partner's surface is"). YADE builds containers of Facets
// (geom.facetBox, geom.facetCylinder, ymport.stl): facets whose corners coincide within `tolerance` share those
// vertices, and two facets that share two vertices meet at an edge. For each facet this finds
//   - at each edge, whether the surface goes on toward a side of the facet: flat, or turning toward that side (a
//     concave seam for a body on that side), so that no cap can come round the edge from there; else the edge is
//     free (nothing beyond) or convex for a body on that side;
//   - its panel: the coplanar facets welded to it whose union is convex (greedily grown from the facet of lowest
//     index), with the panel's outline. A body meets a panel as one finite plane: its contact is the plane's
//     wherever the panel is, as a Wall's, and each triangle contact is kept by exactly one member, the one that
//     holds its c_eff (ownsEdge and ownsCorner settle the points the members share).
//   - at each edge between two panels, the corner of the facet beyond, from which the engine finds the fold and, where
//     the edge is convex for a body, rounds it (TriangleEdgeGeom.hpp): computed once, by the side of lower panel index.
// All in the frame the corners are given in; lengths [m].
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

// A side of a facet: 0 that of its normal (c1 - c0) x (c2 - c0), 1 the other.
using SidePair = std::array<bool, 2>;

struct FacetWeld {
  std::array<SidePair, 3> edgeClosed{};          // edge i (corners i, i+1): the surface goes on toward that side
  std::array<bool, 3> ownsEdge{true, true, true};      // points on edge i belong to this facet, not to the panel's
                                                       // member across it (the one of lower index keeps them)
  std::array<bool, 3> ownsCorner{true, true, true};    // points at corner i: the panel's member of lowest index
  std::vector<Vector3r> outline;        // the panel's outline, counter-clockwise about the normal; the facet alone: its
                                        // corners
  std::vector<SidePair> outlineClosed;  // outline edge i (outline[i], outline[i + 1]): as edgeClosed
  std::vector<Vector3r> outlineBeyond;  // outline edge i: a corner of the facets beyond it, off its line (NaN: none,
                                        // or not one plane)
  std::array<Vector3r, 3> beyond{Vector3r::Constant(kNaN), Vector3r::Constant(kNaN), Vector3r::Constant(kNaN)};
                                        // edge i: the corner, off the edge, of the facet beyond that turns least (NaN:
                                        // a free edge or a flat seam)
  std::array<bool, 3> ownsStrip{};      // edge i: where it is a convex or free edge, this facet computes its rounding
  int panel = -1;                       // index of the panel (the lowest index of its members)
  int panelSize = 1;                    // how many facets it has
};

// The weld of each facet, in the order given. tolerance [m]: how close two corners must be to be one vertex.
std::vector<FacetWeld> weldFacets(const std::vector<std::array<Vector3r, 3>>& facets, Real tolerance);

// The tolerance weldFacets takes for facets as YADE builds them: 1e-6 of the largest coordinate or edge, enough for
// an STL file's single precision, far below any contact's size.
Real weldTolerance(const std::vector<std::array<Vector3r, 3>>& facets);

}  // namespace roundedmesh
