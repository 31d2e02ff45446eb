#include "pkg/shape/SolidDistance.hpp"

#include <algorithm>

#include "pkg/math/ClosestPoint.hpp"

namespace roundedmesh {

SolidDistance::SolidDistance(const std::vector<Vector3r>& vertices, const std::vector<std::array<int, 3>>& triangles,
                             Real spacing, Real band)
    : spacing_(spacing), band_(band) {
  Eigen::AlignedBox<Real, 3> box;
  for (const Vector3r& v : vertices) box.extend(v);
  origin_ = box.min().array() - (band + spacing);
  const Vector3r size = box.sizes().array() + 2 * (band + spacing);
  nx_ = static_cast<int>(std::ceil(size.x() / spacing)) + 1;
  ny_ = static_cast<int>(std::ceil(size.y() / spacing)) + 1;
  nz_ = static_cast<int>(std::ceil(size.z() / spacing)) + 1;
  std::vector<Real> distances(static_cast<size_t>(nx_) * ny_ * nz_, band);
  auto index = [&](int i, int j, int k) { return (static_cast<size_t>(k) * ny_ + j) * nx_ + i; };
  auto position = [&](int i, int j, int k) { return Vector3r(origin_ + spacing * Vector3r(i, j, k)); };

  // Outside: the distance to the nearest triangle, for the nodes within the band of each.
  for (const std::array<int, 3>& t : triangles) {
    const Vector3r &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const Vector3r low = a.cwiseMin(b).cwiseMin(c).array() - band, high = a.cwiseMax(b).cwiseMax(c).array() + band;
    const Eigen::Array3i first = ((low - origin_) / spacing).array().ceil().cast<int>().max(0);
    const Eigen::Array3i last =
        ((high - origin_) / spacing).array().floor().cast<int>().min(Eigen::Array3i(nx_ - 1, ny_ - 1, nz_ - 1));
    for (int k = first.z(); k <= last.z(); ++k)
      for (int j = first.y(); j <= last.y(); ++j)
        for (int i = first.x(); i <= last.x(); ++i) {
          const Vector3r p = position(i, j, k);
          Real& d = distances[index(i, j, k)];
          d = std::min(d, (p - closestOnTriangle(p, a, b, c)).norm());
        }
  }

  // Inside: nodes with an odd number of surface crossings below them along z. The column is moved off the
  // grid line by an irrational fraction of a spacing, so that it never passes exactly through an edge. Each
  // column tests the triangles whose xy box covers it.
  std::vector<std::vector<int>> columns(static_cast<size_t>(nx_) * ny_);
  for (size_t t = 0; t < triangles.size(); ++t) {
    Vector2r low = vertices[triangles[t][0]].head<2>(), high = low;
    for (int corner : triangles[t]) {
      low = low.cwiseMin(vertices[corner].head<2>());
      high = high.cwiseMax(vertices[corner].head<2>());
    }
    const int i0 = std::max(0, static_cast<int>(std::floor((low.x() - origin_.x()) / spacing)));
    const int j0 = std::max(0, static_cast<int>(std::floor((low.y() - origin_.y()) / spacing)));
    const int i1 = std::min(nx_ - 1, static_cast<int>(std::ceil((high.x() - origin_.x()) / spacing)));
    const int j1 = std::min(ny_ - 1, static_cast<int>(std::ceil((high.y() - origin_.y()) / spacing)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) columns[static_cast<size_t>(j) * nx_ + i].push_back(static_cast<int>(t));
  }
  const Vector2r offset = spacing * 1e-6 * Vector2r(std::sqrt(Real(2)), std::sqrt(Real(3)));
  std::vector<Real> crossings;
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const Vector2r column = position(i, j, 0).head<2>() + offset;
      crossings.clear();
      for (int t : columns[static_cast<size_t>(j) * nx_ + i]) {
        const Vector3r &a = vertices[triangles[t][0]], &b = vertices[triangles[t][1]], &c = vertices[triangles[t][2]];
        const Real wa = cross2(b.head<2>() - column, c.head<2>() - column);
        const Real wb = cross2(c.head<2>() - column, a.head<2>() - column);
        const Real wc = cross2(a.head<2>() - column, b.head<2>() - column);
        if ((wa < 0 || wb < 0 || wc < 0) && (wa > 0 || wb > 0 || wc > 0)) continue;
        const Real w = wa + wb + wc;
        if (w != 0) crossings.push_back((wa * a.z() + wb * b.z() + wc * c.z()) / w);
      }
      std::sort(crossings.begin(), crossings.end());
      size_t below = 0;
      for (int k = 0; k < nz_; ++k) {
        const Real z = position(i, j, k).z();
        while (below < crossings.size() && crossings[below] < z) ++below;
        if (below % 2 == 1) distances[index(i, j, k)] = -distances[index(i, j, k)];
      }
    }
  values_.assign(distances.begin(), distances.end());
}

Real SolidDistance::interpolated(const Vector3r& x, bool outsideOnly) const {
  const Vector3r u = (x - origin_) / spacing_;
  if (!(u.minCoeff() >= 0 && u.x() < nx_ - 1 && u.y() < ny_ - 1 && u.z() < nz_ - 1)) return band_;
  const int i = static_cast<int>(u.x()), j = static_cast<int>(u.y()), k = static_cast<int>(u.z());
  const Real fx = u.x() - i, fy = u.y() - j, fz = u.z() - k;
  auto lerp = [](Real p, Real q, Real f) { return p + (q - p) * f; };
  auto value = [&](int di, int dj, int dk) {
    const Real v = node(i + di, j + dj, k + dk);
    return outsideOnly ? std::max(v, Real(0)) : v;
  };
  const Real y0 = lerp(lerp(value(0, 0, 0), value(1, 0, 0), fx), lerp(value(0, 1, 0), value(1, 1, 0), fx), fy);
  const Real y1 = lerp(lerp(value(0, 0, 1), value(1, 0, 1), fx), lerp(value(0, 1, 1), value(1, 1, 1), fx), fy);
  return lerp(y0, y1, fz);
}

}  // namespace roundedmesh
