// Classic curves: interpolating cubic, Hermite, B-spline (de Boor, knot insertion)
// and NURBS (exact circle), each checked against an independent computation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/curve/bspline_curve.hpp"
#include "core/curve/hermite_curve.hpp"
#include "core/curve/interpolating_curve.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

using test::max_abs;

// de Boor's triangle on homogeneous points: independent of the basis-function recursion.
glm::dvec4 de_boor(int p, const std::vector<double>& U, std::vector<glm::dvec4> P, double t) {
  int k = p;
  while (k + 1 < static_cast<int>(P.size()) && U[k + 1] <= t) ++k;
  std::vector<glm::dvec4> d(P.begin() + (k - p), P.begin() + k + 1);
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = j + k - p;
      const double a = (t - U[i]) / (U[i + p - r + 1] - U[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  return d[p];
}

template <class Curve>
void expect_derivatives_match_fd(const Curve& c, double t, double tol) {
  const double h = 1e-5;
  const CurvePoint e = c.evaluate(t), a = c.evaluate(t + h), b = c.evaluate(t - h);
  EXPECT_LT(max_abs(e.d1 - (a.p - b.p) / (2 * h)), tol) << t;
  EXPECT_LT(max_abs(e.d2 - (a.p - 2.0 * e.p + b.p) / (h * h)), 1e3 * tol) << t;
}

TEST(ClassicCurves, InterpolatingCubicPassesThroughItsPoints) {
  const auto q = test::random_points(4, 11);
  const InterpolatingCurve c({q[0], q[1], q[2], q[3]});
  double worst = 0;
  for (int k = 0; k < 4; ++k) worst = std::max(worst, max_abs(c.evaluate(k / 3.0).p - q[k]));
  std::printf("figure interpolating_curve_max_point_error %.3e\n", worst);
  EXPECT_LT(worst, 1e-12);
  const BezierCurve b = c.to_bezier();
  for (double t = 0; t <= 1; t += 0.05) {
    EXPECT_LT(max_abs(b.point(t) - c.evaluate(t).p), 1e-12);
    expect_derivatives_match_fd(c, t, 1e-7);
  }
}

TEST(ClassicCurves, HermiteReproducesEndData) {
  const auto q = test::random_points(4, 12);
  const HermiteCurve c(q[0], q[1], q[2], q[3]);
  EXPECT_LT(max_abs(c.evaluate(0).p - q[0]), 1e-15);
  EXPECT_LT(max_abs(c.evaluate(1).p - q[1]), 1e-15);
  EXPECT_LT(max_abs(c.evaluate(0).d1 - q[2]), 1e-14);
  EXPECT_LT(max_abs(c.evaluate(1).d1 - q[3]), 1e-14);
  const BezierCurve b = c.to_bezier();
  for (double t = 0; t <= 1; t += 0.05) {
    EXPECT_LT(max_abs(b.point(t) - c.evaluate(t).p), 1e-14);
    expect_derivatives_match_fd(c, t, 1e-7);
  }
}

struct SplineCase {
  int degree;
  std::vector<double> knots;
};

TEST(ClassicCurves, BSplineAgreesWithDeBoorAndDeCasteljauAndKnotInsertion) {
  const std::vector<SplineCase> cases = {
      {3, BSplineCurve::clamped_uniform_knots(3, 7)},
      {2, {0, 0, 0, 0.1, 0.5, 0.55, 0.55, 1, 1, 1}},        // non-uniform, double knot
      {3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}},              // uniform, unclamped
      {4, {0, 0, 0, 0, 0, 0.3, 0.35, 0.9, 1, 1, 1, 1, 1}},  // quartic, non-uniform
      {1, {0, 0, 0.2, 0.7, 1, 1}}};
  double worst_deboor = 0, worst_bezier = 0, worst_insert = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const auto& sc = cases[c];
    const std::size_t n = sc.knots.size() - sc.degree - 1;
    const BSplineCurve curve(sc.degree, sc.knots, test::random_points(n, 20 + c));
    std::vector<glm::dvec4> hom;
    for (const Vec3& q : curve.control_points()) hom.emplace_back(q, 1.0);
    const auto pieces = curve.bezier_pieces();
    BSplineCurve refined = curve.inserted(0.37 * curve.t_min() + 0.63 * curve.t_max());
    refined = refined.inserted(0.9 * curve.t_min() + 0.1 * curve.t_max());
    std::vector<double> breaks;  // distinct knots in range: which Bézier piece a t belongs to
    for (int i = sc.degree; i <= static_cast<int>(n); ++i)
      if (breaks.empty() || sc.knots[i] != breaks.back()) breaks.push_back(sc.knots[i]);
    ASSERT_EQ(pieces.size() + 1, breaks.size());
    for (int s = 0; s <= 200; ++s) {
      const double t = curve.t_min() + (curve.t_max() - curve.t_min()) * s / 200.0;
      const Vec3 p = curve.evaluate(t).p;
      worst_deboor =
          std::max(worst_deboor, max_abs(p - Vec3(de_boor(sc.degree, sc.knots, hom, t))));
      std::size_t k = 0;
      while (k + 2 < breaks.size() && t >= breaks[k + 1]) ++k;
      const double local = (t - breaks[k]) / (breaks[k + 1] - breaks[k]);
      worst_bezier = std::max(worst_bezier, max_abs(p - pieces[k].point(local)));
      const CurvePoint a = curve.evaluate(t), b = refined.evaluate(t);
      worst_insert = std::max({worst_insert, max_abs(a.p - b.p), max_abs(a.d1 - b.d1) * 1e-2});
      if (s % 7 == 3) expect_derivatives_match_fd(curve, t, 1e-6 * (1 + max_abs(a.d1)));
    }
  }
  std::printf(
      "figure bspline_curve_vs_de_boor %.3e\nfigure bspline_curve_vs_de_casteljau %.3e\n"
      "figure bspline_curve_knot_insertion_change %.3e\n",
      worst_deboor, worst_bezier, worst_insert);
  EXPECT_LT(worst_deboor, 1e-13);
  EXPECT_LT(worst_bezier, 1e-13);
  EXPECT_LT(worst_insert, 1e-12);
}

TEST(ClassicCurves, NurbsCircleIsExactAndAgreesWithHomogeneousDeBoor) {
  const double R = 2.5;
  const Vec3 center(1, -2, 0.5), x = glm::normalize(Vec3(1, 1, 0)),
                                 y = glm::normalize(Vec3(-1, 1, 1));
  const Vec3 y2 = glm::normalize(y - glm::dot(y, x) * x);
  const NurbsCurve c = NurbsCurve::circle(center, x, y2, R);
  const NurbsCurve refined = c.inserted(0.3).inserted(0.61);
  std::vector<glm::dvec4> hom;
  for (std::size_t i = 0; i < c.control_points().size(); ++i)
    hom.emplace_back(c.weights()[i] * c.control_points()[i], c.weights()[i]);
  double radius_err = 0, curvature_err = 0, deboor = 0, insert = 0;
  for (int s = 0; s <= 1000; ++s) {
    const double t = s / 1000.0;
    const CurvePoint e = c.evaluate(t);
    radius_err = std::max(radius_err, std::fabs(glm::length(e.p - center) - R));
    curvature_err = std::max(curvature_err, std::fabs(c.curvature(t) - 1 / R));
    const glm::dvec4 h = de_boor(2, c.knots(), hom, t);
    deboor = std::max(deboor, max_abs(e.p - Vec3(h) / h.w));
    insert = std::max(insert, max_abs(e.p - refined.evaluate(t).p));
    if (s % 13 == 5) expect_derivatives_match_fd(c, t, 1e-6);
  }
  std::printf(
      "figure nurbs_circle_radius_error %.3e\nfigure nurbs_circle_curvature_error %.3e\n"
      "figure nurbs_curve_vs_de_boor %.3e\nfigure nurbs_curve_knot_insertion_change %.3e\n",
      radius_err, curvature_err, deboor, insert);
  EXPECT_LT(radius_err, 1e-10);
  EXPECT_LT(curvature_err, 1e-10);
  EXPECT_LT(deboor, 1e-13);
  EXPECT_LT(insert, 1e-13);
}

TEST(ClassicCurves, InvalidSplinesAreRejected) {
  const auto q = test::random_points(4, 3);
  EXPECT_THROW(BSplineCurve(3, {0, 0, 0, 0, 1, 1, 1}, q), std::invalid_argument);  // too few knots
  EXPECT_THROW(BSplineCurve(3, {0, 0, 0, 1, 0, 1, 1, 1}, q), std::invalid_argument);  // decreasing
  EXPECT_THROW(BSplineCurve(1, {0, 0, 0.5, 0.5, 1, 1}, q), std::invalid_argument);  // disconnected
  EXPECT_THROW(NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, q, {1, 0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, q, {1, NAN, 1, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace pl
