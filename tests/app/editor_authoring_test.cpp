// The authoring tools (add vertex, add edge, make face, split edge), driven by pointer events as
// the window layer sends them, and the actions on the selection (delete, add edge, make face,
// fill holes, split, tangent planes), run through the registry the menus and keys use: what
// each makes in the document, one undo step each, refusals that change nothing, and the
// selection following the renumbering.
#include <gtest/gtest.h>

#include "app/cli/load_input.hpp"
#include "app/editor/logic/add_edge_tool.hpp"
#include "app/editor/logic/add_vertex_tool.hpp"
#include "app/editor/logic/authoring_actions.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/make_face_tool.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/logic/select_tool.hpp"
#include "app/editor/logic/split_edge_tool.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

const ViewRect kRect{0, 20, 1000, 700};

// An empty network seen from the top (orthographic), where the XY work plane faces the viewer.
struct AuthoringTools : ::testing::Test {
  Document doc{[] {
    Scene s;
    s.network = Network{};
    return s;
  }()};
  Selection selection;
  WorkPlane plane;
  Camera camera = preset_camera(ViewPreset::Top, Box{Vec3(-1), Vec3(1)}, kRect.aspect(), true);
  std::vector<std::string> said;
  ToolContext ctx{doc, selection, camera, plane,
                  [this](const std::string& m) { said.push_back(m); }};
  PickResult under;

  // An event at `pixel` with nothing picked there (empty space), or the given pick.
  PointerEvent at(const Vec2& pixel, PickResult pick = {}, bool shift = false) {
    under = std::move(pick);
    PointerEvent e;
    e.pixel = pixel;
    e.rect = kRect;
    e.shift = shift;
    e.under = &under;
    return e;
  }
  static PickResult vertex(int v) {
    PickResult r;
    r.item = SelectionItem::of_point(PointRef::vertex(v));
    return r;
  }
  static PickResult edge(int e, double t = 0.5) {
    PickResult r;
    r.item = SelectionItem::edge(e);
    r.edge = e;
    r.edge_t = t;
    return r;
  }
  Vec2 pixel_of(const Vec3& p) const { return *project_to_window(camera, kRect, p); }
  const Network& net() const { return *doc.scene().network; }
  int undo_steps() {
    int n = 0;
    while (doc.undo()) ++n;
    while (doc.redo()) {
    }
    return n;
  }
  // Vertices at the corners of the unit square and a point to their left, added by clicks.
  void add_five(AddVertexTool& tool) {
    for (const Vec3& p :
         {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(-0.6, 0.5, 0)})
      tool.click(ctx, at(pixel_of(p)));
  }
};

TEST_F(AuthoringTools, AddVertexClicksLandOnTheWorkPlaneAndSelectTheNewVertex) {
  AddVertexTool tool;
  EXPECT_TRUE(tool.places_on_work_plane());  // the editor shows the plane's grid for it
  EXPECT_FALSE(AddEdgeTool().places_on_work_plane());
  const Vec2 px = pixel_of(Vec3(0.25, -0.5, 0));
  EXPECT_FALSE(tool.press(ctx, at(px)));  // a drag orbits
  tool.hover(ctx, at(px));
  const auto expected = plane.hit(camera, window_ray(camera, kRect, px));
  ASSERT_TRUE(expected);
  EXPECT_EQ(tool.preview(ctx).target, expected);
  tool.click(ctx, at(px));
  ASSERT_EQ(net().vertices.size(), 1u);
  EXPECT_EQ(net().vertices[0], *expected);
  EXPECT_NEAR(expected->x, 0.25, 1e-12);
  EXPECT_NEAR(expected->y, -0.5, 1e-12);
  EXPECT_EQ(expected->z, 0);
  EXPECT_EQ(selection.items(),
            std::vector<SelectionItem>{SelectionItem::of_point(PointRef::vertex(0))});
  EXPECT_EQ(said.back(), "add vertex 0");
  // Shift keeps the selection; the plane may be moved and turned (XZ through y = 2).
  plane.kind = WorkPlaneKind::XZ;
  plane.origin = Vec3(0, 2, 0);
  camera = preset_camera(ViewPreset::Front, Box{Vec3(-1), Vec3(1)}, kRect.aspect(), true);
  tool.click(ctx, at(pixel_of(Vec3(0.5, 2, 0.75)), {}, true));
  ASSERT_EQ(net().vertices.size(), 2u);
  EXPECT_NEAR(glm::length(net().vertices[1] - Vec3(0.5, 2, 0.75)), 0, 1e-12);
  EXPECT_EQ(net().vertices[1].y, 2);
  EXPECT_EQ(selection.size(), 2u);
  // Typed coordinates; a non-finite one is refused and changes nothing.
  EXPECT_EQ(tool.add_at(ctx, Vec3(3, 4, 5)), 2);
  EXPECT_EQ(net().vertices[2], Vec3(3, 4, 5));
  EXPECT_EQ(tool.add_at(ctx, Vec3(NAN, 0, 0)), -1);
  EXPECT_EQ(net().vertices.size(), 3u);
  EXPECT_EQ(undo_steps(), 3);
}

TEST_F(AuthoringTools, AddVertexOnAVertexTakesItShiftAddsItToTheChain) {
  AddVertexTool tool;
  add_five(tool);
  ASSERT_EQ(net().vertices.size(), 5u);
  const std::vector<Vec3> before = net().vertices;
  const int steps = undo_steps();
  // The hover over vertex 2 marks the vertex itself, not the plane point beside it.
  const Vec2 beside = pixel_of(before[2]) + Vec2(3, -2);
  tool.hover(ctx, at(beside, vertex(2)));
  EXPECT_EQ(tool.preview(ctx).target, before[2]);
  // Shift: added to the selection (a chain of vertices for a face), no vertex made.
  tool.click(ctx, at(beside, vertex(2), true));
  EXPECT_EQ(net().vertices, before);
  EXPECT_EQ(selection.items(),
            (std::vector<SelectionItem>{SelectionItem::of_point(PointRef::vertex(4)),
                                        SelectionItem::of_point(PointRef::vertex(2))}));
  EXPECT_EQ(said.back(), "vertex 2 is already here: added it to the selection, no new vertex");
  // Without Shift: it becomes the selection.
  tool.click(ctx, at(beside, vertex(0)));
  EXPECT_EQ(selection.items(),
            std::vector<SelectionItem>{SelectionItem::of_point(PointRef::vertex(0))});
  EXPECT_EQ(said.back(), "vertex 0 is already here: selected it, no new vertex");
  EXPECT_EQ(undo_steps(), steps) << "no undo step";
}

TEST_F(AuthoringTools, AddVertexOnASurfaceTakesTheSurfacePoint) {
  doc =
      Document(load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/default.json"));
  LiveSurfaces live(doc.scene(), 16, std::nullopt, "default");
  camera = preset_camera(ViewPreset::Iso, live.draw().bounds(), kRect.aspect());
  ScenePicker picker;
  const std::vector<SelectionItem> items = surface_items(live.surfaces());
  const SurfaceMesh& m = live.draw().surfaces[1];
  const Vec2 px = pixel_of(m.positions[m.positions.size() / 2]);
  PickResult pick = picker.pick({live.draw().surfaces, items, live.draw().network_curves,
                                 &live.points(), live.draw().free_curves},
                                camera, kRect, px);
  ASSERT_TRUE(pick.surface);
  const Vec3 on_surface = pick.surface->position;
  AddVertexTool tool;
  tool.click(ctx, at(px, pick));
  EXPECT_EQ(net().vertices.back(), on_surface);
  // Not where the ray meets the work plane: the surface is above it.
  EXPECT_NE(on_surface.z, 0);
}

TEST_F(AuthoringTools, AddEdgeJoinsTwoClickedVerticesAndChainsOn) {
  AddVertexTool vertices;
  add_five(vertices);
  AddEdgeTool tool;
  tool.click(ctx, at(Vec2(0), vertex(0)));
  EXPECT_TRUE(tool.capturing());
  EXPECT_EQ(tool.from(), 0);
  const Vec2 cursor = pixel_of(Vec3(0.5, 0.5, 0));
  tool.hover(ctx, at(cursor));
  ToolPreview p = tool.preview(ctx);
  ASSERT_EQ(p.pending.size(), 1u);
  EXPECT_EQ(p.pending[0][0], net().vertices[0]);
  EXPECT_NEAR(glm::length(p.pending[0][1] - Vec3(0.5, 0.5, 0)), 0, 1e-12);
  // The rubber band snaps to a vertex under the cursor.
  tool.hover(ctx, at(cursor, vertex(2)));
  EXPECT_EQ(tool.preview(ctx).pending[0][1], net().vertices[2]);
  tool.click(ctx, at(Vec2(0), vertex(1)));
  tool.click(ctx, at(Vec2(0), vertex(2)));
  ASSERT_EQ(net().edges.size(), 2u);
  EXPECT_EQ(net().edges[0].v, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(net().edges[1].v, (std::array<int, 2>{1, 2}));
  // Handles at a third and two thirds of the chord (the plane of two edges holds them).
  EXPECT_NEAR(glm::length(net().edges[0].handles[0] - Vec3(1.0 / 3, 0, 0)), 0, 1e-12);
  EXPECT_EQ(tool.from(), 2);
  EXPECT_EQ(said.back(), "add edge 1 (vertices 1 and 2)");
  // An edge that exists is refused with a message; the chain stays at its vertex.
  tool.click(ctx, at(Vec2(0), vertex(1)));
  EXPECT_EQ(net().edges.size(), 2u);
  EXPECT_EQ(said.back().rfind("refused: ", 0), 0u) << said.back();
  EXPECT_EQ(tool.from(), 2);
  // A click on the chain's vertex or on empty space ends it.
  tool.click(ctx, at(Vec2(0), vertex(2)));
  EXPECT_FALSE(tool.capturing());
  tool.click(ctx, at(Vec2(0), vertex(3)));
  tool.click(ctx, at(Vec2(3, 25)));
  EXPECT_FALSE(tool.capturing());
  EXPECT_EQ(net().edges.size(), 2u);
  EXPECT_EQ(undo_steps(), 5 + 2);
}

TEST_F(AuthoringTools, MakeFaceFromClickedVerticesFacesTheViewer) {
  AddVertexTool vertices;
  add_five(vertices);
  MakeFaceTool tool;
  // Clockwise as seen from above: the face must still face the viewer (+z).
  for (int v : {0, 3, 2}) tool.click(ctx, at(Vec2(0), vertex(v)));
  tool.click(ctx, at(Vec2(0), vertex(3)));  // already in the chain: refused, nothing picked
  EXPECT_EQ(tool.vertices(), (std::vector<int>{0, 3, 2}));
  tool.hover(ctx, at(pixel_of(Vec3(1.2, -0.2, 0))));
  const ToolPreview p = tool.preview(ctx);
  EXPECT_EQ(p.picked.size(), 3u);
  EXPECT_EQ(p.pending.size(), 2u);  // to the cursor, and from it back to the first vertex
  tool.click(ctx, at(Vec2(0), vertex(1)));
  EXPECT_TRUE(tool.can_finish(ctx));
  tool.click(ctx, at(Vec2(0), vertex(0)));  // the first vertex again closes the chain
  ASSERT_EQ(net().faces.size(), 1u);
  EXPECT_EQ(net().edges.size(), 4u);  // every side was made with the face
  EXPECT_FALSE(tool.capturing());
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::face(0)});
  // Newell normal of the loop: towards the viewer.
  const std::vector<int>& loop = net().faces[0].loop;
  Vec3 normal(0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    normal += glm::cross(net().vertices[loop[i]], net().vertices[loop[(i + 1) % loop.size()]]);
  EXPECT_GT(glm::dot(normal, towards_viewer(camera)), 0);
  EXPECT_EQ(said.back(), "make face 0 (4 sides, 4 new edges)");
  EXPECT_EQ(undo_steps(), 5 + 1);  // edges and face: one step
}

TEST_F(AuthoringTools, MakeFaceFromEdgesEnterFinishesRefusalsKeepThePicks) {
  AddVertexTool vertices;
  add_five(vertices);
  AddEdgeTool edges;
  for (int v : {0, 1, 2, 3, 0}) edges.click(ctx, at(Vec2(0), vertex(v)));
  edges.click(ctx, at(Vec2(3, 25)));  // ends the chain
  for (int v : {3, 4, 0}) edges.click(ctx, at(Vec2(0), vertex(v)));
  ASSERT_EQ(net().edges.size(), 6u);  // square 0-3, then 3-4, 4-0
  MakeFaceTool tool;
  // Edges of the square but one, then a wrong one: not closed, refused, nothing changes.
  for (int e : {0, 1, 2, 4}) tool.click(ctx, at(Vec2(0), edge(e)));
  const std::string before = scene_to_json(doc.scene());
  ASSERT_TRUE(tool.can_finish(ctx));
  tool.finish(ctx);
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  EXPECT_EQ(said.back().rfind("refused: ", 0), 0u) << said.back();
  EXPECT_EQ(tool.edges().size(), 4u);
  EXPECT_EQ(tool.preview(ctx).lines.size(), 4u);  // the picked curves are drawn
  // A vertex click while picking edges is refused; a click on a picked edge unpicks it.
  tool.click(ctx, at(Vec2(0), vertex(2)));
  EXPECT_TRUE(tool.vertices().empty());
  tool.click(ctx, at(Vec2(0), edge(4)));
  tool.click(ctx, at(Vec2(0), edge(3)));
  tool.finish(ctx);
  ASSERT_EQ(net().faces.size(), 1u);
  // The triangle 0-3-4 next to it runs opposite on the shared edge 3 (0-3), whatever the view.
  camera = preset_camera(ViewPreset::Front, Box{Vec3(-1), Vec3(1)}, kRect.aspect(), true);
  for (int e : {3, 4, 5}) tool.click(ctx, at(Vec2(0), edge(e)));
  tool.finish(ctx);
  ASSERT_EQ(net().faces.size(), 2u);
  const NetworkTopology topo = validate_network(net(), "test");
  EXPECT_EQ(topo.edge_faces[3].size(), 2u);
  // Esc drops a chain.
  tool.click(ctx, at(Vec2(0), edge(0)));
  tool.cancel(ctx);
  EXPECT_FALSE(tool.capturing());
}

TEST_F(AuthoringTools, ANormalSeenEndOnLeavesItsVertexToThePointUnderTheCursor) {
  AddVertexTool vertices;
  add_five(vertices);
  MakeFaceTool face;
  for (int v : {0, 1, 2, 3, 0}) face.click(ctx, at(Vec2(0), vertex(v)));
  ASSERT_EQ(net().faces.size(), 1u);
  selection.set({SelectionItem::of_point(PointRef::vertex(2))});
  // Seen from the top, the flat face's normal points at the viewer: the knob sits on the vertex.
  const std::vector<PlaneHandle> h = plane_handles(doc.scene(), selection, camera, kRect, 1);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_NEAR(glm::dot(h[0].normal, Vec3(0, 0, 1)), 1, 1e-15);
  const Vec2 v2 = pixel_of(net().vertices[2]);
  EXPECT_LT(glm::length(pixel_of(h[0].knob) - v2), 1e-6);
  SelectTool tool;
  // The press on the vertex itself (the picker found it there) drags the vertex.
  ASSERT_TRUE(tool.press(ctx, at(v2, vertex(2))));
  EXPECT_EQ(doc.drag_points(), std::vector<PointRef>{PointRef::vertex(2)});
  tool.release(ctx, at(v2, vertex(2)));
  // Off the point but on the knob: the knob turns the plane.
  ASSERT_TRUE(tool.press(ctx, at(v2 + Vec2(4, 4))));
  EXPECT_FALSE(doc.dragging());
  tool.drag(ctx, at(v2 + Vec2(40, 4)));
  tool.release(ctx, at(v2 + Vec2(40, 4)));
  ASSERT_TRUE(net().normals.size() == 5 && net().normals[2]);
  EXPECT_GT(net().normals[2]->x, 0.3);  // tilted towards the drag (+x on screen is +x here)
}

struct AuthoringOnDefault : AuthoringTools {
  AuthoringOnDefault() {
    doc = Document(
        load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/default.json"));
    selection.adopt(doc.scene());
  }
};

TEST_F(AuthoringOnDefault, SplitEdgeClickSplitsAtThePickedParameterAndSaysWhatTheFaceBecame) {
  SplitEdgeTool tool;
  const BezierCurve before = net().edge_curve(0);
  tool.hover(ctx, at(Vec2(0), edge(0, 0.4)));
  EXPECT_NEAR(glm::length(*tool.preview(ctx).target - before.evaluate(0.4).p), 0, 1e-15);
  // Too near an end: refused.
  tool.click(ctx, at(Vec2(0), edge(0, 0.01)));
  EXPECT_EQ(net().edges.size(), 8u);
  tool.click(ctx, at(Vec2(0), edge(0, 0.4)));
  ASSERT_EQ(net().vertices.size(), 8u);
  EXPECT_NEAR(glm::length(net().vertices[7] - before.evaluate(0.4).p), 0, 1e-14);
  EXPECT_EQ(net().faces[0].loop.size(), 5u);
  EXPECT_NE(said.back().find("face 0 now has 5 sides (GB)"), std::string::npos) << said.back();
  EXPECT_EQ(selection.items(),
            std::vector<SelectionItem>{SelectionItem::of_point(PointRef::vertex(7))});
  // The split renumbered nothing the selection held: following the document keeps it.
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Kept);
  // Undone, edge 0 runs to vertex 1 again: indices may name other objects, the selection goes.
  doc.undo();
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Cleared);
  EXPECT_TRUE(selection.empty());
}

TEST_F(AuthoringOnDefault, SelectionFollowsMovesAppendsAndClearsOnRenumbering) {
  selection.set({SelectionItem::face(1), SelectionItem::of_point(PointRef::vertex(6))});
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::vertex(6)},
                                                  std::vector{Vec3(0.1, 0.2, 0.3)}));
  const uint64_t structure = selection.structure_serial();
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Kept);
  EXPECT_EQ(selection.structure_serial(), structure);        // a move changes no structure
  doc.execute(std::make_unique<AddVertexCommand>(Vec3(5)));  // appended: indices stay
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Kept);
  EXPECT_GT(selection.structure_serial(), structure);  // but what lay under the cursor may not
  selection.add(SelectionItem::of_point(PointRef::vertex(7)));
  doc.undo();  // the new vertex goes from the end: dropped, the rest stays
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Pruned);
  EXPECT_EQ(selection.size(), 2u);
  doc.execute(delete_face_command(0));  // done behind the selection's back: renumbered
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Cleared);
  EXPECT_TRUE(selection.empty());
}

TEST(EditorSelectionRemap, ADeletionDropsWhatWentAndRenumbersTheRest) {
  Selection s;
  s.set({SelectionItem::of_point(PointRef::vertex(5)), SelectionItem::edge(7),
         SelectionItem::face(1), SelectionItem::of_point(PointRef::handle(6, 0)),
         SelectionItem::of_point(PointRef::vertex(2)), SelectionItem::edge(2),
         SelectionItem::of_point(PointRef::patch_point(0, 3))});
  Removed r;
  r.vertices = {2};
  r.edges = {1, 2, 6};
  r.faces = {0};
  s.remap(r);
  EXPECT_EQ(s.items(),
            (std::vector<SelectionItem>{SelectionItem::of_point(PointRef::vertex(4)),
                                        SelectionItem::edge(4), SelectionItem::face(0),
                                        SelectionItem::of_point(PointRef::patch_point(0, 3))}));
}

// The authoring actions, as the editor registers them, on the default scene.
struct AuthoringActions : AuthoringOnDefault {
  ActionRegistry actions;
  std::optional<double> right_clicked;
  AuthoringActions() {
    AuthoringHooks hooks;
    hooks.say = [this](const std::string& m) { said.push_back(m); };
    hooks.towards = [] { return Vec3(0, 0, 1); };
    hooks.split_parameter = [this](int) { return right_clicked; };
    add_selection_actions(actions, doc, selection, hooks.say);
    add_authoring_actions(actions, doc, selection, hooks);
  }
};

TEST_F(AuthoringActions, DeleteRemovesWhatDependsAndRemapsTheSelection) {
  EXPECT_TRUE(actions.conflicts().empty());
  EXPECT_FALSE(actions.run("edit.delete"));  // nothing selected: disabled
  const Action* del = actions.bound_to(*parse_chord("Del"));
  ASSERT_TRUE(del);
  EXPECT_EQ(del->id, "edit.delete");
  EXPECT_EQ(actions.bound_to(*parse_chord("Backspace")), del);
  const std::string before = scene_to_json(doc.scene());
  // Vertices take their edges and those edges' faces with them.
  selection.set({SelectionItem::of_point(PointRef::vertex(5)),
                 SelectionItem::of_point(PointRef::vertex(6)), SelectionItem::edge(7)});
  ASSERT_TRUE(actions.trigger(*parse_chord("Del")));
  EXPECT_EQ(net().vertices.size(), 5u);
  EXPECT_EQ(net().edges.size(), 5u);
  EXPECT_EQ(net().faces.size(), 1u);
  EXPECT_TRUE(selection.empty());
  EXPECT_EQ(said.back(), "delete vertices 5 and 6, edges 5, 6 and 7, face 1") << said.back();
  doc.undo();
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  // What survives is renumbered: vertex 0 takes edges 0 and 3 and face 0, so edge 7's handle
  // is edge 5's now, and the selection says so (and knows the new numbering).
  selection.adopt(doc.scene());
  selection.set({SelectionItem::of_point(PointRef::vertex(0)),
                 SelectionItem::of_point(PointRef::handle(7, 1))});
  ASSERT_TRUE(actions.run("edit.delete"));
  EXPECT_EQ(selection.items(),
            std::vector<SelectionItem>{SelectionItem::of_point(PointRef::handle(5, 1))});
  EXPECT_EQ(net().edges[5].v, (std::array<int, 2>{5, 1}));  // old edge 7: 6 -> 2, renumbered
  EXPECT_EQ(selection.follow(doc.scene()), Selection::Followed::Kept);
}

TEST_F(AuthoringActions, AddEdgeMakeFaceAndFillHolesFromTheSelection) {
  // Two new vertices off the pentagon's edge 5-6, joined into a triangle with vertex 5 by hand.
  doc.execute(std::make_unique<AddVertexCommand>(Vec3(0.5, 2.6, 0)));
  selection.set(
      {SelectionItem::of_point(PointRef::vertex(5)), SelectionItem::of_point(PointRef::vertex(7))});
  ASSERT_TRUE(actions.trigger(*parse_chord("Shift+E")));
  EXPECT_EQ(net().edges.back().v, (std::array<int, 2>{5, 7}));
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::edge(8)});
  selection.set(
      {SelectionItem::of_point(PointRef::vertex(6)), SelectionItem::of_point(PointRef::vertex(7))});
  ASSERT_TRUE(actions.run("network.add_edge"));
  // Fill holes fills every boundary loop (the triangle 5-7-6 among them) as the command does,
  // and selects the new faces.
  Scene expected = doc.scene();
  FillHolesCommand().apply(expected);
  ASSERT_TRUE(actions.run("network.fill_holes"));
  EXPECT_EQ(net(), *expected.network);
  ASSERT_GT(net().faces.size(), 2u);
  EXPECT_EQ(selection.size(), net().faces.size() - 2);
  EXPECT_EQ(selection.items().front(), SelectionItem::face(2));
  EXPECT_EQ(validate_network(net(), "test").edge_faces[6].size(), 2u);  // 5-6 now shared
  // Make Face wants 3 vertices or 3 edges.
  selection.set(
      {SelectionItem::of_point(PointRef::vertex(0)), SelectionItem::of_point(PointRef::vertex(1))});
  EXPECT_FALSE(actions.run("network.make_face"));
}

TEST_F(AuthoringActions, SplitTheSelectedEdgeWhereRightClickedElseInTheMiddle) {
  selection.set({SelectionItem::edge(3)});
  right_clicked = 0.25;
  const BezierCurve c = net().edge_curve(3);
  ASSERT_TRUE(actions.run("network.split_edge"));
  EXPECT_NEAR(glm::length(net().vertices.back() - c.evaluate(0.25).p), 0, 1e-14);
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::of_point(
                                   PointRef::vertex(int(net().vertices.size()) - 1))});
  selection.set({SelectionItem::edge(2)});
  right_clicked.reset();
  const BezierCurve c2 = net().edge_curve(2);
  ASSERT_TRUE(actions.run("network.split_edge"));
  EXPECT_NEAR(glm::length(net().vertices.back() - c2.evaluate(0.5).p), 0, 1e-14) << said.back();
  EXPECT_EQ(net().faces[0].loop.size(), 6u);  // the quad gained two sides
  // Not offered on anything but one edge.
  selection.set({SelectionItem::edge(2), SelectionItem::edge(1)});
  EXPECT_FALSE(actions.run("network.split_edge"));
}

TEST_F(AuthoringActions, MakeFaceOnSelectedVerticesMakesTheMissingEdges) {
  const std::string before = scene_to_json(doc.scene());
  doc.execute(std::make_unique<AddVertexCommand>(Vec3(-1, 0.5, 0)));
  selection.set({SelectionItem::of_point(PointRef::vertex(0)),
                 SelectionItem::of_point(PointRef::vertex(3)),
                 SelectionItem::of_point(PointRef::vertex(7))});
  ASSERT_TRUE(actions.trigger(*parse_chord("Shift+M")));
  ASSERT_EQ(net().faces.size(), 3u);
  EXPECT_EQ(net().edges.size(), 10u);
  EXPECT_EQ(selection.items(), std::vector<SelectionItem>{SelectionItem::face(2)});
  // A face through vertices 1 and 2 would be a third face on edge 1: refused, nothing changes.
  selection.set({SelectionItem::of_point(PointRef::vertex(1)),
                 SelectionItem::of_point(PointRef::vertex(2)),
                 SelectionItem::of_point(PointRef::vertex(7))});
  const std::string made = scene_to_json(doc.scene());
  EXPECT_TRUE(actions.run("network.make_face"));  // ran, and was refused
  EXPECT_EQ(scene_to_json(doc.scene()), made);
  EXPECT_EQ(said.back().rfind("refused: ", 0), 0u) << said.back();
  doc.undo();
  doc.undo();
  EXPECT_EQ(scene_to_json(doc.scene()), before);
}

TEST_F(AuthoringActions, TangentPlanesFixedAndFittedAgainAsOneStep) {
  selection.set(
      {SelectionItem::of_point(PointRef::vertex(1)), SelectionItem::of_point(PointRef::vertex(2))});
  EXPECT_TRUE(actions.find("network.plane_fitted")->checked());
  EXPECT_FALSE(actions.run("network.plane_fitted"));  // already fitted
  const Network fitted = net();
  ASSERT_TRUE(actions.run("network.plane_fixed"));
  EXPECT_TRUE(actions.find("network.plane_fixed")->checked());
  for (int v : {1, 2}) {
    ASSERT_TRUE(net().normals[v]);
    // The plane it was fitted to, now stored: the handles did not move beyond rounding.
    EXPECT_GT(std::abs(glm::dot(*net().normals[v], vertex_plane(fitted, v)->normal)), 1 - 1e-15);
    for (int e : edges_at(net(), v))
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(glm::length(net().edges[e].handles[k] - fitted.edges[e].handles[k]), 0, 1e-14);
  }
  ASSERT_TRUE(actions.run("network.plane_fitted"));
  EXPECT_FALSE(net().normals[1] || net().normals[2]);
  doc.undo();
  doc.undo();
  EXPECT_EQ(net(), fitted);
}

}  // namespace
}  // namespace pl
