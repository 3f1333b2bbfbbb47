#include "app/document/document.hpp"

#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl::test {
namespace {

const char* kScene = R"({"patchlab":1,
 "network":{"vertices":[[0,0,0],[1,0,0],[1,1,0]],
   "edges":[{"v":[0,1],"handles":[[0.3,0,0],[0.6,0,0]]},{"v":[2,1],"handles":[[1,0.6,0],[1,0.3,0]]}]},
 "patches":[{"type":"bezier","degree":[2,2],"points":[[0,0,0],[0,0.5,0],[0,1,0],[0.5,0,0],[0.5,0.5,1],
   [0.5,1,0],[1,0,0],[1,0.5,0],[1,1,0]]}]})";

TEST(Document, DragIsOneUndoStepAndUndoRedoAreExact) {
  Document doc(parse_scene(kScene, "s.json"));
  const PointRef centre = PointRef::patch_point(0, 4);
  EXPECT_FALSE(doc.dirty());
  doc.begin_drag({centre});
  for (int i = 1; i <= 10; ++i) doc.drag_to({Vec3(0.5, 0.5, 1 + 0.1 * i)});
  EXPECT_TRUE(doc.dirty());
  doc.end_drag();
  EXPECT_EQ(point_position(doc.scene(), centre), Vec3(0.5, 0.5, 2));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(point_position(doc.scene(), centre), Vec3(0.5, 0.5, 1));
  EXPECT_FALSE(doc.can_undo());  // ten drag steps were one command
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(point_position(doc.scene(), centre), Vec3(0.5, 0.5, 2));
  EXPECT_EQ(doc.undo_label(), "move patch 0 point 4");
}

TEST(Document, MovingAVertexCarriesItsHandlesAndUndoRestoresThem) {
  Document doc(parse_scene(kScene, "s.json"));
  const std::string before = scene_to_json(doc.scene());
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::vertex(1)},
                                                  std::vector{Vec3(1, 0, 0.5)}));
  const Network& n = *doc.scene().network;
  EXPECT_EQ(n.vertices[1], Vec3(1, 0, 0.5));
  EXPECT_EQ(n.edges[0].handles[1], Vec3(0.6, 0, 0.5));  // edge 0 ends at vertex 1
  EXPECT_EQ(n.edges[1].handles[1], Vec3(1, 0.3, 0.5));  // edge 1 ends at vertex 1
  EXPECT_EQ(n.edges[0].handles[0], Vec3(0.3, 0, 0));    // the far handle stays
  doc.undo();
  EXPECT_EQ(scene_to_json(doc.scene()), before);
}

TEST(Document, CancelledDragRestoresAndNewEditDropsRedo) {
  Document doc(parse_scene(kScene, "s.json"));
  const std::string before = scene_to_json(doc.scene());
  doc.begin_drag({PointRef::vertex(2), PointRef::handle(0, 0)});
  doc.drag_to({Vec3(2, 2, 2), Vec3(3, 3, 3)});
  doc.cancel_drag();
  EXPECT_EQ(scene_to_json(doc.scene()), before);
  EXPECT_FALSE(doc.dirty());
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::handle(0, 0)},
                                                  std::vector{Vec3(0.3, 0.1, 0)}));
  doc.undo();
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::handle(0, 1)},
                                                  std::vector{Vec3(0.6, 0.1, 0)}));
  EXPECT_FALSE(doc.can_redo());
  EXPECT_THROW(doc.begin_drag({PointRef::vertex(99)}), std::invalid_argument);
}

TEST(Document, SaveIsAtomicTracksDirtyAndRoundTrips) {
  TempDir dir;
  Document doc(parse_scene(kScene, "s.json"));
  EXPECT_THROW(doc.save(), DataError);  // no file name yet
  const auto path = dir / "scene.json";
  doc.begin_drag({PointRef::patch_point(0, 4)});
  doc.drag_to({Vec3(0.5, 0.5, 0.25)});
  doc.save_as(path);  // ends the drag, then saves
  EXPECT_FALSE(doc.dirty());
  const Document back = Document::open(path);
  EXPECT_EQ(point_position(back.scene(), PointRef::patch_point(0, 4)), Vec3(0.5, 0.5, 0.25));
  doc.undo();
  EXPECT_TRUE(doc.dirty());
  doc.redo();
  EXPECT_FALSE(doc.dirty());  // back at the saved state
  // A save into a missing folder fails and keeps the document's path.
  EXPECT_THROW(doc.save_as(dir / "missing" / "x.json"), DataError);
  EXPECT_EQ(doc.path(), path);
}

TEST(SceneEvaluation, SyncAfterEditsEqualsFreshEvaluationAndMovesOnlyChangedPoints) {
  Document doc(parse_scene(kScene, "s.json"));
  SceneEvaluation live(doc.scene(), 16, std::nullopt);
  doc.begin_drag({PointRef::patch_point(0, 4)});
  for (int i = 1; i <= 20; ++i) {
    doc.drag_to({Vec3(0.5 + 0.01 * i, 0.5, 1 - 0.03 * i)});
    const SyncStats s = live.sync(doc.scene());
    EXPECT_EQ(s.moved_points, 1u);
    EXPECT_EQ(s.rebuilt_surfaces, 0u);
    EXPECT_EQ(s.changed_surfaces, std::vector<int>{0});
  }
  doc.end_drag();
  doc.undo();
  live.sync(doc.scene());
  const SceneEvaluation fresh(doc.scene(), 16, std::nullopt);
  const auto& a = live.surfaces().surfaces[0].evaluator->jets();
  const auto& b = fresh.surfaces().surfaces[0].evaluator->jets();
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max({worst, glm::length(a[i].p - b[i].p), glm::length(a[i].suv - b[i].suv)});
  EXPECT_LT(worst, 1e-13);
  EXPECT_EQ(live.sync(doc.scene()).moved_points, 0u);  // nothing changed, nothing moved
}

}  // namespace
}  // namespace pl::test
