#include "pkg/shape/InscribedSpheres.hpp"

#include <algorithm>
#include <limits>

#include "pkg/math/ClosestPoint.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {
namespace {

// The distance from x to the nearest triangle of the mesh [m], through its tree (whose boxes hold the triangles).
Real distanceToSurface(const RoundedMesh& mesh, const Vector3r& x) {
  Real best = std::numeric_limits<Real>::infinity();
  mesh.tree().query([&](const AlignedBox3r& box) { return box.squaredExteriorDistance(x) < best * best; },
                    [&](int t) {
                      const Triangle& c = mesh.triangles()[t];
                      const Vector3r& a = mesh.vertices()[c[0]];
                      best = std::min(best, (x - closestOnTriangle(x, a, mesh.vertices()[c[1]], mesh.vertices()[c[2]])).norm());
                    });
  return best;
}

}  // namespace

InscribedSpheres inscribedSpheres(const RoundedMesh& mesh) {
  const std::vector<Vector3r>& vertices = mesh.vertices();
  AlignedBox3r box;
  for (const Vector3r& v : vertices) box.extend(v);
  const Real spacing = box.sizes().maxCoeff() / InscribedSpheres::kCellsAcross;
  const Eigen::Array3i half = ((box.max() - box.center()) / spacing).array().floor().cast<int>();

  // Candidates: grid nodes inside the solid, each with its distance to the surface.
  std::vector<Vector3r> centres;
  std::vector<Real> radii;
  const SolidDistance& solid = mesh.solidDistance();
  for (int k = -half.z(); k <= half.z(); ++k)
    for (int j = -half.y(); j <= half.y(); ++j)
      for (int i = -half.x(); i <= half.x(); ++i) {
        const Vector3r x = box.center() + spacing * Vector3r(i, j, k);
        if (solid.at(x) > 0) continue;
        centres.push_back(x);
        radii.push_back(distanceToSurface(mesh, x));
      }
  InscribedSpheres out;
  if (centres.empty()) return out;
  const Real largest = *std::max_element(radii.begin(), radii.end());
  const Real minRadius = std::min(InscribedSpheres::kMinRadiusCells * spacing, largest / 2);
  size_t kept = 0;
  for (size_t c = 0; c < centres.size(); ++c)
    if (radii[c] >= minRadius) {
      centres[kept] = centres[c];
      radii[kept++] = radii[c];
    }
  centres.resize(kept);
  radii.resize(kept);

  // Surface samples: the vertices (a sixth of each triangle's area at each corner) and the centroids (half).
  std::vector<Vector3r> samples(vertices);
  std::vector<Real> weights(vertices.size(), 0);
  for (const Triangle& t : mesh.triangles()) {
    const Vector3r &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const Real area = 0.5 * (b - a).cross(c - a).norm();
    for (int corner : t) weights[corner] += area / 6;
    samples.push_back((a + b + c) / 3);
    weights.push_back(area / 2);
  }
  const size_t sampleCount = samples.size(), candidateCount = centres.size();
  auto gapOf = [&](size_t candidate, size_t sample) { return (samples[sample] - centres[candidate]).norm() - radii[candidate]; };
  std::vector<Real> floor(sampleCount, std::numeric_limits<Real>::infinity());
  for (size_t s = 0; s < sampleCount; ++s)
    for (size_t c = 0; c < candidateCount; ++c) floor[s] = std::min(floor[s], gapOf(c, s));

  std::vector<size_t> chosen{static_cast<size_t>(std::max_element(radii.begin(), radii.end()) - radii.begin())};
  std::vector<Real> gap(sampleCount);
  for (size_t s = 0; s < sampleCount; ++s) gap[s] = gapOf(chosen[0], s);
  std::vector<bool> taken(candidateCount, false);
  taken[chosen[0]] = true;
  while (static_cast<int>(chosen.size()) < InscribedSpheres::kMaxSpheres) {
    size_t target = 0;
    for (size_t s = 1; s < sampleCount; ++s)
      if (gap[s] - floor[s] > gap[target] - floor[target]) target = s;
    const Real excess = gap[target] - floor[target];
    if (!(excess > spacing / 2)) break;
    const Real tolerance = std::min(spacing, excess) / 2;
    Real nearest = std::numeric_limits<Real>::infinity();
    for (size_t c = 0; c < candidateCount; ++c) nearest = std::min(nearest, gapOf(c, target));
    size_t best = candidateCount;
    Real bestArea = -1;
    for (size_t c = 0; c < candidateCount; ++c) {
      if (taken[c] || gapOf(c, target) > nearest + tolerance) continue;
      Real area = 0;
      for (size_t s = 0; s < sampleCount; ++s)
        if (gap[s] - floor[s] > tolerance && gapOf(c, s) <= floor[s] + tolerance) area += weights[s];
      if (area > bestArea || (area == bestArea && radii[c] > radii[best])) {
        best = c;
        bestArea = area;
      }
    }
    if (best == candidateCount) break;
    chosen.push_back(best);
    taken[best] = true;
    for (size_t s = 0; s < sampleCount; ++s) gap[s] = std::min(gap[s], gapOf(best, s));
  }
  std::stable_sort(chosen.begin(), chosen.end(), [&](size_t a, size_t b) { return radii[a] > radii[b]; });
  for (size_t c : chosen) {
    out.centres.push_back(centres[c]);
    out.radii.push_back(radii[c]);
    out.reach = std::max(out.reach, centres[c].norm() + radii[c]);
    out.box.extend(centres[c] - Vector3r::Constant(radii[c]));
    out.box.extend(centres[c] + Vector3r::Constant(radii[c]));
  }
  return out;
}

}  // namespace roundedmesh
