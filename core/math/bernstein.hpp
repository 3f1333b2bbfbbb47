// Bernstein polynomials B_i^n(t) = C(n,i) t^i (1-t)^(n-i), with derivatives.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/math/jet.hpp"

namespace pl {

namespace detail {
// C(n, k) by the product (n-k+1)/1 * (n-k+2)/2 * ..., each step rounded: exact for these n.
constexpr double binomial_product(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}
inline constexpr int kBinomialRows = 65;
// Computed at compile time with the same operations (IEEE double, one rounding each), so a
// table entry is bitwise the product; the blends of GB patches look these up per term.
inline constexpr auto kBinomials = [] {
  std::array<std::array<double, kBinomialRows>, kBinomialRows> t{};
  for (int n = 0; n < kBinomialRows; ++n)
    for (int k = 0; k <= n; ++k) t[n][k] = binomial_product(n, k);
  return t;
}();
}  // namespace detail

// C(n, k); 0 for k outside 0..n.
inline double binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  if (n < detail::kBinomialRows) return detail::kBinomials[n][k];
  return detail::binomial_product(n, k);
}

// All n+1 Bernstein values of degree n at t (de Casteljau-like triangle, stable on [0,1]).
void bernstein_all(int n, double t, std::span<double> out);

// Values, first and second derivatives of all n+1 polynomials: d0[i], d1[i], d2[i].
void bernstein_all_d2(int n, double t, std::span<double> d0, std::span<double> d1,
                      std::span<double> d2);

// One Bernstein polynomial composed with a jet argument: B_i^n(t(u,v)) with exact derivatives.
Jet bernstein(int n, int i, const Jet& t);

}  // namespace pl
