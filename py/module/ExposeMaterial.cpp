// roundedmesh.HertzMaterial (pkg/material/HertzMaterial.hpp).
#include <boost/python.hpp>
#include <memory>
#include <sstream>
#include <utility>

#include "pkg/material/HertzMaterial.hpp"

namespace roundedmesh::python {
namespace bp = boost::python;
namespace {

// The material's fields, declared once: their names as Python spells them, in the constructor's order (the
// keyword arguments, the read-only properties, HertzMaterial.fields and record()).
const std::pair<const char*, Real HertzMaterial::*> kFields[] = {
    {"young", &HertzMaterial::young},       {"poisson", &HertzMaterial::poisson},
    {"density", &HertzMaterial::density},   {"damping", &HertzMaterial::damping},
    {"friction", &HertzMaterial::friction}, {"tangential_damping", &HertzMaterial::tangentialDamping}};

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
  s << "HertzMaterial(";
  for (const auto& [name, field] : kFields) s << (field == kFields[0].second ? "" : ", ") << name << "=" << m.*field;
  s << ")";
  return s.str();
}

struct MaterialPickle : bp::pickle_suite {
  static bp::tuple getinitargs(const HertzMaterial& m) {
    bp::list values;
    for (const auto& [name, field] : kFields) values.append(m.*field);
    return bp::tuple(values);
  }
};

// {field: value}: what a scene's tags keep of a material (roundedmesh/_records.py), by name.
bp::dict record(const HertzMaterial& m) {
  bp::dict d;
  for (const auto& [name, field] : kFields) d[name] = m.*field;
  return d;
}

bool equal(const HertzMaterial& a, const HertzMaterial& b) {
  for (const auto& [name, field] : kFields)
    if (!(a.*field == b.*field)) return false;
  return true;
}

}  // namespace

void exposeMaterial() {
  bp::class_<HertzMaterial, std::shared_ptr<HertzMaterial>> material(
      "HertzMaterial",
      "Material of a body in Hertz contact.\n\n"
      "HertzMaterial(young, poisson, density, damping=0.0, friction=0.0, tangential_damping=0.0): Young's\n"
      "modulus [Pa] (math.inf for a rigid body), Poisson's ratio in (-1, 0.5), density [kg/m^3], normal damping\n"
      "constant A of Eq. 7 [s], Coulomb friction coefficient mu and tangential damping constant c [N s/m]: the\n"
      "dashpot beside each contact's tangential spring, or the viscous constant of Eqs. 18-21 under\n"
      "rm.engine(friction='viscous') (a contact's mu is the smaller of the two, its A and c the means). Read-only;\n"
      "raises ValueError naming a parameter out of range.",
      bp::no_init);
  material.def("__init__", bp::make_constructor(&makeMaterial, bp::default_call_policies(),
                                            (bp::arg(kFields[0].first), bp::arg(kFields[1].first),
                                             bp::arg(kFields[2].first), bp::arg(kFields[3].first) = 0.0,
                                             bp::arg(kFields[4].first) = 0.0, bp::arg(kFields[5].first) = 0.0)))
      .def("record", &record, "{field: value}, by the names of HertzMaterial.fields: HertzMaterial(**m.record()) == m.")
      .def("__repr__", &repr)
      .def("__eq__", &equal)
      .def("__hash__", +[](const HertzMaterial& m) { return bp::object(repr(m)).attr("__hash__")(); })
      .def_pickle(MaterialPickle());
  bp::list names;
  for (const auto& [name, field] : kFields) {
    material.add_property(name, bp::make_getter(field));
    names.append(name);
  }
  material.attr("fields") = bp::tuple(names);
}

}  // namespace roundedmesh::python
