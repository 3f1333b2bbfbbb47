// The Bernstein evaluation of an independent ribbon (gb_ribbon_patch.hpp) in homogeneous form.
// With s_i = lambda_i / D_i, D_i = lambda_{i-1} + lambda_i and 1 - h_i = D_i,
//   B^d_j(s_i) B^m_k(h_i) = binom(d, j) binom(m, k) lambda_i^j lambda_{i-1}^(d-j) D_i^(m-k-d)
//   h_i^k,
// which stays defined where s_i is 0/0 (the sides away from side i, where both lambdas vanish):
// there it is the exact one-sided limit. The powers of one sample are tabled once per ribbon.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"
#include "core/math/scratch.hpp"

namespace pl {

// The largest ribbon degree and layer count the gb-ribbons format accepts.
inline constexpr int kMaxRibbonDegree = 30, kMaxRibbonLayers = 15;

// a^0 .. a^top (top <= kCap - 1), each by repeated multiplication from 1 like pow(a, k), so a
// table entry is bitwise the value pow() gives. Exponents past the table continue the
// multiplication, so the values stay those of pow() for any degree.
class Powers {
 public:
  static constexpr int kCap = 2 * kMaxRibbonLayers + 2;
  static_assert(kCap > kMaxRibbonDegree);

  void build(const Jet& a, int top) {
    base_ = a;
    top_ = std::min(std::max(top, 0), kCap - 1);
    p_[0] = Jet(1.0);
    for (int k = 1; k <= top_; ++k) p_[k] = p_[k - 1] * a;
  }
  const Jet& base() const { return base_; }
  Jet operator()(int k) const {
    if (k <= top_) return p_[k];
    Jet r = p_[top_];
    for (int i = top_; i < k; ++i) r = r * base_;
    return r;
  }

 private:
  Scratch<Jet, kCap> p_;
  Jet base_;
  int top_ = 0;
};

// The power tables of ribbon i at one sample: lambda_i, lambda_{i-1}, D = lambda_{i-1} +
// lambda_i, 1 / D and h_i, and whether x lies on a side where D vanishes.
struct RibbonPowers {
  // Where |D| / |grad D| (about the distance to a side) is below this, x is on that side.
  static constexpr double kOnSide = 1e-12;

  Powers la, lb, dp, rp, hp;
  bool on_side = false;

  void build(const Jet& lam_i, const Jet& lam_prev, const Jet& D, const Jet& h, int d, int l) {
    const int m = 2 * l - 1;
    la.build(lam_i, d);
    lb.build(lam_prev, d);
    hp.build(h, l - 1);
    // Exponents of D: m - k - d for k = 0 .. l - 1 in basis(), l - d and l - 1 - k in evaluate().
    dp.build(D, std::max(m - d, l - 1));
    // hypot() is slow and needed only near the sides: 2 (|fu| + |fv|) >= 2 hypot(fu, fv), far
    // beyond any rounding, so where the cheap test says "off the side" the hypot() test does too.
    on_side = !(std::fabs(D.f) > 2 * kOnSide * (std::fabs(D.fu) + std::fabs(D.fv))) &&
              !(std::fabs(D.f) > kOnSide * std::hypot(D.fu, D.fv));
    // 1 / D is only needed (and only finite) off the sides where D vanishes.
    if (d - l > 0 && !on_side) rp.build(reciprocal(D), d - l);
  }
};

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
