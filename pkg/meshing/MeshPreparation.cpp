#include "pkg/meshing/MeshPreparation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "pkg/meshing/SurfaceRemesher.hpp"
#include "pkg/shape/CapTolerance.hpp"
#include "pkg/shape/Curvature.hpp"

namespace roundedmesh {
namespace {

std::vector<Real> caps(const TriangleSurface& surface, Real maxRadius) {
  return capHeights(surface, contactRadii(meanCurvature(surface).triangles, maxRadius));
}

// The triangles whose caps are beyond maxCapHeight and their neighbours (sharing a vertex), and the median edge
// length among them [m].
std::pair<std::vector<bool>, Real> patchBeyond(const TriangleSurface& surface, const std::vector<Real>& heights,
                                              Real maxCapHeight) {
  std::vector<bool> nearTall(surface.vertices.size(), false);
  for (std::size_t t = 0; t < heights.size(); ++t)
    if (heights[t] > maxCapHeight)
      for (int v : surface.triangles[t]) nearTall[v] = true;
  std::vector<bool> selected(heights.size(), false);
  std::vector<Real> lengths;
  for (std::size_t t = 0; t < heights.size(); ++t) {
    const Triangle& c = surface.triangles[t];
    if (!(nearTall[c[0]] || nearTall[c[1]] || nearTall[c[2]])) continue;
    selected[t] = true;
    for (int i = 0; i < 3; ++i) lengths.push_back((surface.vertices[c[(i + 1) % 3]] - surface.vertices[c[i]]).norm());
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return {std::move(selected), lengths[lengths.size() / 2]};
}

}  // namespace

PreparedSurface surfaceWithinTolerance(const TriangleSurface& surface, Real maxRadius, Real maxCapHeight) {
  PreparedSurface prepared{surface};
  std::vector<Real> heights = caps(surface, maxRadius);
  for (int pass = 1; pass <= kMaxRemeshPasses; ++pass) {
    const Real tallest = *std::max_element(heights.begin(), heights.end());
    if (tallest <= maxCapHeight) break;
    auto [selected, edgeLength] = patchBeyond(prepared.surface, heights, maxCapHeight);
    edgeLength *= std::clamp(std::sqrt(maxCapHeight / tallest), Real(0.3), Real(0.8));
    TriangleSurface finer = remeshedSurface(prepared.surface, edgeLength, selected);
    if (finer.triangles.size() > kMaxRemeshTriangles) break;
    prepared = {std::move(finer), pass, edgeLength};
    heights = caps(prepared.surface, maxRadius);
  }
  return prepared;
}

}  // namespace roundedmesh
