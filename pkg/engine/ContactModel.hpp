// What the contact engine knows that does not change from step to step: the rounded bodies with their
// meshes and materials, the rigid-shaped partners (planes, YADE Walls, Boxes, Facets and Spheres) with
// theirs, and the engine's options (EngineOptions.hpp). A partner may be a sphere body (rm.add_sphere), the
// engine's second kind of body: an analytic Sphere whose contacts with the other partners the engine computes too.
// Indices into `bodies` and `partners` are the engine's; `id` is YADE's body id.
#pragma once

#include <cmath>
#include <memory>
#include <variant>
#include <vector>

#include "pkg/engine/EngineOptions.hpp"
#include "pkg/material/HertzMaterial.hpp"
#include "pkg/shape/Box.hpp"
#include "pkg/shape/Facet.hpp"
#include "pkg/shape/MassProperties.hpp"
#include "pkg/shape/Plane.hpp"
#include "pkg/shape/RoundedMesh.hpp"
#include "pkg/shape/Sphere.hpp"
#include "pkg/shape/Wall.hpp"

namespace roundedmesh {

// A Plane is given in the global frame; the others are placed by their body's state.
using PartnerShape = std::variant<Plane, Wall, Box, Facet, Sphere>;

// The deepest overlap a Hertz contact is meant to reach, as a fraction of the smaller body's volume-equivalent
// radius: the depth a new candidate list holds, the depth past which a triangle pair must also pass the
// deep-contact criterion (DeepContactCriterion.hpp), and the overlap of the time-step estimate (CriticalTimeStep.hpp).
constexpr Real kDeepestOverlap = 0.1;

struct RoundedBody {
  int id;
  std::shared_ptr<const RoundedMesh> mesh;  // in the body's principal frame
  HertzMaterial material;
  Real equivalentRadius;  // radius of the sphere of the same volume [m]
};

// The contact engine's view of a body made of `mesh` (a BodyMesh, pkg/meshing/BodyMesh.hpp, or anything with its
// sharedShape() and volume() [m^3]): its shape, material and volume-equivalent radius.
template <class Mesh>
RoundedBody roundedBody(int id, const Mesh& mesh, const HertzMaterial& material) {
  return {id, mesh.sharedShape(), material, equivalentRadius(mesh.volume())};
}

struct Partner {
  int id;
  PartnerShape shape;
  HertzMaterial material;
  bool sphereBody = false;  // a Sphere that touches the other partners through the engine (doc/architecture.md)
  Real edgeRadius = -1;     // [m] what its convex edges and corners are rounded by (a Box's, a Facet surface's);
                            // negative: the default of edgeRadiusFor
};

// The radius [m] a partner's convex edges and corners are rounded by for a body of volume-equivalent radius
// `bodyRadius` [m]: the partner's own, or by default kDeepestOverlap of the body's: the deepest a Hertz contact is
// meant to reach, so that the edge's contact stays in its Hertz range over the body's.
inline Real edgeRadiusFor(const Partner& partner, Real bodyRadius) {
  return partner.edgeRadius >= 0 ? partner.edgeRadius : kDeepestOverlap * bodyRadius;
}

// Skins of the lists kept between steps, as fractions of a volume-equivalent radius. The broad phase's
// neighbour list grows every bound by half of `neighbours` (times the smallest body's radius) and is rebuilt
// when a bound leaves its grown box. A pair's candidate triangle pairs hold for relative motions up to the
// list's skin: the motion the pair made per step over its last list, times `candidateSteps`, within
// [candidatesMin, candidatesMax] times the smaller radius of the pair, so that a list lasts about
// candidateSteps steps whether the pair rests or flies. The near list it is taken from has `nearFactor`
// times its skin (doc/physics.md, "Lists kept between steps").
struct ListSkins {
  Real neighbours = 0.2;
  Real candidatesMin = 0.001;
  Real candidatesMax = 0.01;
  Real candidateSteps = 10;
  Real nearFactor = 5;
};

struct ContactModel {
  std::vector<RoundedBody> bodies;
  std::vector<Partner> partners;
  EngineOptions options;
  ListSkins skins;
};

}  // namespace roundedmesh
