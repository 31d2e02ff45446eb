// Part of a RoundedMesh: its triangles' data that the candidate lists test, one array per quantity (structure of
// arrays), so that a batch of triangle pairs is read several pairs per instruction (BatchedCandidates.hpp). The same
// numbers as RoundedTriangle and the triangle tree's cap boxes, body frame [m].
#pragma once

#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class RoundedMesh;

struct TriangleColumns {
  std::vector<Real> boxMin[3], boxMax[3];  // the cap box (TriangleTree::triangleBox)
  std::vector<Real> circumcentre[3];
  std::vector<Real> circumradius;
  std::vector<Real> sphereCentre[3];
  std::vector<Real> radius;                // R of the encompassing sphere
  std::vector<Real> sphereCentreDistance;  // |sphereCentre|, from the body's origin
  std::vector<Real> normal[3];
  std::vector<Real> corner[3][3];          // corner i's coordinate k (triangleCorners)
  Real largestRadius = 0;                  // the largest R: the scale of the numbers a test of these triangles forms
};

TriangleColumns triangleColumns(const RoundedMesh& mesh);

}  // namespace roundedmesh
