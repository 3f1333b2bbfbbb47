// The B-spline data of the export against independent computations: Bézier evaluation (de
// Casteljau), knot insertion and elevation keep the curve, clamping keeps a surface.
#include "core/cad/cad_spline.hpp"

#include <gtest/gtest.h>

#include "core/cad/exact_surfaces.hpp"

namespace pl {
namespace {

BezierCurve wiggle(int degree) {
  std::vector<Vec3> p;
  for (int i = 0; i <= degree; ++i) p.emplace_back(i, std::sin(1.7 * i), 0.3 * i * i - 1);
  return BezierCurve(p);
}

TEST(CadSpline, BezierCurveMatchesDeCasteljauWithDerivative) {
  const BezierCurve b = wiggle(5);
  const CadCurve c = CadCurve::from_bezier(b);
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const CurvePoint e = b.evaluate(t), f = c.evaluate(t);
    EXPECT_LT(glm::length(e.p - f.p), 1e-13);
    EXPECT_LT(glm::length(e.d1 - f.d1), 1e-12);
  }
}

TEST(CadSpline, RefinementAndElevationKeepTheCurve) {
  const CadCurve c = CadCurve::from_bezier(wiggle(3));
  const CadCurve r = c.refined_to(merge_knots(3, c.knots, uniform_knots(3, 5)));
  EXPECT_EQ(r.points.size(), 8u);
  const CadCurve e = r.elevated_to(5);  // several spans: interpolation in the elevated space
  EXPECT_EQ(e.degree, 5);
  // Every interior knot keeps its continuity (multiplicity 1 + 2).
  for (const KnotRun& k : knot_runs(e.knots)) {
    if (k.value > 0 && k.value < 1) {
      EXPECT_EQ(k.multiplicity, 3);
    }
  }
  for (int k = 0; k <= 40; ++k) {
    const double t = k / 40.0;
    EXPECT_LT(glm::length(r.evaluate(t).p - c.evaluate(t).p), 1e-13);
    EXPECT_LT(glm::length(e.evaluate(t).p - c.evaluate(t).p), 1e-12);
    EXPECT_LT(glm::length(e.evaluate(t).d1 - c.evaluate(t).d1), 1e-10);
  }
  const CadCurve rev = c.reversed();
  EXPECT_LT(glm::length(rev.evaluate(0.3).p - c.evaluate(0.7).p), 1e-14);
}

TEST(CadSpline, UnclampedBSplinePatchIsClampedExactly) {
  // Uniform (unclamped) knots: the patch covers [knots[p], knots[n]] of them.
  std::vector<Vec3> pts;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) pts.emplace_back(i, j, std::cos(i + 0.5 * j));
  std::vector<double> ku, kv;
  for (int k = 0; k < 10; ++k) ku.push_back(k);
  for (int k = 0; k < 8; ++k) kv.push_back(0.5 * k * k);  // non-uniform
  const BSplinePatch patch(3, 2, ku, kv, 6, 5, pts);
  const CadSurface s = bspline_surface(patch);
  validate_cad_surface(s);
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) {
      const Vec2 x(a / 10.0, b / 10.0);
      EXPECT_LT(glm::length(s.evaluate(x.x, x.y).p - patch.evaluate(x).p), 1e-12);
    }
}

}  // namespace
}  // namespace pl
