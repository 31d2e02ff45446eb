#include "pkg/shape/Cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace roundedmesh {
namespace {

struct Ring {
  std::vector<int> nodes;  // counter-clockwise about +z, the first at angle `offset`
  Real offset;
  Real angle(int i) const { return offset + 2 * M_PI * i / nodes.size(); }  // unwrapped past one turn
};

struct Layout {
  int around, along, capRings;  // nodes per hull ring, hull intervals along z, rings per cap
  int capRingNodes(int i) const { return std::max(3, int(std::lround(Real(around) * i / capRings))); }
  int nodeCount() const {
    int n = around * (along + 1) + 2;
    for (int i = 1; i < capRings; ++i) n += 2 * capRingNodes(i);
    return n;
  }
};

Layout layoutFor(Real radius, Real length, Real edge) {
  const Real rowSpacing = edge * std::sqrt(3.0) / 2;  // of equilateral triangles
  return {std::max(6, int(std::lround(2 * M_PI * radius / edge))), std::max(1, int(std::lround(length / rowSpacing))),
          std::max(1, int(std::lround(radius / rowSpacing)))};
}

Ring addRing(TriangleSurface& s, Real r, Real z, int count, Real offset) {
  Ring ring{std::vector<int>(count), offset};
  for (int i = 0; i < count; ++i) {
    ring.nodes[i] = static_cast<int>(s.vertices.size());
    const Real angle = ring.angle(i);
    s.vertices.emplace_back(r * std::cos(angle), r * std::sin(angle), z);
  }
  return ring;
}

// Which way is out: radially on the hull, along +z or -z on a cap.
struct Outward {
  Real capSide;  // 0 on the hull, +1 or -1 on the top or bottom cap
  Vector3r at(const Vector3r& x) const { return capSide == 0 ? Vector3r(x.x(), x.y(), 0) : Vector3r(0, 0, capSide); }
};

// Appends a triangle, turned so that its normal points out.
void addTriangle(TriangleSurface& s, Triangle t, const Outward& outward) {
  const Vector3r &a = s.vertices[t[0]], &b = s.vertices[t[1]], &c = s.vertices[t[2]];
  if ((b - a).cross(c - a).dot(outward.at((a + b + c) / 3)) < 0) std::swap(t[1], t[2]);
  s.triangles.push_back(t);
}

// Triangulates the band between two rings, always advancing on the ring whose next node comes first in angle.
void zip(TriangleSurface& s, const Ring& p, const Ring& q, const Outward& outward) {
  const int np = static_cast<int>(p.nodes.size()), nq = static_cast<int>(q.nodes.size());
  for (int i = 0, j = 0; i < np || j < nq;) {
    if (j == nq || (i < np && p.angle(i + 1) <= q.angle(j + 1))) {
      addTriangle(s, {p.nodes[i % np], p.nodes[(i + 1) % np], q.nodes[j % nq]}, outward);
      ++i;
    } else {
      addTriangle(s, {p.nodes[i % np], q.nodes[(j + 1) % nq], q.nodes[j % nq]}, outward);
      ++j;
    }
  }
}

void addCap(TriangleSurface& s, const Ring& rim, const Layout& layout, Real radius, Real z) {
  const Outward outward{z > 0 ? Real(1) : Real(-1)};
  Ring outer = rim;
  for (int i = layout.capRings - 1; i >= 1; --i) {
    const int count = layout.capRingNodes(i);
    const Ring inner = addRing(s, radius * i / layout.capRings, z, count, (i % 2) * M_PI / count);
    zip(s, outer, inner, outward);
    outer = inner;
  }
  const int centre = static_cast<int>(s.vertices.size());
  s.vertices.emplace_back(0, 0, z);
  for (std::size_t i = 0; i < outer.nodes.size(); ++i)
    addTriangle(s, {centre, outer.nodes[i], outer.nodes[(i + 1) % outer.nodes.size()]}, outward);
}

}  // namespace

TriangleSurface cylinderSurface(Real radius, Real length, int nodes) {
  if (!(std::isfinite(radius) && radius > 0 && std::isfinite(length) && length > 0))
    throw std::invalid_argument("cylinder radius and length must be positive and finite, got " +
                                std::to_string(radius) + ", " + std::to_string(length));
  if (nodes < 14) throw std::invalid_argument("nodes must be at least 14, got " + std::to_string(nodes));

  // Node count ~ area / (sqrt(3)/2 edge^2); the layouts are discrete, so scan edges around that estimate
  // and keep the layout whose count is nearest.
  const Real estimate = std::sqrt(4 * M_PI * radius * (length + radius) / (std::sqrt(3.0) * nodes));
  Layout layout = layoutFor(radius, length, estimate);
  for (int step = -100; step <= 100; ++step) {
    const Layout tried = layoutFor(radius, length, estimate * std::pow(2.0, step / 200.0));
    if (std::abs(tried.nodeCount() - nodes) < std::abs(layout.nodeCount() - nodes)) layout = tried;
  }

  TriangleSurface s;
  const Real half = length / 2;
  std::vector<Ring> hull;
  for (int j = 0; j <= layout.along; ++j) {
    const Real z = j == layout.along ? half : -half + length * j / layout.along;  // the rims exactly at +-half
    hull.push_back(addRing(s, radius, z, layout.around, (j % 2) * M_PI / layout.around));
  }
  for (int j = 0; j < layout.along; ++j) zip(s, hull[j], hull[j + 1], Outward{0});
  addCap(s, hull.front(), layout, radius, -half);
  addCap(s, hull.back(), layout, radius, half);
  return s;
}

namespace {

bool onCap(const Vector3r& normal) { return std::abs(normal.z()) > 0.5; }

}  // namespace

std::vector<Real> cylinderTriangleCurvatures(Real radius, const TriangleSurface& surface) {
  std::vector<Real> curvatures;
  curvatures.reserve(surface.triangles.size());
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t)
    curvatures.push_back(onCap(triangleNormal(surface, t)) ? 0 : 1 / (2 * radius));
  return curvatures;
}

std::vector<PrincipalCurvature> cylinderTrianglePrincipalCurvatures(Real radius, const TriangleSurface& surface) {
  std::vector<PrincipalCurvature> out;
  out.reserve(surface.triangles.size());
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
    const Vector3r n = triangleNormal(surface, t);
    const Vector3r around = Vector3r::UnitZ().cross(n);
    out.push_back(onCap(n) ? PrincipalCurvature::isotropic(0, n)
                           : principalCurvature(around * around.transpose() / (radius * around.squaredNorm()), n, n));
  }
  return out;
}

}  // namespace roundedmesh
