#include "pkg/engine/StopRules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pkg/common/Overloaded.hpp"

namespace roundedmesh {
namespace {

bool isFlat(const PartnerShape& shape) { return !std::holds_alternative<Sphere>(shape); }

// Where a point x is against a flat partner in `state` [m]: its signed distance from a Wall's plane (along the Wall's
// axis) or a Plane's (along its normal) or a Facet's (along the normal of its corners' order), and for a Box how far
// it lies outside (negative inside). Its sign changes when x crosses the face.
Real faceSide(const PartnerShape& shape, const BodyState& state, const Vector3r& x) {
  return std::visit(Overloaded{[&](const Wall& wall) { return x[wall.axis] - state.position[wall.axis]; },
                               [&](const Plane& plane) { return plane.normal.dot(x - plane.point); },
                               [&](const Facet& facet) {
                                 const std::array<Vector3r, 3> c = facetCorners(facet, state.position, state.orientation);
                                 return (c[1] - c[0]).cross(c[2] - c[0]).normalized().dot(x - c[0]);
                               },
                               [&](const Box& box) {
                                 const Vector3r local = state.orientation.conjugate() * (x - state.position);
                                 return (local.cwiseAbs() - box.halfExtents).maxCoeff();
                               },
                               [&](const Sphere&) { return Real(0); }},
                    shape);
}

// Whether a centre that moved from `from` (side `before`) to `to` (side `now`) went through the partner's face: a
// Wall's or a Plane's plane anywhere, a Facet's within its triangle, a Box's from outside to inside.
bool crossed(const PartnerShape& shape, const BodyState& state, const Vector3r& from, Real before, const Vector3r& to,
             Real now) {
  if (std::holds_alternative<Box>(shape)) return before > 0 && !(now > 0);
  if (!(before * now < 0)) return false;
  const Facet* facet = std::get_if<Facet>(&shape);
  if (!facet) return true;
  const std::array<Vector3r, 3> c = facetCorners(*facet, state.position, state.orientation);
  const Vector3r x = from + before / (before - now) * (to - from);  // where the segment meets the facet's plane
  const Vector3r n = (c[1] - c[0]).cross(c[2] - c[0]);
  for (int i = 0; i < 3; ++i)
    if ((c[(i + 1) % 3] - c[i]).cross(x - c[i]).dot(n) < 0) return false;
  return true;
}

const PartnerShape* partnerShape(const ContactModel& model, int index) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  return index < bodyCount ? nullptr : &model.partners[index - bodyCount].shape;
}

bool before(const PairRecord& a, const PairRecord& b) { return a.body < b.body || (a.body == b.body && a.other < b.other); }

}  // namespace

Real sideSize(const ContactModel& model, int index) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  if (index < bodyCount) return model.bodies[index].equivalentRadius;
  const PartnerShape& shape = model.partners[index - bodyCount].shape;
  if (const Sphere* sphere = std::get_if<Sphere>(&shape)) return sphere->radius;
  return kInfinity;
}

std::vector<StopReason> checkStopRules(const ContactModel& model, ContactData& data) {
  std::vector<StopReason> stops;
  std::vector<PairRecord>& records = data.pairRecords;
  const int pairCount = static_cast<int>(data.pairs.size());
  const int threads = model.options.resolvedThreads();
  records.resize(pairCount);
  // Each pair's record alone, in parallel (a Facet's side costs it its corners); the searches below in order.
#pragma omp parallel for num_threads(threads) schedule(static) if (pairCount > 1)
  for (int k = 0; k < pairCount; ++k) {
    const BodyPair& pair = data.pairs[k];
    PairRecord& r = records[k];
    r.body = pair.body;
    r.other = pair.other;
    const PairSummary& summary = data.pairResults[k].summary;
    r.overlap = summary.triangleContacts > 0 ? summary.depth : 0;
    r.position = data.state(pair.body).position;
    r.point = summary.triangleContacts > 0 ? summary.point : r.position;
    const BodyState &s1 = data.state(pair.body), &s2 = data.state(pair.other);
    auto velocityAt = [&](const BodyState& s) -> Vector3r { return s.velocity + s.angularVelocity.cross(r.point - s.position); };
    r.closing = (velocityAt(s1) - velocityAt(s2)).dot(summary.normal);
    const PartnerShape* shape = partnerShape(model, pair.other);
    r.flat = shape && isFlat(*shape);
    r.side = r.flat ? faceSide(*shape, data.state(pair.other), r.position) : 0;
  }
  // data.pairs follow the neighbour list's order, sorted by (body, other); kept for the search below.
  if (!data.kept) return stops;
  const std::vector<PairRecord>& last = data.keptRecords;
  for (const PairRecord& r : records) {
    const Real size = std::min(sideSize(model, r.body), sideSize(model, r.other));
    if (!(r.overlap > model.options.stopOverlap * size)) continue;
    const auto found = std::lower_bound(last.begin(), last.end(), r, before);
    const Real previous = found != last.end() && !before(r, *found) ? found->overlap : 0;
    if (r.overlap > previous && (r.flat || r.closing >= 0))
      stops.push_back({StopCause::Overlap, r.body, r.other, r.overlap, size, r.point});
  }
  // Every flat partner a body was near in the last step, whether or not their bounds still overlap.
  const int lastCount = static_cast<int>(last.size());
  std::vector<char> through(lastCount, 0);
#pragma omp parallel for num_threads(threads) schedule(static) if (lastCount > 1)
  for (int k = 0; k < lastCount; ++k) {
    const PairRecord& r = last[k];
    if (!r.flat) continue;
    const PartnerShape& shape = *partnerShape(model, r.other);
    const BodyState& partner = data.state(r.other);
    const Vector3r& now = data.state(r.body).position;
    through[k] = crossed(shape, partner, r.position, r.side, now, faceSide(shape, partner, now));
  }
  for (int k = 0; k < lastCount; ++k) {
    if (!through[k]) continue;
    const PairRecord& r = last[k];
    const auto found = std::lower_bound(records.begin(), records.end(), r, before);
    const bool touching = found != records.end() && !before(r, *found);
    stops.push_back({StopCause::CentreCrossed, r.body, r.other, touching ? found->overlap : 0, sideSize(model, r.body),
                     touching ? found->point : data.state(r.body).position});
  }
  // Crossings first, then the deepest overlap for its size.
  std::stable_sort(stops.begin(), stops.end(), [](const StopReason& a, const StopReason& b) {
    if (a.cause != b.cause) return a.cause == StopCause::CentreCrossed;
    return a.overlap / a.size > b.overlap / b.size;
  });
  return stops;
}

void commitStep(ContactData& data) {
  std::swap(data.keptRecords, data.pairRecords);
  data.kept = true;
}

FastBody fastestBody(const ContactModel& model, const ContactData& data, Real dt) {
  FastBody fastest;
  const int bodyCount = static_cast<int>(model.bodies.size());
  auto consider = [&](int index, Real speed) {
    const Real depth = kDeepestOverlap * sideSize(model, index);
    const Real fraction = speed * dt / depth;
    if (fraction > fastest.fraction) fastest = {index, speed, fraction, depth};
  };
  for (int b = 0; b < bodyCount; ++b) {
    if (data.residences[b] != Residence::Own) continue;  // another process reports it
    const BodyState& s = data.bodyStates[b];
    consider(b, s.velocity.norm() + s.angularVelocity.norm() * model.bodies[b].mesh->sphereBoundRadius());
  }
  // A sphere's turn does not move its surface toward anything.
  for (size_t p = 0; p < model.partners.size(); ++p)
    if (model.partners[p].sphereBody && data.residences[bodyCount + p] == Residence::Own)
      consider(bodyCount + static_cast<int>(p), data.partnerStates[p].velocity.norm());
  return fastest;
}

}  // namespace roundedmesh
