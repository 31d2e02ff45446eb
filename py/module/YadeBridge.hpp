// The only code that touches YADE: reads the states of the bodies the engine manages from YADE's Python
// objects (O.bodies[id].state, .shape) and adds the computed wrenches through O.forces. YADE's Vector3 and
// Quaternion arrive as Eigen types through YADE's own Boost.Python converters (architecture.md).
#pragma once

#include <boost/python.hpp>
#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh::python {

namespace bp = boost::python;

// Fills data.timeStep (O.dt), data.bodyStates, data.partnerStates, their clumps, masses and principal moments of
// inertia (a partner's 0 unless it moves under forces, `dynamic`), and refreshes the partners' shapes from their
// YADE shapes, welding the Facets into surfaces again (WeldedFacets.hpp) when one is new or its corners changed. Returns the ids of managed bodies that are no longer in the scene; when any is missing, the
// states are incomplete and must not be used. Throws std::invalid_argument naming the body if a state is not
// finite, a rounded or sphere body's YADE material was replaced, or a sphere body's shape is no longer a Sphere.
// rank: this process's rank once yade.mpy has split the scene, -1 in one process. Under yade.mpy it also fills
// data.residences from each body's `subdomain` (ContactData.hpp, Residence), and a body not in this process is
// Absent, not missing: the master (rank 0) holds only the bodies it owns, a worker its own and the images of
// those near its subdomain.
std::vector<int> readScene(const bp::object& omega, ContactModel& model, ContactData& data, int rank = -1);

// Adds every non-zero wrench of an Own or Master body (ContactData::appliesWrench) to YADE's force container
// (O.forces.addF / addT).
void applyWrenches(const bp::object& omega, const ContactModel& model, const ContactData& data);

// The partner's shape as YADE has it now: a Wall, Box, Facet or Sphere. Throws std::invalid_argument for any
// other.
PartnerShape yadeShape(const bp::object& body, int id);

// A sphere body's shape: its YADE Sphere. Throws std::invalid_argument naming the body if it is no Sphere (or a
// radius that is not positive and finite).
Sphere sphereShape(const bp::object& body, int id);

}  // namespace roundedmesh::python
