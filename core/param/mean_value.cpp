#include "core/param/mean_value.hpp"

#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

void mean_value_coordinates(std::span<const Vec2> poly, Vec2 x, std::span<Jet> out) {
  constexpr int N = MeanValueParameters::kMaxSides;
  const std::size_t n = poly.size();
  assert(out.size() == n && n >= 3 && n <= std::size_t(N));
  Scratch<Jet, N> dx, dy, r, t, area, dot;
  for (std::size_t i = 0; i < n; ++i) {
    dx[i] = Jet(poly[i].x - x.x, -1, 0, 0, 0, 0);
    dy[i] = Jet(poly[i].y - x.y, 0, -1, 0, 0, 0);
    r[i] = sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
  }
  // The segment nearest to x (if x projects inside it): its weight term is the one that blows
  // up at the boundary, so every weight is multiplied by its signed area A_k, turning
  // A_k tan(alpha_k / 2) into r_k r_k+1 - D_k (as A^2 = (r r - D)(r r + D)).
  std::size_t k = n;
  double best = INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % n], ab = b - a;
    const double s = glm::dot(x - a, ab) / glm::dot(ab, ab);
    if (!(s > 0 && s < 1)) continue;
    const double d = glm::length(x - (a + s * ab));
    if (d < best) best = d, k = i;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    area[i] = dx[i] * dy[j] - dy[i] * dx[j];
    dot[i] = dx[i] * dx[j] + dy[i] * dy[j];
  }
  // tan(alpha_i / 2) = A_i / (r_i r_i+1 + D_i): finite wherever x is off segment i, including
  // on the segment's line extension (where the (r r - D) / A form is 0/0).
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (k < n && i == k)
      t[i] = r[i] * r[j] - dot[i];
    else if (k < n)
      t[i] = area[k] * area[i] / (r[i] * r[j] + dot[i]);
    else
      t[i] = area[i] / (r[i] * r[j] + dot[i]);
  }
  Jet sum(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = (t[(i + n - 1) % n] + t[i]) / r[i];
    sum += out[i];
  }
  const Jet inv = reciprocal(sum);
  for (std::size_t i = 0; i < n; ++i) out[i] = out[i] * inv;
}

MeanValueParameters::MeanValueParameters(std::vector<Vec2> vertices)
    : Parameterization(std::move(vertices)) {
  if (sides() < 3 || sides() > kMaxSides)
    throw std::invalid_argument("mean value parameters need 3 to " + std::to_string(kMaxSides) +
                                " vertices, got " + std::to_string(sides()));
}

void MeanValueParameters::evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s,
                                   std::span<Jet> h, SideMask sides) const {
  const int n = this->sides();
  Scratch<Jet, kMaxSides> own;
  const std::span<Jet> lam = lambda.empty() ? std::span<Jet>(own.data(), n) : lambda;
  mean_value_coordinates(vertices_, x, lam);
  if (!h.empty()) sums_off_side<kMaxSides + 1>(n, lam.data(), h.data(), sides, Jet(0.0));
  if (!s.empty())
    for (int i = 0; i < n; ++i)
      if (sides >> i & 1u) s[i] = lam[i] / (lam[wrap(i - 1)] + lam[i]);
}

}  // namespace pl
