#include "pkg/engine/RoundedMeshEngine.hpp"

#include <cmath>

#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// The plane a partner presents to a body at bodyPosition (global frame); Boxes are not planes.
Plane presentedPlane(const PartnerShape& shape, const BodyState& partner, const Vector3r& bodyPosition) {
  if (const Wall* wall = std::get_if<Wall>(&shape)) return wallPlane(*wall, partner.position, bodyPosition);
  return std::get<Plane>(shape);
}

Real distanceToBox(const Box& box, const BodyState& state, const Vector3r& point) {
  const Vector3r local = state.orientation.conjugate() * (point - state.position);
  return (local.cwiseAbs() - box.halfExtents).cwiseMax(0.0).norm();
}

}  // namespace

bool boundsOverlap(const ContactModel& model, const ContactData& data, int b, int p) {
  const Vector3r& centre = data.bodyStates[b].position;
  const Real reach = model.bodies[b].mesh->sphereBoundRadius();
  const PartnerShape& shape = model.partners[p].shape;
  const BodyState& partner = data.partnerStates[p];
  if (const Box* box = std::get_if<Box>(&shape)) return distanceToBox(*box, partner, centre) < reach;
  const Plane plane = presentedPlane(shape, partner, centre);
  return std::abs(plane.normal.dot(centre - plane.point)) < reach;
}

void resolvePair(const ContactModel& model, ContactData& data, int b, int p, Wrench& onBody, Wrench& onPartner) {
  const RoundedBody& body = model.bodies[b];
  const Partner& partner = model.partners[p];
  const BodyState& s1 = data.bodyStates[b];
  const BodyState& s2 = data.partnerStates[p];
  const Matrix3r toGlobal = s1.orientation.toRotationMatrix();
  const Matrix3r toBody = toGlobal.transpose();

  RelativeMotion motion;
  motion.linear = toBody * (s2.velocity - s1.velocity + s2.angularVelocity.cross(s1.position - s2.position));
  motion.angular = toBody * (s2.angularVelocity - s1.angularVelocity);

  data.geoms.clear();
  std::visit(Overloaded{[&](const Box& box) {
                          Ig2_RoundedMesh_Box_PressureGeom(*body.mesh, box, toBody * (s2.position - s1.position),
                                                           toBody * s2.orientation.toRotationMatrix(), motion,
                                                           data.geoms);
                        },
                        [&](const auto&) {
                          const Plane global = presentedPlane(partner.shape, s2, s1.position);
                          const Plane local{toBody * (global.point - s1.position), toBody * global.normal};
                          Ig2_RoundedMesh_Plane_PressureGeom(*body.mesh, local, motion, data.geoms);
                        }},
             partner.shape);

  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(body.material, partner.material);
  Wrench local;
  for (const PressureGeom& geom : data.geoms) {
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, model.pressure);
    ++(load.regime == Regime::Direct ? data.statistics.directContacts : data.statistics.quadratureContacts);
    const Triangle& corners = body.mesh->triangles()[geom.triangle];
    const std::array<Vector3r, 3> x = {body.mesh->vertices()[corners[0]], body.mesh->vertices()[corners[1]],
                                       body.mesh->vertices()[corners[2]]};
    addNodeForcesToBody(x, nodeForces(geom.nodes, load), geom.normal, local);
  }
  onBody.force = toGlobal * local.force;
  onBody.torque = toGlobal * local.torque;
  // Body 2 receives the opposite node forces at the same points.
  onPartner.force = -onBody.force;
  onPartner.torque = -onBody.torque + (s1.position - s2.position).cross(onPartner.force);
}

void RoundedMeshEngine(const ContactModel& model, ContactData& data) {
  data.statistics = ContactStatistics();
  for (Wrench& w : data.bodyWrenches) w = Wrench();
  for (Wrench& w : data.partnerWrenches) w = Wrench();
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    for (int p = 0; p < static_cast<int>(model.partners.size()); ++p) {
      if (!boundsOverlap(model, data, b, p)) continue;
      ++data.statistics.bodyPairs;
      Wrench onBody, onPartner;
      resolvePair(model, data, b, p, onBody, onPartner);
      data.bodyWrenches[b].force += onBody.force;
      data.bodyWrenches[b].torque += onBody.torque;
      data.partnerWrenches[p].force += onPartner.force;
      data.partnerWrenches[p].torque += onPartner.torque;
    }
  }
}

}  // namespace roundedmesh
