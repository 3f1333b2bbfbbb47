// Bernstein polynomials composed with a Jet argument, for rational blending functions that are
// written in local parameters (GB patches: B_j^d(s_i(u,v)) B_k^d(h_i(u,v))).
#pragma once

#include <span>

#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"

namespace pl {

// Scalar values d0, first d1 and second d2 derivatives of all B_j^d at t, d <= kMax. One
// de Casteljau-like triangle: its rows d-2 and d-1 give the derivatives
// (B_j^d)' = d (B_{j-1}^{d-1} - B_j^{d-1}), and likewise for the second derivative.
struct BernsteinTable {
  static constexpr int kMax = 32;
  double d0[kMax + 1], d1[kMax + 1], d2[kMax + 1];
  BernsteinTable(int degree, double t) {
    const double s = 1 - t;
    const int d = degree;
    // One step of the triangle: from degree n-1 values in `in` to degree n in `out`.
    const auto step = [s, t](const double* in, double* out, int n) {
      out[0] = s * in[0];
      for (int k = 1; k < n; ++k) out[k] = t * in[k - 1] + s * in[k];
      out[n] = t * in[n - 1];
    };
    double r1[kMax + 1], r2[kMax + 1];  // degree d-1 and d-2
    if (d == 0) {
      d0[0] = 1, d1[0] = d2[0] = 0;
      return;
    }
    r2[0] = 1;
    for (int n = 1; n <= d - 2; ++n) {  // in place, from the top down
      r2[n] = t * r2[n - 1];
      for (int k = n - 1; k >= 1; --k) r2[k] = t * r2[k - 1] + s * r2[k];
      r2[0] *= s;
    }
    if (d >= 2)
      step(r2, r1, d - 1);
    else
      r1[0] = 1;
    step(r1, d0, d);
    for (int j = 0; j <= d; ++j) {
      d1[j] = d * ((j > 0 ? r1[j - 1] : 0.0) - (j < d ? r1[j] : 0.0));
      d2[j] = d >= 2
                  ? d * (d - 1) *
                        ((j >= 2 ? r2[j - 2] : 0.0) - 2 * (j >= 1 && j <= d - 1 ? r2[j - 1] : 0.0) +
                         (j <= d - 2 ? r2[j] : 0.0))
                  : 0.0;
    }
  }
  // B_j^d(t(u,v)) by the chain rule, t the argument jet the table was built at.
  Jet compose(int j, const Jet& t) const { return chain(t, d0[j], d1[j], d2[j]); }
};

// One polynomial B_j^d(t) with derivatives, by integer powers (no std::pow).
inline Jet bernstein_jet(int d, int j, const Jet& t) {
  const double x = t.f, y = 1 - x, c = binomial(d, j);
  double xp[3] = {0, 0, 0}, yp[3] = {0, 0, 0};      // x^(j-2..j), y^(d-j-2..d-j)
  auto powers = [](double b, int e, double* out) {  // out[2] = b^e, out[1] = b^(e-1), out[0]...
    double p = 1;
    for (int i = 0; i < e - 2; ++i) p *= b;
    if (e >= 2) out[0] = p, p *= b;
    if (e >= 1) out[1] = p, p *= b;
    out[2] = p;
  };
  powers(x, j, xp);
  powers(y, d - j, yp);
  const int a = j, b = d - j;
  const double g = c * xp[2] * yp[2];
  const double g1 = c * (a * xp[1] * yp[2] - b * xp[2] * yp[1]);
  const double g2 =
      c * (a * (a - 1) * xp[0] * yp[2] - 2.0 * a * b * xp[1] * yp[1] + b * (b - 1) * xp[2] * yp[0]);
  return chain(t, g, g1, g2);
}

}  // namespace pl
