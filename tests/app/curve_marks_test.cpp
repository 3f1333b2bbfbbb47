// The editor's marks on free curves: knot ticks (values, multiplicities, ends, on the curve,
// across its tangent on screen) and the joints with their G0/G1/G2 class, against the curves'
// own numbers and the asset with a G0, a G1 and a G2 joint.
#include "app/editor/logic/curve_marks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/cli/load_input.hpp"
#include "curve_test_util.hpp"

namespace pl {
namespace {

SceneCurve cubic_bspline_with_double_knot() {
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = 3;
  c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}, {5, 1, 0}, {6, 0, 0}};
  // Interior knots 1 (simple) and 2 (double); 7 points + 3 + 1 = 11 knots.
  c.knots = {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 3};
  return c;
}

TEST(CurveMarks, TicksAtEveryDistinctKnotWithItsMultiplicity) {
  const SceneCurve c = cubic_bspline_with_double_knot();
  const std::vector<KnotTick> ticks = knot_ticks(c);
  ASSERT_EQ(ticks.size(), 4u);
  const double t[] = {0, 1, 2, 3};
  const int m[] = {1, 1, 2, 1};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(ticks[i].t, t[i]);
    EXPECT_EQ(ticks[i].multiplicity, m[i]) << i;
    EXPECT_EQ(ticks[i].end, i == 0 || i == 3);
    const CurvePoint p = evaluate(c, t[i]);
    EXPECT_EQ(ticks[i].point, p.p);
    EXPECT_EQ(ticks[i].tangent, p.d1);
  }
  // The ends of a clamped cubic are its first and last points.
  EXPECT_LT(glm::length(ticks.front().point - c.points.front()), 1e-15);
  EXPECT_LT(glm::length(ticks.back().point - c.points.back()), 1e-15);
  // A double knot's tick is longer than a simple one's, the ends longer still than a simple one.
  EXPECT_GT(tick_length_px(ticks[2], 10), tick_length_px(ticks[1], 10));
  EXPECT_GT(tick_length_px(ticks[0], 10), tick_length_px(ticks[1], 10));
}

TEST(CurveMarks, PolynomialCurvesHaveTheirEndsOnly) {
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 0, 1}};
  const std::vector<KnotTick> ticks = knot_ticks(c);
  ASSERT_EQ(ticks.size(), 2u);
  EXPECT_TRUE(ticks[0].end && ticks[1].end);
  EXPECT_EQ(ticks[0].point, c.points[0]);
  EXPECT_EQ(ticks[1].point, c.points[3]);
  // Bezier end tangents: d (P1 - P0) and d (P3 - P2).
  EXPECT_LT(glm::length(ticks[0].tangent - 3.0 * (c.points[1] - c.points[0])), 1e-14);
  EXPECT_LT(glm::length(ticks[1].tangent - 3.0 * (c.points[3] - c.points[2])), 1e-14);
}

TEST(CurveMarks, ATickCrossesTheCurveOnScreen) {
  // Looking down at the XY plane: a curve running along x has vertical ticks, one along the
  // diagonal ticks across the diagonal.
  const ViewRect rect{0, 0, 800, 600};
  Camera cam = preset_camera(ViewPreset::Top, Box{Vec3(-2, -2, 0), Vec3(2, 2, 0)}, rect.aspect());
  const WindowProjector project(cam, rect);
  for (const Vec3 dir : {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, -2, 0)}) {
    KnotTick k;
    k.point = {0.3, -0.2, 0};
    k.tangent = dir;
    const auto s = tick_on_screen(project, k, 20);
    ASSERT_TRUE(s);
    EXPECT_NEAR(glm::length(s->b - s->a), 20, 1e-9);
    EXPECT_LT(glm::length(0.5 * (s->a + s->b) - *project(k.point)), 1e-9);
    const Vec2 along = *project(k.point + 1e-3 * dir) - *project(k.point);
    EXPECT_LT(std::abs(glm::dot(glm::normalize(along), glm::normalize(s->b - s->a))), 1e-6);
  }
  // A vanishing tangent still gets a tick (across the window's x axis).
  KnotTick still;
  const auto s = tick_on_screen(project, still, 10);
  ASSERT_TRUE(s);
  EXPECT_NEAR(std::abs(s->b.y - s->a.y), 10, 1e-9);
}

TEST(CurveMarks, JointsOfTheAssetAreG0G1AndG2) {
  const Scene scene = load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" /
                                 "joints-g0-g1-g2.json");
  CurveMarks marks;
  EXPECT_TRUE(marks.follow(scene.curves));
  ASSERT_EQ(marks.joints().size(), 3u);
  // The pairs are named "G0 a"/"G0 b" and so on: the class must match the name.
  for (const JointReport& j : marks.joints()) {
    const std::string name = scene.curves[j.curves[0]].name;
    EXPECT_EQ(joint_class(j, marks.size()), name.substr(0, 2)) << joint_label(j, marks.size());
    EXPECT_EQ(j.position,
              evaluate(scene.curves[j.curves[0]], j.at_start[0] ? scene.curves[j.curves[0]].t_min()
                                                                : scene.curves[j.curves[0]].t_max())
                  .p);
    EXPECT_EQ(joint_ends(j, scene.curves).find(name), 0u);
  }
}

TEST(CurveMarks, ClassesFollowTheFigures) {
  JointReport j;
  j.curvature = {2.0, 2.0};
  EXPECT_EQ(joint_continuity(j, 1.0), 2);
  j.curvature_jump = 0.5;
  EXPECT_EQ(joint_continuity(j, 1.0), 1);
  j.tangent_angle_deg = 1.0;
  EXPECT_EQ(joint_continuity(j, 1.0), 0);
  // Straight on both sides: G2 (no curvature to jump).
  JointReport straight;
  EXPECT_EQ(joint_continuity(straight, 1.0), 2);
  j.tangent_angle_deg = std::nan("");
  EXPECT_EQ(joint_continuity(j, 1.0), 0);  // never G1 on a NaN
}

TEST(CurveMarks, AnEditOfOneCurveRecomputesThatCurveOnly) {
  std::vector<SceneCurve> curves(3, cubic_bspline_with_double_knot());
  for (int c = 0; c < 3; ++c)
    for (Vec3& p : curves[c].points) p.y += 3.0 * c;
  CurveMarks marks;
  marks.follow(curves);
  EXPECT_EQ(marks.last_recomputed(), 3u);
  EXPECT_FALSE(marks.follow(curves));
  EXPECT_EQ(marks.last_recomputed(), 0u);
  curves[1].points[3].z = 0.5;
  EXPECT_TRUE(marks.follow(curves));
  EXPECT_EQ(marks.last_recomputed(), 1u);
  EXPECT_EQ(marks.ticks()[1][2].point, evaluate(curves[1], 2.0).p);
  // The second curve's end joined onto the third's start: a joint appears.
  curves[2].points.front() = curves[1].points.back();
  marks.follow(curves);
  ASSERT_EQ(marks.joints().size(), 1u);
  EXPECT_EQ(marks.joints()[0].curves, (std::array<int, 2>{1, 2}));
  EXPECT_EQ(marks.joints()[0].at_start, (std::array<bool, 2>{false, true}));
  // A moved point of a long spline evaluates only the knots of its support (p + 2 of them).
  std::vector<SceneCurve> one(1);
  one[0].type = CurveType::BSpline;
  one[0].degree = 3;
  for (int i = 0; i < 1000; ++i) one[0].points.push_back({0.01 * i, std::sin(0.05 * i), 0});
  for (int i = 0; i < 1004; ++i) one[0].knots.push_back(std::clamp(i - 3, 0, 997));
  marks.follow(one);
  EXPECT_EQ(marks.last_ticks_evaluated(), 998u);
  one[0].points[500].z = 0.2;
  marks.follow(one);
  EXPECT_EQ(marks.last_ticks_evaluated(), 5u);  // knots 497 .. 501
  const std::vector<KnotTick> fresh = knot_ticks(one[0]);
  ASSERT_EQ(marks.ticks()[0].size(), fresh.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    EXPECT_EQ(marks.ticks()[0][k].point, fresh[k].point) << k;
    EXPECT_EQ(marks.ticks()[0][k].tangent, fresh[k].tangent) << k;
  }
  curves.clear();
  EXPECT_TRUE(marks.follow(curves));
  EXPECT_TRUE(marks.joints().empty() && marks.ticks().empty());
}

}  // namespace
}  // namespace pl
