#include "core/patch/gb_patch.hpp"

#include <cassert>
#include <stdexcept>

#include "core/math/bernstein_jets.hpp"

namespace pl {

namespace {

// Points closer than this to a domain vertex (domain size ~2) are evaluated through the vertex
// limit plus a first-order Taylor step: the corner weights are 0/0 at the vertex itself.
constexpr double kVertexRadius = 1e-10;
// The vertex limit is extrapolated from 6 points on the ray to the centre at fractions m/128
// (m = 1..6); Lagrange weights for extrapolating to 0 are (-1)^(m+1) C(6, m). The restriction of
// every blend to the ray is analytic in the fraction (alpha, beta are ratios of functions with
// simple zeros there), so the error is O((6/128)^6 f^(6)), at the level of rounding.
constexpr double kRayStep = 1.0 / 128;
constexpr double kExtrapolation[6] = {6, -15, 20, -15, 6, -1};

SurfaceJet times(const SurfaceJet& a, const Jet& b) {
  return {a.p * b.f,
          a.su * b.f + a.p * b.fu,
          a.sv * b.f + a.p * b.fv,
          a.suu * b.f + 2.0 * b.fu * a.su + a.p * b.fuu,
          a.suv * b.f + a.su * b.fv + a.sv * b.fu + a.p * b.fuv,
          a.svv * b.f + 2.0 * b.fv * a.sv + a.p * b.fvv};
}

// sum_j c_j B_j(t) P_j as a vector jet from its t-derivatives q0, q1, q2 (chain rule).
SurfaceJet compose(const Jet& t, const Vec3& q0, const Vec3& q1, const Vec3& q2) {
  return {q0,
          t.fu * q1,
          t.fv * q1,
          t.fuu * q1 + (t.fu * t.fu) * q2,
          t.fuv * q1 + (t.fu * t.fv) * q2,
          t.fvv * q1 + (t.fv * t.fv) * q2};
}

void add(SurfaceJet& a, const SurfaceJet& b, double w = 1.0) {
  a.p += w * b.p;
  a.su += w * b.su;
  a.sv += w * b.sv;
  a.suu += w * b.suu;
  a.suv += w * b.suv;
  a.svv += w * b.svv;
}

void add(SurfaceJet& a, const Vec3& c, const Jet& w) {
  a.p += w.f * c;
  a.su += w.fu * c;
  a.sv += w.fv * c;
  a.suu += w.fuu * c;
  a.suv += w.fuv * c;
  a.svv += w.fvv * c;
}

// Value moved by a first-order Taylor step delta (the vertex limit applied near the vertex).
void shift(Jet& j, Vec2 delta) {
  j.f += j.fu * delta.x + j.fv * delta.y;
  j.fu += j.fuu * delta.x + j.fuv * delta.y;
  j.fv += j.fuv * delta.x + j.fvv * delta.y;
}

}  // namespace

struct GBPatch::Local {
  Jet s[kMaxSides], h[kMaxSides], alpha[kMaxSides], beta[kMaxSides];
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
  grid_.resize(n_ * l * (d + 1));
  occurrences_.assign(size(), {});
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        const std::size_t s = index(i, j, k);
        grid_[(i * l + k) * (d + 1) + j] = static_cast<uint32_t>(s);
        if (mu(j, k) != Mu::Zero) occurrences_[s].push_back({i, j, k});
      }
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

void GBPatch::local(Vec2 x, Local& out) const {
  params_.evaluate(x, {}, std::span(out.s, n_), std::span(out.h, n_));
  if (d_ < 3) return;  // no corner weights
  for (int i = 0; i < n_; ++i) {
    const Jet& prev = out.h[params_.wrap(i - 1)];
    out.alpha[i] = prev / (prev + out.h[i]);
  }
  // beta_i = h_{i+1} / (h_{i+1} + h_i) = 1 - alpha_{i+1}: the two weights of a shared corner
  // point then sum to one exactly.
  for (int i = 0; i < n_; ++i) out.beta[i] = Jet(1.0) - out.alpha[params_.wrap(i + 1)];
}

int GBPatch::vertex_at(Vec2 x) const {
  for (int i = 0; i < n_; ++i) {
    const Vec2 d = x - domain_.vertex(i);
    if (d.x * d.x + d.y * d.y < kVertexRadius * kVertexRadius) return i;
  }
  return -1;
}

SurfaceJet GBPatch::evaluate_regular(Vec2 x) const {
  Local L;
  local(x, L);
  const int d = d_, l = l_;
  SurfaceJet S;
  Jet total;  // sum of every ribbon weight; C_0 takes 1 - total
  for (int i = 0; i < n_; ++i) {
    const Jet &s = L.s[i], &h = L.h[i];
    const BernsteinTable bs(d, s.f), bh(d, h.f);
    // Group the row by weight: 0 = constant (1/2 or 1), 1 = alpha, 2 = beta. Each group is a
    // polynomial in s times one in h, so the s-sums are formed on scalars and composed once.
    SurfaceJet T[3];
    Jet tw[3];
    for (int k = 0; k < l; ++k) {
      const Jet hk = bh.compose(k, h);
      Vec3 q[3][3] = {};
      double w[3][3] = {};
      bool used[3] = {false, false, false};
      const uint32_t* row = &grid_[(i * l + k) * (d + 1)];
      for (int j = 0; j <= d; ++j) {
        const Mu m = mu(j, k);
        if (m == Mu::Zero) continue;
        const int g = m == Mu::Alpha ? 1 : m == Mu::Beta ? 2 : 0;
        const double c = m == Mu::Half ? 0.5 : 1.0;
        const Vec3& P = points_[row[j]];
        const double c0 = c * bs.d0[j], c1 = c * bs.d1[j], c2 = c * bs.d2[j];
        q[g][0] += c0 * P;
        q[g][1] += c1 * P;
        q[g][2] += c2 * P;
        w[g][0] += c0;
        w[g][1] += c1;
        w[g][2] += c2;
        used[g] = true;
      }
      for (int g = 0; g < 3; ++g) {
        if (!used[g]) continue;
        add(T[g], times(compose(s, q[g][0], q[g][1], q[g][2]), hk));
        tw[g] += chain(s, w[g][0], w[g][1], w[g][2]) * hk;
      }
    }
    add(S, T[0]);
    total += tw[0];
    if (d >= 3) {
      add(S, times(T[1], L.alpha[i]));
      add(S, times(T[2], L.beta[i]));
      total += tw[1] * L.alpha[i] + tw[2] * L.beta[i];
    }
  }
  add(S, points_[0], Jet(1.0) - total);
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
  local(x, L);
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

SurfaceJet GBPatch::evaluate(Vec2 x) const {
  const int v = vertex_at(x);
  if (v < 0) return evaluate_regular(x);
  const Vec2 corner = domain_.vertex(v), towards = domain_.interior_point() - corner;
  SurfaceJet S;
  for (int m = 0; m < 6; ++m)
    add(S, evaluate_regular(corner + ((m + 1) * kRayStep) * towards), kExtrapolation[m]);
  S.p = point(v, d_, 0);
  const Vec2 delta = x - corner;
  S.p += delta.x * S.su + delta.y * S.sv;
  S.su += delta.x * S.suu + delta.y * S.suv;
  S.sv += delta.x * S.suv + delta.y * S.svv;
  return S;
}

void GBPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  const int v = vertex_at(x);
  if (v < 0) return basis_regular(x, out);
  const Vec2 corner = domain_.vertex(v), towards = domain_.interior_point() - corner;
  std::vector<Jet> node(size());
  for (Jet& j : out) j = Jet();
  for (int m = 0; m < 6; ++m) {
    basis_regular(corner + ((m + 1) * kRayStep) * towards, node);
    for (std::size_t k = 0; k < size(); ++k) out[k] += node[k] * kExtrapolation[m];
  }
  const std::size_t c = index(v, d_, 0);
  for (std::size_t k = 0; k < size(); ++k) {
    out[k].f = k == c ? 1.0 : 0.0;
    shift(out[k], x - corner);
  }
}

void GBPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  for (std::size_t p = 0; p < xs.size(); ++p) {
    const int v = vertex_at(xs[p]);
    if (v < 0) {
      out[p] = influence_regular(k, xs[p]);
      continue;
    }
    const Vec2 corner = domain_.vertex(v), towards = domain_.interior_point() - corner;
    Jet w;
    for (int m = 0; m < 6; ++m)
      w += influence_regular(k, corner + ((m + 1) * kRayStep) * towards) * kExtrapolation[m];
    w.f = k == index(v, d_, 0) ? 1.0 : 0.0;
    shift(w, xs[p] - corner);
    out[p] = w;
  }
}

}  // namespace pl
