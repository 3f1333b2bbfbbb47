#include "core/patch/gb/gb_interior_patch.hpp"

#include <stdexcept>
#include <string>

#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/ribbon_elevation.hpp"

namespace pl {

namespace {

std::vector<Vec3> all_points(const GBRibbonPatch& filling, const std::vector<Vec3>& net,
                             const std::vector<Vec3>& defaults,
                             const std::vector<std::size_t>& free) {
  std::vector<Vec3> p = net;
  p.insert(p.end(), filling.control_points().begin(), filling.control_points().end());
  for (std::size_t k : free) p.push_back(defaults[k]);
  return p;
}

// The free net indices: C_0 (if carried) and every point of ring >= 2.
std::vector<std::size_t> free_indices(int n, int d, bool centre) {
  std::vector<std::size_t> out;
  if (centre) out.push_back(0);
  for (std::size_t k = 1; k < GBPatch::point_count(n, d); ++k)
    if (gb_ring(n, d, k) >= 2) out.push_back(k);
  return out;
}

}  // namespace

GBInteriorPatch::GBInteriorPatch(GBRibbonPatch filling, int degree,
                                 const std::vector<Vec3>& defaults, const std::vector<Vec3>& net)
    : filling_(std::move(filling)),
      d_(degree),
      net_size_(GBPatch::point_count(filling_.sides(), degree)),
      centre_weight_(filling_.polygon()) {
  const int n = filling_.sides(), d = degree;
  if (d < 3) throw std::invalid_argument("a GB face's degree is at least 3");
  if (defaults.size() != net_size_ || net.size() != net_size_)
    throw std::invalid_argument("the degree-" + std::to_string(d) + " net of a " +
                                std::to_string(n) + "-sided face has " + std::to_string(net_size_) +
                                " points");
  centre_ = centre_weight_.scale() > 0;
  if (!centre_ && net[0] != defaults[0])
    throw std::invalid_argument("the central point's weight vanishes on this face's domain");
  free_ = free_indices(n, d, centre_);
  free_slot_.assign(net_size_, -1);
  for (std::size_t s = 0; s < free_.size(); ++s) free_slot_[free_[s]] = int(s);
  terms_.resize(free_.size());
  points_ = all_points(filling_, net, defaults, free_);

  const int l = GBPatch::layers(d);
  if (l >= 3) {
    // The blend patch: degree d, l layers, rows all zero (the displacements are set below);
    // sides behind a reflex corner get layers until l_i >= d, where the blend has no pole.
    const std::vector<int> deep = GBRibbonPatch::sides_without_positive_pair(filling_.polygon());
    std::vector<bool> is_deep(n, false);
    for (int i : deep) is_deep[i] = true;
    std::vector<std::vector<std::vector<Vec3>>> rows(n);
    for (int i = 0; i < n; ++i) {
      rows[i].assign(l, std::vector<Vec3>(d + 1, Vec3(0)));
      if (is_deep[i])
        while (static_cast<int>(rows[i].size()) < d) rows[i] = ribbon_with_layer(rows[i]);
    }
    blends_.emplace(filling_.polygon(), rows);
    users_.resize(blends_->size());
    // Which blend points each free point feeds, and by how much: the identity on a plain side,
    // the (linear) layer elevation of a unit row entry on a deep one.
    for (int i = 0; i < n; ++i)
      for (int k = 2; k < l; ++k)
        for (int j = 0; j <= d; ++j) {
          const std::size_t g = gb_net_index(n, d, i, j, k);
          if (free_slot_[g] < 0) continue;
          auto& terms = terms_[free_slot(g)];
          if (!is_deep[i]) {
            terms.push_back({blends_->index(i, j, k), 1.0});
            continue;
          }
          std::vector<std::vector<Vec3>> unit(l, std::vector<Vec3>(d + 1, Vec3(0)));
          unit[k][j] = Vec3(1, 0, 0);
          while (static_cast<int>(unit.size()) < d) unit = ribbon_with_layer(unit);
          for (int kk = 2; kk < static_cast<int>(unit.size()); ++kk)
            for (int jj = 0; jj <= d; ++jj)
              if (unit[kk][jj].x != 0) terms.push_back({blends_->index(i, jj, kk), unit[kk][jj].x});
        }
    for (std::size_t s = 0; s < free_.size(); ++s)
      for (const Term& t : terms_[s]) users_[t.q].push_back({s, t.c});
    for (std::size_t q = 0; q < users_.size(); ++q)
      if (!users_[q].empty()) update_blend_point(q);
  }
}

std::size_t GBInteriorPatch::default_index(std::size_t k) const {
  if (!is_free(k)) throw std::out_of_range("net point " + std::to_string(k) + " is not free");
  return net_size_ + filling_.size() + free_slot(k);
}

ControlPointKind GBInteriorPatch::kind(std::size_t k) const {
  if (k < net_size_) {
    const int ring = gb_ring(sides(), d_, k);
    if (ring < 0) return ControlPointKind::Central;
    return ring == 0 ? ControlPointKind::Boundary : ControlPointKind::Inner;
  }
  if (k < net_size_ + filling_.size()) return filling_.kind(k - net_size_);
  return ControlPointKind::Inner;
}

void GBInteriorPatch::update_blend_point(std::size_t q) {
  Vec3 w(0);
  for (const auto& [s, c] : users_[q]) {
    const std::size_t k = free_[s];
    w += c * (points_[k] - points_[net_size_ + filling_.size() + s]);
  }
  const bool was = blends_->control_point(q) != Vec3(0), is = w != Vec3(0);
  if (is && !was) ++displaced_points_;
  if (was && !is) --displaced_points_;
  blends_->set_control_point(q, w);
}

void GBInteriorPatch::set_control_point(std::size_t k, const Vec3& p) {
  points_.at(k) = p;
  const std::size_t fill_end = net_size_ + filling_.size();
  if (k >= net_size_ && k < fill_end) return filling_.set_control_point(k - net_size_, p);
  std::size_t slot;
  if (k < net_size_) {
    if (free_slot_[k] < 0) return;  // a G1 point: drawn, not blended
    slot = free_slot(k);
  } else {
    slot = k - fill_end;
  }
  if (free_[slot] == 0 && !centre_) return;
  for (const Term& t : terms_[slot]) update_blend_point(t.q);
}

Jet GBInteriorPatch::centre_weight(Vec2 x) const {
  if (!centre_) return Jet{};
  return centre_weight_(x);
}

Jet GBInteriorPatch::free_blend(std::size_t k, Vec2 x) const {
  if (!is_free(k)) return Jet{};
  if (k == 0) return centre_weight(x);
  std::vector<Jet> b(blends_->size());
  blends_->basis(x, b);
  Jet phi{};
  for (const Term& t : terms_[free_slot(k)]) phi += b[t.q] * t.c;
  return phi;
}

void GBInteriorPatch::basis(Vec2 x, std::span<Jet> out) const {
  std::fill(out.begin(), out.end(), Jet{});
  filling_.basis(x, out.subspan(net_size_, filling_.size()));
  std::vector<Jet> b(blends_ ? blends_->size() : 0);
  if (blends_) blends_->basis(x, b);
  const std::size_t defaults = net_size_ + filling_.size();
  for (std::size_t s = 0; s < free_.size(); ++s) {
    Jet phi{};
    if (free_[s] == 0) {
      phi = centre_weight(x);
    } else {
      for (const Term& t : terms_[s]) phi += b[t.q] * t.c;
    }
    out[free_[s]] = phi;
    out[defaults + s] = phi * -1.0;
  }
}

void GBInteriorPatch::add_displacement(Vec2 x, SurfaceJet& s) const {
  if (displaced_points_ > 0) {
    const SurfaceJet d = blends_->evaluate(x);
    s.p += d.p;
    s.su += d.su;
    s.sv += d.sv;
    s.suu += d.suu;
    s.suv += d.suv;
    s.svv += d.svv;
  }
  if (centre_) {
    const Vec3 c = offset(0);
    if (c != Vec3(0)) add_scaled(s, centre_weight(x), c);
  }
}

SurfaceJet GBInteriorPatch::evaluate(Vec2 x) const {
  SurfaceJet s = filling_.evaluate(x);
  add_displacement(x, s);
  return s;
}

void GBInteriorPatch::evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
  // add_displacement()'s sums in its order, each part batched: the numbers evaluate() gives.
  filling_.evaluate_many(xs, out);
  if (displaced_points_ > 0) {
    std::vector<SurfaceJet> d(xs.size());
    blends_->evaluate_many(xs, d);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      SurfaceJet& s = out[i];
      s.p += d[i].p, s.su += d[i].su, s.sv += d[i].sv;
      s.suu += d[i].suu, s.suv += d[i].suv, s.svv += d[i].svv;
    }
  }
  if (centre_ && offset(0) != Vec3(0)) {
    const Vec3 c = offset(0);
    std::vector<Jet> w(xs.size());
    centre_weight_.evaluate_many(xs, w);
    for (std::size_t i = 0; i < xs.size(); ++i) add_scaled(out[i], w[i], c);
  }
}

void GBInteriorPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  const std::size_t fill_end = net_size_ + filling_.size();
  if (k >= net_size_ && k < fill_end) return filling_.influence(k - net_size_, xs, out);
  double sign = 1;
  if (k >= fill_end) {
    k = free_.at(k - fill_end);
    sign = -1;
  }
  const std::size_t count = std::min(xs.size(), out.size());
  if (k >= net_size_ || free_slot_[k] < 0) {
    std::fill(out.begin(), out.begin() + count, Jet{});
    return;
  }
  if (k == 0) {
    for (std::size_t i = 0; i < count; ++i) out[i] = centre_weight(xs[i]) * sign;
    return;
  }
  std::vector<Jet> b(blends_->size());
  const auto& terms = terms_[free_slot(k)];
  for (std::size_t i = 0; i < count; ++i) {
    blends_->basis(xs[i], b);
    Jet phi{};
    for (const Term& t : terms) phi += b[t.q] * t.c;
    out[i] = phi * sign;
  }
}

}  // namespace pl
