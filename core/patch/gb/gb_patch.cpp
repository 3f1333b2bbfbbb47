// GBPatch: storage and indexing of the control net, the tables the blend reads, and the entry
// points that pick the regular evaluation (gb_patch_evaluate.cpp) or the vertex limits.
#include "core/patch/gb/gb_patch.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "core/patch/gb/vertex_limits.hpp"

namespace pl {

namespace {

// Checked before any member is built from them.
int checked_sides(int sides, int degree) {
  if (sides < 3 || sides > GBPatch::kMaxSides)
    throw std::invalid_argument("a GB patch needs 3 to " + std::to_string(GBPatch::kMaxSides) +
                                " sides, got " + std::to_string(sides));
  if (degree < 1 || degree > GBPatch::kMaxDegree)
    throw std::invalid_argument("GB patch degree must be between 1 and " +
                                std::to_string(GBPatch::kMaxDegree) + ", got " +
                                std::to_string(degree));
  return sides;
}

std::vector<Mu> mu_table(int d, int l) {
  std::vector<Mu> mu(l * (d + 1));
  for (int k = 0; k < l; ++k)
    for (int j = 0; j <= d; ++j) mu[k * (d + 1) + j] = central_mu(d, j, k);
  return mu;
}

}  // namespace

std::size_t GBPatch::point_count(int n, int d) {
  const int l = layers(d);
  return 1 + static_cast<std::size_t>(n) * (l * d - l * (l - 1));
}

GBPatch::GBPatch(int sides, int degree, std::vector<Vec3> points)
    : PatchType(std::move(points)),
      n_(checked_sides(sides, degree)),
      d_(degree),
      l_(layers(degree)),
      domain_(ConvexPolygonDomain::regular(sides)),
      params_(domain_.vertices()),
      mu_(mu_table(d_, l_)),
      rows_(n_, d_, l_, mu_) {
  if (points_.size() != point_count(n_, d_))
    throw std::invalid_argument("a GB patch with " + std::to_string(n_) + " sides and degree " +
                                std::to_string(d_) + " needs " +
                                std::to_string(point_count(n_, d_)) + " points, got " +
                                std::to_string(points_.size()));
  vertex_distance_ = 1e300;  // see vertex_at()
  for (const Vec2& v : domain_.vertices())
    vertex_distance_ =
        std::min(vertex_distance_, std::max(0.0, glm::length(v) - 2 * kGBVertexRadius));
  const int d = d_, l = l_;
  grid_.resize(n_ * l * (d + 1));
  occurrences_.assign(size(), {});
  std::vector<SideMask> ribbons(size(), 0), weighted(size(), 0);
  for (int i = 0; i < n_; ++i)
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        const std::size_t s = index(i, j, k);
        grid_[(i * l + k) * (d + 1) + j] = static_cast<uint32_t>(s);
        const Mu m = mu(j, k);
        if (m == Mu::Zero) continue;
        occurrences_[s].push_back({i, j, k});
        ribbons[s] |= SideMask{1} << i;
        if (m == Mu::Alpha || m == Mu::Beta) weighted[s] |= SideMask{1} << i;
      }
  for (std::size_t s = 0; s < size(); ++s) needs_.push_back(needs(ribbons[s], weighted[s]));
  update_rows(0);
}

void GBPatch::update_rows(std::size_t k) {
  const auto set = [&](int i, int j, int r) {
    rows_.set(i, j, r, mu(j, r), points_[grid_[(i * l_ + r) * (d_ + 1) + j]] - points_[0]);
  };
  if (k == 0) {  // C_0 moves every relative point
    for (int i = 0; i < n_; ++i)
      for (int r = 0; r < l_; ++r)
        for (int j = 0; j <= d_; ++j) set(i, j, r);
    return;
  }
  for (const Occurrence& o : occurrences_[k]) set(o.i, o.j, o.k);
}

void GBPatch::set_control_point(std::size_t k, const Vec3& p) {
  Patch::set_control_point(k, p);
  update_rows(k);
}

std::size_t gb_net_index(int n, int d, int i, int j, int k) {
  // Shared corner blocks: a point outside the stored range k..d-1-k of its row is stored by a
  // neighbouring side (docs/gbp-format.md), where it falls inside the range (one step suffices).
  if (j < k) return gb_net_index(n, d, i - 1, d - k, j);
  if (j > d - 1 - k) return gb_net_index(n, d, i + 1, k, d - j);
  std::size_t offset = 1;
  for (int r = 0; r < k; ++r) offset += static_cast<std::size_t>(n) * (d - 2 * r);
  const int wrapped = ((i % n) + n) % n;
  return offset + static_cast<std::size_t>(wrapped) * (d - 2 * k) + (j - k);
}

std::size_t GBPatch::index(int i, int j, int k) const {
  assert(0 <= j && j <= d_ && 0 <= k && k < l_);
  return gb_net_index(n_, d_, i, j, k);
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

GBPatch::Needs GBPatch::needs(SideMask ribbons, SideMask weighted) const {
  // Ribbon i needs s_i, h_i, and if weighted alpha_i and (for beta_i) alpha_{i+1}; alpha_i needs
  // h_{i-1}, h_i. An influence column of a point with constant weights needs no corner weight.
  const int n = n_;
  const SideMask all = (SideMask{1} << n) - 1;
  const auto rotl = [&](SideMask m) { return ((m << 1) | (m >> (n - 1))) & all; };
  const auto rotr = [&](SideMask m) { return ((m >> 1) | ((m & 1u) << (n - 1))) & all; };
  ribbons &= all;
  weighted &= ribbons;
  const SideMask alphas = has_corner_weights(d_) ? weighted | rotl(weighted) : 0;
  return {ribbons | alphas | rotr(alphas), alphas};
}

void GBPatch::basis_regular(Vec2 x, std::span<Jet> out) const {
  const int n = n_, d = d_, l = l_;
  Scratch<Jet, kMaxSides> s, h, alpha;
  params_.evaluate(x, {}, std::span(s.data(), n), std::span(h.data(), n));
  if (has_corner_weights(d)) corner_alphas(n, h.data(), alpha.data());
  for (Jet& j : out) j = Jet();
  Jet total;
  Jet bs_jets[kMaxDegree + 1];
  for (int i = 0; i < n; ++i) {
    const BernsteinTable bs(d, s[i].f), bh(d, h[i].f);
    for (int j = 0; j <= d; ++j) bs_jets[j] = bs.compose(j, s[i]);
    for (int k = 0; k < l; ++k) {
      const Jet hk = bh.compose(k, h[i]);
      for (int j = 0; j <= d; ++j) {
        const Mu m = mu(j, k);
        if (m == Mu::Zero) continue;
        const Jet w = weighted(bs_jets[j] * hk, m, alpha.data(), i, n);
        out[grid_[(i * l + k) * (d + 1) + j]] += w;
        total += w;
      }
    }
  }
  out[0] = Jet(1.0) - total;
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
  gb_vertex_basis(*this, v, out);
  for (Jet& j : out) taylor_step(j, x - domain_.vertex(v));
}

Jet GBPatch::influence_at(std::size_t k, Vec2 x) const {
  assert(k < size());
  if (vertex_at(x) >= 0) {
    std::vector<Jet> phi(size());
    basis(x, phi);
    return phi[k];
  }
  return influence_regular(k, x);
}

}  // namespace pl
