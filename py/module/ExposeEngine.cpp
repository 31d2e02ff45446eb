// The contact engine as the Python package drives it (roundedmesh/scene.py), and plane_contact, the same
// pipeline evaluated once without a YADE scene.
#include <boost/python.hpp>
#include <cmath>
#include <stdexcept>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/RoundedMeshEngine.hpp"
#include "pkg/shape/BodyMesh.hpp"
#include "py/module/YadeBridge.hpp"

namespace roundedmesh::python {
namespace {

PressureOptions pressureOptions(Real gamma, const std::string& regime) {
  if (!(std::isfinite(gamma) && gamma > 0))
    throw std::invalid_argument("gamma must be positive and finite, got " + std::to_string(gamma));
  PressureOptions options;
  options.gamma = gamma;
  if (regime == "auto")
    options.regime = RegimeChoice::Auto;
  else if (regime == "quadrature")
    options.regime = RegimeChoice::Quadrature;
  else if (regime == "direct")
    options.regime = RegimeChoice::Direct;
  else
    throw std::invalid_argument("regime must be 'auto', 'quadrature' or 'direct', got '" + regime + "'");
  return options;
}

std::vector<Real> toReals(const bp::object& sequence, size_t expected) {
  if (static_cast<size_t>(bp::len(sequence)) != expected)
    throw std::invalid_argument("expected " + std::to_string(expected) + " masses");
  std::vector<Real> values(expected);
  for (size_t i = 0; i < expected; ++i) values[i] = bp::extract<Real>(sequence[i]);
  return values;
}

class Engine {
 public:
  void addBody(int id, const BodyMesh& mesh, const HertzMaterial& material) {
    model_.bodies.push_back(roundedBody(id, mesh, material));
  }
  void addPartner(const bp::object& body, const HertzMaterial& material) {
    const int id = bp::extract<int>(body.attr("id"));
    model_.partners.push_back({id, yadeShape(body, id), material});
  }
  void setOptions(Real gamma, const std::string& regime) { model_.pressure = pressureOptions(gamma, regime); }

  // One contact step on the current YADE scene; returns the ids of managed bodies that have left it (and
  // then applies nothing).
  bp::list step(const bp::object& omega) {
    bp::list missing;
    for (int id : readScene(omega, model_, data_)) missing.append(id);
    if (bp::len(missing) > 0) return missing;
    RoundedMeshEngine(model_, data_);
    applyWrenches(omega, model_, data_);
    return missing;
  }

  // (time step [s], YADE id of the body, YADE id of the partner) of the most restrictive pair, for the
  // masses the bodies have in YADE now (a partner's mass 0 if it does not move under forces).
  bp::tuple stabilityLimit(const bp::object& bodyMasses, const bp::object& partnerMasses) const {
    const StabilityLimit limit = roundedmesh::stabilityLimit(model_, toReals(bodyMasses, model_.bodies.size()),
                                                             toReals(partnerMasses, model_.partners.size()));
    if (limit.body < 0) return bp::make_tuple(limit.timeStep, -1, -1);
    return bp::make_tuple(limit.timeStep, model_.bodies[limit.body].id, model_.partners[limit.partner].id);
  }

  bp::dict statistics() const {
    bp::dict s;
    s["body_pairs"] = data_.statistics.bodyPairs;
    s["quadrature_contacts"] = data_.statistics.quadratureContacts;
    s["direct_contacts"] = data_.statistics.directContacts;
    return s;
  }

 private:
  ContactModel model_;
  ContactData data_;
};

bp::tuple planeContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const Vector3r& planePoint,
                       const Vector3r& planeNormal, const HertzMaterial& meshMaterial,
                       const HertzMaterial& planeMaterial, const Vector3r& vel, const Vector3r& angVel, Real gamma,
                       const std::string& regime) {
  for (const auto& [name, v] : {std::pair{"pos", pos}, {"plane_point", planePoint}, {"plane_normal", planeNormal},
                                {"vel", vel}, {"ang_vel", angVel}})
    if (!v.allFinite()) throw std::invalid_argument(std::string(name) + " must be finite");
  if (!ori.coeffs().allFinite() || ori.norm() == 0) throw std::invalid_argument("ori must be a finite rotation");
  if (planeNormal.norm() == 0) throw std::invalid_argument("plane_normal must not be zero");
  meshMaterial.validate();
  planeMaterial.validate();

  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, meshMaterial));
  model.partners.push_back({1, Plane{planePoint, planeNormal.normalized()}, planeMaterial});
  model.pressure = pressureOptions(gamma, regime);
  ContactData data;
  data.resize(model);
  data.bodyStates[0] = {pos, ori.normalized(), vel, angVel};
  RoundedMeshEngine(model, data);
  return bp::make_tuple(data.bodyWrenches[0].force, data.bodyWrenches[0].torque);
}

const char* partnerKindName(const Plane&) { return "Plane"; }
const char* partnerKindName(const Wall&) { return "Wall"; }
const char* partnerKindName(const Box&) { return "Box"; }

}  // namespace

void exposeEngine() {
  bp::class_<Engine, boost::noncopyable>("Engine", "Contact engine state of one scene (used by roundedmesh.scene).")
      .def("add_body", &Engine::addBody, (bp::arg("id"), bp::arg("mesh"), bp::arg("material")))
      .def("add_partner", &Engine::addPartner, (bp::arg("body"), bp::arg("material")))
      .def("set_options", &Engine::setOptions, (bp::arg("gamma"), bp::arg("regime")))
      .def("step", &Engine::step, bp::arg("O"))
      .def("stability_limit", &Engine::stabilityLimit, (bp::arg("body_masses"), bp::arg("partner_masses")))
      .add_property("statistics", &Engine::statistics);

  bp::def("partner_kind", +[](const bp::object& body) {
            const int id = bp::extract<int>(body.attr("id"));
            return std::visit([](const auto& shape) { return partnerKindName(shape); }, yadeShape(body, id));
          }, bp::arg("body"), "'Wall' or 'Box' for a body that can be a contact partner; ValueError otherwise.");

  bp::def("plane_contact", &planeContact,
          (bp::arg("mesh"), bp::arg("pos"), bp::arg("ori"), bp::arg("plane_point"), bp::arg("plane_normal"),
           bp::arg("mesh_material"), bp::arg("plane_material"), bp::arg("vel") = Vector3r(Vector3r::Zero()),
           bp::arg("ang_vel") = Vector3r(Vector3r::Zero()), bp::arg("gamma") = 10.0, bp::arg("regime") = "auto"),
          "(force, torque) on a rounded body at pos, ori, moving with vel, ang_vel, pressed against the fixed\n"
          "plane through plane_point with plane_normal pointing toward the body side. Torque is about pos.\n"
          "gamma and regime ('auto', 'quadrature', 'direct') select the pressure integration (Eq. 14).");
}

}  // namespace roundedmesh::python
