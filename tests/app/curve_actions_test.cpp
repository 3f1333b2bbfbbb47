// The curve actions of the editor's table act on the curve of the selected point, at the
// parameter where the right-click menu was opened (nearest sample) or the middle of the longest
// span; each is one undo step and keeps the curve's shape where the operation promises it.
#include "app/editor/logic/curve_actions.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "app/document/curve_commands.hpp"
#include "app/editor/logic/selection_actions.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "curve_test_util.hpp"

namespace pl::test {
namespace {

TEST(CurveActions, ActOnTheSelectedCurveWhereTheMenuWasOpened) {
  Document doc;
  Selection selection;
  ActionRegistry r;
  std::optional<Vec3> menu_at;
  std::string said;
  CurveActionHooks hooks;
  hooks.say = [&](const std::string& s) { said = s; };
  hooks.menu_point = [&] { return menu_at; };
  add_curve_actions(r, doc, selection, hooks);
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::BSpline, six_points()));
  const SceneCurve original = doc.scene().curves[0];

  // Nothing selected: nothing to act on.
  EXPECT_FALSE(r.is_enabled(*r.find("curve.insert_knot")));
  selection.set({SelectionItem::of_point(PointRef::curve_point(0, 2))});
  ASSERT_TRUE(r.is_enabled(*r.find("curve.insert_knot")));

  // From the menu opened at the curve's point at t: a knot at t (to the sampling's resolution).
  const double t_menu = 0.37 * original.t_max();
  menu_at = evaluate(original, t_menu).p;
  ASSERT_TRUE(r.run("curve.insert_knot"));
  const SceneCurve inserted = doc.scene().curves[0];
  ASSERT_EQ(inserted.points.size(), 7u);
  double nearest = 1e9;
  for (double k : inserted.knots)
    if (std::find(original.knots.begin(), original.knots.end(), k) == original.knots.end())
      nearest = std::min(nearest, std::abs(k - t_menu));
  EXPECT_LE(nearest, (original.t_max() - original.t_min()) / 100);
  EXPECT_LE(max_sample_difference(original, inserted), 1e-13);

  menu_at.reset();
  ASSERT_TRUE(r.run("curve.elevate"));
  EXPECT_EQ(curve_degree(doc.scene().curves[0]), 4);
  EXPECT_LE(max_sample_difference(original, doc.scene().curves[0]), 1e-12);
  ASSERT_TRUE(r.run("curve.reverse"));
  EXPECT_LE(glm::length(evaluate(doc.scene().curves[0], doc.scene().curves[0].t_min()).p -
                        original.points.back()),
            1e-12);
  ASSERT_TRUE(r.run("curve.split"));
  EXPECT_EQ(doc.scene().curves.size(), 2u);
  // Each was one step: four undos give back the original curve alone.
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(doc.undo());
  ASSERT_EQ(doc.scene().curves.size(), 1u);
  EXPECT_EQ(doc.scene().curves[0].points, original.points);
  EXPECT_EQ(doc.scene().curves[0].knots, original.knots);
}

TEST(CurveActions, DefaultKnotGoesInTheLongestSpan) {
  SceneCurve c;
  c.type = CurveType::BSpline;
  c.degree = 2;
  c.points = six_points();
  c.knots = {0, 0, 0, 1, 2, 6, 7, 7, 7};
  EXPECT_DOUBLE_EQ(default_knot_parameter(c), 4.0);
  EXPECT_NEAR(nearest_curve_parameter(c, evaluate(c, 5.5).p), 5.5, 7.0 / 100);
}

}  // namespace
}  // namespace pl::test

namespace pl::test {
namespace {

// A curve picked by its line (the whole curve selected, no point) is what the actions act on,
// and the right-click menu on a curve's line offers them.
TEST(CurveActions, ActOnACurveSelectedByItsLine) {
  Document doc;
  Selection selection;
  ActionRegistry r;
  CurveActionHooks hooks;
  hooks.say = [](const std::string&) {};
  add_curve_actions(r, doc, selection, hooks);
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::BSpline, six_points()));
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::Bezier, six_points()));
  EXPECT_EQ(parse_item_name("curve 1"), SelectionItem::curve(1));
  EXPECT_EQ(describe(SelectionItem::curve(1)), "curve 1");
  EXPECT_TRUE(item_exists(doc.scene(), SelectionItem::curve(1)));
  EXPECT_FALSE(item_exists(doc.scene(), SelectionItem::curve(2)));
  selection.set({SelectionItem::curve(1)});
  EXPECT_EQ(selected_curve(doc.scene(), selection), 1);
  const std::vector<const Action*> offered = r.for_context(ContextTarget::Curve);
  std::vector<std::string> ids;
  for (const Action* a : offered) ids.push_back(a->id);
  EXPECT_EQ(ids, (std::vector<std::string>{"curve.insert_knot", "curve.elevate", "curve.split",
                                           "curve.reverse", "curve.to_edges"}));
  ASSERT_TRUE(r.run("curve.elevate"));
  EXPECT_EQ(curve_degree(doc.scene().curves[1]), 6);
  EXPECT_EQ(curve_degree(doc.scene().curves[0]), 3);
  // Its points are the selection's points for framing and the like, and Points of Selection
  // (offered on the curve's right-click menu) selects them.
  EXPECT_EQ(points_of(doc.scene(), selection).size(), doc.scene().curves[1].points.size());
  add_selection_actions(r, doc, selection, hooks.say);
  const std::vector<const Action*> on_curve = r.for_context(ContextTarget::Curve);
  EXPECT_NE(std::find_if(on_curve.begin(), on_curve.end(),
                         [](const Action* a) { return a->id == "select.points_of"; }),
            on_curve.end());
  ASSERT_TRUE(r.run("select.points_of"));
  ASSERT_EQ(selection.size(), doc.scene().curves[1].points.size());
  EXPECT_EQ(selection.items()[0], SelectionItem::of_point(PointRef::curve_point(1, 0)));
}

}  // namespace
}  // namespace pl::test
