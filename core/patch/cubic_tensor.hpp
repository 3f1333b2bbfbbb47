// Shared by the 4x4 cubic tensor-product patches (interpolating, Hermite/Ferguson):
// S(u,v) = sum_ab F_a(u) F_b(v) Q_ab, Q_ab = points[a*4 + b].
#pragma once

#include <span>

#include "core/math/cubic_bases.hpp"
#include "core/math/jet.hpp"

namespace pl {

inline Jet cubic_tensor_phi(const CubicBasis& bu, const CubicBasis& bv, int a, int b) {
  return Jet(bu.d0[a] * bv.d0[b], bu.d1[a] * bv.d0[b], bu.d0[a] * bv.d1[b], bu.d2[a] * bv.d0[b],
             bu.d1[a] * bv.d1[b], bu.d0[a] * bv.d2[b]);
}

inline void cubic_tensor_basis(const CubicBasis& bu, const CubicBasis& bv, std::span<Jet> out) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) out[a * 4 + b] = cubic_tensor_phi(bu, bv, a, b);
}

}  // namespace pl
