// The batched (SIMD across samples) paths of the GB patch against the scalar ones: evaluate_many
// against evaluate and influence columns against influence_at (bit for bit), influence columns
// against phi_k of basis(), at interior points, on the sides,
// at and next to the corners (the vertex-limit path) and at the centre, for many n and d.
#include <gtest/gtest.h>

#include "core/eval/patch_evaluator.hpp"
#include "gb_test_util.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

// Every kind of point, in an order whose vertex points fall in different lanes of a block, and a
// count that leaves a partial last block.
std::vector<Vec2> probe_points(const ConvexPolygonDomain& dom, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(0, 1);
  const int n = dom.side_count();
  std::vector<Vec2> xs{dom.interior_point()};
  for (int i = 0; i < n; ++i) {
    const Vec2 c = dom.vertex(i), in = dom.interior_point() - c;
    xs.push_back(c);
    for (double e : {1e-11, 1e-9, 1e-6, 1e-3, 2e-2}) xs.push_back(c + e * in);
    for (double t : {0.0, 1e-12, 1e-7, 0.02, 0.3, 0.5, 1 - 1e-7, 1.0})
      xs.push_back(dom.side_point(i, t));
    xs.push_back(dom.side_point(i, 0.7) + 1e-9 * (dom.interior_point() - dom.side_point(i, 0.7)));
  }
  while (xs.size() % kWideLanes != 3 || xs.size() < 200) {
    // A random point of the triangle centre, vertex i, vertex i+1.
    const int i = static_cast<int>(r(rng) * n) % n;
    double a = r(rng), b = r(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    xs.push_back(dom.interior_point() + a * (dom.vertex(i) - dom.interior_point()) +
                 b * (dom.vertex(i + 1) - dom.interior_point()));
  }
  return xs;
}

// Runs the batched paths of both widths where the CPU has the wide ones.
class GBBatch : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override { narrow_lanes_only = GetParam(); }
  void TearDown() override { narrow_lanes_only = false; }
};
INSTANTIATE_TEST_SUITE_P(Widths, GBBatch, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "narrow" : "wide"; });

// |a - b| relative to the size of b's entry and to the patch size.
double rel(double a, double b, double scale) {
  return std::fabs(a - b) / std::max(scale, std::fabs(b));
}

double jet_rel(const SurfaceJet& a, const SurfaceJet& b, double scale) {
  double worst = 0;
  const Vec3* pa[6] = {&a.p, &a.su, &a.sv, &a.suu, &a.suv, &a.svv};
  const Vec3* pb[6] = {&b.p, &b.su, &b.sv, &b.suu, &b.suv, &b.svv};
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, rel((*pa[r])[c], (*pb[r])[c], scale));
  return worst;
}

TEST_P(GBBatch, EvaluateManyEqualsEvaluate) {
  double worst = 0;
  for (int n : {3, 4, 5, 6, 7, 9, 16})
    for (int d = 1; d <= 8; ++d) {
      const GBPatch g = test::random_gb(n, d, 31 + n * d);
      const double scale = test::bbox_diagonal(g.control_points());
      const auto xs = probe_points(g.polygon(), 32 + n + d);
      std::vector<SurfaceJet> many(xs.size());
      g.evaluate_many(xs, many);
      for (std::size_t p = 0; p < xs.size(); ++p) {
        const double e = jet_rel(many[p], g.evaluate(xs[p]), scale);
        worst = std::max(worst, e);
        // One template computes both (core/patch/gb/gb_patch_evaluate.cpp): bit for bit.
        ASSERT_EQ(e, 0.0) << "n=" << n << " d=" << d << " point " << p << " (" << xs[p].x << ", "
                          << xs[p].y << ")";
      }
    }
  std::printf("[ batch     ] evaluate_many vs evaluate: max relative difference %.3g\n", worst);
}

// |a - b| per derivative order, relative to the largest entry of b of that order (at least 1).
double jet_rel(const Jet& a, const Jet& b) {
  const double m1 = std::max(1.0, std::fabs(b.f));
  const double m2 = std::max({1.0, std::fabs(b.fu), std::fabs(b.fv)});
  const double m3 = std::max({1.0, std::fabs(b.fuu), std::fabs(b.fuv), std::fabs(b.fvv)});
  return std::max({std::fabs(a.f - b.f) / m1, std::fabs(a.fu - b.fu) / m2,
                   std::fabs(a.fv - b.fv) / m2, std::fabs(a.fuu - b.fuu) / m3,
                   std::fabs(a.fuv - b.fuv) / m3, std::fabs(a.fvv - b.fvv) / m3});
}

// The batched columns against the scalar influence at every point, and against phi_k of basis()
// wherever the two formulas are well conditioned: at the vertices (both take the vertex limits)
// and away from them. Within ~0.05 of a vertex the corner weights' derivatives grow like
// 1/distance^2 and the basis sums its terms in another order, so phi_k's second derivatives
// agree only to ~1e-16/distance^2 there (the surface, a sum in which they cancel, does not).
TEST_P(GBBatch, InfluenceColumnsArePhiOfTheBasis) {
  double worst_scalar = 0, worst_basis = 0;
  for (int n : {3, 4, 5, 6, 9})
    for (int d : {1, 2, 3, 4, 5, 6, 7}) {
      const GBPatch g = test::random_gb(n, d, 41 + n * d);
      const auto& dom = g.polygon();
      const auto xs = probe_points(dom, 42 + n + d);
      std::vector<bool> conditioned(xs.size());
      for (std::size_t p = 0; p < xs.size(); ++p) {
        double near = 1e300;
        for (int i = 0; i < n; ++i) near = std::min(near, glm::length(xs[p] - dom.vertex(i)));
        conditioned[p] = near < 1e-10 || near >= 0.05;
      }
      std::vector<std::vector<Jet>> phi(xs.size(), std::vector<Jet>(g.size()));
      for (std::size_t p = 0; p < xs.size(); ++p) g.basis(xs[p], phi[p]);
      std::vector<Jet> col(xs.size());
      for (std::size_t k = 0; k < g.size(); ++k) {
        g.influence(k, xs, col);
        for (std::size_t p = 0; p < xs.size(); ++p) {
          const double es = jet_rel(col[p], g.influence_at(k, xs[p]));
          worst_scalar = std::max(worst_scalar, es);
          ASSERT_EQ(es, 0.0) << "n=" << n << " d=" << d << " k=" << k << " point " << p;
          if (!conditioned[p]) continue;
          const double eb = jet_rel(col[p], phi[p][k]);
          worst_basis = std::max(worst_basis, eb);
          ASSERT_LT(eb, 1e-13) << "n=" << n << " d=" << d << " k=" << k << " point " << p;
        }
      }
    }
  std::printf("[ batch     ] influence vs scalar influence %.3g, vs basis %.3g (max relative)\n",
              worst_scalar, worst_basis);
}

TEST_P(GBBatch, ReferenceSamplesThroughEvaluateMany) {
  PATCHLAB_REQUIRE_GB_REFERENCE();
  for (const std::string& name : test::gb_reference_models()) {
    const GBPatch patch = read_gbp(test::gb_reference_dir() / (name + ".gbp"));
    const auto samples = test::read_gb_samples(test::gb_reference_dir() / (name + ".samples.txt"));
    std::vector<Vec2> xs;
    for (const auto& s : samples) xs.push_back(s.x);
    std::vector<SurfaceJet> many(xs.size());
    patch.evaluate_many(xs, many);
    const double diag = test::bbox_diagonal(patch.control_points());
    double worst = 0;
    for (std::size_t p = 0; p < xs.size(); ++p)
      worst = std::max(worst, glm::length(many[p].p - samples[p].p) / diag);
    EXPECT_LT(worst, 1e-12) << name;
    for (int i = 0; i < patch.sides(); ++i)  // the domain vertices come first, exact
      EXPECT_EQ(many[i].p, patch.point(i, patch.degree(), 0)) << name << " vertex " << i;
  }
}

TEST_P(GBBatch, EvaluatorSamplesEqualEvaluate) {
  auto patch = std::make_shared<GBPatch>(test::random_gb(6, 5, 51));
  const auto tess =
      std::make_shared<const Tessellation>(ConvexPolygonDomain::regular(6).tessellate(60));
  PatchEvaluator ev(patch, tess);
  const double scale = test::bbox_diagonal(patch->control_points());
  for (std::size_t i = 0; i < ev.sample_count(); ++i)
    ASSERT_LT(jet_rel(ev.jets()[i], patch->evaluate(tess->points[i]), scale), 1e-13) << i;
}

}  // namespace
}  // namespace pl
