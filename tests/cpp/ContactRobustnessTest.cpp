// 10,000 random pairs of rounded triangles, sizes from slivers up, radii from the circumradius to 1e4 times
// it, in general position, exactly coplanar and edge on edge: the whole triangle contact (Ig2, Law2, node
// forces, friction) gives finite forces, and moving one triangle by a tiny step changes them by little.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/law/CoulombFriction.hpp"
#include "pkg/law/HertzPressure.hpp"
#include "pkg/law/NodeForces.hpp"

namespace roundedmesh {
namespace {

struct Outcome {
  bool contact = false;
  Real normal = 0;                     // Fn [N]
  Vector3r tangential = Vector3r::Zero();
  Real scale = 0;                      // whole-circle damped Hertz force of Eq. 7 for delta_s, R* [N]
  Regime regime = Regime::Quadrature;
  bool sliding = false;
};

Outcome evaluate(const RoundedMesh& p, const RoundedMesh& q, const Vector3r& shift, const RelativeMotion& motion,
                 const HertzPhys& phys) {
  Outcome out;
  PressureGeom geom;
  if (!triangleSphereGeom(p, 0, contactSphere(q, 0, Matrix3r::Identity(), shift), motion, geom)) return out;
  const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, PressureOptions());
  const std::array<Real, 3> nodes = nodeForces(geom.nodes, load);
  const std::array<Real, 3> partnerNodes = nodeForces(geom.partnerNodes, load);
  const TangentialLoad t = coulombFriction(geom, load, phys);
  EXPECT_TRUE(std::isfinite(load.force) && load.moment.allFinite() && t.force.allFinite());
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(nodes[i]) && std::isfinite(partnerNodes[i]));
  EXPECT_TRUE(std::isfinite(geom.effectiveOverlap) && geom.effectivePoint.allFinite());
  out.contact = true;
  out.normal = load.force;
  out.tangential = t.force;
  out.scale = hertzPressure(geom, phys).totalForce();
  out.regime = load.regime;
  out.sliding = t.sliding;
  return out;
}

class RandomPairs {
 public:
  explicit RandomPairs(unsigned seed) : rng_(seed) {}
  Real uniform(Real a, Real b) { return std::uniform_real_distribution<Real>(a, b)(rng_); }
  Vector3r direction() {
    std::normal_distribution<Real> n;
    return Vector3r(n(rng_), n(rng_), n(rng_)).normalized();
  }
  // A triangle of size ~s about x, in the plane normal to `normal`, counter-clockwise about it; a sliver (one
  // corner within 1e-5 s of the opposite edge) one time in five.
  std::array<Vector3r, 3> triangle(const Vector3r& x, const Vector3r& normal, Real s) {
    const Vector3r u = normal.unitOrthogonal(), v = normal.cross(u);
    std::array<Vector3r, 3> t;
    for (Vector3r& c : t) c = x + s * (uniform(-1, 1) * u + uniform(-1, 1) * v);
    if (uniform(0, 1) < 0.2) t[2] = 0.5 * (t[0] + t[1]) + 1e-5 * s * (normal.cross(t[1] - t[0]));
    if ((t[1] - t[0]).cross(t[2] - t[0]).dot(normal) < 0) std::swap(t[1], t[2]);
    return t;
  }
  // A radius from the circumradius up to 1e4 times it (log-uniform above it).
  Real radius(const std::array<Vector3r, 3>& t) {
    const Vector3r ab = t[1] - t[0], ac = t[2] - t[0];
    const Real rho = ab.norm() * ac.norm() * (t[2] - t[1]).norm() / (2 * ab.cross(ac).norm());
    return rho * (1 + std::exp(uniform(-12, std::log(1e4))));
  }

 private:
  std::mt19937 rng_;
};

RoundedMesh single(const std::array<Vector3r, 3>& t, Real radius) {
  return RoundedMesh({t[0], t[1], t[2]}, {Triangle{0, 1, 2}}, {radius});
}

// Jump allowed where a move switches the regime, relative to the whole-circle force: the direct regime
// spreads the force over S n Omega by area, the quadrature by pressure; the two fractions of a region of the
// circle differ by at most the integral of (1.5 sqrt(1 - r^2) - 1)+ over the unit disc / pi = 1 - (4/9)^1.5 - 5/9
// = 0.148 (the region r < sqrt(5/9)), plus the quadrature's own error; Eq. 21's switch jumps by mu times that.
// Where the contact ends, the force tends to zero with the overlap of circle and S.
constexpr Real kSwitchJump = 0.16;
// Change allowed for a step without a switch, relative to the whole-circle force and to step / delta_s: the
// delta^1.5 law alone moves by 1.5 step / delta_s and the damping term by 0.5 step / delta_s; the approach rate
// itself changes as n12 and c move with the step, which the random spins (up to 10 rad/s) make comparable.
// Measured worst 4.8; 10 leaves a margin while still catching any jump (a jump is ~ delta_s / step = 1e5
// times larger on this scale).
constexpr Real kSmoothSlope = 10.0;

// Scans a move of q along `direction` over 0.2 of the size in 20 steps; where the outcome's regime, sliding
// state or contact changes between two samples, bisects to a width of 1e-10 of the size and returns the worst
// jump across (relative to the larger whole-circle force). Between samples without a change, checks the slope.
Real worstSwitchJump(const RoundedMesh& p, const RoundedMesh& q, const Vector3r& direction, Real size,
                     const RelativeMotion& motion, const HertzPhys& phys, int& switches) {
  auto at = [&](Real s) { return evaluate(p, q, s * size * direction, motion, phys); };
  auto same = [](const Outcome& a, const Outcome& b) {
    return a.contact == b.contact && a.regime == b.regime && a.sliding == b.sliding;
  };
  Real worst = 0, scanScale = 0;
  Outcome previous = at(0);
  for (int k = 0; k <= 20; ++k) scanScale = std::max(scanScale, at(0.01 * k).scale);
  for (int k = 1; k <= 20; ++k) {
    Real lo = 0.01 * (k - 1), hi = 0.01 * k;
    const Outcome next = at(hi);
    if (!same(previous, next)) {
      Outcome a = previous, b = next;
      while ((hi - lo) * size > 1e-10 * size) {
        const Real mid = 0.5 * (lo + hi);
        const Outcome m = at(mid);
        if (same(a, m)) lo = mid, a = m; else hi = mid, b = m;
      }
      ++switches;
      // Where the contact ends, the damped force (Eq. 7: A ddelta/dt sqrt(delta)) falls to zero like a square
      // root: compare with the force the contact has along the scan, not with its own vanishing scale.
      const Real scale = a.contact && b.contact ? std::max(a.scale, b.scale) : scanScale;
      if (scale > 0)
        worst = std::max(worst, std::max(std::abs(a.normal - b.normal), (a.tangential - b.tangential).norm()) / scale);
    }
    previous = next;
  }
  return worst;
}

TEST(ContactRobustness, RandomTrianglePairsGiveFiniteContinuousForces) {
  RandomPairs random(11);
  const HertzPhys phys{2e6, 1e-3, 0.5, 3.0};
  int contacts = 0, switches = 0;
  Real worstSmooth = 0, worstSwitch = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const int kind = trial % 4;  // 0, 1: general; 2: exactly coplanar; 3: edge on edge
    const Real size = std::exp(random.uniform(std::log(1e-3), 0));
    const Vector3r n = random.direction();
    const std::array<Vector3r, 3> a = random.triangle(Vector3r::Zero(), n, size);
    std::array<Vector3r, 3> b;
    if (kind == 2) {
      b = random.triangle(Vector3r::Zero(), -n, size);
    } else if (kind == 3) {
      // Shares a's first edge line (reversed) with its third corner on the far side of that edge, in a's plane
      // or tilted out of it.
      const Vector3r across = n.cross(a[1] - a[0]).normalized();
      b = {a[1], a[0], Vector3r(0.5 * (a[0] + a[1]) - size * random.uniform(0.1, 1) * across +
                                size * random.uniform(-0.3, 0.3) * n)};
      if ((b[1] - b[0]).cross(b[2] - b[0]).dot(n) > 0) std::swap(b[0], b[1]);
    } else {
      const Vector3r tilt = (-n + random.uniform(0, 0.8) * random.direction()).normalized();
      b = random.triangle(size * (random.uniform(-0.5, 0.5) * random.direction() + random.uniform(-0.05, 0.05) * n),
                          tilt, size);
    }
    const RoundedMesh p = single(a, random.radius(a)), q = single(b, random.radius(b));
    RelativeMotion motion;
    motion.linear = random.uniform(0, 2) * random.direction();
    motion.angular = random.uniform(0, 10) * random.direction();
    const Outcome here = evaluate(p, q, Vector3r::Zero(), motion, phys);
    if (!here.contact || !(here.scale > 0)) continue;
    ++contacts;
    const Real step = 1e-9 * size;
    const Outcome moved = evaluate(p, q, step * random.direction(), motion, phys);
    if (moved.contact && moved.regime == here.regime && moved.sliding == here.sliding) {
      PressureGeom geom;
      triangleSphereGeom(p, 0, contactSphere(q, 0, Matrix3r::Identity(), Vector3r::Zero()), motion, geom);
      const Real change = std::max(std::abs(moved.normal - here.normal), (moved.tangential - here.tangential).norm()) /
                          here.scale / (step / geom.sphereOverlap);
      worstSmooth = std::max(worstSmooth, change);
      EXPECT_LE(change, kSmoothSlope) << "trial " << trial;
    }
    const Real jump = worstSwitchJump(p, q, random.direction(), size, motion, phys, switches);
    worstSwitch = std::max(worstSwitch, jump);
    EXPECT_LE(jump, kSwitchJump) << "trial " << trial;
  }
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(switches, 500);
  std::cout << contacts << " contacts, " << switches << " switches; worst slope " << worstSmooth
            << " (step / delta_s), worst jump at a switch " << worstSwitch << " (of the whole-circle Hertz force)\n";
}

}  // namespace
}  // namespace roundedmesh
