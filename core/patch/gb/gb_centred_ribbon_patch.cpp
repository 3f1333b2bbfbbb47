#include "core/patch/gb/gb_centred_ribbon_patch.hpp"

#include <cmath>
#include <stdexcept>

#include "core/math/scratch.hpp"

namespace pl {

namespace {

std::vector<Vec3> with_centre(const GBRibbonPatch& r, Vec3 c, Vec3 d) {
  std::vector<Vec3> p = r.control_points();
  p.push_back(c);
  p.push_back(d);
  return p;
}

// prod_i h_i at x (not a domain vertex).
Jet h_product(const MeanValueParameters& params, Vec2 x) {
  const int n = params.sides();
  Scratch<Jet, MeanValueParameters::kMaxSides> lam, h;
  params.evaluate(x, std::span(lam.data(), n), {}, std::span(h.data(), n));
  Jet p = h[0];
  for (int i = 1; i < n; ++i) p = p * h[i];
  return p;
}

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

GBCentredRibbonPatch::GBCentredRibbonPatch(GBRibbonPatch ribbons, Vec3 centre, Vec3 centre_default)
    : PatchType(with_centre(ribbons, centre, centre_default)),
      ribbons_(std::move(ribbons)),
      params_(ribbons_.polygon().vertices()) {
  Vec2 c(0);
  for (const Vec2& v : ribbons_.polygon().vertices()) c += v;
  c /= double(ribbons_.polygon().vertices().size());
  if (!inside(ribbons_.polygon().vertices(), c))
    throw std::invalid_argument(
        "the central point needs the average of the domain vertices "
        "inside the domain (this face is too concave)");
  const double h = h_product(params_, c).f;
  if (!(std::isfinite(h) && h * h > 1e-200))
    throw std::invalid_argument("the central point's weight vanishes at the domain centre");
  scale_ = 1 / (h * h);
}

ControlPointKind GBCentredRibbonPatch::kind(std::size_t k) const {
  if (k == centre_index()) return ControlPointKind::Central;
  if (k == centre_default_index()) return ControlPointKind::Inner;
  return ribbons_.kind(k);
}

void GBCentredRibbonPatch::set_control_point(std::size_t k, const Vec3& p) {
  points_.at(k) = p;
  if (k < ribbons_.size()) ribbons_.set_control_point(k, p);
}

Jet GBCentredRibbonPatch::centre_weight(Vec2 x) const {
  // At a domain vertex two factors vanish linearly: phi_0 and its first and second derivatives
  // are 0 there (mean value coordinates are not evaluated at vertices).
  for (const Vec2& v : ribbons_.polygon().vertices())
    if (x == v) return Jet{};
  const Jet p = h_product(params_, x);
  return (p * p) * scale_;
}

void GBCentredRibbonPatch::basis(Vec2 x, std::span<Jet> out) const {
  ribbons_.basis(x, out.first(ribbons_.size()));
  const Jet w = centre_weight(x);
  out[centre_index()] = w;
  out[centre_default_index()] = -w;
}

namespace {
void add_centre(SurfaceJet& s, const Jet& w, Vec3 d) {
  s.p += w.f * d;
  s.su += w.fu * d;
  s.sv += w.fv * d;
  s.suu += w.fuu * d;
  s.suv += w.fuv * d;
  s.svv += w.fvv * d;
}
}  // namespace

SurfaceJet GBCentredRibbonPatch::evaluate(Vec2 x) const {
  SurfaceJet s = ribbons_.evaluate(x);
  const Vec3 d = points_[centre_index()] - points_[centre_default_index()];
  if (d != Vec3(0)) add_centre(s, centre_weight(x), d);
  return s;
}

void GBCentredRibbonPatch::evaluate_many(std::span<const Vec2> xs,
                                         std::span<SurfaceJet> out) const {
  ribbons_.evaluate_many(xs, out);
  const Vec3 d = points_[centre_index()] - points_[centre_default_index()];
  if (d == Vec3(0)) return;
  for (std::size_t i = 0; i < xs.size() && i < out.size(); ++i)
    add_centre(out[i], centre_weight(xs[i]), d);
}

void GBCentredRibbonPatch::influence(std::size_t k, std::span<const Vec2> xs,
                                     std::span<Jet> out) const {
  if (k < ribbons_.size()) return ribbons_.influence(k, xs, out);
  const double sign = k == centre_index() ? 1 : -1;
  for (std::size_t i = 0; i < xs.size() && i < out.size(); ++i)
    out[i] = centre_weight(xs[i]) * sign;
}

}  // namespace pl
