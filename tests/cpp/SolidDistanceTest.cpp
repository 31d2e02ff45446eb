// SolidDistance against the exact distance from a meshed unit sphere's solid: 0 inside, r - 1 outside up to the
// band (the flat mesh lies between its inradius and 1, so the exact value lies between r - 1 and r - r_in), all
// within the field's stated tolerance sqrt(3) * spacing; beyond the band, the band.
#include <gtest/gtest.h>

#include <random>

#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

TEST(SolidDistance, MatchesTheDistanceFromAMeshedSphere) {
  const RoundedMesh mesh = icosphere(1.0, 3);
  const SolidDistance& field = mesh.solidDistance();
  Real inradius = 1;
  for (int t = 0; t < mesh.triangleCount(); ++t)
    inradius = std::min(inradius, mesh.rounded(t).normal.dot(mesh.vertices()[mesh.triangles()[t][0]]));
  std::mt19937 rng(2);
  std::normal_distribution<Real> normal;
  std::uniform_real_distribution<Real> uniform(0, 1);
  int inside = 0, near = 0, far = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vector3r direction = Vector3r(normal(rng), normal(rng), normal(rng)).normalized();
    const Real r = 1.5 * uniform(rng) + 0.2 * uniform(rng) * (k % 2) + (k % 3 == 0 ? field.band() : 0);
    const Real value = field.at(r * direction);
    if (r < inradius) {
      EXPECT_LE(value, field.tolerance()) << "r = " << r;
      ++inside;
    } else {
      // The band clamps the field, which stays 1-Lipschitz, so the tolerance holds for the clamped values.
      EXPECT_GE(value, std::min(r - 1, field.band()) - field.tolerance()) << "r = " << r;
      EXPECT_LE(value, std::min(r - inradius, field.band()) + field.tolerance()) << "r = " << r;
      ++(r - 1 < field.band() ? near : far);
    }
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(near, 300);
  EXPECT_GT(far, 100);
  EXPECT_LT(field.tolerance(), 0.1);
}

}  // namespace
}  // namespace roundedmesh
