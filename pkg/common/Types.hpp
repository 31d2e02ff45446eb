// Scalar and vector types of the core. Real is double, as in Debian's yade-double build, so that the
// Boost.Python layer hands YADE's Vector3 and Quaternion to these types without conversion.
#pragma once

#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roundedmesh {

using Real = double;
using Vector2r = Eigen::Matrix<Real, 2, 1>;
using Vector3r = Eigen::Matrix<Real, 3, 1>;
using Matrix2r = Eigen::Matrix<Real, 2, 2>;
using Matrix3r = Eigen::Matrix<Real, 3, 3>;
using Quaternionr = Eigen::Quaternion<Real>;

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

// z-component of the cross product of two plane vectors.
inline Real cross2(const Vector2r& a, const Vector2r& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace roundedmesh
