// Both principal curvatures per triangle (PrincipalCurvature.hpp): Rusinkiewicz's estimate against analytic
// curvatures (sphere, cylinder, torus with its concave inner side, spheroid), the analytic spheroid and cylinder,
// and how a mesh keeps and moves them.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Cylinder.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

Vector3r centroid(const TriangleSurface& s, const Triangle& t) {
  return (s.vertices[t[0]] + s.vertices[t[1]] + s.vertices[t[2]]) / 3;
}

// Max's vertex normals are exact on a sphere, and Rusinkiewicz's fit then maps each edge e to e / R exactly: the
// estimate is 1/R twice to round-off (measured 3e-14 at 2562 nodes).
TEST(PrincipalCurvature, IcosphereEstimateIsTheSpheresCurvature) {
  for (int k : {2, 3, 4}) {
    const std::vector<PrincipalCurvature> c = principalCurvatures(icosphereSurface(2.0, k));
    for (const PrincipalCurvature& p : c) {
      EXPECT_NEAR(p.k1, 0.5, 1e-12);
      EXPECT_NEAR(p.k2, 0.5, 1e-12);
    }
  }
}

// Away from the rims (whose vertex normals average hull and cap), a hull triangle's vertex normals are radial: 1/R
// around to round-off; along the axis the rings' stagger leaves 1e-3/R (642 nodes) and 3e-4/R (2562): bound 2e-3/R.
TEST(PrincipalCurvature, CylinderHullEstimateIsOneOverRAroundAndZeroAlong) {
  const Real R = 1, L = 4;
  for (int nodes : {642, 2562}) {
    const TriangleSurface s = cylinderSurface(R, L, nodes);
    const std::vector<PrincipalCurvature> c = principalCurvatures(s);
    int interior = 0;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      bool awayFromRims = true;
      for (int v : s.triangles[t]) awayFromRims = awayFromRims && std::abs(s.vertices[v].z()) < L / 2 - 1e-9;
      if (!awayFromRims) continue;
      ++interior;
      EXPECT_NEAR(c[t].k1, 1 / R, 1e-12);
      EXPECT_NEAR(c[t].k2, 0, 2e-3 / R);
      EXPECT_NEAR(std::abs(c[t].d1.z()), 0, 1e-3) << "k1 runs around the hull";
    }
    EXPECT_GT(interior, nodes / 2);
  }
}

// On the regular torus grid the estimate has the signs of the surface: the tube's 1/r everywhere, and
// cos v / (R + r cos v) around the axis, negative on the inner side. Errors at the triangle's centroid are
// O(h): measured 1.7 % of 1/r at worst on a 96 x 48 grid; bound 4 %.
TEST(PrincipalCurvature, TorusEstimateHasTheSignsAndValuesOfTheSurface) {
  const Real R = 1, r = 0.4;
  const TriangleSurface s = test::torus(R, r, 96, 48);
  const std::vector<PrincipalCurvature> c = principalCurvatures(s);
  Real worst = 0;
  int concave = 0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Vector3r x = centroid(s, s.triangles[t]);
    const Real radial = std::hypot(x.x(), x.y()) - R;
    const Real cosV = radial / std::hypot(radial, x.z());
    const Real around = cosV / (R + r * cosV);
    worst = std::max({worst, std::abs(c[t].k1 - 1 / r) * r, std::abs(c[t].k2 - around) * r});
    concave += c[t].k2 < 0;
  }
  std::cout << "[ torus 96 x 48 ] worst principal curvature error " << worst << " of 1/r\n";
  EXPECT_LT(worst, 0.04);
  EXPECT_NEAR(concave, static_cast<int>(s.triangles.size()) / 2, s.triangles.size() / 20) << "half the torus is saddle";
}

// On the isotropically remeshed spheroid (valence 5 and 7 nodes) the estimate is first order like Eq. 1 there:
// measured RMS error 2.1 % / 1.6 % of the larger curvature at 642 / 2562 nodes, worst 8 % / 7 %, mean of k2's
// relative error 2.0 % / 0.8 %. Bounds: RMS 3 %, worst 12 %, and the bias falling with refinement.
TEST(PrincipalCurvature, SpheroidEstimateApproachesTheExactCurvatures) {
  const Real a = 2, b = 1;
  Real previousBias = 1;
  for (int nodes : {642, 2562}) {
    const TriangleSurface s = spheroidSurface(a, b, nodes);
    const std::vector<PrincipalCurvature> estimate = principalCurvatures(s);
    const std::vector<PrincipalCurvature> exact = spheroidTrianglePrincipalCurvatures(a, b, s);
    Real squared = 0, worst = 0, bias = 0;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const Real scale = exact[t].k1;
      for (const Real e : {(estimate[t].k1 - exact[t].k1) / scale, (estimate[t].k2 - exact[t].k2) / scale}) {
        squared += e * e / 2;
        worst = std::max(worst, std::abs(e));
      }
      bias += (estimate[t].k2 - exact[t].k2) / exact[t].k2 / s.triangles.size();
    }
    const Real rms = std::sqrt(squared / s.triangles.size());
    std::cout << "[ spheroid a=2 b=1, " << nodes << " nodes ] principal curvatures RMS " << rms << ", worst " << worst
              << ", bias of k2 " << bias << "\n";
    EXPECT_LT(rms, 0.03);
    EXPECT_LT(worst, 0.12);
    EXPECT_LT(std::abs(bias), previousBias);
    previousBias = std::abs(bias);
  }
}

// The analytic spheroid x^2/b^2 + y^2/b^2 + z^2/a^2 = 1 at its equator: 1/b around, b/a^2 along the meridian
// (the direction of z). Triangles whose centroid lies within 0.05 b of the equator: the curvatures change by
// less than 1 % of 1/b over that height (they are even in z: (0.05 b / a)^2 terms), d1 around the equator.
TEST(PrincipalCurvature, AnalyticSpheroidHasItsEquatorCurvatures) {
  const Real a = 2, b = 1;
  const TriangleSurface s = spheroidSurface(a, b, 2562);
  const std::vector<PrincipalCurvature> c = spheroidTrianglePrincipalCurvatures(a, b, s);
  int near = 0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    if (std::abs(centroid(s, s.triangles[t]).z()) > 0.05 * b) continue;
    ++near;
    EXPECT_NEAR(c[t].k1, 1 / b, 0.01 / b);
    EXPECT_NEAR(c[t].k2, b / (a * a), 0.01 / b);
    EXPECT_LT(std::abs(c[t].d1.z()), 0.1);
  }
  EXPECT_GT(near, 10);
}

// A known operator: diag(3, 1) in the plane z = 0 has k1 = 3 along x; turned into a tilted triangle's plane the
// values stay and d1 lies in that plane.
TEST(PrincipalCurvature, KnownOperatorKeepsItsValuesInATiltedTrianglesPlane) {
  const Matrix3r op = Vector3r(3, 1, 0).asDiagonal();
  const Vector3r tilted = Vector3r(0.1, 0.2, 1).normalized();
  const PrincipalCurvature p = principalCurvature(op, Vector3r::UnitZ(), tilted);
  EXPECT_NEAR(p.k1, 3, 1e-14);
  EXPECT_NEAR(p.k2, 1, 1e-14);
  EXPECT_NEAR(p.d1.dot(tilted), 0, 1e-14);
  EXPECT_NEAR(std::abs(p.d1.x()), 1, 0.03);
}

// The mesh keeps them through its move into the principal frame, turning the directions with it; prescribed
// mean curvatures without principal ones give k1 = k2 = H; a computed mesh gets the estimate.
TEST(PrincipalCurvature, BodyMeshKeepsAndTurnsThem) {
  const Real a = 2, b = 1;
  TriangleSurface s = spheroidSurface(a, b, 642);
  // The spheroid along x instead of z: the body frame turns it back onto a principal axis.
  for (Vector3r& v : s.vertices) v = Vector3r(v.z(), v.x(), v.y());
  TriangleSurface upright = spheroidSurface(a, b, 642);
  const std::vector<PrincipalCurvature> exact = spheroidTrianglePrincipalCurvatures(a, b, upright);
  std::vector<PrincipalCurvature> turned = exact;
  for (PrincipalCurvature& p : turned) p.d1 = Vector3r(p.d1.z(), p.d1.x(), p.d1.y());
  const BodyMesh body(s, spheroidTriangleCurvatures(a, b, upright), std::nullopt, turned);
  const Matrix3r toInput = body.inputOrientation().toRotationMatrix();
  for (int t = 0; t < body.shape().triangleCount(); ++t) {
    const PrincipalCurvature& p = body.shape().principal(t);
    EXPECT_EQ(p.k1, exact[t].k1);
    EXPECT_EQ(p.k2, exact[t].k2);
    EXPECT_NEAR((toInput * p.d1 - turned[t].d1).norm(), 0, 1e-12);
    EXPECT_NEAR(p.d1.dot(body.shape().rounded(t).normal), 0, 0.05) << "tangent to its triangle";
  }
  const BodyMesh mean(upright, std::vector<Real>(upright.triangles.size(), -0.25));
  EXPECT_EQ(mean.shape().principal(7).k1, -0.25);
  EXPECT_EQ(mean.shape().principal(7).k2, -0.25);
  const BodyMesh computed(upright, std::nullopt);
  EXPECT_NE(computed.shape().principal(7).k1, computed.shape().principal(7).k2);
}

TEST(PrincipalCurvature, MeshRefusesInconsistentPrincipalCurvatures) {
  const TriangleSurface s = icosphereSurface(1, 1);
  const std::vector<Real> radii(s.triangles.size(), 1.0);
  EXPECT_THROW(RoundedMesh(s.vertices, s.triangles, radii, std::vector<PrincipalCurvature>(3)), std::invalid_argument);
  std::vector<PrincipalCurvature> swapped(s.triangles.size(), PrincipalCurvature{0.5, 1.0, Vector3r::UnitX()});
  EXPECT_THROW(RoundedMesh(s.vertices, s.triangles, radii, swapped), std::invalid_argument);
  std::vector<PrincipalCurvature> notANumber(s.triangles.size(), PrincipalCurvature{NAN, 1.0, Vector3r::UnitX()});
  EXPECT_THROW(RoundedMesh(s.vertices, s.triangles, radii, notANumber), std::invalid_argument);
}

}  // namespace
}  // namespace roundedmesh
