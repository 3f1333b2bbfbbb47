#include "core/math/bernstein.hpp"

#include <cassert>
#include <cmath>

namespace pl {

void bernstein_all(int n, double t, std::span<double> out) {
  assert(static_cast<int>(out.size()) >= n + 1);
  const double s = 1 - t;
  out[0] = 1;
  for (int j = 1; j <= n; ++j) {
    double saved = 0;
    for (int k = 0; k < j; ++k) {
      const double tmp = out[k];
      out[k] = saved + s * tmp;
      saved = t * tmp;
    }
    out[j] = saved;
  }
}

void bernstein_all_d2(int n, double t, std::span<double> d0, std::span<double> d1,
                      std::span<double> d2) {
  // d/dt B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}); second derivative likewise from degree n-2.
  double lower1[64], lower2[64];
  assert(n < 64);
  bernstein_all(n, t, d0);
  for (int i = 0; i <= n; ++i) d1[i] = d2[i] = 0;
  if (n >= 1) {
    bernstein_all(n - 1, t, lower1);
    for (int i = 0; i <= n; ++i) {
      const double a = i > 0 ? lower1[i - 1] : 0;
      const double b = i < n ? lower1[i] : 0;
      d1[i] = n * (a - b);
    }
  }
  if (n >= 2) {
    bernstein_all(n - 2, t, lower2);
    for (int i = 0; i <= n; ++i) {
      const double a = (i >= 2) ? lower2[i - 2] : 0;
      const double b = (i >= 1 && i - 1 <= n - 2) ? lower2[i - 1] : 0;
      const double c = (i <= n - 2) ? lower2[i] : 0;
      d2[i] = n * (n - 1) * (a - 2 * b + c);
    }
  }
}

Jet bernstein(int n, int i, const Jet& t) {
  if (i < 0 || i > n) return Jet(0.0);
  // g(x) = C x^i (1-x)^(n-i); first and second derivatives in closed form.
  const double x = t.f, y = 1 - x, c = binomial(n, i);
  auto ipow = [](double b, int e) { return e < 0 ? 0.0 : std::pow(b, e); };
  const int a = i, b = n - i;
  const double g = c * ipow(x, a) * ipow(y, b);
  double g1 = 0, g2 = 0;
  if (a >= 1) g1 += c * a * ipow(x, a - 1) * ipow(y, b);
  if (b >= 1) g1 -= c * b * ipow(x, a) * ipow(y, b - 1);
  if (a >= 2) g2 += c * a * (a - 1) * ipow(x, a - 2) * ipow(y, b);
  if (a >= 1 && b >= 1) g2 -= 2 * c * a * b * ipow(x, a - 1) * ipow(y, b - 1);
  if (b >= 2) g2 += c * b * (b - 1) * ipow(x, a) * ipow(y, b - 2);
  return chain(t, g, g1, g2);
}

}  // namespace pl
