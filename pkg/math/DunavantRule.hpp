// Dunavant's symmetric 16-point quadrature rule of polynomial degree 8 on a triangle (Eq. 11):
//   integral over T of f dA  ~=  area(T) * sum_i weight_i * f(l1_i p1 + l2_i p2 + l3_i p3)
// with barycentric coordinates (l1, l2, l3) and weights summing to 1 (the paper's w_i / N_Q).
// Source: D. A. Dunavant, Int. J. Numer. Meth. Eng. 21 (1985) 1129-1148, rule for p = 8.
#pragma once

#include <array>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct QuadraturePoint {
  Real l1, l2, l3;  // barycentric coordinates
  Real weight;      // fraction of the triangle's area
};

namespace dunavant_detail {
constexpr Real w0 = 0.144315607677787, w1 = 0.095091634267285, w2 = 0.103217370534718,
               w3 = 0.032458497623198, w4 = 0.027230314174435;
constexpr Real a1 = 0.081414823414554, b1 = 0.459292588292723;
constexpr Real a2 = 0.658861384496480, b2 = 0.170569307751760;
constexpr Real a3 = 0.898905543365938, b3 = 0.050547228317031;
constexpr Real c1 = 0.008394777409958, c2 = 0.263112829634638, c3 = 0.728492392955404;
}  // namespace dunavant_detail

inline constexpr std::array<QuadraturePoint, 16> kDunavant8 = [] {
  using namespace dunavant_detail;
  return std::array<QuadraturePoint, 16>{{
      {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, w0},
      {a1, b1, b1, w1}, {b1, a1, b1, w1}, {b1, b1, a1, w1},
      {a2, b2, b2, w2}, {b2, a2, b2, w2}, {b2, b2, a2, w2},
      {a3, b3, b3, w3}, {b3, a3, b3, w3}, {b3, b3, a3, w3},
      {c1, c2, c3, w4}, {c1, c3, c2, w4}, {c2, c1, c3, w4},
      {c2, c3, c1, w4}, {c3, c1, c2, w4}, {c3, c2, c1, w4},
  }};
}();

// The same rule by columns, as Eigen arrays, so that the quadrature runs on all points at once (SIMD).
using QuadratureColumn = Eigen::Array<Real, 16, 1>;
struct QuadratureColumns {
  QuadratureColumn l1, l2, l3, weight;
};

inline const QuadratureColumns& dunavant8Columns() {
  static const QuadratureColumns columns = [] {
    QuadratureColumns c;
    for (size_t i = 0; i < kDunavant8.size(); ++i) {
      c.l1[i] = kDunavant8[i].l1;
      c.l2[i] = kDunavant8[i].l2;
      c.l3[i] = kDunavant8[i].l3;
      c.weight[i] = kDunavant8[i].weight;
    }
    return c;
  }();
  return columns;
}

}  // namespace roundedmesh
