// The blend of a Generalized Bézier patch: the weight mu that each ribbon control point gets on
// top of its Bernstein products, and the rational corner weights alpha and beta in it.
//
// Central-point GB (Várady, Salvi, Karikó 2016; transfinite's SurfaceGeneralizedBezier), point
// (j, k) of a degree-d ribbon, the first rule that applies:
//   alpha for k < 2, j < 2;  beta for k < 2, j > d - 2   (the 2x2 corner blocks; d >= 3 only),
//   1/2 on the diagonals j = k and j = d - k,  0 beyond them,  1 elsewhere.
// Degree 1 and 2 have no corner rule: their 2x2 corner blocks would overlap and give the middle
// boundary point a rational weight; the diagonal rule alone interpolates the boundary.
// Independent ribbons (Salvi & Várady 2018): alpha on the first half of a row (2j < d), 1 at its
// middle, beta on the second half, whatever the row.
//
// Corner weights of side i from side weights w (w = h for the central patch, w = h^2 for the
// independent ribbons, the papers' "squared" variant):
//   alpha_i = w_{i-1} / (w_{i-1} + w_i),   beta_i = w_{i+1} / (w_{i+1} + w_i) = 1 - alpha_{i+1},
// computed as 1 - alpha_{i+1}, so the two weights a shared corner point gets from the ribbons
// meeting there sum to one exactly. Both are 0/0 at the domain vertices (vertex_limits.hpp).
//
// Templates over the jet type: Jet for one sample, JetLanesOf<V> for a block of samples (one
// per SIMD lane), running the same operations, so batched and scalar paths agree bit for bit.
#pragma once

#include <cstdint>

#include "core/math/lanes.hpp"

namespace pl {

enum class Mu : uint8_t { Zero, Half, One, Alpha, Beta };

constexpr Mu central_mu(int d, int j, int k) {
  if (d >= 3 && k < 2 && j < 2) return Mu::Alpha;
  if (d >= 3 && k < 2 && j > d - 2) return Mu::Beta;
  if (j == k || j == d - k) return Mu::Half;
  if (j < k || j > d - k) return Mu::Zero;
  return Mu::One;
}

constexpr Mu ribbon_mu(int d, int j) {
  return 2 * j < d ? Mu::Alpha : 2 * j == d ? Mu::One : Mu::Beta;
}

// Whether the central patch has corner weights at all (degree 3 and up).
constexpr bool has_corner_weights(int d) {
  return d >= 3;
}

template <class J>
[[gnu::always_inline]] inline J corner_alpha(const J& w_prev, const J& w) {
  return product(w_prev, reciprocal(sum(w_prev, w)));
}

// alpha_i of every side whose bit is set in `sides`, from the side weights w (h or h^2).
template <class J>
[[gnu::always_inline]] inline void corner_alphas(int n, const J* w, J* alpha,
                                                 uint64_t sides = ~uint64_t{0}) {
  for (int i = 0; i < n; ++i)
    if (sides >> i & 1u) alpha[i] = corner_alpha(w[i == 0 ? n - 1 : i - 1], w[i]);
}

// 1 - alpha_next, component by component (the sign of zero as Jet(1.0) - alpha gives it).
template <class J>
[[gnu::always_inline]] inline J corner_beta(const J& alpha_next) {
  const J& a = alpha_next;
  return {1.0 - a.f, 0.0 - a.fu, 0.0 - a.fv, 0.0 - a.fuu, 0.0 - a.fuv, 0.0 - a.fvv};
}

// b mu for a point of ribbon i with rule m, given alpha of every side the rule needs (alpha_i,
// and alpha_{i+1} for beta_i). Zero gives no term: callers skip it.
template <class J>
[[gnu::always_inline]] inline J weighted(const J& b, Mu m, const J* alpha, int i, int n) {
  switch (m) {
    case Mu::Half:
      return scaled(b, 0.5);
    case Mu::Alpha:
      return product(b, alpha[i]);
    case Mu::Beta:
      return product(b, corner_beta(alpha[i + 1 == n ? 0 : i + 1]));
    default:
      return b;
  }
}

// Sums over all ribbons split each ribbon's points into groups by their weight: with
// beta_i = 1 - alpha_{i+1},
//   sum_i (C_i + alpha_i A_i + beta_i B_i) = sum_i (C_i + B_i) + sum_i alpha_i (A_i - B_{i-1}),
// so group 0 holds the constant weights and the beta points, group 1 the alpha points and
// group 2 the beta points again: one rational product per ribbon.
inline constexpr int kMuGroups = 3;
// The factor of a point of rule m in group g (0 where it is not in the group).
constexpr double mu_group_factor(Mu m, int g) {
  switch (g) {
    case 0:
      return m == Mu::Half ? 0.5 : m == Mu::One || m == Mu::Beta ? 1.0 : 0.0;
    case 1:
      return m == Mu::Alpha ? 1.0 : 0.0;
    default:
      return m == Mu::Beta ? 1.0 : 0.0;
  }
}

}  // namespace pl
