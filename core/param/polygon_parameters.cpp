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
// The Wachspress weights w_i = C_i * (product of the side areas L_m but sides i and i+1) by
// prefix and suffix products, for Jet and for JetLanes with the same operations.
template <class J, class Linear>
[[gnu::always_inline]] inline void wachspress_weights(int n, const Linear* L, const double* corner,
                                                      const J& one, J* prefix, J* suffix, J* w) {
  const auto scaled = [](const J& a, double c) -> J {
    return {a.f * c, a.fu * c, a.fv * c, a.fuu * c, a.fuv * c, a.fvv * c};
  };
  prefix[0] = one;
  for (int m = 0; m < n; ++m) prefix[m + 1] = jet_times_linear(prefix[m], L[m]);
  suffix[n] = one;
  for (int m = n - 1; m >= 0; --m) suffix[m] = jet_times_linear(suffix[m + 1], L[m]);
  for (int i = 0; i + 1 < n; ++i) w[i] = scaled(jet_product(prefix[i], suffix[i + 2]), corner[i]);
  J p = one;  // i = n-1 omits sides n-1 and 0
  for (int m = 1; m < n - 1; ++m) p = jet_times_linear(p, L[m]);
  w[n - 1] = scaled(p, corner[n - 1]);
}
}  // namespace

void PolygonParameters::evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s, std::span<Jet> h,
                                 uint32_t sides) const {
  const int n = n_;
  Scratch<Jet, kMaxSides> L, w;
  Scratch<Jet, kMaxSides + 1> prefix, suffix;
  for (int m = 0; m < n; ++m) L[m] = side_area(m, x);
  wachspress_weights(n, L.data(), corner_.data(), Jet(1.0), prefix.data(), suffix.data(), w.data());
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

template <class V>
[[gnu::always_inline]] inline void PolygonParameters::lanes(const V& u, const V& v,
                                                            JetLanesOf<V>* s, JetLanesOf<V>* h,
                                                            uint32_t sides) const {
  using J = JetLanesOf<V>;
  const int n = n_;
  LinearLanesOf<V> L[kMaxSides];
  // Neighbour indices without wrap(): its modulo costs more than a block's arithmetic.
  const auto before = [n](int i) { return i == 0 ? n - 1 : i - 1; };
  const auto after = [n](int i) { return i + 1 == n ? 0 : i + 1; };
  for (int m = 0; m < n; ++m) {
    const Vec2 a = vertices_[before(m)], e = vertices_[m] - a;
    L[m] = {e.x * (v - a.y) - e.y * (u - a.x), -e.y, e.x};
  }
  // evaluate()'s operations, so that every lane computes evaluate()'s numbers.
  J w[kMaxSides], prefix[kMaxSides + 1], suffix[kMaxSides + 1];
  wachspress_weights(n, L, corner_.data(), constant_lanes<V>(1.0), prefix, suffix, w);
  J total = constant_lanes<V>(0);
  for (int i = 0; i < n; ++i) add_to(total, w[i]);
  const J r = reciprocal(total);
  for (int i = 0; i < n; ++i) {
    if (!(sides >> i & 1u)) continue;
    J rest = constant_lanes<V>(0);  // every vertex not on side i, as evaluate() sums them
    for (int j = 0; j < n; ++j)
      if (j != before(i) && j != i) add_to(rest, w[j]);
    h[i] = product(rest, r);
    const LinearLanesOf<V>& prev = L[before(i)];
    const LinearLanesOf<V>& next = L[after(i)];
    const double ci = corner_[i], cp = corner_[before(i)];
    const LinearLanesOf<V> num{ci * prev.f, ci * prev.fu, ci * prev.fv};
    const LinearLanesOf<V> den{cp * next.f + num.f, cp * next.fu + num.fu, cp * next.fv + num.fv};
    // As a full product in evaluate()'s operand order: s is 0/0-like near the far vertices of a
    // triangle, where a different summation order of its Hessian shows.
    const V z{};
    s[i] = product(J{num.f, z + num.fu, z + num.fv, z, z, z}, reciprocal(den));
  }
}

PATCHLAB_LANES_CLONES
void PolygonParameters::evaluate_lanes(const Lane& u, const Lane& v, JetLanes* s, JetLanes* h,
                                       uint32_t sides) const {
  lanes(u, v, s, h, sides);
}

PATCHLAB_LANES_WIDE
void PolygonParameters::evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* s,
                                       WideJetLanes* h, uint32_t sides) const {
  lanes(u, v, s, h, sides);
}

}  // namespace pl
