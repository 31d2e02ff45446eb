// roundedmesh.HertzMaterial (pkg/material/HertzMaterial.hpp).
#include <boost/python.hpp>
#include <memory>
#include <sstream>

#include "pkg/material/HertzMaterial.hpp"

namespace roundedmesh::python {
namespace bp = boost::python;
namespace {

std::shared_ptr<HertzMaterial> makeMaterial(Real young, Real poisson, Real density, Real damping, Real friction,
                                            Real tangentialDamping) {
  auto material =
      std::make_shared<HertzMaterial>(HertzMaterial{young, poisson, density, damping, friction, tangentialDamping});
  material->validate();
  return material;
}

std::string repr(const HertzMaterial& m) {
  std::ostringstream s;
  s.precision(17);
  s << "HertzMaterial(young=" << m.young << ", poisson=" << m.poisson << ", density=" << m.density
    << ", damping=" << m.damping << ", friction=" << m.friction << ", tangential_damping=" << m.tangentialDamping
    << ")";
  return s.str();
}

struct MaterialPickle : bp::pickle_suite {
  static bp::tuple getinitargs(const HertzMaterial& m) {
    return bp::make_tuple(m.young, m.poisson, m.density, m.damping, m.friction, m.tangentialDamping);
  }
};

bool equal(const HertzMaterial& a, const HertzMaterial& b) {
  return a.young == b.young && a.poisson == b.poisson && a.density == b.density && a.damping == b.damping &&
         a.friction == b.friction && a.tangentialDamping == b.tangentialDamping;
}

}  // namespace

void exposeMaterial() {
  bp::class_<HertzMaterial, std::shared_ptr<HertzMaterial>>(
      "HertzMaterial",
      "Material of a body in Hertz contact.\n\n"
      "HertzMaterial(young, poisson, density, damping=0.0, friction=0.0, tangential_damping=0.0): Young's\n"
      "modulus [Pa] (math.inf for a rigid body), Poisson's ratio in (-1, 0.5), density [kg/m^3], normal damping\n"
      "constant A of Eq. 7 [s], Coulomb friction coefficient mu and tangential damping constant c [N s/m]: the\n"
      "dashpot beside each contact's tangential spring, or the viscous constant of Eqs. 18-21 under\n"
      "rm.engine(friction='viscous') (a contact's mu is the smaller of the two, its A and c the means). Read-only;\n"
      "raises ValueError naming a parameter out of range.",
      bp::no_init)
      .def("__init__", bp::make_constructor(&makeMaterial, bp::default_call_policies(),
                                            (bp::arg("young"), bp::arg("poisson"), bp::arg("density"),
                                             bp::arg("damping") = 0.0, bp::arg("friction") = 0.0,
                                             bp::arg("tangential_damping") = 0.0)))
      .def_readonly("young", &HertzMaterial::young)
      .def_readonly("poisson", &HertzMaterial::poisson)
      .def_readonly("density", &HertzMaterial::density)
      .def_readonly("damping", &HertzMaterial::damping)
      .def_readonly("friction", &HertzMaterial::friction)
      .def_readonly("tangential_damping", &HertzMaterial::tangentialDamping)
      .def("__repr__", &repr)
      .def("__eq__", &equal)
      .def("__hash__", +[](const HertzMaterial& m) { return bp::object(repr(m)).attr("__hash__")(); })
      .def_pickle(MaterialPickle());
}

}  // namespace roundedmesh::python
