#include "pkg/meshing/SurfaceRepair.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "pkg/shape/MassProperties.hpp"
#include "pkg/shape/MeshTopology.hpp"

namespace roundedmesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// Names vertices in messages by their index in the input and their coordinates.
class VertexNames {
 public:
  VertexNames(const std::vector<Vector3r>& points, std::vector<std::size_t> inputIndex)
      : points_(points), inputIndex_(std::move(inputIndex)) {}
  std::string operator()(std::size_t v) const {
    std::ostringstream s;
    const Vector3r& x = points_[v];
    if (v < inputIndex_.size()) s << "vertex " << inputIndex_[v];
    else s << "the centre of a filled hole";
    s << " (" << x.x() << ", " << x.y() << ", " << x.z() << ")";
    return s.str();
  }

 private:
  const std::vector<Vector3r>& points_;
  std::vector<std::size_t> inputIndex_;
};

[[noreturn]] void reject(int count, const std::string& singular, const std::string& plural,
                         const std::string& where) {
  throw std::invalid_argument(std::to_string(count) + " " + (count == 1 ? singular : plural) + ", first " + where);
}

std::vector<std::size_t> identityIndex(std::size_t count) {
  std::vector<std::size_t> identity(count);
  for (std::size_t v = 0; v < count; ++v) identity[v] = v;
  return identity;
}

// Only vertices that a face uses matter: a stray point with a NaN is dropped like any unused vertex.
void requireFinite(const std::vector<Vector3r>& points, const std::vector<bool>& used) {
  int count = 0;
  std::size_t first = 0;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v] && !points[v].allFinite() && count++ == 0) first = v;
  if (count > 0)
    reject(count, "vertex with a non-finite coordinate", "vertices with non-finite coordinates",
           VertexNames(points, identityIndex(points.size()))(first));
}

std::vector<bool> usedVertices(const PolygonSoup& soup) {
  std::vector<bool> used(soup.points.size(), false);
  for (const auto& polygon : soup.polygons)
    for (std::size_t corner : polygon) used[corner] = true;
  return used;
}

void requireValidCorners(const PolygonSoup& soup) {
  for (std::size_t p = 0; p < soup.polygons.size(); ++p) {
    const auto& polygon = soup.polygons[p];
    if (polygon.size() < 3)
      throw std::invalid_argument("face " + std::to_string(p) + " has " + std::to_string(polygon.size()) +
                                  " corners; a face needs at least 3");
    for (std::size_t corner : polygon)
      if (corner >= soup.points.size())
        throw std::invalid_argument("face " + std::to_string(p) + " refers to vertex " + std::to_string(corner) +
                                    ", but there are " + std::to_string(soup.points.size()) + " vertices");
  }
}

// Welds vertices with identical coordinates and drops unused ones, keeping the input's order. Returns the
// surviving points, the input index of each, and the polygons renumbered (repeated corners removed).
struct Welded {
  std::vector<Vector3r> points;
  std::vector<std::size_t> inputIndex;
  std::vector<std::vector<std::size_t>> polygons;
};

Welded weld(const PolygonSoup& soup, const std::vector<bool>& used) {
  std::map<std::array<Real, 3>, std::size_t> byPosition;
  std::vector<std::size_t> renumbered(soup.points.size());
  Welded w;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (!used[v]) continue;
    const Vector3r& x = soup.points[v];
    const auto [it, inserted] = byPosition.emplace(std::array<Real, 3>{x.x(), x.y(), x.z()}, w.points.size());
    if (inserted) {
      w.points.push_back(x);
      w.inputIndex.push_back(v);
    }
    renumbered[v] = it->second;
  }
  // A face that ran through two vertices now welded into one loses the repeated corner.
  for (const auto& polygon : soup.polygons) {
    std::vector<std::size_t> corners;
    for (std::size_t corner : polygon)
      if (corners.empty() || corners.back() != renumbered[corner]) corners.push_back(renumbered[corner]);
    while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
    w.polygons.push_back(std::move(corners));
  }
  return w;
}

// Triangulates a face of more than three corners with CGAL's hole filling, which finds the triangulation
// of the closed polyline with the least area (also for non-planar and non-convex faces). A face left with
// fewer than three distinct corners after welding is degenerate.
void triangulate(const std::vector<std::size_t>& face, std::size_t faceIndex, const std::vector<Vector3r>& points,
                 TriangleSurface& out, std::vector<std::size_t>& faceOf) {
  if (face.size() < 3)
    throw std::invalid_argument("face " + std::to_string(faceIndex) + " is degenerate: it has " +
                                std::to_string(face.size()) + " distinct corners once duplicate vertices are welded");
  auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    out.triangles.push_back({static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)});
    faceOf.push_back(faceIndex);
  };
  if (face.size() == 3) return add(face[0], face[1], face[2]);
  std::vector<Kernel::Point_3> polyline;
  for (std::size_t corner : face) polyline.emplace_back(points[corner].x(), points[corner].y(), points[corner].z());
  std::vector<CGAL::Triple<int, int, int>> patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(patch));
  if (patch.size() != face.size() - 2)
    throw std::invalid_argument("face " + std::to_string(faceIndex) + " (" + std::to_string(face.size()) +
                                " corners) cannot be triangulated");
  for (const auto& t : patch) add(face[t.first], face[t.second], face[t.third]);
}

// faceOf: the input face each triangle comes from, for messages.
void requireNonDegenerate(const TriangleSurface& s, const VertexNames& name, const std::vector<std::size_t>& faceOf) {
  int count = 0;
  std::size_t first = 0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& corners = s.triangles[t];
    if (hasZeroArea(s.vertices[corners[0]], s.vertices[corners[1]], s.vertices[corners[2]]) && count++ == 0) first = t;
  }
  if (count > 0) {
    const Triangle& t = s.triangles[first];
    reject(count, "degenerate (zero-area) triangle", "degenerate (zero-area) triangles",
           "face " + std::to_string(faceOf[first]) + " at " + name(t[0]) + ", " + name(t[1]) + ", " + name(t[2]));
  }
}

void requireClosedManifoldOriented(const TriangleSurface& s, const VertexNames& name) {
  const EdgeDefects defects = findEdgeDefects(s.triangles);
  auto at = [&](const EdgeDefect& d) { return "at the edge from " + name(d.first[0]) + " to " + name(d.first[1]); };
  if (defects.boundary.count)
    reject(defects.boundary.count, "boundary edge (the surface is not closed)",
           "boundary edges (the surface is not closed)", at(defects.boundary));
  if (defects.nonManifold.count)
    reject(defects.nonManifold.count, "non-manifold edge (bordering more than two triangles)",
           "non-manifold edges (bordering more than two triangles)", at(defects.nonManifold));
  if (defects.misoriented.count)
    reject(defects.misoriented.count,
           "edge between triangles of opposite orientation (the surface is not consistently oriented)",
           "edges between triangles of opposite orientation (the surface is not consistently oriented)",
           at(defects.misoriented));
}

// Each connected component (triangles sharing vertices), in order of first triangle: its triangles and signed volume.
struct Component {
  std::vector<int> triangles;
  Real volume;
  int firstVertex;
};

std::vector<Component> components(const TriangleSurface& s) {
  std::vector<int> parent(s.vertices.size());
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const std::function<int(int)> root = [&](int v) { return parent[v] == v ? v : parent[v] = root(parent[v]); };
  for (const Triangle& t : s.triangles)
    for (int i = 1; i < 3; ++i) parent[root(t[i])] = root(t[0]);
  std::map<int, std::vector<int>> byRoot;
  std::vector<int> order;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    std::vector<int>& part = byRoot[root(s.triangles[t][0])];
    if (part.empty()) order.push_back(root(s.triangles[t][0]));
    part.push_back(static_cast<int>(t));
  }
  std::vector<Component> out;
  for (int r : order) {
    std::vector<Triangle> triangles;
    for (int t : byRoot[r]) triangles.push_back(s.triangles[t]);
    out.push_back({byRoot[r], massProperties(s.vertices, triangles).volume, triangles.front()[0]});
  }
  return out;
}

// The holes of a surface (its boundary edges, each bordering one triangle) closed where each is flat and star-shaped
// from its centroid (an open end cut square, as in YADE's examples/rod-penetration/rod-tiny.stl): a fan of triangles
// from the centroid of its corners to each boundary edge, run against the edge's triangle so that the fan agrees with
// it. A hole that is not a simple loop, not flat (farther than 1e-9 of its size from its plane) or not seen whole
// from its centroid is refused, naming it: closing it would mean inventing a surface.
void fillFlatHoles(TriangleSurface& s, const VertexNames& name) {
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // undirected edge -> (uses, the direction of the last)
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) {
      const int from = t[i], to = t[(i + 1) % 3];
      auto& use = edges[{std::min(from, to), std::max(from, to)}];
      ++use.first;
      use.second = from;
    }
  std::map<int, std::vector<int>> next;  // boundary vertex -> its boundary neighbours
  for (const auto& [edge, use] : edges)
    if (use.first == 1) {
      next[edge.first].push_back(edge.second);
      next[edge.second].push_back(edge.first);
    }
  std::map<int, bool> visited;
  for (const auto& [start, unused] : next) {
    if (visited[start]) continue;
    std::vector<int> loop{start};
    for (int previous = -1, at = start;;) {
      visited[at] = true;
      if (next[at].size() != 2)
        throw std::invalid_argument("a hole meets itself at " + name(at) + ": only simple holes can be filled");
      const int step = next[at][0] != previous ? next[at][0] : next[at][1];
      previous = at;
      at = step;
      if (at == start) break;
      loop.push_back(at);
    }
    Vector3r centre = Vector3r::Zero();
    for (int v : loop) centre += s.vertices[v] / loop.size();
    Matrix3r scatter = Matrix3r::Zero();
    Real size = 0;
    for (int v : loop) {
      scatter += (s.vertices[v] - centre) * (s.vertices[v] - centre).transpose();
      size = std::max(size, (s.vertices[v] - centre).norm());
    }
    const Vector3r normal = Eigen::SelfAdjointEigenSolver<Matrix3r>(scatter).eigenvectors().col(0);
    Real offPlane = 0;
    for (int v : loop) offPlane = std::max(offPlane, std::abs((s.vertices[v] - centre).dot(normal)));
    const std::string hole = "the hole of " + std::to_string(loop.size()) + " edges through " + name(start);
    if (offPlane > 1e-9 * size) {
      std::ostringstream message;
      message << hole << " is not flat (a corner " << offPlane << " m off its plane): only flat holes can be filled";
      throw std::invalid_argument(message.str());
    }
    const int middle = static_cast<int>(s.vertices.size());
    s.vertices.push_back(centre);
    Real turn = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      const Real side = (s.vertices[a] - centre).cross(s.vertices[b] - centre).dot(normal);
      if (!(std::abs(side) > 1e-12 * size * size) || side * turn < 0)
        throw std::invalid_argument(hole + " is not seen whole from its centroid: only flat holes shaped so can be filled");
      turn = side;
      const bool runsForward = edges[{std::min(a, b), std::max(a, b)}].second == a;
      s.triangles.push_back(runsForward ? Triangle{b, a, middle} : Triangle{a, b, middle});
    }
  }
}

// A closed, edge-manifold surface some of whose neighbouring triangles run the same way along their shared edge (STL
// writers often mix them): the triangles are turned to agree with CGAL's orient_polygon_soup, then every separate part
// outward, since a turned part's sense is arbitrary (a body's parts must all face out; a cavity is refused anyway).
// Only the order of corners changes, never a vertex. The surface is left as it is where there is nothing to turn or it
// cannot be done without splitting a vertex (a non-orientable or pinched surface): the checks then say why.
void orientConsistently(TriangleSurface& s) {
  const EdgeDefects defects = findEdgeDefects(s.triangles);
  if (defects.misoriented.count == 0 || defects.boundary.count > 0 || defects.nonManifold.count > 0) return;
  std::vector<Kernel::Point_3> points;
  for (const Vector3r& x : s.vertices) points.emplace_back(x.x(), x.y(), x.z());
  std::vector<std::vector<std::size_t>> polygons;
  for (const Triangle& t : s.triangles) polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  if (!CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons) || points.size() != s.vertices.size())
    return;
  for (std::size_t t = 0; t < polygons.size(); ++t)
    for (int i = 0; i < 3; ++i) s.triangles[t][i] = static_cast<int>(polygons[t][i]);
  for (const Component& part : components(s))
    if (part.volume < 0)
      for (int t : part.triangles) std::swap(s.triangles[t][1], s.triangles[t][2]);
}

// The enclosed volume, positive or negative (inside-out). Every connected component must turn the same
// way: a body made of pieces some of which are inside-out cannot be repaired safely (nor can a cavity
// be told from a piece turned inside-out).
Real enclosedVolume(const TriangleSurface& s, const VertexNames& name) {
  const std::vector<Component> parts = components(s);
  for (const Component& part : parts)
    if (part.volume * parts.front().volume < 0)
      throw std::invalid_argument("the surface has " + std::to_string(parts.size()) + " separate parts of opposite " +
                                  "orientation (inside-out pieces, or a cavity), first the part at " +
                                  name(part.firstVertex) + ": orient every part outward");
  const MassProperties mass = massProperties(s.vertices, s.triangles);
  const Real volume = mass.volume;
  // A closed surface folded flat encloses nothing; round-off alone stays far below 1e-9 of its box.
  if (!(std::abs(volume) > 1e-9 * boundingBox(s.vertices).volume()))
  {
    std::ostringstream message;
    message << "the surface encloses no volume (" << volume << " m^3): it is flat or folded onto itself";
    throw std::invalid_argument(message.str());
  }
  // A solid's principal moments are positive and each at most the sum of the other two (I_x + I_y - I_z is
  // twice the integral of z^2). A closed, consistently oriented surface that passes through itself counts
  // some regions negatively and can break either (found by fuzz/obj_reader_fuzzer, doc/reliability.md); its
  // mass properties would be meaningless. 1e-9 of the trace is far above round-off, far below any real body.
  const Vector3r moments = (volume > 0 ? 1 : -1) * Eigen::SelfAdjointEigenSolver<Matrix3r>(mass.inertia).eigenvalues();
  const Real tolerance = 1e-9 * std::abs(moments.sum());
  if (!(moments.minCoeff() > tolerance && moments.sum() - 2 * moments.maxCoeff() >= -tolerance)) {
    std::ostringstream message;
    message << "the surface intersects itself: its principal moments of inertia (" << moments.x() << ", "
            << moments.y() << ", " << moments.z() << ") m^5 are not those of a solid (each positive and at most the "
            << "sum of the other two)";
    throw std::invalid_argument(message.str());
  }
  return volume;
}

}  // namespace

TriangleSurface repairedSurface(const PolygonSoup& soup, const RepairOptions& options) {
  if (soup.points.empty() || soup.polygons.empty())
    throw std::invalid_argument("the mesh is empty (" + std::to_string(soup.points.size()) + " vertices, " +
                                std::to_string(soup.polygons.size()) + " faces)");
  requireValidCorners(soup);
  const std::vector<bool> used = usedVertices(soup);
  requireFinite(soup.points, used);
  Welded welded = weld(soup, used);
  TriangleSurface s;
  std::vector<std::size_t> faceOf;
  for (std::size_t f = 0; f < welded.polygons.size(); ++f) triangulate(welded.polygons[f], f, welded.points, s, faceOf);
  s.vertices = std::move(welded.points);
  const VertexNames name(s.vertices, std::move(welded.inputIndex));
  requireNonDegenerate(s, name, faceOf);
  if (options.fillFlatHoles) fillFlatHoles(s, name);
  orientConsistently(s);
  requireClosedManifoldOriented(s, name);
  if (enclosedVolume(s, name) < 0)
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}

void requireValidSurface(const TriangleSurface& surface) {
  const std::vector<bool> everyVertex(surface.vertices.size(), true);
  requireFinite(surface.vertices, everyVertex);
  const VertexNames name(surface.vertices, identityIndex(surface.vertices.size()));
  requireNonDegenerate(surface, name, identityIndex(surface.triangles.size()));
  requireClosedManifoldOriented(surface, name);
  if (enclosedVolume(surface, name) < 0)
    throw std::invalid_argument("the surface is inside-out: its triangles must run counter-clockwise seen from "
                                "outside");
}

}  // namespace roundedmesh
