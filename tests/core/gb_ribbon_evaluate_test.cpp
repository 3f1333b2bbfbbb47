// GBRibbonPatch::evaluate (the direct sum b C / sum b with power tables) against the reference
// sum of basis() times the control points: positions, first and second derivatives on random
// interior points, on the sides and at the corners, over convex and concave domains, with mixed
// degrees and layer counts (up to the format's limits). Near the corners (1e-9 .. 1e-3 away) the
// blend's derivatives grow like 1 / distance^2 and cancel, and the reference sum itself loses
// digits (~1e-6 of the second derivatives at 1e-9), so there both are compared with the same
// blend summed in binary128 from the same mean value coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "core/domain/tessellation.hpp"
#include "core/math/bernstein.hpp"
#include "core/math/jet.hpp"
#include "core/param/mean_value.hpp"
#include "core/patch/gb/central_weight.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gb/shared_basis.hpp"

namespace pl {
namespace {

std::vector<Vec2> regular(int n) {
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i)
    v.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
  return v;
}

const std::vector<Vec2> kSkewed = {{0, 0}, {3, 0.2}, {3.4, 1.5}, {1.2, 2.1}, {-0.4, 1.1}};
// Concave: one reflex corner (a chevron), two (a T), and every other corner (a 7-pointed star).
const std::vector<Vec2> kChevron = {{0, 0}, {1.5, 0.8}, {3, 0}, {3, 1.5}, {0, 1.5}};
const std::vector<Vec2> kT = {{1, 0}, {2, 0}, {2, 1.2}, {3, 1.2},
                              {3, 2}, {0, 2}, {0, 1.2}, {1, 1.2}};
std::vector<Vec2> star(int points) {
  std::vector<Vec2> v = regular(2 * points);
  for (std::size_t i = 1; i < v.size(); i += 2) v[i] *= 0.65;
  return v;
}

// Ribbons over a wavy lift of the domain with random offsets: cubic with two layers (what
// network faces use) except side 0 of degree d0 and side 1 with l1 layers, so that D_i has
// negative exponents (d > l) and there are several layers.
GBRibbonPatch make_patch(const std::vector<Vec2>& poly, int d0, int l1) {
  const ConcavePolygonDomain dom(poly);
  const int n = dom.side_count();
  // Sides where the mean value coordinates would give a ribbon with d > l a pole (the T) get as
  // many layers as their degree, as network faces do (gb_face.cpp).
  std::vector<char> pole(n, 0);
  for (int i : GBRibbonPatch::sides_without_positive_pair(dom)) pole[i] = 1;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> z(-0.2, 0.2);
  std::vector<std::vector<std::vector<Vec3>>> ribbons(n);
  for (int i = 0; i < n; ++i) {
    const int d = i == 0 ? d0 : 3, l = std::max(i == 1 ? l1 : 2, pole[i] ? d : 0);
    const Vec2 e = dom.vertex(i) - dom.vertex(i - 1);
    const Vec2 inward = Vec2(-e.y, e.x) / glm::length(e);
    for (int k = 0; k < l; ++k) {
      std::vector<Vec3> row;
      for (int j = 0; j <= d; ++j) {
        const Vec2 q = dom.side_point(i, double(j) / d) + 0.2 * k / (l - 1) * inward;
        Vec3 p{q.x, q.y, 0.3 * std::sin(1.3 * q.x) * std::cos(0.7 * q.y)};
        if (!(k == 0 && (j == 0 || j == d))) p += Vec3(z(rng), z(rng), z(rng));
        row.push_back(p);
      }
      ribbons[i].push_back(row);
    }
  }
  return GBRibbonPatch(dom, ribbons);
}

const Vec3 SurfaceJet::*const kParts[] = {&SurfaceJet::p,   &SurfaceJet::su,  &SurfaceJet::sv,
                                          &SurfaceJet::suu, &SurfaceJet::suv, &SurfaceJet::svv};

SurfaceJet basis_sum(const GBRibbonPatch& g, Vec2 x) {
  std::vector<Jet> phi(g.size());
  g.basis(x, phi);
  return combine(g.control_points(), phi);
}

// Largest difference over the six quantities; NaN where the reference r is not finite. Each
// quantity is measured relative to `scale` (its size, floored at 1, the size of the geometry).
double relative_difference(const SurfaceJet& s, const SurfaceJet& r, const SurfaceJet& scale) {
  double worst = 0;
  for (auto part : kParts) {
    const Vec3 a = s.*part, b = r.*part;
    if (!std::isfinite(b.x + b.y + b.z)) return NAN;
    if (!std::isfinite(a.x + a.y + a.z)) return INFINITY;
    worst = std::max(worst, glm::length(a - b) / std::max(1.0, glm::length(scale.*part)));
  }
  return worst;
}
double relative_difference(const SurfaceJet& s, const SurfaceJet& r) {
  return relative_difference(s, r, r);
}

// evaluate(x) against the basis() sum, each quantity relative to the size of the sum's terms,
// sum_k |phi_k| |C_k| (the scale of its rounding; where the terms cancel, e.g. a mixed
// derivative that is small by symmetry, the sum is not accurate relative to its result).
double difference_to_basis_sum(const GBRibbonPatch& g, Vec2 x) {
  std::vector<Jet> phi(g.size());
  g.basis(x, phi);
  SurfaceJet terms;
  for (std::size_t k = 0; k < phi.size(); ++k) {
    const double c = glm::length(g.control_point(k));
    const Jet& w = phi[k];
    terms.p.x += std::fabs(w.f) * c, terms.su.x += std::fabs(w.fu) * c;
    terms.sv.x += std::fabs(w.fv) * c, terms.suu.x += std::fabs(w.fuu) * c;
    terms.suv.x += std::fabs(w.fuv) * c, terms.svv.x += std::fabs(w.fvv) * c;
  }
  return relative_difference(g.evaluate(x), combine(g.control_points(), phi), terms);
}

// Each quantity's scale for relative_difference(): the size of the largest quantity of its
// order (a mixed derivative that is small by symmetry next to large pure ones is not resolved
// better than those).
SurfaceJet order_scale(const SurfaceJet& e) {
  const double first = std::max(glm::length(e.su), glm::length(e.sv));
  const double second = std::max({glm::length(e.suu), glm::length(e.suv), glm::length(e.svv)});
  SurfaceJet s;
  s.p = e.p;
  s.su = s.sv = Vec3(first, 0, 0);
  s.suu = s.suv = s.svv = Vec3(second, 0, 0);
  return s;
}

// The worst difference of a group of samples, and how many samples the reference could not
// evaluate.
struct Worst {
  double value = 0;
  int reference_not_finite = 0;
  void add(double d) {
    if (std::isnan(d))
      ++reference_not_finite;
    else
      value = std::max(value, d);
  }
};

// The blend summed in binary128 from the (double) mean value coordinates at x: the same
// formula as basis() with ~34 digits, so near a corner it is exact next to either double sum.
// Only for points off the sides (no one-sided limits).
using Quad = __float128;
struct QuadJet {
  Quad f = 0, fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0;
};
// The product and chain rules of core/math/jet.hpp, on binary128.
QuadJet operator*(const QuadJet& a, const QuadJet& b) {
  return jet_product(a, b);
}
QuadJet operator+(const QuadJet& a, const QuadJet& b) {
  return {a.f + b.f, a.fu + b.fu, a.fv + b.fv, a.fuu + b.fuu, a.fuv + b.fuv, a.fvv + b.fvv};
}
QuadJet operator*(Quad s, const QuadJet& a) {
  return {s * a.f, s * a.fu, s * a.fv, s * a.fuu, s * a.fuv, s * a.fvv};
}
QuadJet reciprocal(const QuadJet& a) {
  const Quad r = 1 / a.f;
  return jet_chain(a, r, -r * r, 2 * r * r * r);
}

// a^0 .. a^top.
std::vector<QuadJet> powers(const QuadJet& a, int top) {
  std::vector<QuadJet> p{QuadJet{1}};
  for (int i = 1; i <= top; ++i) p.push_back(p.back() * a);
  return p;
}

SurfaceJet quad_sum(const GBRibbonPatch& g, Vec2 x) {
  const int n = g.sides();
  // lambda, h and D in double as both double sums form them (the same inputs; D can cancel
  // where mean value coordinates turn negative), the rest in binary128.
  std::vector<Jet> lam_d(n), h_d(n, Jet(0.0)), D_d(n);
  mean_value_coordinates(g.polygon().vertices(), x, lam_d);
  for (int i = 0; i < n; ++i) {
    D_d[i] = lam_d[(i + n - 1) % n] + lam_d[i];
    for (int j = 1; j < n - 1; ++j) h_d[i] += lam_d[(i + j) % n];
  }
  const auto quad = [](const Jet& a) { return QuadJet{a.f, a.fu, a.fv, a.fuu, a.fuv, a.fvv}; };
  std::vector<QuadJet> lam(n), h(n), Ds(n);
  for (int i = 0; i < n; ++i) lam[i] = quad(lam_d[i]), h[i] = quad(h_d[i]), Ds[i] = quad(D_d[i]);
  const auto at = [n](const std::vector<QuadJet>& a, int i) { return a[(i + n) % n]; };
  QuadJet w, s[3];
  for (int i = 0; i < n; ++i) {
    const int d = g.degree(i), m = 2 * g.layers(i) - 1;
    const QuadJet D = Ds[i], h2 = h[i] * h[i];
    const QuadJet hp2 = at(h, i - 1) * at(h, i - 1), hn2 = at(h, i + 1) * at(h, i + 1);
    const QuadJet alpha = hp2 * reciprocal(hp2 + h2), beta = hn2 * reciprocal(hn2 + h2);
    const auto la = powers(lam[i], d), lb = powers(at(lam, i - 1), d), hp = powers(h[i], m);
    const auto dp = powers(D, m), rp = powers(reciprocal(D), d);
    for (int k = 0; k < g.layers(i); ++k)
      for (int j = 0; j <= d; ++j) {
        const int e = m - k - d;
        QuadJet b = Quad(binomial(d, j) * binomial(m, k)) * la[j] * lb[d - j] *
                    (e >= 0 ? dp[e] : rp[-e]) * hp[k];
        if (2 * j < d) b = b * alpha;
        if (2 * j > d) b = b * beta;
        const Vec3 c = g.point(i, j, k);
        w = w + b;
        for (int e = 0; e < 3; ++e) s[e] = s[e] + Quad(c[e]) * b;
      }
  }
  const QuadJet inv = reciprocal(w);
  SurfaceJet r;
  for (int e = 0; e < 3; ++e) {
    const QuadJet q = s[e] * inv;
    r.p[e] = double(q.f), r.su[e] = double(q.fu), r.sv[e] = double(q.fv);
    r.suu[e] = double(q.fuu), r.suv[e] = double(q.fuv), r.svv[e] = double(q.fvv);
  }
  return r;
}

struct Case {
  const char* name;
  std::vector<Vec2> poly;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> c{{"pentagon", regular(5)}, {"triangle", regular(3)},
                                   {"octagon", regular(8)},  {"skewed", kSkewed},
                                   {"chevron", kChevron},    {"T", kT},
                                   {"star", star(7)}};
  return c;
}

// (degree of side 0, layers of side 1): plain cubic ribbons, moderate, and the format's limits.
constexpr int kVariants[][2] = {
    {3, 2}, {7, 4}, {GBRibbonPatch::kMaxDegree, 2}, {3, GBRibbonPatch::kMaxLayers}};

std::string label(const Case& c, const int* variant) {
  return std::string(c.name) + ", d_0 " + std::to_string(variant[0]) + ", l_1 " +
         std::to_string(variant[1]);
}

TEST(GBRibbonEvaluate, MatchesBasisSumInsideOnSidesAndAtCorners) {
  Worst interior, side, corner;
  for (const Case& c : cases())
    for (const auto& variant : kVariants) {
      SCOPED_TRACE(label(c, variant));
      const GBRibbonPatch g = make_patch(c.poly, variant[0], variant[1]);
      const auto& dom = g.polygon();
      std::mt19937_64 rng(11);
      std::uniform_real_distribution<double> ut(0, 1);
      // Random points of random triangles of a coarse tessellation: inside the domain.
      const Tessellation tess = dom.tessellate(6);
      std::uniform_int_distribution<std::size_t> tri(0, tess.triangles.size() - 1);
      for (int sample = 0; sample < 60; ++sample) {
        const auto& t = tess.triangles[tri(rng)];
        double a = ut(rng), b = ut(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Vec2 x = tess.points[t[0]] + a * (tess.points[t[1]] - tess.points[t[0]]) +
                       b * (tess.points[t[2]] - tess.points[t[0]]);
        interior.add(difference_to_basis_sum(g, x));
      }
      for (int i = 0; i < g.sides(); ++i) {
        for (int s = 0; s < 6; ++s) {
          const Vec2 x = dom.side_point(i, ut(rng));
          side.add(difference_to_basis_sum(g, x));
        }
        corner.add(relative_difference(g.evaluate(dom.vertex(i)), basis_sum(g, dom.vertex(i))));
      }
    }
  std::printf(
      "evaluate vs basis sum, relative to its terms: interior %.2e, sides %.2e, corners %.2e\n",
      interior.value, side.value, corner.value);
  EXPECT_LE(interior.value, 1e-13);
  EXPECT_LE(side.value, 1e-13);
  EXPECT_EQ(corner.value, 0);  // the same gb_ribbon_corner_basis() path
  EXPECT_EQ(interior.reference_not_finite + side.reference_not_finite + corner.reference_not_finite,
            0);
}

TEST(GBRibbonEvaluate, NearCornersCloserToExactSumThanBasisSum) {
  const double distances[] = {1e-9, 1e-7, 1e-5, 1e-3};
  // Worst relative errors per distance; evaluate()'s also without degree 30, whose power tables
  // (rounded alike in both double sums, lambda^30 times 1 / D^28) dominate it at 1e-3.
  Worst evaluate_error[4], basis_error[4], evaluate_error_below_30[4];
  int both_overflow = 0;
  for (const Case& c : cases())
    for (const auto& variant : kVariants) {
      SCOPED_TRACE(label(c, variant));
      const GBRibbonPatch g = make_patch(c.poly, variant[0], variant[1]);
      const auto& dom = g.polygon();
      for (int i = 0; i < g.sides(); ++i) {
        // Into the domain along the corner's bisector (negated at reflex corners), and close to
        // either side.
        const Vec2 v = dom.vertex(i), a = glm::normalize(dom.vertex(i - 1) - v),
                   b = glm::normalize(dom.vertex(i + 1) - v);
        const Vec2 in = glm::normalize(a + b) * (cross(b, a) > 0 ? 1.0 : -1.0);
        for (int e = 0; e < 4; ++e)
          for (Vec2 dir : {in, glm::normalize(a + 0.1 * in), glm::normalize(b + 0.1 * in)}) {
            const Vec2 x = v + distances[e] * dir;
            const SurfaceJet exact = quad_sum(g, x);
            const SurfaceJet scale = order_scale(exact);
            const double ev = relative_difference(g.evaluate(x), exact, scale),
                         bs = relative_difference(basis_sum(g, x), exact, scale);
            // Degree 30 against a 1e-10 thin D of a ribbon away from the corner: 1 / D^28 and
            // its derivatives overflow in both double sums alike.
            if (std::isinf(ev) && std::isinf(bs)) {
              ++both_overflow;
              continue;
            }
            evaluate_error[e].add(ev);
            if (variant[0] < GBRibbonPatch::kMaxDegree) evaluate_error_below_30[e].add(ev);
            basis_error[e].add(bs);
          }
      }
    }
  for (int e = 0; e < 4; ++e) {
    std::printf(
        "%.0e from a corner, relative to the binary128 sum: evaluate %.2e (%.2e below degree "
        "30), basis sum %.2e (%d samples the binary128 sum could not evaluate)\n",
        distances[e], evaluate_error[e].value, evaluate_error_below_30[e].value,
        basis_error[e].value, evaluate_error[e].reference_not_finite);
    EXPECT_LE(evaluate_error[e].value, basis_error[e].value);
    EXPECT_LE(evaluate_error_below_30[e].value, 1e-13);
    EXPECT_EQ(evaluate_error[e].reference_not_finite, 0);
  }
  std::printf("%d samples overflowed in both double sums\n", both_overflow);
}

}  // namespace
}  // namespace pl

namespace pl {
namespace {

// evaluate_many() on its own (the SIMD path: quotient form over convex domains, the homogeneous
// sums over concave ones, the scalar path on the sides and at the corners) gives evaluate()'s
// numbers bit for bit, in the wide and the narrow lanes; so does the interior-control variant's
// central weight.
TEST(GBRibbonEvaluate, BatchedEqualsScalarBitForBit) {
  const SharedBasisBypass alone;
  std::size_t samples = 0, differing = 0;
  for (const Case& c : cases())
    for (const auto& variant : kVariants) {
      SCOPED_TRACE(label(c, variant));
      const GBRibbonPatch g = make_patch(c.poly, variant[0], variant[1]);
      const Tessellation t = g.polygon().tessellate(9);  // vertices, sides and inside
      const CentralWeight centre(g.polygon());
      for (bool narrow : {false, true}) {
        narrow_lanes_only = narrow;
        std::vector<SurfaceJet> many(t.points.size());
        g.evaluate_many(t.points, many);
        std::vector<Jet> weights(t.points.size());
        centre.evaluate_many(t.points, weights);
        for (std::size_t i = 0; i < t.points.size(); ++i) {
          const SurfaceJet one = g.evaluate(t.points[i]);
          const Jet w = centre(t.points[i]);
          ++samples;
          if (!(many[i].p == one.p && many[i].su == one.su && many[i].sv == one.sv &&
                many[i].suu == one.suu && many[i].suv == one.suv && many[i].svv == one.svv &&
                weights[i].f == w.f && weights[i].fuu == w.fuu && weights[i].fuv == w.fuv))
            ++differing;
        }
      }
      narrow_lanes_only = false;
    }
  std::printf("[ batch     ] %zu samples, %zu differ from the scalar path\n", samples, differing);
  EXPECT_GT(samples, 1000u);
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace pl
