// Part of a RoundedMesh: a static bounding-volume hierarchy over its triangles, built once in the body frame
// (architecture.md). Triangle t's box holds its corners and its cap, the part of its encompassing sphere
// beyond the triangle's plane where contact pressure acts: the corners' box inflated on every side by the
// cap height R - sqrt(R^2 - rho^2) (rho the circumradius). A node's box holds its children's.
// Queries allocate only to grow a thread's cache: traversal runs on a fixed stack (the median split keeps the depth
// at log2(n)).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

using AlignedBox3r = Eigen::AlignedBox<Real, 3>;

class TriangleTree {
 public:
  struct Node {
    AlignedBox3r box;
    int first;  // leaf: first index into order(); inner: index of the left child (the right one follows it)
    int count;  // leaf: number of triangles (> 0); inner: 0
    Real sizeSq;  // the box's squared diagonal, which queryPairs compares to choose the node it descends [m^2]
  };

  TriangleTree() = default;
  // boxes[t]: the box of triangle t.
  explicit TriangleTree(std::vector<AlignedBox3r> boxes);

  const std::vector<Node>& nodes() const { return nodes_; }
  const AlignedBox3r& triangleBox(int t) const { return boxes_[t]; }
  const std::vector<AlignedBox3r>& triangleBoxes() const { return boxes_; }

  // Calls visit(t) for every triangle t whose box passes `test` (a predicate on an AlignedBox3r that must hold
  // for every box containing one that passes: it is applied to nodes before their triangles), in the tree's order:
  // one order of all its triangles, whichever the test passes.
  template <class BoxTest, class Visit>
  void query(const BoxTest& test, const Visit& visit) const;
  // The same, with the nodes tested by `nodeTest`, which must pass every node that holds a triangle whose box passes
  // `test`.
  template <class NodeTest, class BoxTest, class Visit>
  void query(const NodeTest& nodeTest, const BoxTest& test, const Visit& visit) const;
  // Calls visit(t) for every triangle t whose box passes `reach` (reach(box) for a triangle's box, reach.node(box) for
  // a node's, which passes every node that holds a triangle reach passes), in the tree's order: from `candidates`
  // alone where given, which must hold every such triangle in the tree's order, else from the whole tree.
  template <class Reach, class Visit>
  void visitReachable(const Reach& reach, const Visit& visit, const std::vector<int>* candidates = nullptr) const;

  // Calls visit(s, t) for every triangle s of `a` and t of `b` whose boxes come closer than `margin` on every
  // axis when b's frame is placed in a's by x_a = rotation * x_b + translation (b's boxes taken as the
  // axis-aligned boxes of their rotated images, which contain them). The margin is the deepest overlap to be
  // found: two caps that have sunk into each other by d have boxes up to d apart.
  template <class Visit>
  static void queryPairs(const TriangleTree& a, const TriangleTree& b, const Matrix3r& rotation,
                         const Vector3r& translation, Real margin, const Visit& visit);

 private:
  static constexpr int kStackSize = 128;
  void build(int self, int first, int count);

  std::vector<AlignedBox3r> boxes_;
  std::vector<int> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
};

// A box inside another: its centre's distance from the other's centre plus its own half-diagonal is at most this
// times the other's half-diagonal (|d_i| + r_i <= h_i on each axis, and a + b <= sqrt(2 (a^2 + b^2))). So a test on a
// box's circumscribed ball passes every node that holds a box passing it when the node's ball is this much larger.
constexpr Real kNestedBallFactor = 1.4142135623730951;  // sqrt(2)

// AlignedBox3r::intersects with its six comparisons joined without branches: one branch on the outcome, where the
// traversal of a tree would mispredict several.
inline bool meet(const AlignedBox3r& a, const AlignedBox3r& b) {
  const int all = int(a.min().x() <= b.max().x()) & int(a.min().y() <= b.max().y()) & int(a.min().z() <= b.max().z()) &
                  int(b.min().x() <= a.max().x()) & int(b.min().y() <= a.max().y()) & int(b.min().z() <= a.max().z());
  return all != 0;
}

// The axis-aligned box of `box` rotated and translated: centre R c + t, half-sizes |R| h, grown by margin.
inline AlignedBox3r transformedBox(const AlignedBox3r& box, const Matrix3r& rotation, const Vector3r& translation,
                                   Real margin = 0) {
  const Vector3r centre = rotation * box.center() + translation;
  const Vector3r half = (rotation.cwiseAbs() * (0.5 * box.sizes())).array() + margin;
  return AlignedBox3r(centre - half, centre + half);
}

template <class BoxTest, class Visit>
void TriangleTree::query(const BoxTest& test, const Visit& visit) const {
  query(test, test, visit);
}

template <class NodeTest, class BoxTest, class Visit>
void TriangleTree::query(const NodeTest& nodeTest, const BoxTest& test, const Visit& visit) const {
  if (nodes_.empty()) return;
  std::array<int, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!nodeTest(node.box)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        if (test(boxes_[order_[i]])) visit(order_[i]);
    } else {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
}

template <class Reach, class Visit>
void TriangleTree::visitReachable(const Reach& reach, const Visit& visit, const std::vector<int>* candidates) const {
  if (!candidates) {
    query([&](const AlignedBox3r& box) { return reach.node(box); }, reach, visit);
    return;
  }
  for (int t : *candidates)
    if (reach(boxes_[t])) visit(t);
}

template <class Visit>
void TriangleTree::queryPairs(const TriangleTree& a, const TriangleTree& b, const Matrix3r& rotation,
                              const Vector3r& translation, Real margin, const Visit& visit) {
  if (a.nodes_.empty() || b.nodes_.empty()) return;
  // transformedBox with |R| formed once.
  const Matrix3r absRotation = rotation.cwiseAbs();
  auto moved = [&](const AlignedBox3r& box) {
    const Vector3r centre = rotation * box.center() + translation;
    const Vector3r half = (absRotation * (0.5 * box.sizes())).array() + margin;
    return AlignedBox3r(centre - half, centre + half);
  };
  // b's boxes in a's frame, each placed once per query however many of a's nodes it meets (a thread's cache,
  // stamped with the query it belongs to).
  struct Placed {
    std::vector<AlignedBox3r> boxes;
    std::vector<unsigned> stamps;
  };
  thread_local Placed placedNodes, placedTriangles;
  thread_local unsigned stamp = 0;
  if (++stamp == 0) {
    for (Placed* placed : {&placedNodes, &placedTriangles}) std::fill(placed->stamps.begin(), placed->stamps.end(), 0u);
    stamp = 1;
  }
  for (auto [placed, count] : {std::pair(&placedNodes, b.nodes_.size()), std::pair(&placedTriangles, b.boxes_.size())})
    if (placed->stamps.size() < count) {
      placed->stamps.resize(count, 0u);
      placed->boxes.resize(count);
    }
  auto place = [&](Placed& placed, int index, const AlignedBox3r& box) -> const AlignedBox3r& {
    if (placed.stamps[index] != stamp) {
      placed.boxes[index] = moved(box);
      placed.stamps[index] = stamp;
    }
    return placed.boxes[index];
  };
  std::array<std::array<int, 2>, kStackSize> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const auto [i, j] = stack[--top];
    const Node& na = a.nodes_[i];
    const Node& nb = b.nodes_[j];
    if (!meet(na.box, place(placedNodes, j, nb.box))) continue;
    if (na.count > 0 && nb.count > 0) {
      for (int q = nb.first; q < nb.first + nb.count; ++q) {
        const int t = b.order_[q];
        const AlignedBox3r& triangleB = place(placedTriangles, t, b.boxes_[t]);
        for (int p = na.first; p < na.first + na.count; ++p)
          if (meet(a.boxes_[a.order_[p]], triangleB)) visit(a.order_[p], t);
      }
    } else if (nb.count > 0 || (na.count == 0 && na.sizeSq >= nb.sizeSq)) {
      // Descend the larger of two inner nodes, or the only inner one.
      stack[top++] = {na.first, j};
      stack[top++] = {na.first + 1, j};
    } else {
      stack[top++] = {i, nb.first};
      stack[top++] = {i, nb.first + 1};
    }
  }
}

}  // namespace roundedmesh
