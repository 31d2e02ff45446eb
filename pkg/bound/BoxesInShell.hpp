// Bound: which of many axis-aligned boxes lie in the shell between two boxes, several boxes per instruction (Google
// Highway, the widest vector unit the processor has, chosen at run time): box i is kept if it meets `outer` and does
// not meet `inner`, as Eigen's AlignedBox3r::intersects decides (min <= other max and other min <= max on every axis,
// a NaN meeting nothing). The lanes only compare, so they decide exactly as intersects does.
//
// The deep lists' search (nearTrianglePairs, TrianglePairCandidates.hpp) asks this of every triangle of body 1 whose
// cap reaches into body 2, once for each such triangle of body 2: the pairs within the list's depth that the trees'
// search at the Hertz range did not find.
#pragma once

#include <cstdint>
#include <vector>

#include "pkg/shape/TriangleTree.hpp"

namespace roundedmesh {

// Boxes as six columns, padded to whole vectors with boxes that meet nothing.
class BoxColumns {
 public:
  // The boxes boxes[i] for i in `which`, in that order.
  void assign(const std::vector<AlignedBox3r>& boxes, const std::vector<int>& which);
  size_t size() const { return size_; }
  size_t paddedSize() const { return min_[0].size(); }
  const Real* min(int axis) const { return min_[axis].data(); }
  const Real* max(int axis) const { return max_[axis].data(); }

 private:
  std::vector<Real> min_[3], max_[3];
  size_t size_ = 0;
};

// Sets `kept` to the positions (into `boxes`, in increasing order) of the boxes that meet outer and not inner.
void boxesInShell(const BoxColumns& boxes, const AlignedBox3r& outer, const AlignedBox3r& inner,
                  std::vector<int64_t>& kept);

}  // namespace roundedmesh
