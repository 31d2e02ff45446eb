#include "pkg/engine/ContactModel.hpp"

#include <cmath>

namespace roundedmesh {

RoundedBody roundedBody(int id, const BodyMesh& mesh, const HertzMaterial& material) {
  return {id, mesh.sharedShape(), material, std::cbrt(3 * mesh.volume() / (4 * M_PI))};
}

}  // namespace roundedmesh
