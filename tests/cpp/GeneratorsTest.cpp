// Shape generators: distorted icospheres (Fig. 4a), spheroids and cylinders (S5), blended shapes
// (shapes.json). Each must be closed and outward, match its node count, and converge to the smooth
// shape's mass properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "pkg/meshing/BlendedShape.hpp"
#include "pkg/shape/Cylinder.hpp"
#include "pkg/shape/Distortion.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "pkg/shape/MassProperties.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

// Relative errors of volume and principal moments (ascending) against exact values.
struct MassErrors {
  Real volume, moments;
};
MassErrors massErrors(const TriangleSurface& s, Real volume, Vector3r moments) {
  const MassProperties m = massProperties(s.vertices, s.triangles);
  Vector3r computed = principalAxes(m.inertia).moments;
  std::sort(computed.data(), computed.data() + 3);
  std::sort(moments.data(), moments.data() + 3);
  return {std::abs(m.volume / volume - 1), (computed - moments).cwiseQuotient(moments).cwiseAbs().maxCoeff()};
}

// The inscribed polyhedron's volume and moments converge to the smooth solid's at O(h^2): each fourfold
// refinement (162, 642, 2562 nodes) must cut the error by at least 2.5 and end below 0.5 %.
void expectMassPropertiesConverge(const std::function<TriangleSurface(int)>& mesh, Real volume,
                                  const Vector3r& moments) {
  MassErrors previous{1, 1};
  for (int nodes : {162, 642, 2562}) {
    const MassErrors e = massErrors(mesh(nodes), volume, moments);
    EXPECT_LT(e.volume, previous.volume / 2.5) << nodes;
    EXPECT_LT(e.moments, previous.moments / 2.5) << nodes;
    previous = e;
  }
  EXPECT_LT(previous.volume, 0.005);
  EXPECT_LT(previous.moments, 0.005);
}

TEST(Distortion, IsTheRelativeSpreadOfTriangleAreas) {
  // Areas 1/2, 1/2, 2, 2 (population std 0.75, mean 1.25): D = 0.6.
  const TriangleSurface s{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 2, 0}},
                          {{0, 1, 2}, {0, 2, 1}, {0, 3, 4}, {0, 4, 3}}};
  EXPECT_NEAR(distortion(s), 0.6, 1e-15);
}

TEST(DistortedIcosphere, ReachesTheRequestedDistortionWithoutFolding) {
  for (Real target : {0.3, 0.5, 0.7}) {
    const TriangleSurface s = distortedIcosphereSurface(1.5, 3, target, 7);
    EXPECT_NEAR(distortion(s), target, 2e-3);
    EXPECT_NO_THROW(requireValidSurface(s));
    for (const Vector3r& v : s.vertices) EXPECT_NEAR(v.norm(), 1.5, 1e-12);
  }
}

TEST(DistortedIcosphere, IsReproducibleForASeed) {
  const TriangleSurface a = distortedIcosphereSurface(1.0, 2, 0.5, 3), b = distortedIcosphereSurface(1.0, 2, 0.5, 3),
                        c = distortedIcosphereSurface(1.0, 2, 0.5, 4);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_NE(a.vertices, c.vertices);
}

TEST(DistortedIcosphere, RejectsADistortionOutOfRange) {
  EXPECT_THROW(distortedIcosphereSurface(1.0, 3, 0.01, 1), std::invalid_argument);  // the regular one has 0.086
  EXPECT_THROW(distortedIcosphereSurface(1.0, 3, 2.0, 1), std::invalid_argument);
  EXPECT_THROW(distortedIcosphereSurface(1.0, 3, NAN, 1), std::invalid_argument);
}

TEST(Spheroid, HasTheRequestedNodesOnTheSurface) {
  for (int nodes : {162, 642}) {
    const TriangleSurface s = spheroidSurface(2.0, 1.0, nodes);
    EXPECT_NEAR(Real(s.vertices.size()) / nodes, 1.0, 0.02);
    EXPECT_NO_THROW(requireValidSurface(s));
    for (const Vector3r& x : s.vertices)
      EXPECT_NEAR((x.x() * x.x() + x.y() * x.y()) + x.z() * x.z() / 4, 1.0, 1e-10);
    EXPECT_LT(distortion(s), 0.3);  // near-equilateral, unlike a stretched icosphere
  }
}

TEST(Spheroid, MassPropertiesConvergeToTheAnalyticOnes) {
  const Real a = 1.5, b = 1.0, volume = 4 * M_PI * a * b * b / 3;
  expectMassPropertiesConverge([&](int nodes) { return spheroidSurface(a, b, nodes); }, volume,
                               volume / 5 * Vector3r(a * a + b * b, a * a + b * b, 2 * b * b));
}

// Lengths whose ring heights are not exact in binary, short and long cylinders, coarse and fine.
TEST(Cylinder, IsClosedAndOutwardForAnyProportions) {
  for (const auto& [radius, length] : {std::pair<Real, Real>{0.01, 0.011}, {0.01, 0.029}, {0.01, 0.1}, {0.3, 0.07}})
    for (int nodes : {30, 300, 1000}) {
      const TriangleSurface s = cylinderSurface(radius, length, nodes);
      EXPECT_NO_THROW(requireValidSurface(s)) << radius << " " << length << " " << nodes;
      EXPECT_NEAR(massProperties(s.vertices, s.triangles).volume / (M_PI * radius * radius * length), 1, 0.2);
    }
}

TEST(Cylinder, HasTheRequestedNodesAndFlatCaps) {
  for (int nodes : {100, 642, 2562}) {
    const TriangleSurface s = cylinderSurface(0.5, 3.0, nodes);
    EXPECT_NEAR(Real(s.vertices.size()) / nodes, 1.0, 0.03) << nodes;
    EXPECT_NO_THROW(requireValidSurface(s));
    for (const Vector3r& x : s.vertices) {
      const bool onHull = std::abs(std::hypot(x.x(), x.y()) - 0.5) < 1e-12;
      const bool onCap = std::abs(std::abs(x.z()) - 1.5) < 1e-12 && std::hypot(x.x(), x.y()) < 0.5 + 1e-12;
      EXPECT_TRUE(onHull || onCap);
    }
    const std::vector<Real> curvature = cylinderTriangleCurvatures(0.5, s);
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const bool cap = std::abs(s.vertices[s.triangles[t][0]].z()) == 1.5 &&
                       std::abs(s.vertices[s.triangles[t][1]].z()) == 1.5 &&
                       std::abs(s.vertices[s.triangles[t][2]].z()) == 1.5;
      EXPECT_EQ(curvature[t], cap ? 0.0 : 1.0);
    }
  }
}

TEST(Cylinder, MassPropertiesConvergeToTheAnalyticOnes) {
  const Real r = 1.0, length = 4.0, volume = M_PI * r * r * length, across = (3 * r * r + length * length) / 12;
  expectMassPropertiesConverge([&](int nodes) { return cylinderSurface(r, length, nodes); }, volume,
                               volume * Vector3r(across, across, r * r / 2));
}

TEST(BlendedShape, IsThePolynomialSmoothMinimumOfSignedDistances) {
  const BlendedShape shape{0.5, {{{0, 0, 0}, {0, 0, 0}, 1.0}, {{3, 0, 0}, {3, 0, 2}, 0.5}}};
  // Far from the blend: the plain distances.
  EXPECT_NEAR(blendedDistance(shape, {-3, 0, 0}), 2.0, 1e-15);
  EXPECT_NEAR(blendedDistance(shape, {5, 0, 1}), 1.5, 1e-15);
  // Midway, distances 0.75 (sphere) and 0.75 (capsule's end ball): h = 1, smin = 0.75 - 0.5/4.
  EXPECT_NEAR(blendedDistance(shape, {1.75, 0, 0}), 0.625, 1e-15);
  const Vector3r x(1.5, 0, 0);
  const Real sphere = 0.5, capsule = 1.0;  // 1.5 - 1 and 1.5 - 0.5
  EXPECT_NEAR(blendedDistance(shape, x), std::min(sphere, capsule), 1e-15);  // |a - b| = 0.5 = k: no blending
}

TEST(BlendedShape, OneSphereMeshesToThatSphereScaledToTheVolume) {
  const BlendedShape ball{0.1, {{{1, 2, 3}, {1, 2, 3}, 0.5}}};
  Real scale = 0;
  const Real volume = 4 * M_PI / 3 * std::pow(0.025, 3);
  const TriangleSurface s = blendedShapeSurface(ball, 486, volume, &scale);
  EXPECT_NEAR(Real(s.vertices.size()) / 486, 1.0, 0.02);
  EXPECT_NEAR(massProperties(s.vertices, s.triangles).volume, volume, 1e-12 * volume);
  // The polyhedron inscribed in the ball has a little less volume, so the scale is a little more than 0.05.
  EXPECT_GT(scale, 0.05);
  EXPECT_LT(scale, 0.05 * 1.005);
  for (const Vector3r& x : s.vertices) EXPECT_NEAR((x / scale - Vector3r(1, 2, 3)).norm(), 0.5, 1e-9);
}

TEST(BlendedShape, RejectsBadDefinitions) {
  EXPECT_THROW(implicitSolid(BlendedShape{0.1, {}}), std::invalid_argument);
  EXPECT_THROW(implicitSolid(BlendedShape{-0.1, {{{0, 0, 0}, {0, 0, 0}, 1.0}}}), std::invalid_argument);
  EXPECT_THROW(implicitSolid(BlendedShape{0.1, {{{0, 0, 0}, {0, 0, 0}, 0.0}}}), std::invalid_argument);
}

}  // namespace
}  // namespace roundedmesh
