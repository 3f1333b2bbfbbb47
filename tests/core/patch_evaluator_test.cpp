// Incremental re-evaluation (an axpy per move) must agree with evaluation from scratch.
#include "core/eval/patch_evaluator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/domain/unit_square.hpp"
#include "core/patch/bezier_patch.hpp"
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
            PatchEvaluator::kMaxColumns * tess->points.size() * sizeof(Jet));
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

}  // namespace
}  // namespace pl
