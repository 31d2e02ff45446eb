#include "pkg/engine/CandidateLists.hpp"

#include <algorithm>

#include "pkg/bound/BatchedCandidates.hpp"
#include "pkg/common/StageClock.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"

namespace roundedmesh {
namespace {

// How far a point of body 2 may have moved relative to body 1 between two of its poses in body 1's frame:
// the offset plus the turn times its bound radius (|R - R0| = 2 |vec(q0^-1 q)|).
Real motionBound(const Quaternionr& fromRotation, const Vector3r& fromTranslation, const Quaternionr& rotation,
                 const Vector3r& translation, Real boundRadius) {
  return (translation - fromTranslation).norm() + 2 * (fromRotation.conjugate() * rotation).vec().norm() * boundRadius;
}

// The radius about the body's centre of the ball that holds every box of its triangle tree [m].
Real treeRadius(const RoundedMesh& mesh) {
  const AlignedBox3r& root = mesh.tree().nodes().front().box;
  return (root.center().cwiseAbs() + 0.5 * root.sizes()).norm();
}

// A Facet's list is kept while the motion bound stays this fraction of the body's tree radius inside its skin, and the
// centre's motion inside its side's clearance: the tests round off by about 1e-16 of the distances they compare.
constexpr Real kSkinRoundOff = 1e-9;

}  // namespace

Real deepestPossible(const RoundedMesh& a, const RoundedMesh& b) {
  auto reach = [](const RoundedMesh& m) {
    return m.sphereBoundRadius() + m.maxCapHeight() + m.solidDistance().tolerance();
  };
  return 2 * std::min(reach(a), reach(b));
}

void updateCandidates(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Quaternionr& rotation,
                      const Matrix3r& matrix, const Vector3r& translation, const ListSkins& skins, Real radius,
                      Real shallow, Real full, CandidateList& list, ContactStatistics& statistics, bool timed) {
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
    StageClock clock(timed);
    nearTrianglePairs(mesh1, mesh2, matrix, translation, list.nearSkin, list.nearDepth, shallow, list.near);
    statistics.cpu.nearSearch += clock.lap();
    ++statistics.nearRebuilds;
  }
  list.built = true;
  list.skin = skin;
  list.depth = depth;
  list.age = 0;
  list.rotation = rotation;
  list.translation = translation;
  touchableTrianglePairsBatched(mesh1, mesh2, matrix, translation, skin, depth, list.near, list.pairs);
  ++statistics.candidateRebuilds;
  statistics.nearPairsScanned += static_cast<long>(list.near.size());
}

void updateFacetCandidates(const RoundedMesh& mesh, const Facet& facet, const Matrix3r& toBody,
                           const Vector3r& facetOrigin, const BodyState& body, const BodyState& facetState,
                           Real edgeRadius, const ListSkins& skins, Real radius, FacetList& list,
                           ContactStatistics& statistics) {
  const Quaternionr toFacet = facetState.orientation.conjugate();
  const Quaternionr rotation = toFacet * body.orientation;
  const Vector3r translation = toFacet * (body.position - facetState.position);
  const Real bound = treeRadius(mesh);
  Real skin = skins.candidatesMin * radius;
  if (list.built) {
    ++list.age;
    const Real motion = motionBound(list.rotation, list.translation, rotation, translation, bound);
    const Real roundOff = kSkinRoundOff * bound;
    if (list.weld == facet.weld && list.vertices == facet.vertices && list.edgeRadius == edgeRadius &&
        motion + roundOff <= list.skin && (translation - list.translation).norm() + roundOff < list.sideClearance)
      return;
    skin = std::clamp(skins.candidateSteps * motion / list.age, skin, skins.candidatesMax * radius);
  }
  const PlacedFacet placed = placeFacet(facet, toBody, facetOrigin);
  const int side = facetSide(placed, &list.sideClearance);
  facetCandidates(mesh, placed, side, edgeRadius, skin, list.candidates);
  list.built = true;
  list.rotation = rotation;
  list.translation = translation;
  list.skin = skin;
  list.age = 0;
  list.weld = facet.weld;
  list.vertices = facet.vertices;
  list.edgeRadius = edgeRadius;
  ++statistics.candidateRebuilds;
}

}  // namespace roundedmesh
