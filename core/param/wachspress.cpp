#include "core/param/wachspress.hpp"

#include <stdexcept>
#include <string>

namespace pl {

WachspressParameters::WachspressParameters(std::vector<Vec2> vertices)
    : Parameterization(std::move(vertices)) {
  if (sides() < 3 || sides() > kMaxSides)
    throw std::invalid_argument("Wachspress parameters need 3 to " + std::to_string(kMaxSides) +
                                " vertices, got " + std::to_string(sides()));
  corner_.resize(sides());
  for (int i = 0; i < sides(); ++i)
    corner_[i] = cross(vertex(i) - vertex(i - 1), vertex(i + 1) - vertex(i));
}

namespace {
// The Wachspress weights w_i = C_i * (product of the side areas L_m but sides i and i+1) by
// prefix and suffix products.
template <class J, class Linear>
[[gnu::always_inline]] inline void wachspress_weights(int n, const Linear* L, const double* corner,
                                                      const J& one, J* prefix, J* suffix, J* w) {
  prefix[0] = one;
  for (int m = 0; m < n; ++m) prefix[m + 1] = jet_times_linear(prefix[m], L[m]);
  suffix[n] = one;
  for (int m = n - 1; m >= 0; --m) suffix[m] = jet_times_linear(suffix[m + 1], L[m]);
  for (int i = 0; i + 1 < n; ++i) w[i] = scaled(product(prefix[i], suffix[i + 2]), corner[i]);
  J p = one;  // i = n-1 omits sides n-1 and 0
  for (int m = 1; m < n - 1; ++m) p = jet_times_linear(p, L[m]);
  w[n - 1] = scaled(p, corner[n - 1]);
}
}  // namespace

template <class T>
[[gnu::always_inline]] inline void WachspressParameters::sample(const T& u, const T& v,
                                                                JetOf<T>* lambda, JetOf<T>* s,
                                                                JetOf<T>* h, SideMask sides) const {
  using J = JetOf<T>;
  const int n = this->sides();
  // Neighbour indices without wrap(): its modulo costs more than a block's arithmetic.
  const auto before = [n](int i) { return i == 0 ? n - 1 : i - 1; };
  const auto after = [n](int i) { return i + 1 == n ? 0 : i + 1; };
  Scratch<LinearLanesOf<T>, kMaxSides> L;  // side m runs from v_{m-1} to v_m; L_m > 0 inside
  for (int m = 0; m < n; ++m) {
    const Vec2 a = vertices_[before(m)], e = vertices_[m] - a;
    L[m] = {e.x * (v - a.y) - e.y * (u - a.x), -e.y, e.x};
  }
  Scratch<J, kMaxSides> w;
  Scratch<J, kMaxSides + 1> prefix, suffix;
  const J zero = constant_jet<T>(0);
  wachspress_weights(n, L.data(), corner_.data(), constant_jet<T>(1.0), prefix.data(),
                     suffix.data(), w.data());
  J total = zero;
  for (int i = 0; i < n; ++i) add_to(total, w[i]);
  const J r = reciprocal(total);
  if (lambda)
    for (int i = 0; i < n; ++i) lambda[i] = product(w[i], r);
  if (h) sums_off_side<kMaxSides + 1>(n, w.data(), h, sides, zero, &r);  // off side i, over all
  if (s)
    for (int i = 0; i < n; ++i) {
      if (!(sides >> i & 1u)) continue;
      const LinearLanesOf<T>& prev = L[before(i)];
      const LinearLanesOf<T>& next = L[after(i)];
      const double ci = corner_[i], cp = corner_[before(i)];
      const LinearLanesOf<T> num{ci * prev.f, ci * prev.fu, ci * prev.fv};
      const LinearLanesOf<T> den{cp * next.f + num.f, cp * next.fu + num.fu, cp * next.fv + num.fv};
      s[i] = product(linear_jet(num), reciprocal(den));
    }
}

void WachspressParameters::evaluate(Vec2 x, std::span<Jet> lambda, std::span<Jet> s,
                                    std::span<Jet> h, SideMask sides) const {
  sample<double>(x.x, x.y, lambda.empty() ? nullptr : lambda.data(), s.empty() ? nullptr : s.data(),
                 h.empty() ? nullptr : h.data(), sides);
}

PATCHLAB_LANES_CLONES
void WachspressParameters::evaluate_lanes(const Lane& u, const Lane& v, JetLanes* s, JetLanes* h,
                                          SideMask sides) const {
  sample(u, v, nullptr, s, h, sides);
}

PATCHLAB_LANES_WIDE
void WachspressParameters::evaluate_lanes(const WideLane& u, const WideLane& v, WideJetLanes* s,
                                          WideJetLanes* h, SideMask sides) const {
  sample(u, v, nullptr, s, h, sides);
}

}  // namespace pl
