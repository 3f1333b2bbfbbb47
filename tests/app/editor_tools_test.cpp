// The select tool and the view navigator, driven by pointer events as the window layer sends
// them, against the document and the exact view-plane maths.
#include <gtest/gtest.h>

#include "app/cli/load_input.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/select_tool.hpp"
#include "app/editor/logic/view_navigator.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

const ViewRect kRect{0, 20, 1000, 700};

struct ToolFixture : ::testing::Test {
  Document doc{load_input(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json")};
  Selection selection;
  WorkPlane plane;
  LiveSurfaces live{doc.scene(), 16, std::nullopt, "default"};
  Camera camera = preset_camera(ViewPreset::Iso, live.draw().bounds(), kRect.aspect());
  ToolContext ctx{doc, selection, camera, plane};
  ScenePicker picker;
  std::vector<SelectionItem> items = surface_items(live.surfaces());
  PickResult under;

  // The event at `pixel` with the pick there, as the editor builds it each frame.
  PointerEvent at(const Vec2& pixel, bool shift = false, bool ctrl = false) {
    under = picker.pick({live.draw().surfaces, items, live.draw().network_curves, &live.points()},
                        camera, kRect, pixel);
    PointerEvent e;
    e.pixel = pixel;
    e.rect = kRect;
    e.shift = shift;
    e.ctrl = ctrl;
    e.under = &under;
    return e;
  }
  Vec2 pixel_of(const PointRef& p) {
    return *project_to_window(camera, kRect, point_position(doc.scene(), p));
  }
  // A pixel on face f: one of its samples whose pick is that face.
  Vec2 pixel_on_face(int f) {
    const SurfaceMesh& m = live.draw().surfaces[f];
    for (std::size_t i = m.positions.size() / 2; i < m.positions.size(); i += 7) {
      const Vec2 px = *project_to_window(camera, kRect, m.positions[i]);
      if (at(px).under->item == SelectionItem::face(f)) return px;
    }
    ADD_FAILURE() << "no clear pixel on face " << f;
    return Vec2(0);
  }
};

TEST_F(ToolFixture, DragMovesTheSelectedPointsByTheViewPlaneOffsetAsOneStep) {
  SelectTool tool;
  const std::string before = scene_to_json(doc.scene());
  const PointRef v = PointRef::vertex(2);
  const Vec3 start = point_position(doc.scene(), v);
  const Vec2 p0 = pixel_of(v);
  ASSERT_TRUE(tool.press(ctx, at(p0)));
  EXPECT_TRUE(tool.capturing());
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::of_point(v)});
  EXPECT_TRUE(doc.dragging());
  for (int dx : {10, 20, 30}) tool.drag(ctx, at(p0 + Vec2(dx, 0)));
  tool.release(ctx, at(p0 + Vec2(40, -10)));
  EXPECT_FALSE(tool.capturing());
  EXPECT_FALSE(doc.dragging());
  const Vec3 expected = DragMotion{start, p0}.offset(camera, kRect, p0 + Vec2(40, -10), {});
  EXPECT_EQ(point_position(doc.scene(), v), start + expected);
  EXPECT_GT(glm::length(expected), 1e-3);
  // One undo step, restoring the scene bit for bit.
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.can_undo());
  EXPECT_EQ(scene_to_json(doc.scene()), before);
}

TEST_F(ToolFixture, AxisHeldMovesAlongThatAxisOnly) {
  SelectTool tool;
  // At vertex 0, which has two edges: no tangent plane holds the handle (at vertex 1, with three,
  // the drag would be kept in the plane).
  const PointRef h = PointRef::handle(0, 0);
  const Vec3 start = point_position(doc.scene(), h);
  const Vec2 p0 = pixel_of(h);
  ASSERT_TRUE(tool.press(ctx, at(p0)));
  PointerEvent e = at(p0 + Vec2(25, 15));
  e.axis = Vec3(0, 0, 1);
  tool.release(ctx, e);
  const Vec3 moved = point_position(doc.scene(), h) - start;
  EXPECT_EQ(moved.x, 0);
  EXPECT_EQ(moved.y, 0);
  EXPECT_NE(moved.z, 0);
}

TEST_F(ToolFixture, ClicksSelectFacesAndEdgesShiftAddsCtrlTogglesEmptyClears) {
  SelectTool tool;
  const Vec2 f1 = pixel_on_face(1), f0 = pixel_on_face(0);
  // A press on a face does not capture (a drag there orbits); the click selects.
  PointerEvent e = at(f1);
  EXPECT_FALSE(tool.press(ctx, e));
  tool.click(ctx, e);
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::face(1)});
  e = at(f0, true);
  tool.click(ctx, e);
  EXPECT_EQ(selection.items(),
            (std::vector<SelectionItem>{SelectionItem::face(1), SelectionItem::face(0)}));
  e = at(f1, false, true);
  tool.click(ctx, e);
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::face(0)});
  // A curve: its edge.
  const Polyline& line = live.draw().network_curves[0];
  const Vec2 mid = *project_to_window(camera, kRect, line[line.size() / 2 + 3]);
  e = at(mid);
  ASSERT_TRUE(e.under->item);
  tool.click(ctx, e);
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::edge(0)});
  // Shift-click on empty space keeps the selection; a plain one clears it.
  tool.click(ctx, at(Vec2(3, 25), true));
  EXPECT_EQ(selection.size(), 1u);
  tool.click(ctx, at(Vec2(3, 25)));
  EXPECT_TRUE(selection.empty());
  EXPECT_FALSE(doc.can_undo());  // selecting is no edit
}

TEST_F(ToolFixture, PressOnOneOfSeveralSelectedPointsDragsThemAllCancelRestores) {
  SelectTool tool;
  const std::string before = scene_to_json(doc.scene());
  selection.set({SelectionItem::of_point(PointRef::vertex(0)),
                 SelectionItem::of_point(PointRef::vertex(1)), SelectionItem::face(0)});
  const Vec2 p0 = pixel_of(PointRef::vertex(1));
  ASSERT_TRUE(tool.press(ctx, at(p0)));
  EXPECT_EQ(selection.size(), 3u);
  EXPECT_EQ(doc.drag_points().size(), 2u);
  tool.drag(ctx, at(p0 + Vec2(30, 30)));
  EXPECT_NE(scene_to_json(doc.scene()), before);
  tool.cancel(ctx);
  EXPECT_FALSE(doc.dragging());
  EXPECT_FALSE(tool.capturing());
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  // Ctrl on a selected point takes it out and drags nothing.
  ASSERT_TRUE(tool.press(ctx, at(p0, false, true)));
  EXPECT_FALSE(doc.dragging());
  EXPECT_FALSE(selection.contains(SelectionItem::of_point(PointRef::vertex(1))));
  tool.release(ctx, at(p0));
  EXPECT_FALSE(doc.can_undo());
}

TEST_F(ToolFixture, ToolBoxCancelsTheToolItLeaves) {
  ToolBox box;
  box.add(std::make_unique<SelectTool>());
  box.add(std::make_unique<SelectTool>());
  const Vec2 p0 = pixel_of(PointRef::vertex(2));
  ASSERT_TRUE(box.active().press(ctx, at(p0)));
  box.active().drag(ctx, at(p0 + Vec2(5, 5)));
  ASSERT_TRUE(box.activate(1, ctx));
  EXPECT_FALSE(doc.dragging());
  EXPECT_FALSE(box.tool(0).capturing());
  EXPECT_EQ(box.active_index(), 1u);
  EXPECT_FALSE(box.activate(7, ctx));
}

TEST(EditorNavigator, ClickOrbitPanAndWheel) {
  Box box;
  box.add(Vec3(-1));
  box.add(Vec3(1));
  ViewNavigator nav;
  EXPECT_FALSE(nav.framed());
  nav.frame(box, kRect.aspect());
  EXPECT_TRUE(nav.framed());
  const Camera start = nav.camera();
  // A press and release within the slop is a click and moves nothing much.
  nav.begin(ViewNavigator::Gesture::Orbit, Vec2(500, 400), Vec3(0));
  nav.move(Vec2(501, 401), kRect);
  EXPECT_TRUE(nav.end());
  // An orbit keeps the pivot where it is on screen.
  const Vec3 pivot(0.5, 0.2, -0.1);
  const Vec2 before = *project_to_window(nav.camera(), kRect, pivot);
  nav.begin(ViewNavigator::Gesture::Orbit, Vec2(500, 400), pivot);
  for (int i = 1; i <= 10; ++i) nav.move(Vec2(500 + 8 * i, 400 + 3 * i), kRect);
  EXPECT_FALSE(nav.end());
  const Vec2 after = *project_to_window(nav.camera(), kRect, pivot);
  EXPECT_LT(glm::length(after - before), 1e-6);
  EXPECT_NE(nav.camera().yaw, start.yaw);
  // A pan moves the target in the view plane.
  const Vec3 t0 = nav.camera().target;
  nav.begin(ViewNavigator::Gesture::Pan, Vec2(100, 100), Vec3(0));
  nav.move(Vec2(160, 100), kRect);
  EXPECT_FALSE(nav.end());
  EXPECT_NEAR(glm::dot(nav.camera().target - t0, nav.camera().forward()), 0, 1e-12);
  EXPECT_GT(glm::length(nav.camera().target - t0), 0);
  // The wheel zooms towards the cursor.
  const double d0 = nav.camera().distance;
  nav.wheel(kRect, Vec2(300, 300), 2);
  EXPECT_NEAR(nav.camera().distance, d0 / (ViewNavigator::kWheelZoom * ViewNavigator::kWheelZoom),
              1e-12);
  // Framing closely keeps the clipping planes sized for the scene.
  const double radius = nav.camera().scene_radius;
  Box small;
  small.add(Vec3(0.1));
  nav.frame_closely(small, kRect.aspect());
  EXPECT_GE(nav.camera().scene_radius, radius);
  nav.unframe();
  EXPECT_FALSE(nav.framed());
}

}  // namespace
}  // namespace pl
