#include "pkg/shape/Curvature.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace roundedmesh {
namespace {

// Cotangents of the angles at the three corners.
std::array<Real, 3> cotangents(const std::array<Vector3r, 3>& x) {
  const Real doubleArea = (x[1] - x[0]).cross(x[2] - x[0]).norm();
  std::array<Real, 3> cot;
  for (int i = 0; i < 3; ++i) cot[i] = (x[(i + 1) % 3] - x[i]).dot(x[(i + 2) % 3] - x[i]) / doubleArea;
  return cot;
}

}  // namespace

std::array<Real, 3> mixedVoronoiShares(const std::array<Vector3r, 3>& x) {
  const std::array<Real, 3> cot = cotangents(x);
  const Real area = (x[1] - x[0]).cross(x[2] - x[0]).norm() / 2;
  std::array<Real, 3> shares;
  for (int i = 0; i < 3; ++i)
    if (cot[i] < 0) {
      shares.fill(area / 4);
      shares[i] = area / 2;
      return shares;
    }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    shares[i] = ((x[i] - x[k]).squaredNorm() * cot[j] + (x[i] - x[j]).squaredNorm() * cot[k]) / 8;
  }
  return shares;
}

MeanCurvature meanCurvature(const TriangleSurface& surface) {
  const std::size_t nodeCount = surface.vertices.size();
  std::vector<Vector3r> laplacian(nodeCount, Vector3r::Zero()), normals(nodeCount, Vector3r::Zero());
  std::vector<Real> voronoiArea(nodeCount, 0);
  std::vector<std::array<Real, 3>> shares(surface.triangles.size());

  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const Triangle& corners = surface.triangles[t];
    const std::array<Vector3r, 3> x = {surface.vertices[corners[0]], surface.vertices[corners[1]],
                                       surface.vertices[corners[2]]};
    const Vector3r doubleAreaNormal = (x[1] - x[0]).cross(x[2] - x[0]);
    const std::array<Real, 3> cot = cotangents(x);
    shares[t] = mixedVoronoiShares(x);
    for (int i = 0; i < 3; ++i) {
      // The edge opposite corner i joins j and k; its weight is the cotangent of the angle at i.
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      laplacian[corners[j]] += cot[i] * (x[j] - x[k]);
      laplacian[corners[k]] += cot[i] * (x[k] - x[j]);
      voronoiArea[corners[i]] += shares[t][i];
      normals[corners[i]] += doubleAreaNormal;
    }
  }

  MeanCurvature h;
  h.nodes.resize(nodeCount, 0);
  for (std::size_t i = 0; i < nodeCount; ++i) {
    if (voronoiArea[i] == 0) continue;  // a vertex no triangle uses
    const Vector3r K = laplacian[i] / (2 * voronoiArea[i]);
    h.nodes[i] = std::copysign(K.norm() / 2, K.dot(normals[i]));
  }
  h.triangles.resize(surface.triangles.size());
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    Real weighted = 0, total = 0;
    for (int i = 0; i < 3; ++i) {
      weighted += shares[t][i] * h.nodes[surface.triangles[t][i]];
      total += shares[t][i];
    }
    h.triangles[t] = weighted / total;
  }
  return h;
}

std::vector<Real> contactRadii(const std::vector<Real>& meanCurvatures, Real maxRadius) {
  if (!(std::isfinite(maxRadius) && maxRadius > 0))
    throw std::invalid_argument("max_radius must be positive and finite, got " + std::to_string(maxRadius));
  std::vector<Real> radii;
  radii.reserve(meanCurvatures.size());
  for (std::size_t t = 0; t < meanCurvatures.size(); ++t) {
    const Real H = meanCurvatures[t];
    if (std::isnan(H)) throw std::invalid_argument("curvature of triangle " + std::to_string(t) + " is NaN");
    radii.push_back(H * maxRadius > 1 ? 1 / H : maxRadius);
  }
  return radii;
}

}  // namespace roundedmesh
