// Random rounded-triangle pairs and rounded-body pairs, and the checks every one of them must pass: finite
// forces, forces that change smoothly with a small move, and a bounded jump where a move switches the regime
// (Eq. 14), the sliding state (Eq. 21) or the contact itself. Shared by the GoogleTest suite (10,000 pairs,
// ContactRobustnessTest.cpp), the stress program (10^6 pairs, bench/stress_pairs.cpp) and the triangle-pair
// fuzzer (fuzz/triangle_pair_fuzzer.cpp), which draw from different sources: a Mersenne twister or the
// fuzzer's bytes. A Source has `Real uniform(Real a, Real b)` and `Vector3r direction()` (a unit vector).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/law/CoulombFriction.hpp"
#include "pkg/law/HertzPressure.hpp"
#include "pkg/law/NodeForces.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh::test {

// Jump allowed where a move switches the regime, relative to the whole-circle force: the direct regime
// spreads the force over S n Omega by area, the quadrature by pressure; the two fractions of a region of the
// circle differ by at most the integral of (1.5 sqrt(1 - r^2) - 1)+ over the unit disc / pi = 1 - (4/9)^1.5 - 5/9
// = 0.148 (the region r < sqrt(5/9)), plus the quadrature's own error; Eq. 21's switch jumps by mu times that.
// Where the contact ends, the force tends to zero with the overlap of circle and S.
constexpr Real kSwitchJump = 0.16;
// Change allowed for a step without a switch, relative to the whole-circle force and to step / delta_s: the
// delta^1.5 law alone moves by 1.5 step / delta_s and the damping term by 0.5 step / delta_s; the approach rate
// itself changes as n12 and c move with the step, which the random spins (up to 10 rad/s) make comparable.
// Measured worst 6.8 over 10^6 pairs (doc/reliability.md); 10 leaves a margin while still catching any jump
// (a jump is ~ delta_s / step = 1e5 times larger on this scale).
constexpr Real kSmoothSlope = 10.0;

class RandomSource {
 public:
  explicit RandomSource(unsigned seed) : rng_(seed) {}
  Real uniform(Real a, Real b) { return std::uniform_real_distribution<Real>(a, b)(rng_); }
  Vector3r direction() {
    std::normal_distribution<Real> n;
    return Vector3r(n(rng_), n(rng_), n(rng_)).normalized();
  }

 private:
  std::mt19937 rng_;
};

// A triangle of size ~s about x, in the plane normal to `normal`, counter-clockwise about it; a sliver (one
// corner within 1e-5 s of the opposite edge) one time in five.
template <class Source>
std::array<Vector3r, 3> randomTriangle(Source& random, const Vector3r& x, const Vector3r& normal, Real s) {
  const Vector3r u = normal.unitOrthogonal(), v = normal.cross(u);
  std::array<Vector3r, 3> t;
  for (Vector3r& c : t) c = x + s * (random.uniform(-1, 1) * u + random.uniform(-1, 1) * v);
  if (random.uniform(0, 1) < 0.2) t[2] = 0.5 * (t[0] + t[1]) + 1e-5 * s * (normal.cross(t[1] - t[0]));
  if ((t[1] - t[0]).cross(t[2] - t[0]).dot(normal) < 0) std::swap(t[1], t[2]);
  return t;
}

// A radius from the circumradius up to 1e4 times it (log-uniform above it).
template <class Source>
Real randomRadius(Source& random, const std::array<Vector3r, 3>& t) {
  const Vector3r ab = t[1] - t[0], ac = t[2] - t[0];
  const Real rho = ab.norm() * ac.norm() * (t[2] - t[1]).norm() / (2 * ab.cross(ac).norm());
  return rho * (1 + std::exp(random.uniform(-12, std::log(1e4))));
}

inline RoundedMesh singleTriangle(const std::array<Vector3r, 3>& t, Real radius) {
  return RoundedMesh({t[0], t[1], t[2]}, {Triangle{0, 1, 2}}, {radius});
}

enum class PairKind { General, Coplanar, EdgeOnEdge };

struct TrianglePair {
  RoundedMesh p, q;
  RelativeMotion motion;  // of q relative to p: up to 2 m/s and 10 rad/s
  Real size;              // of the triangles, 1e-3 to 1 [m]
};

// Two triangles facing each other: in general position (tilted up to 0.8 rad-ish, shifted up to half the size
// and 5 % of it along the normal), exactly coplanar and opposite, or sharing an edge line (reversed) with the
// third corner across it, in the first's plane or tilted out of it.
template <class Source>
TrianglePair randomTrianglePair(Source& random, PairKind kind) {
  const Real size = std::exp(random.uniform(std::log(1e-3), 0));
  const Vector3r n = random.direction();
  const std::array<Vector3r, 3> a = randomTriangle(random, Vector3r::Zero(), n, size);
  std::array<Vector3r, 3> b;
  if (kind == PairKind::Coplanar) {
    b = randomTriangle(random, Vector3r::Zero(), -n, size);
  } else if (kind == PairKind::EdgeOnEdge) {
    const Vector3r across = n.cross(a[1] - a[0]).normalized();
    b = {a[1], a[0], Vector3r(0.5 * (a[0] + a[1]) - size * random.uniform(0.1, 1) * across +
                              size * random.uniform(-0.3, 0.3) * n)};
    if ((b[1] - b[0]).cross(b[2] - b[0]).dot(n) > 0) std::swap(b[0], b[1]);
  } else {
    const Vector3r tilt = (-n + random.uniform(0, 0.8) * random.direction()).normalized();
    b = randomTriangle(random,
                       size * (random.uniform(-0.5, 0.5) * random.direction() + random.uniform(-0.05, 0.05) * n),
                       tilt, size);
  }
  const Real radiusA = randomRadius(random, a), radiusB = randomRadius(random, b);
  RelativeMotion motion;
  motion.linear = random.uniform(0, 2) * random.direction();
  motion.angular = random.uniform(0, 10) * random.direction();
  return {singleTriangle(a, radiusA), singleTriangle(b, radiusB), motion, size};
}

// The kinds in the proportions of the suite: general half the time, coplanar and edge on edge a quarter each.
inline PairKind pairKind(long trial) {
  switch (trial % 4) {
    case 2: return PairKind::Coplanar;
    case 3: return PairKind::EdgeOnEdge;
    default: return PairKind::General;
  }
}

// One triangle contact evaluated as the engine does: Ig2, Law2, node forces, friction.
struct Outcome {
  bool contact = false;
  bool finite = true;                  // every force, moment, node force and c_eff, delta_eff finite
  Real normal = 0;                     // Fn [N]
  Vector3r tangential = Vector3r::Zero();
  Real scale = 0;                      // whole-circle force of Eq. 7 for delta_s, R*: elastic + |damping| [N]
  Real sphereOverlap = 0;              // delta_s [m]
  Regime regime = Regime::Quadrature;
  bool sliding = false;
};

inline Outcome evaluateTriangleContact(const PressureGeom& geom, const HertzPhys& phys) {
  Outcome out;
  const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, PressureOptions());
  const std::array<Real, 3> nodes = nodeForces(geom.nodes, load);
  const std::array<Real, 3> partnerNodes = nodeForces(geom.partnerNodes, load);
  const TangentialLoad t = coulombFriction(geom, load, phys);
  out.finite = std::isfinite(load.force) && load.moment.allFinite() && t.force.allFinite() &&
               std::isfinite(geom.effectiveOverlap) && geom.effectivePoint.allFinite();
  for (int i = 0; i < 3; ++i) out.finite = out.finite && std::isfinite(nodes[i]) && std::isfinite(partnerNodes[i]);
  out.contact = true;
  out.normal = load.force;
  out.tangential = t.force;
  // Each term of Eq. 7 on its own: while separating, the damping term can all but cancel the elastic one, and
  // their small difference is no measure of how much either changes.
  HertzPhys elastic = phys;
  elastic.damping = 0;
  out.scale = hertzPressure(geom, elastic).totalForce() * (1 + phys.damping * std::abs(geom.overlapRate) / geom.sphereOverlap);
  out.sphereOverlap = geom.sphereOverlap;
  out.regime = load.regime;
  out.sliding = t.sliding;
  return out;
}

// q moved by `shift` against p.
inline Outcome evaluatePair(const RoundedMesh& p, const RoundedMesh& q, const Vector3r& shift,
                            const RelativeMotion& motion, const HertzPhys& phys) {
  PressureGeom geom;
  if (!triangleSphereGeom(p, 0, contactSphere(q, 0, Matrix3r::Identity(), shift), motion, geom)) return {};
  return evaluateTriangleContact(geom, phys);
}

inline bool sameState(const Outcome& a, const Outcome& b) {
  return a.contact == b.contact && a.regime == b.regime && a.sliding == b.sliding;
}

inline Real forceChange(const Outcome& a, const Outcome& b) {
  return std::max(std::abs(a.normal - b.normal), (a.tangential - b.tangential).norm());
}

// What the checks of one pair found. slope < 0: not measured (no contact, or a switch within the step).
struct PairCheck {
  bool contact = false;
  bool finite = true;
  Real slope = -1;  // force change over a tiny step, per whole-circle force and step / delta_s
  Real jump = 0;    // worst force change across a switch, per whole-circle force
  int switches = 0;
};

// Scans a move of q along `direction` over 0.2 of the size in 20 steps; where the outcome's regime, sliding
// state or contact changes between two samples, bisects to a width of 1e-10 of the size and records the
// worst jump across (relative to the larger whole-circle force). Non-finite outcomes clear check.finite.
inline void scanSwitches(const TrianglePair& pair, const Vector3r& direction, const HertzPhys& phys, PairCheck& check) {
  auto at = [&](Real s) {
    const Outcome o = evaluatePair(pair.p, pair.q, s * pair.size * direction, pair.motion, phys);
    check.finite = check.finite && o.finite;
    return o;
  };
  Real scanScale = 0;
  Outcome previous = at(0);
  for (int k = 0; k <= 20; ++k) scanScale = std::max(scanScale, at(0.01 * k).scale);
  for (int k = 1; k <= 20; ++k) {
    Real lo = 0.01 * (k - 1), hi = 0.01 * k;
    const Outcome next = at(hi);
    if (!sameState(previous, next)) {
      Outcome a = previous, b = next;
      while (hi - lo > 1e-10) {
        const Real mid = 0.5 * (lo + hi);
        const Outcome m = at(mid);
        if (sameState(a, m)) lo = mid, a = m; else hi = mid, b = m;
      }
      ++check.switches;
      // Where the contact ends, the damped force (Eq. 7: A ddelta/dt sqrt(delta)) falls to zero like a square
      // root: compare with the force the contact has along the scan, not with its own vanishing scale.
      const Real scale = a.contact && b.contact ? std::max(a.scale, b.scale) : scanScale;
      if (scale > 0) check.jump = std::max(check.jump, forceChange(a, b) / scale);
    }
    previous = next;
  }
}

// The checks of one triangle pair: finite forces; where there is a contact, the change over a step of 1e-9 of
// the size in a random direction (the slope, when the step switches nothing), and the switches along a scan
// in another random direction.
template <class Source>
PairCheck checkTrianglePair(const TrianglePair& pair, const HertzPhys& phys, Source& random) {
  PairCheck check;
  const Outcome here = evaluatePair(pair.p, pair.q, Vector3r::Zero(), pair.motion, phys);
  check.finite = here.finite;
  if (!here.contact || !(here.scale > 0)) return check;
  check.contact = true;
  const Real step = 1e-9 * pair.size;
  const Outcome moved = evaluatePair(pair.p, pair.q, step * random.direction(), pair.motion, phys);
  check.finite = check.finite && moved.finite;
  if (sameState(moved, here)) check.slope = forceChange(moved, here) / here.scale / (step / here.sphereOverlap);
  scanSwitches(pair, random.direction(), phys, check);
  return check;
}

// --- Body pairs --------------------------------------------------------------------------------------------

// The bodies of the body pairs, about 1 in size (radius or semi-axes), as the engine holds them: icospheres of
// 162 and 642 nodes (exact curvature), a distorted icosphere (D = 0.5, curvature from the mesh: uneven radii,
// some flat) and a spheroid of aspect 2 (about 500 nodes, curvature from the mesh).
// The bodies of the random body pairs: an icosphere of 162 and one of 642 nodes (exact curvature), a distorted
// icosphere (D = 0.5) and a spheroid of aspect 2 (curvature from the mesh), each of unit size, scaled by one of
// kScales sizes log-spaced from 1e-3 to 1 (half a decade apart). A scaled mesh is made on first use and shared by
// every pair that draws it, as a scene shares one mesh among its bodies: a mesh builds its distance field
// (SolidDistance.hpp) once, which a new mesh per pair would build every time (0.1 to 0.5 s each).
class BodyLibrary {
 public:
  static constexpr int kScales = 7;

  explicit BodyLibrary(const HertzMaterial& material) {
    unit_.push_back(roundedBody(0, BodyMesh(icosphere(1, 2)), material));
    unit_.push_back(roundedBody(0, BodyMesh(icosphere(1, 3)), material));
    unit_.push_back(roundedBody(0, BodyMesh(distortedIcosphereSurface(1, 3, 0.5, 5), std::nullopt), material));
    unit_.push_back(roundedBody(0, BodyMesh(spheroidSurface(1, 0.5, 500), std::nullopt), material));
    scaled_.resize(unit_.size() * kScales);
  }

  int kinds() const { return static_cast<int>(unit_.size()); }
  static Real scale(int level) { return std::pow(10.0, -3.0 + 3.0 * level / (kScales - 1)); }

  // Body `kind` scaled by scale(level), every length and radius included.
  RoundedBody body(int kind, int level) {
    RoundedBody body = unit_[kind];
    std::shared_ptr<const RoundedMesh>& mesh = scaled_[kind * kScales + level];
    if (!mesh) mesh = std::make_shared<const RoundedMesh>(scaledMesh(*body.mesh, scale(level)));
    body.mesh = mesh;
    body.equivalentRadius *= scale(level);
    return body;
  }

 private:
  static RoundedMesh scaledMesh(const RoundedMesh& mesh, Real scale) {
    std::vector<Vector3r> vertices = mesh.vertices();
    for (Vector3r& v : vertices) v *= scale;
    std::vector<Real> radii = mesh.radii();
    for (Real& r : radii) r *= scale;
    return RoundedMesh(std::move(vertices), mesh.triangles(), radii);
  }

  std::vector<RoundedBody> unit_;
  std::vector<std::shared_ptr<const RoundedMesh>> scaled_;
};

struct BodyPairCase {
  ContactModel model;
  ContactData data;
};

// Two bodies of the library at one of its sizes, in random orientations, body 2 along a random direction from
// body 1 at the distance where their vertex hulls touch, less an overlap log-uniform from 1e-7 (grazing) to
// kDeepestOverlap (deep) of the size; each moving at up to 1 m/s and 10 rad/s.
template <class Source>
BodyPairCase randomBodyPair(Source& random, BodyLibrary& library) {
  auto draw = [&](int count) { return std::min(count - 1, static_cast<int>(random.uniform(0, count))); };
  const int level = draw(BodyLibrary::kScales);
  const Real scale = BodyLibrary::scale(level);
  BodyPairCase c;
  for (int b = 0; b < 2; ++b) {
    RoundedBody body = library.body(draw(library.kinds()), level);
    body.id = b;
    c.model.bodies.push_back(body);
  }
  c.data.resize(c.model);
  const Vector3r d = random.direction();
  BodyState& s1 = c.data.bodyStates[0];
  BodyState& s2 = c.data.bodyStates[1];
  for (BodyState* s : {&s1, &s2}) {
    s->orientation = Quaternionr(Eigen::AngleAxis<Real>(random.uniform(0, 2 * M_PI), random.direction()));
    s->velocity = random.uniform(0, 1) * random.direction();
    s->angularVelocity = random.uniform(0, 10) * random.direction();
  }
  auto reach = [](const RoundedMesh& mesh, const Quaternionr& q, const Vector3r& along) {
    Real extent = -INFINITY;
    for (const Vector3r& v : mesh.vertices()) extent = std::max(extent, (q * v).dot(along));
    return extent;
  };
  const Real overlap = scale * std::exp(random.uniform(std::log(1e-7), std::log(kDeepestOverlap)));
  s2.position = (reach(*c.model.bodies[0].mesh, s1.orientation, d) + reach(*c.model.bodies[1].mesh, s2.orientation, -d) -
                 overlap) * d;
  return c;
}

struct BodyPairCheck {
  int contacts = 0;
  bool finite = true;   // wrenches and every triangle contact
  Real worstSlope = 0;  // over the triangle contacts kept through a tiny step, as for a triangle pair
  Real worstJump = 0;   // over the switches found along a longer move, each bisected
  int switches = 0;
};

// The pair through resolvePair at its pose, then with body 2 moved by `step` and by `scan` (fractions of the
// smaller equivalent radius) in two random directions. Each triangle contact found at the pose and after the
// step, in the same state, gives a slope as a triangle pair does. Each found at the pose and after the longer
// move in another state (regime or sliding) is bisected along the move, to 1e-10 of the radius, and gives a
// jump; a contact that ends somewhere within the move is left to the triangle pairs' scans.
template <class Source>
BodyPairCheck checkBodyPair(BodyPairCase& c, Source& random, Real step = 1e-7, Real scan = 1e-4) {
  BodyPairCheck check;
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(c.model.bodies[0].material, c.model.bodies[1].material);
  const Real radius = std::min(c.model.bodies[0].equivalentRadius, c.model.bodies[1].equivalentRadius);
  const Vector3r origin = c.data.bodyStates[1].position;
  std::vector<PressureGeom> scratch;
  std::vector<TriangleContact> contacts;
  auto at = [&](const Vector3r& shift) {
    c.data.bodyStates[1].position = origin + shift;
    contacts.clear();
    const PairResult r = resolvePair(c.model, c.data, {0, 1}, scratch, &contacts);
    check.finite = check.finite && r.onBody.force.allFinite() && r.onBody.torque.allFinite() &&
                   r.onOther.force.allFinite() && r.onOther.torque.allFinite();
    std::map<std::array<int, 2>, Outcome> outcomes;
    for (const TriangleContact& t : contacts) {
      const Outcome o = evaluateTriangleContact(t.geom, phys);
      check.finite = check.finite && o.finite;
      outcomes[{t.geom.triangle, t.geom.partnerTriangle}] = o;
    }
    return outcomes;
  };
  const auto here = at(Vector3r::Zero());
  check.contacts = int(here.size());
  const Vector3r small = step * radius * random.direction(), large = scan * radius * random.direction();
  const auto stepped = at(small);
  for (const auto& [key, a] : here) {
    const auto found = stepped.find(key);
    if (found != stepped.end() && a.scale > 0 && sameState(a, found->second))
      check.worstSlope = std::max(check.worstSlope,
                                  forceChange(a, found->second) / a.scale / (small.norm() / a.sphereOverlap));
  }
  const auto moved = at(large);
  for (const auto& [key, first] : here) {
    const auto found = moved.find(key);
    if (found == moved.end() || sameState(first, found->second)) continue;
    Real lo = 0, hi = 1;
    Outcome a = first, b = found->second;
    bool kept = true;
    while (kept && (hi - lo) * scan > 1e-10) {
      const Real mid = 0.5 * (lo + hi);
      const auto outcomes = at(mid * large);
      const auto m = outcomes.find(key);
      kept = m != outcomes.end();
      if (!kept) break;
      if (sameState(a, m->second)) lo = mid, a = m->second; else hi = mid, b = m->second;
    }
    if (!kept) continue;
    ++check.switches;
    check.worstJump = std::max(check.worstJump, forceChange(a, b) / std::max(a.scale, b.scale));
  }
  c.data.bodyStates[1].position = origin;
  return check;
}

}  // namespace roundedmesh::test
