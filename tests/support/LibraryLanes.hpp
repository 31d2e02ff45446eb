// The narrow phase's lanes on random body pairs of the library (icospheres, a distorted icosphere, a spheroid, 1 mm
// to 1 m, from grazing to deep, each moving at up to 1 m/s and 10 rad/s): every near triangle pair within a tenth of
// the smaller body's size, in batches of 1 to 16 lanes (the size cycling with the body pair), through the contact
// planes, S and the rest (TrianglePlanes.hpp, TriangleIntersections.hpp, PolygonContacts.hpp), for tests that compare
// each lane with the narrow phase one candidate at a time.
#pragma once

#include <string>
#include <vector>

#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/geom/PolygonContacts.hpp"
#include "pkg/geom/TrianglePlanes.hpp"
#include "tests/support/RandomPairs.hpp"

namespace roundedmesh::test {

// One lane of a batch, and the body pair it belongs to.
struct LibraryLane {
  const RoundedMesh& mesh1;
  const RoundedMesh& mesh2;
  const Matrix3r& rotation;  // x1 = rotation x2 + translation
  const Vector3r& translation;
  const RelativeMotion& motion;
  const TrianglePlanes& planes;
  const TriangleIntersections& clips;
  const PolygonContacts& contacts;
  int k;     // the lane
  int s, t;  // its triangles
  std::string where;
};

template <class Visit>
void forEachLibraryLane(unsigned seed, int bodyPairs, const Visit& visit) {
  RandomSource random(seed);
  BodyLibrary library(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
  TrianglePlanes planes;
  TriangleIntersections clips;
  PolygonContacts contacts;
  for (int bodyPair = 0; bodyPair < bodyPairs; ++bodyPair) {
    const BodyPairCase c = randomBodyPair(random, library);
    const RoundedMesh &mesh1 = *c.model.bodies[0].mesh, &mesh2 = *c.model.bodies[1].mesh;
    const BodyState &s1 = c.data.bodyStates[0], &s2 = c.data.bodyStates[1];
    const Matrix3r rotation = (s1.orientation.conjugate() * s2.orientation).toRotationMatrix();
    const Vector3r translation = s1.orientation.conjugate() * (s2.position - s1.position);
    const RelativeMotion motion = relativeMotion(s1, s2, s1.orientation.conjugate().toRotationMatrix());
    const Real reach = 0.1 * std::min(c.model.bodies[0].equivalentRadius, c.model.bodies[1].equivalentRadius);
    std::vector<roundedmesh::TrianglePair> near;
    nearTrianglePairs(mesh1, mesh2, rotation, translation, reach, reach, reach, near);
    const int batch = 1 + bodyPair % TrianglePlanes::kCapacity;
    for (size_t first = 0; first < near.size(); first += batch) {
      planes.size = static_cast<int>(std::min<size_t>(batch, near.size() - first));
      for (int k = 0; k < planes.size; ++k) {
        planes.s[k] = near[first + k][0];
        planes.t[k] = near[first + k][1];
      }
      trianglePlanes(mesh1, mesh2, rotation, translation, planes, clips);
      intersectTriangles(clips);
      polygonContacts(mesh1, mesh2, rotation, planes, clips, motion, contacts);
      for (int k = 0; k < planes.size; ++k) {
        const auto [s, t] = near[first + k];
        visit(LibraryLane{mesh1, mesh2, rotation, translation, motion, planes, clips, contacts, k, s, t,
                          "body pair " + std::to_string(bodyPair) + ", triangles " + std::to_string(s) + ", " +
                              std::to_string(t)});
      }
    }
  }
}

}  // namespace roundedmesh::test
