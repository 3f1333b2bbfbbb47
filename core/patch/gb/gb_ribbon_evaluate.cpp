// GBRibbonPatch away from the domain vertices, written once as a template over the number type T:
// double for one sample (evaluate()) and Lane or WideLane for a block of samples, one per SIMD
// lane (evaluate_many()). The core is built without FMA contraction, so a lane computes the
// scalar path's numbers bit for bit. The rare samples on a side where some D_i vanishes (the
// one-sided limits of the homogeneous form, which do not factor) and the domain vertices are
// left to the scalar path.
#include <algorithm>
#include <cassert>

#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gb/ribbon.hpp"
#include "core/patch/gb/ribbon_local.hpp"
#include "core/patch/gb/shared_basis.hpp"

namespace pl {

template <class T>
PATCHLAB_LANES_INLINE uint32_t GBRibbonPatch::quotient_form(const RibbonLocalOf<T>& L,
                                                            const T* origin,
                                                            VectorJet<T, 4>& S) const {
  // Over a convex domain D_i = lambda_i-1 + lambda_i > 0 inside, and the blends are those of the
  // papers, b_jk = mu_j B^d_j(s_i) B^m_k(h_i) with s_i = lambda_i / D_i: polynomials in (s_i, h_i)
  // per weight group (alpha for 2j < d, 1 for 2j = d, beta for 2j > d), summed over the points
  // with plain numbers and carried to (u, v) by the chain rule once per group, as GBPatch's
  // ribbons are (ribbon.hpp). The point and its weight are carried together (coordinate 3).
  // With beta_i = 1 - alpha_i+1 (blend.hpp),
  //   sum_i (alpha_i A_i + M_i + beta_i B_i) = sum_i (M_i + B_i) + sum_i alpha_i (A_i - B_i-1),
  // one rational product per ribbon. Returns the samples on a side where some D_i vanishes
  // (s_i is 0/0 there): their values here are not used.
  using J = JetOf<T>;
  const int n = sides();
  uint32_t on_side = 0;
  VectorJet<T, 4> A0, B_prev, diff;
  clear(S);
  for (int i = 0; i < n; ++i) {
    const int d = degree_[i], l = layers_[i], m = 2 * l - 1;
    const J& prev = L.lam[i == 0 ? n - 1 : i - 1];
    const J D = sum(prev, L.lam[i]);
    on_side |= on_side_lanes(D);
    const J r = reciprocal(D), s = product(L.lam[i], r);
    // 1 - s = lambda_i-1 / D and 1 - h = D from the coordinates themselves, not by subtraction:
    // near a corner they are small, and 1 - s or 1 - h would keep only the digits of s or h
    // beyond it (the powers of 1 - h are those of D that the homogeneous form takes directly).
    const BernsteinTableOf<T> bs(d, s.f, prev.f * r.f), bh(m, L.h[i].f, D.f);
    const std::size_t row0 = offset_[i], end0 = offset_[(i + 1) % n], inner = offset_[i] + d;
    // The (s, h) jets of the alpha, middle and beta points.
    VectorJet<T, 4> G[3];
    for (auto& g : G) clear(g);
    const int last_alpha = (d - 1) / 2, first_beta = d / 2 + 1;
    T H[3]{};  // sum over k < l of B^m_k(h) and its two derivatives
    for (int k = 0; k < l; ++k) {
      const T h0 = bh.d0[k], h1 = bh.d1[k], h2 = bh.d2[k];
      H[0] += h0, H[1] += h1, H[2] += h2;
      const auto add_rows = [&](int first, int last, VectorJet<T, 4>& g) {
        T r0[3]{}, r1[3]{}, r2[3]{};
        for (int j = first; j <= last; ++j) {
          const Vec3& c = points_[k > 0 ? inner + (k - 1) * (d + 1) + j : j < d ? row0 + j : end0];
          const T p[3] = {c.x - origin[0], c.y - origin[1], c.z - origin[2]};
          for (int q = 0; q < 3; ++q) {
            r0[q] += bs.d0[j] * p[q];
            r1[q] += bs.d1[j] * p[q];
            r2[q] += bs.d2[j] * p[q];
          }
        }
        for (int q = 0; q < 3; ++q) {
          g.c[0][q] += h0 * r0[q];
          g.c[1][q] += h0 * r1[q];
          g.c[3][q] += h0 * r2[q];
          g.c[2][q] += h1 * r0[q];
          g.c[4][q] += h1 * r1[q];
          g.c[5][q] += h2 * r0[q];
        }
      };
      add_rows(0, last_alpha, G[0]);
      if (d % 2 == 0) add_rows(d / 2, d / 2, G[1]);
      add_rows(first_beta, d, G[2]);
    }
    // The weights separate: sum_j sum_k B_j(s) B_k(h) = (sum_j B_j(s)) (sum_k B_k(h)).
    const auto add_weights = [&](int first, int last, VectorJet<T, 4>& g) {
      T w0{}, w1{}, w2{};
      for (int j = first; j <= last; ++j) w0 += bs.d0[j], w1 += bs.d1[j], w2 += bs.d2[j];
      g.c[0][3] = w0 * H[0], g.c[1][3] = w1 * H[0], g.c[3][3] = w2 * H[0];
      g.c[2][3] = w0 * H[1], g.c[4][3] = w1 * H[1], g.c[5][3] = w0 * H[2];
    };
    add_weights(0, last_alpha, G[0]);
    if (d % 2 == 0) add_weights(d / 2, d / 2, G[1]);
    add_weights(first_beta, d, G[2]);
    VectorJet<T, 4> A, B;
    to_uv(G[0], s, L.h[i], A);
    to_uv(G[2], s, L.h[i], B);
    add_to(S, B);
    if (d % 2 == 0) {
      VectorJet<T, 4> M;
      to_uv(G[1], s, L.h[i], M);
      add_to(S, M);
    }
    if (i == 0) {
      A0 = A;
    } else {
      difference(A, B_prev, diff);
      add_times(S, diff, L.alpha[i]);
    }
    B_prev = B;
  }
  difference(A0, B_prev, diff);
  add_times(S, diff, L.alpha[0]);
  return on_side;
}

template <class T>
PATCHLAB_LANES_INLINE uint32_t GBRibbonPatch::surface_at(const T& u, const T& v,
                                                         SurfaceJet* out) const {
  // S = N / W with N = sum b_jk C_jk, W = sum b_jk, summed directly instead of normalising every
  // basis function (no per-sample heap allocation, no pow() per term). Off the limit case,
  //   b_jk = [binom(d, j) lambda_i^j lambda_i-1^(d-j) D_i^(l-d) mu_j] [binom(m, k) h_i^k
  //          D_i^(l-1-k)] = a_j H_k,
  // so N_i = sum_k H_k (sum_j a_j C_jk) and W_i = (sum_j a_j)(sum_k H_k): a few jet products
  // per row and per j instead of several per term. The lowest power of D (negative for d > l)
  // goes with the lambdas, as in basis(), so the huge 1 / D^(d-l) near other ribbons' sides meets
  // the tiny lambda powers first instead of overflowing with h's. Equal to the basis() sum up to
  // rounding.
  using J = JetOf<T>;
  constexpr int W = lane_count<T>;
  const int n = sides();
  const RibbonLocalOf<T> L(params_, u, v);
  // Summed relative to the corner point of the largest lambda: near a corner the two ribbons
  // meeting there give that point weights whose second derivatives are huge (those of mu grow
  // like 1 / distance^2) and cancel only in their sum. Multiplied by the point before summing,
  // the cancellation would cost ~|C| 1e-16 / distance^2 (worse than basis(), which adds the two
  // weights first); relative to the point itself those terms are exactly zero.
  Vec3 origin[W];
  T ox{}, oy{}, oz{};
  for (int b = 0; b < W; ++b) {
    int near = 0;
    for (int i = 1; i < n; ++i)
      if (lane_value(L.lam[i].f, b) > lane_value(L.lam[near].f, b)) near = i;
    origin[b] = points_[offset_[(near + 1) % n]];
    set_lane_value(ox, b, origin[b].x), set_lane_value(oy, b, origin[b].y);
    set_lane_value(oz, b, origin[b].z);
  }
  const auto put = [&](const J& px, const J& py, const J& pz) {
    for (int b = 0; b < W; ++b) {
      const Jet x = lane(px, b), y = lane(py, b), z = lane(pz, b);
      SurfaceJet& s = out[b];
      s.p = origin[b] + Vec3(x.f, y.f, z.f);
      s.su = {x.fu, y.fu, z.fu};
      s.sv = {x.fv, y.fv, z.fv};
      s.suu = {x.fuu, y.fuu, z.fuu};
      s.suv = {x.fuv, y.fuv, z.fuv};
      s.svv = {x.fvv, y.fvv, z.fvv};
    }
  };
  if (convex_) {
    VectorJet<T, 4> S;
    const T o[3] = {ox, oy, oz};
    const uint32_t on_side = quotient_form(L, o, S);
    if (W > 1 || !on_side) {
      const auto row = [&](int q) -> J {
        return {S.c[0][q], S.c[1][q], S.c[2][q], S.c[3][q], S.c[4][q], S.c[5][q]};
      };
      const J inv = reciprocal(row(3));
      put(product(row(0), inv), product(row(1), inv), product(row(2), inv));
      return on_side;  // those lanes to the scalar path, which sums them below
    }
  }
  struct Point {
    T x, y, z;
  };
  J w = constant_jet<T>(0.0), sx = w, sy = w, sz = w;
  uint32_t scalar_lanes = 0;  // lanes the scalar path must redo
  RibbonPowersOf<T> t;
  Scratch<J, kMaxDegree + 1> A;
  for (int i = 0; i < n; ++i) {
    const int d = degree_[i], l = layers_[i], m = 2 * l - 1;
    const J& prev = L.lam[i == 0 ? n - 1 : i - 1];
    t.build(L.lam[i], prev, sum(prev, L.lam[i]), L.h[i], d, l);
    // Storage of C^i_{j,k}: see index(); row 0 ends at the next ribbon's first point.
    const std::size_t row0 = offset_[i], end0 = offset_[(i + 1) % n], inner = offset_[i] + d;
    const auto point_at = [&](int j, int k) -> Point {
      const Vec3& c = points_[k > 0 ? inner + (k - 1) * (d + 1) + j : j < d ? row0 + j : end0];
      return {c.x - ox, c.y - oy, c.z - oz};
    };
    if (t.on_side && d > l) {
      if constexpr (W > 1) {
        scalar_lanes |= t.on_side;
      } else {
        // x on a side where D_i vanishes and some exponent of D_i is negative: the terms are the
        // one-sided limits of homogeneous(), which do not factor; this is rare (boundary
        // samples), so sum term by term as basis() does.
        for (int k = 0; k < l; ++k) {
          const Jet hk = binomial(m, k) * t.hp(k);
          for (int j = 0; j <= d; ++j) {
            const Jet b = weighted(binomial(d, j) * homogeneous(t, j, d - j, m - k - d) * hk,
                                   ribbon_mu(d, j), L.alpha.data(), i, n);
            const Point c = point_at(j, k);
            sx += b * c.x, sy += b * c.y, sz += b * c.z;
            w += b;
          }
        }
        continue;
      }
    }
    J asum = constant_jet<T>(0.0), hsum = asum;
    for (int j = 0; j <= d; ++j) {
      // homogeneous(t, j, d - j, l - d) off the limit case.
      A[j] = weighted(
          scaled(product(product(t.la(j), t.lb(d - j)), l >= d ? t.dp(l - d) : t.rp(d - l)),
                 binomial(d, j)),
          ribbon_mu(d, j), L.alpha.data(), i, n);
      add_to(asum, A[j]);
    }
    // Rows first: l jet products per coordinate instead of d + 1 (l <= d + 1 in practice).
    for (int k = 0; k < l; ++k) {
      const J Hk = product(scaled(t.hp(k), binomial(m, k)), t.dp(l - 1 - k));
      add_to(hsum, Hk);
      J vx = constant_jet<T>(0.0), vy = vx, vz = vx;
      for (int j = 0; j <= d; ++j) {
        const Point c = point_at(j, k);
        add_to(vx, scaled(A[j], c.x)), add_to(vy, scaled(A[j], c.y)), add_to(vz, scaled(A[j], c.z));
      }
      add_to(sx, product(Hk, vx)), add_to(sy, product(Hk, vy)), add_to(sz, product(Hk, vz));
    }
    add_to(w, product(asum, hsum));
  }
  const J inv = reciprocal(w);
  put(product(sx, inv), product(sy, inv), product(sz, inv));
  return scalar_lanes;
}

SurfaceJet GBRibbonPatch::evaluate(Vec2 x) const {
  // At a vertex the weights are 0/0 and basis() has the exact corner limits.
  for (const Vec2& vertex : domain_.vertices())
    if (x == vertex) return Patch::evaluate(x);
  SurfaceJet s;
  surface_at(x.x, x.y, &s);
  return s;
}

PATCHLAB_LANES_CLONES
uint32_t GBRibbonPatch::evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out) const {
  return surface_at(u, v, out);
}

PATCHLAB_LANES_WIDE
uint32_t GBRibbonPatch::evaluate_lanes(const WideLane& u, const WideLane& v,
                                       SurfaceJet* out) const {
  return surface_at(u, v, out);
}

template <class V>
void GBRibbonPatch::evaluate_blocks(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
  constexpr int width = lane_count<V>;
  const Vec2 inside = domain_.interior_point();
  const auto& vertices = domain_.vertices();
  SurfaceJet block[width];
  for (std::size_t first = 0; first < xs.size(); first += width) {
    const int count = static_cast<int>(std::min<std::size_t>(width, xs.size() - first));
    V u = V{} + inside.x, v = V{} + inside.y;  // padding: any point off the sides
    uint32_t scalar = 0;
    for (int b = 0; b < count; ++b) {
      const Vec2 x = xs[first + b];
      if (std::find(vertices.begin(), vertices.end(), x) != vertices.end()) {
        scalar |= 1u << b;  // the corner limits
        continue;
      }
      u[b] = x.x, v[b] = x.y;
    }
    scalar |= evaluate_lanes(u, v, block);
    for (int b = 0; b < count; ++b)
      out[first + b] = scalar >> b & 1u ? evaluate(xs[first + b]) : block[b];
  }
}

void GBRibbonPatch::evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
  assert(xs.size() == out.size());
  if (convex_ && !shared_basis_bypassed()) return evaluate_shared(xs, out);
  if (wide_lanes())
    evaluate_blocks<WideLane>(xs, out);
  else
    evaluate_blocks<Lane>(xs, out);
}

}  // namespace pl
