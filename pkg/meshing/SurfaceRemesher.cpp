#include "pkg/meshing/SurfaceRemesher.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

}  // namespace

TriangleSurface remeshedSurface(const TriangleSurface& surface, Real edgeLength, const std::vector<bool>& selected) {
  if (!(edgeLength > 0)) throw std::invalid_argument("edge length must be positive, got " + std::to_string(edgeLength));
  Mesh mesh;
  std::vector<Mesh::Vertex_index> index;
  for (const Vector3r& v : surface.vertices) index.push_back(mesh.add_vertex(Point(v.x(), v.y(), v.z())));
  std::vector<Mesh::Face_index> patch;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const Triangle& c = surface.triangles[t];
    const Mesh::Face_index f = mesh.add_face(index[c[0]], index[c[1]], index[c[2]]);
    if (selected.empty() || selected[t]) patch.push_back(f);
  }
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, kSharpAngle, sharp);
  PMP::isotropic_remeshing(patch, edgeLength, mesh,
                           CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(sharp));
  mesh.collect_garbage();
  PolygonSoup soup;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    soup.points.push_back(Vector3r(p.x(), p.y(), p.z()));
  }
  for (Mesh::Face_index f : mesh.faces()) {
    std::vector<std::size_t> corners;
    for (Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) corners.push_back(v);
    soup.polygons.push_back(std::move(corners));
  }
  return repairedSurface(soup);
}

TriangleSurface remeshedToNodes(const TriangleSurface& surface, int nodes) {
  if (nodes < 4 || nodes > 200000) throw std::invalid_argument("nodes must be in [4, 200000], got " + std::to_string(nodes));
  Real area = 0;
  for (Real a : triangleAreas(surface)) area += a;
  Real edgeLength = std::sqrt(2 * area / (std::sqrt(Real(3)) * nodes));
  TriangleSurface best;
  std::string failure;
  for (int attempt = 0; attempt < 4; ++attempt, edgeLength *= Real(0.97)) {
    TriangleSurface remeshed;
    try {
      remeshed = remeshedSurface(surface, edgeLength);
    } catch (const std::invalid_argument& e) {  // a collapse left a degenerate triangle: another length may not
      failure = e.what();
      continue;
    }
    const Real ratio = Real(remeshed.vertices.size()) / nodes;
    if (best.vertices.empty() || std::abs(ratio - 1) < std::abs(Real(best.vertices.size()) / nodes - 1))
      best = std::move(remeshed);
    if (std::abs(ratio - 1) <= 0.05) break;
    edgeLength *= std::sqrt(ratio);
  }
  if (best.vertices.empty())
    throw std::invalid_argument("remeshing to " + std::to_string(nodes) + " nodes failed at every edge length: " + failure);
  return best;
}

}  // namespace roundedmesh
