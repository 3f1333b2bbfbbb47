#include "core/patch/bezier_patch.hpp"

#include <gtest/gtest.h>

#include "core/curve/bezier_curve.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

BezierPatch random_patch(int m, int n, unsigned seed) {
  return BezierPatch(m, n, test::random_points((m + 1) * (n + 1), seed));
}

TEST(BezierPatch, FastEvaluateAgreesWithBasisSumAndNestedDeCasteljau) {
  for (auto [m, n] : {std::pair{1, 1}, {3, 3}, {2, 5}, {6, 4}}) {
    const BezierPatch p = random_patch(m, n, 11 + m * 7 + n);
    for (double u : {0.0, 0.21, 0.5, 1.0})
      for (double v : {0.0, 0.66, 1.0}) {
        std::vector<Jet> phi(p.size());
        p.basis({u, v}, phi);
        const SurfaceJet a = p.evaluate({u, v}), b = combine(p.control_points(), phi);
        EXPECT_LT(test::max_abs(a.p - b.p) + test::max_abs(a.suu - b.suu) +
                      test::max_abs(a.suv - b.suv) + test::max_abs(a.svv - b.svv),
                  1e-12);
        // Independent: de Casteljau on each row in v, then in u.
        std::vector<Vec3> col;
        for (int i = 0; i <= m; ++i) {
          std::vector<Vec3> row;
          for (int j = 0; j <= n; ++j) row.push_back(p.at(i, j));
          col.push_back(BezierCurve(row).point(v));
        }
        EXPECT_LT(test::max_abs(a.p - BezierCurve(col).point(u)), 1e-13);
      }
  }
}

TEST(BezierPatch, ExactDerivativesMatchFiniteDifferences) {
  const BezierPatch p = random_patch(3, 4, 5);
  for (Vec2 x : {Vec2(0.3, 0.4), Vec2(0.7, 0.2), Vec2(0.5, 0.9)}) {
    const SurfaceJet s = p.evaluate(x);
    const auto d = test::finite_differences(p, x, 1e-4);
    EXPECT_LT(test::max_abs(s.su - d.su), 1e-7);
    EXPECT_LT(test::max_abs(s.sv - d.sv), 1e-7);
    EXPECT_LT(test::max_abs(s.suu - d.suu), 1e-5);
    EXPECT_LT(test::max_abs(s.suv - d.suv), 1e-5);
    EXPECT_LT(test::max_abs(s.svv - d.svv), 1e-5);
  }
}

TEST(BezierPatch, InfluenceIsTheBasisColumn) {
  const BezierPatch p = random_patch(3, 2, 9);
  const std::vector<Vec2> xs{{0.1, 0.2}, {0.9, 0.5}, {0.4, 1.0}};
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::vector<Jet> col(xs.size()), phi(p.size());
    p.influence(k, xs, col);
    for (std::size_t s = 0; s < xs.size(); ++s) {
      p.basis(xs[s], phi);
      EXPECT_NEAR(col[s].f, phi[k].f, 1e-14);
      EXPECT_NEAR(col[s].fu, phi[k].fu, 1e-12);
      EXPECT_NEAR(col[s].fuv, phi[k].fuv, 1e-11);
      EXPECT_NEAR(col[s].fvv, phi[k].fvv, 1e-11);
    }
  }
}

TEST(BezierPatch, BoundaryCurvesFollowTheDomainSides) {
  const BezierPatch p = random_patch(3, 3, 3);
  const auto curves = p.boundary_curves();
  for (int s = 0; s < 4; ++s)
    for (double t : {0.0, 0.3, 1.0})
      EXPECT_LT(test::max_abs(p.evaluate(p.domain().side_point(s, t)).p - curves[s].point(t)),
                1e-14);
}

TEST(BezierPatch, RejectsBadInput) {
  EXPECT_THROW(BezierPatch(0, 1, {}), std::invalid_argument);
  EXPECT_THROW(BezierPatch(1, 1, test::random_points(3, 1)), std::invalid_argument);
}

TEST(BezierCurve, ElevationSplitAndDerivatives) {
  const BezierCurve c(test::random_points(5, 42));
  const BezierCurve e = c.elevated_to(7);
  const auto [l, r] = c.split(0.3);
  for (double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    EXPECT_LT(test::max_abs(e.point(t) - c.point(t)), 1e-14);
    EXPECT_LT(test::max_abs(l.point(t) - c.point(0.3 * t)), 1e-14);
    EXPECT_LT(test::max_abs(r.point(t) - c.point(0.3 + 0.7 * t)), 1e-14);
    EXPECT_LT(test::max_abs(c.evaluate(t).p - c.point(t)), 1e-14);
    EXPECT_LT(test::max_abs(c.evaluate(t).d1 - c.derivative().point(t)), 1e-12);
    EXPECT_LT(test::max_abs(c.evaluate(t).d2 - c.derivative().derivative().point(t)), 1e-11);
  }
}

}  // namespace
}  // namespace pl
