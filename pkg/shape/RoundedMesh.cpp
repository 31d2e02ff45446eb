#include "pkg/shape/RoundedMesh.hpp"

#include "pkg/shape/TriangleSurface.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace roundedmesh {
namespace {

[[noreturn]] void reject(const std::string& message) { throw std::invalid_argument(message); }

std::string describe(const Vector3r& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

}  // namespace

RoundedMesh::RoundedMesh(std::vector<Vector3r> vertices, std::vector<Triangle> triangles,
                         const std::vector<Real>& radii, std::vector<PrincipalCurvature> principal)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), principal_(std::move(principal)) {
  if (vertices_.empty()) reject("vertices: the mesh has no vertices");
  if (triangles_.empty()) reject("triangles: the mesh has no triangles");
  if (radii.size() != triangles_.size())
    reject("radii: " + std::to_string(radii.size()) + " radii given for " + std::to_string(triangles_.size()) +
           " triangles");
  if (!principal_.empty() && principal_.size() != triangles_.size())
    reject("principal curvatures: " + std::to_string(principal_.size()) + " given for " +
           std::to_string(triangles_.size()) + " triangles");
  for (std::size_t t = 0; t < principal_.size(); ++t) {
    const PrincipalCurvature& k = principal_[t];
    if (!(std::isfinite(k.k1) && std::isfinite(k.k2) && k.k1 >= k.k2 && k.d1.allFinite() &&
          std::abs(k.d1.norm() - 1) < 1e-6))
      reject("principal curvatures of triangle " + std::to_string(t) +
             " must be finite, k1 >= k2, with a unit direction");
  }
  const int vertexCount = static_cast<int>(vertices_.size());
  for (int v = 0; v < vertexCount; ++v)
    if (!vertices_[v].allFinite()) reject("vertices: vertex " + std::to_string(v) + " is not finite");

  rounded_.resize(triangles_.size());
  std::vector<AlignedBox3r> boxes(triangles_.size());
  for (int t = 0; t < triangleCount(); ++t) {
    const Triangle& tri = triangles_[t];
    for (int corner : tri)
      if (corner < 0 || corner >= vertexCount)
        reject("triangles: triangle " + std::to_string(t) + " refers to vertex " + std::to_string(corner) +
               ", but there are " + std::to_string(vertexCount) + " vertices");
    if (!(std::isfinite(radii[t]) && radii[t] > 0))
      reject("radius of triangle " + std::to_string(t) + " must be positive and finite, got " +
             std::to_string(radii[t]));
    const Vector3r &a = vertices_[tri[0]], &b = vertices_[tri[1]], &c = vertices_[tri[2]];
    const Vector3r doubleAreaNormal = (b - a).cross(c - a);
    const Real doubleArea = doubleAreaNormal.norm();
    if (hasZeroArea(a, b, c))
      reject("triangles: triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
             std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ") has zero area, near " + describe(a));

    RoundedTriangle& r = rounded_[t];
    r.normal = doubleAreaNormal / doubleArea;
    r.area = 0.5 * doubleArea;
    r.circumcentre = circumcentre(a, b, c);
    r.circumradius = (a - r.circumcentre).norm();
    r.radius = std::max(radii[t], r.circumradius);
    const Real centreDepth = std::sqrt(std::max(r.radius * r.radius - r.circumradius * r.circumradius, Real(0)));
    r.sphereCentre = r.circumcentre - centreDepth * r.normal;
    r.capHeight = r.radius - centreDepth;
    maxCapHeight_ = std::max(maxCapHeight_, r.capHeight);
    AlignedBox3r& box = boxes[t];
    box.extend(a).extend(b).extend(c);
    box.min().array() -= r.capHeight;
    box.max().array() += r.capHeight;
    // Contact only ever involves the triangle's cap: the part of the sphere on the outer side of the
    // triangle's plane, which lies within the circumradius of the circumcentre (R >= circumradius).
    sphereBoundRadius_ = std::max(sphereBoundRadius_, std::min(r.sphereCentre.norm() + r.radius,
                                                               r.circumcentre.norm() + r.circumradius));
  }
  tree_ = TriangleTree(std::move(boxes));
  columns_ = triangleColumns(*this);
  if (principal_.empty())
    for (const RoundedTriangle& r : rounded_) principal_.push_back(PrincipalCurvature::isotropic(1 / r.radius, r.normal));
}

const SolidDistance& RoundedMesh::solidDistance() const {
  std::call_once(lazy_->distanceBuilt, [&] {
    Real meanCircumradius = 0;
    for (const RoundedTriangle& r : rounded_) meanCircumradius += r.circumradius / rounded_.size();
    AlignedBox3r box;
    for (const Vector3r& v : vertices_) box.extend(v);
    const Real extent = box.sizes().maxCoeff();
    const Real spacing = std::max(0.5 * meanCircumradius, 0.01 * extent);
    lazy_->distance = std::make_unique<const SolidDistance>(vertices_, triangles_, spacing,
                                                            4 * meanCircumradius + 2 * spacing);
  });
  return *lazy_->distance;
}

const InscribedSpheres& RoundedMesh::inscribedSpheres() const {
  std::call_once(lazy_->spheresBuilt, [&] { lazy_->spheres = roundedmesh::inscribedSpheres(*this); });
  return lazy_->spheres;
}

const TriangleExits& RoundedMesh::exits() const {
  std::call_once(lazy_->exitsBuilt, [&] { lazy_->exits = TriangleExits(*this, 0.1 * sphereBoundRadius_); });
  return lazy_->exits;
}

std::vector<Real> RoundedMesh::radii() const {
  std::vector<Real> out(rounded_.size());
  std::transform(rounded_.begin(), rounded_.end(), out.begin(), [](const RoundedTriangle& r) { return r.radius; });
  return out;
}

RoundedMesh RoundedMesh::transformed(const Matrix3r& rotation, const Vector3r& translation) const {
  std::vector<Vector3r> moved(vertices_.size());
  std::transform(vertices_.begin(), vertices_.end(), moved.begin(),
                 [&](const Vector3r& v) { return Vector3r(rotation * v + translation); });
  std::vector<PrincipalCurvature> principal = principal_;
  for (PrincipalCurvature& k : principal) k.d1 = rotation * k.d1;
  return RoundedMesh(std::move(moved), triangles_, radii(), std::move(principal));
}

}  // namespace roundedmesh
