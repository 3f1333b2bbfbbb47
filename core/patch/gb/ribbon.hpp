// The ribbons of a central-point GB patch: the control rows P^i_{j,k} (j = 0..d along side i,
// k = 0..l-1 inwards) of every side, and their Bernstein evaluation
//   R_i(s, h) = sum_k B^d_k(h) sum_j B^d_j(s) c_{j,k} P^i_{j,k}
// with its first and second (s, h) derivatives, then carried to (u, v) by the chain rule.
//
// The rows are stored per weight group of the blend (blend.hpp: constant and beta points, alpha
// points, beta points), relative to the central point and multiplied by their factor in the
// group (c_{j,k} above), contiguously, so that the sums over j read consecutive memory and the
// patch needs no index gather per sample. Templates over the number type T (double for one sample,
// Lane or WideLane for a block of samples, one per SIMD lane) run the same operations on either.
#pragma once

#include <vector>

#include "core/math/bernstein_jets.hpp"
#include "core/math/lanes.hpp"
#include "core/math/vec.hpp"
#include "core/patch/gb/blend.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl {

// A vector-valued function with its first and second derivatives, per lane: c[r][x], rows
// r = value, d1, d2, d11, d12, d22 in the variables at hand ((s, h) or (u, v)), x = coordinate
// (C of them: 3 for a point, 4 for a point and its weight).
template <class T, int C = 3>
struct VectorJet {
  T c[6][C];
};

template <class T, int C>
PATCHLAB_LANES_INLINE void clear(VectorJet<T, C>& a) {
  for (auto& row : a.c)
    for (T& x : row) x = T{};
}

// Sample b of a (u, v) vector jet as a SurfaceJet.
template <class T, int C>
PATCHLAB_LANES_INLINE SurfaceJet surface_jet(const VectorJet<T, C>& S, int b) {
  SurfaceJet o;
  Vec3* rows[6] = {&o.p, &o.su, &o.sv, &o.suu, &o.suv, &o.svv};
  for (int r = 0; r < 6; ++r) {
    if constexpr (std::is_same_v<T, double>)
      *rows[r] = Vec3(S.c[r][0], S.c[r][1], S.c[r][2]);
    else
      *rows[r] = Vec3(S.c[r][0][b], S.c[r][1][b], S.c[r][2][b]);
  }
  return o;
}

// The (u, v) jet of G(s(u, v), h(u, v)) from its (s, h) jet, coordinate by coordinate.
template <class T, int C>
PATCHLAB_LANES_INLINE void to_uv(const VectorJet<T, C>& G, const JetOf<T>& s, const JetOf<T>& h,
                                 VectorJet<T, C>& out) {
  const T ss_u = s.fu * s.fu, sh_u = 2 * s.fu * h.fu, hh_u = h.fu * h.fu;
  const T ss_uv = s.fu * s.fv, sh_uv = s.fu * h.fv + s.fv * h.fu, hh_uv = h.fu * h.fv;
  const T ss_v = s.fv * s.fv, sh_v = 2 * s.fv * h.fv, hh_v = h.fv * h.fv;
  for (int c = 0; c < C; ++c) {
    const T g = G.c[0][c], gs = G.c[1][c], gh = G.c[2][c];
    const T gss = G.c[3][c], gsh = G.c[4][c], ghh = G.c[5][c];
    out.c[0][c] = g;
    out.c[1][c] = s.fu * gs + h.fu * gh;
    out.c[2][c] = s.fv * gs + h.fv * gh;
    out.c[3][c] = ss_u * gss + sh_u * gsh + hh_u * ghh + s.fuu * gs + h.fuu * gh;
    out.c[4][c] = ss_uv * gss + sh_uv * gsh + hh_uv * ghh + s.fuv * gs + h.fuv * gh;
    out.c[5][c] = ss_v * gss + sh_v * gsh + hh_v * ghh + s.fvv * gs + h.fvv * gh;
  }
}

template <class T, int C>
PATCHLAB_LANES_INLINE void add_to(VectorJet<T, C>& S, const VectorJet<T, C>& D) {
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < C; ++c) S.c[r][c] += D.c[r][c];
}

// D = A - B.
template <class T, int C>
PATCHLAB_LANES_INLINE void difference(const VectorJet<T, C>& A, const VectorJet<T, C>& B,
                                      VectorJet<T, C>& D) {
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < C; ++c) D.c[r][c] = A.c[r][c] - B.c[r][c];
}

// S += D w, w a scalar (u, v) jet: the product rule.
template <class T, int C>
PATCHLAB_LANES_INLINE void add_times(VectorJet<T, C>& S, const VectorJet<T, C>& D,
                                     const JetOf<T>& w) {
  for (int c = 0; c < C; ++c) {
    const T p = D.c[0][c], su = D.c[1][c], sv = D.c[2][c];
    S.c[0][c] += p * w.f;
    S.c[1][c] += su * w.f + p * w.fu;
    S.c[2][c] += sv * w.f + p * w.fv;
    S.c[3][c] += D.c[3][c] * w.f + 2.0 * w.fu * su + p * w.fuu;
    S.c[4][c] += D.c[4][c] * w.f + su * w.fv + sv * w.fu + p * w.fuv;
    S.c[5][c] += D.c[5][c] * w.f + 2.0 * w.fv * sv + p * w.fvv;
  }
}

class RibbonRows {
 public:
  // mu: the central patch's rule per grid position, [k * (d+1) + j].
  RibbonRows(int sides, int degree, int layers, const std::vector<Mu>& mu);

  // Stores grid point (i, j, k) of rule m, given relative to the central point.
  void set(int i, int j, int k, Mu m, const Vec3& relative);
  // Whether group g of this patch has any point.
  bool has_group(int g) const { return g == 0 || has_corner_weights(d_); }

  // G += the (s, h) jet of the group-g rows of side i, given the Bernstein tables at s_i, h_i.
  template <class T>
  PATCHLAB_LANES_INLINE void add_group(int i, int g, const BernsteinTableOf<T>& bs,
                                       const BernsteinTableOf<T>& bh, VectorJet<T>& G) const {
    for (int k = 0; k < l_; ++k) {
      const Span sp = span_[g * l_ + k];
      if (sp.first > sp.last) continue;
      const Vec3* P = &rows_[((i * kMuGroups + g) * l_ + k) * (d_ + 1)];
      T r0[3]{}, r1[3]{}, r2[3]{};
      for (int j = sp.first; j <= sp.last; ++j)
        for (int c = 0; c < 3; ++c) {
          r0[c] += bs.d0[j] * P[j][c];
          r1[c] += bs.d1[j] * P[j][c];
          r2[c] += bs.d2[j] * P[j][c];
        }
      const T h0 = bh.d0[k], h1 = bh.d1[k], h2 = bh.d2[k];
      for (int c = 0; c < 3; ++c) {
        G.c[0][c] += h0 * r0[c];
        G.c[1][c] += h0 * r1[c];
        G.c[3][c] += h0 * r2[c];
        G.c[2][c] += h1 * r0[c];
        G.c[4][c] += h1 * r1[c];
        G.c[5][c] += h2 * r0[c];
      }
    }
  }

 private:
  int n_, d_, l_;
  // rows_[((i * kMuGroups + g) * l + k) * (d+1) + j] = mu_group_factor * (P - C_0) for the
  // grid point (i, j, k): 0 unless it belongs to group g.
  std::vector<Vec3> rows_;
  // The j range [first, last] of the non-zero entries of group g, row k: span_[g * l + k].
  struct Span {
    int first, last;
  };
  std::vector<Span> span_;
};

}  // namespace pl
