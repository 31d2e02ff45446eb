#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {

const std::vector<NormalLawEntry>& normalLaws() {
  static const std::vector<NormalLawEntry> registry = {
      {"pressure", NormalLaw::Pressure, &pressureNormalLaw, false, false},
      {"energy", NormalLaw::Energy, &energyNormalLaw, true, true},
  };
  return registry;
}

const NormalLawEntry& normalLaw(NormalLaw law) { return normalLaws()[static_cast<size_t>(law)]; }

}  // namespace roundedmesh
