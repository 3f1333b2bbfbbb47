// The select tool and the view navigator, driven by pointer events as the window layer sends
// them, against the document and the exact view-plane maths.
#include <gtest/gtest.h>

#include "app/cli/load_input.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/select_tool.hpp"
#include "app/editor/logic/view_navigator.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/handle_planes.hpp"
#include "core/network/network_filling.hpp"
#include "core/network/tangent_planes.hpp"

namespace pl {
namespace {

const ViewRect kRect{0, 20, 1000, 700};

struct ToolFixture : ::testing::Test {
  Document doc{load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json")};
  Selection selection;
  WorkPlane plane;
  LiveSurfaces live{doc.scene(), 16, std::nullopt, "default"};
  Camera camera = preset_camera(ViewPreset::Iso, live.draw().bounds(), kRect.aspect());
  ToolContext ctx{doc, selection, camera, plane};
  ScenePicker picker;
  std::vector<SelectionItem> items = surface_items(live.surfaces());
  PickResult under;

  // The event at `pixel` with the pick there, as the editor builds it each frame.
  PointerEvent at(const Vec2& pixel, bool shift = false, bool ctrl = false, bool alt = false) {
    under = picker.pick({live.draw().surfaces, items, live.draw().network_curves, &live.points(),
                         live.draw().free_curves},
                        camera, kRect, pixel);
    PointerEvent e;
    e.pixel = pixel;
    e.rect = kRect;
    e.shift = shift;
    e.ctrl = ctrl;
    e.alt = alt;
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

// The end tangents at vertex v, and how far the most tilted one is off the plane of normal n
// (degrees).
double worst_off_plane_deg(const Network& n, int v, const Vec3& normal) {
  double worst = 0;
  for (int e : edges_at(n, v)) {
    const Vec3 t = glm::normalize(end_tangent(n, e, v));
    worst = std::max(worst, std::asin(std::min(1.0, std::abs(glm::dot(t, normal)))) * 180 / M_PI);
  }
  return worst;
}

TEST_F(ToolFixture, DraggingANormalKnobTurnsTheTangentPlaneAsOneStepWhateverThePauses) {
  SelectTool tool;
  auto now = Document::Clock::time_point();
  doc.set_clock([&] { return now; });
  const std::string before = scene_to_json(doc.scene());
  selection.set({SelectionItem::of_point(PointRef::vertex(1))});
  const std::vector<PlaneHandle> handles = plane_handles(doc.scene(), selection, camera, kRect, 1);
  ASSERT_EQ(handles.size(), 1u);
  const PlaneHandle h = handles[0];
  EXPECT_FALSE(h.fixed);
  // The disc is the plane the filling uses at the vertex, on the faces' side.
  const Network& n0 = *doc.scene().network;
  const TangentPlane filled = vertex_tangent_plane(n0, validate_network(n0, "t"), 1);
  EXPECT_GT(glm::dot(h.normal, filled.normal), 1 - 1e-12);
  const Vec2 knob = *project_to_window(camera, kRect, h.knob);
  // As long as kNormalHandlePx pixels at the vertex's depth (shorter on screen when tilted).
  EXPECT_NEAR(glm::length(h.knob - h.centre),
              kNormalHandlePx * world_per_pixel(camera, kRect, h.centre), 1e-12);
  EXPECT_EQ(pick_knob(handles, camera, kRect, knob + Vec2(5, -5), kKnobPickRadiusPx), 0);
  EXPECT_EQ(pick_knob(handles, camera, kRect, knob + Vec2(9, -9), kKnobPickRadiusPx), -1);
  ASSERT_TRUE(tool.press(ctx, at(knob)));
  EXPECT_TRUE(tool.capturing());
  EXPECT_TRUE(selection.contains(SelectionItem::of_point(PointRef::vertex(1))));
  const Vec2 end = knob + Vec2(28, 16);
  for (const Vec2& d : {Vec2(10, 5), Vec2(20, 10), end - knob}) {
    now += std::chrono::seconds(3);  // pauses longer than the merge window
    tool.drag(ctx, at(knob + d));
  }
  tool.release(ctx, at(end));
  EXPECT_FALSE(tool.capturing());
  const Network& n = *doc.scene().network;
  ASSERT_TRUE(n.normals.size() == n.vertices.size() && n.normals[1]);
  const Vec3 normal = *n.normals[1];
  EXPECT_LT(glm::dot(normal, h.normal), 0.999);  // turned
  // The normal points from the vertex towards the cursor on screen.
  const Vec2 c = *project_to_window(camera, kRect, h.centre);
  const Vec2 along = *project_to_window(camera, kRect, h.centre + 1e-4 * normal) - c;
  const Vec2 to_cursor = end - c;
  EXPECT_LT(std::abs(along.x * to_cursor.y - along.y * to_cursor.x),
            1e-6 * glm::length(along) * glm::length(to_cursor));
  EXPECT_GT(glm::dot(along, to_cursor), 0);
  // The handles turned with the plane: no tangent is projected, the faces stay G1.
  EXPECT_LT(worst_off_plane_deg(n, 1, normal), 1e-9);
  const NetworkFilling f = fill_network(n, validate_network(n, "t"), std::nullopt, "t");
  EXPECT_TRUE(f.projected_vertices.empty());
  // One undo step, bit for bit.
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  EXPECT_FALSE(doc.can_undo());
  // Esc during a knob drag puts the plane back.
  selection.adopt(doc.scene());
  ASSERT_TRUE(tool.press(ctx, at(knob)));
  tool.drag(ctx, at(knob + Vec2(-20, 0)));
  EXPECT_NE(scene_to_json(doc.scene()), before);
  tool.cancel(ctx);
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  EXPECT_FALSE(tool.capturing());
}

TEST_F(ToolFixture, HandlesStayInTheirVertexPlaneUnlessAltIsHeld) {
  SelectTool tool;
  // Edge 0's handle at vertex 1, where three edges meet.
  const PointRef h = PointRef::handle(0, 1);
  const Vec3 start = point_position(doc.scene(), h);
  const Network n0 = *doc.scene().network;
  const Vec3 plane = *handle_plane_normal(n0, 1, std::vector<int>{0});
  const Vec2 p0 = pixel_of(h);
  const Vec2 p1 = p0 + Vec2(30, -25);
  const Vec3 target = start + DragMotion{start, p0}.offset(camera, kRect, p1, {});
  ASSERT_GT(std::abs(glm::dot(target - n0.vertices[1], plane)), 1e-3);  // off the plane
  ASSERT_TRUE(tool.press(ctx, at(p0)));
  tool.release(ctx, at(p1));
  const Vec3 kept = point_position(doc.scene(), h);
  EXPECT_NEAR(glm::dot(kept - n0.vertices[1], plane), 0, 1e-12);
  EXPECT_LT(worst_off_plane_deg(*doc.scene().network, 1, plane), 1e-9);
  ASSERT_TRUE(doc.undo());

  // With Alt the handle goes where the cursor says and the plane turns with it.
  selection.clear();
  ASSERT_TRUE(tool.press(ctx, at(p0, false, false, true)));
  tool.release(ctx, at(p1, false, false, true));
  const Network free = *doc.scene().network;
  EXPECT_EQ(point_position(doc.scene(), h), target);
  const Vec3 turned = *handle_plane_normal(free, 1);
  EXPECT_LT(worst_off_plane_deg(free, 1, turned), 1e-9);
  EXPECT_GT(std::abs(glm::dot(turned, plane)), 0.5);  // turned, not flipped
  EXPECT_LT(std::abs(glm::dot(turned, plane)), 1 - 1e-6);
  ASSERT_TRUE(doc.undo());

  // Alt pressed during a drag: it goes on freely from the drag's start.
  ASSERT_TRUE(tool.press(ctx, at(p0)));
  tool.drag(ctx, at(p0 + Vec2(10, -5)));
  tool.drag(ctx, at(p1, false, false, true));
  tool.release(ctx, at(p1, false, false, true));
  EXPECT_EQ(*doc.scene().network, free);
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.can_undo());  // one step
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
