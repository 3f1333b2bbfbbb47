// Delete on free curves, through the keys, the menus and the status bar as a designer meets
// them: a curve clicked on its line is deleted by Del (one undo step; undo brings it back in its
// place, the curves after it renumbered meanwhile), Delete is offered on a curve's right-click
// menu, network elements and curves selected together go in one step, and a Delete that has
// nothing to act on says why in the status bar instead of doing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model_driver.hpp"

namespace pl::test {

namespace {

// Clicks a free curve of `points` with the New Curve tool and makes it (Enter).
void draw_curve(ModelDriver& d, const std::vector<Vec3>& points) {
  d.key("B");
  for (const Vec3& p : points) d.click(d.world_to_pixel(p));
  d.key("Enter");
}

const std::vector<Vec3> kFirst = {{-0.9, 0.2, 0}, {-0.6, 0.7, 0}, {-0.2, 0.6, 0}, {0, 0.3, 0}};
const std::vector<Vec3> kSecond = {{0.2, -0.6, 0}, {0.5, -0.2, 0}, {0.8, -0.5, 0}};

bool offers(EditorModel& m, ContextTarget target, const std::string& id) {
  const auto actions = m.actions().for_context(target);
  return std::any_of(actions.begin(), actions.end(), [&](const Action* a) { return a->id == id; });
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(Delete, DelRemovesTheFreeCurveClickedAndUndoBringsItBack) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  draw_curve(d, kFirst);
  draw_curve(d, kSecond);
  const std::vector<SceneCurve> before = m.doc().scene().curves;
  ASSERT_EQ(before.size(), 2u);

  d.key("Q");
  d.click(d.curve(0));
  ASSERT_EQ(m.selection().items(), std::vector<SelectionItem>{SelectionItem::curve(0)});
  const Action* del = m.actions().find("edit.delete");
  ASSERT_TRUE(del);
  EXPECT_TRUE(m.actions().is_enabled(*del)) << "Edit > Delete is offered for a selected curve";
  EXPECT_TRUE(offers(m, ContextTarget::Curve, "edit.delete")) << "and on the curve's menu";

  const uint64_t revision = m.doc().revision();
  d.key("Del");
  const std::vector<SceneCurve>& after = m.doc().scene().curves;
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].points, before[1].points) << "the other curve is kept, now curve 0";
  EXPECT_TRUE(m.selection().empty()) << "what was deleted is no longer selected";
  EXPECT_TRUE(contains(m.status().message(), "delete curve 0")) << m.status().message();
  EXPECT_EQ(m.doc().revision(), revision + 1) << "one undo step";

  d.key("Ctrl+Z");
  ASSERT_EQ(m.doc().scene().curves.size(), 2u);
  EXPECT_EQ(m.doc().scene().curves[0].points, before[0].points) << "back in its place";
  EXPECT_EQ(m.doc().scene().curves[1].points, before[1].points);
  d.key("Ctrl+Y");
  ASSERT_EQ(m.doc().scene().curves.size(), 1u);
  EXPECT_EQ(m.doc().scene().curves[0].points, before[1].points);
}

TEST(Delete, ANetworkVertexAndACurveSelectedTogetherGoInOneStep) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  d.key("V");
  d.click(d.world_to_pixel(Vec3(0.5, 0.5, 0)));
  d.click(d.world_to_pixel(Vec3(-0.5, -0.5, 0)));
  draw_curve(d, kFirst);
  draw_curve(d, kSecond);
  const std::vector<SceneCurve> before = m.doc().scene().curves;
  ASSERT_EQ(before.size(), 2u);
  d.key("Q");
  // A Shift-click would add them one by one; the selection they make:
  m.selection().set({SelectionItem::of_point(PointRef::vertex(0)), SelectionItem::curve(1),
                     SelectionItem::of_point(PointRef::curve_point(0, 2))});
  const Vec3 kept_vertex = m.doc().scene().network->vertices[1];
  d.key("Del");
  ASSERT_EQ(m.doc().scene().network->vertices.size(), 1u);
  EXPECT_EQ(m.doc().scene().network->vertices[0], kept_vertex);
  ASSERT_EQ(m.doc().scene().curves.size(), 1u);
  EXPECT_EQ(m.doc().scene().curves[0].points, before[0].points);
  // The point of the curve that stays is still selected, under the curve's (unchanged) number.
  EXPECT_EQ(m.selection().items(),
            std::vector<SelectionItem>{SelectionItem::of_point(PointRef::curve_point(0, 2))});
  d.key("Ctrl+Z");
  EXPECT_EQ(m.doc().scene().network->vertices.size(), 2u) << "one undo step brings back both";
  EXPECT_EQ(m.doc().scene().curves.size(), 2u);
}

TEST(Delete, ADeleteWithNothingToActOnSaysWhy) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  d.key("Del");
  EXPECT_TRUE(contains(m.status().message(), "Delete")) << m.status().message();
  EXPECT_TRUE(contains(m.status().message(), "nothing selected")) << m.status().message();

  // After Enter the new curve's last point is selected: a control point is not deleted alone,
  // and the status bar says how to delete the curve.
  draw_curve(d, kSecond);
  ASSERT_EQ(m.selection().points(), std::vector<PointRef>{PointRef::curve_point(0, 2)});
  const std::vector<SceneCurve> before = m.doc().scene().curves;
  d.key("Del");
  ASSERT_EQ(m.doc().scene().curves.size(), 1u) << "nothing deleted";
  EXPECT_EQ(m.doc().scene().curves[0].points, before[0].points);
  EXPECT_TRUE(contains(m.status().message(), "control points")) << m.status().message();
  EXPECT_TRUE(contains(m.status().message(), "select the curve")) << m.status().message();
}

}  // namespace pl::test
