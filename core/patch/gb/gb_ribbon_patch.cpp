#include "core/patch/gb/gb_ribbon_patch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/patch/gb/blend.hpp"
#include "core/patch/gb/ribbon_local.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/patch/gb/vertex_limits.hpp"

namespace pl {

namespace {

// Checked before any member is built from it.
const ConcavePolygonDomain& checked(const ConcavePolygonDomain& domain) {
  if (domain.side_count() > GBRibbonPatch::kMaxSides)
    throw std::invalid_argument("a gb-ribbons patch has at most " +
                                std::to_string(GBRibbonPatch::kMaxSides) + " sides, got " +
                                std::to_string(domain.side_count()));
  return domain;
}

bool is_convex(const ConcavePolygonDomain& d);

}  // namespace

GBRibbonPatch::GBRibbonPatch(ConcavePolygonDomain domain,
                             const std::vector<std::vector<std::vector<Vec3>>>& ribbons)
    : domain_(checked(domain)), params_(domain_.vertices()) {
  const int n = domain_.side_count();
  if (static_cast<int>(ribbons.size()) != n)
    throw std::invalid_argument("gb-ribbons patch has " + std::to_string(ribbons.size()) +
                                " ribbons for a " + std::to_string(n) + "-sided domain");
  for (int i = 0; i < n; ++i) {
    const auto& r = ribbons[i];
    const std::string which = "ribbon " + std::to_string(i);
    if (r.size() < 2)
      throw std::invalid_argument(which + " needs at least 2 layers (G1 needs the second row)");
    if (r[0].size() < 2) throw std::invalid_argument(which + " needs degree >= 1");
    if (r[0].size() > kMaxDegree + 1 || r.size() > kMaxLayers)
      throw std::invalid_argument(which + " exceeds degree " + std::to_string(kMaxDegree) + " or " +
                                  std::to_string(kMaxLayers) + " layers");
    for (const auto& row : r)
      if (row.size() != r[0].size())
        throw std::invalid_argument(which + " has rows of different lengths");
    degree_.push_back(static_cast<int>(r[0].size()) - 1);
    layers_.push_back(static_cast<int>(r.size()));
    for (const auto& row : r)
      for (const Vec3& p : row)
        if (!finite(p)) throw std::invalid_argument(which + " has a non-finite control point");
  }
  for (int i = 0; i < n; ++i) {
    const Vec3 a = ribbons[i][0].back(), b = ribbons[(i + 1) % n][0].front();
    const double scale = 1 + std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    if (glm::length(a - b) > 1e-12 * scale)
      throw std::invalid_argument("ribbon " + std::to_string(i) + " does not end where ribbon " +
                                  std::to_string((i + 1) % n) + " starts");
    const Vec2 ea = domain_.vertex(i) - domain_.vertex(i - 1);
    const Vec2 eb = domain_.vertex(i + 1) - domain_.vertex(i);
    if (!(std::fabs(cross(ea, eb)) > 1e-9 * glm::length(ea) * glm::length(eb)))
      throw std::invalid_argument("domain corner " + std::to_string(i) + " is straight");
  }
  std::size_t count = 0;
  for (int i = 0; i < n; ++i) {
    offset_.push_back(count);
    count += degree_[i] + (layers_[i] - 1) * (degree_[i] + 1);
  }
  offset_.push_back(count);
  points_.assign(count, Vec3(0));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < layers_[i]; ++k)
      for (int j = 0; j <= degree_[i]; ++j)
        if (k > 0 || j < degree_[i]) points_[index(i, j, k)] = ribbons[i][k][j];
  convex_ = is_convex(domain_);
  check_parameterisation();
}

std::size_t GBRibbonPatch::index(int side, int j, int k) const {
  const int n = sides();
  side = ((side % n) + n) % n;
  const int d = degree_[side];
  if (k == 0) return j == d ? offset_[(side + 1) % n] : offset_[side] + j;
  return offset_[side] + d + (k - 1) * (d + 1) + j;
}

ControlPointKind GBRibbonPatch::kind(std::size_t k) const {
  const auto it = std::upper_bound(offset_.begin(), offset_.end(), k);
  const int side = static_cast<int>(it - offset_.begin()) - 1;
  return k - offset_[side] < std::size_t(degree_[side]) ? ControlPointKind::Boundary
                                                        : ControlPointKind::Inner;
}

std::vector<std::vector<std::vector<Vec3>>> GBRibbonPatch::ribbons() const {
  std::vector<std::vector<std::vector<Vec3>>> r(sides());
  for (int i = 0; i < sides(); ++i) {
    r[i].assign(layers_[i], std::vector<Vec3>(degree_[i] + 1));
    for (int k = 0; k < layers_[i]; ++k)
      for (int j = 0; j <= degree_[i]; ++j) r[i][k][j] = point(i, j, k);
  }
  return r;
}

std::vector<BezierCurve> GBRibbonPatch::boundary_curves() const {
  std::vector<BezierCurve> c;
  for (const auto& r : ribbons()) c.emplace_back(r[0]);
  return c;
}

void GBRibbonPatch::evaluate_shared(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
  std::string layout = kType;
  layout += '|';
  layout += domain_.key();
  for (std::size_t i = 0; i < degree_.size(); ++i) {
    layout += '|';
    layout += std::to_string(degree_[i]);
    layout += ',';
    layout += std::to_string(layers_[i]);
  }
  const std::size_t width = size();
  const auto block =
      shared_basis_block(layout, xs, width, [this](Vec2 x, std::span<Jet> row) { basis(x, row); });
  // Relative to one control point, so that a far-away patch does not round its offsets away.
  // Without a kept block the basis is evaluated here, the same numbers summed the same way: a
  // face's samples do not depend on whether another face asked for its block before.
  const Vec3 origin = points_[0];
  std::vector<Jet> own(block ? 0 : width);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!block) basis(xs[i], own);
    const Jet* phi = block ? block->data() + i * width : own.data();
    SurfaceJet s;
    for (std::size_t k = 0; k < width; ++k) add_scaled(s, phi[k], points_[k] - origin);
    s.p += origin;
    out[i] = s;
  }
}

void GBRibbonPatch::basis(Vec2 x, std::span<Jet> out) const {
  const int n = sides();
  const auto& v = domain_.vertices();
  for (int i = 0; i < n; ++i)
    if (x == v[i]) {
      std::fill(out.begin(), out.end(), Jet(0.0));
      return gb_ribbon_corner_basis(*this, i, out);
    }
  const Jet inv = reciprocal(blends(x, out));
  for (Jet& b : out) b = b * inv;
}

Jet GBRibbonPatch::blends(Vec2 x, std::span<Jet> out) const {
  const int n = sides();
  std::fill(out.begin(), out.end(), Jet(0.0));
  const RibbonLocalOf<double> L(params_, x.x, x.y);
  Jet sum(0.0);
  RibbonPowers t;
  for (int i = 0; i < n; ++i) {
    const int d = degree_[i], m = 2 * layers_[i] - 1;
    const Jet& prev = L.lam[i == 0 ? n - 1 : i - 1];
    t.build(L.lam[i], prev, prev + L.lam[i], L.h[i], d, layers_[i]);
    for (int k = 0; k < layers_[i]; ++k) {
      const Jet hk = binomial(m, k) * t.hp(k);
      for (int j = 0; j <= d; ++j) {
        const Jet b = weighted(binomial(d, j) * homogeneous(t, j, d - j, m - k - d) * hk,
                               ribbon_mu(d, j), L.alpha.data(), i, n);
        out[index(i, j, k)] += b;
        sum += b;
      }
    }
  }
  return sum;
}

namespace {

// The points the parameterization checks look at: a tessellation's interior points.
std::vector<Vec2> interior_samples(const ConcavePolygonDomain& domain) {
  constexpr int kCheckDensity = 16;
  const Tessellation t = domain.tessellate(kCheckDensity);
  std::vector<bool> boundary(t.points.size(), false);
  for (const auto& side : t.sides)
    for (uint32_t k : side) boundary[k] = true;
  std::vector<Vec2> xs;
  for (std::size_t k = 0; k < t.points.size(); ++k)
    if (!boundary[k]) xs.push_back(t.points[k]);
  return xs;
}

// Samples per side of the checks on the sides.
constexpr int kSideSamples = 16;

// The least share of its coordinates' slope at which D_i may grow from a side where they all
// vanish: |s_i| up to ~1 / kMinShare next to the side.
constexpr double kMinShare = 1e-3;

bool is_convex(const ConcavePolygonDomain& d) {
  for (int i = 0; i < d.side_count(); ++i)
    if (!(cross(d.vertex(i) - d.vertex(i - 1), d.vertex(i + 1) - d.vertex(i)) > 0)) return false;
  return true;
}

std::string at(Vec2 x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.3g, %.3g)", x.x, x.y);
  return buf;
}

}  // namespace

std::vector<int> GBRibbonPatch::sides_without_positive_pair(const ConcavePolygonDomain& domain,
                                                            std::vector<Vec2>* where) {
  // Inside a convex polygon the coordinates are all positive (Floater 2003): only a domain with
  // a reflex corner needs the sampled check (it costs a few ms, paid on every re-fill of a drag).
  std::vector<int> out;
  if (is_convex(domain)) return out;
  const int n = domain.side_count();
  std::vector<Jet> lam(n);
  std::vector<char> bad(n, 0);
  const auto flag = [&](int i, Vec2 x) {
    if (bad[i]) return;
    bad[i] = 1;
    out.push_back(i);
    if (where) where->push_back(x);
  };
  for (const Vec2& x : interior_samples(domain)) {
    mean_value_coordinates(domain.vertices(), x, lam);
    for (int i = 0; i < n; ++i)
      if (!(lam[(i + n - 1) % n].f + lam[i].f > 0)) flag(i, x);
  }
  // D_i vanishes on every side s away from vertices i-1 and i, and so do lambda_{i-1} and
  // lambda_i; s_i = lambda_i / D_i stays bounded next to side s only if D_i grows into the
  // domain at least a fraction of as fast as they do. Where it does not, D_i is negative (or
  // vanishes to second order) in a layer along side s too thin for the interior samples, and
  // a ribbon with d_i > l_i has a pole there: checked on the sides.
  for (int s = 0; s < n; ++s) {
    const Vec2 a = domain.vertex(s - 1), b = domain.vertex(s);
    const Vec2 inward = Vec2(a.y - b.y, b.x - a.x) / glm::length(b - a);  // CCW polygon
    for (int k = 0; k < kSideSamples; ++k) {
      const Vec2 x = a + ((k + 0.5) / kSideSamples) * (b - a);
      mean_value_coordinates(domain.vertices(), x, lam);
      for (int i = 0; i < n; ++i) {
        const int p = (i + n - 1) % n, s0 = (s + n - 1) % n;
        if (p == s0 || p == s || i == s0 || i == s) continue;  // D_i > 0 on side s
        const auto slope = [&](const Jet& f) { return f.fu * inward.x + f.fv * inward.y; };
        const double pair = std::max(std::fabs(slope(lam[p])), std::fabs(slope(lam[i])));
        if (pair > 0 && !(slope(lam[p] + lam[i]) > kMinShare * pair)) flag(i, x);
      }
    }
  }
  return out;
}

void GBRibbonPatch::check_parameterisation() const {
  // Mean value coordinates can be negative behind reflex vertices. Where D_i = lambda_{i-1} +
  // lambda_i vanishes inside the domain, a ribbon with d_i > l_i has a pole (its blend carries
  // 1 / D_i^(d_i - l_i)); a ribbon with d_i <= l_i is polynomial in the coordinates and has
  // none. Every blend is finite then, and the patch needs only a positive sum of blends.
  if (convex_) return;  // positive coordinates, positive blends
  // h_s must grow into the domain from side s: its slope is the sum of the other coordinates'
  // slopes, and behind reflex corners some of those are negative. Where they cancel, ribbon s
  // has no cross-boundary direction (the surface folds along the side): no layer helps.
  const int n = sides();
  std::vector<Jet> lam(n);
  for (int s = 0; s < n; ++s) {
    const Vec2 a = domain_.vertex(s - 1), b = domain_.vertex(s);
    const Vec2 inward = Vec2(a.y - b.y, b.x - a.x) / glm::length(b - a);
    for (int k = 0; k < kSideSamples; ++k) {
      const Vec2 x = a + ((k + 0.5) / kSideSamples) * (b - a);
      mean_value_coordinates(domain_.vertices(), x, lam);
      double slope = 0, total = 0;
      for (int j = 0; j < n; ++j) {
        const double sj = lam[j].fu * inward.x + lam[j].fv * inward.y;
        total += std::fabs(sj);
        if (j != (s + n - 1) % n && j != s) slope += sj;
      }
      if (!(slope > kMinShare * total))
        throw std::invalid_argument(
            "domain too concave for mean value coordinates: on side " + std::to_string(s) + " at " +
            at(x) +
            " the distance parameter h does not grow into the domain (the coordinates of "
            "vertices hidden behind reflex corners cancel it)");
    }
  }
  std::vector<Vec2> where;
  const std::vector<int> bad = sides_without_positive_pair(domain_, &where);
  for (std::size_t b = 0; b < bad.size(); ++b) {
    const int i = bad[b];
    if (degree_[i] > layers_[i])
      throw std::invalid_argument(
          "domain too concave for mean value coordinates: lambda_i-1 + lambda_i <= 0 at " +
          at(where[b]) + " for side " + std::to_string(i) + ", a pole of its ribbon (degree " +
          std::to_string(degree_[i]) + ", " + std::to_string(layers_[i]) +
          " layers; a ribbon with as many layers as its degree has none)");
  }
  std::vector<Jet> phi(size());
  for (const Vec2& x : interior_samples(domain_)) {
    const Jet w = blends(x, phi);
    if (!(w.f > 0) || !std::isfinite(w.fuu) || !std::isfinite(w.fuv) || !std::isfinite(w.fvv))
      throw std::invalid_argument("gb-ribbons blend sum is not positive at " + at(x) +
                                  " inside the domain");
  }
}

}  // namespace pl
