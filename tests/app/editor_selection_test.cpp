// The selection, the properties the selection panel shows, and the actions on the selection
// (run through the registry the menus and keys use).
#include <gtest/gtest.h>

#include <cmath>

#include "app/cli/load_input.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/selection_actions.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

using Kind = SelectionItem::Kind;

Scene default_scene() {
  return load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json");
}

TEST(EditorSelection, ClickReplacesAddsAndToggles) {
  Selection s;
  const auto a = SelectionItem::face(1), b = SelectionItem::edge(3),
             c = SelectionItem::of_point(PointRef::vertex(2));
  uint64_t serial = s.serial();
  s.click(a, SelectMode::Replace);
  EXPECT_EQ(s.items(), std::vector<SelectionItem>{a});
  EXPECT_GT(s.serial(), serial);
  s.click(b, SelectMode::Add);
  s.click(c, SelectMode::Add);
  EXPECT_EQ(s.items(), (std::vector<SelectionItem>{a, b, c}));
  // Replace on a selected item keeps the selection (a press on one of several selected points
  // drags them all).
  serial = s.serial();
  s.click(b, SelectMode::Replace);
  EXPECT_EQ(s.size(), 3u);
  EXPECT_EQ(s.serial(), serial);
  s.click(b, SelectMode::Toggle);
  EXPECT_EQ(s.items(), (std::vector<SelectionItem>{a, c}));
  s.click(b, SelectMode::Toggle);
  EXPECT_TRUE(s.contains(b));
  EXPECT_EQ(s.points(), std::vector<PointRef>{PointRef::vertex(2)});
  EXPECT_EQ(s.of_kind(Kind::Face), std::vector<int>{1});
  EXPECT_TRUE(s.has(Kind::Edge));
  EXPECT_FALSE(s.has(Kind::Patch));
  s.set({a, a, c});  // duplicates dropped
  EXPECT_EQ(s.size(), 2u);
  s.clear();
  EXPECT_TRUE(s.empty());
}

TEST(EditorSelection, PruneDropsWhatTheSceneNoLongerHas) {
  Scene scene = default_scene();
  Selection s;
  s.set({SelectionItem::face(1), SelectionItem::edge(6),
         SelectionItem::of_point(PointRef::vertex(6)), SelectionItem::patch(0)});
  EXPECT_TRUE(s.prune(scene));  // no explicit patches in the default scene
  EXPECT_EQ(s.size(), 3u);
  EXPECT_FALSE(s.prune(scene));
  scene.network->faces.pop_back();
  EXPECT_TRUE(s.prune(scene));
  EXPECT_EQ(s.items(), (std::vector<SelectionItem>{SelectionItem::edge(6),
                                                   SelectionItem::of_point(PointRef::vertex(6))}));
}

TEST(EditorSelection, DeletedCurvesAreDroppedAndTheLaterOnesRenumbered) {
  Selection s;
  s.set({SelectionItem::curve(0), SelectionItem::of_point(PointRef::curve_point(1, 4)),
         SelectionItem::curve(3), SelectionItem::of_point(PointRef::curve_point(4, 0)),
         SelectionItem::face(1), SelectionItem::of_point(PointRef::vertex(3))});
  const uint64_t serial = s.serial();
  s.remap_curves({1, 2});  // curves 1 and 2 deleted: 3 and 4 become 1 and 2
  EXPECT_EQ(s.items(), (std::vector<SelectionItem>{
                           SelectionItem::curve(0), SelectionItem::curve(1),
                           SelectionItem::of_point(PointRef::curve_point(2, 0)),
                           SelectionItem::face(1), SelectionItem::of_point(PointRef::vertex(3))}));
  EXPECT_GT(s.serial(), serial);
}

TEST(EditorSelection, NamesRoundTrip) {
  for (const SelectionItem& i :
       {SelectionItem::face(4), SelectionItem::edge(0), SelectionItem::patch(2),
        SelectionItem::of_point(PointRef::vertex(3)),
        SelectionItem::of_point(PointRef::handle(5, 1)),
        SelectionItem::of_point(PointRef::patch_point(0, 7))}) {
    const auto back = parse_item_name(describe(i));
    ASSERT_TRUE(back) << describe(i);
    EXPECT_EQ(*back, i);
  }
  EXPECT_FALSE(parse_item_name("face"));
  EXPECT_FALSE(parse_item_name("face -1"));
  EXPECT_FALSE(parse_item_name("face 1 2"));
  EXPECT_FALSE(parse_item_name("cell 1"));
  Selection s;
  s.set({SelectionItem::face(1), SelectionItem::edge(2)});
  EXPECT_EQ(describe(s), "face 1, edge 2");
  EXPECT_EQ(describe(s, 1), "face 1, ... (2 items)");
}

TEST(EditorSelectionProperties, FaceEdgeVertex) {
  Scene scene = default_scene();
  const Network& net = *scene.network;
  const auto quad = face_properties(scene, 0), penta = face_properties(scene, 1);
  ASSERT_TRUE(quad && penta);
  EXPECT_EQ(quad->sides, 4);
  EXPECT_EQ(quad->resolved, FaceScheme::Gregory);
  EXPECT_TRUE(quad->gregory_allowed);
  EXPECT_EQ(penta->sides, 5);
  EXPECT_EQ(penta->resolved, FaceScheme::GB);
  EXPECT_FALSE(penta->gregory_allowed);
  EXPECT_FALSE(face_properties(scene, 2));

  // The shared edge has both faces; its length matches a fine polyline (the chord sum of 2^16
  // segments converges to the arc length like h^2, far below the tolerance used).
  int shared = -1;
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    if (edge_properties(scene, int(e))->faces.size() == 2) shared = int(e);
  ASSERT_GE(shared, 0);
  const auto ep = edge_properties(scene, shared);
  EXPECT_EQ(ep->faces, (std::vector<int>{0, 1}));
  const BezierCurve curve = net.edge_curve(shared);
  double polyline = 0;
  const int n = 1 << 16;
  for (int i = 0; i < n; ++i)
    polyline += glm::length(curve.point(double(i + 1) / n) - curve.point(double(i) / n));
  EXPECT_NEAR(ep->length, polyline, 1e-8 * polyline);
  EXPECT_GE(ep->length, polyline);  // a chord is never longer than its arc
  // A straight edge with evenly spaced handles: exactly its chord.
  const BezierCurve straight({Vec3(0), Vec3(1, 2, 2), Vec3(2, 4, 4), Vec3(3, 6, 6)});
  EXPECT_NEAR(curve_length(straight), 9.0, 1e-13);

  // Vertex tangent planes: fitted until a normal is stored.
  auto vp = vertex_properties(scene, 2);
  ASSERT_TRUE(vp);
  EXPECT_FALSE(vp->tangent_plane_fixed);
  EXPECT_EQ(vp->edges, 3);
  scene.network->normals.assign(net.vertices.size(), std::nullopt);
  scene.network->normals[2] = Vec3(0, 0, 1);
  vp = vertex_properties(scene, 2);
  EXPECT_TRUE(vp->tangent_plane_fixed);
  EXPECT_EQ(*vp->normal, Vec3(0, 0, 1));
  EXPECT_FALSE(vertex_properties(scene, 99));
}

TEST(EditorSelectionProperties, PointsAndBoundsOfTheSelection) {
  const Scene scene = default_scene();
  Selection s;
  s.set({SelectionItem::face(0)});
  const std::vector<PointRef> pts = points_of(scene, s);
  // A quad: 4 vertices and 2 handles on each of its 4 edges.
  EXPECT_EQ(pts.size(), 12u);
  int vertices = 0;
  for (const PointRef& p : pts) vertices += p.kind == PointRef::Kind::NetworkVertex;
  EXPECT_EQ(vertices, 4);
  const Box b = selection_bounds(scene, s);
  for (const PointRef& p : pts) {
    const Vec3 q = point_position(scene, p);
    EXPECT_TRUE(q.x >= b.lo.x && q.y >= b.lo.y && q.z >= b.lo.z && q.x <= b.hi.x && q.y <= b.hi.y &&
                q.z <= b.hi.z);
  }
  s.clear();
  EXPECT_TRUE(selection_bounds(scene, s).empty());
}

struct ActionFixture : ::testing::Test {
  Document doc{default_scene()};
  Selection selection;
  ActionRegistry actions;
  void SetUp() override { add_selection_actions(actions, doc, selection); }
};

TEST_F(ActionFixture, SchemeOfSelectedFacesIsOneUndoStepUndoneBitExactly) {
  const std::string before = scene_to_json(doc.scene());
  EXPECT_FALSE(actions.run("face.scheme.gb"));  // nothing selected: disabled
  selection.set({SelectionItem::face(0), SelectionItem::face(1)});
  EXPECT_FALSE(actions.is_enabled(*actions.find("face.scheme.gregory")));  // the pentagon
  EXPECT_FALSE(actions.find("face.scheme.gb")->checked());
  ASSERT_TRUE(actions.run("face.scheme.gb"));
  EXPECT_EQ(doc.scene().network->faces[0].scheme, FaceScheme::GB);
  EXPECT_EQ(doc.scene().network->faces[1].scheme, FaceScheme::GB);
  EXPECT_TRUE(actions.find("face.scheme.gb")->checked());
  // Again: nothing changes, no new step.
  EXPECT_TRUE(actions.run("face.scheme.gb"));
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.can_undo());
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  // The quad alone may be Gregory; the written scene says so and reads back.
  selection.set({SelectionItem::face(0)});
  ASSERT_TRUE(actions.run("face.scheme.gregory"));
  const Scene back = parse_scene(scene_to_json(doc.scene()), "saved");
  EXPECT_EQ(back.network->faces[0].scheme, FaceScheme::Gregory);
}

TEST_F(ActionFixture, SelectRelatedObjects) {
  selection.set({SelectionItem::face(1)});
  ASSERT_TRUE(actions.run("select.face_edges"));
  EXPECT_EQ(selection.size(), 5u);
  EXPECT_TRUE(selection.has(Kind::Edge));
  ASSERT_TRUE(actions.run("select.edge_faces"));
  // The pentagon's edges border the pentagon and, along the shared one, the quad.
  EXPECT_EQ(selection.size(), 2u);
  EXPECT_TRUE(selection.contains(SelectionItem::face(0)));
  EXPECT_TRUE(selection.contains(SelectionItem::face(1)));
  ASSERT_TRUE(actions.run("select.points_of"));
  EXPECT_EQ(selection.points().size(), selection.size());
  EXPECT_EQ(selection.size(), 7u + 2 * doc.scene().network->edges.size());
  ASSERT_TRUE(actions.trigger(*parse_chord("Ctrl+A")));
  EXPECT_EQ(selection.size(), doc.scene().network->vertices.size());
  EXPECT_FALSE(actions.run("select.face_edges"));  // no face selected now
  // The right-click menu on a face offers the scheme and the face's selections.
  std::vector<std::string> ids;
  for (const Action* a : actions.for_context(ContextTarget::Face)) ids.push_back(a->id);
  EXPECT_NE(std::find(ids.begin(), ids.end(), "face.scheme.gb"), ids.end());
  EXPECT_NE(std::find(ids.begin(), ids.end(), "select.face_edges"), ids.end());
  EXPECT_TRUE(actions.conflicts().empty());
}

}  // namespace
}  // namespace pl
