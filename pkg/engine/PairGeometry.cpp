#include "pkg/engine/PairGeometry.hpp"

#include <algorithm>
#include <memory>

#include "pkg/common/Overloaded.hpp"
#include "pkg/common/StageClock.hpp"
#include "pkg/engine/CandidateLists.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Sphere_PressureGeom.hpp"

namespace roundedmesh {
namespace {

// Passes of one pair's evaluation while its deepest contact outgrows its list. A pair within the Hertz range grows
// its list's depth by half per pass; one past it takes a list as deep as the bodies (deepestPossible) at once.
constexpr int kDeepeningPasses = 8;

// Ig2 of a body against a plane given in the global frame.
void planeGeometry(const RoundedMesh& mesh, const Plane& global, const BodyState& body, const Matrix3r& R_BW,
                   const RelativeMotion& motion, const GeomOutput& out, CurvatureModel curvature) {
  Ig2_RoundedMesh_Plane_PressureGeom(mesh, Plane{R_BW * (global.point - body.position), R_BW * global.normal},
                                     motion, out, curvature);
}

// Ig2 of body 1's triangles against the other side, in body 1's frame (origin at its position).
void contactGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                     const RelativeMotion& motion, CandidateList* candidates, std::vector<PressureGeom>& geoms,
                     ContactStatistics& statistics) {
  const RoundedBody& body = model.bodies[pair.body];
  const BodyState& s1 = data.bodyStates[pair.body];
  const Matrix3r R_BW = s1.orientation.toRotationMatrix().transpose();
  auto inBody = [&](const Vector3r& x) -> Vector3r { return R_BW * (x - s1.position); };
  const GeomOutput out(geoms, &statistics.narrowPhase);
  const CurvatureModel curvature = model.options.pressure.curvature;
  const bool timed = model.options.timing == Timing::Stages;
  StageClock clock(timed);
  const int bodyCount = static_cast<int>(model.bodies.size());
  if (pair.other < bodyCount) {
    const BodyState& s2 = data.bodyStates[pair.other];
    const RoundedBody& other = model.bodies[pair.other];
    const Real smaller = std::min(body.equivalentRadius, other.equivalentRadius);
    const Quaternionr rotation = s1.orientation.conjugate() * s2.orientation;
    const Matrix3r matrix = rotation.toRotationMatrix();
    const Vector3r translation = inBody(s2.position);
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
                       list.deepest > shallow ? fullDepth() : shallow, list, statistics, timed);
      statistics.cpu.lists += clock.lap();
      NarrowPhaseCounts counts;
      geoms.clear();
      Ig2_RoundedMesh_RoundedMesh_PressureGeom(*body.mesh, *other.mesh, matrix, translation, list.pairs, shallow,
                                               motion, GeomOutput(geoms, &counts), curvature);
      statistics.cpu.narrowPhase += clock.lap();
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
  const Partner& partner = model.partners[pair.other - bodyCount];
  const Real edgeRadius = edgeRadiusFor(partner, body.equivalentRadius);
  std::visit(Overloaded{[&](const Box& box) {
                          Ig2_RoundedMesh_Box_PressureGeom(*body.mesh, box, inBody(s2.position),
                                                           R_BW * s2.orientation.toRotationMatrix(), edgeRadius,
                                                           motion, out, curvature);
                        },
                        [&](const Facet& facet) {
                          const Matrix3r toBody = R_BW * s2.orientation.toRotationMatrix();
                          const Vector3r facetOrigin = inBody(s2.position);
                          if (!candidates) {
                            Ig2_RoundedMesh_Facet_PressureGeom(*body.mesh, placeFacet(facet, toBody, facetOrigin),
                                                               edgeRadius, motion, out, curvature);
                            return;
                          }
                          if (!candidates->facet) candidates->facet = std::make_unique<FacetList>();
                          FacetList& list = *candidates->facet;
                          updateFacetCandidates(*body.mesh, facet, toBody, facetOrigin, s1, s2, edgeRadius,
                                                model.skins, body.equivalentRadius, list, statistics);
                          statistics.cpu.lists += clock.lap();
                          // None: the Ig2 would find nothing, and the facet is not placed.
                          if (!list.candidates.empty())
                            Ig2_RoundedMesh_Facet_PressureGeom(*body.mesh, placeFacet(facet, toBody, facetOrigin),
                                                               edgeRadius, motion, out, curvature, &list.candidates);
                        },
                        [&](const Sphere& sphere) {
                          Ig2_RoundedMesh_Sphere_PressureGeom(
                              *body.mesh, sphere, inBody(s2.position), motion, out, curvature,
                              kDeepestOverlap * std::min(body.equivalentRadius, sphere.radius));
                        },
                        [&](const Plane& plane) { planeGeometry(*body.mesh, plane, s1, R_BW, motion, out, curvature); },
                        [&](const Wall& wall) {
                          planeGeometry(*body.mesh, wallPlane(wall, s2.position, s1.position), s1, R_BW, motion, out,
                                        curvature);
                        }},
             partner.shape);
  statistics.cpu.narrowPhase += clock.lap();
}

}  // namespace

RelativeMotion relativeMotion(const BodyState& s1, const BodyState& s2, const Matrix3r& R_BW) {
  RelativeMotion motion;
  motion.linear = R_BW * (s2.velocity - s1.velocity + s2.angularVelocity.cross(s1.position - s2.position));
  motion.angular = R_BW * (s2.angularVelocity - s1.angularVelocity);
  return motion;
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

}  // namespace roundedmesh
