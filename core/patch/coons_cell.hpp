// One bicubically blended Coons cell (S. A. Coons, "Surfaces for computer-aided design of space
// forms", MIT MAC-TR-41, 1967) of a curve network with non-uniform parameter spacing (Coons
// surfaces on a non-rectangular network; docs/classic-types.md).
//
// The network gives at each node r, r_s, r_t, r_st with respect to the network's own curve
// parameters s (along rows) and t (along columns). The cell's opposite boundaries may have
// different parametric lengths: S0 (bottom, v = 0) and S1 (top, v = 1) in s, T0 (left, u = 0)
// and T1 (right, u = 1) in t. Each boundary is the cubic Hermite curve of its
// own length:  r(i, v) = r(i,0) a0(v) + r(i,1) a1(v) + [r_t(i,0) b0(v) + r_t(i,1) b1(v)] T_i.
// Cross-boundary derivatives (u = i; v = j symmetric):
//   r_u(i, v) = S(v) r_s(i, v) + lambda_i(v) r_v(i, v),
//   S(v) = (1-v) S0 + v S1,   r_s(i, v) = r_s(i,0) a0 + r_s(i,1) a1 + [r_st(i,0) b0 + r_st(i,1) b1]
//   T_i, lambda_i(v) = (T1 - T0) / T_i (b0(v) + b1(v)).
// r_s(i, v) depends only on the edge's own data, so the neighbour across the edge has a cross
// derivative in the same plane span(r_v, r_s) with a positive factor S(v): the composite is G1.
// lambda (zero at the corners, a tangential term only) makes the two corner twists agree:
//   r_uv(i,j) = S_j T_i r_st + (S1 - S0) r_s + (T1 - T0) r_t,
// so the Coons patch reproduces every boundary and cross-boundary derivative exactly. With
// S0 = S1 and T0 = T1 it is the Ferguson patch F(u) Q F(v)^T of the scaled corner data.
#pragma once

#include <span>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

struct CellLengths {
  double S0, S1, T0, T1;  // parametric lengths: bottom, top (in s), left, right (in t); > 0
};

// Coefficient jets (in local u, v) of the 16 corner data: index (i*2 + j)*4 + q for corner
// (u, v) = (i, j) and q = 0: r, 1: r_s, 2: r_t, 3: r_st.
void coons_cell_basis(Vec2 uv, const CellLengths& len, std::span<Jet> out);

}  // namespace pl
