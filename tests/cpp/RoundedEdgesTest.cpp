// Rounded edges and corners of partners (TriangleEdgeGeom.hpp; doc/physics.md, "What each partner's surface is"): a
// ball pressed onto a Box's 90-degree edge, onto the 37-degree ridge of a drum's lifter made of Facets, and onto a
// Box's corner gets Hertz's force for a sphere on a cylinder (a sphere) of the rounding's radius, and a force that
// rises along every push; sliding over an edge, the force changes continuously.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/geom/EllipticalHertz.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;

const HertzMaterial kBall{1e6, 0.4, 2000, 0, 0};
const HertzMaterial kSteel{5e6, 0.4, 2000, 0, 0};
const Real kModulus = 1 / ((1 - 0.16) / 1e6 + (1 - 0.16) / 5e6);  // E*, Eq. 3
constexpr Real kR = 0.025;                                         // the ball's radius

const BodyMesh& ball() {
  static const BodyMesh mesh(icosphere(kR, 3));  // 642 nodes
  return mesh;
}

Real edgeRadius() { return kDeepestOverlap * equivalentRadius(ball().volume()); }

// Hertz's force for relative principal curvatures lambdaA <= lambdaB at approach delta (Johnson 1985, Section 4.2).
Real hertzForce(Real lambdaA, Real lambdaB, Real delta) {
  const HertzEllipse e = hertzEllipse(lambdaA, lambdaB, delta);
  return 2 * M_PI / 3 * e.a * e.b * e.peakPerModulus * kModulus;
}

// The force on the ball at `centre`, turned off every symmetry of the partners, along `direction`.
Real pushBack(const std::vector<Partner>& partners, const Vector3r& centre, const Vector3r& direction) {
  const BodyState state = at(centre, Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r(1, 2, 3).normalized())));
  std::vector<BodyState> states(partners.size(), at(Vector3r::Zero()));
  return surfaceContact(roundedBody(0, ball(), kBall), state, partners, states, EngineOptions()).onFirst.force.dot(direction);
}

// Pushes from the axis `axis` (through the origin of the arc of outward normals from `from` to `to`, along y) in 20
// directions spread over the arc, 10 degrees clear of its ends: the force rises over each push to 0.3 r_eq, and where
// Hertz's ellipse stays on the strip (its half-width b, as an angle b / rho, clear of the arc's ends) at 0.05 and 0.1
// rho deep, it is Hertz's for the ball on a cylinder of radius rho within 5 % (the icosphere's facets depart from the
// sphere by 0.06 mm, the depth of a cap: a few per cent of these overlaps).
void expectHertzOnTheEdge(const std::vector<Partner>& partners, const Vector3r& axis, Real from, Real to) {
  const Real rho = edgeRadius(), r_eq = equivalentRadius(ball().volume());
  int compared = 0;
  for (int k = 0; k < 20; ++k) {
    const Real clear = 10 * M_PI / 180, angle = from + clear + (to - from - 2 * clear) * k / 19;
    const Vector3r direction(std::sin(angle), 0, std::cos(angle));
    Real last = 0;
    for (int step = 1; step <= 30; ++step) {
      const Real delta = 0.3 * r_eq * step / 30;
      const Real force = pushBack(partners, axis + (rho + kR - delta) * direction, direction);
      EXPECT_GT(force, last) << angle << " " << delta;
      last = force;
    }
    for (Real depth : {0.05, 0.1}) {
      const Real delta = depth * rho;
      const HertzEllipse e = hertzEllipse(1 / kR, 1 / kR + 1 / rho, delta);
      if (std::min(angle - from, to - angle) < e.b / rho) continue;
      ++compared;
      const Real expected = hertzForce(1 / kR, 1 / kR + 1 / rho, delta);
      EXPECT_NEAR(pushBack(partners, axis + (rho + kR - delta) * direction, direction), expected, 0.05 * expected)
          << angle << " " << depth;
    }
  }
  EXPECT_GE(compared, 20);
}

TEST(RoundedEdges, ABallOnABoxEdgeIsHertzOnACylinder) {
  // The edge along y at x = z = h; rounded by rho, its axis runs rho behind both faces.
  const Real h = 0.1, rho = edgeRadius();
  expectHertzOnTheEdge({Partner{0, Box{Vector3r::Constant(h)}, kSteel}}, Vector3r(h - rho, 0, h - rho), 0, M_PI / 2);
}

// A lifter's ridge: two faces of two Facets each meeting at 37 degrees at an apex along y through the origin.
std::vector<Partner> ridge(Real apex) {
  const Real side = 0.15, sx = side * std::sin(apex / 2), sz = -side * std::cos(apex / 2);
  const Vector3r a0(0, -0.1, 0), a1(0, 0.1, 0), r0(sx, -0.1, sz), r1(sx, 0.1, sz), l0(-sx, -0.1, sz), l1(-sx, 0.1, sz);
  std::vector<Partner> facets;
  for (const std::array<Vector3r, 3>& c : {std::array<Vector3r, 3>{a0, a1, r1}, {a0, r1, r0}, {a0, l1, a1}, {a0, l0, l1}})
    facets.push_back(Partner{static_cast<int>(facets.size()), Facet{c, nullptr}, kSteel});
  return facets;
}

TEST(RoundedEdges, ABallOnALiftersRidgeOfFacetsIsHertzOnACylinder) {
  const Real apex = 37 * M_PI / 180, rho = edgeRadius();
  // The faces' outward normals lie (90 - 18.5) degrees either side of +z; the axis rho behind both.
  const Real normal = M_PI / 2 - apex / 2;
  const Vector3r axis(0, 0, -rho / std::sin(apex / 2));
  expectHertzOnTheEdge(ridge(apex), axis, -normal, normal);
}

TEST(RoundedEdges, ABallOnABoxCornerIsHertzOnASphere) {
  // Along the corner's diagonal, its patch's middle: Hertz's circle for radii R and rho within 5 %, as above.
  const Real h = 0.1, rho = edgeRadius();
  const Vector3r centre = Vector3r::Constant(h - rho), direction = Vector3r::Ones().normalized();
  for (Real depth : {0.05, 0.1}) {
    const Real delta = depth * rho, expected = hertzForce(1 / kR + 1 / rho, 1 / kR + 1 / rho, delta);
    EXPECT_NEAR(pushBack({Partner{0, Box{Vector3r::Constant(h)}, kSteel}}, centre + (rho + kR - delta) * direction,
                         direction),
                expected, 0.05 * expected);
  }
}

TEST(RoundedEdges, SlidingOverAnEdgeTheForceChangesContinuously) {
  // The ball held 0.5 mm into the rounded Box (its centre on the surface offset by R - 0.5 mm) and slid from the top
  // face round the edge onto the side: the force passes from the plane's Hertz force to the cylinder's (about half)
  // and back. Continuous: halving the step (12 um of path) halves the largest change between neighbouring poses
  // (a jump would keep it); measured 0.53.
  const Real h = 0.1, rho = edgeRadius(), delta = 0.0005, arc = M_PI / 2 * rho;
  const std::vector<Partner> box{Partner{0, Box{Vector3r::Constant(h)}, kSteel}};
  auto centre = [&](Real s) -> Vector3r {
    if (s < 0) return Vector3r(h - rho + s, 0, h + kR - delta);
    if (s > arc) return Vector3r(h + kR - delta, 0, h - rho - (s - arc));
    return Vector3r(h - rho, 0, h - rho) + (rho + kR - delta) * Vector3r(std::sin(s / rho), 0, std::cos(s / rho));
  };
  const int steps = 2000;
  std::vector<Real> force;
  for (int i = 0; i <= steps; ++i) {
    const Real s = -0.01 + (arc + 0.02) * i / steps;
    const BodyState state = at(centre(s), Quaternionr(Eigen::AngleAxis<Real>(0.4, Vector3r(1, 2, 3).normalized())));
    force.push_back(surfaceContact(roundedBody(0, ball(), kBall), state, box, {at(Vector3r::Zero())}, EngineOptions())
                        .onFirst.force.norm());
  }
  auto largestChange = [&](int stride) {
    Real largest = 0;
    for (int i = stride; i <= steps; i += stride) largest = std::max(largest, std::abs(force[i] - force[i - stride]));
    return largest;
  };
  EXPECT_LT(largestChange(1), 0.75 * largestChange(2));
  EXPECT_LT(largestChange(1), 0.03 * *std::max_element(force.begin(), force.end()));
}

}  // namespace
}  // namespace roundedmesh
