// Free curves as chains of cubic Bézier spans: a curve that is one cubic comes out as itself; any
// other curve within the tolerance, checked here independently by the two-sided distance between
// dense polylines of the curve and of the chain; consecutive spans share their ends and their
// tangent directions where the curve is smooth.
#include "core/curve/cubic_fit.hpp"

#include <gtest/gtest.h>

#include "scene_curve_samples.hpp"

namespace pl {
namespace {

double diagonal(const std::vector<Vec3>& pts) {
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

SceneCurve bezier(std::vector<Vec3> points) {
  return test::bezier_scene_curve(std::move(points));
}

// A non-uniform cubic B-spline with a double knot, unclamped at its start.
SceneCurve wavy() {
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = 3;
  c.knots = {-0.5, -0.2, 0, 0.1, 0.3, 0.3, 0.7, 0.9, 1.2, 1.4, 1.5};
  c.points = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 0}, {3, 1, 1}, {4, 0, -1}, {5, 2, 0}, {6, 1, 0.5}};
  validate_curve(c);
  return c;
}

// The same with weights: rational, so no span is a cubic and every span is fitted.
SceneCurve rational_wavy() {
  SceneCurve c = wavy();
  c.type = CurveType::Nurbs;
  c.weights = {1, 0.5, 2, 1.5, 0.7, 1, 3};
  validate_curve(c);
  return c;
}

SceneCurve circle() {
  return test::circle_scene_curve(Vec3(1, 2, 0), 3);
}

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t =
      glm::dot(d, d) > 0 ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

// The largest distance from a point of `from` to the polyline `to`.
double one_sided(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  double worst = 0;
  for (const Vec3& p : from) {
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < to.size(); ++i)
      best = std::min(best, point_segment(p, to[i], to[i + 1]));
    worst = std::max(worst, best);
  }
  return worst;
}

std::vector<Vec3> curve_polyline(const SceneCurve& c, int n) {
  std::vector<Vec3> out;
  for (int k = 0; k <= n; ++k)
    out.push_back(evaluate(c, c.t_min() + (c.t_max() - c.t_min()) * k / n).p);
  return out;
}

std::vector<Vec3> chain_polyline(const CubicChain& chain, int per_span) {
  std::vector<Vec3> out;
  for (const auto& s : chain.spans)
    for (int k = 0; k <= per_span; ++k)
      out.push_back(BezierCurve({s[0], s[1], s[2], s[3]}).point(double(k) / per_span));
  return out;
}

// The two-sided distance, on polylines fine enough that their chords stray far less than the
// tolerances used here.
double hausdorff(const SceneCurve& c, const CubicChain& chain) {
  return std::max(one_sided(curve_polyline(c, 3000), chain_polyline(chain, 400)),
                  one_sided(chain_polyline(chain, 100), curve_polyline(c, 3000)));
}

TEST(CubicFit, ACubicBezierIsItself) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 2, 0.5}, {3, 2, -1}, {4, 0, 0}};
  const CubicChain chain = cubic_chain(bezier(p), 1e-6);
  ASSERT_EQ(chain.spans.size(), 1u);
  for (int i = 0; i < 4; ++i) EXPECT_LT(glm::length(chain.spans[0][i] - p[i]), 1e-15 * 5);
  EXPECT_LT(chain.deviation, 1e-14);
}

TEST(CubicFit, LowerDegreeAndHermiteCurvesAreOneExactSpan) {
  const std::vector<Vec3> q{{0, 0, 0}, {1, 2, 0}, {3, 0, 1}};
  const CubicChain quad = cubic_chain(bezier(q), 1e-9);
  ASSERT_EQ(quad.spans.size(), 1u);  // the quadratic raised: (P0 + 2 P1) / 3, (2 P1 + P2) / 3
  EXPECT_LT(glm::length(quad.spans[0][1] - (q[0] + 2.0 * q[1]) / 3.0), 1e-15);
  EXPECT_LT(glm::length(quad.spans[0][2] - (2.0 * q[1] + q[2]) / 3.0), 1e-15);
  SceneCurve h;
  h.type = CurveType::Hermite;
  h.points = {{0, 0, 0}, {2, 1, 0}};
  h.tangents = {{3, 0, 0}, {0, 3, 1}};
  const CubicChain hermite = cubic_chain(h, 1e-9);
  ASSERT_EQ(hermite.spans.size(), 1u);
  EXPECT_LT(glm::length(hermite.spans[0][1] - (h.points[0] + h.tangents[0] / 3.0)), 1e-15);
  EXPECT_LT(glm::length(hermite.spans[0][2] - (h.points[1] - h.tangents[1] / 3.0)), 1e-15);
}

TEST(CubicFit, ACubicSplineIsOneExactSpanPerKnotSpan) {
  const SceneCurve c = wavy();
  const CubicChain chain = cubic_chain(c, 1e-12);
  EXPECT_EQ(chain.spans.size(), curve_span_count(c));
  EXPECT_LT(chain.deviation, 1e-13);
  EXPECT_EQ(chain.breaks, (std::vector<double>{0.1, 0.3, 0.7, 0.9}));
}

TEST(CubicFit, ARationalSplineIsFittedWithinTheToleranceWithSmoothJoints) {
  const SceneCurve c = rational_wavy();
  for (const double relative : {1e-2, 1e-3, 1e-5}) {
    const double tol = relative * diagonal(c.points);
    const CubicChain chain = cubic_chain(c, tol);
    EXPECT_GT(chain.spans.size(), 1u);
    EXPECT_LE(chain.deviation, tol);
    EXPECT_LE(hausdorff(c, chain), tol * 1.001) << relative;
    for (std::size_t s = 1; s < chain.spans.size(); ++s) {
      EXPECT_EQ(chain.spans[s][0], chain.spans[s - 1][3]);
      const Vec3 in = glm::normalize(chain.spans[s - 1][3] - chain.spans[s - 1][2]);
      const Vec3 out = glm::normalize(chain.spans[s][1] - chain.spans[s][0]);
      EXPECT_LT(glm::length(in - out), 1e-9) << "joint " << s;  // the curve is C1
    }
    EXPECT_EQ(chain.breaks.size(), chain.spans.size() + 1);
    EXPECT_EQ(chain.breaks.front(), c.t_min());
    EXPECT_EQ(chain.breaks.back(), c.t_max());
  }
}

TEST(CubicFit, ARationalCircleIsFittedWithinTheTolerance) {
  const SceneCurve c = circle();
  const double tol = 1e-4 * 6;
  const CubicChain chain = cubic_chain(c, tol);
  EXPECT_LE(hausdorff(c, chain), tol * 1.001);
  // The spans match the circle's parametric derivatives, not its arc length: more than the
  // fewest cubics would need, but bounded.
  EXPECT_LE(chain.spans.size(), 32u);
  EXPECT_LT(glm::length(chain.spans.back()[3] - chain.spans.front()[0]), 1e-12);  // closed
}

TEST(CubicFit, RefusesWhatItCannotDo) {
  EXPECT_THROW(cubic_chain(wavy(), 0), std::invalid_argument);
  EXPECT_THROW(cubic_chain(wavy(), NAN), std::invalid_argument);
  try {
    cubic_chain(circle(), 1e-9, 4);
    ADD_FAILURE() << "four cubics cannot follow a circle to 1e-9";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("more than 4"), std::string::npos) << e.what();
  }
  SceneCurve broken = wavy();  // a knot of multiplicity 4: two pieces apart
  broken.knots = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1};
  broken.points = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0},
                   {5, 0, 0}, {6, 1, 0}, {7, 1, 0}, {8, 0, 0}};
  validate_curve(broken);
  try {
    cubic_chain(broken, 1e-3);
    ADD_FAILURE() << "a broken curve is not one chain";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("broken"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pl
