// roundedmesh.EngineOptions (pkg/engine/EngineOptions.hpp): every option of the contact engine, made and checked
// from keywords by the C++ field table, read-only, with its record for the scene's tags.
#include "py/module/ExposeEngineOptions.hpp"

#include <memory>
#include <sstream>
#include <string>

namespace roundedmesh::python {
namespace {

[[noreturn]] void raiseTypeError(const std::string& message) {
  PyErr_SetString(PyExc_TypeError, message.c_str());
  bp::throw_error_already_set();
  throw std::logic_error("unreachable");
}

std::string pythonRepr(const bp::object& value) { return bp::extract<std::string>(value.attr("__repr__")()); }

bool isNumber(const bp::object& value) {
  PyObject* p = value.ptr();
  return !PyBool_Check(p) && (PyFloat_Check(p) || PyLong_Check(p) || PyObject_HasAttrString(p, "__float__")) &&
         !PyComplex_Check(p);
}

bp::object valueOf(const EngineOptions& options, const EngineOptionField& f) {
  if (!f.choices.empty()) return bp::object(choiceName(options, f.name));
  const Real number = numberValue(options, f.name);
  return std::string(f.name) == "threads" ? bp::object(static_cast<int>(number)) : bp::object(number);
}

std::shared_ptr<EngineOptions> copyOf(const EngineOptions& options) { return std::make_shared<EngineOptions>(options); }

// EngineOptions(**options): the keyword arguments as the binding's one entry point, so that an unknown name, a
// value of the wrong type and a value out of range each get a message naming the option.
bp::object construct(bp::tuple args, bp::dict keywords) {
  if (bp::len(args) != 1) raiseTypeError("EngineOptions takes keyword arguments only (" + engineOptionNames() + ")");
  return args[0].attr("_construct")(engineOptions(keywords));
}

bp::dict record(const EngineOptions& options) {
  bp::dict d;
  for (const EngineOptionField& f : engineOptionFields()) d[f.name] = valueOf(options, f);
  return d;
}

std::string repr(const EngineOptions& options) {
  std::ostringstream s;
  s << "EngineOptions(";
  for (const EngineOptionField& f : engineOptionFields())
    s << (&f == &engineOptionFields().front() ? "" : ", ") << f.name << "=" << pythonRepr(valueOf(options, f));
  s << ")";
  return s.str();
}

struct OptionsPickle : bp::pickle_suite {
  static bp::tuple getstate(const EngineOptions& options) { return bp::make_tuple(record(options)); }
  static void setstate(EngineOptions& options, bp::tuple state) {
    options = engineOptions(bp::extract<bp::dict>(state[0]));
  }
};

}  // namespace

EngineOptions engineOptions(const bp::dict& keywords) {
  EngineOptions options;
  const bp::list names = keywords.keys();
  std::string unknown;
  for (long k = 0; k < bp::len(names); ++k) {
    const std::string name = bp::extract<std::string>(names[k]);
    if (!findEngineOptionField(name)) unknown += std::string(unknown.empty() ? "" : ", ") + name;
  }
  if (!unknown.empty()) raiseTypeError("unknown option(s) " + unknown + "; known: " + engineOptionNames());
  for (const EngineOptionField& f : engineOptionFields()) {
    if (!keywords.has_key(f.name)) continue;
    const bp::object value = keywords[f.name];
    if (!f.choices.empty()) {
      if (!PyUnicode_Check(value.ptr())) raiseTypeError(std::string(f.name) + ": expected a string, got " + pythonRepr(value));
      setChoice(options, f.name, bp::extract<std::string>(value));
    } else {
      if (!isNumber(value)) raiseTypeError(std::string(f.name) + ": expected a number, got " + pythonRepr(value));
      setNumber(options, f.name, bp::extract<Real>(value.attr("__float__")()));
    }
  }
  options.validate();
  return options;
}

void exposeEngineOptions() {
  std::string doc =
      "Every option of the contact engine (rm.engine(**options), rm.engine(options=...), and the contact\n"
      "functions' options=), checked on construction: EngineOptions(name=value, ...), any left out at its\n"
      "default. Read-only; record() is {name: value}, EngineOptions(**o.record()) == o. Options:\n";
  for (const EngineOptionField& f : engineOptionFields()) doc += std::string("  ") + f.name + ": " + f.meaning + "\n";
  bp::class_<EngineOptions, std::shared_ptr<EngineOptions>> options("EngineOptions", doc.c_str(), bp::no_init);
  options.def("__init__", bp::raw_function(&construct))
      .def("_construct", bp::make_constructor(&copyOf))
      .def("record", &record, "{option: value}, in the order of EngineOptions.fields.")
      .def("__repr__", &repr)
      .def("__eq__", +[](const EngineOptions& a, const EngineOptions& b) { return a == b; })
      .def("__hash__", +[](const EngineOptions& o) { return bp::object(repr(o)).attr("__hash__")(); })
      .def_pickle(OptionsPickle());
  bp::list names;
  bp::dict choices;
  for (const EngineOptionField& f : engineOptionFields()) {
    const std::string name = f.name;
    options.add_property(f.name, bp::make_function(
                                     [name](const EngineOptions& o) { return valueOf(o, *findEngineOptionField(name)); },
                                     bp::default_call_policies(),
                                     boost::mpl::vector<bp::object, const EngineOptions&>()));
    names.append(f.name);
    if (f.choices.empty()) continue;
    bp::list allowed;
    for (const char* choice : f.choices) allowed.append(choice);
    choices[f.name] = bp::tuple(allowed);
  }
  options.attr("fields") = bp::tuple(names);
  // The defaults and the allowed values of the choices, as plain dicts.
  bp::scope().attr("ENGINE_OPTIONS") = record(EngineOptions());
  bp::scope().attr("ENGINE_CHOICES") = choices;
}

}  // namespace roundedmesh::python
