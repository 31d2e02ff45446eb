// Stage 3's deep-overlap term for one pair (CoreRepulsion.hpp): the core spheres of a rounded body against the other
// side, which is another rounded body's core, or a partner: a plane (Wall, Plane) on the side of the body's centre, a
// Box's solid, a Sphere, or a Facet's panel as a sheet without thickness: each core sphere is pushed away from the
// panel's nearest point (its projection, or the nearest point of the rim), on the side the sphere's centre is on,
// every point of the panel kept by one member as the triangle contacts are (facetOwns). A sheet has no inside: a core
// sphere pushed through it meets its largest force, Hertz's at delta = rho, as its centre reaches the sheet (the body's
// centre reaching it stops the run, StopRules.hpp), and a body beside a plate's rim is pushed off the rim on either
// side, continuously. Nothing when options.coreInset is 1.
// Input: the pair (pair.body a rounded body), the states. Output: the load on pair.body (global frame, torque about its
// position); the other side takes the reaction.
#pragma once

#include "pkg/engine/ContactData.hpp"
#include "pkg/law/CoreRepulsion.hpp"

namespace roundedmesh {

CoreLoad corePair(const ContactModel& model, const ContactData& data, const BodyPair& pair);

}  // namespace roundedmesh
