// GB patch with independent ribbons over convex and concave polygons: ribbon interpolation and
// G1 (against the ribbons themselves), exact derivatives against finite differences, finite
// samples everywhere, incremental drags against full re-evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/eval/patch_evaluator.hpp"
#include "core/math/bernstein.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"

namespace pl {
namespace {

const std::vector<Vec2> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
const std::vector<Vec2> kNotch = {{0, 0}, {2, 0}, {2, 2}, {1, 0.6}, {0, 2}};
const std::vector<Vec2> kStar = [] {
  std::vector<Vec2> v;
  for (int i = 0; i < 10; ++i) {
    const double a = 2 * M_PI * i / 10, r = i % 2 ? 0.6 : 1.0;
    v.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return v;
}();
// A U: points in one prong see the inner side of the other prong from behind, where mean value
// coordinates make lambda_i-1 + lambda_i negative; the patch must refuse it.
const std::vector<Vec2> kU = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.8}, {1, 0.8}, {1, 2}, {0, 2}};

std::vector<Vec2> regular(int n) {
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i)
    v.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
  return v;
}

Vec3 lift(Vec2 x) {
  return {x.x, x.y, 0.3 * std::sin(1.3 * x.x) * std::cos(0.7 * x.y)};
}

// Ribbons over the lifted domain with random heights; degrees and layers vary per side.
GBRibbonPatch make_patch(const std::vector<Vec2>& poly, unsigned seed, bool vary = true) {
  const ConcavePolygonDomain dom(poly);
  const int n = dom.side_count();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> z(-0.1, 0.1);
  std::vector<std::vector<std::vector<Vec3>>> ribbons(n);
  for (int i = 0; i < n; ++i) {
    const int d = vary ? 3 + i % 3 : 3, l = vary ? 2 + (i % 2) : 2;
    const Vec2 e = dom.vertex(i) - dom.vertex(i - 1);
    const Vec2 inward = Vec2(-e.y, e.x) / glm::length(e);
    for (int k = 0; k < l; ++k) {
      std::vector<Vec3> row;
      for (int j = 0; j <= d; ++j) {
        Vec3 p = lift(dom.side_point(i, double(j) / d) + 0.15 * k * inward);
        if (!(k == 0 && (j == 0 || j == d))) p.z += z(rng);
        row.push_back(p);
      }
      ribbons[i].push_back(row);
    }
  }
  return GBRibbonPatch(dom, ribbons);
}

double angle_deg(Vec3 a, Vec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180 / M_PI;
}

// Ribbon side i at t: point, tangent along the side, derivative across it (in h), computed
// from the ribbon's control points alone.
struct RibbonFrame {
  Vec3 p, dt, dh;
};
RibbonFrame ribbon_frame(const GBRibbonPatch& g, int i, double t) {
  const int d = g.degree(i), m = 2 * g.layers(i) - 1;
  std::vector<double> b(d + 1), b1(d + 1), b2(d + 1);
  bernstein_all_d2(d, t, b, b1, b2);
  RibbonFrame f{Vec3(0), Vec3(0), Vec3(0)};
  for (int j = 0; j <= d; ++j) {
    f.p += b[j] * g.point(i, j, 0);
    f.dt += b1[j] * g.point(i, j, 0);
    f.dh += b[j] * double(m) * (g.point(i, j, 1) - g.point(i, j, 0));
  }
  return f;
}

void check_ribbons(const GBRibbonPatch& g, double* worst_dev, double* worst_angle) {
  const auto& dom = g.polygon();
  double scale = 0;
  for (const Vec3& p : g.control_points()) scale = std::max(scale, glm::length(p));
  for (int i = 0; i < g.sides(); ++i)
    for (int k = 0; k <= 40; ++k) {
      const double t = k / 40.0;
      const RibbonFrame f = ribbon_frame(g, i, t);
      const SurfaceJet s = g.evaluate(dom.side_point(i, t));
      *worst_dev = std::max(*worst_dev, glm::length(s.p - f.p) / scale);
      if (k == 0 || k == 40) continue;  // corners: the two ribbons need not agree there
      // Su x Sv must be the ribbon's normal: tangent x inward derivative.
      *worst_angle =
          std::max(*worst_angle, angle_deg(glm::cross(s.su, s.sv), glm::cross(f.dt, f.dh)));
    }
}

TEST(ConcaveGBPatch, InterpolatesRibbonsAndIsG1WithThem) {
  double dev = 0, ang = 0;
  for (const auto& poly : {kL, kNotch, kStar}) check_ribbons(make_patch(poly, 3), &dev, &ang);
  for (int n = 3; n <= 12; ++n) check_ribbons(make_patch(regular(n), 10 + n), &dev, &ang);
  std::printf("ribbon interpolation: max relative deviation %.3g, max normal angle %.3g deg\n", dev,
              ang);
  EXPECT_LT(dev, 1e-12);
  EXPECT_LT(ang, 1e-6);
}

TEST(ConcaveGBPatch, DerivativesMatchFiniteDifferences) {
  // Gradient against central differences of positions; Hessian against central differences of
  // the exact gradient. Points away from the corners, including ones near the reflex vertex.
  const double h = 1e-5;
  for (const auto& [poly, xs] :
       {std::pair{kL,
                  std::vector<Vec2>{{0.5, 0.5}, {1.5, 0.4}, {0.3, 1.6}, {0.9, 0.9}, {1.9, 0.5}}},
        std::pair{regular(5), std::vector<Vec2>{{0, 0}, {0.3, 0.2}, {-0.5, 0.1}, {0.6, -0.5}}}}) {
    const GBRibbonPatch g = make_patch(poly, 7);
    for (Vec2 x : xs) {
      const SurfaceJet s = g.evaluate(x);
      const SurfaceJet pu = g.evaluate(x + Vec2(h, 0)), mu = g.evaluate(x - Vec2(h, 0));
      const SurfaceJet pv = g.evaluate(x + Vec2(0, h)), mv = g.evaluate(x - Vec2(0, h));
      EXPECT_LT(glm::length(s.su - (pu.p - mu.p) / (2 * h)), 1e-8) << x.x << "," << x.y;
      EXPECT_LT(glm::length(s.sv - (pv.p - mv.p) / (2 * h)), 1e-8);
      EXPECT_LT(glm::length(s.suu - (pu.su - mu.su) / (2 * h)), 1e-6);
      EXPECT_LT(glm::length(s.suv - (pu.sv - mu.sv) / (2 * h)), 1e-6);
      EXPECT_LT(glm::length(s.suv - (pv.su - mv.su) / (2 * h)), 1e-6);
      EXPECT_LT(glm::length(s.svv - (pv.sv - mv.sv) / (2 * h)), 1e-6);
    }
  }
}

TEST(ConcaveGBPatch, SideSamplesAreInteriorLimits) {
  // On a side the blends of the far ribbons are 0/0 and take their exact limit: the jets there
  // must continue the interior ones. The first-order extrapolation 2 J(d) - J(2d) from two
  // interior points at distance d and 2d removes the O(d) term.
  const double d = 1e-6;
  for (const auto& poly : {kL, kNotch}) {
    const GBRibbonPatch g = make_patch(poly, 5);
    const auto& dom = g.polygon();
    for (int i = 0; i < dom.side_count(); ++i)
      for (double t : {0.2, 0.5, 0.9}) {
        const Vec2 x = dom.side_point(i, t), e = dom.vertex(i) - dom.vertex(i - 1);
        const Vec2 in = Vec2(-e.y, e.x) / glm::length(e);
        const SurfaceJet a = g.evaluate(x), b = g.evaluate(x + d * in),
                         c = g.evaluate(x + 2 * d * in);
        const auto extrapolated = [](Vec3 one, Vec3 two) { return 2.0 * one - two; };
        EXPECT_LT(glm::length(a.su - extrapolated(b.su, c.su)), 1e-8) << i << " " << t;
        EXPECT_LT(glm::length(a.sv - extrapolated(b.sv, c.sv)), 1e-8) << i << " " << t;
        EXPECT_LT(glm::length(a.suu - extrapolated(b.suu, c.suu)), 1e-6) << i << " " << t;
        EXPECT_LT(glm::length(a.suv - extrapolated(b.suv, c.suv)), 1e-6) << i << " " << t;
        EXPECT_LT(glm::length(a.svv - extrapolated(b.svv, c.svv)), 1e-6) << i << " " << t;
      }
  }
}

// Ribbons with d > l have a pole where lambda_{i-1} + lambda_i vanishes; with as many layers as
// their degree they have none, and the patch over the same U is finite. A comb, where the
// distance parameter of some sides does not grow into the domain, is refused whatever the
// layers.
TEST(ConcaveGBPatch, RefusesDomainsWhereMeanValueCoordinatesFail) {
  EXPECT_THROW(make_patch(kU, 1), std::invalid_argument);
  const ConcavePolygonDomain dom(kU);
  const auto poles = GBRibbonPatch::sides_without_positive_pair(dom);
  ASSERT_FALSE(poles.empty());
  std::vector<std::vector<std::vector<Vec3>>> ribbons(dom.side_count());
  for (int i = 0; i < dom.side_count(); ++i) {
    const bool pole = std::find(poles.begin(), poles.end(), i) != poles.end();
    const Vec2 e = dom.vertex(i) - dom.vertex(i - 1), inward = Vec2(-e.y, e.x) / glm::length(e);
    for (int k = 0; k < (pole ? 3 : 2); ++k) {
      std::vector<Vec3> row;
      for (int j = 0; j <= 3; ++j)
        row.push_back(lift(dom.side_point(i, j / 3.0) + 0.15 * k * inward));
      ribbons[i].push_back(row);
    }
  }
  const GBRibbonPatch layered(dom, ribbons);
  for (const Vec2& x : dom.tessellate(24).points) {
    const SurfaceJet s = layered.evaluate(x);
    ASSERT_TRUE(std::isfinite(s.p.z + s.suu.z + s.suv.z + s.svv.z)) << x.x << " " << x.y;
  }
  const std::vector<Vec2> comb = {
      {0, 0},     {4, 0},     {4, 2},   {3.6, 2}, {3.6, 0.5}, {3.2, 0.5}, {3.2, 2}, {2.2, 2},
      {2.2, 0.5}, {1.8, 0.5}, {1.8, 2}, {0.8, 2}, {0.8, 0.5}, {0.4, 0.5}, {0.4, 2}, {0, 2}};
  try {
    make_patch(comb, 1, false);
    FAIL() << "expected the comb to be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("does not grow into the domain"), std::string::npos)
        << e.what();
  }
}

TEST(ConcaveGBPatch, NoNonFiniteSamples) {
  std::vector<std::vector<Vec2>> polys{kL, kNotch, kStar};
  for (int n = 3; n <= 12; ++n) polys.push_back(regular(n));
  for (const auto& poly : polys) {
    const GBRibbonPatch g = make_patch(poly, 11);
    for (int N : {1, 3, 16}) {
      const Tessellation t = g.domain().tessellate(N);
      for (const Vec2& x : t.points) {
        const SurfaceJet s = g.evaluate(x);
        for (const Vec3& v : {s.p, s.su, s.sv, s.suu, s.suv, s.svv})
          ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))
              << poly.size() << "-gon N=" << N << " at " << x.x << "," << x.y;
      }
    }
  }
}

TEST(ConcaveGBPatch, CornerValuesAndTangentsComeFromTheBoundaryCurves) {
  const GBRibbonPatch g = make_patch(kL, 2);
  const auto& dom = g.polygon();
  for (int i = 0; i < g.sides(); ++i) {
    const SurfaceJet s = g.evaluate(dom.vertex(i));
    EXPECT_EQ(s.p, g.point(i, g.degree(i), 0));
    // Directional derivatives along both sides equal the curves' end tangents.
    const Vec2 ea = dom.vertex(i) - dom.vertex(i - 1), eb = dom.vertex(i + 1) - dom.vertex(i);
    const Vec3 ta = ea.x * s.su + ea.y * s.sv, tb = eb.x * s.su + eb.y * s.sv;
    EXPECT_LT(glm::length(ta - ribbon_frame(g, i, 1).dt), 1e-12);
    EXPECT_LT(glm::length(tb - ribbon_frame(g, (i + 1) % g.sides(), 0).dt), 1e-12);
  }
}

TEST(ConcaveGBPatch, IncrementalDragsEqualFullReevaluation) {
  auto patch = std::make_shared<GBRibbonPatch>(make_patch(kL, 21));
  auto tess = std::make_shared<const Tessellation>(patch->domain().tessellate(20));
  PatchEvaluator incremental(patch, tess);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::size_t> pick(0, patch->size() - 1);
  std::uniform_real_distribution<double> step(-0.2, 0.2);
  for (int move = 0; move < 100; ++move) {
    const std::size_t k = pick(rng);
    incremental.move_control_point(k,
                                   patch->control_point(k) + Vec3(step(rng), step(rng), step(rng)));
  }
  PatchEvaluator full(std::shared_ptr<Patch>(patch->clone()), tess);
  double scale = 0, worst = 0;
  for (const SurfaceJet& j : full.jets()) scale = std::max(scale, glm::length(j.p));
  for (std::size_t i = 0; i < full.sample_count(); ++i) {
    const SurfaceJet &a = incremental.jets()[i], &b = full.jets()[i];
    for (const auto& [u, v] : {std::pair{a.p, b.p},
                               {a.su, b.su},
                               {a.sv, b.sv},
                               {a.suu, b.suu},
                               {a.suv, b.suv},
                               {a.svv, b.svv}})
      worst = std::max(worst, glm::length(u - v) / scale);
  }
  std::printf("gb-ribbons incremental vs full: %.3g\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(ConcaveGBPatch, RejectsBadRibbons) {
  const ConcavePolygonDomain dom(kL);
  const GBRibbonPatch good = make_patch(kL, 1, false);
  auto r = good.ribbons();
  r[2][0][3] += Vec3(0, 0, 1e-3);  // ribbon 2 no longer ends where ribbon 3 starts
  EXPECT_THROW(GBRibbonPatch(dom, r), std::invalid_argument);
  r = good.ribbons();
  r[1].pop_back();  // one layer: no cross-boundary data
  EXPECT_THROW(GBRibbonPatch(dom, r), std::invalid_argument);
  r = good.ribbons();
  r.pop_back();
  EXPECT_THROW(GBRibbonPatch(dom, r), std::invalid_argument);
}

}  // namespace
}  // namespace pl
