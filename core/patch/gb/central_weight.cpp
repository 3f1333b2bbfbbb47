#include "core/patch/gb/central_weight.hpp"

#include <cmath>

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

// A plane function linear in x, c + l.(x - x0) at x = x0: value c, gradient l.
Jet linear(double c, Vec2 l) {
  return {c, l.x, l.y, 0, 0, 0};
}

// (rho - s) / 2 for rho = |x - v| >= |s|, s a signed distance along the side, f the distance
// across it (rho^2 = s^2 + f^2): zero over the side, where s > 0 and it equals f^2 / (2 (rho +
// s)) (written so, without the cancellation), and about |s| past the side's end.
Jet past_end(const Jet& rho, const Jet& s, const Jet& f2) {
  if (s.f > 0) return f2 / ((rho + s) * 2.0);
  return (rho - s) * 0.5;
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

Jet CentralWeight::unnormalised(Vec2 x) const {
  for (const Vec2& v : vertices_)
    if (x == v) return Jet{};  // two factors vanish: w and its derivatives are 0
  const auto distance_to = [&](Vec2 v) {
    const Vec2 d = x - v;
    return sqrt(Jet(glm::dot(d, d), 2 * d.x, 2 * d.y, 2, 0, 2));
  };
  Jet rho_a = distance_to(sides_.front().a);  // side 0 runs from the last vertex to vertex 0
  Jet w(1.0);
  for (std::size_t i = 0; i < sides_.size(); ++i) {
    const Side& side = sides_[i];
    const Jet rho_b = distance_to(vertices_[i]);
    const Vec2 d = x - side.a;
    const Vec2 across(-side.e.y, side.e.x);
    const Jet f = linear(glm::dot(across, d), across);
    const Jet s_a = linear(glm::dot(side.e, d), side.e);
    const Jet s_b = linear(side.length - s_a.f, -side.e);
    const Jet f2 = f * f;
    const Jet r_a = past_end(rho_a, s_a, f2), r_b = past_end(rho_b, s_b, f2);
    const Jet g = f2 + r_a * r_a + r_b * r_b;
    w = w * (g / (g + reach_));
    rho_a = rho_b;
  }
  return w;
}

}  // namespace pl
