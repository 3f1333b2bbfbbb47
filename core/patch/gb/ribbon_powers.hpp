// The Bernstein evaluation of an independent ribbon (gb_ribbon_patch.hpp) in homogeneous form.
// With s_i = lambda_i / D_i, D_i = lambda_{i-1} + lambda_i and 1 - h_i = D_i,
//   B^d_j(s_i) B^m_k(h_i) = binom(d, j) binom(m, k) lambda_i^j lambda_{i-1}^(d-j) D_i^(m-k-d)
//   h_i^k,
// which stays defined where s_i is 0/0 (the sides away from side i, where both lambdas vanish):
// there it is the exact one-sided limit. The powers of one sample are tabled once per ribbon.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"
#include "core/math/lanes.hpp"
#include "core/math/scratch.hpp"

namespace pl {

// The largest ribbon degree and layer count the gb-ribbons format accepts.
inline constexpr int kMaxRibbonDegree = 30, kMaxRibbonLayers = 15;

// a^0 .. a^top (top <= kCap - 1), each by repeated multiplication from 1 like pow(a, k), so a
// table entry is bitwise the value pow() gives. Exponents past the table continue the
// multiplication, so the values stay those of pow() for any degree. J = Jet for one sample, or
// JetLanesOf<V> for a block of samples.
template <class J>
class PowersOf {
 public:
  static constexpr int kCap = 2 * kMaxRibbonLayers + 2;
  static_assert(kCap > kMaxRibbonDegree);

  PATCHLAB_LANES_INLINE void build(const J& a, int top) {
    base_ = a;
    top_ = std::min(std::max(top, 0), kCap - 1);
    p_[0] = constant_one();
    for (int k = 1; k <= top_; ++k) p_[k] = product(p_[k - 1], a);
  }
  const J& base() const { return base_; }
  PATCHLAB_LANES_INLINE J operator()(int k) const {
    if (k <= top_) return p_[k];
    J r = p_[top_];
    for (int i = top_; i < k; ++i) r = product(r, base_);
    return r;
  }

 private:
  static J constant_one() {
    J one{};
    one.f += 1.0;
    return one;
  }
  Scratch<J, kCap> p_;
  J base_;
  int top_ = 0;
};
using Powers = PowersOf<Jet>;

// The samples (bit b for sample b; bit 0 for one sample) where D = lambda_{i-1} + lambda_i
// vanishes: |D| / |grad D| (about the distance to a side where it does) below kOnSide.
inline constexpr double kOnSide = 1e-12;
template <class J>
PATCHLAB_LANES_INLINE uint32_t on_side_lanes(const J& D) {
  uint32_t on = 0;
  for (int b = 0; b < lane_count<decltype(D.f)>; ++b) {
    const double f = lane_value(D.f, b), fu = lane_value(D.fu, b), fv = lane_value(D.fv, b);
    // hypot() is slow and needed only near the sides: 2 (|fu| + |fv|) >= 2 hypot(fu, fv), far
    // beyond any rounding, so where the cheap test says "off the side" the hypot() test does too.
    if (!(std::fabs(f) > 2 * kOnSide * (std::fabs(fu) + std::fabs(fv))) &&
        !(std::fabs(f) > kOnSide * std::hypot(fu, fv)))
      on |= 1u << b;
  }
  return on;
}

// The power tables of ribbon i at one sample (T = double) or a block of samples (a lane type):
// lambda_i, lambda_{i-1}, D = lambda_{i-1} + lambda_i, 1 / D and h_i, and which samples lie on
// a side where D vanishes.
template <class T>
struct RibbonPowersOf {
  using J = JetOf<T>;

  PowersOf<J> la, lb, dp, rp, hp;
  uint32_t on_side = 0;  // bit b: sample b is on such a side (bit 0 for one sample)

  PATCHLAB_LANES_INLINE void build(const J& lam_i, const J& lam_prev, const J& D, const J& h, int d,
                                   int l) {
    const int m = 2 * l - 1;
    la.build(lam_i, d);
    lb.build(lam_prev, d);
    hp.build(h, l - 1);
    // Exponents of D: m - k - d for k = 0 .. l - 1 in basis(), l - d and l - 1 - k in evaluate().
    dp.build(D, std::max(m - d, l - 1));
    on_side = on_side_lanes(D);
    // 1 / D is only needed (and only finite) off the sides where D vanishes.
    constexpr uint32_t all = lane_count<T> == 32 ? ~0u : (1u << lane_count<T>)-1;
    if (d - l > 0 && on_side != all) rp.build(reciprocal(D), d - l);
  }
};
using RibbonPowers = RibbonPowersOf<double>;

// la^ja lb^jb D^e with D = la + lb, total degree q = ja + jb + e >= 2. Where D vanishes (x on a
// side away from this ribbon, so la and lb vanish too, all to first order along the same normal
// n) the value and gradient are 0 and the Hessian is 2 c n n^T, c the product of the normal
// slopes: the exact limit of the 0/0 quotient. Same operations, in the same order, as
// pow(la, ja) * pow(lb, jb) * pow(D, e) (pow(1 / D, -e) for e < 0).
inline Jet homogeneous(const RibbonPowers& t, int ja, int jb, int e) {
  if (e >= 0) return t.la(ja) * t.lb(jb) * t.dp(e);
  if (!t.on_side) return t.la(ja) * t.lb(jb) * t.rp(-e);
  const Jet& D = t.dp.base();
  const double g = std::hypot(D.fu, D.fv);
  if (ja + jb + e >= 3 || g == 0) return Jet(0.0);
  const Jet &la = t.la.base(), &lb = t.lb.base();
  const double nx = D.fu / g, ny = D.fv / g;
  const double ca = la.fu * nx + la.fv * ny, cb = lb.fu * nx + lb.fv * ny;
  const double c = std::pow(ca, ja) * std::pow(cb, jb) * std::pow(g, e);
  return Jet(0, 0, 0, 2 * c * nx * nx, 2 * c * nx * ny, 2 * c * ny * ny);
}

}  // namespace pl
