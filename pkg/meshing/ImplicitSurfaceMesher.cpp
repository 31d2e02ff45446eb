#include "pkg/meshing/ImplicitSurfaceMesher.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

constexpr int kMaxGridNodes = 256;  // per axis: 16.7 million values of f, 134 MB

Vector3r toVector(const Point& p) { return {p.x(), p.y(), p.z()}; }
Point toPoint(const Vector3r& v) { return {v.x(), v.y(), v.z()}; }

// Step 1: a fine, closed, manifold sample of the surface by marching tetrahedra on a cubic grid of the given
// spacing, each cube split into the six tetrahedra of Kuhn's triangulation (conforming across cubes, no
// ambiguous cases). Fully deterministic, unlike CGAL's surface mesher, whose output depends on memory
// addresses.
Mesh sampleSurface(const ImplicitSolid& solid, Real spacing) {
  const int n = static_cast<int>(std::ceil(2 * solid.boundingRadius / spacing)) + 1;
  if (n > kMaxGridNodes)
    throw std::invalid_argument("the sampling grid would need " + std::to_string(n) + " nodes along each axis (at " +
                                "most " + std::to_string(kMaxGridNodes) + "): ask for fewer nodes");
  const Vector3r origin = solid.inside - Vector3r::Constant(solid.boundingRadius);
  auto index = [n](int i, int j, int k) { return (std::int64_t(i) * n + j) * n + k; };
  auto position = [&](std::int64_t g) {
    return Vector3r(origin.x() + spacing * (g / (std::int64_t(n) * n)), origin.y() + spacing * ((g / n) % n),
                    origin.z() + spacing * (g % n));
  };
  std::vector<Real> value(std::size_t(n) * n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) value[index(i, j, k)] = solid.f(position(index(i, j, k)));

  Mesh mesh;
  std::map<std::pair<std::int64_t, std::int64_t>, Mesh::Vertex_index> onEdge;
  // The surface point on the grid edge between an inside and an outside node, kept off the nodes themselves
  // so that no triangle collapses.
  auto crossing = [&](std::int64_t inside, std::int64_t outside) {
    const auto key = std::make_pair(inside, outside);
    const auto found = onEdge.find(key);
    if (found != onEdge.end()) return found->second;
    const Real t = std::clamp(value[inside] / (value[inside] - value[outside]), Real(1e-3), Real(1 - 1e-3));
    const Mesh::Vertex_index v = mesh.add_vertex(toPoint((1 - t) * position(inside) + t * position(outside)));
    onEdge.emplace(key, v);
    return v;
  };
  auto addTriangle = [&](std::array<Mesh::Vertex_index, 3> t, const Vector3r& outward) {
    const Vector3r a = toVector(mesh.point(t[0])), b = toVector(mesh.point(t[1])), c = toVector(mesh.point(t[2]));
    if ((b - a).cross(c - a).dot(outward) < 0) std::swap(t[1], t[2]);
    mesh.add_face(t[0], t[1], t[2]);
  };
  constexpr int kKuhn[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j)
      for (int k = 0; k + 1 < n; ++k)
        for (const auto& path : kKuhn) {
          // Tetrahedron: cube corners 0, a, a + b, a + b + c (bits: 1 = +x, 2 = +y, 4 = +z).
          std::array<std::int64_t, 4> node;
          int corner = 0;
          for (int m = 0; m < 4; ++m) {
            if (m > 0) corner |= path[m - 1];
            node[m] = index(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
          }
          std::array<std::int64_t, 4> in, out;
          int inCount = 0, outCount = 0;
          for (std::int64_t g : node) value[g] < 0 ? in[inCount++] = g : out[outCount++] = g;
          if (inCount == 0 || outCount == 0) continue;
          Vector3r outward = Vector3r::Zero();
          for (int m = 0; m < outCount; ++m) outward += position(out[m]) / outCount;
          for (int m = 0; m < inCount; ++m) outward -= position(in[m]) / inCount;
          if (inCount == 1 || outCount == 1) {
            const auto& lone = inCount == 1 ? in : out;
            const auto& rest = inCount == 1 ? out : in;
            std::array<Mesh::Vertex_index, 3> t;
            for (int m = 0; m < 3; ++m) t[m] = inCount == 1 ? crossing(lone[0], rest[m]) : crossing(rest[m], lone[0]);
            addTriangle(t, outward);
          } else {
            const Mesh::Vertex_index p = crossing(in[0], out[0]), q = crossing(in[0], out[1]),
                                     r = crossing(in[1], out[1]), s = crossing(in[1], out[0]);
            addTriangle({p, q, r}, outward);
            addTriangle({p, r, s}, outward);
          }
        }
  if (mesh.number_of_faces() == 0)
    throw std::invalid_argument("the implicit surface was not found: is f negative inside and positive outside?");
  return mesh;
}

// Step 2: uniform edge length, nodes on the surface.
Mesh remesh(const Mesh& sample, const ImplicitSolid& solid, Real edgeLength) {
  Mesh mesh = sample;
  const auto onSurface = [&](Mesh::Vertex_index v) { return toPoint(projectOnSurface(solid, toVector(mesh.point(v)))); };
  PMP::isotropic_remeshing(faces(mesh), edgeLength, mesh,
                           CGAL::parameters::number_of_iterations(8).projection_functor(onSurface));
  mesh.collect_garbage();
  return mesh;
}

// Every node on the surface (remeshing projects only the nodes it moves or creates), checked like any input.
TriangleSurface toSurface(const Mesh& mesh, const ImplicitSolid& solid) {
  PolygonSoup soup;
  for (Mesh::Vertex_index v : mesh.vertices()) soup.points.push_back(projectOnSurface(solid, toVector(mesh.point(v))));
  for (Mesh::Face_index f : mesh.faces()) {
    std::vector<std::size_t> corners;
    for (Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(v);
    soup.polygons.push_back(std::move(corners));
  }
  return repairedSurface(soup);
}

}  // namespace

Vector3r projectOnSurface(const ImplicitSolid& solid, Vector3r x) {
  const Real step = 1e-7 * solid.boundingRadius;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Real value = solid.f(x);
    Vector3r gradient;
    for (int i = 0; i < 3; ++i) {
      const Vector3r dx = Vector3r::Unit(i) * step;
      gradient[i] = (solid.f(x + dx) - solid.f(x - dx)) / (2 * step);
    }
    const Vector3r move = value / gradient.squaredNorm() * gradient;
    x -= move;
    if (move.norm() < 1e-13 * solid.boundingRadius) break;
  }
  return x;
}

TriangleSurface meshImplicitSurface(const ImplicitSolid& solid, int nodes) {
  if (nodes < 12 || nodes > 50000)
    throw std::invalid_argument("nodes must be between 12 and 50000, got " + std::to_string(nodes));
  if (!(solid.thickness * 30 > solid.boundingRadius))
    throw std::invalid_argument("the solid is too thin for the mesher: thickness " + std::to_string(solid.thickness) +
                                " against a size of " + std::to_string(solid.boundingRadius));
  const Mesh coarse = sampleSurface(solid, std::min(solid.boundingRadius / 20, solid.thickness / 4));
  const Real area = PMP::area(coarse);
  Real edgeLength = std::sqrt(2 * area / (std::sqrt(3.0) * nodes));
  const Mesh sample = sampleSurface(solid, edgeLength / 2);
  Mesh best;
  for (int attempt = 0; attempt < 8; ++attempt) {
    Mesh mesh = remesh(sample, solid, edgeLength);
    const Real ratio = Real(mesh.number_of_vertices()) / nodes;
    if (best.is_empty() || std::abs(ratio - 1) < std::abs(Real(best.number_of_vertices()) / nodes - 1))
      best = std::move(mesh);
    if (std::abs(ratio - 1) < 0.02) break;
    edgeLength *= std::sqrt(ratio);
  }
  return toSurface(best, solid);
}

}  // namespace roundedmesh
