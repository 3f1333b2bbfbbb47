// The camera commands on what a designer has in front of them: the preset views (keys 7, 1, 3, 0)
// in a new, empty scene, where drawing starts, and Frame All (F) around free curves with their
// curvature combs shown, checked by projecting every point drawn (the combs' tips too) into the
// view: each must land inside it with room to spare, in orthographic and perspective views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model_driver.hpp"
#include "render/default_view.hpp"

namespace pl::test {

namespace {

ViewRect view_of(EditorModel& m) {
  return m.layout().panels(m.views().panels())[0];
}

// The points of `points` as the view shows them: the largest share of the way from the view's
// centre to its edge any of them lies at, horizontally or vertically (1: on the edge, more:
// outside), or +inf when one is behind the eye.
double farthest_out(EditorModel& m, const std::vector<Vec3>& points) {
  const ViewRect r = view_of(m);
  const Vec2 centre(r.x + 0.5 * r.width, r.y + 0.5 * r.height);
  double most = 0;
  for (const Vec3& p : points) {
    const std::optional<Vec2> px = project_to_window(m.nav().camera(), r, p);
    if (!px) return INFINITY;
    most = std::max({most, std::abs(px->x - centre.x) / (0.5 * r.width),
                     std::abs(px->y - centre.y) / (0.5 * r.height)});
  }
  return most;
}

// The cube [-1, 1]^3's corners: where a new scene's points go.
std::vector<Vec3> unit_cube() {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  return corners;
}

// The tips of the free curve's comb teeth where the renderer draws them in the one pane: a
// tooth is the curvature vector (pointing away from the centre of curvature) times the scale
// that makes the 90th-percentile curvature's tooth 6 % of the drawn scene's diagonal, times the
// Display panel's comb scale, and is cut at 3 of those reference lengths.
std::vector<Vec3> drawn_comb_tips(EditorModel& m) {
  const EvaluatedView& view = m.views().panel(0);
  const std::vector<const CurvatureComb*> combs = view.curves().free_comb_refs();
  const Box box = view.shown().draw().bounds();
  const double diagonal = glm::length(box.hi - box.lo);
  const DisplaySettings& d = m.prefs().display;
  const double scale = automatic_comb_scale_of(combs, diagonal) * d.comb_scale;
  const double cap = 3 * 0.06 * diagonal * d.comb_scale;
  std::vector<Vec3> tips;
  for (const CurvatureComb* c : combs)
    for (std::size_t k = 0; k < c->points.size(); ++k) {
      const Vec3 tooth = scale * c->teeth[k];
      tips.push_back(c->points[k] + tooth * std::min(1.0, cap / glm::length(tooth)));
    }
  return tips;
}

void expect_direction(const Vec3& forward, const Vec3& expected, const std::string& view) {
  EXPECT_LT(glm::length(forward - glm::normalize(expected)), 1e-9)
      << view << ": looking along " << forward.x << " " << forward.y << " " << forward.z;
}

}  // namespace

TEST(ViewFraming, PresetViewsTurnTheViewOfANewEmptyScene) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  ASSERT_TRUE(m.doc().scene().curves.empty());
  ASSERT_TRUE(!m.doc().scene().network || m.doc().scene().network->vertices.empty());
  ASSERT_TRUE(m.scene_box().empty()) << "nothing is drawn in a new scene";
  ASSERT_TRUE(m.nav().camera().orthographic);

  // The world is z-up: Top looks down -z, Front along +y (from -y), Right along -x (from +x),
  // Iso from (+x, -y, +z).
  const struct {
    const char* key;
    Vec3 forward;
  } presets[] = {{"7", {0, 0, -1}}, {"1", {0, 1, 0}}, {"3", {-1, 0, 0}}, {"0", {-1, 1, -1}}};
  for (const auto& p : presets) {
    d.key(p.key);
    expect_direction(m.nav().camera().forward(), p.forward, std::string("key ") + p.key);
    EXPECT_TRUE(m.nav().camera().orthographic) << "a preset keeps the projection";
    // It frames where new points go: the cube about the origin, whole and filling the view.
    const double out = farthest_out(m, unit_cube());
    EXPECT_LT(out, 1.0) << "key " << p.key;
    EXPECT_GT(out, 0.5) << "key " << p.key;
  }

  // Drawing from the top view puts the vertex where the click was, on the XY work plane.
  d.key("7");
  d.key("V");
  d.click(d.world_to_pixel(Vec3(0.4, -0.3, 0)));
  ASSERT_TRUE(m.doc().scene().network);
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 1u);
  const Vec3 v = m.doc().scene().network->vertices[0];
  EXPECT_NEAR(v.x, 0.4, 0.01);
  EXPECT_NEAR(v.y, -0.3, 0.01);
  EXPECT_NEAR(v.z, 0.0, 1e-12);
}

TEST(ViewFraming, FrameAllKeepsEveryPointAndCombTipInsideTheViewWithAMargin) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  // A "C" opening to the left, taller than wide: its combs stick out above and below it.
  d.key("B");
  for (const Vec3& p : {Vec3(0, -1, 0), Vec3(0.6, -0.5, 0), Vec3(0.6, 0.5, 0), Vec3(0, 1, 0)})
    d.click(d.world_to_pixel(p));
  d.key("Enter");
  ASSERT_EQ(m.doc().scene().curves.size(), 1u);
  d.key("Q");
  m.prefs().display.combs = true;
  m.prefs().display.comb_scale = 2;  // the teeth drawn twice as long (the Display panel's scale)
  d.settle();

  for (const bool ortho : {true, false}) {
    if (m.nav().camera().orthographic != ortho) d.key("5");
    ASSERT_EQ(m.nav().camera().orthographic, ortho);
    for (const char* view : {"7", "1", "0"}) {
      d.key(view);
      d.key("F");
      const std::string where =
          std::string(ortho ? "orthographic" : "perspective") + ", view " + view;
      const std::vector<const DrawScene*> scenes = m.shown_scenes();
      ASSERT_EQ(scenes.size(), 1u);
      const std::vector<Vec3> tips = drawn_comb_tips(m);
      ASSERT_FALSE(tips.empty()) << "the combs are drawn";
      const std::vector<Vec3> drawn = framing_points(scenes);  // curve, its points, no combs
      // Everything inside with at least 5 % of the view's half-size to spare on every side...
      EXPECT_LE(farthest_out(m, tips), 0.95) << where << ": a comb is cut or touches the edge";
      EXPECT_LE(farthest_out(m, drawn), 0.95) << where << ": the curve touches the edge";
      // ... and framed, not just far away: something reaches towards the edge (in perspective
      // the eye also stays in front of the nearest point, which can keep an edge-on curve
      // deep in the view from reaching the margin itself).
      EXPECT_GE(std::max(farthest_out(m, tips), farthest_out(m, drawn)), 0.6) << where;
    }
  }
}

TEST(ViewFraming, FrameAllInANewEmptySceneShowsWhereNewPointsGo) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  m.nav().camera().zoom(20);  // zoomed far in: F must bring the work area back
  d.key("F");
  const double out = farthest_out(m, unit_cube());
  EXPECT_LT(out, 1.0);
  EXPECT_GT(out, 0.5);
}

}  // namespace pl::test
