#include "py/module/YadeBridge.hpp"

#include <stdexcept>
#include <string>

namespace roundedmesh::python {
namespace {

// O.bodies[id], or None if the id is out of range or the body was erased.
bp::object bodyOrNone(const bp::object& bodies, int id) {
  try {
    return bodies[id];
  } catch (const bp::error_already_set&) {
    PyErr_Clear();
    return bp::object();
  }
}

void readState(const bp::object& body, BodyState& state) {
  const bp::object s = body.attr("state");
  state.position = bp::extract<Vector3r>(s.attr("pos"));
  state.orientation = bp::extract<Quaternionr>(s.attr("ori"));
  state.velocity = bp::extract<Vector3r>(s.attr("vel"));
  state.angularVelocity = bp::extract<Vector3r>(s.attr("angVel"));
}

}  // namespace

PartnerShape yadeShape(const bp::object& body, int id) {
  const bp::object shape = body.attr("shape");
  const std::string kind = shape.is_none() ? "no shape" : bp::extract<std::string>(shape.attr("__class__").attr("__name__"))();
  if (kind == "Wall") return Wall{bp::extract<int>(shape.attr("axis")), bp::extract<int>(shape.attr("sense"))};
  if (kind == "Box") return Box{bp::extract<Vector3r>(shape.attr("extents"))};
  if (kind == "Sphere") return Sphere{bp::extract<Real>(shape.attr("radius"))};
  if (kind == "Facet") {
    const bp::object v = shape.attr("vertices");
    return Facet{{bp::extract<Vector3r>(v[0])(), bp::extract<Vector3r>(v[1])(), bp::extract<Vector3r>(v[2])()}};
  }
  throw std::invalid_argument("body " + std::to_string(id) + ": a " + kind +
                              " cannot be a roundedmesh contact partner; Walls, Boxes, Facets and Spheres can");
}

std::vector<int> readScene(const bp::object& omega, ContactModel& model, ContactData& data) {
  const bp::object bodies = omega.attr("bodies");
  std::vector<int> missing;
  data.resize(model);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const bp::object body = bodyOrNone(bodies, model.bodies[b].id);
    if (body.is_none())
      missing.push_back(model.bodies[b].id);
    else
      readState(body, data.bodyStates[b]);
  }
  for (size_t p = 0; p < model.partners.size(); ++p) {
    Partner& partner = model.partners[p];
    const bp::object body = bodyOrNone(bodies, partner.id);
    if (body.is_none()) {
      missing.push_back(partner.id);
      continue;
    }
    readState(body, data.partnerStates[p]);
    partner.shape = yadeShape(body, partner.id);
  }
  return missing;
}

void applyWrenches(const bp::object& omega, const ContactModel& model, const ContactData& data) {
  const bp::object forces = omega.attr("forces");
  const bp::object addF = forces.attr("addF"), addT = forces.attr("addT");
  auto apply = [&](int id, const Wrench& w) {
    if (!w.force.isZero(0)) addF(id, w.force);
    if (!w.torque.isZero(0)) addT(id, w.torque);
  };
  for (size_t b = 0; b < model.bodies.size(); ++b) apply(model.bodies[b].id, data.bodyWrenches[b]);
  for (size_t p = 0; p < model.partners.size(); ++p) apply(model.partners[p].id, data.partnerWrenches[p]);
}

}  // namespace roundedmesh::python
