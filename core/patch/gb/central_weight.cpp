#include "core/patch/gb/central_weight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pl {

namespace {

// Crossing-number test: x strictly inside the simple polygon.
bool inside(const std::vector<Vec2>& poly, Vec2 x) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > x.y) != (b.y > x.y) && x.x < a.x + (x.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
  }
  return in;
}

}  // namespace

CentralWeight::CentralWeight(const ConcavePolygonDomain& domain) : vertices_(domain.vertices()) {
  const int n = static_cast<int>(vertices_.size());
  double area = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 a = vertices_[(i + n - 1) % n], b = vertices_[i];
    const double length = glm::length(b - a);
    sides_.push_back({a, (b - a) / length, length});
    area += cross(a, b) / 2;
  }
  reach_ = std::abs(area) / (4 * M_PI);
  // The largest value: the best of the domain's interior samples (and of the average vertex, the
  // centre of a regular polygon), then Newton steps on the gradient from there, each kept only if
  // it stays inside and increases the weight.
  std::vector<Vec2> candidates = domain.tessellate(8).points;
  Vec2 c(0);
  for (const Vec2& v : vertices_) c += v;
  candidates.push_back(c / double(n));
  double best = 0;
  for (const Vec2& x : candidates) {
    if (!inside(vertices_, x)) continue;
    const double w = unnormalised(x).f;
    if (w > best) best = w, peak_ = x;
  }
  if (!(best > 0 && std::isfinite(best))) return;
  for (int step = 0; step < 32; ++step) {
    const Jet w = unnormalised(peak_);
    const double det = w.fuu * w.fvv - w.fuv * w.fuv;
    Vec2 d = w.fuu < 0 && det > 0
                 ? Vec2(-(w.fvv * w.fu - w.fuv * w.fv) / det, -(w.fuu * w.fv - w.fuv * w.fu) / det)
                 : Vec2(w.fu, w.fv);  // not concave here: uphill, the step halved below as needed
    bool better = false;
    for (int halve = 0; halve < 40 && !better; ++halve, d *= 0.5) {
      const Vec2 x = peak_ + d;
      if (x == peak_) break;
      if (!inside(vertices_, x)) continue;
      const double v = unnormalised(x).f;
      if (v > best) best = v, peak_ = x, better = true;
    }
    if (!better) break;
  }
  scale_ = std::isfinite(best) && best > 1e-200 ? 1 / best : 0;
}

template <class T>
PATCHLAB_LANES_INLINE JetOf<T> CentralWeight::weight_at(const T& u, const T& v) const {
  using J = JetOf<T>;
  const T z{};
  const auto distance_to = [&](Vec2 p) {
    const T dx = u - p.x, dy = v - p.y;
    return jet_sqrt(J{dx * dx + dy * dy, 2 * dx, 2 * dy, z + 2, z, z + 2});
  };
  // (rho - s) / 2 for rho = |x - v| >= |s|, s a signed distance along the side, f the distance
  // across it (rho^2 = s^2 + f^2): zero over the side, where s > 0 and it equals
  // f^2 / (2 (rho + s)) (written so, without the cancellation), and about |s| past the side's end.
  const auto past_end = [](const J& rho, const J& s, const J& f2) {
    return select_jet(s.f > 0, product(f2, reciprocal(scaled(sum(rho, s), 2.0))),
                      scaled(difference(rho, s), 0.5));
  };
  J rho_a = distance_to(sides_.front().a);  // side 0 runs from the last vertex to vertex 0
  J w = constant_jet<T>(1.0);
  for (std::size_t i = 0; i < sides_.size(); ++i) {
    const Side& side = sides_[i];
    const J rho_b = distance_to(vertices_[i]);
    const T dx = u - side.a.x, dy = v - side.a.y;
    const Vec2 across(-side.e.y, side.e.x);
    // Linear in x: the distances across the side and along it from each end.
    const J f = {across.x * dx + across.y * dy, z + across.x, z + across.y, z, z, z};
    const J s_a = {side.e.x * dx + side.e.y * dy, z + side.e.x, z + side.e.y, z, z, z};
    const J s_b = {side.length - s_a.f, z - side.e.x, z - side.e.y, z, z, z};
    const J f2 = product(f, f);
    const J r_a = past_end(rho_a, s_a, f2), r_b = past_end(rho_b, s_b, f2);
    const J g = sum(sum(f2, product(r_a, r_a)), product(r_b, r_b));
    J g_reach = g;
    g_reach.f += reach_;
    w = product(w, product(g, reciprocal(g_reach)));
    rho_a = rho_b;
  }
  return w;
}

Jet CentralWeight::unnormalised(Vec2 x) const {
  for (const Vec2& v : vertices_)
    if (x == v) return Jet{};  // two factors vanish: w and its derivatives are 0
  return weight_at(x.x, x.y);
}

PATCHLAB_LANES_CLONES
void CentralWeight::weight_lanes(const Lane& u, const Lane& v, Jet* out) const {
  const JetLanes w = weight_at(u, v);
  for (int b = 0; b < kLanes; ++b) out[b] = lane(w, b) * scale_;
}

PATCHLAB_LANES_WIDE
void CentralWeight::weight_lanes(const WideLane& u, const WideLane& v, Jet* out) const {
  const WideJetLanes w = weight_at(u, v);
  for (int b = 0; b < kWideLanes; ++b) out[b] = lane(w, b) * scale_;
}

template <class V>
void CentralWeight::weight_blocks(std::span<const Vec2> xs, std::span<Jet> out) const {
  constexpr int width = lane_count<V>;
  Jet block[width];
  for (std::size_t first = 0; first < xs.size(); first += width) {
    const int count = static_cast<int>(std::min<std::size_t>(width, xs.size() - first));
    V u = V{} + peak_.x, v = V{} + peak_.y;  // padding: a point inside
    uint32_t at_vertex = 0;
    for (int b = 0; b < count; ++b) {
      const Vec2 x = xs[first + b];
      if (std::find(vertices_.begin(), vertices_.end(), x) != vertices_.end())
        at_vertex |= 1u << b;
      else
        u[b] = x.x, v[b] = x.y;
    }
    weight_lanes(u, v, block);
    for (int b = 0; b < count; ++b) out[first + b] = at_vertex >> b & 1u ? Jet{} : block[b];
  }
}

void CentralWeight::evaluate_many(std::span<const Vec2> xs, std::span<Jet> out) const {
  if (wide_lanes())
    weight_blocks<WideLane>(xs, out);
  else
    weight_blocks<Lane>(xs, out);
}

}  // namespace pl
