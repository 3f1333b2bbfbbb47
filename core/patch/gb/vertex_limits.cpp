#include "core/patch/gb/vertex_limits.hpp"

#include <cmath>
#include <vector>

#include "core/math/bernstein_jets.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {

void gb_vertex_basis(const GBPatch& g, int v, std::span<Jet> out) {
  // Exact limits at vertex v along the ray theta to the centre. Ribbon a = v ends at v and
  // ribbon b = v+1 starts there; their shared 2x2 corner block is weighted X_k (1 - r) + Y_k r
  // with X_k, Y_k the smooth Bernstein products of ribbons a and b and r = alpha_b =
  // h_a / (h_a + h_b), 0/0 at v. D_k = Y_k - X_k vanishes with its gradient at v (the blocks
  // are shared), so r D_k has value and gradient 0 there and its Hessian's limit is that of
  // r0 * (second-order part of D_k), r0 the ratio of the linear parts of h_a, h_b.
  // Every other ribbon m has lambda_{m-1} = lambda_m = 0 at v, and its products are
  // C h^k lambda_{m-1}^(d-j) lambda_m^j / (lambda_{m-1} + lambda_m)^k: homogeneous of degree
  // d - k in two vanishing functions, so only degree <= 2 leaves a (second-order) trace.
  const int n = g.sides(), d = g.degree(), l = g.layers();
  const WachspressParameters& params = g.parameters();
  const Vec2 x = g.polygon().vertex(v), theta = g.polygon().interior_point() - x;
  Scratch<Jet, GBPatch::kMaxSides> lambda, s, h, alpha;
  params.evaluate(x, std::span(lambda.data(), n), std::span(s.data(), n), std::span(h.data(), n));
  const int a = params.wrap(v), b = params.wrap(v + 1);
  // alpha_i is smooth at v for every i but b (where it is the 0/0 ratio r above).
  if (has_corner_weights(d)) corner_alphas(n, h.data(), alpha.data(), ~(uint64_t{1} << b));
  const auto linear = [&](const Jet& f) {  // the linear part of f at x, evaluated at x + theta
    return Jet(f.fu * theta.x + f.fv * theta.y, f.fu, f.fv, 0, 0, 0);
  };
  const auto hessian_only = [](const Jet& f) { return Jet(0, 0, 0, f.fuu, f.fuv, f.fvv); };
  std::vector<Jet> X(g.size()), Y(g.size());
  std::vector<char> block(g.size(), 0);
  for (Jet& j : out) j = Jet();
  for (int m = 0; m < n; ++m) {
    if (m == a || m == b) {
      const BernsteinTable bs(d, s[m].f), bh(d, h[m].f);
      for (int k = 0; k < l; ++k)
        for (int j = 0; j <= d; ++j) {
          const Mu mu = g.mu(j, k);
          if (mu == Mu::Zero) continue;
          const std::size_t idx = g.index(m, j, k);
          const Jet w = bs.compose(j, s[m]) * bh.compose(k, h[m]);
          if (m == a && mu == Mu::Beta)
            X[idx] += w, block[idx] = 1;
          else if (m == b && mu == Mu::Alpha)
            Y[idx] += w, block[idx] = 1;
          else
            out[idx] += weighted(w, mu, alpha.data(), m, n);
        }
      continue;
    }
    const Jet &A = lambda[params.wrap(m - 1)], &B = lambda[m];
    const Jet A0 = linear(A), B0 = linear(B), S0 = A0 + B0;
    for (int k = 0; k < l; ++k) {
      if (d - k >= 3) continue;  // vanishes to third order
      for (int j = 0; j <= d; ++j) {
        const Mu mu = g.mu(j, k);
        if (mu == Mu::Zero) continue;
        Jet F;
        if (k == 0) {
          F = pow(A, d - j) * pow(B, j);  // d <= 2: a polynomial, exact as it stands
        } else {
          if (!(std::fabs(S0.f) > 0)) continue;  // both vanish to second order: F = O(|dx|^4)
          F = hessian_only(pow(A0, d - j) * pow(B0, j) / pow(S0, k));
        }
        const Jet term = (binomial(d, j) * binomial(d, k)) * pow(h[m], k) * F;
        out[g.index(m, j, k)] += weighted(term, mu, alpha.data(), m, n);
      }
    }
  }
  const Jet P0 = linear(h[a]), Q0 = linear(h[b]);
  const Jet r0 = P0 / (P0 + Q0);
  for (std::size_t k = 0; k < g.size(); ++k) {
    if (!block[k]) continue;
    const Jet D = Y[k] - X[k];
    const Vec2 Ht(D.fuu * theta.x + D.fuv * theta.y, D.fuv * theta.x + D.fvv * theta.y);
    const Jet Dq(0.5 * (theta.x * Ht.x + theta.y * Ht.y), Ht.x, Ht.y, D.fuu, D.fuv, D.fvv);
    out[k] += X[k] + hessian_only(r0 * Dq);
  }
  Jet total;
  for (std::size_t k = 1; k < g.size(); ++k) total += out[k];
  out[0] = Jet(1.0) - total;
  const std::size_t corner = g.index(v, d, 0);
  for (std::size_t k = 0; k < g.size(); ++k) out[k].f = k == corner ? 1.0 : 0.0;
}

void gb_ribbon_corner_basis(const GBRibbonPatch& g, int vtx, std::span<Jet> out) {
  // Corner between side a = vtx (ending here) and side b = vtx + 1 (starting here). Known
  // exactly: the point, the first derivative along both sides (the curves' end tangents) and
  // the second derivative along both sides. The mixed term D^2 S[e_a, e_b] is the mean of the
  // two ribbons' twists (ribbon a: d/ds d/dh at (1, 0); ribbon b, whose h runs against e_a:
  // minus its twist at (0, 0)).
  const int n = g.sides(), a = vtx, b = (vtx + 1) % n;
  struct Coef {
    double val = 0, da = 0, db = 0, aa = 0, bb = 0, ab = 0;
  };
  std::vector<Coef> c(g.size());
  const auto at = [&](int side, int j, int k) -> Coef& { return c[g.index(side, j, k)]; };
  const int d = g.degree(a), m = 2 * g.layers(a) - 1;
  const int e = g.degree(b), mb = 2 * g.layers(b) - 1;
  at(a, d, 0).val += 1;
  at(a, d, 0).da += d;
  at(a, d - 1, 0).da -= d;
  at(b, 1, 0).db += e;
  at(b, 0, 0).db -= e;
  if (d >= 2) {
    at(a, d, 0).aa += d * (d - 1);
    at(a, d - 1, 0).aa -= 2 * d * (d - 1);
    at(a, d - 2, 0).aa += d * (d - 1);
  }
  if (e >= 2) {
    at(b, 0, 0).bb += e * (e - 1);
    at(b, 1, 0).bb -= 2 * e * (e - 1);
    at(b, 2, 0).bb += e * (e - 1);
  }
  const double ta = 0.5 * m * d, tb = -0.5 * mb * e;
  at(a, d, 1).ab += ta;
  at(a, d - 1, 1).ab -= ta;
  at(a, d, 0).ab -= ta;
  at(a, d - 1, 0).ab += ta;
  at(b, 1, 1).ab += tb;
  at(b, 0, 1).ab -= tb;
  at(b, 1, 0).ab -= tb;
  at(b, 0, 0).ab += tb;
  const Vec2 ea = g.polygon().vertex(a) - g.polygon().vertex(a - 1);
  const Vec2 eb = g.polygon().vertex(a + 1) - g.polygon().vertex(a);
  const double det = cross(ea, eb);
  // Columns of E^-1, E = [e_a e_b]: grad = E^-T (da, db), Hessian = E^-T K E^-1.
  const double p = eb.y / det, q = -eb.x / det, r = -ea.y / det, s = ea.x / det;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Coef& f = c[k];
    out[k] = Jet(f.val, p * f.da + r * f.db, q * f.da + s * f.db,
                 p * p * f.aa + 2 * p * r * f.ab + r * r * f.bb,
                 p * q * f.aa + (p * s + r * q) * f.ab + r * s * f.bb,
                 q * q * f.aa + 2 * q * s * f.ab + s * s * f.bb);
  }
}

}  // namespace pl
