// The editor's side of interior control, without a window: a GB face's free points are listed
// as editable points of their own kind at default + offset, follow a drag of their own or of the
// network incrementally (one face re-evaluated, the list equal to a fresh one), and the interior
// actions (raise, lower, reset) act on the selected face or free point and refuse Gregory faces.
#include <gtest/gtest.h>

#include "app/document/interior_commands.hpp"
#include "app/document/network_commands.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/interior_actions.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/net_thinning.hpp"
#include "command_test_util.hpp"
#include "core/network/gb_face_free_points.hpp"

namespace pl::test {
namespace {

Scene asset(const std::string& name) {
  return read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / name);
}

// The free points the list holds for face f, by name.
std::vector<std::pair<PointRef, Vec3>> listed(const ScenePoints& pts, int f) {
  std::vector<std::pair<PointRef, Vec3>> out;
  for (std::size_t i = 0; i < pts.positions.size(); ++i)
    if (pts.refs[i] && pts.refs[i]->kind == PointRef::Kind::FreePoint && pts.refs[i]->object == f) {
      EXPECT_EQ(pts.kinds[i], ControlPointKind::FreeInterior);
      out.emplace_back(*pts.refs[i], pts.positions[i]);
    }
  return out;
}

void expect_points_as_fresh(const LiveSurfaces& live, const Scene& scene) {
  const LiveSurfaces fresh(scene, live.density(), live.scheme(), "fresh");
  EXPECT_EQ(live.points().refs, fresh.points().refs);
  EXPECT_EQ(live.points().kinds, fresh.points().kinds);
  ASSERT_EQ(live.points().positions.size(), fresh.points().positions.size());
  for (std::size_t i = 0; i < live.points().positions.size(); ++i)
    EXPECT_LT(glm::length(live.points().positions[i] - fresh.points().positions[i]), 1e-12) << i;
}

TEST(EditorInterior, FreePointsAreListedEditableAtDefaultPlusOffset) {
  const Scene s = asset("gb-interior.json");
  const LiveSurfaces live(s, 6, std::nullopt, "test");
  const ScenePoints& pts = live.points();
  // Pentagon (degree 5): the centre and one point per side; hexagon (degree 3): the centre;
  // Gregory quads and triangles: none.
  const auto pentagon = listed(pts, 0);
  ASSERT_EQ(pentagon.size(), 6u);
  EXPECT_EQ(listed(pts, 1).size(), 1u);
  for (int f = 2; f < 6; ++f) EXPECT_TRUE(listed(pts, f).empty()) << f;
  for (const auto& [ref, p] : pentagon) {
    EXPECT_LT(glm::length(p - point_position(s, ref)), 1e-12) << describe(ref);
    EXPECT_GE(pts.find(ref), 0);
  }
  // Drawn as editable (filled) points of their own kind.
  ControlNet net;
  make_control_net(pts, false, net);
  int free_editable = 0;
  for (std::size_t i = 0; i < net.points.size(); ++i)
    free_editable +=
        net.kinds[i] == ControlPointKind::FreeInterior && net.role(i) == PointRole::Editable;
  EXPECT_EQ(free_editable, 7);
  // In the comparison's Gregory panel a quad set to GB shows no free points (it is Gregory there).
  Scene gb_quad = s;
  gb_quad.network->faces[2].scheme = FaceScheme::GB;
  EXPECT_EQ(listed(LiveSurfaces(gb_quad, 6, std::nullopt, "test").points(), 2).size(), 1u);
  EXPECT_TRUE(listed(LiveSurfaces(gb_quad, 6, FaceScheme::Gregory, "test").points(), 2).empty());
}

TEST(EditorInterior, AFreePointDragReevaluatesItsFaceOnly) {
  Document doc(asset("gb-interior.json"));
  LiveSurfaces live(doc.scene(), 6, std::nullopt, "test", doc.revision());
  const PointRef p = PointRef::free_point(0, {.side = 1, .j = 2, .layer = 2});
  const Vec3 p0 = point_position(doc.scene(), p);
  doc.begin_drag({p});
  for (int i = 1; i <= 3; ++i) {
    doc.drag_to({p0 + Vec3(0, 0, 0.02 * i)});
    const std::vector<int> changed = live.sync(doc.scene(), doc.revision());
    EXPECT_EQ(changed, std::vector<int>{0});
    const int k = live.points().find(p);
    ASSERT_GE(k, 0);
    EXPECT_LT(glm::length(live.points().positions[k] - (p0 + Vec3(0, 0, 0.02 * i))), 1e-12);
  }
  doc.end_drag();
  expect_points_as_fresh(live, doc.scene());
  // The engine follows the face point by point: one control point moved, nothing rebuilt.
  SceneEvaluation engine(doc.scene(), 6, std::nullopt);
  doc.begin_drag({p});
  doc.drag_to({point_position(doc.scene(), p) + Vec3(0.01, 0, 0)});
  const SyncStats stats = engine.sync(doc.scene());
  EXPECT_EQ(stats.changed_surfaces, std::vector<int>{0});
  EXPECT_EQ(stats.rebuilt_surfaces, 0u);
  EXPECT_EQ(stats.moved_points, 1u);
  doc.cancel_drag();
  // The network moves: the free points follow their new defaults, offsets kept.
  const int v = doc.scene().network->faces[0].loop[1];
  doc.begin_drag({PointRef::vertex(v)});
  doc.drag_to({doc.scene().network->vertices[v] + Vec3(0.03, 0.01, 0.02)});
  live.sync(doc.scene(), doc.revision());
  doc.end_drag();
  expect_points_as_fresh(live, doc.scene());
  for (const auto& [ref, at] : listed(live.points(), 0))
    EXPECT_LT(glm::length(at - point_position(doc.scene(), ref)), 1e-12) << describe(ref);
  // A degree change lists the face's points anew.
  doc.execute(std::make_unique<SetFaceDegreeCommand>(0, 6));
  live.sync(doc.scene(), doc.revision());
  EXPECT_EQ(listed(live.points(), 0).size(), 11u);
  expect_points_as_fresh(live, doc.scene());
}

TEST(EditorInterior, ActionsActOnTheSelectedFaceOrFreePoint) {
  Document doc(asset("default.json"));  // face 0 a Gregory quad, face 1 a GB pentagon
  Selection selection;
  ActionRegistry r;
  std::string said;
  add_interior_actions(r, doc, selection, [&](const std::string& m) { said = m; });
  EXPECT_TRUE(r.conflicts().empty());
  const Action* raise = r.find("face.degree.raise");
  const Action* lower = r.find("face.degree.lower");
  const Action* reset = r.find("face.interior.reset");
  ASSERT_TRUE(raise && lower && reset);
  EXPECT_FALSE(r.is_enabled(*raise));  // nothing selected
  selection.set({SelectionItem::face(0)});
  EXPECT_FALSE(r.is_enabled(*raise));
  const auto gregory = interior_summary(doc.scene(), 0);
  ASSERT_TRUE(gregory);
  EXPECT_FALSE(gregory->has_interior);
  EXPECT_NE(gregory->why_not.find("Gregory faces have no free interior"), std::string::npos);
  selection.set({SelectionItem::face(1)});
  EXPECT_TRUE(r.is_enabled(*raise));
  EXPECT_FALSE(r.is_enabled(*lower));  // degree 3
  EXPECT_FALSE(r.is_enabled(*reset));  // nothing moved
  EXPECT_TRUE(r.run("face.degree.raise"));
  EXPECT_TRUE(r.run("face.degree.raise"));
  EXPECT_EQ(said, "face 1 degree 5");
  auto s = interior_summary(doc.scene(), 1);
  EXPECT_EQ(s->degree, 5);
  EXPECT_EQ(s->free_points, 6);
  EXPECT_EQ(s->moved, 0);
  // With a free point selected the actions act on its face.
  const PointRef c = PointRef::free_point(1, {.centre = true});
  doc.execute(std::make_unique<MovePointsCommand>(
      std::vector{c}, std::vector{point_position(doc.scene(), c) + Vec3(0, 0, 0.1)}));
  selection.set({SelectionItem::of_point(c)});
  EXPECT_EQ(interior_face(doc.scene(), selection), 1);
  EXPECT_EQ(interior_summary(doc.scene(), 1)->moved, 1);
  EXPECT_TRUE(r.is_enabled(*reset));
  EXPECT_TRUE(r.is_enabled(*lower));
  EXPECT_TRUE(r.run("face.interior.reset"));
  EXPECT_EQ(said, "reset the interior of face 1");
  EXPECT_TRUE(doc.scene().network->faces[1].offsets.empty());
  // Offered on a right-click on a face or a point.
  int offered = 0;
  for (const Action* a : r.for_context(ContextTarget::Face)) offered += a->menu == "Face";
  EXPECT_EQ(offered, 3);
}

TEST(EditorInterior, TheComparisonsDistanceFollowsAnInteriorEdit) {
  // The quad of the default scene filled GB at degree 4: Gregory on the left, GB on the right.
  Document doc(asset("default.json"));
  doc.execute(std::make_unique<SetFaceSchemeCommand>(0, FaceScheme::GB));
  doc.execute(std::make_unique<SetFaceDegreeCommand>(0, 4));
  LiveSurfaces gregory(doc.scene(), 12, FaceScheme::Gregory, "g", doc.revision());
  LiveSurfaces gb(doc.scene(), 12, FaceScheme::GB, "b", doc.revision());
  DifferenceField field;
  EXPECT_TRUE(field.follow(gregory.draw(), gb.draw(), doc.revision()));
  const double before = field.max_abs();
  EXPECT_LT(before, 0.1);  // two fillings of one boundary
  // Its centre raised by 0.2: the GB surface moves by 0.2 phi_0, phi_0 = 1 at the domain's
  // centre; a distance moves by at most the displacement (it is 1-Lipschitz).
  const PointRef c = PointRef::free_point(0, {.centre = true});
  doc.begin_drag({c});
  doc.drag_to({point_position(doc.scene(), c) + Vec3(0, 0, 0.2)});
  EXPECT_TRUE(gregory.sync(doc.scene(), doc.revision()).empty());  // Gregory has no interior
  EXPECT_EQ(gb.sync(doc.scene(), doc.revision()), std::vector<int>{0});
  EXPECT_TRUE(field.follow(gregory.draw(), gb.draw(), doc.revision()));
  const double raised = field.max_abs();
  EXPECT_GT(raised, before + 0.1);
  EXPECT_LE(raised, before + 0.2 + 1e-9);
  EXPECT_EQ(field.range(), raised);  // the legend's symmetric range
  doc.end_drag();
  doc.undo();
  gregory.sync(doc.scene(), doc.revision());
  gb.sync(doc.scene(), doc.revision());
  EXPECT_TRUE(field.follow(gregory.draw(), gb.draw(), doc.revision()));
  EXPECT_NEAR(field.max_abs(), before, 1e-12);
}

TEST(EditorInterior, FreePointsAreThinnedWithTheirFaceAndShownWhenFocused) {
  const Scene s = asset("gb-interior.json");
  const LiveSurfaces live(s, 6, std::nullopt, "test");
  const ScenePoints& pts = live.points();
  // Every surface a few pixels wide: the faces' nets are hidden, free points with them.
  NetScreenSizes tiny;
  tiny.edge_pixels.assign(s.network->edges.size(), 4.0);
  tiny.surface_pixels.assign(live.surfaces().surfaces.size(), 8.0);
  const NetThinning hidden = thin_control_net(pts, live.surfaces(), &*s.network, tiny, {}, 8);
  EXPECT_EQ(hidden.hidden_free, 7u);  // the pentagon's six and the hexagon's centre
  EXPECT_NE(hidden.note().find("7 free points"), std::string::npos) << hidden.note();
  // A selected free point keeps its face's net, free points included.
  const PointRef c = PointRef::free_point(0, {.centre = true});
  const NetThinning focused =
      thin_control_net(pts, live.surfaces(), &*s.network, tiny, net_focus({c}, {}, {}, {}), 8);
  EXPECT_EQ(focused.hidden_free, 1u);  // the hexagon's
  for (const auto& [ref, at] : listed(pts, 0)) EXPECT_FALSE(focused.hidden[pts.find(ref)]);
}

}  // namespace
}  // namespace pl::test
