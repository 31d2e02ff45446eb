#include "pkg/shape/TriangleTree.hpp"

#include <algorithm>
#include <numeric>

namespace roundedmesh {
namespace {

constexpr int kLeafSize = 2;

}  // namespace

TriangleTree::TriangleTree(std::vector<AlignedBox3r> boxes) : boxes_(std::move(boxes)), order_(boxes_.size()) {
  std::iota(order_.begin(), order_.end(), 0);
  if (boxes_.empty()) return;
  nodes_.emplace_back();
  build(0, 0, static_cast<int>(order_.size()));
}

// Makes node `self` hold triangles order_[first, first + count): a leaf, or the parent of two children split at
// the median of the box centres along the longest axis (ties by index, so the tree is the same on every run).
void TriangleTree::build(int self, int first, int count) {
  AlignedBox3r box;
  for (int i = first; i < first + count; ++i) box.extend(boxes_[order_[i]]);
  nodes_[self].box = box;
  nodes_[self].sizeSq = box.sizes().squaredNorm();
  if (count <= kLeafSize) {
    nodes_[self].first = first;
    nodes_[self].count = count;
    return;
  }
  int axis;
  box.sizes().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int s, int t) {
                     const Real cs = boxes_[s].center()[axis], ct = boxes_[t].center()[axis];
                     return cs < ct || (cs == ct && s < t);
                   });
  const int left = static_cast<int>(nodes_.size());
  nodes_[self].first = left;
  nodes_[self].count = 0;
  nodes_.resize(nodes_.size() + 2);
  build(left, first, half);
  build(left + 1, first + half, count - half);
}

}  // namespace roundedmesh
