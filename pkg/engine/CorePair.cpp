#include "pkg/engine/CorePair.hpp"

#include <array>

#include "pkg/common/Overloaded.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"  // facetOwns
#include "pkg/math/ClosestPoint.hpp"
#include "pkg/math/Segment.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

// A body's core in the frame centred on its position with the global axes: centres [m] and radii [m], without an
// allocation (a step evaluates it for every pair).
struct PlacedCore {
  std::array<Vector3r, InscribedSpheres::kMaxSpheres> centres;
  std::array<Real, InscribedSpheres::kMaxSpheres> radii;
  int count = 0;
};

PlacedCore placedCore(const InscribedSpheres& spheres, const Quaternionr& orientation, Real inset) {
  PlacedCore core;
  const Matrix3r rotation = orientation.toRotationMatrix();
  core.count = static_cast<int>(spheres.radii.size());
  for (int i = 0; i < core.count; ++i) {
    core.centres[i] = rotation * spheres.centres[i];
    core.radii[i] = (1 - inset) * spheres.radii[i];
  }
  return core;
}

// Two cores, in body 1's frame: body 2's spheres brought there, each tested against the box of body 1's core first.
void againstCore(const InscribedSpheres& a, const BodyState& s1, const InscribedSpheres& b, const BodyState& s2,
                 Real inset, Real modulus, CoreLoad& load) {
  const Vector3r offset = s2.position - s1.position;
  if (offset.norm() >= a.reach + b.reach) return;
  const Matrix3r R1 = s1.orientation.toRotationMatrix();
  const Matrix3r R12 = R1.transpose() * s2.orientation.toRotationMatrix();
  const Vector3r t = R1.transpose() * offset;
  CoreLoad inBody;
  for (size_t j = 0; j < b.radii.size(); ++j) {
    const Vector3r c = R12 * b.centres[j] + t;
    const Real rho2 = (1 - inset) * b.radii[j];
    if (a.box.squaredExteriorDistance(c) >= rho2 * rho2) continue;
    for (size_t i = 0; i < a.radii.size(); ++i) {
      const Real rho1 = (1 - inset) * a.radii[i];
      const Vector3r apart = a.centres[i] - c;
      const Real distance = apart.norm();
      const Real delta = rho1 + rho2 - distance;
      if (delta <= 0 || distance == 0) continue;
      inBody.add(a.centres[i], apart / distance, delta, rho1 * rho2 / (rho1 + rho2), modulus);
    }
  }
  load = inBody;
  load.force = R1 * inBody.force;
  load.torque = R1 * inBody.torque;
}

// The core against a partner's solid: nearest(x, normal, height) gives, for a core centre x, the unit normal along
// which the partner pushes it and the centre's height over the partner's surface (negative inside), or false where
// this partner does not push it. partnerRadius: a Sphere's radius, infinite for a flat surface (R = rho).
template <class Nearest>
void againstSolid(const PlacedCore& core, Real partnerRadius, Real modulus, const Nearest& nearest, CoreLoad& load) {
  for (int i = 0; i < core.count; ++i) {
    const Real rho = core.radii[i];
    Vector3r normal;
    Real height;
    if (!nearest(core.centres[i], normal, height)) continue;
    const Real delta = rho - height;
    if (delta <= 0) continue;
    const Real radius = std::isinf(partnerRadius) ? rho : rho * partnerRadius / (rho + partnerRadius);
    load.add(core.centres[i], normal, delta, radius, modulus);
  }
}

// The point of the convex polygon `outline` (counter-clockwise in the plane coordinates, interior included) nearest p.
Vector2r nearestOnOutline(const std::vector<Vector2r>& outline, const Vector2r& p) {
  bool inside = true;
  Vector2r best = outline[0];
  Real bestDistance = kInfinity;
  const int n = static_cast<int>(outline.size());
  for (int k = 0; k < n; ++k) {
    const Vector2r &a = outline[k], &b = outline[(k + 1) % n];
    if (cross2(b - a, p - a) < 0) inside = false;
    const Vector2r q = closestOnSegment(p, a, b);
    if ((p - q).norm() < bestDistance) {
      bestDistance = (p - q).norm();
      best = q;
    }
  }
  return inside ? p : best;
}

void againstFacet(const PlacedCore& core, const Facet& facet, const BodyState& body, const BodyState& facetState,
                  Real modulus, CoreLoad& load) {
  const PlacedFacet placed = placeFacet(facet, facetState.orientation.toRotationMatrix(), facetState.position - body.position);
  const std::array<Vector3r, 3>& corners = placed.corners;
  if (!hasArea(corners)) return;
  const Vector3r normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  const int side = facetSide(placed);
  const Vector3r towardBody = side == 1 ? Vector3r(-normal) : normal;
  // A core sphere at least its radius in front of the plane is at least that far from every point of the facet: a
  // body resting on it (the core lies inset below its surface) is done here.
  bool reaches = false;
  for (int i = 0; i < core.count && !reaches; ++i)
    reaches = towardBody.dot(core.centres[i] - corners[0]) < core.radii[i];
  if (!reaches) return;
  const Vector3r t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);  // (t1, t2, normal) right-handed
  auto inPlane = [&](const Vector3r& x) { return Vector2r((x - corners[0]).dot(t1), (x - corners[0]).dot(t2)); };
  std::vector<Vector2r> outline;
  std::vector<bool> open;  // outline edge k (outline[k] to outline[k + 1]): nothing goes on beyond it on the body's side
  if (placed.weld) {
    for (size_t k = 0; k < placed.outline.size(); ++k) {  // counter-clockwise about the normal
      outline.push_back(inPlane(placed.outline[k]));
      open.push_back(!placed.weld->outlineClosed[k][side]);
    }
  } else {
    for (const Vector3r& x : corners) outline.push_back(inPlane(x));
    if (cross2(outline[1] - outline[0], outline[2] - outline[0]) < 0) std::swap(outline[1], outline[2]);
    open.assign(3, true);
  }
  // How far from p the sheet's nearest open edge is, in its plane.
  auto toOpenEdge = [&](const Vector2r& p) {
    Real nearest = kInfinity;
    const size_t n = outline.size();
    for (size_t k = 0; k < n; ++k)
      if (open[k]) nearest = std::min(nearest, (p - closestOnSegment(p, outline[k], outline[(k + 1) % n])).norm());
    return nearest;
  };
  const std::array<Vector2r, 3> own{inPlane(corners[0]), inPlane(corners[1]), inPlane(corners[2])};
  const FacetWeld* weld = placed.weld;
  auto owns = [&](const Vector2r& q) {
    if (!weld) return true;
    if (!facetOwns(own, *weld, q)) return false;
    // A point on an edge between two panels belongs to the one that rounds that edge (FacetWeld::ownsStrip).
    for (int e = 0; e < 3; ++e) {
      const Vector2r &a = own[e], &b = own[(e + 1) % 3];
      if (weld->beyond[e].allFinite() && (q - closestOnSegment(q, a, b)).norm() <= 1e-9 * (b - a).norm())
        return weld->ownsStrip[e];
    }
    return true;
  };
  againstSolid(core, kInfinity, modulus,
               [&](const Vector3r& x, Vector3r& pushed, Real& height) {
                 const Vector2r p = inPlane(x), q = nearestOnOutline(outline, p);
                 if (!owns(q)) return false;
                 const Real front = towardBody.dot(x - corners[0]);
                 if (q == p && front < 0 && -front < toOpenEdge(p)) {  // came through the sheet: pushed back
                   pushed = towardBody;
                   height = front;
                   return true;
                 }
                 const Vector3r away = x - (corners[0] + q.x() * t1 + q.y() * t2);
                 height = away.norm();
                 if (height == 0) return false;
                 pushed = away / height;
                 return true;
               },
               load);
}

void againstPlane(const PlacedCore& core, const Plane& plane, const BodyState& body, Real modulus, CoreLoad& load) {
  againstSolid(core, kInfinity, modulus,
               [&](const Vector3r& x, Vector3r& pushed, Real& height) {
                 pushed = plane.normal;
                 height = plane.normal.dot(x + body.position - plane.point);
                 return true;
               },
               load);
}

void againstBox(const PlacedCore& core, const Box& box, const BodyState& body, const BodyState& boxState, Real modulus,
                CoreLoad& load) {
  const Matrix3r R = boxState.orientation.toRotationMatrix();
  const Vector3r centre = boxState.position - body.position;
  const Vector3r& h = box.halfExtents;
  againstSolid(core, kInfinity, modulus,
               [&](const Vector3r& x, Vector3r& pushed, Real& height) {
                 const Vector3r local = R.transpose() * (x - centre);
                 const Vector3r clamped = local.cwiseMax(-h).cwiseMin(h);
                 if (clamped != local) {  // outside: away from the nearest point of the box
                   height = (local - clamped).norm();
                   pushed = R * (local - clamped) / height;
                   return true;
                 }
                 int axis = 0;  // inside: out through the nearest face
                 const Vector3r depth = h - local.cwiseAbs();
                 depth.minCoeff(&axis);
                 height = -depth[axis];
                 pushed = R * Vector3r::Unit(axis) * (local[axis] >= 0 ? 1 : -1);
                 return true;
               },
               load);
}

}  // namespace

CoreLoad corePair(const ContactModel& model, const ContactData& data, const BodyPair& pair, const PairSummary& contacts) {
  CoreLoad load;
  const Real inset = model.options.coreInset;
  if (!(inset < 1)) return load;
  const int bodyCount = static_cast<int>(model.bodies.size());
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const bool otherIsBody = pair.other < bodyCount;
  const HertzMaterial& otherMaterial =
      otherIsBody ? model.bodies[pair.other].material : model.partners[pair.other - bodyCount].material;
  const Real modulus = Ip2_HertzMaterial_HertzMaterial_HertzPhys(body.material, otherMaterial).effectiveModulus;
  const InscribedSpheres& spheres = body.mesh->inscribedSpheres();
  if (otherIsBody) {
    const RoundedMesh& mesh2 = *model.bodies[pair.other].mesh;
    const InscribedSpheres& other = mesh2.inscribedSpheres();
    const BodyState& s2 = data.bodyStates[pair.other];
    // A body thinner than the core's grid resolves (a 1 mm plate 50 mm long) has no core.
    if (spheres.radii.empty() || other.radii.empty()) return load;
    // Two core spheres touch only where the bodies' solids overlap by inset (r_i + r_j) or more: a pair whose triangle
    // contacts are all shallower than half the least of that, or which has none and neither centre inside the other
    // body, is skipped (most pairs of a packing, at the cost of a comparison).
    const Real onset = inset * (spheres.radii.back() + other.radii.back());
    const bool deep = contacts.triangleContacts > 0
                          ? contacts.deepestOverlap >= 0.5 * onset
                          : body.mesh->solidDistance().at(s1.orientation.conjugate() * (s2.position - s1.position)) == 0 ||
                                mesh2.solidDistance().at(s2.orientation.conjugate() * (s1.position - s2.position)) == 0;
    if (deep) againstCore(spheres, s1, other, s2, inset, modulus, load);
    return load;
  }
  // A partner farther from the body's centre than its core reaches touches no core sphere.
  const BodyState& s2 = data.partnerStates[pair.other - bodyCount];
  const Vector3r centre = s1.position;
  const Real reach = spheres.reach;
  const bool beyond = std::visit(
      Overloaded{[&](const Facet& facet) {
                   const std::array<Vector3r, 3> c = facetCorners(facet, s2.position, s2.orientation);
                   return (centre - closestOnTriangle(centre, c[0], c[1], c[2])).norm() >= reach;
                 },
                 [&](const Box& box) {
                   const Vector3r local = s2.orientation.conjugate() * (centre - s2.position);
                   return (local - local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents)).norm() >= reach;
                 },
                 [&](const Sphere& sphere) { return (centre - s2.position).norm() - sphere.radius >= reach; },
                 [&](const Plane& plane) { return plane.normal.dot(centre - plane.point) >= reach; },
                 [&](const Wall& wall) {
                   const Plane plane = wallPlane(wall, s2.position, centre);
                   return plane.normal.dot(centre - plane.point) >= reach;
                 }},
      model.partners[pair.other - bodyCount].shape);
  if (beyond) return load;
  const PlacedCore core = placedCore(spheres, s1.orientation, inset);
  std::visit(Overloaded{[&](const Facet& facet) { againstFacet(core, facet, s1, s2, modulus, load); },
                        [&](const Box& box) { againstBox(core, box, s1, s2, modulus, load); },
                        [&](const Sphere& sphere) {
                          againstSolid(core, sphere.radius, modulus,
                                       [&](const Vector3r& x, Vector3r& pushed, Real& height) {
                                         const Vector3r away = x - (s2.position - s1.position);
                                         const Real distance = away.norm();
                                         if (distance == 0) return false;
                                         pushed = away / distance;
                                         height = distance - sphere.radius;
                                         return true;
                                       },
                                       load);
                        },
                        [&](const Plane& plane) { againstPlane(core, plane, s1, modulus, load); },
                        [&](const Wall& wall) {
                          againstPlane(core, wallPlane(wall, s2.position, s1.position), s1, modulus, load);
                        }},
             model.partners[pair.other - bodyCount].shape);
  return load;
}

}  // namespace roundedmesh
