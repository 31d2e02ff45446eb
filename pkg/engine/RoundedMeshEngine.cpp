#include "pkg/engine/RoundedMeshEngine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <omp.h>

#include "pkg/common/Overloaded.hpp"
#include "pkg/engine/SpherePair.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Sphere_PressureGeom.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
// Passes of one pair's evaluation while its deepest contact outgrows its list. A pair within the Hertz range grows
// its list's depth by half per pass; one past it takes a list as deep as the bodies (deepestPossible) at once.
constexpr int kDeepeningPasses = 8;

// The deepest effective overlap a triangle pair of these bodies can have and pass the deep-contact criterion
// (DeepContactCriterion.hpp): its surface points q1, q2 both lie within each body's solid, up to the criterion's
// tolerance, so |q1 - q2| is at most the diameter of the ball that holds the smaller one.
Real deepestPossible(const RoundedMesh& a, const RoundedMesh& b) {
  auto reach = [](const RoundedMesh& m) {
    return m.sphereBoundRadius() + m.maxCapHeight() + m.solidDistance().tolerance();
  };
  return 2 * std::min(reach(a), reach(b));
}

// Ig2 of a body against a plane given in the global frame.
void planeGeometry(const RoundedMesh& mesh, const Plane& global, const BodyState& body, const Matrix3r& toBody,
                   const RelativeMotion& motion, const GeomOutput& out, CurvatureModel curvature) {
  Ig2_RoundedMesh_Plane_PressureGeom(mesh, Plane{toBody * (global.point - body.position), toBody * global.normal},
                                     motion, out, curvature);
}

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

// How far a point of body 2 may have moved relative to body 1 between two of its poses in body 1's frame:
// the offset plus the turn times its bound radius (|R - R0| = 2 |vec(q0^-1 q)|).
Real motionBound(const Quaternionr& fromRotation, const Vector3r& fromTranslation, const Quaternionr& rotation,
                 const Vector3r& translation, Real boundRadius) {
  return (translation - fromTranslation).norm() + 2 * (fromRotation.conjugate() * rotation).vec().norm() * boundRadius;
}

// The candidate list of two rounded bodies, brought up to date for body 2's pose in body 1's frame. Within the
// Hertz range a list holds contacts 1.5 times as deep as the pair's deepest one at its last evaluation, plus two
// skins: contacts deepen continuously, so the list grows with them (a new list holds `shallow`, the deepest contact
// meant to be Hertzian). A pair past it holds every contact it can have, `full` deep (deepestPossible): the
// deep-contact criterion can accept a pair much deeper than the others at once (a segment through both bodies at
// a slant), which a list grown from the deepest one would miss. A list is rebuilt when it was never built, when
// body 2 may have moved by more than the skin since, when the deepest contact comes within a skin of the depth it
// holds or passes the Hertz range, or when it holds more than twice the depth needed (a pair that has come apart).
// The new skin follows the pair's motion per step (ListSkins); the near list it is taken from is searched again
// only when it no longer covers the new one.
void updateCandidates(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Quaternionr& rotation,
                      const Matrix3r& matrix, const Vector3r& translation, const ListSkins& skins, Real radius,
                      Real shallow, Real full, CandidateList& list, ContactStatistics& statistics) {
  const Real bound = mesh2.sphereBoundRadius();
  auto needed = [&](Real skin) { return list.deepest > shallow ? full : 1.5 * list.deepest + 2 * skin; };
  Real skin = skins.candidatesMin * radius, depth = shallow;
  if (list.built) {
    ++list.age;
    const Real motion = motionBound(list.rotation, list.translation, rotation, translation, bound);
    if (motion <= list.skin && list.deepest <= list.depth - list.skin && list.depth <= 2 * needed(list.skin) &&
        (list.deepest <= shallow || list.depth >= full))
      return;
    skin = std::clamp(skins.candidateSteps * motion / list.age, skin, skins.candidatesMax * radius);
    depth = needed(skin);
  }
  const bool nearCovers = list.nearSkin > 0 && depth <= list.nearDepth &&
                          motionBound(list.nearRotation, list.nearTranslation, rotation, translation, bound) + skin <=
                              list.nearSkin;
  if (!nearCovers) {
    list.nearRotation = rotation;
    list.nearTranslation = translation;
    list.nearSkin = skins.nearFactor * skin;
    list.nearDepth = depth + list.nearSkin;
    nearTrianglePairs(mesh1, mesh2, matrix, translation, list.nearSkin, list.nearDepth, shallow, list.near);
    ++statistics.nearRebuilds;
  }
  list.built = true;
  list.skin = skin;
  list.depth = depth;
  list.age = 0;
  list.rotation = rotation;
  list.translation = translation;
  touchableTrianglePairs(mesh1, mesh2, matrix, translation, skin, depth, list.near, list.pairs);
  ++statistics.candidateRebuilds;
}

// Ig2 of body 1's triangles against the other side, in body 1's frame (origin at its position).
void contactGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                     const RelativeMotion& motion, CandidateList* candidates, std::vector<PressureGeom>& geoms,
                     ContactStatistics& statistics) {
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const Matrix3r toBody = s1.orientation.toRotationMatrix().transpose();
  auto local = [&](const Vector3r& x) -> Vector3r { return toBody * (x - s1.position); };
  const GeomOutput out(geoms, &statistics.narrowPhase);
  const CurvatureModel curvature = model.pressure.curvature;
  const int bodyCount = static_cast<int>(model.bodies.size());
  if (pair.other < bodyCount) {
    const BodyState& s2 = data.bodyStates[pair.other];
    const RoundedBody& other = model.bodies[pair.other];
    const Real smaller = std::min(body.equivalentRadius, other.equivalentRadius);
    const Quaternionr rotation = s1.orientation.conjugate() * s2.orientation;
    const Matrix3r matrix = rotation.toRotationMatrix();
    const Vector3r translation = local(s2.position);
    CandidateList fresh;
    CandidateList& list = candidates ? *candidates : fresh;
    const Real shallow = kDeepestOverlap * smaller;
    // A contact deeper than its list holds may have neighbours deeper still that the list missed: the list grows
    // with it and the pair is evaluated again (a pair past the Hertz range takes a list of every contact it can
    // have, in one more pass).
    Real full = 0;  // deepestPossible, found when first needed (it builds the bodies' distance fields)
    auto fullDepth = [&]() {
      if (full == 0) full = deepestPossible(*body.mesh, *other.mesh);
      return full;
    };
    for (int pass = 0;; ++pass) {
      updateCandidates(*body.mesh, *other.mesh, rotation, matrix, translation, model.skins, smaller, shallow,
                       list.deepest > shallow ? fullDepth() : shallow, list, statistics);
      NarrowPhaseCounts counts;
      geoms.clear();
      Ig2_RoundedMesh_RoundedMesh_PressureGeom(*body.mesh, *other.mesh, matrix, translation, list.pairs, shallow,
                                               motion, GeomOutput(geoms, &counts), curvature);
      list.deepest = 0;
      for (const PressureGeom& geom : geoms) list.deepest = std::max(list.deepest, geom.effectiveOverlap);
      const bool complete =
          list.deepest <= list.depth - list.skin && (list.deepest <= shallow || list.depth >= fullDepth());
      if (complete || pass == kDeepeningPasses) {
        statistics.narrowPhase += counts;
        return;
      }
    }
  }
  const BodyState& s2 = data.partnerStates[pair.other - bodyCount];
  const PartnerShape& shape = model.partners[pair.other - bodyCount].shape;
  std::visit(Overloaded{[&](const Box& box) {
                          Ig2_RoundedMesh_Box_PressureGeom(*body.mesh, box, local(s2.position),
                                                           toBody * s2.orientation.toRotationMatrix(), motion, out,
                                                           curvature);
                        },
                        [&](const Facet& facet) {
                          std::array<Vector3r, 3> corners = facetCorners(facet, s2.position, s2.orientation);
                          for (Vector3r& x : corners) x = local(x);
                          Ig2_RoundedMesh_Facet_PressureGeom(*body.mesh, corners, motion, out, curvature);
                        },
                        [&](const Sphere& sphere) {
                          Ig2_RoundedMesh_Sphere_PressureGeom(
                              *body.mesh, sphere, local(s2.position), motion, out, curvature,
                              kDeepestOverlap * std::min(body.equivalentRadius, sphere.radius));
                        },
                        [&](const Plane& plane) { planeGeometry(*body.mesh, plane, s1, toBody, motion, out, curvature); },
                        [&](const Wall& wall) {
                          planeGeometry(*body.mesh, wallPlane(wall, s2.position, s1.position), s1, toBody, motion, out,
                                        curvature);
                        }},
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
  for (int b = 0; b < bodyCount; ++b) {
    boxes[b] = ball(data.bodyStates[b].position, model.bodies[b].mesh->sphereBoundRadius());
    smallest = std::min(smallest, model.bodies[b].equivalentRadius);
  }
  for (int p = 0; p < count - bodyCount; ++p) {
    boxes[bodyCount + p] = partnerBox(model.partners[p].shape, data.partnerStates[p]);
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
        (clump >= 0 && clump == otherClump) || !boxes[pair.body].intersects(boxes[pair.other]) ||
        (pair.other < bodyCount &&
         (data.bodyStates[pair.body].position - data.bodyStates[pair.other].position).norm() >=
             model.bodies[pair.body].mesh->sphereBoundRadius() + model.bodies[pair.other].mesh->sphereBoundRadius());
    if (apart) {
      // Not touching: the pair's spring is forgotten (it had let go in the step the pair stopped touching).
      data.springs[pair.neighbour] = TangentialSpring();
      continue;
    }
    data.pairs.push_back(pair);
  }
}

RelativeMotion relativeMotion(const BodyState& s1, const BodyState& s2, const Matrix3r& toBody) {
  RelativeMotion motion;
  motion.linear = toBody * (s2.velocity - s1.velocity + s2.angularVelocity.cross(s1.position - s2.position));
  motion.angular = toBody * (s2.angularVelocity - s1.angularVelocity);
  return motion;
}

Wrench reaction(const Wrench& onBody, const Vector3r& bodyPosition, const Vector3r& otherPosition) {
  return {-onBody.force, -onBody.torque + (otherPosition - bodyPosition).cross(onBody.force)};
}

void pairGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                  std::vector<PressureGeom>& geoms, ContactStatistics& statistics, CandidateList* candidates) {
  const BodyState& s1 = data.bodyStates[pair.body];
  const RelativeMotion motion = relativeMotion(s1, data.state(pair.other), s1.orientation.toRotationMatrix().transpose());
  geoms.clear();
  contactGeometry(model, data, pair, motion, candidates, geoms, statistics);
  ++statistics.bodyPairs;
  if (!geoms.empty()) ++statistics.touchingPairs;
}

namespace {

// One triangle contact's normal load and where it acts (body 1's frame), kept while the pair's friction is found.
struct ContactShare {
  NormalLoad load;
  Vector3r point;  // where Fn acts: c + (-Mn_y, Mn_x) / Fn, or c_eff if Fn = 0
};

// The viscous friction of the paper (FrictionLaw::Viscous, CoulombFriction.hpp) on each triangle contact at c_eff,
// the circle fractions shared out so that they sum to 1 over the pair: adds it to `local` (body 1's frame) and to
// the summary, and each triangle's to `listed` (global frame).
void viscousFriction(const std::vector<PressureGeom>& geoms, const std::vector<ContactShare>& shares,
                     const HertzPhys& phys, const Matrix3r& toGlobal, Wrench& local, PairResult& result,
                     TriangleContact* listed) {
  thread_local std::vector<Real> fraction;
  fraction.resize(geoms.size());
  Real fractions = 0;
  for (size_t k = 0; k < geoms.size(); ++k) fractions += fraction[k] = circleFraction(geoms[k]);
  for (size_t k = 0; k < geoms.size(); ++k) {
    const PressureGeom& geom = geoms[k];
    const TangentialLoad friction =
        coulombFriction(geom, shares[k].load, phys, fractions > 0 ? fraction[k] / fractions : 0);
    const Vector3r point = planePoint(geom, geom.effectivePoint);
    local.force -= friction.force;
    local.torque -= point.cross(friction.force);
    result.summary.frictionPower -= friction.force.dot(geom.slip);
    if (friction.sliding) {
      ++result.statistics.slidingContacts;
      result.summary.sliding = true;
    }
    if (listed) listed[k].friction = {toGlobal * friction.force, friction.sliding};
  }
}

// The pair's tangential spring (FrictionLaw::Spring, TangentialSpring.hpp) at the centre of pressure `centre` with
// normal `normal` (body 1's frame): brings `spring` to this step, adds its load to `local` and the summary, and
// each triangle contact's share to `listed` (global frame).
void springFriction(const std::vector<ContactShare>& shares, Real normalForce, Real normalStiffness,
                    const Vector3r& centre, const Vector3r& normal, const RelativeMotion& motion, const BodyState& s1,
                    const BodyState& s2, const HertzPhys& phys, Real dt, const Matrix3r& toGlobal,
                    TangentialSpring& spring, Wrench& local, PairResult& result, TriangleContact* listed) {
  SpringContact contact;
  Real polar = 0, radius = 0;
  if (normalForce > 0) {
    for (const ContactShare& share : shares) {
      Vector3r r = share.point - centre;
      r -= r.dot(normal) * normal;
      polar += share.load.force * r.squaredNorm();
      radius += share.load.force * r.norm();
    }
    polar /= normalForce;
    radius /= normalForce;
  }
  const Vector3r v = motion.at(centre);
  contact.normal = toGlobal * normal;
  contact.slip = toGlobal * (v - v.dot(normal) * normal);
  contact.spin = motion.angular.dot(normal);
  contact.frameSpin = 0.5 * (s1.angularVelocity + s2.angularVelocity).dot(contact.normal);
  contact.normalForce = normalForce;
  contact.stiffness = phys.stiffnessRatio * normalStiffness;
  contact.polarMoment = polar;
  contact.meanRadius = radius;
  const SpringLoad load = tangentialSpring(contact, phys, dt, spring);
  const Vector3r force = toGlobal.transpose() * load.force;
  local.force -= force;
  local.torque -= centre.cross(force) + load.torque * normal;
  result.summary.frictionPower += load.dissipatedPower;
  result.summary.elasticEnergy += spring.energy;
  result.summary.sliding = load.sliding;
  if (load.sliding) result.statistics.slidingContacts += static_cast<int>(shares.size());
  if (listed) {
    for (size_t k = 0; k < shares.size(); ++k) {
      const Real w = normalForce > 0 ? shares[k].load.force / normalForce : 0;
      Vector3r r = shares[k].point - centre;
      r -= r.dot(normal) * normal;
      const Vector3r twist =
          polar > 0 ? Vector3r(load.torque / polar * contact.normal.cross(toGlobal * r)) : Vector3r::Zero();
      listed[k].friction = {w * (load.force + twist), load.sliding};
    }
  }
}

}  // namespace

PairResult pairLoad(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                    const std::vector<PressureGeom>& geoms, std::vector<TriangleContact>* contacts,
                    TangentialSpring* spring) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const bool otherIsBody = pair.other < bodyCount;
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const BodyState& s2 = otherIsBody ? data.bodyStates[pair.other] : data.partnerStates[pair.other - bodyCount];
  const HertzMaterial& otherMaterial =
      otherIsBody ? model.bodies[pair.other].material : model.partners[pair.other - bodyCount].material;
  const Matrix3r toGlobal = s1.orientation.toRotationMatrix();
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(body.material, otherMaterial);
  const RoundedMesh& mesh = *body.mesh;
  PairResult result;
  PairSummary& summary = result.summary;
  if (geoms.empty()) {
    // Not touching: the spring lets go, and what it held is dissipated.
    if (spring) {
      if (data.timeStep > 0) summary.frictionPower = spring->energy / data.timeStep;
      *spring = TangentialSpring();
    }
    result.onOther = reaction(result.onBody, s1.position, s2.position);
    return result;
  }
  Wrench local;
  // Sums of Fn times the point of application and along the normal, and of the unweighted ones for a pair
  // whose normal forces are all zero (body 1's frame); the pair's normal stiffness.
  Vector3r moment = Vector3r::Zero(), normals = Vector3r::Zero(), points = Vector3r::Zero();
  Real normalForce = 0, stiffness = 0;
  thread_local std::vector<ContactShare> shares;
  shares.clear();
  const size_t listedFrom = contacts ? contacts->size() : 0;
  for (const PressureGeom& geom : geoms) {
    const NormalLoad load = Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, model.pressure);
    ++(load.regime == Regime::Direct ? result.statistics.directContacts : result.statistics.quadratureContacts);
    const Triangle& corners = mesh.triangles()[geom.triangle];
    const std::array<Vector3r, 3> x = {mesh.vertices()[corners[0]], mesh.vertices()[corners[1]],
                                       mesh.vertices()[corners[2]]};
    const std::array<Real, 3> forces = nodeForces(geom.nodes, load);
    addNodeForcesToBody(x, forces, geom.normal, local);
    const Vector3r point = planePoint(geom, geom.effectivePoint);
    // Fn acts at c + (-Mn_y, Mn_x) / Fn (NodeForces.hpp), so Fn times that point needs no division.
    const Vector3r weighted =
        load.force * geom.centre - load.moment.y() * geom.tangent1 + load.moment.x() * geom.tangent2;
    moment += weighted;
    normalForce += load.force;
    normals += load.force * geom.normal;
    points += point;
    // dF/d(delta) = (3/2) F / delta of a Hertz contact, for its elastic part.
    if (geom.sphereOverlap > 0) stiffness += 1.5 * load.elasticForce / geom.sphereOverlap;
    shares.push_back({load, load.force > 0 ? Vector3r(weighted / load.force) : point});
    summary.add(geom, load);
    if (contacts) {
      TriangleContact& c = contacts->emplace_back();
      c.geom = geom;
      c.point = s1.position + toGlobal * point;
      c.normal = toGlobal * geom.normal;
      c.load = load;
      c.friction = TangentialLoad();
      c.nodeForces = forces;
      if (geom.partnerTriangle >= 0) c.partnerNodeForces = nodeForces(geom.partnerNodes, load);
    }
  }
  summary.triangleContacts = static_cast<int>(geoms.size());
  const bool loaded = normalForce > 0;
  const Vector3r centre = loaded ? Vector3r(moment / normalForce) : Vector3r(points / geoms.size());
  if (!loaded)
    for (const PressureGeom& geom : geoms) normals += geom.normal;
  const Vector3r normal = normals.normalized();
  summary.point = s1.position + toGlobal * centre;
  summary.normal = toGlobal * normal;
  for (const PressureGeom& geom : geoms)
    summary.depth = std::max(summary.depth, geom.effectiveOverlap * geom.normal.dot(normal));
  TriangleContact* listed = contacts ? contacts->data() + listedFrom : nullptr;
  if (!(phys.friction > 0) || model.friction == FrictionLaw::Viscous) {
    // No spring: frictionless now (a material changed), or the viscous law.
    if (spring && spring->active()) {
      if (data.timeStep > 0) summary.frictionPower += spring->energy / data.timeStep;
      *spring = TangentialSpring();
    }
  }
  if (phys.friction > 0) {
    if (model.friction == FrictionLaw::Viscous) {
      viscousFriction(geoms, shares, phys, toGlobal, local, result, listed);
    } else {
      TangentialSpring fresh;
      springFriction(shares, normalForce, stiffness, centre, normal, relativeMotion(s1, s2, toGlobal.transpose()), s1,
                     s2, phys, spring ? data.timeStep : 0, toGlobal, spring ? *spring : fresh, local, result, listed);
    }
  }
  result.onBody.force = toGlobal * local.force;
  result.onBody.torque = toGlobal * local.torque;
  // For a mesh, Eq. 15 on its own triangle's corners gives the same wrench as reaction's (doc/physics.md).
  result.onOther = reaction(result.onBody, s1.position, s2.position);
  return result;
}

PairResult resolvePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                       std::vector<PressureGeom>& scratch, std::vector<TriangleContact>* contacts,
                       CandidateList* candidates, TangentialSpring* spring) {
  if (pair.body >= static_cast<int>(model.bodies.size())) return resolveSpherePair(model, data, pair, spring);
  ContactStatistics statistics;
  pairGeometry(model, data, pair, scratch, statistics, candidates);
  PairResult result = pairLoad(model, data, pair, scratch, contacts, spring);
  result.statistics += statistics;
  return result;
}

void RoundedMeshEngine(const ContactModel& model, ContactData& data) {
  if (data.geoms.size() < static_cast<size_t>(omp_get_max_threads())) data.geoms.resize(omp_get_max_threads());
  data.statistics = ContactStatistics();
  const double start = omp_get_wtime();
  broadPhase(model, data);
  const double broad = omp_get_wtime();
  const int pairCount = static_cast<int>(data.pairs.size());
  data.pairResults.resize(pairCount);
  data.pairContacts.resize(data.keepTriangleContacts ? pairCount : 0);
#pragma omp parallel for schedule(dynamic, 4) if (pairCount > 1)
  for (int k = 0; k < pairCount; ++k) {
    const BodyPair& pair = data.pairs[k];
    std::vector<TriangleContact>* contacts = nullptr;
    if (data.keepTriangleContacts) {
      contacts = &data.pairContacts[k];
      contacts->clear();
    }
    data.pairResults[k] = resolvePair(model, data, pair, data.geoms[omp_get_thread_num()], contacts,
                                      &data.candidateLists[pair.neighbour], &data.springs[pair.neighbour]);
  }
  const double resolved = omp_get_wtime();

  const int bodyCount = static_cast<int>(model.bodies.size());
  for (Wrench& w : data.bodyWrenches) w = Wrench();
  for (Wrench& w : data.partnerWrenches) w = Wrench();
  auto wrench = [&](int index) -> Wrench& {
    return index < bodyCount ? data.bodyWrenches[index] : data.partnerWrenches[index - bodyCount];
  };
  for (int k = 0; k < pairCount; ++k) {
    const PairResult& r = data.pairResults[k];
    Wrench& body = wrench(data.pairs[k].body);
    Wrench& otherWrench = wrench(data.pairs[k].other);
    body.force += r.onBody.force;
    body.torque += r.onBody.torque;
    otherWrench.force += r.onOther.force;
    otherWrench.torque += r.onOther.torque;
    data.statistics += r.statistics;
  }
  data.times = {broad - start, resolved - broad, omp_get_wtime() - resolved};
}

}  // namespace roundedmesh
