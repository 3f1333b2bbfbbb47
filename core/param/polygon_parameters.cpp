#include "core/param/polygon_parameters.hpp"

#include <cassert>
#include <stdexcept>

#include "core/math/scratch.hpp"

namespace pl {

namespace {
double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
}  // namespace

PolygonParameters::PolygonParameters(std::vector<Vec2> vertices)
    : n_(static_cast<int>(vertices.size())), vertices_(std::move(vertices)) {
  if (n_ < 3 || n_ > kMaxSides)
    throw std::invalid_argument("polygon parameters need 3 to " + std::to_string(kMaxSides) +
                                " vertices");
  corner_.resize(n_);
  for (int i = 0; i < n_; ++i)
    corner_[i] = cross(vertex(i) - vertex(i - 1), vertex(i + 1) - vertex(i));
}

Jet PolygonParameters::side_area(int m, Vec2 x) const {
  // Side m runs from v_{m-1} to v_m; cross(e, x - a) is linear in x, so its Hessian is zero.
  const Vec2 a = vertex(m - 1), e = vertex(m) - a;
  return {cross(e, x - a), -e.y, e.x, 0, 0, 0};
}

namespace {
// a * l for a linear l (zero Hessian): the products of side areas need no full Jet product.
inline Jet times_linear(const Jet& a, const Jet& l) {
  return {a.f * l.f,
          a.fu * l.f + a.f * l.fu,
          a.fv * l.f + a.f * l.fv,
          a.fuu * l.f + 2 * a.fu * l.fu,
          a.fuv * l.f + a.fu * l.fv + a.fv * l.fu,
          a.fvv * l.f + 2 * a.fv * l.fv};
}
}  // namespace

void PolygonParameters::evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                                 uint32_t sides) const {
  const int n = n_;
  Scratch<Jet, kMaxSides> L, w;
  Scratch<Jet, kMaxSides + 1> prefix, suffix;
  for (int m = 0; m < n; ++m) L[m] = side_area(m, x);
  // w_i omits the two sides meeting at v_i: side i and side i+1.
  prefix[0] = Jet(1.0);
  for (int m = 0; m < n; ++m) prefix[m + 1] = times_linear(prefix[m], L[m]);
  suffix[n] = Jet(1.0);
  for (int m = n - 1; m >= 0; --m) suffix[m] = times_linear(suffix[m + 1], L[m]);
  for (int i = 0; i + 1 < n; ++i) w[i] = corner_[i] * (prefix[i] * suffix[i + 2]);
  {
    Jet p(1.0);  // i = n-1 omits sides n-1 and 0
    for (int m = 1; m < n - 1; ++m) p = times_linear(p, L[m]);
    w[n - 1] = corner_[n - 1] * p;
  }
  Jet total;
  for (int i = 0; i < n; ++i) total += w[i];
  const Jet r = reciprocal(total);
  if (!lambda.empty())
    for (int i = 0; i < n; ++i) lambda[i] = w[i] * r;
  for (int i = 0; i < n; ++i) {
    if (!(sides >> i & 1u)) continue;
    if (!h.empty()) {
      Jet rest;  // sum of the weights of every vertex not on side i
      for (int j = 0; j < n; ++j)
        if (j != wrap(i - 1) && j != i) rest += w[j];
      h[i] = rest * r;
    }
    if (!s.empty()) {
      const Jet num = corner_[i] * L[wrap(i - 1)];
      s[i] = num / (corner_[wrap(i - 1)] * L[wrap(i + 1)] + num);
    }
  }
}

}  // namespace pl
