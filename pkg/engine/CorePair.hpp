// Stage 3's deep-overlap term for one pair (CoreRepulsion.hpp): the core spheres of a rounded body against the other
// side, which is another rounded body's core, or a partner: a plane (Wall, Plane) on the side of the body's centre, a
// Box's solid, a Sphere, or a Facet's panel as a sheet without thickness, every point of a panel kept by one member
// as the triangle contacts are (facetOwns). A core sphere is pushed away from the panel's nearest point, on the side
// its centre is on, except one whose centre lies behind the sheet, seen from the side of the surface the body's
// centre is on (Ig2_RoundedMesh_Facet_PressureGeom.hpp, facetSide), nearer the sheet than any open edge of it: that
// one came through the sheet, and is pushed back, delta = rho + its depth behind it, so that a body pushed into a
// sheet meets a core that keeps pushing harder, from either side, as on a Wall (the sheet rule of the triangle
// contacts, TrianglePlaneGeom.hpp). Farther behind than an open edge it came round that edge (a body over a plate's
// rim), and is pushed off on its own side. Nothing when options.coreInset is 1. Two bodies' cores are looked at only
// where they can touch: the pair's triangle contacts (`contacts`) reach half the least onset inset (r_i + r_j) of its
// core spheres, or it has none and one body's centre lies inside the other's solid.
// Input: the pair (pair.body a rounded body), the states, the summary of its triangle contacts. Output: the load on
// pair.body (global frame, torque about its position); the other side takes the reaction.
#pragma once

#include "pkg/engine/ContactData.hpp"
#include "pkg/law/CoreRepulsion.hpp"

namespace roundedmesh {

CoreLoad corePair(const ContactModel& model, const ContactData& data, const BodyPair& pair, const PairSummary& contacts);

}  // namespace roundedmesh
