#include "core/math/bspline_basis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

void validate_knots(int p, std::span<const double> U, std::size_t n) {
  if (p < 1 || p > kMaxSplineDegree)
    throw std::invalid_argument("spline degree must be between 1 and 15, got " + std::to_string(p));
  if (n < static_cast<std::size_t>(p) + 1)
    throw std::invalid_argument("degree " + std::to_string(p) + " needs at least " +
                                std::to_string(p + 1) + " control points, got " +
                                std::to_string(n));
  if (U.size() != n + p + 1)
    throw std::invalid_argument("expected " + std::to_string(n + p + 1) +
                                " knots (points + degree + 1), got " + std::to_string(U.size()));
  for (std::size_t i = 0; i < U.size(); ++i) {
    if (!std::isfinite(U[i]))
      throw std::invalid_argument("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && U[i] < U[i - 1])
      throw std::invalid_argument("knots must not decrease (knot " + std::to_string(i) + ")");
  }
  for (std::size_t i = p + 1; i < n; ++i) {  // interior knots
    std::size_t m = 1;
    while (i + m < n && U[i + m] == U[i]) ++m;
    if (m > static_cast<std::size_t>(p))
      throw std::invalid_argument("interior knot " + std::to_string(U[i]) + " has multiplicity " +
                                  std::to_string(m) +
                                  " > degree: the spline would be disconnected");
  }
  if (!(U[p] < U[n])) throw std::invalid_argument("the knot vector has an empty parameter range");
}

int find_span(int p, std::span<const double> U, std::size_t n, double t) {
  const auto first = U.begin() + p, last = U.begin() + static_cast<std::ptrdiff_t>(n);
  int i = static_cast<int>(std::upper_bound(first, last, t) - U.begin()) - 1;
  i = std::clamp(i, p, static_cast<int>(n) - 1);
  while (i > p && U[i] == U[i + 1]) --i;  // t at the end of the range: last non-empty span
  return i;
}

int find_span(int p, std::span<const double> U, std::size_t n, double t, int hint) {
  // Where U[h] <= t < U[h + 1] the search above stops at h too (the first knot above t is
  // U[h + 1], or the range ends there), and h is not an empty span.
  const auto in = [&](int h) { return h >= p && h < int(n) && U[h] <= t && t < U[h + 1]; };
  if (in(hint)) return hint;
  if (in(hint + 1)) return hint + 1;
  return find_span(p, U, n, t);
}

SplineBasis spline_basis(int p, std::span<const double> U, std::size_t n, double t) {
  return spline_basis_at(p, U, find_span(p, U, n, t), t);
}

SplineBasis spline_basis_at(int p, std::span<const double> U, int span, double t) {
  SplineBasis b;
  const int s = b.span = span;
  // level[k][r] = N_{s-k+r, k}(t), r = 0..k: every degree up to p (derivatives need p-1, p-2).
  double level[kMaxSplineDegree + 1][kMaxSplineDegree + 1];
  level[0][0] = 1;
  auto N = [&](int k, int i) {  // N_{i,k}, zero outside the non-zero set at this span
    const int r = i - (s - k);
    return (r < 0 || r > k) ? 0.0 : level[k][r];
  };
  auto ratio = [&](double num, int a, int b) { return U[b] == U[a] ? 0.0 : num / (U[b] - U[a]); };
  for (int k = 1; k <= p; ++k)
    for (int r = 0; r <= k; ++r) {
      const int i = s - k + r;
      level[k][r] = ratio(t - U[i], i, i + k) * N(k - 1, i) +
                    ratio(U[i + k + 1] - t, i + 1, i + k + 1) * N(k - 1, i + 1);
    }
  // N'_{i,k} = k (N_{i,k-1} / (U[i+k]-U[i]) - N_{i+1,k-1} / (U[i+k+1]-U[i+1])), applied twice.
  auto dN = [&](int k, int i) {
    return k * (ratio(N(k - 1, i), i, i + k) - ratio(N(k - 1, i + 1), i + 1, i + k + 1));
  };
  for (int r = 0; r <= p; ++r) {
    const int i = s - p + r;
    b.d0[r] = level[p][r];
    b.d1[r] = dN(p, i);
    b.d2[r] = p >= 2
                  ? p * (ratio(dN(p - 1, i), i, i + p) - ratio(dN(p - 1, i + 1), i + 1, i + p + 1))
                  : 0.0;
  }
  return b;
}

}  // namespace pl
