// 3-vectors as three Highway vectors, one lane per item of a batch: the few operations the batched kernels share
// (BatchedCandidates.cpp, TrianglePlanes.cpp, PolygonContacts.cpp), with the sums in the order Eigen evaluates them for 3-vectors in the
// portable build (SSE2, two doubles per packet): a dot product left to right, (a0 b0 + a1 b1) + a2 b2; a 3 x 3 matrix
// times a vector by rows 0 and 1 as one packet, left to right, and row 2 as a reduction halved recursively,
// m20 x0 + (m21 x1 + m22 x2). Included inside each kernel file's per-target code (Highway's foreach_target), hence
// the guard that toggles with HWY_TARGET_TOGGLE.
#if defined(ROUNDEDMESH_VECTOR3_LANES_HPP) == defined(HWY_TARGET_TOGGLE)
#ifdef ROUNDEDMESH_VECTOR3_LANES_HPP
#undef ROUNDEDMESH_VECTOR3_LANES_HPP
#else
#define ROUNDEDMESH_VECTOR3_LANES_HPP
#endif

#include <vector>

#include "hwy/highway.h"
#include "pkg/common/Types.hpp"

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {

template <class V>
HWY_INLINE V Dot3(const V a[3], const V b[3]) {
  namespace hn = hwy::HWY_NAMESPACE;
  return hn::Add(hn::Add(hn::Mul(a[0], b[0]), hn::Mul(a[1], b[1])), hn::Mul(a[2], b[2]));
}

// a x b, as Eigen's cross product.
template <class V>
HWY_INLINE void Cross3(const V a[3], const V b[3], V out[3]) {
  namespace hn = hwy::HWY_NAMESPACE;
  out[0] = hn::Sub(hn::Mul(a[1], b[2]), hn::Mul(a[2], b[1]));
  out[1] = hn::Sub(hn::Mul(a[2], b[0]), hn::Mul(a[0], b[2]));
  out[2] = hn::Sub(hn::Mul(a[0], b[1]), hn::Mul(a[1], b[0]));
}

// The 3 x 3 matrix m times x.
template <class V>
HWY_INLINE void Rotate3(const V (&m)[3][3], const V x[3], V out[3]) {
  namespace hn = hwy::HWY_NAMESPACE;
  for (int i = 0; i < 2; ++i) out[i] = hn::Add(hn::Add(hn::Mul(m[i][0], x[0]), hn::Mul(m[i][1], x[1])), hn::Mul(m[i][2], x[2]));
  out[2] = hn::Add(hn::Mul(m[2][0], x[0]), hn::Add(hn::Mul(m[2][1], x[1]), hn::Mul(m[2][2], x[2])));
}

// Each lane's item `index` of three columns.
template <class D, class VI>
HWY_INLINE void Gather3(D d, const std::vector<Real> (&column)[3], VI index, hwy::HWY_NAMESPACE::Vec<D> out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = hwy::HWY_NAMESPACE::GatherIndex(d, column[k].data(), index);
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#endif  // ROUNDEDMESH_VECTOR3_LANES_HPP
