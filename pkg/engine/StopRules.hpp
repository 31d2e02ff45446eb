// What stops a run, and what warns of a step too large for a body's speed (doc/physics.md, "Deep overlaps and
// fast impacts"). A contact pushes two bodies apart only while each triangle's sphere lies on its own side of
// the other body: a body whose centre has passed through a Wall or a Facet is pushed on through it, and a pair
// overlapping by a good part of a body's size is beyond anything the contact describes. Both happen when a step
// carries a body deeper than the contact can follow, i.e. when O.dt is too large for its speed. The rules:
//   crossing: a body (rounded or sphere body) whose centre has crossed a Wall's or a Plane's plane, a Facet
//             (the segment between its centres of the two steps passes through the facet's triangle) or into a
//             Box since the last step, in which their bounds overlapped (they touched, or were about to);
//   overlap:  a pair whose overlap exceeds options.stopOverlap times the size of the smaller side (a rounded body's
//             volume-equivalent radius, a sphere's radius; a flat partner has no size) and has grown since the last
//             step; between two bodies, also not parting at the pair's centre of pressure along its normal (a pair
//             placed that deep is warned of by rm.add_body and the scene, and its cores push it apart: the deepest
//             triangle contact of so deep a pair can still grow a little as the bodies part). Against a flat partner
//             the growth alone: a body whose centre has gone through a plane meets it from the far side, where
//             "parting" would mean going on through. The overlap is the
//             deepest triangle contact's along the pair's normal (PairSummary::depth): against a plane, its depth;
//             between two bodies, about their approach, where the deepest triangle contact alone can run through
//             both at a slant, twice as long.
// The rules compare a step with the last step that was kept (commitStep): a step that breaks one is not kept, so
// redoing it breaks it again.
#pragma once

#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

// Rounded bodies and sphere bodies: the size they are measured by [m] (r_eq, or the sphere's radius); partners
// that are not sphere bodies: a Sphere's radius, infinite for flat ones. `index` as in BodyPair.
Real sideSize(const ContactModel& model, int index);

// After contactForces (ContactStep.hpp): data.pairRecords for this step and, against those of the last kept step,
// the reasons to stop, crossings first, then the deepest overlap for its size.
std::vector<StopReason> checkStopRules(const ContactModel& model, ContactData& data);

// Keeps the step: its pair records become the ones the next step is compared with.
void commitStep(ContactData& data);

// The body (rounded or sphere body) whose points move fastest relative to its contact depth kDeepestOverlap * size
// in a step of dt [s]: the speed of its centre plus its angular speed times its bound radius, times dt. Among the
// bodies this process owns (ContactData::residences).
struct FastBody {
  int body = -1;        // engine index, -1 if nothing moves
  Real speed = 0;       // [m/s]
  Real fraction = 0;    // speed * dt / depth
  Real depth = 0;       // its contact depth kDeepestOverlap * size [m]
};
FastBody fastestBody(const ContactModel& model, const ContactData& data, Real dt);

}  // namespace roundedmesh
