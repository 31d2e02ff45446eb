#include "pkg/engine/PairLoad.hpp"

#include <algorithm>
#include <variant>

#include "pkg/engine/PairFriction.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/law/DampedLoads.hpp"
#include "pkg/law/PairLaw.hpp"
#include "pkg/math/DiskPolygonBatch.hpp"

namespace roundedmesh {
namespace {

// Body 2 of a triangle contact as a normal law that needs it sees it (NormalLaws.hpp), in body 1's frame: the pose
// of a rounded body 2 (x1 = rotation * x2 + translation), or its partner shape.
struct PartnerFrame {
  const RoundedMesh* mesh2 = nullptr;
  Matrix3r rotation = Matrix3r::Identity();
  Vector3r translation = Vector3r::Zero();
  EnergyPartner::Kind kind = EnergyPartner::Plane;

  EnergyPartner partner(const PressureGeom& geom) const {
    EnergyPartner p{kind, Vector3r::Zero(), {}};
    if (kind == EnergyPartner::Triangle) {
      const Triangle& corners = mesh2->triangles()[geom.partnerTriangle];
      for (int i = 0; i < 3; ++i) p.corners[i] = rotation * mesh2->vertices()[corners[i]] + translation;
      const RoundedTriangle& rounded = mesh2->rounded(geom.partnerTriangle);
      p.sphereCentre = rotation * rounded.sphereCentre + translation;
      p.normal = rotation * rounded.normal;
    } else if (kind == EnergyPartner::Sphere) {
      p.sphereCentre = translation;
    }
    return p;
  }
};

PartnerFrame partnerFrame(const ContactModel& model, const BodyPair& pair, const BodyState& s1, const BodyState& s2,
                          const Matrix3r& R_BW) {
  PartnerFrame frame;
  const int bodyCount = static_cast<int>(model.bodies.size());
  frame.translation = R_BW * (s2.position - s1.position);
  if (pair.other < bodyCount) {
    frame.kind = EnergyPartner::Triangle;
    frame.mesh2 = model.bodies[pair.other].mesh.get();
    frame.rotation = R_BW * s2.orientation.toRotationMatrix();
  } else if (std::holds_alternative<Sphere>(model.partners[pair.other - bodyCount].shape)) {
    frame.kind = EnergyPartner::Sphere;
  }
  return frame;
}

}  // namespace

Wrench reaction(const Wrench& onBody, const Vector3r& bodyPosition, const Vector3r& otherPosition) {
  return {-onBody.force, -onBody.torque + (otherPosition - bodyPosition).cross(onBody.force)};
}

// Frames: R_WB turns body 1's axes into the world's; ..._B is in body 1's frame (origin at its position), as the
// geoms are; ..._W in the world's.
PairResult pairLoad(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                    const std::vector<PressureGeom>& geoms, std::vector<TriangleContact>* contacts,
                    TangentialSpring* spring) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const bool otherIsBody = pair.other < bodyCount;
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const BodyState& s2 = otherIsBody ? data.bodyStates[pair.other] : data.partnerStates[pair.other - bodyCount];
  const HertzMaterial& otherMaterial =
      otherIsBody ? model.bodies[pair.other].material : model.partners[pair.other - bodyCount].material;
  PairResult result;
  PairSummary& summary = result.summary;
  if (geoms.empty()) {
    if (spring) releaseSpring(*spring, data.timeStep, summary);  // not touching: the spring lets go
    result.onOther = reaction(result.onBody, s1.position, s2.position);
    return result;
  }
  const Matrix3r R_WB = s1.orientation.toRotationMatrix();
  const PairLaw law(body.material, otherMaterial, model.options.pressure, model.options.friction);
  const HertzPhys& phys = law.phys;
  const RoundedMesh& mesh = *body.mesh;
  Wrench onBody_B;
  // Sums of Fn times the point of application and along the normal, and of the unweighted ones for a pair
  // whose normal forces are all zero; the pair's normal stiffness.
  Vector3r moment_B = Vector3r::Zero(), normals_B = Vector3r::Zero(), points_B = Vector3r::Zero();
  Real normalForce = 0, stiffness = 0;
  // The friction laws' inputs, only where the pair has friction.
  const bool frictional = law.frictional(), springs = frictional && !law.viscous();
  thread_local std::vector<ContactShare> shares;
  shares.clear();
  const size_t listedFrom = contacts ? contacts->size() : 0;
  const bool needsPartner = law.normal->needsPartner;
  const PartnerFrame frame = needsPartner ? partnerFrame(model, pair, s1, s2, R_WB.transpose()) : PartnerFrame();
  // Law2 in two stages, 16 contacts at a time: each contact's elastic load (in closed form, the polygons' edges in
  // lanes, where the options ask for it), then their damping and node forces (Eq. 15) in lanes.
  thread_local DiskPolygonBatch exact;
  thread_local DampedLoads batch;
  static_assert(DiskPolygonBatch::kPolygons == DampedLoads::kCapacity);
  const bool exactly = law.integratesExactly();
  batch.damping = phys.damping;
  batch.withDamping = law.normal->needsDamping;
  // One contact's force on the bodies and its share of the pair's sums, added in the contacts' order, from its lane of
  // the batches.
  auto addContact = [&](const PressureGeom& geom, int lane) {
    NormalLoad load = batch.load(lane);
    const std::array<Real, 3> forces = batch.nodeForces(lane);
    ++(load.regime == Regime::Direct  ? result.statistics.directContacts
       : load.regime == Regime::Exact ? result.statistics.exactContacts
                                      : result.statistics.quadratureContacts);
    const Triangle& corners = mesh.triangles()[geom.triangle];
    const std::array<Vector3r, 3> x_B = {mesh.vertices()[corners[0]], mesh.vertices()[corners[1]],
                                         mesh.vertices()[corners[2]]};
    const EnergyPartner partner = needsPartner ? frame.partner(geom) : EnergyPartner{};
    const RoundedTriangle& rounded = mesh.rounded(geom.triangle);
    load.elasticEnergy =
        law.normal->apply({geom, load, x_B, forces, batch.dampingNodeForces(lane), rounded.sphereCentre, rounded.normal,
                           partner, phys, exactly ? &exact : nullptr, lane},
                          onBody_B);
    const Vector3r point_B = planePoint(geom, geom.effectivePoint);
    // Fn acts at c + (-Mn_y, Mn_x) / Fn (NodeForces.hpp), so Fn times that point needs no division.
    const Vector3r weighted_B =
        load.force * geom.centre - load.moment.y() * geom.tangent1 + load.moment.x() * geom.tangent2;
    moment_B += weighted_B;
    normalForce += load.force;
    normals_B += load.force * geom.normal;
    points_B += point_B;
    if (springs && geom.sphereOverlap > 0) stiffness += hertzStiffness(load.elasticForce, geom.sphereOverlap);
    if (frictional) shares.push_back({load, load.force > 0 ? Vector3r(weighted_B / load.force) : point_B});
    summary.add(geom, load);
    if (contacts) {
      TriangleContact& c = contacts->emplace_back();
      c.geom = geom;
      c.point = s1.position + R_WB * point_B;
      c.normal = R_WB * geom.normal;
      c.load = load;
      c.friction = TangentialLoad();
      c.nodeForces = forces;
      if (geom.partnerTriangle >= 0) c.partnerNodeForces = nodeForces(geom.partnerNodes, load);
    }
  };
  const int count = static_cast<int>(geoms.size());
  for (int first = 0; first < count; first += DampedLoads::kCapacity) {
    batch.size = std::min(DampedLoads::kCapacity, count - first);
    if (exactly) {
      exact.clear();
      for (int k = 0; k < batch.size; ++k) exact.add(geoms[first + k].contactRadius, circlePolygon(geoms[first + k]));
      integrateDiskPolygons(exact);
      for (int k = 0; k < batch.size; ++k)
        batch.set(k, law.exactLoad(exact.integrals(k), geoms[first + k]), geoms[first + k]);
    } else {
      for (int k = 0; k < batch.size; ++k) batch.set(k, law.elasticLoad(geoms[first + k]), geoms[first + k]);
    }
    dampLoads(batch);
    for (int k = 0; k < batch.size; ++k) addContact(geoms[first + k], k);
  }
  summary.triangleContacts = static_cast<int>(geoms.size());
  const bool loaded = normalForce > 0;
  const Vector3r centre_B = loaded ? Vector3r(moment_B / normalForce) : Vector3r(points_B / geoms.size());
  if (!loaded)
    for (const PressureGeom& geom : geoms) normals_B += geom.normal;
  const Vector3r normal_B = normals_B.normalized();
  summary.point = s1.position + R_WB * centre_B;
  summary.normal = R_WB * normal_B;
  for (const PressureGeom& geom : geoms)
    summary.depth = std::max(summary.depth, geom.effectiveOverlap * geom.normal.dot(normal_B));
  TriangleContact* listed = contacts ? contacts->data() + listedFrom : nullptr;
  dropUnusedSpring(law, spring, data.timeStep, summary);
  if (frictional) {
    if (law.viscous()) {
      viscousFriction(geoms, shares, phys, R_WB, onBody_B, result, listed);
    } else {
      TangentialSpring fresh;
      springFriction(shares, normalForce, stiffness, centre_B, normal_B, relativeMotion(s1, s2, R_WB.transpose()),
                     s1, s2, phys, spring ? data.timeStep : 0, R_WB, spring ? *spring : fresh, onBody_B, result,
                     listed);
    }
  }
  result.onBody.force = R_WB * onBody_B.force;
  result.onBody.torque = R_WB * onBody_B.torque;
  // For a mesh, Eq. 15 on its own triangle's corners gives the same wrench as reaction's (doc/physics.md).
  result.onOther = reaction(result.onBody, s1.position, s2.position);
  return result;
}

}  // namespace roundedmesh
