#include "pkg/engine/EngineOptions.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {
namespace {

std::vector<const char*> normalLawNames() {
  std::vector<const char*> names;
  for (const NormalLawEntry& law : normalLaws()) names.push_back(law.name);
  return names;
}

// The table's order is rm.engine's and the saved record's; a choice's names follow its enum's values (the normal
// laws' are their registry's, NormalLaws.hpp).
const std::vector<EngineOptionField> kFields = {
    {"gamma", "expected number of quadrature points in a contact circle below which a triangle contact uses the "
              "direct regime (Eq. 14); 10 as in the paper", {}},
    {"regime", "'auto' (Eq. 14), 'quadrature' or 'direct' to force one regime, or 'exact': the pressure integrated "
               "over each contact in closed form", {"auto", "quadrature", "direct", "exact"}},
    {"friction", "the tangential law: 'spring', an elastic spring-dashpot per body pair capped by Coulomb, or "
                 "'viscous', the paper's no-slip force -c v_t (Eqs. 18-21)", {"spring", "viscous"}},
    {"stop_overlap", "a pair whose overlap grows past this fraction of the smaller side's size (r_eq, or a sphere's "
                     "radius) stops the run; math.inf never", {}},
    {"curvature", "'mean': the contact circle from each triangle's mean curvature (Eq. 1); 'principal': Hertz's "
                  "contact ellipse from both principal curvatures", {"mean", "principal"}},
    {"normal", "'pressure': each triangle contact's integrated pressure at its centre of pressure (Eq. 15); "
               "'energy': the exact gradient of the contacts' energy (curvature 'mean')", normalLawNames()},
    {"core_inset", "how far below the surface each sphere of a body's core lies, as a fraction of its inscribed radius: "
                   "the cores push where a pair overlaps past the Hertz range of its own radii; 1: no core", {}},
    {"threads", "OpenMP threads of a step; 0: as YADE, OMP_NUM_THREADS where set (yade -jN), else one", {}},
    {"timing", "'off', or 'stages': rm.statistics() also gives the CPU time of each stage inside the pairs (lists, "
               "near searches, narrow phase, law, core), for a few clock readings per pair", {"off", "stages"}},
};

const EngineOptionField& field(const std::string& name) {
  if (const EngineOptionField* f = findEngineOptionField(name)) return *f;
  throw std::invalid_argument("unknown engine option '" + name + "'; known: " + engineOptionNames());
}

// The enum behind a choice, as the index of its value in the field's list.
size_t choiceIndex(const EngineOptions& o, const std::string& name) {
  if (name == "regime") return static_cast<size_t>(o.pressure.regime);
  if (name == "friction") return static_cast<size_t>(o.friction);
  if (name == "curvature") return static_cast<size_t>(o.pressure.curvature);
  if (name == "normal") return static_cast<size_t>(o.pressure.normal);
  if (name == "timing") return static_cast<size_t>(o.timing);
  throw std::invalid_argument("engine option '" + name + "' is a number, not a choice");
}

std::string number(Real value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}

}  // namespace

const std::vector<EngineOptionField>& engineOptionFields() { return kFields; }

const EngineOptionField* findEngineOptionField(const std::string& name) {
  for (const EngineOptionField& f : kFields)
    if (name == f.name) return &f;
  return nullptr;
}

std::string engineOptionNames() {
  std::string names;
  for (const EngineOptionField& f : kFields) names += std::string(names.empty() ? "" : ", ") + f.name;
  return names;
}

void EngineOptions::validate() const {
  if (!(std::isfinite(pressure.gamma) && pressure.gamma > 0))
    throw std::invalid_argument("gamma must be positive and finite, got " + number(pressure.gamma));
  if (!(stopOverlap > 0))
    throw std::invalid_argument("stop_overlap must be positive (math.inf: never), got " + number(stopOverlap));
  if (!(coreInset > 0 && coreInset <= 1))
    throw std::invalid_argument("core_inset must be in (0, 1] (1: no core), got " + number(coreInset));
  if (threads < 0) throw std::invalid_argument("threads must be 0 (as YADE) or positive, got " + std::to_string(threads));
  if (pressure.normal == NormalLaw::Energy && pressure.curvature != CurvatureModel::Mean)
    throw std::invalid_argument("normal='energy' takes the contact circle of curvature='mean', not the ellipse of '" +
                                choiceName(*this, "curvature") + "'");
}

int EngineOptions::resolvedThreads() const {
  if (threads > 0) return threads;
  const char* environment = std::getenv("OMP_NUM_THREADS");
  const int given = environment ? std::atoi(environment) : 0;
  return given > 0 ? given : 1;
}

bool EngineOptions::operator==(const EngineOptions& o) const {
  return pressure.gamma == o.pressure.gamma && pressure.regime == o.pressure.regime &&
         pressure.curvature == o.pressure.curvature && pressure.normal == o.pressure.normal && friction == o.friction &&
         stopOverlap == o.stopOverlap && coreInset == o.coreInset && threads == o.threads && timing == o.timing;
}

std::string choiceName(const EngineOptions& options, const std::string& name) {
  return field(name).choices.at(choiceIndex(options, name));
}

void setChoice(EngineOptions& options, const std::string& name, const std::string& value) {
  const EngineOptionField& f = field(name);
  if (f.choices.empty()) throw std::invalid_argument(name + " must be a number, got '" + value + "'");
  std::string known;  // 'a', 'b' or 'c'
  for (size_t k = 0; k < f.choices.size(); ++k) {
    if (value == f.choices[k]) {
      if (name == "regime") options.pressure.regime = static_cast<RegimeChoice>(k);
      if (name == "friction") options.friction = static_cast<FrictionLaw>(k);
      if (name == "curvature") options.pressure.curvature = static_cast<CurvatureModel>(k);
      if (name == "normal") options.pressure.normal = static_cast<NormalLaw>(k);
      if (name == "timing") options.timing = static_cast<Timing>(k);
      return;
    }
    known += std::string(k == 0 ? "" : k + 1 == f.choices.size() ? " or " : ", ") + "'" + f.choices[k] + "'";
  }
  throw std::invalid_argument(name + " must be " + known + ", got '" + value + "'");
}

Real numberValue(const EngineOptions& options, const std::string& name) {
  if (!field(name).choices.empty()) throw std::invalid_argument("engine option '" + name + "' is a choice, not a number");
  if (name == "gamma") return options.pressure.gamma;
  if (name == "stop_overlap") return options.stopOverlap;
  if (name == "core_inset") return options.coreInset;
  return options.threads;
}

void setNumber(EngineOptions& options, const std::string& name, Real value) {
  if (!field(name).choices.empty())
    throw std::invalid_argument(name + " must be " + std::string("a name, got the number ") + number(value));
  if (name == "gamma") options.pressure.gamma = value;
  if (name == "stop_overlap") options.stopOverlap = value;
  if (name == "core_inset") options.coreInset = value;
  if (name == "threads") {
    if (!(value >= 0 && value <= 1024 && value == std::floor(value)))
      throw std::invalid_argument("threads must be a whole number from 0 (as YADE) to 1024, got " + number(value));
    options.threads = static_cast<int>(value);
  }
}

}  // namespace roundedmesh
