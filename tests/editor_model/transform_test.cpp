// The Selection panel's Transform rows as the model runs them: a typed rotation, scale or move
// of the selection about a pivot is one undo step with exactly the similarity's images, a face's
// moved interior point turns with the face, and what cannot be done is refused with a reason in
// the status line and nothing changed.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/document/command.hpp"
#include "app/editor/logic/transform_selection.hpp"
#include "model_driver.hpp"

namespace pl::test {

namespace {

namespace fs = std::filesystem;

DocumentSession default_scene_session() {
  DocumentSession session({fs::path(PATCHLAB_SOURCE_DIR) / "assets"});
  session.open(fs::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json");
  return session;
}

}  // namespace

TEST(Transform, TypedRotationAboutTheSelectionCentreIsOneUndoStep) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  const Network before = *m.doc().scene().network;
  m.selection().set(
      {SelectionItem::of_point(PointRef::vertex(0)), SelectionItem::of_point(PointRef::vertex(2))});
  const Vec3 centre = (before.vertices[0] + before.vertices[2]) / 2.0;
  TransformRequest r;
  r.kind = TransformKind::Rotate, r.axis = AxisKind::Z, r.angle_deg = 90;
  ASSERT_TRUE(transform_selection(m, r)) << m.status().message();
  d.settle();
  const Network& after = *m.doc().scene().network;
  for (int v : {0, 2}) {
    const Vec3 q = before.vertices[v] - centre;  // a quarter turn: (x, y) -> (-y, x)
    EXPECT_LT(glm::length(after.vertices[v] - (centre + Vec3(-q.y, q.x, q.z))), 1e-14);
  }
  for (int v : {1, 3, 4, 5, 6}) EXPECT_EQ(after.vertices[v], before.vertices[v]);
  EXPECT_EQ(m.doc().undo_label(), "rotate 2 points");
  d.key("Ctrl+Z");
  EXPECT_EQ(*m.doc().scene().network, before);
}

TEST(Transform, AFacesMovedCentreTurnsWithTheFace) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  int gb = -1;
  for (std::size_t f = 0; f < m.doc().scene().network->faces.size(); ++f)
    if (is_gb_face(m.doc().scene(), int(f))) gb = int(f);
  ASSERT_GE(gb, 0) << "the default scene has a GB face";
  const PointRef centre = PointRef::free_point(gb, InteriorOffset{.centre = true});
  const Vec3 raised = point_position(m.doc().scene(), centre) + Vec3(0, 0, 0.3);
  m.doc().execute(std::make_unique<MovePointsCommand>(std::vector{centre}, std::vector{raised}));
  m.selection().set({SelectionItem::face(gb)});
  TransformRequest r;
  r.kind = TransformKind::Rotate, r.pivot = PivotKind::Origin, r.axis = AxisKind::X;
  r.angle_deg = 30;
  ASSERT_TRUE(transform_selection(m, r)) << m.status().message();
  const Similarity t = Similarity::rotation_about(Vec3(0), Vec3(1, 0, 0), M_PI / 6);
  EXPECT_LT(glm::length(point_position(m.doc().scene(), centre) - t.point(raised)), 1e-12);
}

TEST(Transform, ScaleAboutAVertexAndMoveBy) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  const Network before = *m.doc().scene().network;
  m.selection().set(
      {SelectionItem::of_point(PointRef::vertex(1)), SelectionItem::of_point(PointRef::vertex(4))});
  TransformRequest r;
  r.kind = TransformKind::Scale, r.pivot = PivotKind::Vertex, r.pivot_vertex = 1;
  r.factor = 0.5;
  ASSERT_TRUE(transform_selection(m, r)) << m.status().message();
  const Network& scaled = *m.doc().scene().network;
  EXPECT_EQ(scaled.vertices[1], before.vertices[1]);  // the pivot stays
  const Vec3 half = before.vertices[1] + 0.5 * (before.vertices[4] - before.vertices[1]);
  EXPECT_LT(glm::length(scaled.vertices[4] - half), 1e-14);
  r.kind = TransformKind::Move, r.offset = Vec3(0.25, 0, -0.5);
  ASSERT_TRUE(transform_selection(m, r));
  EXPECT_LT(glm::length(m.doc().scene().network->vertices[4] - (half + r.offset)), 1e-14);
  EXPECT_EQ(m.doc().undo_label(), "move 2 points");
}

TEST(Transform, WhatCannotBeDoneIsRefusedWithAReason) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  TransformRequest r;
  r.kind = TransformKind::Rotate, r.angle_deg = 10;
  EXPECT_FALSE(transform_selection(m, r));
  EXPECT_NE(m.status().message().find("nothing selected"), std::string::npos)
      << m.status().message();
  m.selection().set({SelectionItem::of_point(PointRef::vertex(1))});
  r.kind = TransformKind::Scale, r.factor = 0;
  EXPECT_FALSE(transform_selection(m, r));
  EXPECT_NE(m.status().message().find("positive"), std::string::npos) << m.status().message();
  r.kind = TransformKind::Rotate, r.pivot = PivotKind::Vertex, r.pivot_vertex = 99;
  EXPECT_FALSE(transform_selection(m, r));
  EXPECT_NE(m.status().message().find("no vertex 99"), std::string::npos);
  EXPECT_FALSE(m.doc().can_undo()) << "nothing was changed";
}

}  // namespace pl::test
