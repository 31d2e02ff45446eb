#include "py/module/YadeBridge.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pkg/engine/WeldedFacets.hpp"

namespace roundedmesh::python {
namespace {

bp::object interned(const char* text) { return bp::object(bp::handle<>(PyUnicode_InternFromString(text))); }

// The attributes read of every body in every step, their names made once and interned: a lookup by a C string makes
// and hashes a new Python string each time. Never freed, so that none is released after the interpreter has ended.
struct AttributeNames {
  bp::object state, pos, ori, vel, angVel, clumpId, dynamic, mass, inertia, material, label, subdomain, shape, type,
      typeName, vertices;
};

const AttributeNames& names() {
  static const AttributeNames* const made = new AttributeNames{
      interned("state"),   interned("pos"),      interned("ori"),       interned("vel"),     interned("angVel"),
      interned("clumpId"), interned("dynamic"),  interned("mass"),      interned("inertia"), interned("material"),
      interned("label"),   interned("subdomain"), interned("shape"),    interned("__class__"), interned("__name__"),
      interned("vertices")};
  return *made;
}

// O.bodies[id], or None if the id is out of range or the body was erased.
bp::object bodyOrNone(const bp::object& bodies, int id) {
  try {
    return bodies[id];
  } catch (const bp::error_already_set&) {
    PyErr_Clear();
    return bp::object();
  }
}

// The body's state, clump (YADE's clumpId, -1 for none), mass and principal moments of inertia (0 for a body that
// does not move under forces, when `dynamicOnly`). A state that is not finite stops the step: a NaN would
// otherwise spread silently through every contact of the body.
void readState(const bp::object& body, int id, bool dynamicOnly, BodyState& state, int& clump, Real& mass,
               Vector3r& inertia) {
  const AttributeNames& n = names();
  const bp::object s = body.attr(n.state);
  state.position = bp::extract<Vector3r>(s.attr(n.pos));
  state.orientation = bp::extract<Quaternionr>(s.attr(n.ori));
  state.velocity = bp::extract<Vector3r>(s.attr(n.vel));
  state.angularVelocity = bp::extract<Vector3r>(s.attr(n.angVel));
  clump = bp::extract<int>(body.attr(n.clumpId));
  const bool moves = !dynamicOnly || bp::extract<bool>(body.attr(n.dynamic))();
  mass = moves ? bp::extract<Real>(s.attr(n.mass))() : 0;
  inertia = moves ? bp::extract<Vector3r>(s.attr(n.inertia))() : Vector3r(Vector3r::Zero());
  const char* bad = !state.position.allFinite()                ? "position"
                    : !state.orientation.coeffs().allFinite() ? "orientation"
                    : !state.velocity.allFinite()             ? "velocity"
                    : !state.angularVelocity.allFinite()      ? "angular velocity"
                                                              : nullptr;
  if (bad)
    throw std::invalid_argument("body " + std::to_string(id) + ": its " + bad +
                                " is not finite (a time step too large for the contacts, or a bad state given to "
                                "it); reduce O.dt or fix the state");
}

// A rounded or sphere body's YADE material is the plain Material add_body or add_sphere gave it (label
// "roundedmesh"); one replaced by hand would go on with the HertzMaterial the engine knows, silently: refuse the
// step instead.
void requireOwnMaterial(const bp::object& body, int id, const char* kind) {
  const AttributeNames& n = names();
  const bp::object material = body.attr(n.material);
  if (!material.is_none() && bp::extract<std::string>(material.attr(n.label))() == "roundedmesh") return;
  const std::string found =
      material.is_none() ? "removed"
                         : "replaced by a " + bp::extract<std::string>(material.attr("__class__").attr("__name__"))() +
                               " (label " + bp::extract<std::string>(material.attr("label").attr("__repr__")())() + ")";
  throw std::invalid_argument(std::string(kind) + " body " + std::to_string(id) + ": its YADE material was " + found +
                              "; a " + kind + " body's contact material is a roundedmesh.HertzMaterial, changed with "
                              "roundedmesh.set_material(" + std::to_string(id) + ", material)");
}

// Where `body` is, seen from process `rank` (readScene).
Residence residence(const bp::object& body, int rank) {
  if (rank < 0) return Residence::Own;
  const int owner = bp::extract<int>(body.attr(names().subdomain));
  if (owner == rank) return Residence::Own;
  // The master computes only the pairs among its own bodies: the workers compute every other pair and send it
  // the forces on its bodies. A worker's body the master still holds has a stale state.
  if (rank == 0) return Residence::Absent;
  return owner == 0 ? Residence::Master : Residence::Image;
}

}  // namespace

PartnerShape yadeShape(const bp::object& body, int id) {
  const AttributeNames& n = names();
  const bp::object shape = body.attr(n.shape);
  const std::string kind = shape.is_none() ? "no shape" : bp::extract<std::string>(shape.attr(n.type).attr(n.typeName))();
  if (kind == "Wall") return Wall{bp::extract<int>(shape.attr("axis")), bp::extract<int>(shape.attr("sense"))};
  if (kind == "Box") return Box{bp::extract<Vector3r>(shape.attr("extents"))};
  if (kind == "Sphere") return Sphere{bp::extract<Real>(shape.attr("radius"))};
  if (kind == "Facet") {
    const bp::object v = shape.attr(n.vertices);
    return Facet{{bp::extract<Vector3r>(v[0])(), bp::extract<Vector3r>(v[1])(), bp::extract<Vector3r>(v[2])()}, nullptr};
  }
  throw std::invalid_argument("body " + std::to_string(id) + ": a " + kind +
                              " cannot be a roundedmesh contact partner; Walls, Boxes, Facets and Spheres can");
}

Sphere sphereShape(const bp::object& body, int id) {
  const PartnerShape shape = yadeShape(body, id);
  const Sphere* sphere = std::get_if<Sphere>(&shape);
  if (!sphere) throw std::invalid_argument("sphere body " + std::to_string(id) + ": its YADE shape is no longer a Sphere");
  if (!(std::isfinite(sphere->radius) && sphere->radius > 0))
    throw std::invalid_argument("sphere body " + std::to_string(id) + ": its radius " + std::to_string(sphere->radius) +
                                " is not positive and finite");
  return *sphere;
}

std::vector<int> readScene(const bp::object& omega, ContactModel& model, ContactData& data, int rank) {
  const bp::object bodies = omega.attr("bodies");
  std::vector<int> missing;
  data.resize(model);
  data.timeStep = bp::extract<Real>(omega.attr("dt"));
  const int bodyCount = static_cast<int>(model.bodies.size());
  // Not in the scene: missing in one process; under yade.mpy, in another process.
  auto absent = [&](int id) {
    if (rank < 0) missing.push_back(id);
  };
  for (int b = 0; b < bodyCount; ++b) {
    const bp::object body = bodyOrNone(bodies, model.bodies[b].id);
    data.residences[b] = body.is_none() ? Residence::Absent : residence(body, rank);
    if (data.residences[b] == Residence::Absent) {
      absent(model.bodies[b].id);
      data.bodyMasses[b] = 0;  // puts no limit on the time step
      continue;
    }
    requireOwnMaterial(body, model.bodies[b].id, "rounded");
    readState(body, model.bodies[b].id, false, data.bodyStates[b], data.bodyClumps[b], data.bodyMasses[b],
              data.bodyInertias[b]);
  }
  bool weldAgain = false;
  for (size_t p = 0; p < model.partners.size(); ++p) {
    Partner& partner = model.partners[p];
    const bp::object body = bodyOrNone(bodies, partner.id);
    const int index = bodyCount + static_cast<int>(p);
    data.residences[index] = body.is_none() ? Residence::Absent : residence(body, rank);
    if (data.residences[index] == Residence::Absent) {
      absent(partner.id);
      data.partnerMasses[p] = 0;
      continue;
    }
    readState(body, partner.id, true, data.partnerStates[p], data.partnerClumps[p], data.partnerMasses[p],
              data.partnerInertias[p]);
    if (partner.sphereBody) {
      requireOwnMaterial(body, partner.id, "sphere");
      partner.shape = sphereShape(body, partner.id);
    } else {
      PartnerShape shape = yadeShape(body, partner.id);
      // A facet keeps its weld while its corners stay as they were; one that is new or was changed is welded with
      // all the others afresh, below.
      const Facet* before = std::get_if<Facet>(&partner.shape);
      Facet* now = std::get_if<Facet>(&shape);
      if (before && now && before->vertices == now->vertices) now->weld = before->weld;
      weldAgain = weldAgain || (now && !now->weld);
      partner.shape = std::move(shape);
    }
  }
  if (weldAgain) weldFacetPartners(model, data.partnerStates);
  return missing;
}

void applyWrenches(const bp::object& omega, const ContactModel& model, const ContactData& data) {
  const bp::object forces = omega.attr("forces");
  const bp::object addF = forces.attr("addF"), addT = forces.attr("addT");
  auto apply = [&](int index, int id, const Wrench& w) {
    if (!data.appliesWrench(index)) return;
    if (!w.force.isZero(0)) addF(id, w.force);
    if (!w.torque.isZero(0)) addT(id, w.torque);
  };
  const int bodyCount = static_cast<int>(model.bodies.size());
  for (int b = 0; b < bodyCount; ++b) apply(b, model.bodies[b].id, data.bodyWrenches[b]);
  for (size_t p = 0; p < model.partners.size(); ++p)
    apply(bodyCount + static_cast<int>(p), model.partners[p].id, data.partnerWrenches[p]);
}

}  // namespace roundedmesh::python
