// Snapping as a designer meets it: with Snap on (Shift+G) a vertex clicked on the work plane lands
// on the grid drawn there, Alt places it freely, a click near a vertex takes that vertex, and a
// click near a free curve lands exactly on its end, its midpoint or a point of the curve.
#include <gtest/gtest.h>

#include <cmath>

#include "app/document/curve_commands.hpp"
#include "model_driver.hpp"

namespace pl::test {

namespace {

// Whether x is a whole multiple of step (to rounding).
bool on_multiple(double x, double step) {
  return std::fabs(x / step - std::round(x / step)) < 1e-9;
}

Vec3 vertex(EditorModel& m, int v) {
  return m.doc().scene().network->vertices.at(v);
}

}  // namespace

TEST(Snapping, VerticesLandOnTheGridAltPlacesFreelyANearVertexIsTaken) {
  ModelDriver d(1280, 720);
  d.new_scene();
  d.key("7");  // looking down on the XY work plane
  EditorModel& m = d.model();
  d.key("Shift+G");
  ASSERT_TRUE(m.work_plane().snap);
  d.key("V");
  const double step = shown_grid_step(m.nav().camera());
  const Vec3 aim(0.37, 0.52, 0);
  d.click(d.world_to_pixel(aim));
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 1u) << m.status().message();
  const Vec3 a = vertex(m, 0);
  EXPECT_TRUE(on_multiple(a.x, step) && on_multiple(a.y, step)) << a.x << " " << a.y;
  EXPECT_EQ(a.z, 0);
  EXPECT_LE(glm::length(a - aim), step * std::sqrt(0.5) + 0.01);
  EXPECT_NE(m.status().message().find("snapped to grid"), std::string::npos)
      << m.status().message();

  d.hold(false, false, true);  // Alt: exactly where the cursor meets the plane
  const Vec3 free_aim(0.61, 0.13, 0);
  d.click(d.world_to_pixel(free_aim));
  d.hold(false, false, false);
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 2u);
  const Vec3 b = vertex(m, 1);
  EXPECT_FALSE(on_multiple(b.x, step) && on_multiple(b.y, step));
  EXPECT_LT(glm::length(b - free_aim), 0.01);

  // Four pixels beside vertex 0: that vertex, no new one.
  d.click(d.world_to_pixel(a) + Vec2(4, 0));
  EXPECT_EQ(m.doc().scene().network->vertices.size(), 2u);
  EXPECT_EQ(m.selection().points(), std::vector<PointRef>{PointRef::vertex(0)});
}

TEST(Snapping, ClicksNearAFreeCurveLandOnItsEndMidpointAndOnTheCurve) {
  ModelDriver d(1280, 720);
  d.new_scene();
  d.key("7");
  EditorModel& m = d.model();
  const std::vector<Vec3> p{{-0.8, -0.8, 0}, {-0.3, 0.4, 0}, {0.3, -0.4, 0}, {0.8, 0.8, 0}};
  m.doc().execute(std::make_unique<AddCurveCommand>(CurveType::Bezier, p));
  const SceneCurve c = m.doc().scene().curves.at(0);
  d.key("Shift+G");
  d.key("V");
  d.click(d.world_to_pixel(evaluate(c, c.t_max()).p) + Vec2(3, -2));
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 1u);
  EXPECT_EQ(vertex(m, 0), evaluate(c, c.t_max()).p);

  const Vec3 mid = evaluate(c, 0.5 * (c.t_min() + c.t_max())).p;
  d.click(d.world_to_pixel(mid) + Vec2(-3, 3));
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 2u);
  EXPECT_EQ(vertex(m, 1), mid);

  // Beside the curve at t = 0.2, far from its points: a point of the curve.
  const CurvePoint at = evaluate(c, 0.2);
  const Vec3 side = glm::normalize(Vec3(-at.d1.y, at.d1.x, 0));
  d.click(d.world_to_pixel(at.p) + 4.0 * Vec2(side.x, -side.y));
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 3u);
  const Vec3 on = vertex(m, 2);
  double nearest = INFINITY;
  for (int k = 0; k <= 20000; ++k)
    nearest = std::min(nearest, glm::length(evaluate(c, k / 20000.0).p - on));
  EXPECT_LT(nearest, 1e-4) << "on the curve (to the dense sampling's spacing)";
  EXPECT_LT(glm::length(on - at.p), 0.02);
}

}  // namespace pl::test
