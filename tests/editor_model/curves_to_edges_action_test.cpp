// Curve ▸ To Network Edges as the editor runs it: offered once a curve is selected, it turns
// every selected curve into edges in one undo step and selects the new edges, which Make Face
// (Shift+M on the selection) then closes into a face.
#include <gtest/gtest.h>

#include "app/document/curve_commands.hpp"
#include "model_driver.hpp"

namespace pl::test {

TEST(CurvesToEdgesAction, DrawnCurvesBecomeEdgesAndAFace) {
  ModelDriver d(1280, 720);
  d.new_scene();
  EditorModel& m = d.model();
  const Vec3 a(0, 0, 0), b(2, 0, 0.3), c(2, 2, 0), e(0, 2, 0.3);
  const std::vector<std::vector<Vec3>> sides{{a, {0.7, -0.2, 0.2}, {1.3, 0.1, 0.4}, b},
                                             {b, {2.2, 0.7, 0.2}, {1.9, 1.3, 0.1}, c},
                                             {c, {1.3, 2.1, 0.1}, {0.7, 1.9, 0.2}, e},
                                             {e, {-0.1, 1.3, 0.2}, {0.2, 0.7, 0.1}, a}};
  for (const auto& p : sides)
    m.doc().execute(std::make_unique<AddCurveCommand>(CurveType::Bezier, p));
  const Action* to_edges = m.actions().find("curve.to_edges");
  ASSERT_TRUE(to_edges);
  EXPECT_FALSE(m.actions().is_enabled(*to_edges)) << "nothing selected";
  m.selection().set({SelectionItem::curve(0), SelectionItem::curve(1), SelectionItem::curve(2),
                     SelectionItem::curve(3)});
  EXPECT_TRUE(m.actions().is_enabled(*to_edges));
  ASSERT_TRUE(m.actions().run("curve.to_edges"));
  d.settle();
  const Scene& s = m.doc().scene();
  EXPECT_TRUE(s.curves.empty());
  ASSERT_TRUE(s.network);
  EXPECT_EQ(s.network->vertices.size(), 4u);
  EXPECT_EQ(s.network->edges.size(), 4u);
  EXPECT_EQ(m.selection().items().size(), 4u);
  EXPECT_EQ(m.doc().undo_label(), "curves 0, 1, 2, 3 to 4 network edges (exact)");
  d.key("Shift+M");  // a face on the selected edges
  ASSERT_EQ(m.doc().scene().network->faces.size(), 1u) << m.status().message();
  EXPECT_EQ(m.doc().scene().network->faces[0].loop.size(), 4u);
  d.key("Ctrl+Z");
  d.key("Ctrl+Z");
  EXPECT_EQ(m.doc().scene().curves.size(), 4u) << "undo brings the curves back";
}

}  // namespace pl::test
