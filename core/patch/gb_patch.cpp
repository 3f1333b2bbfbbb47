#include "core/patch/gb_patch.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "core/math/bernstein_jets.hpp"
#include "core/math/lanes.hpp"
#include "core/math/scratch.hpp"

namespace pl {

namespace {

// Points closer than this to a domain vertex (domain size ~2) are evaluated through the vertex
// limit plus a first-order Taylor step: the corner weights are 0/0 at the vertex itself.
constexpr double kVertexRadius = 1e-10;
SurfaceJet times(const SurfaceJet& a, const Jet& b) {
  return {a.p * b.f,
          a.su * b.f + a.p * b.fu,
          a.sv * b.f + a.p * b.fv,
          a.suu * b.f + 2.0 * b.fu * a.su + a.p * b.fuu,
          a.suv * b.f + a.su * b.fv + a.sv * b.fu + a.p * b.fuv,
          a.svv * b.f + 2.0 * b.fv * a.sv + a.p * b.fvv};
}

void add(SurfaceJet& a, const SurfaceJet& b, double w = 1.0) {
  a.p += w * b.p;
  a.su += w * b.su;
  a.sv += w * b.sv;
  a.suu += w * b.suu;
  a.suv += w * b.suv;
  a.svv += w * b.svv;
}

// Value moved by a first-order Taylor step delta (the vertex limit applied near the vertex).
void shift(Jet& j, Vec2 delta) {
  j.f += j.fu * delta.x + j.fv * delta.y;
  j.fu += j.fuu * delta.x + j.fuv * delta.y;
  j.fv += j.fuv * delta.x + j.fvv * delta.y;
}

}  // namespace

struct GBPatch::Local {
  Scratch<Jet, kMaxSides> s, h, alpha, beta;
};

std::size_t GBPatch::point_count(int n, int d) {
  const int l = layers(d);
  return 1 + static_cast<std::size_t>(n) * (l * d - l * (l - 1));
}

GBPatch::GBPatch(int sides, int degree, std::vector<Vec3> points)
    : Patch(std::move(points)),
      n_(sides),
      d_(degree),
      l_(layers(degree)),
      domain_(ConvexPolygonDomain::regular(sides < 3 ? 3 : sides)),
      params_(domain_.vertices()) {
  if (sides < 3 || sides > kMaxSides)
    throw std::invalid_argument("a GB patch needs 3 to " + std::to_string(kMaxSides) +
                                " sides, got " + std::to_string(sides));
  if (degree < 1 || degree > kMaxDegree)
    throw std::invalid_argument("GB patch degree must be between 1 and " +
                                std::to_string(kMaxDegree) + ", got " + std::to_string(degree));
  if (points_.size() != point_count(n_, d_))
    throw std::invalid_argument("a GB patch with " + std::to_string(n_) + " sides and degree " +
                                std::to_string(d_) + " needs " +
                                std::to_string(point_count(n_, d_)) + " points, got " +
                                std::to_string(points_.size()));
  const int d = d_, l = l_;
  mu_.resize(l * (d + 1));
  for (int k = 0; k < l; ++k)
    for (int j = 0; j <= d; ++j) {
      Mu m = Mu::One;
      if (d >= 3 && k < 2 && j < 2)
        m = Mu::Alpha;
      else if (d >= 3 && k < 2 && j > d - 2)
        m = Mu::Beta;
      else if (j == k || j == d - k)
        m = Mu::Half;
      else if (j < k || j > d - k)
        m = Mu::Zero;
      mu_[k * (d + 1) + j] = m;
    }
  update_relative(0);
  vertex_distance_ = 1e300;
  for (const Vec2& v : domain_.vertices())
    vertex_distance_ =
        std::min(vertex_distance_, std::max(0.0, glm::length(v) - 2 * kVertexRadius));
  grid_.resize(n_ * l * (d + 1));
  occurrences_.assign(size(), {});
  ribbons_of_.assign(size(), 0);
  weighted_of_.assign(size(), 0);
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        const std::size_t s = index(i, j, k);
        grid_[(i * l + k) * (d + 1) + j] = static_cast<uint32_t>(s);
        if (mu(j, k) != Mu::Zero) {
          occurrences_[s].push_back({i, j, k});
          ribbons_of_[s] |= 1u << i;
          if (mu(j, k) == Mu::Alpha || mu(j, k) == Mu::Beta) weighted_of_[s] |= 1u << i;
        }
      }
  span_.assign(3 * l, Span{d + 1, -1});
  for (int k = 0; k < l; ++k)
    for (int j = 0; j <= d; ++j) {
      const Mu m = mu(j, k);
      if (m == Mu::Zero) continue;
      const auto widen = [&](int g) {
        Span& sp = span_[g * l + k];
        sp.first = std::min(sp.first, j), sp.last = std::max(sp.last, j);
      };
      widen(m == Mu::Alpha ? 1 : 0);
      if (m == Mu::Beta) widen(2);
    }
  fill_dense(0);
}

void GBPatch::fill_dense(std::size_t k) {
  const int d = d_, l = l_;
  const auto set = [&](int i, int j, int r) {
    const Vec3& P = relative_[grid_[(i * l + r) * (d + 1) + j]];
    const auto at = [&](int g) -> Vec3& { return dense_[((i * 3 + g) * l + r) * (d + 1) + j]; };
    switch (mu(j, r)) {
      case Mu::One:
        at(0) = P;
        break;
      case Mu::Half:
        at(0) = 0.5 * P;
        break;
      case Mu::Alpha:
        at(1) = P;
        break;
      case Mu::Beta:
        at(0) = P, at(2) = P;
        break;
      case Mu::Zero:
        break;
    }
  };
  if (k == 0) {  // C_0 moves every relative point
    dense_.assign(static_cast<std::size_t>(n_) * 3 * l * (d + 1), Vec3(0));
    for (int i = 0; i < n_; ++i)
      for (int r = 0; r < l; ++r)
        for (int j = 0; j <= d; ++j) set(i, j, r);
    return;
  }
  for (const Occurrence& o : occurrences_[k]) set(o.i, o.j, o.k);
}

std::size_t GBPatch::index(int i, int j, int k) const {
  assert(0 <= j && j <= d_ && 0 <= k && k < l_);
  // Shared corner blocks: a point outside the stored range k..d-1-k of its row is stored by a
  // neighbouring side (gbp-format.md), where it falls inside the range.
  if (j < k) return index(i - 1, d_ - k, j);
  if (j > d_ - 1 - k) return index(i + 1, k, d_ - j);
  std::size_t offset = 1;
  for (int r = 0; r < k; ++r) offset += static_cast<std::size_t>(n_) * (d_ - 2 * r);
  return offset + static_cast<std::size_t>(params_.wrap(i)) * (d_ - 2 * k) + (j - k);
}

ControlPointKind GBPatch::kind(std::size_t k) const {
  if (k == 0) return ControlPointKind::Central;
  return k <= static_cast<std::size_t>(n_ * d_) ? ControlPointKind::Boundary
                                                : ControlPointKind::Inner;
}

std::vector<BezierCurve> GBPatch::boundary_curves() const {
  std::vector<BezierCurve> curves;
  for (int i = 0; i < n_; ++i) {
    std::vector<Vec3> row;
    for (int j = 0; j <= d_; ++j) row.push_back(point(i, j, 0));
    curves.emplace_back(std::move(row));
  }
  return curves;
}

void GBPatch::local(Vec2 x, Local& out, uint32_t ribbons, uint32_t weighted) const {
  // Ribbon i needs s_i, h_i, and if weighted alpha_i and (for beta_i) alpha_{i+1}; alpha_i needs
  // h_{i-1}, h_i. An influence column of a point with constant weights needs no corner weight.
  const int n = n_;
  const uint32_t all = (1u << n) - 1;
  const auto rotl = [&](uint32_t m) { return ((m << 1) | (m >> (n - 1))) & all; };
  const auto rotr = [&](uint32_t m) { return ((m >> 1) | ((m & 1u) << (n - 1))) & all; };
  ribbons &= all;
  weighted &= ribbons;
  const uint32_t alphas = d_ >= 3 ? weighted | rotl(weighted) : 0;  // ribbon i or i-1 is asked
  const uint32_t sides = ribbons | alphas | rotr(alphas);
  params_.evaluate(x, {}, std::span(out.s.data(), n), std::span(out.h.data(), n), sides);
  if (d_ < 3) return;  // no corner weights
  for (int i = 0; i < n; ++i) {
    if (!(alphas >> i & 1u)) continue;
    const Jet& prev = out.h[params_.wrap(i - 1)];
    out.alpha[i] = prev / (prev + out.h[i]);
  }
  // beta_i = h_{i+1} / (h_{i+1} + h_i) = 1 - alpha_{i+1}: the two weights of a shared corner
  // point then sum to one exactly.
  for (int i = 0; i < n; ++i)
    if (weighted >> i & 1u) out.beta[i] = Jet(1.0) - out.alpha[params_.wrap(i + 1)];
}

int GBPatch::vertex_at(Vec2 x) const {
  // Every vertex is at least vertex_distance_ from the origin: most points are nearer to it.
  if (glm::dot(x, x) < vertex_distance_ * vertex_distance_) return -1;
  const auto& vertices = domain_.vertices();
  for (int i = 0; i < n_; ++i) {
    const Vec2 d = x - vertices[i];
    if (d.x * d.x + d.y * d.y < kVertexRadius * kVertexRadius) return i;
  }
  return -1;
}

namespace {
// A vector-valued polynomial in (s, h) with its partial derivatives up to second order.
struct SHJet {
  Vec3 g{0}, gs{0}, gh{0}, gss{0}, gsh{0}, ghh{0};
  void operator+=(const SHJet& b) {
    g += b.g, gs += b.gs, gh += b.gh, gss += b.gss, gsh += b.gsh, ghh += b.ghh;
  }
};
// The (u, v) jet of G(s(u,v), h(u,v)) by the chain rule.
SurfaceJet to_uv(const SHJet& G, const Jet& s, const Jet& h) {
  return {G.g,
          s.fu * G.gs + h.fu * G.gh,
          s.fv * G.gs + h.fv * G.gh,
          (s.fu * s.fu) * G.gss + (2 * s.fu * h.fu) * G.gsh + (h.fu * h.fu) * G.ghh + s.fuu * G.gs +
              h.fuu * G.gh,
          (s.fu * s.fv) * G.gss + (s.fu * h.fv + s.fv * h.fu) * G.gsh + (h.fu * h.fv) * G.ghh +
              s.fuv * G.gs + h.fuv * G.gh,
          (s.fv * s.fv) * G.gss + (2 * s.fv * h.fv) * G.gsh + (h.fv * h.fv) * G.ghh + s.fvv * G.gs +
              h.fvv * G.gh};
}
// S += to_uv(G, s, h) without the temporary (the same operations, so the same rounding).
void add_uv(SurfaceJet& S, const SHJet& G, const Jet& s, const Jet& h) {
  S.p += G.g;
  S.su += s.fu * G.gs + h.fu * G.gh;
  S.sv += s.fv * G.gs + h.fv * G.gh;
  S.suu += (s.fu * s.fu) * G.gss + (2 * s.fu * h.fu) * G.gsh + (h.fu * h.fu) * G.ghh +
           s.fuu * G.gs + h.fuu * G.gh;
  S.suv += (s.fu * s.fv) * G.gss + (s.fu * h.fv + s.fv * h.fu) * G.gsh + (h.fu * h.fv) * G.ghh +
           s.fuv * G.gs + h.fuv * G.gh;
  S.svv += (s.fv * s.fv) * G.gss + (2 * s.fv * h.fv) * G.gsh + (h.fv * h.fv) * G.ghh +
           s.fvv * G.gs + h.fvv * G.gh;
}
}  // namespace

void GBPatch::set_control_point(std::size_t k, const Vec3& p) {
  Patch::set_control_point(k, p);
  update_relative(k);
}

void GBPatch::update_relative(std::size_t k) {
  if (k == 0) {
    relative_.resize(size());
    for (std::size_t i = 0; i < size(); ++i) relative_[i] = points_[i] - points_[0];
  } else {
    relative_[k] = points_[k] - points_[0];
  }
  if (!dense_.empty()) fill_dense(k);  // empty only while the constructor builds the tables
}

SurfaceJet GBPatch::evaluate_regular(Vec2 x) const {
  // S = C_0 + sum of the ribbon weights times (P - C_0): the central weight needs no sum.
  // Ribbon i splits into polynomial groups in (s_i, h_i): constant weights (C), alpha (A) and
  // beta (B) ones. With beta_i = 1 - alpha_{i+1},
  //   sum_i (C_i + alpha_i A_i + beta_i B_i) = sum_i (C_i + B_i) + sum_i alpha_i (A_i - B_{i-1}),
  // so each ribbon needs three chain rules and one product with a rational weight. The groups'
  // points come from dense_, laid out so the row sums run over contiguous memory.
  Local L;
  local(x, L);
  const int d = d_, l = l_, groups = d >= 3 ? 3 : 1;
  SurfaceJet S;
  S.p = points_[0];
  Scratch<SurfaceJet, kMaxSides> A, B;
  for (int i = 0; i < n_; ++i) {
    const Jet &s = L.s[i], &h = L.h[i];
    const BernsteinTable bs(d, s.f), bh(d, h.f);
    SHJet G[3];  // 0: C + B, 1: A, 2: B
    for (int g = 0; g < groups; ++g)
      for (int k = 0; k < l; ++k) {
        const Span sp = span_[g * l + k];
        if (sp.first > sp.last) continue;
        const Vec3* P = &dense_[((i * 3 + g) * l + k) * (d + 1)];
        Vec3 r0(0), r1(0), r2(0);
        for (int j = sp.first; j <= sp.last; ++j) {
          r0 += bs.d0[j] * P[j];
          r1 += bs.d1[j] * P[j];
          r2 += bs.d2[j] * P[j];
        }
        const double h0 = bh.d0[k], h1 = bh.d1[k], h2 = bh.d2[k];
        G[g].g += h0 * r0;
        G[g].gs += h0 * r1;
        G[g].gss += h0 * r2;
        G[g].gh += h1 * r0;
        G[g].gsh += h1 * r1;
        G[g].ghh += h2 * r0;
      }
    if (d >= 3) {
      A[i] = to_uv(G[1], s, h);
      B[i] = to_uv(G[2], s, h);
    }
    add_uv(S, G[0], s, h);
  }
  if (d >= 3)
    for (int i = 0; i < n_; ++i) {
      SurfaceJet D = A[i];
      add(D, B[params_.wrap(i - 1)], -1.0);
      add(S, times(D, L.alpha[i]));
    }
  return S;
}

void GBPatch::basis_regular(Vec2 x, std::span<Jet> out) const {
  Local L;
  local(x, L);
  const int d = d_, l = l_;
  for (Jet& j : out) j = Jet();
  Jet total;
  Jet bs_jets[kMaxDegree + 1];
  for (int i = 0; i < n_; ++i) {
    const Jet &s = L.s[i], &h = L.h[i];
    const BernsteinTable bs(d, s.f), bh(d, h.f);
    for (int j = 0; j <= d; ++j) bs_jets[j] = bs.compose(j, s);
    for (int k = 0; k < l; ++k) {
      const Jet hk = bh.compose(k, h);
      for (int j = 0; j <= d; ++j) {
        const Mu m = mu(j, k);
        if (m == Mu::Zero) continue;
        Jet w = bs_jets[j] * hk;
        if (m == Mu::Half) w *= 0.5;
        if (m == Mu::Alpha) w = w * L.alpha[i];
        if (m == Mu::Beta) w = w * L.beta[i];
        out[grid_[(i * l + k) * (d + 1) + j]] += w;
        total += w;
      }
    }
  }
  out[0] = Jet(1.0) - total;
}

Jet GBPatch::influence_regular(std::size_t k, Vec2 x) const {
  Local L;
  local(x, L, k == 0 ? ~0u : ribbons_of_[k], k == 0 ? ~0u : weighted_of_[k]);
  if (k == 0) {  // the central weight needs every ribbon
    Jet total;
    for (int i = 0; i < n_; ++i) {
      const BernsteinTable bs(d_, L.s[i].f), bh(d_, L.h[i].f);
      Jet tw[3];
      for (int r = 0; r < l_; ++r) {
        double w[3][3] = {};
        for (int j = 0; j <= d_; ++j) {
          const Mu m = mu(j, r);
          if (m == Mu::Zero) continue;
          const int g = m == Mu::Alpha ? 1 : m == Mu::Beta ? 2 : 0;
          const double c = m == Mu::Half ? 0.5 : 1.0;
          w[g][0] += c * bs.d0[j], w[g][1] += c * bs.d1[j], w[g][2] += c * bs.d2[j];
        }
        const Jet hk = bh.compose(r, L.h[i]);
        for (int g = 0; g < 3; ++g) tw[g] += chain(L.s[i], w[g][0], w[g][1], w[g][2]) * hk;
      }
      total += tw[0];
      if (d_ >= 3) total += tw[1] * L.alpha[i] + tw[2] * L.beta[i];
    }
    return Jet(1.0) - total;
  }
  Jet w;
  for (const Occurrence& o : occurrences_[k]) {
    Jet b = bernstein_jet(d_, o.j, L.s[o.i]) * bernstein_jet(d_, o.k, L.h[o.i]);
    switch (mu(o.j, o.k)) {
      case Mu::Half:
        b *= 0.5;
        break;
      case Mu::Alpha:
        b = b * L.alpha[o.i];
        break;
      case Mu::Beta:
        b = b * L.beta[o.i];
        break;
      default:
        break;
    }
    w += b;
  }
  return w;
}

void GBPatch::basis_vertex(int v, std::span<Jet> out) const {
  // Exact limits at vertex v along the ray theta to the centre. Ribbon a = v ends at v and
  // ribbon b = v+1 starts there; their shared 2x2 corner block is weighted X_k (1 - r) + Y_k r
  // with X_k, Y_k the smooth Bernstein products of ribbons a and b and r = alpha_b =
  // h_a / (h_a + h_b), 0/0 at v. D_k = Y_k - X_k vanishes with its gradient at v (the blocks
  // are shared), so r D_k has value and gradient 0 there and its Hessian's limit is that of
  // r0 * (second-order part of D_k), r0 the ratio of the linear parts of h_a, h_b.
  // Every other ribbon m has lambda_{m-1} = lambda_m = 0 at v, and its products are
  // C h^k lambda_{m-1}^(d-j) lambda_m^j / (lambda_{m-1} + lambda_m)^k: homogeneous of degree
  // d - k in two vanishing functions, so only degree <= 2 leaves a (second-order) trace.
  const Vec2 x = domain_.vertex(v), theta = domain_.interior_point() - x;
  Scratch<Jet, kMaxSides> lambda;
  Local L;
  params_.evaluate(x, std::span(lambda.data(), n_), std::span(L.s.data(), n_),
                   std::span(L.h.data(), n_));
  const int a = params_.wrap(v), b = params_.wrap(v + 1), d = d_, l = l_;
  const auto alpha = [&](int i) {  // smooth alpha_i (never i = b)
    const Jet& prev = L.h[params_.wrap(i - 1)];
    return prev / (prev + L.h[params_.wrap(i)]);
  };
  const auto linear = [&](const Jet& f) {  // the linear part of f at x, evaluated at x + theta
    return Jet(f.fu * theta.x + f.fv * theta.y, f.fu, f.fv, 0, 0, 0);
  };
  const auto hessian_only = [](const Jet& f) { return Jet(0, 0, 0, f.fuu, f.fuv, f.fvv); };
  std::vector<Jet> X(size()), Y(size());
  std::vector<char> block(size(), 0);
  for (Jet& j : out) j = Jet();
  for (int m = 0; m < n_; ++m) {
    if (m == a || m == b) {
      const Jet &s = L.s[m], &h = L.h[m];
      const BernsteinTable bs(d, s.f), bh(d, h.f);
      const Jet alpha_m = d >= 3 && m == a ? alpha(a) : Jet();
      const Jet beta_m = d >= 3 && m == b ? Jet(1.0) - alpha(b + 1) : Jet();
      for (int k = 0; k < l; ++k)
        for (int j = 0; j <= d; ++j) {
          const Mu mu_jk = mu(j, k);
          if (mu_jk == Mu::Zero) continue;
          const std::size_t idx = grid_[(m * l + k) * (d + 1) + j];
          const Jet w = bs.compose(j, s) * bh.compose(k, h);
          if (m == a && mu_jk == Mu::Beta) {
            X[idx] += w, block[idx] = 1;
          } else if (m == b && mu_jk == Mu::Alpha) {
            Y[idx] += w, block[idx] = 1;
          } else {
            const Jet weight = mu_jk == Mu::Half    ? Jet(0.5)
                               : mu_jk == Mu::Alpha ? alpha_m
                               : mu_jk == Mu::Beta  ? beta_m
                                                    : Jet(1.0);
            out[idx] += w * weight;
          }
        }
      continue;
    }
    const Jet &A = lambda[params_.wrap(m - 1)], &B = lambda[m];
    const Jet A0 = linear(A), B0 = linear(B), S0 = A0 + B0;
    const Jet alpha_m = d >= 3 ? alpha(m) : Jet(),
              beta_m = d >= 3 ? Jet(1.0) - alpha(m + 1) : Jet();
    for (int k = 0; k < l; ++k) {
      if (d - k >= 3) continue;  // vanishes to third order
      for (int j = 0; j <= d; ++j) {
        const Mu mu_jk = mu(j, k);
        if (mu_jk == Mu::Zero) continue;
        Jet F;
        if (k == 0) {
          F = pow(A, d - j) * pow(B, j);  // d <= 2: a polynomial, exact as it stands
        } else {
          if (!(std::fabs(S0.f) > 0)) continue;  // both vanish to second order: F = O(|dx|^4)
          F = hessian_only(pow(A0, d - j) * pow(B0, j) / pow(S0, k));
        }
        const Jet weight = mu_jk == Mu::Half    ? Jet(0.5)
                           : mu_jk == Mu::Alpha ? alpha_m
                           : mu_jk == Mu::Beta  ? beta_m
                                                : Jet(1.0);
        out[grid_[(m * l + k) * (d + 1) + j]] +=
            (binomial(d, j) * binomial(d, k)) * pow(L.h[m], k) * weight * F;
      }
    }
  }
  const Jet P0 = linear(L.h[a]), Q0 = linear(L.h[b]);
  const Jet r0 = P0 / (P0 + Q0);
  for (std::size_t k = 0; k < size(); ++k) {
    if (!block[k]) continue;
    const Jet D = Y[k] - X[k];
    const Vec2 Ht(D.fuu * theta.x + D.fuv * theta.y, D.fuv * theta.x + D.fvv * theta.y);
    const Jet Dq(0.5 * (theta.x * Ht.x + theta.y * Ht.y), Ht.x, Ht.y, D.fuu, D.fuv, D.fvv);
    out[k] += X[k] + hessian_only(r0 * Dq);
  }
  Jet total;
  for (std::size_t k = 1; k < size(); ++k) total += out[k];
  out[0] = Jet(1.0) - total;
  const std::size_t corner = index(v, d, 0);
  for (std::size_t k = 0; k < size(); ++k) out[k].f = k == corner ? 1.0 : 0.0;
}

SurfaceJet GBPatch::evaluate(Vec2 x) const {
  const int v = vertex_at(x);
  if (v < 0) return evaluate_regular(x);
  std::vector<Jet> phi(size());
  basis(x, phi);
  SurfaceJet S = combine(points_, phi);
  S.p = point(v, d_, 0);  // exactly the corner point, plus the Taylor step of basis()
  const Vec2 delta = x - domain_.vertex(v);
  S.p += delta.x * S.su + delta.y * S.sv;
  return S;
}

void GBPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  const int v = vertex_at(x);
  if (v < 0) return basis_regular(x, out);
  basis_vertex(v, out);
  for (Jet& j : out) shift(j, x - domain_.vertex(v));
}

Jet GBPatch::influence_at(std::size_t k, Vec2 x) const {
  if (vertex_at(x) < 0) return influence_regular(k, x);
  std::vector<Jet> phi(size());
  basis(x, phi);
  return phi[k];
}

void GBPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  if (k == 0) {  // the central weight needs every ribbon: the scalar path
    for (std::size_t p = 0; p < xs.size(); ++p) out[p] = influence_at(k, xs[p]);
    return;
  }
  const auto lanes = [&](const auto& u, const auto& v, std::size_t first, int count) {
    influence_lanes(k, u, v, &out[first], count);
  };
  const auto at_vertex = [&](std::size_t p) { out[p] = influence_at(k, xs[p]); };
  if (wide_lanes())
    for_lane_blocks<WideLane>(xs, lanes, at_vertex);
  else
    for_lane_blocks<Lane>(xs, lanes, at_vertex);
}

// Batched evaluation: kLanes (or kWideLanes) samples at once, one per SIMD lane. The formulas and
// their operation order are evaluate_regular's and influence_regular's (the core is built without
// FMA contraction), except that the ribbons' terms are added into S in another order: influence
// columns equal influence_at bit for bit, evaluate_many equals evaluate to rounding (tests).

namespace {

// A Vec3 per lane, and a surface jet or (s, h) jet of them: [derivative][coordinate].
template <class V>
struct SurfaceLanes {
  V c[6][3];  // p, su, sv, suu, suv, svv (or g, gs, gh, gss, gsh, ghh)
};

template <class V>
PATCHLAB_LANES_INLINE void clear(SurfaceLanes<V>& a) {
  for (auto& row : a.c)
    for (V& x : row) x = V{};
}

// to_uv of evaluate_regular: the (u, v) jet of G(s(u,v), h(u,v)), coordinate by coordinate.
template <class V>
PATCHLAB_LANES_INLINE void to_uv(const SurfaceLanes<V>& G, const JetLanesOf<V>& s,
                                 const JetLanesOf<V>& h, SurfaceLanes<V>& out) {
  const V ss_u = s.fu * s.fu, sh_u = 2 * s.fu * h.fu, hh_u = h.fu * h.fu;
  const V ss_uv = s.fu * s.fv, sh_uv = s.fu * h.fv + s.fv * h.fu, hh_uv = h.fu * h.fv;
  const V ss_v = s.fv * s.fv, sh_v = 2 * s.fv * h.fv, hh_v = h.fv * h.fv;
  for (int c = 0; c < 3; ++c) {
    const V g = G.c[0][c], gs = G.c[1][c], gh = G.c[2][c];
    const V gss = G.c[3][c], gsh = G.c[4][c], ghh = G.c[5][c];
    out.c[0][c] = g;
    out.c[1][c] = s.fu * gs + h.fu * gh;
    out.c[2][c] = s.fv * gs + h.fv * gh;
    out.c[3][c] = ss_u * gss + sh_u * gsh + hh_u * ghh + s.fuu * gs + h.fuu * gh;
    out.c[4][c] = ss_uv * gss + sh_uv * gsh + hh_uv * ghh + s.fuv * gs + h.fuv * gh;
    out.c[5][c] = ss_v * gss + sh_v * gsh + hh_v * ghh + s.fvv * gs + h.fvv * gh;
  }
}

// S += D * w (times() of evaluate_regular).
template <class V>
PATCHLAB_LANES_INLINE void add_times(SurfaceLanes<V>& S, const SurfaceLanes<V>& D,
                                     const JetLanesOf<V>& w) {
  for (int c = 0; c < 3; ++c) {
    const V p = D.c[0][c], su = D.c[1][c], sv = D.c[2][c];
    S.c[0][c] += p * w.f;
    S.c[1][c] += su * w.f + p * w.fu;
    S.c[2][c] += sv * w.f + p * w.fv;
    S.c[3][c] += D.c[3][c] * w.f + 2.0 * w.fu * su + p * w.fuu;
    S.c[4][c] += D.c[4][c] * w.f + su * w.fv + sv * w.fu + p * w.fuv;
    S.c[5][c] += D.c[5][c] * w.f + 2.0 * w.fv * sv + p * w.fvv;
  }
}

template <class V>
PATCHLAB_LANES_INLINE void sum_uv(SurfaceLanes<V>& S, const SurfaceLanes<V>& G,
                                  const JetLanesOf<V>& s, const JetLanesOf<V>& h) {
  SurfaceLanes<V> T;
  to_uv(G, s, h, T);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 3; ++c) S.c[r][c] += T.c[r][c];
}

}  // namespace

template <class V>
[[gnu::always_inline]] inline void GBPatch::evaluate_block(const V& u, const V& v, SurfaceJet* out,
                                                           int count) const {
  const int n = n_, d = d_, l = l_, groups = d >= 3 ? 3 : 1;
  JetLanesOf<V> s[kMaxSides], h[kMaxSides], alpha[kMaxSides];
  params_.evaluate_lanes(u, v, s, h);
  if (d >= 3)
    for (int i = 0; i < n; ++i) {
      const JetLanesOf<V>& prev = h[i == 0 ? n - 1 : i - 1];
      alpha[i] = product(prev, reciprocal(sum(prev, h[i])));
    }
  SurfaceLanes<V> S, A0, D, Bprev;
  clear(S);
  for (int c = 0; c < 3; ++c) S.c[0][c] = V{} + points_[0][c];
  for (int i = 0; i < n; ++i) {
    const BernsteinTableOf<V> bs(d, s[i].f), bh(d, h[i].f);
    SurfaceLanes<V> G[3];  // 0: C + B, 1: A, 2: B (see evaluate_regular)
    for (int g = 0; g < groups; ++g) {
      clear(G[g]);
      for (int k = 0; k < l; ++k) {
        const Span sp = span_[g * l + k];
        if (sp.first > sp.last) continue;
        const Vec3* P = &dense_[((i * 3 + g) * l + k) * (d + 1)];
        V r0[3]{}, r1[3]{}, r2[3]{};
        for (int j = sp.first; j <= sp.last; ++j)
          for (int c = 0; c < 3; ++c) {
            r0[c] += bs.d0[j] * P[j][c];
            r1[c] += bs.d1[j] * P[j][c];
            r2[c] += bs.d2[j] * P[j][c];
          }
        const V h0 = bh.d0[k], h1 = bh.d1[k], h2 = bh.d2[k];
        for (int c = 0; c < 3; ++c) {
          G[g].c[0][c] += h0 * r0[c];
          G[g].c[1][c] += h0 * r1[c];
          G[g].c[3][c] += h0 * r2[c];
          G[g].c[2][c] += h1 * r0[c];
          G[g].c[4][c] += h1 * r1[c];
          G[g].c[5][c] += h2 * r0[c];
        }
      }
    }
    sum_uv(S, G[0], s[i], h[i]);
    if (d < 3) continue;
    // alpha_i (A_i - B_{i-1}): the difference first, as evaluate_regular takes it, because the
    // two cancel near vertex i-1 where alpha_i's derivatives grow without bound.
    SurfaceLanes<V> A;
    to_uv(G[1], s[i], h[i], i == 0 ? A0 : A);
    if (i > 0) {
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 3; ++c) D.c[r][c] = A.c[r][c] - Bprev.c[r][c];
      add_times(S, D, alpha[i]);
    }
    to_uv(G[2], s[i], h[i], Bprev);
  }
  if (d >= 3) {
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 3; ++c) D.c[r][c] = A0.c[r][c] - Bprev.c[r][c];
    add_times(S, D, alpha[0]);
  }
  for (int b = 0; b < count; ++b) {
    SurfaceJet& o = out[b];
    Vec3* rows[6] = {&o.p, &o.su, &o.sv, &o.suu, &o.suv, &o.svv};
    for (int r = 0; r < 6; ++r) *rows[r] = Vec3(S.c[r][0][b], S.c[r][1][b], S.c[r][2][b]);
  }
}

template <class V>
[[gnu::always_inline]] inline void GBPatch::influence_block(std::size_t k, const V& u, const V& v,
                                                            Jet* out, int count) const {
  assert(k > 0);
  // The sides local() would ask for; see there.
  const int n = n_;
  const uint32_t all = (1u << n) - 1;
  const uint32_t weighted = weighted_of_[k] & all;
  const uint32_t rotl = ((weighted << 1) | (weighted >> (n - 1))) & all;
  const uint32_t alphas = d_ >= 3 ? weighted | rotl : 0;
  const uint32_t rotr = ((alphas >> 1) | ((alphas & 1u) << (n - 1))) & all;
  JetLanesOf<V> s[kMaxSides], h[kMaxSides], alpha[kMaxSides];
  params_.evaluate_lanes(u, v, s, h, ribbons_of_[k] | alphas | rotr);
  for (int i = 0; i < n; ++i)
    if (alphas >> i & 1u) {
      const JetLanesOf<V>& prev = h[i == 0 ? n - 1 : i - 1];
      alpha[i] = product(prev, reciprocal(sum(prev, h[i])));
    }
  JetLanesOf<V> w = constant_lanes<V>(0);
  for (const Occurrence& o : occurrences_[k]) {
    JetLanesOf<V> bj, bk;
    const JetLanesOf<V>&si = s[o.i], &hi = h[o.i];
    V g, g1, g2;
    bernstein_d2(d_, o.j, si.f, g, g1, g2);
    bj = chain(si, g, g1, g2);
    bernstein_d2(d_, o.k, hi.f, g, g1, g2);
    bk = chain(hi, g, g1, g2);
    JetLanesOf<V> b = product(bj, bk);
    switch (mu(o.j, o.k)) {
      case Mu::Half:
        b = scaled(b, 0.5);
        break;
      case Mu::Alpha:
        b = product(b, alpha[o.i]);
        break;
      case Mu::Beta: {
        const JetLanesOf<V>& next = alpha[o.i + 1 == n ? 0 : o.i + 1];
        const V z{};  // Jet(1.0) - alpha, sign of zero included
        const JetLanesOf<V> beta{1.0 - next.f, z - next.fu,  z - next.fv,
                                 z - next.fuu, z - next.fuv, z - next.fvv};
        b = product(b, beta);
        break;
      }
      default:
        break;
    }
    add_to(w, b);
  }
  for (int b = 0; b < count; ++b) out[b] = lane(w, b);
}

PATCHLAB_LANES_CLONES
void GBPatch::evaluate_lanes(const Lane& u, const Lane& v, SurfaceJet* out, int count) const {
  evaluate_block(u, v, out, count);
}

PATCHLAB_LANES_WIDE
void GBPatch::evaluate_lanes(const WideLane& u, const WideLane& v, SurfaceJet* out,
                             int count) const {
  evaluate_block(u, v, out, count);
}

PATCHLAB_LANES_CLONES
void GBPatch::influence_lanes(std::size_t k, const Lane& u, const Lane& v, Jet* out,
                              int count) const {
  influence_block(k, u, v, out, count);
}

PATCHLAB_LANES_WIDE
void GBPatch::influence_lanes(std::size_t k, const WideLane& u, const WideLane& v, Jet* out,
                              int count) const {
  influence_block(k, u, v, out, count);
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

}  // namespace pl
