#include "pkg/engine/CorePair.hpp"

#include "pkg/common/Overloaded.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"  // facetOwns
#include "pkg/math/Segment.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

// A body's core in the frame centred on its position with the global axes: centres [m], radii [m], and the radius of
// the ball about the position that holds them all.
struct PlacedCore {
  std::vector<Vector3r> centres;
  std::vector<Real> radii;
  Real reach = 0;
};

PlacedCore placedCore(const RoundedMesh& mesh, const Quaternionr& orientation, Real inset) {
  const InscribedSpheres& spheres = mesh.inscribedSpheres();
  PlacedCore core;
  const Matrix3r rotation = orientation.toRotationMatrix();
  for (size_t i = 0; i < spheres.centres.size(); ++i) {
    core.centres.push_back(rotation * spheres.centres[i]);
    core.radii.push_back((1 - inset) * spheres.radii[i]);
    core.reach = std::max(core.reach, spheres.centres[i].norm() + core.radii.back());
  }
  return core;
}

void againstCore(const PlacedCore& core, const PlacedCore& other, const Vector3r& offset, Real modulus, CoreLoad& load) {
  for (size_t i = 0; i < core.centres.size(); ++i) {
    if ((core.centres[i] - offset).norm() >= core.radii[i] + other.reach) continue;
    for (size_t j = 0; j < other.centres.size(); ++j) {
      const Vector3r apart = core.centres[i] - (offset + other.centres[j]);
      const Real distance = apart.norm();
      const Real delta = core.radii[i] + other.radii[j] - distance;
      if (delta <= 0 || distance == 0) continue;
      load.add(core.centres[i], apart / distance, delta, core.radii[i] * other.radii[j] / (core.radii[i] + other.radii[j]),
               modulus);
    }
  }
}

// The core against a partner's solid: nearest(x, normal, height) gives, for a core centre x, the unit normal along
// which the partner pushes it and the centre's height over the partner's surface (negative inside), or false where
// this partner does not push it. partnerRadius: a Sphere's radius, infinite for a flat surface (R = rho).
template <class Nearest>
void againstSolid(const PlacedCore& core, Real partnerRadius, Real modulus, const Nearest& nearest, CoreLoad& load) {
  for (size_t i = 0; i < core.centres.size(); ++i) {
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
  const Vector3r t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);  // (t1, t2, normal) right-handed
  auto inPlane = [&](const Vector3r& x) { return Vector2r((x - corners[0]).dot(t1), (x - corners[0]).dot(t2)); };
  std::vector<Vector2r> outline;
  if (placed.weld) {
    for (const Vector3r& x : placed.outline) outline.push_back(inPlane(x));  // counter-clockwise about the normal
  } else {
    for (const Vector3r& x : corners) outline.push_back(inPlane(x));
    if (cross2(outline[1] - outline[0], outline[2] - outline[0]) < 0) std::swap(outline[1], outline[2]);
  }
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
                 const Vector2r q = nearestOnOutline(outline, inPlane(x));
                 if (!owns(q)) return false;
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

CoreLoad corePair(const ContactModel& model, const ContactData& data, const BodyPair& pair) {
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
  const PlacedCore core = placedCore(*body.mesh, s1.orientation, inset);
  if (otherIsBody) {
    const BodyState& s2 = data.bodyStates[pair.other];
    const Vector3r offset = s2.position - s1.position;
    const PlacedCore other = placedCore(*model.bodies[pair.other].mesh, s2.orientation, inset);
    if (offset.norm() < core.reach + other.reach) againstCore(core, other, offset, modulus, load);
    return load;
  }
  const BodyState& s2 = data.partnerStates[pair.other - bodyCount];
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
