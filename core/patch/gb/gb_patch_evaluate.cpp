// GBPatch away from the domain vertices: the surface, one basis function and the central weight,
// each written once as a template over the number type T, double for one sample and Lane or
// WideLane for a block of samples (one per SIMD lane, core/math/lanes.hpp). The core is built
// without FMA contraction, so every ISA clone computes the scalar path's numbers bit for bit.
#include <algorithm>
#include <cassert>

#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/vertex_limits.hpp"

namespace pl {

template <class T>
[[gnu::always_inline]] inline void GBPatch::parameters_at(const T& u, const T& v, JetOf<T>* s,
                                                          JetOf<T>* h, SideMask sides) const {
  if constexpr (std::is_same_v<T, double>)
    params_.evaluate({u, v}, {}, std::span(s, n_), std::span(h, n_), sides);
  else
    params_.evaluate_lanes(u, v, s, h, sides);
}

template <class T>
[[gnu::always_inline]] inline VectorJet<T> GBPatch::surface_at(const T& u, const T& v) const {
  // S = C_0 + sum of the ribbon weights times (P - C_0): the central weight needs no sum.
  // Ribbon i splits into polynomial groups in (s_i, h_i) (blend.hpp): constant weights and beta
  // (C + B), alpha (A), beta (B), and
  //   S = C_0 + sum_i (C_i + B_i) + sum_i alpha_i (A_i - B_{i-1}):
  // three chain rules and one product with a rational weight per ribbon. A_i - B_{i-1} is taken
  // first because the two cancel near vertex i-1, where alpha_i's derivatives grow unbounded.
  using J = JetOf<T>;
  const int n = n_, d = d_;
  const bool corners = has_corner_weights(d);
  Scratch<J, kMaxSides> s, h, alpha;
  parameters_at(u, v, s.data(), h.data(), kAllSides);
  if (corners) corner_alphas(n, h.data(), alpha.data());
  VectorJet<T> S, A0, A, D, Bprev;
  clear(S);
  for (int c = 0; c < 3; ++c) S.c[0][c] = T{} + points_[0][c];
  for (int i = 0; i < n; ++i) {
    const BernsteinTableOf<T> bs(d, s[i].f), bh(d, h[i].f);
    VectorJet<T> G, T0;
    clear(G);
    rows_.add_group(i, 0, bs, bh, G);
    to_uv(G, s[i], h[i], T0);
    add_to(S, T0);
    if (!corners) continue;
    clear(G);
    rows_.add_group(i, 1, bs, bh, G);
    to_uv(G, s[i], h[i], i == 0 ? A0 : A);
    if (i > 0) {
      difference(A, Bprev, D);
      add_times(S, D, alpha[i]);
    }
    clear(G);
    rows_.add_group(i, 2, bs, bh, G);
    to_uv(G, s[i], h[i], Bprev);
  }
  if (corners) {
    difference(A0, Bprev, D);
    add_times(S, D, alpha[0]);
  }
  return S;
}

template <class T>
[[gnu::always_inline]] inline JetOf<T> GBPatch::weight_at(std::size_t k, const T& u,
                                                          const T& v) const {
  // phi_k (k > 0): the sum over the grid positions of point k, each B^d_j(s_i) B^d_k(h_i) mu.
  assert(k > 0);
  using J = JetOf<T>;
  const int n = n_;
  const Needs& need = needs_[k];
  Scratch<J, kMaxSides> s, h, alpha;
  parameters_at(u, v, s.data(), h.data(), need.sides);
  corner_alphas(n, h.data(), alpha.data(), need.alphas);
  J w = constant_jet<T>(0);
  for (const Occurrence& o : occurrences_[k]) {
    T g, g1, g2;
    bernstein_d2(d_, o.j, s[o.i].f, g, g1, g2);
    const J bj = chain(s[o.i], g, g1, g2);
    bernstein_d2(d_, o.k, h[o.i].f, g, g1, g2);
    const J bk = chain(h[o.i], g, g1, g2);
    add_to(w, weighted(product(bj, bk), mu(o.j, o.k), alpha.data(), o.i, n));
  }
  return w;
}

template <class T>
[[gnu::always_inline]] inline JetOf<T> GBPatch::central_weight_at(const T& u, const T& v) const {
  // phi_0 = 1 - (every other weight), summed by the groups of surface_at() with the points
  // replaced by their factors.
  using J = JetOf<T>;
  const int n = n_, d = d_, l = l_;
  const bool corners = has_corner_weights(d);
  Scratch<J, kMaxSides> s, h, alpha;
  parameters_at(u, v, s.data(), h.data(), kAllSides);
  if (corners) corner_alphas(n, h.data(), alpha.data());
  J total = constant_jet<T>(0), first{}, prev{};
  for (int i = 0; i < n; ++i) {
    const BernsteinTableOf<T> bs(d, s[i].f), bh(d, h[i].f);
    J W[kMuGroups];
    for (int g = 0; g < (corners ? kMuGroups : 1); ++g) {
      W[g] = constant_jet<T>(0);
      for (int r = 0; r < l; ++r) {
        T w0{}, w1{}, w2{};
        for (int j = 0; j <= d; ++j) {
          const double c = mu_group_factor(mu(j, r), g);
          if (c == 0) continue;
          w0 += c * bs.d0[j], w1 += c * bs.d1[j], w2 += c * bs.d2[j];
        }
        add_to(W[g], product(chain(s[i], w0, w1, w2), chain(h[i], bh.d0[r], bh.d1[r], bh.d2[r])));
      }
    }
    add_to(total, W[0]);
    if (!corners) continue;
    if (i == 0)
      first = W[1];
    else
      add_to(total, product(sum(W[1], scaled(prev, -1.0)), alpha[i]));
    prev = W[2];
  }
  if (corners) add_to(total, product(sum(first, scaled(prev, -1.0)), alpha[0]));
  return sum(constant_jet<T>(1.0), scaled(total, -1.0));
}

SurfaceJet GBPatch::evaluate_regular(Vec2 x) const {
  return surface_jet(surface_at(x.x, x.y), 0);
}

Jet GBPatch::influence_regular(std::size_t k, Vec2 x) const {
  return k == 0 ? central_weight_at(x.x, x.y) : weight_at(k, x.x, x.y);
}

PATCHLAB_LANES_CLONES
void GBPatch::evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out, int count) const {
  const VectorJet<Lane> S = surface_at(u, v);
  for (int b = 0; b < count; ++b) out[b] = surface_jet(S, b);
}

PATCHLAB_LANES_WIDE
void GBPatch::evaluate_lanes(const WideLane& u, const WideLane& v, SurfaceJet* out,
                             int count) const {
  const VectorJet<WideLane> S = surface_at(u, v);
  for (int b = 0; b < count; ++b) out[b] = surface_jet(S, b);
}

PATCHLAB_LANES_CLONES
void GBPatch::influence_lanes(std::size_t k, const Lane& u, const Lane& v, Jet* out,
                              int count) const {
  const JetLanes w = k == 0 ? central_weight_at(u, v) : weight_at(k, u, v);
  for (int b = 0; b < count; ++b) out[b] = lane(w, b);
}

PATCHLAB_LANES_WIDE
void GBPatch::influence_lanes(std::size_t k, const WideLane& u, const WideLane& v, Jet* out,
                              int count) const {
  const WideJetLanes w = k == 0 ? central_weight_at(u, v) : weight_at(k, u, v);
  for (int b = 0; b < count; ++b) out[b] = lane(w, b);
}

int GBPatch::vertex_at(Vec2 x) const {
  // Every vertex is at least vertex_distance_ from the origin: most points are nearer to it.
  if (glm::dot(x, x) < vertex_distance_ * vertex_distance_) return -1;
  const auto& vertices = domain_.vertices();
  for (int i = 0; i < n_; ++i) {
    const Vec2 d = x - vertices[i];
    if (d.x * d.x + d.y * d.y < kGBVertexRadius * kGBVertexRadius) return i;
  }
  return -1;
}

template <class V, class Lanes, class AtVertex>
void GBPatch::for_lane_blocks(std::span<const Vec2> xs, Lanes&& lanes, AtVertex&& at_vertex) const {
  constexpr int width = sizeof(V) / sizeof(double);
  const Vec2 inside = domain_.interior_point();
  for (std::size_t first = 0; first < xs.size(); first += width) {
    const int count = static_cast<int>(std::min<std::size_t>(width, xs.size() - first));
    V u = V{} + inside.x, v = V{} + inside.y;  // padding: any regular point
    uint32_t at_vertices = 0;
    for (int b = 0; b < count; ++b) {
      const Vec2 x = xs[first + b];
      if (vertex_at(x) >= 0) {
        at_vertices |= 1u << b;
        continue;
      }
      u[b] = x.x, v[b] = x.y;
    }
    lanes(u, v, first, count);
    for (int b = 0; b < count; ++b)
      if (at_vertices >> b & 1u) at_vertex(first + b);
  }
}

void GBPatch::evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
  assert(xs.size() == out.size());
  const auto lanes = [&](const auto& u, const auto& v, std::size_t first, int count) {
    evaluate_lanes(u, v, &out[first], count);
  };
  const auto at_vertex = [&](std::size_t p) { out[p] = evaluate(xs[p]); };
  if (wide_lanes())
    for_lane_blocks<WideLane>(xs, lanes, at_vertex);
  else
    for_lane_blocks<Lane>(xs, lanes, at_vertex);
}

void GBPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  const auto lanes = [&](const auto& u, const auto& v, std::size_t first, int count) {
    influence_lanes(k, u, v, &out[first], count);
  };
  const auto at_vertex = [&](std::size_t p) { out[p] = influence_at(k, xs[p]); };
  if (wide_lanes())
    for_lane_blocks<WideLane>(xs, lanes, at_vertex);
  else
    for_lane_blocks<Lane>(xs, lanes, at_vertex);
}

}  // namespace pl
