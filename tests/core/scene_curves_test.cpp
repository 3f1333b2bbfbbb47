// Free curves of a scene: the defining properties of every type, the exactness of the editing
// operations (knot insertion, degree elevation, split, reverse) and the analysis figures, each
// against an independent computation (closed forms, de Boor's triangle written here).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/analysis/curve_analysis.hpp"
#include "core/curve/curvature.hpp"
#include "core/curve/nurbs_curve.hpp"
#include "core/curve/scene_curve.hpp"
#include "scene_curve_samples.hpp"

namespace pl {
namespace {

// de Boor's triangle on homogeneous points (independent of the basis recursion of the code).
Vec3 de_boor(const SplineCurve& c, double t) {
  const int p = c.degree;
  int k = p;
  while (k + 1 < static_cast<int>(c.points.size()) && c.knots[k + 1] <= t) ++k;
  std::vector<glm::dvec4> d;
  for (int i = k - p; i <= k; ++i) d.emplace_back(c.weight(i) * c.points[i], c.weight(i));
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = j + k - p;
      const double a = (t - c.knots[i]) / (c.knots[i + p - r + 1] - c.knots[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  return Vec3(d[p]) / d[p].w;
}

double diagonal(const std::vector<Vec3>& pts) {
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

SceneCurve circle_curve(Vec3 center, double r) {
  return test::circle_scene_curve(center, r);
}

SceneCurve spline_curve(int p, std::vector<double> knots, std::vector<Vec3> pts) {
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = p;
  c.knots = std::move(knots);
  c.points = std::move(pts);
  validate_curve(c);
  return c;
}

// A non-uniform cubic with a double knot, unclamped at its start.
SceneCurve wavy_bspline() {
  return spline_curve(
      3, {-0.5, -0.2, 0, 0.1, 0.3, 0.3, 0.7, 0.9, 1.2, 1.4, 1.5},
      {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 0}, {3, 1, 1}, {4, 0, -1}, {5, 2, 0}, {6, 1, 0.5}});
}

SceneCurve rational_wave() {
  SceneCurve c = wavy_bspline();
  c.type = CurveType::Nurbs;
  c.weights = {1, 0.5, 2, 1.5, 0.7, 1, 3};
  return c;
}

// Largest distance between a and b at 1,000 samples of [a.t_min, a.t_max], relative to the
// diagonal of a's control points; b is evaluated at map(t).
template <class Map>
double sample_difference(const SceneCurve& a, const SceneCurve& b, Map map) {
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    const double t = a.t_min() + (a.t_max() - a.t_min()) * i / 999.0;
    worst = std::max(worst, glm::length(evaluate(a, t).p - evaluate(b, map(t)).p));
  }
  return worst / diagonal(spline_form(a).points);
}

TEST(SceneCurves, NurbsCircleHasCurvatureOneOverRadiusAndLengthTwoPiR) {
  const double r = 2.5;
  const SceneCurve c = circle_curve({0.3, -1.2, 0.7}, r);
  for (int i = 0; i < 1000; ++i) {
    const double t = i / 999.0;
    const CurvePoint p = evaluate(c, t);
    EXPECT_NEAR(glm::length(p.p - Vec3(0.3, -1.2, 0.7)), r, 1e-14 * r) << t;
    EXPECT_NEAR(curve_curvature(p), 1 / r, 1e-12 / r) << t;
  }
  EXPECT_NEAR(curve_length(c), 2 * M_PI * r, 1e-9 * 2 * M_PI * r);
  EXPECT_EQ(curve_inflections(c, 32), 0);
}

TEST(SceneCurves, SplineEvaluationMatchesDeBoor) {
  for (const SceneCurve& c : {wavy_bspline(), rational_wave(), circle_curve({0, 0, 0}, 1)}) {
    const SplineCurve s = spline_form(c);
    for (int i = 0; i < 1000; ++i) {
      const double t = c.t_min() + (c.t_max() - c.t_min()) * i / 999.0;
      EXPECT_LT(glm::length(evaluate(c, t).p - de_boor(s, t)), 1e-14 * diagonal(c.points));
    }
  }
}

TEST(SceneCurves, InterpolatingCubicPassesItsPoints) {
  SceneCurve c;
  c.type = CurveType::Interpolating;
  c.points = {{0, 0, 0}, {1, 2, 0.5}, {2.5, -0.5, 1}, {3, 1, -0.25}};
  const double ts[4] = {0, 1.0 / 3.0, 2.0 / 3.0, 1};
  for (int k = 0; k < 4; ++k)
    EXPECT_LE(glm::length(evaluate(c, ts[k]).p - c.points[k]), 1e-15 * diagonal(c.points)) << k;
}

TEST(SceneCurves, HermiteHasItsEndDerivatives) {
  SceneCurve c;
  c.type = CurveType::Hermite;
  c.points = {{0, 0, 0}, {2, 1, 0}};
  c.tangents = {{3, 0, 1}, {0, -4, 0.5}};
  EXPECT_LE(glm::length(evaluate(c, 0).d1 - c.tangents[0]), 1e-15 * 4);
  EXPECT_LE(glm::length(evaluate(c, 1).d1 - c.tangents[1]), 1e-15 * 4);
  EXPECT_EQ(evaluate(c, 0).p, c.points[0]);
  EXPECT_LE(glm::length(evaluate(c, 1).p - c.points[1]), 1e-15 * 2);
}

std::vector<SceneCurve> every_type() {
  SceneCurve bez, interp, herm;
  bez.type = CurveType::Bezier;
  bez.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0.5, 0}, {4, 1, -1}};
  interp.type = CurveType::Interpolating;
  interp.points = {{0, 0, 0}, {1, 2, 0.5}, {2.5, -0.5, 1}, {3, 1, -0.25}};
  herm.type = CurveType::Hermite;
  herm.points = {{0, 0, 0}, {2, 1, 0}};
  herm.tangents = {{3, 0, 1}, {0, -4, 0.5}};
  return {bez, interp, herm, wavy_bspline(), rational_wave(), circle_curve({1, 2, 3}, 0.75)};
}

TEST(SceneCurves, KnotInsertionLeavesTheCurveUnchanged) {
  for (const SceneCurve& c : every_type()) {
    for (double f : {0.1234, 0.5, 0.7}) {  // 0.5 hits an existing knot of several curves
      const double t = c.t_min() + f * (c.t_max() - c.t_min());
      const SceneCurve d = curve_knot_inserted(c, t);
      EXPECT_EQ(d.points.size(), spline_form(c).points.size() + 1);
      EXPECT_LE(sample_difference(c, d, [](double s) { return s; }), 1e-14)
          << curve_type_name(c.type) << " " << t;
    }
  }
}

TEST(SceneCurves, DegreeElevationLeavesTheCurveUnchanged) {
  for (const SceneCurve& c : every_type()) {
    const SceneCurve d = curve_degree_elevated(c);
    EXPECT_EQ(curve_degree(d), curve_degree(c) + 1);
    EXPECT_LE(sample_difference(c, d, [](double s) { return s; }), 1e-14)
        << curve_type_name(c.type);
    // Twice, and the continuity at the double knot is kept: same number of spans.
    const SceneCurve e = curve_degree_elevated(d);
    EXPECT_EQ(curve_spans(e).size(), curve_spans(c).size());
    EXPECT_LE(sample_difference(c, e, [](double s) { return s; }), 1e-14)
        << curve_type_name(c.type);
  }
}

TEST(SceneCurves, DegreeElevationKeepsTheKnotStructure) {
  // A C2 cubic with simple interior knots becomes a C2 quartic: each knot doubled, so
  // n + 1 + (spans) points; interior continuity unchanged means the quartic's second derivative
  // is continuous at the knots.
  const SceneCurve c =
      spline_curve(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1},
                   {{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 0}, {4, 0, 0}, {5, 1, 1}, {6, 0, 0}});
  const SceneCurve d = curve_degree_elevated(c);
  EXPECT_EQ(d.points.size(), c.points.size() + 4);
  for (double t : {0.25, 0.5, 0.75}) {
    const CurvePoint left = evaluate(spline_form(d), std::nextafter(t, 0.0));
    const CurvePoint right = evaluate(spline_form(d), t);
    EXPECT_LT(glm::length(left.d2 - right.d2), 1e-9 * glm::length(right.d2) + 1e-9) << t;
  }
}

TEST(SceneCurves, SplitGivesTwoPiecesOfTheSameCurve) {
  for (const SceneCurve& c : every_type()) {
    const double t = c.t_min() + 0.4321 * (c.t_max() - c.t_min());
    const auto [l, r] = curve_split(c, t);
    const bool poly = c.type != CurveType::BSpline && c.type != CurveType::Nurbs;
    // Polynomial types are split into Béziers on [0, 1] each.
    const auto left_t = [&](double s) { return poly ? (s - c.t_min()) / (t - c.t_min()) : s; };
    const auto right_t = [&](double s) { return poly ? (s - t) / (c.t_max() - t) : s; };
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
      const double s = c.t_min() + (c.t_max() - c.t_min()) * i / 999.0;
      const Vec3 q = s <= t ? evaluate(l, left_t(s)).p : evaluate(r, right_t(s)).p;
      worst = std::max(worst, glm::length(q - evaluate(c, s).p));
    }
    EXPECT_LE(worst, 1e-14 * diagonal(spline_form(c).points)) << curve_type_name(c.type);
  }
}

TEST(SceneCurves, ReverseRunsTheSameCurveBackwards) {
  for (const SceneCurve& c : every_type()) {
    const SceneCurve r = curve_reversed(c);
    EXPECT_EQ(r.type, c.type);
    EXPECT_LE(sample_difference(c, r, [&](double s) { return c.t_min() + c.t_max() - s; }), 1e-14)
        << curve_type_name(c.type);
  }
}

TEST(SceneCurves, SampleParametersShareSpanEnds) {
  const SceneCurve c = wavy_bspline();  // range [0.1, 0.9], spans [0.1,0.3], [0.3,0.7], [0.7,0.9]
  const auto ts = curve_sample_parameters(c, 4);
  ASSERT_EQ(ts.size(), 3u * 4u + 1u);
  EXPECT_EQ(ts.front(), 0.1);
  EXPECT_EQ(ts[4], 0.3);
  EXPECT_EQ(ts[8], 0.7);
  EXPECT_EQ(ts.back(), 0.9);
}

SceneCurve bezier(std::vector<Vec3> pts) {
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = std::move(pts);
  return c;
}

TEST(SceneCurves, JointOfAG1PairThatIsNotG2) {
  // Tangents both along +x at (1, 0, 0); the second curve bends more sharply.
  const std::vector<SceneCurve> curves{bezier({{0, 1, 0}, {0.3, 0.2, 0}, {0.6, 0, 0}, {1, 0, 0}}),
                                       bezier({{1, 0, 0}, {1.5, 0, 0}, {1.7, 0.6, 0}, {2, 1, 0}})};
  const auto joints = curve_joints(curves);
  ASSERT_EQ(joints.size(), 1u);
  EXPECT_EQ(joints[0].curves, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(joints[0].gap, 0.0);
  EXPECT_LT(joints[0].tangent_angle_deg, 1e-9);
  // Independent: kappa at a Bézier end = (d-1)/d * h / a^2 (h the distance of the third point
  // from the end tangent, a the length of the end leg), both centres on the +y side here:
  // 2/3 * 0.2 / 0.4^2 for the first curve's end, 2/3 * 0.6 / 0.5^2 for the second's start.
  EXPECT_NEAR(joints[0].curvature_jump, 2.0 / 3.0 * (0.6 / 0.25 - 0.2 / 0.16), 1e-12);
  // The curvatures on both sides, and the class the editor shows: G1.
  EXPECT_NEAR(joints[0].curvature[0], 2.0 / 3.0 * 0.2 / 0.16, 1e-12);
  EXPECT_NEAR(joints[0].curvature[1], 2.0 / 3.0 * 0.6 / 0.25, 1e-12);
  EXPECT_EQ(joints[0].at_start, (std::array<bool, 2>{false, true}));
  EXPECT_EQ(joints[0].position, Vec3(1, 0, 0));
  EXPECT_EQ(joint_continuity(joints[0], curves_size(curves)), 1);
  // The box of the control points: (0, 0, 0) to (2, 1, 0).
  EXPECT_NEAR(curves_size(curves), std::sqrt(5.0), 1e-15);
}

TEST(SceneCurves, JointOfAG2Pair) {
  // A curve split in two: G2 (indeed C2); the second half reversed as well, so the joint is the
  // end of one and the end of the other.
  const SceneCurve whole = rational_wave();
  auto [a, b] = curve_split(whole, 0.55);
  for (const std::vector<SceneCurve>& curves :
       {std::vector<SceneCurve>{a, b}, std::vector<SceneCurve>{a, curve_reversed(b)},
        std::vector<SceneCurve>{curve_reversed(a), b}}) {
    const auto joints = curve_joints(curves);
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_LT(joints[0].gap, 1e-12);
    EXPECT_LT(joints[0].tangent_angle_deg, 1e-9);
    EXPECT_LT(joints[0].curvature_jump, 1e-9);
    EXPECT_EQ(joint_continuity(joints[0], curves_size(curves)), 2);
  }
}

TEST(SceneCurves, ClosedCircleIsAJointWithItself) {
  const SceneCurve c = circle_curve({0, 0, 0}, 3);
  const std::vector<SceneCurve> curves{c};
  const auto joints = curve_joints(curves);
  ASSERT_EQ(joints.size(), 1u);
  EXPECT_EQ(joints[0].curves, (std::array<int, 2>{0, 0}));
  EXPECT_LT(joints[0].tangent_angle_deg, 1e-9);
  EXPECT_LT(joints[0].curvature_jump, 1e-9);
}

TEST(SceneCurves, InflectionsOfAPlanarSCurve) {
  // Signed curvature of this planar cubic changes sign once (its control polygon zig-zags once).
  const SceneCurve s = bezier({{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}});
  EXPECT_EQ(curve_inflections(s, 64), 1);
  // The same curve lifted out of its plane: not planar, no inflections counted.
  const SceneCurve t = bezier({{0, 0, 0}, {1, 1, 0}, {2, -1, 0.5}, {3, 0, 0}});
  EXPECT_EQ(curve_inflections(t, 64), 0);
}

TEST(SceneCurves, LengthOfAStraightBezierAndAnArc) {
  EXPECT_NEAR(curve_length(bezier({{0, 0, 0}, {1, 0, 0}, {5, 0, 0}, {3, 4, 0}})),
              curve_length(bezier({{0, 0, 0}, {1, 0, 0}, {5, 0, 0}, {3, 4, 0}})), 0);
  // A parabola y = x^2 on [0, 1] as a quadratic Bézier; closed form of its arc length.
  const double exact = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4;
  EXPECT_NEAR(curve_length(bezier({{0, 0, 0}, {0.5, 0, 0}, {1, 1, 0}})), exact, 1e-13 * exact);
}

}  // namespace
}  // namespace pl
