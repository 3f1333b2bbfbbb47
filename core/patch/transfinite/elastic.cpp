// The elastic patch after M. Sabin, "Further transfinite surface developments", in The
// Mathematics of Surfaces VIII (1998), as the authors of the ribbon-based schemes implement it
// (salvipeter/transfinite, SurfaceElastic). Every side i contributes, from its foot point
// b_i = (1 - s_i) v_{i-1} + s_i v_i (s_i the bilinear parameter) at domain distance
// delta_i = |x - b_i|, its boundary point P_i(s_i) and the ribbon's step T_i = D_i(s_i) delta_i,
// weighted by omega_i = delta_i^-3, to a 3 x 3 linear system for the point X_0 and a gradient
// G = (G_u, G_v):
//   sum_i omega_i [2 X_0 + Delta_i . G]            = sum_i omega_i (2 P_i + T_i)
//   sum_i omega_i Delta_i [3 X_0 + 2 Delta_i . G]  = sum_i omega_i Delta_i (3 P_i + T_i)
// with Delta_i = x - b_i; the surface is X_0. No distance reparameterization, no corner data.
//
// Solved as written, the system is singular on the boundary and loses about 1e-16 / delta of its
// digits near it (delta^-5 in the second derivatives), since one side's weight swamps the rest.
// Here it is solved for the same X_0 in unknowns scaled to the nearest side k instead:
// X_0 = P_k + delta_k alpha, G = g_e e + g_n e_perp with e the direction of Delta_k (the line of
// constant s_k), the first equation times delta_k^2 and the second's e and e_perp components
// times delta_k and 1. On side k this reads 2 alpha + g_e = D_k, 3 alpha + 2 g_e = D_k, so
// alpha = D_k: the patch interpolates P_k and its derivative along e is D_k (G1 to the ribbons),
// and value and derivatives stay exact on and near the boundary. delta_k is written as
// d_k |q_k(s_k)| (the bilinear d and the direction q of the line of constant s), which is smooth
// through the side.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

namespace {

Jet clamp01(const Jet& s) {
  return s.f < 0 ? Jet(0.0) : s.f > 1 ? Jet(1.0) : s;
}

// One side's foot point data at x.
struct Foot {
  Jet du, dv;           // Delta_i
  SurfaceJet p, cross;  // P_i(s_i), D_i(s_i)
};

Foot foot(const SchemeInput& in, int i, const Jet& s_raw, const Jet& u, const Jet& v) {
  const Jet s = clamp01(s_raw);
  const Vec2 a = in.domain.vertex(i - 1), b = in.domain.vertex(i);
  const RibbonCurves& r = in.ribbons.side(i);
  return {u - ((1.0 - s) * a.x + s * b.x), v - ((1.0 - s) * a.y + s * b.y),
          compose(r.curve.at(s.f), s), compose(r.cross.at(s.f), s)};
}

SurfaceJet divided(const SurfaceJet& s, const Jet& d) {
  return reciprocal(d) * s;
}

// The first unknown of M z = R by Gaussian elimination with partial pivoting, in jets.
SurfaceJet first_unknown(std::array<std::array<Jet, 3>, 3> M, std::array<SurfaceJet, 3> R) {
  for (int k = 0; k < 3; ++k) {
    int pivot = k;
    for (int j = k + 1; j < 3; ++j)
      if (std::abs(M[j][k].f) > std::abs(M[pivot][k].f)) pivot = j;
    std::swap(M[k], M[pivot]);
    std::swap(R[k], R[pivot]);
    const Jet inv = reciprocal(M[k][k]);
    for (int j = k + 1; j < 3; ++j) {
      const Jet f = M[j][k] * inv;
      for (int l = k; l < 3; ++l) M[j][l] -= f * M[k][l];
      R[j] -= f * R[k];
    }
  }
  const SurfaceJet z2 = divided(R[2], M[2][2]);
  const SurfaceJet z1 = divided(R[1] - M[1][2] * z2, M[1][1]);
  return divided(R[0] - M[0][1] * z1 - M[0][2] * z2, M[0][0]);
}

}  // namespace

SurfaceJet elastic_surface(const SchemeInput& in, Vec2 x) {
  const PolygonParameters& dom = in.domain;
  const int n = in.ribbons.size();
  const SideParameters par = dom.bilinear(x);
  const Jet u = Jet::u(x.x), v = Jet::v(x.y);
  std::vector<Foot> feet;
  feet.reserve(std::size_t(n));
  int k = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    feet.push_back(foot(in, i, par.s[std::size_t(i)], u, v));
    const double d = std::hypot(feet.back().du.f, feet.back().dv.f);
    if (d < nearest) nearest = d, k = i;
  }

  // Side k: delta = d_k |q|, q = (1 - s) (v_{k-2} - v_{k-1}) + s (v_{k+1} - v_k) the direction of
  // the bilinear quadrilateral's line of constant s (x = b_k + d_k q).
  const Jet s = clamp01(par.s[std::size_t(k)]);
  const Vec2 qa = dom.vertex(k - 2) - dom.vertex(k - 1), qb = dom.vertex(k + 1) - dom.vertex(k);
  const Jet qx = (1.0 - s) * qa.x + s * qb.x, qy = (1.0 - s) * qa.y + s * qb.y;
  const Jet qlen = sqrt(qx * qx + qy * qy);
  const Jet ex = qx / qlen, ey = qy / qlen;
  const Jet delta = par.d[std::size_t(k)] * qlen;
  const Foot& fk = feet[std::size_t(k)];

  std::array<std::array<Jet, 3>, 3> M{};
  std::array<SurfaceJet, 3> R{};
  M[0][0] = 2.0, M[0][1] = 1.0, R[0] = fk.cross;
  M[1][0] = 3.0, M[1][1] = 2.0, R[1] = fk.cross;
  const Jet delta2 = delta * delta;
  for (int i = 0; i < n; ++i) {
    if (i == k) continue;
    const Foot& f = feet[std::size_t(i)];
    const Jet di = sqrt(f.du * f.du + f.dv * f.dv);
    const Jet w = reciprocal(di * di * di);
    const Jet pe = f.du * ex + f.dv * ey;  // Delta_i . e
    const Jet pn = f.dv * ex - f.du * ey;  // Delta_i . e_perp
    const SurfaceJet gap = fk.p - f.p, step = di * f.cross;
    const SurfaceJet two = 2.0 * gap - step, three = 3.0 * gap - step;
    const Jet wa = delta2 * w, wb = delta * w * pe, wc = w * pn;
    M[0][0] += 2.0 * (wa * delta), M[0][1] += wa * pe, M[0][2] += wa * pn;
    R[0] -= wa * two;
    M[1][0] += 3.0 * (wb * delta), M[1][1] += 2.0 * (wb * pe), M[1][2] += 2.0 * (wb * pn);
    R[1] -= wb * three;
    M[2][0] += 3.0 * (wc * delta), M[2][1] += 2.0 * (wc * pe), M[2][2] += 2.0 * (wc * pn);
    R[2] -= wc * three;
  }
  return fk.p + delta * first_unknown(M, R);
}

}  // namespace pl::transfinite
