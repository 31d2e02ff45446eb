// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/bound/BoxesInShell.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "pkg/bound/BoxesInShell.hpp"

#ifndef ROUNDEDMESH_BOXES_IN_SHELL_ONCE
#define ROUNDEDMESH_BOXES_IN_SHELL_ONCE

namespace roundedmesh {
namespace shell {

// The columns' padding: a multiple of the lanes the kernel takes, at most 16 doubles, on every vector unit.
constexpr size_t kWholeVectors = 16;

// The two boxes' corners.
struct Query {
  Real outerMin[3], outerMax[3], innerMin[3], innerMax[3];
};

}  // namespace shell
}  // namespace roundedmesh

#endif  // ROUNDEDMESH_BOXES_IN_SHELL_ONCE

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Returns how many positions it wrote to `kept`. A compressed store writes a whole vector, which stays within the
// first i + lanes entries since the count written is at most i.
size_t BoxesInShellLanes(const BoxColumns& boxes, const shell::Query& q, int64_t* kept) {
  const hn::CappedTag<double, shell::kWholeVectors> d;  // a power of two lanes, at most 16: whole vectors
  const hn::RebindToSigned<decltype(d)> di;
  const size_t lanes = hn::Lanes(d);
  size_t count = 0;
  for (size_t i = 0; i < boxes.paddedSize(); i += lanes) {
    auto meetsOuter = hn::FirstN(d, lanes), meetsInner = hn::FirstN(d, lanes);
    for (int axis = 0; axis < 3; ++axis) {
      const auto min = hn::LoadU(d, boxes.min(axis) + i), max = hn::LoadU(d, boxes.max(axis) + i);
      meetsOuter = hn::And(meetsOuter, hn::And(hn::Le(min, hn::Set(d, q.outerMax[axis])),
                                               hn::Le(hn::Set(d, q.outerMin[axis]), max)));
      meetsInner = hn::And(meetsInner, hn::And(hn::Le(min, hn::Set(d, q.innerMax[axis])),
                                               hn::Le(hn::Set(d, q.innerMin[axis]), max)));
    }
    const auto keep = hn::AndNot(meetsInner, meetsOuter);
    count += hn::CompressStore(hn::Iota(di, static_cast<int64_t>(i)), hn::RebindMask(di, keep), di, kept + count);
  }
  return count;
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

#include <limits>

namespace roundedmesh {

HWY_EXPORT(BoxesInShellLanes);

void BoxColumns::assign(const std::vector<AlignedBox3r>& boxes, const std::vector<int>& which) {
  size_ = which.size();
  const size_t padded = (size_ + shell::kWholeVectors - 1) / shell::kWholeVectors * shell::kWholeVectors;
  for (int axis = 0; axis < 3; ++axis) {
    // The padding's boxes are NaN: they meet nothing.
    min_[axis].assign(padded, std::numeric_limits<Real>::quiet_NaN());
    max_[axis].assign(padded, std::numeric_limits<Real>::quiet_NaN());
    for (size_t i = 0; i < size_; ++i) {
      const AlignedBox3r& box = boxes[which[i]];
      min_[axis][i] = box.min()[axis];
      max_[axis][i] = box.max()[axis];
    }
  }
}

void boxesInShell(const BoxColumns& boxes, const AlignedBox3r& outer, const AlignedBox3r& inner,
                  std::vector<int64_t>& kept) {
  shell::Query q;
  for (int axis = 0; axis < 3; ++axis) {
    q.outerMin[axis] = outer.min()[axis];
    q.outerMax[axis] = outer.max()[axis];
    q.innerMin[axis] = inner.min()[axis];
    q.innerMax[axis] = inner.max()[axis];
  }
  kept.resize(boxes.paddedSize() + shell::kWholeVectors);
  kept.resize(HWY_DYNAMIC_DISPATCH(BoxesInShellLanes)(boxes, q, kept.data()));
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
