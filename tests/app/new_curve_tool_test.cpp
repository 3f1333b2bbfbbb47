// The New Curve tool: clicks put points on the work plane, Enter (finish) makes one curve of the
// chosen type through/with them as one undo step and selects its last point; too few points or
// Esc make nothing.
#include "app/editor/logic/new_curve_tool.hpp"

#include <gtest/gtest.h>

namespace pl::test {
namespace {

const ViewRect kRect{0, 0, 1000, 700};

struct NewCurveFixture : ::testing::Test {
  Document doc;
  Selection selection;
  WorkPlane plane{WorkPlaneKind::View};  // the view plane through the origin
  Box box = [] {
    Box b;
    b.add(Vec3(-5, -5, 0));
    b.add(Vec3(5, 5, 0));
    return b;
  }();
  Camera camera = preset_camera(ViewPreset::Front, box, kRect.aspect());
  ToolContext ctx{doc, selection, camera, plane};
  NewCurveTool tool;

  // The point x right and y up of the origin, in the view plane through the origin.
  Vec3 world(const Vec2& xy) const { return xy.x * camera.right() + xy.y * camera.up(); }
  // Clicks at the pixels of world(x, y) and returns the points as the plane places them.
  std::vector<Vec3> click(const std::vector<Vec2>& xy) {
    std::vector<Vec3> placed;
    for (const Vec2& w : xy) {
      PointerEvent e;
      e.rect = kRect;
      e.pixel = *project_to_window(camera, kRect, world(w));
      placed.push_back(*placement(ctx, e));
      tool.click(ctx, e);
    }
    return placed;
  }
};

TEST_F(NewCurveFixture, SixClicksAndEnterMakeACubicBSplineThroughTheClickedPoints) {
  const auto placed = click({{-4, 0}, {-2, 3}, {0, -1}, {1, 2}, {3, 0}, {4, 3}});
  for (std::size_t i = 0; i < placed.size(); ++i)
    EXPECT_LE(glm::length(placed[i] - tool.points()[i]), 1e-12);
  // The work plane is the view plane through the origin: the clicks land where they were aimed.
  EXPECT_LE(glm::length(placed[1] - world({-2, 3})), 1e-9);
  ASSERT_TRUE(tool.can_finish(ctx));
  EXPECT_FALSE(tool.preview(ctx).lines.empty());
  tool.finish(ctx);
  ASSERT_EQ(doc.scene().curves.size(), 1u);
  const SceneCurve& c = doc.scene().curves[0];
  EXPECT_EQ(c.type, CurveType::BSpline);
  EXPECT_EQ(c.degree, 3);
  EXPECT_EQ(c.points, placed);
  EXPECT_TRUE(tool.points().empty());
  EXPECT_EQ(selection.items().size(), 1u);
  EXPECT_EQ(selection.items()[0].point, PointRef::curve_point(0, 5));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().curves.empty());
}

TEST_F(NewCurveFixture, TypesNeedTheirPointsAndEscDropsThem) {
  tool.set_type(CurveType::Interpolating);
  click({{0, 0}, {1, 1}, {2, 0}});
  EXPECT_FALSE(tool.can_finish(ctx));
  tool.finish(ctx);  // refused: says why
  EXPECT_TRUE(doc.scene().curves.empty());
  click({{3, 1}});
  tool.finish(ctx);
  ASSERT_EQ(doc.scene().curves.size(), 1u);
  EXPECT_EQ(doc.scene().curves[0].type, CurveType::Interpolating);
  // The interpolating cubic passes its four points at 0, 1/3, 2/3, 1.
  EXPECT_LE(glm::length(evaluate(doc.scene().curves[0], 1.0 / 3).p - world({1, 1})), 1e-9);
  tool.set_type(CurveType::Nurbs);
  click({{0, 2}, {1, 3}});
  EXPECT_TRUE(tool.capturing());
  tool.cancel(ctx);
  EXPECT_FALSE(tool.capturing());
  EXPECT_FALSE(tool.can_finish(ctx));
  EXPECT_EQ(doc.scene().curves.size(), 1u);
}

}  // namespace
}  // namespace pl::test
