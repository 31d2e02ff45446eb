#include "pkg/math/ConvexPolygon.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace roundedmesh {

ConvexPolygon ConvexPolygon::triangle(const Vector2r& a, const Vector2r& b, const Vector2r& c) {
  ConvexPolygon t;
  t.push(a);
  if (cross2(b - a, c - a) >= 0) {
    t.push(b);
    t.push(c);
  } else {
    t.push(c);
    t.push(b);
  }
  return t;
}

ConvexPolygon ConvexPolygon::rectangle(const Vector2r& centre, Real hx, Real hy) {
  ConvexPolygon r;
  r.push(centre + Vector2r(-hx, -hy));
  r.push(centre + Vector2r(hx, -hy));
  r.push(centre + Vector2r(hx, hy));
  r.push(centre + Vector2r(-hx, hy));
  return r;
}

void ConvexPolygon::overflow() { throw std::logic_error("ConvexPolygon: more than 10 corners"); }

Real ConvexPolygon::area() const {
  Real twice = 0;
  for (int i = 0; i < size_; ++i) twice += cross2(corners_[i], corners_[i + 1 < size_ ? i + 1 : 0]);
  return 0.5 * twice;
}

bool ConvexPolygon::contains(const Vector2r& p) const {
  if (empty()) return false;
  for (int i = 0; i < size_; ++i) {
    const Vector2r& a = corners_[i];
    const Vector2r& b = corners_[i + 1 < size_ ? i + 1 : 0];
    if (cross2(b - a, p - a) < 0) return false;
  }
  return true;
}

Vector2r ConvexPolygon::closestPoint(const Vector2r& p) const {
  // p lies outside exactly the edges it sees (negative side); the closest point is on one of them.
  Vector2r best = p;
  Real bestDistanceSq = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < size_; ++i) {
    const Vector2r& a = corners_[i];
    const Vector2r edge = corners_[i + 1 < size_ ? i + 1 : 0] - a;
    if (!(cross2(edge, p - a) < 0)) continue;
    const Real lengthSq = edge.squaredNorm();
    const Real t = lengthSq > 0 ? std::clamp((p - a).dot(edge) / lengthSq, Real(0), Real(1)) : Real(0);
    const Vector2r q = a + t * edge;
    const Real d = (p - q).squaredNorm();
    if (d < bestDistanceSq) {
      bestDistanceSq = d;
      best = q;
    }
  }
  return best;
}

ConvexPolygon ConvexPolygon::clippedBy(const Vector2r& a, const Vector2r& b) const {
  ConvexPolygon out;
  clipInto(a, b, out);
  return out;
}

void ConvexPolygon::clipInto(const Vector2r& a, const Vector2r& b, ConvexPolygon& out) const {
  out.size_ = 0;
  if (size_ == 0) return;
  const Vector2r direction = b - a;
  const Real first = cross2(direction, corners_[0] - a);
  Real sp = first;
  for (int i = 0; i < size_; ++i) {
    const bool last = i + 1 == size_;
    const Vector2r& p = corners_[i];
    const Vector2r& q = corners_[last ? 0 : i + 1];
    const Real sq = last ? first : cross2(direction, q - a);
    if (sp >= 0) out.push(p);
    // The edge crosses the line strictly: add the crossing point. Corners on the line are kept above,
    // so a crossing is only added between strictly opposite signs and never duplicates a corner.
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push(p + (sp / (sp - sq)) * (q - p));
    sp = sq;
  }
}

ConvexPolygon ConvexPolygon::intersection(const ConvexPolygon& clip) const {
  ConvexPolygon buffers[2];
  const ConvexPolygon* current = this;
  for (int i = 0; i < clip.size() && !current->empty(); ++i) {
    ConvexPolygon& next = buffers[i % 2];
    current->clipInto(clip[i], clip[i + 1 < clip.size() ? i + 1 : 0], next);
    current = &next;
  }
  return *current;
}

ConvexPolygon ConvexPolygon::clippedToSquare(Real h) const {
  const ConvexPolygon square = rectangle(Vector2r::Zero(), h, h);
  // Bit k: a corner lies beyond the square's edge k, where clipInto's side of it, cross2(edge, p - from), is not >= 0.
  // For the edges from (-h, -h), (h, -h), (h, h), (-h, h) that side is 2h (p_y + h), 2h (h - p_x), 2h (h - p_y),
  // 2h (p_x + h) (the other product is 0 times a finite number), and a sum or difference of two doubles has the sign
  // of the exact one: for finite corners these are clipInto's own tests (where the product underflows to 0, clipInto
  // keeps every corner as it is).
  auto beyond = [h](const ConvexPolygon& polygon) {
    unsigned edges = 0;
    for (int k = 0; k < polygon.size(); ++k) {
      const Vector2r& p = polygon[k];
      edges |= unsigned(!(p.y() >= -h)) | unsigned(!(p.x() <= h)) << 1 | unsigned(!(p.y() <= h)) << 2 |
               unsigned(!(p.x() >= -h)) << 3;
    }
    return edges;
  };
  ConvexPolygon buffers[2];
  int spare = 0;
  const ConvexPolygon* current = this;
  unsigned edges = beyond(*this);
  for (int edge = 0; edge < 4 && !current->empty(); ++edge) {
    if (!(edges >> edge & 1u)) continue;
    current->clipInto(square[edge], square[edge < 3 ? edge + 1 : 0], buffers[spare]);
    current = &buffers[spare];
    spare = 1 - spare;
    edges = beyond(*current);
  }
  return *current;
}

ConvexPolygon ConvexPolygon::translated(const Vector2r& offset) const {
  ConvexPolygon out = *this;
  for (int i = 0; i < size_; ++i) out.corners_[i] += offset;
  return out;
}

}  // namespace roundedmesh
