#include "pkg/engine/CriticalTimeStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <variant>

#include <Eigen/Eigenvalues>

#include "pkg/common/Overloaded.hpp"
#include "pkg/law/HertzPressure.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

// What the limit of a pair depends on, for one side: mass [kg] (0: does not move under forces), radius of
// the sphere standing for it [m] (infinite for a flat partner), its rotational compliance at the worst contact
// point [1/kg] (0: rotation left out), material.
struct Side {
  Real mass;
  Real radius;
  Real lever;        // [1/kg], any direction at any contact point
  Real normalLever;  // [1/kg], along the surface's normal there
  const HertzMaterial* material;

  // What a tangential force at a contact point moves (CriticalTimeStep.hpp).
  Real tangentialMass() const { return 1 / (1 / mass + lever); }
  // What a normal force at a contact point moves.
  Real normalMass() const { return 1 / (1 / mass + normalLever); }
};

// max over the mesh's vertices x of the largest eigenvalue of [x]^T I^-1 [x] ([x] the cross-product matrix, I the
// principal moments in the mesh's principal frame): the most a unit force at a contact point, in any direction,
// accelerates that point through the body's rotation [1/kg]. 0 if a moment is not positive.
Real meshLever(const RoundedMesh& mesh, const Vector3r& inertia) {
  if (!(inertia.minCoeff() > 0)) return 0;
  const Vector3r inverse = inertia.cwiseInverse();
  Real lever = 0;
  for (const Vector3r& x : mesh.vertices()) {
    Matrix3r cross;
    cross << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    const Matrix3r m = cross.transpose() * inverse.asDiagonal() * cross;
    Eigen::SelfAdjointEigenSolver<Matrix3r> eigen;
    eigen.computeDirect(m, Eigen::EigenvaluesOnly);
    lever = std::max(lever, eigen.eigenvalues().maxCoeff());
  }
  return lever;
}

Real reduced(Real a, Real b) { return b > 0 ? a * b / (a + b) : a; }

// Infinite for two rigid sides, which have no Hertz contact (the scene refuses them), and for two sides that
// do not move under forces.
StabilityLimit pairLimit(Side a, Side b, FrictionLaw law, Real impactSpeed) {
  StabilityLimit limit;
  if (std::isinf(a.material->young) && std::isinf(b.material->young)) return limit;
  if (!(a.mass > 0)) std::swap(a, b);
  if (!(a.mass > 0)) return limit;
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(*a.material, *b.material);
  const Real radius = std::isinf(b.radius) ? a.radius : a.radius * b.radius / (a.radius + b.radius);
  const Real overlap = kDeepestOverlap * std::min(a.radius, b.radius);
  limit.timeStep = std::min(
      criticalTimeStep(reduced(a.normalMass(), b.mass > 0 ? b.normalMass() : 0), phys.effectiveModulus, radius,
                       phys.damping, overlap),
      impactTimeStep(reduced(a.mass, b.mass), phys.effectiveModulus, radius, overlap, impactSpeed));
  if (phys.friction > 0) {
    const Real normalStiffness = hertzStiffnessAt(phys, radius, overlap);
    const Real stiffness = law == FrictionLaw::Spring ? phys.stiffnessRatio * normalStiffness : 0;
    const Real mass = reduced(a.tangentialMass(), b.mass > 0 ? b.tangentialMass() : 0);
    const Real tangential = leapFrogLimit(mass, stiffness, phys.tangentialDamping);
    if (tangential < limit.timeStep) {
      limit.timeStep = tangential;
      limit.tangential = true;
    }
  }
  return limit;
}

Real partnerRadius(const PartnerShape& shape) {
  if (const Sphere* sphere = std::get_if<Sphere>(&shape)) return sphere->radius;
  return kInfinity;
}

// The farthest a partner's contact point can be from its position; 0 for a Wall or Plane (no finite lever).
Real partnerReach(const PartnerShape& shape) {
  return std::visit(Overloaded{[](const Sphere& s) { return s.radius; },
                               [](const Box& b) { return b.halfExtents.norm(); },
                               [](const Facet& f) {
                                 Real reach = 0;
                                 for (const Vector3r& x : f.vertices) reach = std::max(reach, x.norm());
                                 return reach;
                               },
                               [](const auto&) { return Real(0); }},
                    shape);
}

}  // namespace

Real normalLever(const RoundedMesh& mesh, const Vector3r& inertia) {
  if (!(inertia.minCoeff() > 0)) return 0;
  const Vector3r inverse = inertia.cwiseInverse();
  auto along = [&](const Vector3r& x, const Vector3r& u) { return x.cross(u).cwiseAbs2().dot(inverse); };
  Real lever = 0;
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const RoundedTriangle& cap = mesh.rounded(t);
    lever = std::max(lever, along(cap.sphereCentre + cap.radius * cap.normal, cap.normal));
    for (int corner : mesh.triangles()[t]) {
      const Vector3r& x = mesh.vertices()[corner];
      lever = std::max(lever, along(x, (x - cap.sphereCentre).normalized()));
    }
  }
  return lever;
}

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses, const std::vector<Vector3r>& bodyInertias,
                              const std::vector<Vector3r>& partnerInertias, Real impactSpeed) {
  StabilityLimit limit;
  const int bodyCount = static_cast<int>(model.bodies.size());
  // Every side as an engine index (bodies, then partners), and which ones move through the engine's contacts:
  // rounded bodies and sphere bodies.
  const int count = bodyCount + static_cast<int>(model.partners.size());
  std::vector<Real> levers(count, 0), normalLevers(count, 0);
  for (int b = 0; b < bodyCount && !bodyInertias.empty(); ++b) {
    // Bodies sharing a mesh and inertia (the usual case) share the sweep over its vertices.
    int same = 0;
    while (same < b && !(model.bodies[same].mesh == model.bodies[b].mesh && bodyInertias[same] == bodyInertias[b]))
      ++same;
    levers[b] = same < b ? levers[same] : meshLever(*model.bodies[b].mesh, bodyInertias[b]);
    normalLevers[b] = same < b ? normalLevers[same] : normalLever(*model.bodies[b].mesh, bodyInertias[b]);
  }
  for (int p = 0; p < count - bodyCount && !partnerInertias.empty(); ++p) {
    const PartnerShape& shape = model.partners[p].shape;
    const Real reach = partnerReach(shape), inertia = partnerInertias[p].minCoeff();
    levers[bodyCount + p] = inertia > 0 ? reach * reach / inertia : 0;
    // A sphere's normal passes through its centre; a Box's or Facet's is bounded by any direction's.
    normalLevers[bodyCount + p] = std::holds_alternative<Sphere>(shape) ? 0 : levers[bodyCount + p];
  }
  auto side = [&](int i) -> Side {
    if (i < bodyCount)
      return {bodyMasses[i], model.bodies[i].equivalentRadius, levers[i], normalLevers[i], &model.bodies[i].material};
    const Partner& partner = model.partners[i - bodyCount];
    return {partnerMasses[i - bodyCount], partnerRadius(partner.shape), levers[i], normalLevers[i], &partner.material};
  };
  auto isBody = [&](int i) { return i < bodyCount || model.partners[i - bodyCount].sphereBody; };
  auto sameMaterial = [](const HertzMaterial& a, const HertzMaterial& b) {
    return std::tie(a.young, a.poisson, a.damping, a.friction, a.tangentialDamping) ==
           std::tie(b.young, b.poisson, b.damping, b.friction, b.tangentialDamping);
  };
  // Bodies alike in mass, size, inertia and material have the same limit: each kind is checked once.
  std::vector<int> kinds;
  for (int b = 0; b < count; ++b) {
    if (!isBody(b)) continue;
    const Side s = side(b);
    const bool seen = std::any_of(kinds.begin(), kinds.end(), [&](int k) {
      const Side o = side(k);
      return (k < bodyCount) == (b < bodyCount) && o.mass == s.mass && o.radius == s.radius && o.lever == s.lever &&
             o.normalLever == s.normalLever && sameMaterial(*o.material, *s.material);
    });
    if (!seen) kinds.push_back(b);
  }
  auto consider = [&](StabilityLimit pair, int b, int other) {
    if (pair.timeStep < limit.timeStep) limit = {pair.timeStep, b, other, pair.tangential};
  };
  for (int b : kinds) {
    for (int k : kinds)
      if (k >= b) consider(pairLimit(side(b), side(k), model.options.friction, impactSpeed), b, k);
    // Partners other than bodies: a sphere body meets them all, a rounded body every partner.
    for (int p = bodyCount; p < count; ++p)
      if (b < bodyCount || !isBody(p)) consider(pairLimit(side(b), side(p), model.options.friction, impactSpeed), b, p);
  }
  return limit;
}

}  // namespace roundedmesh
