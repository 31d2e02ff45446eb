#include "pkg/engine/RoundedMeshEngine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <omp.h>

#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Sphere_PressureGeom.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

// The plane a partner presents to a body at bodyPosition (global frame): a Plane, or a Wall.
Plane presentedPlane(const PartnerShape& shape, const BodyState& partner, const Vector3r& bodyPosition) {
  if (const Wall* wall = std::get_if<Wall>(&shape)) return wallPlane(*wall, partner.position, bodyPosition);
  return std::get<Plane>(shape);
}

std::array<Vector3r, 3> facetCorners(const Facet& facet, const BodyState& state) {
  std::array<Vector3r, 3> corners;
  for (int i = 0; i < 3; ++i) corners[i] = state.position + state.orientation * facet.vertices[i];
  return corners;
}

AlignedBox3r ball(const Vector3r& centre, Real radius) {
  return AlignedBox3r(centre.array() - radius, centre.array() + radius);
}

// The world box of a partner: where a body must reach to touch it.
AlignedBox3r partnerBox(const PartnerShape& shape, const BodyState& state) {
  return std::visit(Overloaded{[&](const Plane&) { return AlignedBox3r(Vector3r::Constant(-kInfinity), Vector3r::Constant(kInfinity)); },
                               [&](const Wall& wall) {
                                 AlignedBox3r box(Vector3r::Constant(-kInfinity), Vector3r::Constant(kInfinity));
                                 box.min()[wall.axis] = box.max()[wall.axis] = state.position[wall.axis];
                                 return box;
                               },
                               [&](const Box& b) {
                                 return transformedBox(AlignedBox3r(-b.halfExtents, b.halfExtents),
                                                       state.orientation.toRotationMatrix(), state.position);
                               },
                               [&](const Facet& facet) {
                                 AlignedBox3r box;
                                 for (const Vector3r& x : facetCorners(facet, state)) box.extend(x);
                                 return box;
                               },
                               [&](const Sphere& sphere) { return ball(state.position, sphere.radius); }},
                    shape);
}

// Ig2 of body 1's triangles against the other side, in body 1's frame (origin at its position).
void contactGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                     const RelativeMotion& motion, std::vector<PressureGeom>& geoms) {
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const Matrix3r toBody = s1.orientation.toRotationMatrix().transpose();
  auto local = [&](const Vector3r& x) -> Vector3r { return toBody * (x - s1.position); };
  const int bodyCount = static_cast<int>(model.bodies.size());
  if (pair.other < bodyCount) {
    const BodyState& s2 = data.bodyStates[pair.other];
    const RoundedBody& other = model.bodies[pair.other];
    Ig2_RoundedMesh_RoundedMesh_PressureGeom(*body.mesh, *other.mesh, toBody * s2.orientation.toRotationMatrix(),
                                             local(s2.position),
                                             kDeepestOverlap * std::min(body.equivalentRadius, other.equivalentRadius),
                                             motion, geoms);
    return;
  }
  const BodyState& s2 = data.partnerStates[pair.other - bodyCount];
  const PartnerShape& shape = model.partners[pair.other - bodyCount].shape;
  std::visit(Overloaded{[&](const Box& box) {
                          Ig2_RoundedMesh_Box_PressureGeom(*body.mesh, box, local(s2.position),
                                                           toBody * s2.orientation.toRotationMatrix(), motion, geoms);
                        },
                        [&](const Facet& facet) {
                          std::array<Vector3r, 3> corners = facetCorners(facet, s2);
                          for (Vector3r& x : corners) x = local(x);
                          Ig2_RoundedMesh_Facet_PressureGeom(*body.mesh, corners, kDeepestOverlap * body.equivalentRadius,
                                                             motion, geoms);
                        },
                        [&](const Sphere& sphere) {
                          Ig2_RoundedMesh_Sphere_PressureGeom(*body.mesh, sphere, local(s2.position), motion, geoms);
                        },
                        [&](const auto&) {
                          const Plane global = presentedPlane(shape, s2, s1.position);
                          Ig2_RoundedMesh_Plane_PressureGeom(*body.mesh, Plane{local(global.point), toBody * global.normal},
                                                             motion, geoms);
                        }},
             shape);
}

}  // namespace

void broadPhase(const ContactModel& model, ContactData& data) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const int count = bodyCount + static_cast<int>(model.partners.size());
  std::vector<AlignedBox3r> boxes(count);
  Vector3r mean = Vector3r::Zero(), meanSq = Vector3r::Zero();
  for (int b = 0; b < bodyCount; ++b) {
    const Vector3r& x = data.bodyStates[b].position;
    boxes[b] = ball(x, model.bodies[b].mesh->sphereBoundRadius());
    mean += x;
    meanSq += x.cwiseProduct(x);
  }
  for (int p = 0; p < count - bodyCount; ++p)
    boxes[bodyCount + p] = partnerBox(model.partners[p].shape, data.partnerStates[p]);
  // Sweep along the axis on which the bodies spread most.
  int axis;
  (meanSq * bodyCount - mean.cwiseProduct(mean)).maxCoeff(&axis);

  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const Real a = boxes[i].min()[axis], b = boxes[j].min()[axis];
    return a < b || (a == b && i < j);
  });
  data.pairs.clear();
  for (int k = 0; k < count; ++k) {
    const int i = order[k];
    for (int l = k + 1; l < count && boxes[order[l]].min()[axis] <= boxes[i].max()[axis]; ++l) {
      const int j = order[l];
      if ((i >= bodyCount && j >= bodyCount) || !boxes[i].intersects(boxes[j])) continue;
      const int body = std::min(i, j), other = std::max(i, j);
      if (other < bodyCount &&
          (data.bodyStates[body].position - data.bodyStates[other].position).norm() >=
              model.bodies[body].mesh->sphereBoundRadius() + model.bodies[other].mesh->sphereBoundRadius())
        continue;
      data.pairs.push_back({body, other});
    }
  }
  // Sorted, so that the pairs and the sums over them do not depend on how the sweep met them.
  std::sort(data.pairs.begin(), data.pairs.end(),
            [](const BodyPair& a, const BodyPair& b) { return a.body < b.body || (a.body == b.body && a.other < b.other); });
}

PairResult resolvePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                       std::vector<PressureGeom>& scratch, std::vector<TriangleContact>* contacts) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const bool otherIsBody = pair.other < bodyCount;
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const BodyState& s2 = otherIsBody ? data.bodyStates[pair.other] : data.partnerStates[pair.other - bodyCount];
  const HertzMaterial& otherMaterial =
      otherIsBody ? model.bodies[pair.other].material : model.partners[pair.other - bodyCount].material;
  const Matrix3r toGlobal = s1.orientation.toRotationMatrix();
  const Matrix3r toBody = toGlobal.transpose();

  RelativeMotion motion;
  motion.linear = toBody * (s2.velocity - s1.velocity + s2.angularVelocity.cross(s1.position - s2.position));
  motion.angular = toBody * (s2.angularVelocity - s1.angularVelocity);
  scratch.clear();
  contactGeometry(model, data, pair, motion, scratch);

  PairResult result;
  result.statistics.bodyPairs = 1;
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(body.material, otherMaterial);
  const RoundedMesh& mesh = *body.mesh;
  Wrench local;
  for (const PressureGeom& geom : scratch) {
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, model.pressure);
    ++(load.regime == Regime::Direct ? result.statistics.directContacts : result.statistics.quadratureContacts);
    const Triangle& corners = mesh.triangles()[geom.triangle];
    const std::array<Vector3r, 3> x = {mesh.vertices()[corners[0]], mesh.vertices()[corners[1]],
                                       mesh.vertices()[corners[2]]};
    const std::array<Real, 3> forces = nodeForces(geom.nodes, load);
    addNodeForcesToBody(x, forces, geom.normal, local);
    const TangentialLoad friction = coulombFriction(geom, load, phys);
    const Vector3r point = planePoint(geom, geom.effectivePoint);
    if (friction.sliding) ++result.statistics.slidingContacts;
    local.force -= friction.force;
    local.torque -= point.cross(friction.force);
    if (contacts) {
      TriangleContact& c = contacts->emplace_back();
      c.geom = geom;
      c.point = s1.position + toGlobal * point;
      c.normal = toGlobal * geom.normal;
      c.load = load;
      c.friction = {toGlobal * friction.force, friction.sliding};
      c.nodeForces = forces;
      if (geom.partnerTriangle >= 0) c.partnerNodeForces = nodeForces(geom.partnerNodes, load);
    }
  }
  result.onBody.force = toGlobal * local.force;
  result.onBody.torque = toGlobal * local.torque;
  // The other side receives the opposite forces at the same points (for a mesh, Eq. 15 on its own
  // triangle's corners gives the same wrench: doc/physics.md).
  result.onOther.force = -result.onBody.force;
  result.onOther.torque = -result.onBody.torque + (s1.position - s2.position).cross(result.onOther.force);
  return result;
}

void RoundedMeshEngine(const ContactModel& model, ContactData& data) {
  if (data.geoms.size() < static_cast<size_t>(omp_get_max_threads())) data.geoms.resize(omp_get_max_threads());
  broadPhase(model, data);
  const int pairCount = static_cast<int>(data.pairs.size());
  data.pairResults.resize(pairCount);
#pragma omp parallel for schedule(dynamic, 4) if (pairCount > 1)
  for (int k = 0; k < pairCount; ++k)
    data.pairResults[k] = resolvePair(model, data, data.pairs[k], data.geoms[omp_get_thread_num()]);

  const int bodyCount = static_cast<int>(model.bodies.size());
  data.statistics = ContactStatistics();
  for (Wrench& w : data.bodyWrenches) w = Wrench();
  for (Wrench& w : data.partnerWrenches) w = Wrench();
  for (int k = 0; k < pairCount; ++k) {
    const PairResult& r = data.pairResults[k];
    Wrench& body = data.bodyWrenches[data.pairs[k].body];
    const int other = data.pairs[k].other;
    Wrench& otherWrench = other < bodyCount ? data.bodyWrenches[other] : data.partnerWrenches[other - bodyCount];
    body.force += r.onBody.force;
    body.torque += r.onBody.torque;
    otherWrench.force += r.onOther.force;
    otherWrench.torque += r.onOther.torque;
    data.statistics += r.statistics;
  }
}

}  // namespace roundedmesh
