#include "pkg/engine/BroadPhase.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "pkg/common/Overloaded.hpp"

namespace roundedmesh {
namespace {

AlignedBox3r ball(const Vector3r& centre, Real radius) {
  return AlignedBox3r(centre.array() - radius, centre.array() + radius);
}

// The world box of a partner: where a body must reach to touch it.
AlignedBox3r partnerBox(const PartnerShape& shape, const BodyState& state) {
  return std::visit(Overloaded{[&](const Plane&) { return AlignedBox3r(Vector3r::Constant(-kInfinity), Vector3r::Constant(kInfinity)); },
                               [&](const Wall& wall) {
                                 AlignedBox3r box(Vector3r::Constant(-kInfinity), Vector3r::Constant(kInfinity));
                                 box.min()[wall.axis] = box.max()[wall.axis] = state.position[wall.axis];
                                 return box;
                               },
                               [&](const Box& b) {
                                 return transformedBox(AlignedBox3r(-b.halfExtents, b.halfExtents),
                                                       state.orientation.toRotationMatrix(), state.position);
                               },
                               [&](const Facet& facet) {
                                 AlignedBox3r box;
                                 for (const Vector3r& x : facetCorners(facet, state.position, state.orientation)) box.extend(x);
                                 return box;
                               },
                               [&](const Sphere& sphere) { return ball(state.position, sphere.radius); }},
                    shape);
}

// The grown world boxes the neighbour list is built from and checked against.
AlignedBox3r grown(const AlignedBox3r& box, Real margin) {
  return AlignedBox3r(box.min().array() - margin, box.max().array() + margin);
}

// Sweep and prune of the grown boxes along the axis on which the bodies spread most -> data.neighbours, sorted,
// each keeping the candidate list it had if it was a neighbour before.
void rebuildNeighbours(const ContactModel& model, ContactData& data, const std::vector<AlignedBox3r>& boxes, Real margin) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const int count = static_cast<int>(boxes.size());
  data.neighbourBoxes.resize(count);
  for (int i = 0; i < count; ++i) data.neighbourBoxes[i] = grown(boxes[i], margin);
  const std::vector<AlignedBox3r>& grownBoxes = data.neighbourBoxes;
  Vector3r mean = Vector3r::Zero(), meanSq = Vector3r::Zero();
  for (int b = 0; b < bodyCount; ++b) {
    const Vector3r& x = data.bodyStates[b].position;
    mean += x;
    meanSq += x.cwiseProduct(x);
  }
  int movers = bodyCount;
  for (int p = 0; p < count - bodyCount; ++p)
    if (model.partners[p].sphereBody) {
      const Vector3r& x = data.partnerStates[p].position;
      mean += x;
      meanSq += x.cwiseProduct(x);
      ++movers;
    }
  int axis;
  (meanSq * movers - mean.cwiseProduct(mean)).maxCoeff(&axis);

  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const Real a = grownBoxes[i].min()[axis], b = grownBoxes[j].min()[axis];
    return a < b || (a == b && i < j);
  });
  std::vector<BodyPair> neighbours;
  for (int k = 0; k < count; ++k) {
    const int i = order[k];
    for (int l = k + 1; l < count && grownBoxes[order[l]].min()[axis] <= grownBoxes[i].max()[axis]; ++l) {
      const int j = order[l];
      if (!grownBoxes[i].intersects(grownBoxes[j])) continue;
      if (i < bodyCount || j < bodyCount) {
        neighbours.push_back({std::min(i, j), std::max(i, j)});
      } else if (model.partners[i - bodyCount].sphereBody || model.partners[j - bodyCount].sphereBody) {
        // Two partners meet through the engine only if one is a sphere body, which goes first.
        const bool iFirst = model.partners[i - bodyCount].sphereBody && (i < j || !model.partners[j - bodyCount].sphereBody);
        neighbours.push_back(iFirst ? BodyPair{i, j} : BodyPair{j, i});
      }
    }
  }
  // Sorted, so that the pairs and the sums over them do not depend on how the sweep met them.
  auto before = [](const BodyPair& a, const BodyPair& b) { return a.body < b.body || (a.body == b.body && a.other < b.other); };
  std::sort(neighbours.begin(), neighbours.end(), before);
  std::vector<CandidateList> lists(neighbours.size());
  std::vector<TangentialSpring> springs(neighbours.size());
  size_t old = 0;
  for (size_t n = 0; n < neighbours.size(); ++n) {
    neighbours[n].neighbour = static_cast<int>(n);
    while (old < data.neighbours.size() && before(data.neighbours[old], neighbours[n])) ++old;
    if (old < data.neighbours.size() && !before(neighbours[n], data.neighbours[old])) {
      lists[n] = std::move(data.candidateLists[old]);
      springs[n] = data.springs[old];
    }
  }
  // Springs restored from a saved scene (ContactData::restoreSprings) go to their pairs, seen from the pair's side.
  if (!data.restoredSprings.empty()) {
    auto find = [&](int body, int other) {
      const auto it = std::lower_bound(data.restoredSprings.begin(), data.restoredSprings.end(), BodyPair{body, other},
                                       [&](const auto& entry, const BodyPair& key) { return before(entry.first, key); });
      return it != data.restoredSprings.end() && it->first.body == body && it->first.other == other ? &it->second
                                                                                                    : nullptr;
    };
    for (size_t n = 0; n < neighbours.size(); ++n) {
      if (const TangentialSpring* same = find(neighbours[n].body, neighbours[n].other)) {
        springs[n] = *same;
      } else if (const TangentialSpring* reversed = find(neighbours[n].other, neighbours[n].body)) {
        springs[n] = *reversed;
        springs[n].displacement = -reversed->displacement;
        springs[n].twist = -reversed->twist;
        springs[n].normal = -reversed->normal;
      }
    }
    data.restoredSprings.clear();
  }
  data.neighbours = std::move(neighbours);
  data.candidateLists = std::move(lists);
  data.springs = std::move(springs);
}

}  // namespace

void broadPhase(const ContactModel& model, ContactData& data) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const int count = bodyCount + static_cast<int>(model.partners.size());
  std::vector<AlignedBox3r>& boxes = data.boxes;
  boxes.resize(count);
  Real smallest = kInfinity;
  // A body absent from this process (under yade.mpy) has an empty box: it is no one's neighbour.
  for (int b = 0; b < bodyCount; ++b) {
    boxes[b] = data.present(b) ? ball(data.bodyStates[b].position, model.bodies[b].mesh->sphereBoundRadius())
                               : AlignedBox3r();
    smallest = std::min(smallest, model.bodies[b].equivalentRadius);
  }
  for (int p = 0; p < count - bodyCount; ++p) {
    boxes[bodyCount + p] =
        data.present(bodyCount + p) ? partnerBox(model.partners[p].shape, data.partnerStates[p]) : AlignedBox3r();
    if (model.partners[p].sphereBody) smallest = std::min(smallest, std::get<Sphere>(model.partners[p].shape).radius);
  }
  bool current = static_cast<int>(data.neighbourBoxes.size()) == count;
  for (int i = 0; current && i < count; ++i) current = data.neighbourBoxes[i].contains(boxes[i]);
  if (!current) {
    rebuildNeighbours(model, data, boxes, 0.5 * model.skins.neighbours * smallest);
    ++data.statistics.neighbourRebuilds;
  }
  data.pairs.clear();
  for (const BodyPair& pair : data.neighbours) {
    const int clump = data.clump(pair.body);
    const int otherClump = data.clump(pair.other);
    const bool apart =
        !data.computesPair(pair.body, pair.other) || (clump >= 0 && clump == otherClump) ||
        !boxes[pair.body].intersects(boxes[pair.other]) ||
        (pair.other < bodyCount &&
         (data.bodyStates[pair.body].position - data.bodyStates[pair.other].position).norm() >=
             model.bodies[pair.body].mesh->sphereBoundRadius() + model.bodies[pair.other].mesh->sphereBoundRadius());
    if (apart) {
      // Not touching, or another process's: the pair's spring is forgotten (it had let go in the step the pair
      // stopped touching).
      data.springs[pair.neighbour] = TangentialSpring();
      continue;
    }
    data.pairs.push_back(pair);
  }
}

}  // namespace roundedmesh
