// Incremental re-evaluation (an axpy per move) must agree with evaluation from scratch.
#include "core/eval/patch_evaluator.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/domain/unit_square.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/bspline_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

double rel_diff(const Vec3& a, const Vec3& b, double scale) {
  return glm::length(a - b) / scale;
}

TEST(PatchEvaluator, HundredsOfRandomMovesEqualFullReevaluation) {
  auto patch = std::make_shared<BezierPatch>(3, 4, test::random_points(20, 17));
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(40));
  PatchEvaluator incremental(patch, tess);
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<std::size_t> pick(0, patch->size() - 1);
  std::uniform_real_distribution<double> step(-0.2, 0.2);
  for (int move = 0; move < 400; ++move) {
    const std::size_t k = pick(rng);
    incremental.move_control_point(k,
                                   patch->control_point(k) + Vec3(step(rng), step(rng), step(rng)));
  }
  EXPECT_LE(incremental.influence_bytes(),
            incremental.max_columns() * tess->points.size() * sizeof(Jet));
  EXPECT_LE(incremental.max_columns() * tess->points.size() * sizeof(Jet),
            PatchEvaluator::kColumnBudget);
  // From scratch, on an independent copy of the moved patch.
  auto copy = std::shared_ptr<Patch>(patch->clone());
  PatchEvaluator full(copy, tess);
  double scale = 0;
  for (const SurfaceJet& j : full.jets()) scale = std::max(scale, glm::length(j.p));
  double worst_p = 0, worst_d = 0, worst_n = 0, worst_k = 0;
  for (std::size_t i = 0; i < full.sample_count(); ++i) {
    const SurfaceJet &a = incremental.jets()[i], &b = full.jets()[i];
    worst_p = std::max(worst_p, rel_diff(a.p, b.p, scale));
    worst_d = std::max({worst_d, rel_diff(a.su, b.su, scale), rel_diff(a.svv, b.svv, scale),
                        rel_diff(a.suv, b.suv, scale)});
    const SurfaceGeometry &ga = incremental.geometry()[i], &gb = full.geometry()[i];
    worst_n = std::max(worst_n, glm::length(ga.normal - gb.normal));
    const double kscale = std::max(1.0, std::fabs(gb.kmax) + std::fabs(gb.kmin));
    worst_k = std::max({worst_k, std::fabs(ga.mean - gb.mean) / kscale,
                        std::fabs(ga.gaussian - gb.gaussian) / (kscale * kscale)});
  }
  EXPECT_LT(worst_p, 1e-12);
  EXPECT_LT(worst_d, 1e-12);
  EXPECT_LT(worst_n, 1e-12);
  EXPECT_LT(worst_k, 1e-12);
  std::printf(
      "max relative difference after 400 moves: position %.3g, derivatives %.3g, "
      "normal %.3g, curvature %.3g\n",
      worst_p, worst_d, worst_n, worst_k);
}

// Largest relative difference of positions, second derivatives and curvatures between two
// evaluators of the same tessellation.
double worst_difference(const PatchEvaluator& a, const PatchEvaluator& b) {
  double scale = 0, worst = 0;
  for (const SurfaceJet& j : b.jets()) scale = std::max(scale, glm::length(j.p));
  for (std::size_t i = 0; i < b.sample_count(); ++i) {
    const SurfaceJet &x = a.jets()[i], &y = b.jets()[i];
    const SurfaceGeometry &gx = a.geometry()[i], &gy = b.geometry()[i];
    const double kscale = std::max(1.0, std::fabs(gy.kmax) + std::fabs(gy.kmin));
    worst = std::max({worst, rel_diff(x.p, y.p, scale), rel_diff(x.suv, y.suv, scale),
                      rel_diff(x.svv, y.svv, scale), glm::length(gx.normal - gy.normal),
                      std::fabs(gx.mean - gy.mean) / kscale});
  }
  return worst;
}

TEST(PatchEvaluator, BatchedMovesEqualFullReevaluation) {
  // Interior points, corner and edge points (weights vanishing on two sides), and six points:
  // with the budget at 0 only kMaxColumns columns are kept, so that batch takes the full
  // re-evaluation path.
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(30));
  const std::vector<std::vector<std::size_t>> batches = {{6, 7, 11, 12}, {0, 5, 6, 19}, {}};
  for (std::size_t budget : {PatchEvaluator::kColumnBudget, std::size_t(0)}) {
    for (const auto& ks : batches) {
      auto patch = std::make_shared<BezierPatch>(3, 4, test::random_points(20, 5));
      PatchEvaluator ev(patch, tess);
      ev.set_column_budget(budget);  // 0: kMaxColumns columns, so 6 moves take the full path
      std::vector<std::size_t> moved =
          ks.empty() ? std::vector<std::size_t>{1, 2, 3, 8, 9, 13} : ks;
      for (int step = 0; step < 3; ++step) {  // repeated, as in a drag: columns are reused
        std::vector<PatchEvaluator::PointMove> moves;
        for (std::size_t k : moved)
          moves.push_back({k, patch->control_point(k) + Vec3(0.05 * (k + 1), -0.1, 0.2 * step)});
        const uint64_t rev = ev.revision();
        EXPECT_GT(ev.move_control_points(moves), 0u);
        EXPECT_GT(ev.revision(), rev);
        for (const auto& m : moves) EXPECT_EQ(ev.patch().control_point(m.k), m.p);
        // The first batch is a one-off edit (full evaluation, no columns); from the second on
        // the same points move again, as in a drag, and their columns are built and kept.
        const bool columns_expected = step > 0 && moved.size() <= ev.max_columns();
        EXPECT_EQ(ev.influence_bytes() > 0, columns_expected) << "step " << step;
      }
      PatchEvaluator full(std::shared_ptr<Patch>(patch->clone()), tess);
      const double worst = worst_difference(ev, full);
      EXPECT_LT(worst, 1e-12) << "budget " << budget << ", " << moved.size() << " points";
      std::printf("batched moves (%zu points, budget %zu): max relative difference %.3g\n",
                  moved.size(), budget, worst);
    }
  }
}

TEST(PatchEvaluator, SmallSurfacesKeepMoreColumns) {
  auto patch = std::make_shared<BezierPatch>(3, 3, test::random_points(16, 3));
  PatchEvaluator small(patch,
                       std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(16)));
  EXPECT_EQ(small.max_columns(), PatchEvaluator::kColumnBudget / (17 * 17 * sizeof(Jet)));
  small.set_column_budget(0);
  EXPECT_EQ(small.max_columns(), PatchEvaluator::kMaxColumns);
}

TEST(PatchEvaluator, OnlyInfluencedSamplesChangeAndRevisionAdvances) {
  auto patch = std::make_shared<BezierPatch>(3, 3, test::random_points(16, 3));
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(8));
  PatchEvaluator ev(patch, tess);
  const auto before = ev.jets();
  const uint64_t rev = ev.revision();
  // Corner point P_00 (k = 0): only samples with B_0(u) B_0(v) != 0, i.e. u < 1 and v < 1.
  ev.move_control_point(0, patch->control_point(0) + Vec3(0, 0, 1));
  EXPECT_GT(ev.revision(), rev);
  for (std::size_t i = 0; i < ev.sample_count(); ++i) {
    const Vec2 x = tess->points[i];
    const bool influenced = x.x < 1 && x.y < 1;
    EXPECT_EQ(before[i].p != ev.jets()[i].p, influenced) << x.x << "," << x.y;
  }
}

TEST(PatchEvaluator, SingularCornerGetsALimitNormalNotNaN) {
  // Side u = 0 collapses to a point (a triangle-like patch): Su x Sv = 0 along it.
  auto patch = std::make_shared<BezierPatch>(
      1, 2,
      std::vector<Vec3>{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, -1, 0.2}, {1, 0, 0.5}, {1, 1, 0.2}});
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(6));
  PatchEvaluator ev(patch, tess);
  int singular = 0;
  for (const SurfaceGeometry& g : ev.geometry()) {
    ASSERT_TRUE(std::isfinite(g.normal.x) && std::isfinite(g.mean));
    EXPECT_NEAR(glm::length(g.normal), 1.0, 1e-9);
    singular += g.status == GeometryStatus::Singular;
  }
  EXPECT_EQ(singular, 7);  // the 7 samples of side u = 0
}

// Compact storage keeps what the jets storage computes, bit for bit, without the jets: the same
// positions and geometry after construction and after moves (which evaluate again), and the same
// verdict on non-finite samples.
TEST(PatchEvaluator, CompactStorageKeepsTheSamePositionsAndGeometry) {
  auto a = std::make_shared<BezierPatch>(3, 4, test::random_points(20, 5));
  auto b = std::shared_ptr<Patch>(a->clone());
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(30));
  PatchEvaluator jets(a, tess), compact(b, tess, SampleStorage::Compact);
  EXPECT_TRUE(compact.jets().empty());
  EXPECT_EQ(compact.sample_count(), jets.sample_count());
  const auto bits = [](const auto& x, const auto& y) {  // NaN included
    return std::memcmp(&x, &y, sizeof x) == 0;
  };
  const auto same = [&] {
    for (std::size_t i = 0; i < jets.sample_count(); ++i) {
      ASSERT_TRUE(bits(jets.position(i), compact.position(i))) << i;
      const SurfaceGeometry &g = jets.geometry()[i], &h = compact.geometry()[i];
      ASSERT_TRUE(bits(g.normal, h.normal)) << i;
      ASSERT_TRUE(bits(g.mean, h.mean)) << i;
      ASSERT_TRUE(bits(g.gaussian, h.gaussian)) << i;
      ASSERT_EQ(g.status, h.status) << i;
      ASSERT_EQ(jets.finite(i), compact.finite(i)) << i;
    }
  };
  same();
  const std::vector<PatchEvaluator::PointMove> moves{{3, Vec3(0.1, 0.2, 0.9)},
                                                     {7, Vec3(-0.3, 0.5, 0.2)}};
  jets.evaluate_all();  // columns off: both evaluate the moved patch from scratch
  for (const auto& m : moves) a->set_control_point(m.k, m.p);
  jets.evaluate_all();
  const uint64_t revision = compact.revision();
  compact.move_control_points(moves);
  EXPECT_GT(compact.revision(), revision);
  same();
  // A non-finite point: every sample it reaches is reported, in both storages.
  a->set_control_point(0, Vec3(NAN, 0, 0));
  jets.evaluate_all();
  compact.move_control_point(0, Vec3(NAN, 0, 0));
  std::size_t bad = 0;
  for (std::size_t i = 0; i < compact.sample_count(); ++i) bad += !compact.finite(i);
  EXPECT_GT(bad, 0u);
  same();
}

// influence_support lists exactly the samples where the point's basis function is non-zero (an
// independent evaluation of phi_k), or says `all` for a column covering every sample.
TEST(PatchEvaluator, InfluenceSupportIsWherePhiIsNonZero) {
  // Cubic B-spline, 7 x 7 points: the basis of P_00 lives on one knot span of four in each
  // direction, that of P_11 on two.
  const std::vector<double> knots = {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
  auto spline =
      std::make_shared<BSplinePatch>(3, 3, knots, knots, 7, 7, test::random_points(49, 8));
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(24));
  PatchEvaluator ev(spline, tess);
  for (std::size_t k : {std::size_t(0), std::size_t(8)}) {  // P_00 and P_11
    std::vector<Jet> phi(tess->points.size());
    spline->influence(k, tess->points, phi);
    std::vector<uint32_t> nonzero;
    for (std::size_t i = 0; i < phi.size(); ++i)
      if (!phi[i].is_zero()) nonzero.push_back(static_cast<uint32_t>(i));
    const PatchEvaluator::Support support = ev.influence_support(k);
    ASSERT_FALSE(support.all) << k;  // local support: less than half the samples
    EXPECT_EQ(std::vector<uint32_t>(support.samples.begin(), support.samples.end()), nonzero) << k;
  }
  // A Bernstein point moves every sample.
  auto bezier = std::make_shared<BezierPatch>(3, 3, test::random_points(16, 3));
  PatchEvaluator dense(bezier, tess);
  EXPECT_TRUE(dense.influence_support(5).all);
}

}  // namespace
}  // namespace pl
