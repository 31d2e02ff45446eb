// Eq. 15 (node forces) and Eqs. 16-17 (body force and torque).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "pkg/law/NodeForces.hpp"

namespace roundedmesh {
namespace {

// Eq. 15 solved literally as the 3 x 3 linear system, independently of the barycentric solution.
std::array<Real, 3> solveEq15(const std::array<Vector2r, 3>& r, const NormalLoad& load) {
  Matrix3r m;
  m << r[0].y(), r[1].y(), r[2].y(), -r[0].x(), -r[1].x(), -r[2].x(), 1, 1, 1;
  const Vector3r rhs(load.moment.x(), load.moment.y(), load.force);
  const Vector3r f = m.fullPivLu().solve(rhs);
  return {f[0], f[1], f[2]};
}

// Random triangles and loads whose centre of pressure lies inside the triangle (as it always does, being
// inside S): the barycentric solution equals Eq. 15's, for loads that push and, every other trial, loads that pull
// (the energy law's damping while the sides part). Tolerance 1e-9 relative to Fn: LU round-off on triangles with a
// condition number up to ~1e4.
TEST(NodeForces, SolveEq15) {
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> u(-1, 1), positive(0, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const std::array<Vector2r, 3> nodes = {Vector2r(u(random), u(random)), Vector2r(u(random), u(random)),
                                           Vector2r(u(random), u(random))};
    if (std::abs(cross2(nodes[1] - nodes[0], nodes[2] - nodes[0])) < 1e-2) continue;
    Real l0 = positive(random), l1 = positive(random), l2 = positive(random);
    const Real s = l0 + l1 + l2;
    const Vector2r cop = (l0 * nodes[0] + l1 * nodes[1] + l2 * nodes[2]) / s;
    const Real F = (trial % 2 ? 1 : -1) * (1 + 10 * positive(random));
    const NormalLoad load{F, F * Vector2r(cop.y(), -cop.x()), Regime::Quadrature};
    const std::array<Real, 3> ours = nodeForces(nodes, load), reference = solveEq15(nodes, load);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(ours[i], reference[i], 1e-9 * std::abs(F));
    EXPECT_NEAR(ours[0] + ours[1] + ours[2], F, 1e-12 * std::abs(F));
  }
}

TEST(NodeForces, ZeroLoadGivesZeroNodeForces) {
  const std::array<Vector2r, 3> nodes = {Vector2r(0, 0), Vector2r(1, 0), Vector2r(0, 1)};
  const std::array<Real, 3> f = nodeForces(nodes, NormalLoad{0, Vector2r::Zero(), Regime::Direct});
  EXPECT_EQ(f[0] + f[1] + f[2], 0);
}

// Eqs. 16-17: the node forces give the body -Fn n12 and the torque of that force applied at the centre of
// pressure, lifted anywhere along n12 (the lift does not change the torque).
TEST(NodeForces, BodyWrenchIsTheResultantAtTheCentreOfPressure) {
  const Vector3r n(0, 0, -1), t1(0, 1, 0), t2(1, 0, 0), c(0.2, -0.1, -1.0);
  const std::array<Vector3r, 3> corners = {Vector3r(0.1, -0.3, -0.9), Vector3r(0.5, 0.0, -0.95),
                                           Vector3r(0.0, 0.3, -0.97)};
  std::array<Vector2r, 3> nodes;
  for (int i = 0; i < 3; ++i) nodes[i] = Vector2r((corners[i] - c).dot(t1), (corners[i] - c).dot(t2));
  const Vector2r cop = 0.2 * nodes[0] + 0.5 * nodes[1] + 0.3 * nodes[2];
  const NormalLoad load{2.5, 2.5 * Vector2r(cop.y(), -cop.x()), Regime::Quadrature};
  Wrench w;
  addNodeForcesToBody(corners, nodeForces(nodes, load), n, w);
  EXPECT_TRUE(w.force.isApprox(-2.5 * n, 1e-14));
  const Vector3r at = c + cop.x() * t1 + cop.y() * t2 + 0.37 * n;
  EXPECT_TRUE(w.torque.isApprox(at.cross(-2.5 * n), 1e-13));
}

}  // namespace
}  // namespace roundedmesh
