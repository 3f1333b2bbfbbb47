#include "app/document/document.hpp"

#include <gtest/gtest.h>

#include "app/document/network_commands.hpp"
#include "cli_test_util.hpp"
#include "core/base/data_error.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/network_filling.hpp"
#include "core/network/sample_networks.hpp"
#include "core/network_test_util.hpp"

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

// The record an evaluation follows a free-point drag by (SceneEvaluation's InteriorEdit): the
// faces whose offsets alone changed since a revision, and nothing to go by after anything else.
TEST(Document, KnowsWhichFacesAFreePointDragChanged) {
  Scene s;
  s.network = cube_sphere_network(2, FaceScheme::GB);
  Document doc(std::move(s));
  EXPECT_EQ(doc.interior_faces_since(doc.revision()), std::vector<int>{});
  const uint64_t start = doc.revision();
  const PointRef centre3 = PointRef::free_point(3, InteriorOffset{.centre = true});
  const PointRef centre5 = PointRef::free_point(5, InteriorOffset{.centre = true});
  const Vec3 p3 = point_position(doc.scene(), centre3), p5 = point_position(doc.scene(), centre5);
  doc.begin_drag({centre3});
  doc.drag_to({p3 + Vec3(0, 0, 0.01)});
  doc.drag_to({p3 + Vec3(0, 0, 0.02)});
  EXPECT_EQ(doc.interior_faces_since(start), std::vector<int>{3});
  doc.end_drag();  // records the step; the scene is as the last drag step left it
  const uint64_t after_first = doc.revision();
  doc.begin_drag({centre5, centre3});
  doc.drag_to({p5 + Vec3(0.01, 0, 0), p3});
  EXPECT_EQ(doc.interior_faces_since(after_first), (std::vector<int>{3, 5}));
  doc.end_drag();
  // A vertex drag, an undo, a command: anything may have changed.
  const uint64_t before_vertex = doc.revision();
  doc.begin_drag({PointRef::vertex(0)});
  doc.drag_to({doc.scene().network->vertices[0] + Vec3(0.01, 0, 0)});
  EXPECT_EQ(doc.interior_faces_since(before_vertex), std::nullopt);
  doc.end_drag();
  const uint64_t before_undo = doc.revision();
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.interior_faces_since(before_undo), std::nullopt);
  // Too old, or from the future.
  const uint64_t now = doc.revision();
  EXPECT_EQ(doc.interior_faces_since(now + 1), std::nullopt);
  doc.begin_drag({centre3});
  for (std::size_t i = 0; i <= Document::kEditRecord; ++i)
    doc.drag_to({p3 + Vec3(0, 0, 0.001 * double(i))});
  EXPECT_EQ(doc.interior_faces_since(now), std::nullopt);
  EXPECT_EQ(doc.interior_faces_since(now + 1), std::vector<int>{3});
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

TEST(Document, NudgesOfTheSamePointsMergeIntoOneStepForAMoment) {
  Document doc(parse_scene(kScene, "s.json"));
  auto now = Document::Clock::time_point();
  doc.set_clock([&] { return now; });
  const std::string original = scene_to_json(doc.scene());
  const auto nudge = [&](PointRef p, Vec3 d) {
    now += std::chrono::milliseconds(200);
    doc.execute(std::make_unique<MovePointsCommand>(std::vector{p},
                                                    std::vector{point_position(doc.scene(), p) + d},
                                                    HandleMode::KeepPlane, true));
  };
  for (int i = 0; i < 5; ++i) nudge(PointRef::vertex(2), Vec3(0.1, 0, 0));
  EXPECT_EQ(doc.undo_label(), "nudge vertex 2");
  EXPECT_LT(glm::length(doc.scene().network->vertices[2] - Vec3(1.5, 1, 0)), 1e-15);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), original);  // five nudges, one step
  EXPECT_FALSE(doc.can_undo());
  ASSERT_TRUE(doc.redo());

  nudge(PointRef::vertex(0), Vec3(0, 0.1, 0));  // other points: a step of their own
  nudge(PointRef::vertex(0), Vec3(0, 0.1, 0));
  now += std::chrono::seconds(2);  // a pause: a new step
  nudge(PointRef::vertex(0), Vec3(0, 0.1, 0));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().network->vertices[0], Vec3(0, 0.2, 0));
  nudge(PointRef::vertex(0), Vec3(0, 0.1, 0));  // after an undo: a new step
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().network->vertices[0], Vec3(0, 0.2, 0));
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), original);

  // Typed coordinates are steps of their own, and a save ends a run of nudges.
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::vertex(1)},
                                                  std::vector{Vec3(1, 0, 1)}));
  doc.execute(std::make_unique<MovePointsCommand>(std::vector{PointRef::vertex(1)},
                                                  std::vector{Vec3(1, 0, 2)}));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().network->vertices[1], Vec3(1, 0, 1));
  TempDir dir;
  nudge(PointRef::vertex(1), Vec3(0, 0, 0.5));
  doc.save_as(dir / "s.json");
  nudge(PointRef::vertex(1), Vec3(0, 0, 0.5));
  EXPECT_TRUE(doc.dirty());
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.dirty());  // the saved state is a step boundary
}

TEST(Document, AGestureOfCommandsIsOneStepHoweverLongItPauses) {
  Scene scene = read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/default.json");
  Document doc(scene);
  auto now = Document::Clock::time_point();
  doc.set_clock([&] { return now; });
  const std::string original = scene_to_json(doc.scene());
  const auto turn = [&](double x) {
    now += std::chrono::seconds(3);  // longer than the merge window
    doc.execute(std::make_unique<SetVertexNormalCommand>(1, Vec3(x, 0.1, 1), true));
  };
  doc.begin_gesture();
  EXPECT_TRUE(doc.in_gesture());
  for (double x : {0.1, 0.2, 0.3}) turn(x);
  doc.end_gesture();
  const std::string turned = scene_to_json(doc.scene());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), original);  // three commands, one step
  EXPECT_FALSE(doc.can_undo());
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(scene_to_json(doc.scene()), turned);

  // A second gesture on the same vertex right after the first is a step of its own.
  doc.begin_gesture();
  now -= std::chrono::seconds(3);  // within the merge window of the last command
  turn(0.4);
  doc.end_gesture();
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), turned);
  // Outside a gesture the window applies again: a pause starts a new step.
  turn(0.5);
  turn(0.6);
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), turned);
}

// The scene every handle-mode test starts from: the default scene, whose vertex 1 has three
// edges (two faces meet there).
Scene default_scene() {
  return read_scene(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets/default.json");
}

double g1_angle(const Scene& s) {
  const NetworkTopology topo = validate_network(*s.network, "test");
  const NetworkFilling f = fill_network(*s.network, topo, std::nullopt, "test");
  EXPECT_TRUE(f.projected_vertices.empty());
  return max_g1_angle_deg(topo, surfaces(f));
}

TEST(Document, HandleDragsKeepTheTangentPlaneOrTurnIt) {
  Document doc(default_scene());
  const Network& n = *doc.scene().network;
  ASSERT_EQ(edges_at(n, 1).size(), 3u);
  const int e = edges_at(n, 1)[0], end = n.edges[e].v[0] == 1 ? 0 : 1;
  const Vec3 vertex = n.vertices[1], start = n.edges[e].handles[end];
  const Vec3 plane = *handle_plane_normal(n, 1, std::vector{e});
  EXPECT_LT(g1_angle(doc.scene()), 1e-6);
  // Default: the handle slides in the plane of the two other handles; G1 stays.
  doc.begin_drag({PointRef::handle(e, end)});
  const Vec3 target = start + Vec3(0.1, -0.2, 0.3);
  doc.drag_to({target});
  const Vec3 h = doc.scene().network->edges[e].handles[end];
  EXPECT_LT(std::fabs(glm::dot(h - vertex, plane)), 1e-15);
  EXPECT_LT(glm::length(h - (target - glm::dot(target - vertex, plane) * plane)), 1e-15);
  doc.end_drag();
  EXPECT_EQ(doc.undo_label(), "move edge " + std::to_string(e) + " handle " + std::to_string(end));
  EXPECT_LT(g1_angle(doc.scene()), 1e-6);
  doc.undo();

  // Free: the handle goes exactly where asked, the plane and the other handles turn with it.
  doc.begin_drag({PointRef::handle(e, end)}, HandleMode::RotatePlane);
  for (int i = 1; i <= 10; ++i) doc.drag_to({start + 0.03 * i * Vec3(0.1, -0.2, 0.3)});
  doc.drag_to({target});
  const Network& m = *doc.scene().network;
  EXPECT_EQ(m.edges[e].handles[end], target);
  const Vec3 turned = *handle_plane_normal(m, 1, std::vector{e});
  for (int other : edges_at(m, 1))
    EXPECT_LT(std::fabs(glm::dot(end_tangent(m, other, 1), turned)), 1e-14);
  // Each step starts from the drag's start, so ten steps then the target are the target alone.
  Scene direct = default_scene();
  move_handle_turning_plane(*direct.network, e, end, target);
  EXPECT_EQ(*direct.network, m);
  doc.end_drag();
  EXPECT_LT(g1_angle(doc.scene()), 1e-6);
  doc.undo();
  EXPECT_EQ(*doc.scene().network, *default_scene().network);
}

}  // namespace
}  // namespace pl::test
