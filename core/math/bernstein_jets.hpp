// Bernstein polynomials composed with a Jet argument, for rational blending functions that are
// written in local parameters (GB patches: B_j^d(s_i(u,v)) B_k^d(h_i(u,v))).
//
// The tables are templates over the number type so that batched evaluation (T = Lane, one sample
// per SIMD lane) runs exactly the scalar operations.
#pragma once

#include <span>

#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"

namespace pl {

// Scalar values d0, first d1 and second d2 derivatives of all B_j^d at t, d <= kMax. One
// de Casteljau-like triangle: its rows d-2 and d-1 give the derivatives
// (B_j^d)' = d (B_{j-1}^{d-1} - B_j^{d-1}), and likewise for the second derivative.
template <class T>
struct BernsteinTableOf {
  static constexpr int kMax = 32;
  T d0[kMax + 1], d1[kMax + 1], d2[kMax + 1];
  [[gnu::always_inline]] BernsteinTableOf(int degree, const T& t)
      : BernsteinTableOf(degree, t, 1.0 - t) {}
  // With 1 - t given: where t is near 1 and 1 - t is known to more digits than t's own rounding
  // leaves it (a small quantity the caller has directly), the powers of 1 - t keep them.
  [[gnu::always_inline]] BernsteinTableOf(int degree, const T& t, const T& s) {
    const T zero{};
    const int d = degree;
    T r1[kMax + 1], r2[kMax + 1];  // degree d-1 and d-2
    if (d == 0) {
      d0[0] = zero + 1.0, d1[0] = d2[0] = zero;
      return;
    }
    r2[0] = zero + 1.0;
    for (int n = 1; n <= d - 2; ++n) {  // in place, from the top down
      r2[n] = t * r2[n - 1];
      for (int k = n - 1; k >= 1; --k) r2[k] = t * r2[k - 1] + s * r2[k];
      r2[0] *= s;
    }
    if (d >= 2)
      step(s, t, r2, r1, d - 1);
    else
      r1[0] = zero + 1.0;
    step(s, t, r1, d0, d);
    for (int j = 0; j <= d; ++j) {
      d1[j] = double(d) * ((j > 0 ? r1[j - 1] : zero) - (j < d ? r1[j] : zero));
      d2[j] = d >= 2 ? double(d * (d - 1)) * ((j >= 2 ? r2[j - 2] : zero) -
                                              2.0 * (j >= 1 && j <= d - 1 ? r2[j - 1] : zero) +
                                              (j <= d - 2 ? r2[j] : zero))
                     : zero;
    }
  }

 private:
  // One step of the triangle: from degree n-1 values in `in` to degree n in `out`.
  [[gnu::always_inline]] static void step(const T& s, const T& t, const T* in, T* out, int n) {
    out[0] = s * in[0];
    for (int k = 1; k < n; ++k) out[k] = t * in[k - 1] + s * in[k];
    out[n] = t * in[n - 1];
  }
};

struct BernsteinTable : BernsteinTableOf<double> {
  BernsteinTable(int degree, double t) : BernsteinTableOf<double>(degree, t) {}
  // B_j^d(t(u,v)) by the chain rule, t the argument jet the table was built at.
  Jet compose(int j, const Jet& t) const { return chain(t, d0[j], d1[j], d2[j]); }
};

namespace detail {
// out[2] = b^e, out[1] = b^(e-1), out[0] = b^(e-2) (those with a non-negative exponent).
template <class T>
[[gnu::always_inline]] inline void top_powers(const T& b, int e, T* out) {
  T p = T{} + 1.0;
  for (int i = 0; i < e - 2; ++i) p *= b;
  if (e >= 2) out[0] = p, p *= b;
  if (e >= 1) out[1] = p, p *= b;
  out[2] = p;
}
}  // namespace detail

// One polynomial B_j^d at x with its first two derivatives g1, g2, by integer powers (no
// std::pow).
template <class T>
[[gnu::always_inline]] inline void bernstein_d2(int d, int j, const T& x, T& g, T& g1, T& g2) {
  const T zero{}, y = 1.0 - x;
  const double c = binomial(d, j);
  T xp[3] = {zero, zero, zero}, yp[3] = {zero, zero, zero};  // x^(j-2..j), y^(d-j-2..d-j)
  detail::top_powers(x, j, xp);
  detail::top_powers(y, d - j, yp);
  const double a = j, b = d - j;
  g = c * xp[2] * yp[2];
  g1 = c * (a * xp[1] * yp[2] - b * xp[2] * yp[1]);
  g2 =
      c * (a * (a - 1) * xp[0] * yp[2] - 2.0 * a * b * xp[1] * yp[1] + b * (b - 1) * xp[2] * yp[0]);
}

// One polynomial B_j^d(t) with derivatives.
inline Jet bernstein_jet(int d, int j, const Jet& t) {
  double g, g1, g2;
  bernstein_d2(d, j, t.f, g, g1, g2);
  return chain(t, g, g1, g2);
}

}  // namespace pl
