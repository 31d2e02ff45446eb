// RoundedMesh: encompassing spheres (Section 2.1, Fig. 1) and input validation.
#include <gtest/gtest.h>

#include <cmath>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {
namespace {

RoundedMesh singleTriangle(Real radius) {
  return RoundedMesh({{0, 0, 0}, {1, 0, 0}, {0.2, 0.9, 0.1}}, {{0, 1, 2}}, {radius});
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// The encompassing sphere passes through the three corners and has its centre on the inner side.
TEST(RoundedMesh, EncompassingSpherePassesThroughTheCornersOnTheInnerSide) {
  const RoundedMesh m = singleTriangle(3.0);
  const RoundedTriangle& r = m.rounded(0);
  for (const Vector3r& v : m.vertices()) EXPECT_NEAR((v - r.sphereCentre).norm(), 3.0, 1e-13);
  EXPECT_LT(r.normal.dot(r.sphereCentre - m.vertices()[0]), 0);
  EXPECT_NEAR(r.area, 0.5 * (m.vertices()[1] - m.vertices()[0]).cross(m.vertices()[2] - m.vertices()[0]).norm(),
              1e-15);
}

// No sphere through the corners is smaller than the circumcircle: a smaller radius is raised to it and
// the centre then lies in the triangle's plane.
TEST(RoundedMesh, RadiusBelowTheCircumradiusIsRaisedToIt) {
  const RoundedMesh m = singleTriangle(0.01);
  const RoundedTriangle& r = m.rounded(0);
  for (const Vector3r& v : m.vertices()) EXPECT_NEAR((v - r.sphereCentre).norm(), r.radius, 1e-13);
  EXPECT_NEAR(r.normal.dot(r.sphereCentre - m.vertices()[0]), 0, 1e-13);
  EXPECT_GT(r.radius, 0.5);
}

TEST(RoundedMesh, RejectsBadInputNamingIt) {
  EXPECT_NE(messageOf([] { singleTriangle(-1); }).find("radius of triangle 0"), std::string::npos);
  EXPECT_NE(messageOf([] { singleTriangle(std::nan("")); }).find("radius of triangle 0"), std::string::npos);
  EXPECT_NE(messageOf([] { RoundedMesh({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}}, {1}); })
                .find("vertex 2 is not finite"),
            std::string::npos);
  EXPECT_NE(messageOf([] { RoundedMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 5}}, {1}); })
                .find("triangle 0 refers to vertex 5"),
            std::string::npos);
  EXPECT_NE(messageOf([] { RoundedMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}, {1}); })
                .find("triangle 0 (vertices 0, 1, 2) has zero area"),
            std::string::npos);
  EXPECT_NE(messageOf([] { RoundedMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {1, 2}); }).find("radii"),
            std::string::npos);
}

TEST(RoundedMesh, TransformedMovesEverythingRigidly) {
  const RoundedMesh m = singleTriangle(2.0);
  const Matrix3r rotation = Eigen::AngleAxis<Real>(0.7, Vector3r(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3r shift(0.3, -1, 2);
  const RoundedMesh moved = m.transformed(rotation, shift);
  EXPECT_TRUE(moved.rounded(0).sphereCentre.isApprox(rotation * m.rounded(0).sphereCentre + shift, 1e-13));
  EXPECT_TRUE(moved.rounded(0).normal.isApprox(rotation * m.rounded(0).normal, 1e-13));
  EXPECT_NEAR(moved.rounded(0).radius, 2.0, 1e-15);
}

}  // namespace
}  // namespace roundedmesh
