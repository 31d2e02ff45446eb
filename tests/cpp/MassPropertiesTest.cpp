// Mass properties of closed meshes and the principal frame (BodyMesh).
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Cylinder.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

// Axis-aligned cuboid [0, a] x [0, b] x [0, c], outward-oriented.
RoundedMesh cuboid(Real a, Real b, Real c) {
  std::vector<Vector3r> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? a : 0, i & 2 ? b : 0, i & 4 ? c : 0);
  const std::vector<Triangle> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return RoundedMesh(v, t, std::vector<Real>(t.size(), 10.0));
}

// A polyhedron's mass properties are exact: a cuboid's are V = abc, centre (a, b, c)/2 and
// I_xx = V (b^2 + c^2) / 12 etc. Tolerance: round-off.
TEST(MassProperties, CuboidIsExact) {
  const RoundedMesh box = cuboid(1, 2, 3);
  const MassProperties p = massProperties(box.vertices(), box.triangles());
  EXPECT_NEAR(p.volume, 6, 1e-13);
  EXPECT_TRUE(p.centroid.isApprox(Vector3r(0.5, 1, 1.5), 1e-14));
  EXPECT_NEAR(p.inertia(0, 0), 6 * (4 + 9) / 12.0, 1e-12);
  EXPECT_NEAR(p.inertia(1, 1), 6 * (1 + 9) / 12.0, 1e-12);
  EXPECT_NEAR(p.inertia(2, 2), 6 * (1 + 4) / 12.0, 1e-12);
  EXPECT_NEAR(p.inertia(0, 1), 0, 1e-12);
  EXPECT_NEAR(p.inertia(1, 2), 0, 1e-12);
}

// Tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1): V = 1/6, centroid 1/4, and about the centroid
// I_xx = 1/80, I_xy = +1/480 (product of inertia -integral(x y) + V x_c y_c = -1/120 + 1/96).
TEST(MassProperties, TetrahedronIsExact) {
  const std::vector<Vector3r> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Triangle> t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const MassProperties p = massProperties(v, t);
  EXPECT_NEAR(p.volume, 1.0 / 6, 1e-15);
  EXPECT_TRUE(p.centroid.isApprox(Vector3r::Constant(0.25), 1e-14));
  EXPECT_NEAR(p.inertia(0, 0), 1.0 / 80, 1e-15);
  EXPECT_NEAR(p.inertia(0, 1), 1.0 / 480, 1e-15);
}

// The inscribed icosphere's volume and moments approach the sphere's (4/3 pi R^3, 2/5 V R^2) from below,
// the error shrinking about fourfold per subdivision (second order in the edge length). The missing volume
// is bounded independently: over each triangle it lies in the cone from the centre, between the
// triangle's plane (at distance d from the centre) and the sphere, so it is at most the cap height R - d
// times the triangle's area magnified to the sphere, (R/d)^2.
TEST(MassProperties, IcosphereConvergesToTheSphere) {
  const Real volumeExact = 4 * M_PI / 3, inertiaExact = 0.4 * volumeExact;
  Real previous = 1;
  for (int k = 1; k <= 5; ++k) {
    const RoundedMesh m = icosphere(1.0, k);
    const MassProperties p = massProperties(m.vertices(), m.triangles());
    Real missingBound = 0;
    for (int t = 0; t < m.triangleCount(); ++t) {
      const Real d = m.rounded(t).normal.dot(m.vertices()[m.triangles()[t][0]]);
      missingBound += (1 - d) * m.rounded(t).area / (d * d);
    }
    const Real volumeError = 1 - p.volume / volumeExact;
    const Real inertiaError = 1 - p.inertia(0, 0) / inertiaExact;
    EXPECT_GT(volumeError, 0);
    EXPECT_LT(volumeError * volumeExact, missingBound);
    EXPECT_GT(inertiaError, 0);
    EXPECT_LT(volumeError, previous / 3.5);
    EXPECT_NEAR(p.inertia(0, 0), p.inertia(2, 2), 1e-12);
    previous = volumeError;
  }
}

// Far from the origin the mass properties are those of the same mesh at the origin: moments are taken
// about the vertices' mean, so nothing cancels. A 2.5 cm sphere 10 km away: the coordinates themselves
// carry 1e4 * 1e-16 m of round-off, 4e-11 of the radius, hence 1e-9 relative.
TEST(MassProperties, AreTheSameFarFromTheOrigin) {
  const RoundedMesh here = icosphere(0.025, 3);
  const RoundedMesh far = here.transformed(Matrix3r::Identity(), Vector3r(1e4, -3e3, 7e3));
  const MassProperties p = massProperties(here.vertices(), here.triangles());
  const MassProperties q = massProperties(far.vertices(), far.triangles());
  EXPECT_NEAR(q.volume, p.volume, 1e-9 * p.volume);
  EXPECT_LT((q.centroid - Vector3r(1e4, -3e3, 7e3)).norm(), 1e-9);
  EXPECT_LT((q.inertia - p.inertia).norm(), 1e-9 * p.inertia.norm());
}

TEST(BodyMesh, AMeshGivenFarAwayRestoresFromItsPrincipalFrame) {
  const BodyMesh body(icosphere(0.025, 3).transformed(Matrix3r::Identity(), Vector3r(3, 100, -40)));
  const BodyMesh restored(body.shape(), body.inputCentroid(), body.inputOrientation(), body.curvature());
  EXPECT_TRUE(restored.principalMoments().isApprox(body.principalMoments(), 1e-9));
}

// A rotated, shifted cuboid is brought back to its principal frame: moments of the cuboid, and the
// stored pose maps body-frame vertices back onto the input.
TEST(BodyMesh, MovesTheMeshIntoItsPrincipalFrame) {
  const Matrix3r rotation = Eigen::AngleAxis<Real>(0.9, Vector3r(1, -2, 0.5).normalized()).toRotationMatrix();
  const RoundedMesh input = cuboid(1, 2, 3).transformed(rotation, Vector3r(4, 5, 6));
  const BodyMesh body(input);
  EXPECT_NEAR(body.volume(), 6, 1e-12);
  Vector3r moments = body.principalMoments();
  std::sort(moments.data(), moments.data() + 3);
  EXPECT_TRUE(moments.isApprox(Vector3r(2.5, 5, 6.5), 1e-12));
  const MassProperties p = massProperties(body.shape().vertices(), body.shape().triangles());
  EXPECT_LT(p.centroid.norm(), 1e-12);
  EXPECT_LT((p.inertia - Matrix3r(p.inertia.diagonal().asDiagonal())).norm(), 1e-11);
  for (size_t i = 0; i < input.vertices().size(); ++i)
    EXPECT_TRUE((body.inputOrientation() * body.shape().vertices()[i] + body.inputCentroid())
                    .isApprox(input.vertices()[i], 1e-12));
}

TEST(BodyMesh, KeepsAnAxisAlignedMeshUnrotated) {
  const BodyMesh body(cuboid(1, 3, 2));
  EXPECT_TRUE(body.inputOrientation().coeffs().isApprox(Quaternionr::Identity().coeffs()));
  EXPECT_TRUE(body.principalMoments().isApprox(Vector3r(6 * 13 / 12.0, 6 * 5 / 12.0, 6 * 10 / 12.0), 1e-12));
}

TEST(BodyMesh, RestoresAPrincipalFrameMeshWithoutMovingIt) {
  const BodyMesh body(icosphere(1.0, 2).transformed(Matrix3r::Identity(), Vector3r(1, 2, 3)));
  const BodyMesh restored(body.shape(), body.inputCentroid(), body.inputOrientation(), body.curvature());
  for (size_t i = 0; i < body.shape().vertices().size(); ++i)
    EXPECT_EQ(restored.shape().vertices()[i], body.shape().vertices()[i]);
  const SurfaceCurvature unit{std::vector<Real>(80, 1.0), CurvatureSource::Prescribed, 100.0};
  EXPECT_THROW(BodyMesh(icosphere(1.0, 1).transformed(Matrix3r::Identity(), Vector3r(1, 0, 0)), Vector3r::Zero(),
                        Quaternionr::Identity(), unit),
               std::invalid_argument);
}

// From a bare surface: curvature computed by Eq. 1 unless prescribed. Flat regions (a cylinder's cap away
// from the rim, where Eq. 1 gives exactly 0) get the cap radius, 100 volume-equivalent radii by default;
// the input-frame surface is the one given.
TEST(BodyMesh, TakesItsRadiiFromTheCurvature) {
  const TriangleSurface cylinder = cylinderSurface(1.0, 2.0, 400);
  const BodyMesh computed(cylinder, std::nullopt);
  EXPECT_EQ(computed.curvature().source, CurvatureSource::Computed);
  const Real cap = 100 * std::cbrt(3 * computed.volume() / (4 * M_PI));
  EXPECT_NEAR(computed.curvature().maxRadius, cap, 1e-12);
  int flat = 0;
  for (int t = 0; t < computed.shape().triangleCount(); ++t) {
    const Triangle& corners = cylinder.triangles[t];
    bool inner = true;
    for (int c : corners) inner = inner && std::abs(cylinder.vertices[c].z()) == 1.0 && cylinder.vertices[c].head<2>().norm() < 0.99;
    if (!inner) continue;
    ++flat;
    EXPECT_EQ(computed.shape().radii()[t], cap);
  }
  EXPECT_GT(flat, 50);

  TriangleSurface cube{cuboid(1, 1, 1).vertices(), cuboid(1, 1, 1).triangles()};
  for (Vector3r& v : cube.vertices) v += Vector3r(2, 0, 0);
  const BodyMesh prescribed(cube, std::vector<Real>(12, 0.25), 7.0);
  EXPECT_EQ(prescribed.curvature().source, CurvatureSource::Prescribed);
  EXPECT_EQ(prescribed.curvature().maxRadius, 7.0);
  for (Real r : prescribed.shape().radii()) EXPECT_NEAR(r, 4.0, 1e-12);
  const TriangleSurface back = prescribed.inputFrameSurface();
  for (std::size_t i = 0; i < cube.vertices.size(); ++i) EXPECT_TRUE(back.vertices[i].isApprox(cube.vertices[i], 1e-14));
  EXPECT_THROW(BodyMesh(cube, std::vector<Real>(11, 1.0)), std::invalid_argument);
}

TEST(BodyMesh, RejectsAMeshWithoutVolume) {
  const RoundedMesh flat({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}, {1, 1});
  EXPECT_THROW(BodyMesh{flat}, std::invalid_argument);
  // Inside-out: the volume is negative.
  const RoundedMesh sphere = icosphere(1.0, 1);
  std::vector<Triangle> flipped = sphere.triangles();
  for (Triangle& t : flipped) std::swap(t[1], t[2]);
  EXPECT_THROW(BodyMesh(RoundedMesh(sphere.vertices(), flipped, sphere.radii())), std::invalid_argument);
}

}  // namespace
}  // namespace roundedmesh
