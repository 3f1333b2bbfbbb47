// Bernstein polynomials composed with a Jet argument, for rational blending functions that are
// written in local parameters (GB patches: B_j^d(s_i(u,v)) B_k^d(h_i(u,v))).
#pragma once

#include <span>

#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"

namespace pl {

// Scalar values d0, first d1 and second d2 derivatives of all B_j^d at t, d <= 62.
struct BernsteinTable {
  static constexpr int kMax = 32;
  double d0[kMax + 1], d1[kMax + 1], d2[kMax + 1];
  BernsteinTable(int degree, double t) { bernstein_all_d2(degree, t, d0, d1, d2); }
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
