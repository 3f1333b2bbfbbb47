// The editor's document session: the default scene and shipped samples open as untitled copies,
// a save never goes under assets/, File > New is an empty scene that saves and reads back.
// Also the small parts around it: continuity figures, the difference field, the status line,
// the window layout.
#include <gtest/gtest.h>

#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/document_session.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/logic/editor_paths.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/status_line.hpp"
#include "cli_test_util.hpp"
#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(PATCHLAB_SOURCE_DIR) / "assets";

TEST(EditorSession, DefaultSceneIsAnUntitledCopyAndSavesGoElsewhere) {
  // The folders the editor protects: the sources' assets (the build installs no other copy).
  const std::vector<fs::path> shipped = shipped_scene_dirs(executable_path());
  ASSERT_FALSE(shipped.empty());
  EXPECT_TRUE(is_inside(kAssets / "default.json", shipped[0]));

  const fs::path def = *default_scene_path(executable_path());
  const std::string original = test::slurp(def);
  const auto stamp = fs::last_write_time(def);
  DocumentSession session(shipped);
  session.open(def);
  EXPECT_TRUE(session.untitled());
  EXPECT_EQ(session.title(), "untitled (from default.json)");
  // An edit, then Save: nothing is written, the caller must ask for a path.
  Document& doc = session.doc();
  doc.execute(std::make_unique<MovePointsCommand>(std::vector<PointRef>{PointRef::vertex(2)},
                                                  std::vector<Vec3>{Vec3(1, 1, 0.9)}));
  EXPECT_EQ(session.title(), "untitled (from default.json) *");
  EXPECT_FALSE(session.save());
  // Save As into the shipped folder (or a sub-folder, or through "..") is refused.
  for (const fs::path& p :
       {def, kAssets / "classic" / "x.json", kAssets / "sub" / ".." / "y.json"}) {
    EXPECT_THROW(session.save_as(p), DataError) << p;
    EXPECT_FALSE(fs::exists(kAssets / "x.json"));
  }
  EXPECT_FALSE(fs::exists(kAssets / "classic" / "x.json"));
  EXPECT_FALSE(fs::exists(kAssets / "y.json"));
  EXPECT_TRUE(doc.dirty());
  // Elsewhere it is written, and from then on Save goes there.
  test::TempDir tmp;
  session.save_as(tmp / "mine.json");
  EXPECT_EQ(session.title(), "mine.json");
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(read_scene(tmp / "mine.json").network->vertices[2], Vec3(1, 1, 0.9));
  doc.execute(std::make_unique<MovePointsCommand>(std::vector<PointRef>{PointRef::vertex(2)},
                                                  std::vector<Vec3>{Vec3(1, 1, 1)}));
  EXPECT_TRUE(session.save());
  EXPECT_EQ(read_scene(tmp / "mine.json").network->vertices[2], Vec3(1, 1, 1));
  // The shipped file is untouched.
  EXPECT_EQ(test::slurp(def), original);
  EXPECT_EQ(fs::last_write_time(def), stamp);
}

TEST(EditorSession, OpenKeepsPathsOutsideTheSamplesAndImportsGbp) {
  DocumentSession session({kAssets});
  test::TempDir tmp;
  fs::copy_file(kAssets / "gregory-cap-open.json", tmp / "cap.json");
  const uint64_t serial = session.serial();
  session.open(tmp / "cap.json");
  EXPECT_GT(session.serial(), serial);
  EXPECT_FALSE(session.untitled());
  EXPECT_EQ(session.title(), "cap.json");
  session.open(kAssets / "classic" /
               fs::directory_iterator(kAssets / "classic")->path().filename());
  EXPECT_TRUE(session.untitled());
  // A failed open keeps the document.
  const uint64_t before = session.serial();
  EXPECT_THROW(session.open(tmp / "missing.json"), DataError);
  EXPECT_EQ(session.serial(), before);
}

TEST(EditorSession, NewIsAnEmptyNetworkThatSavesAndReadsBack) {
  DocumentSession session({kAssets});
  session.new_scene();
  EXPECT_TRUE(session.untitled());
  EXPECT_EQ(session.title(), "untitled");
  ASSERT_TRUE(session.doc().scene().network);
  EXPECT_TRUE(session.doc().scene().network->vertices.empty());
  EXPECT_FALSE(session.doc().can_undo());
  EXPECT_FALSE(session.doc().dirty());  // nothing to lose yet
  // It can be drawn (no surfaces) and written; the reader accepts it.
  const LiveSurfaces live(session.doc().scene(), 8, std::nullopt, "new");
  EXPECT_TRUE(live.draw().surfaces.empty());
  test::TempDir tmp;
  session.save_as(tmp / "empty.json");
  const Scene back = read_scene(tmp / "empty.json");
  EXPECT_TRUE(back.patches.empty());
  EXPECT_TRUE(!back.network || back.network->vertices.empty());
}

TEST(EditorContinuity, FollowsRevisionsAndFindsTheWorstEdge) {
  Scene s = read_scene(kAssets / "default.json");
  LiveSurfaces live(s, 16, std::nullopt, "default");
  ContinuityMonitor m;
  EXPECT_TRUE(m.follow(s, live.surfaces(), 0));
  EXPECT_FALSE(m.follow(s, live.surfaces(), 0));
  ASSERT_EQ(m.report().edges.size(), 1u);  // the one shared edge
  EXPECT_EQ(m.worst(), 0);
  EXPECT_EQ(m.worst_edge(), m.report().edges[0].edge);
  m.reset();
  EXPECT_TRUE(m.follow(s, live.surfaces(), 0));
}

TEST(EditorDifference, GbColouredByDistanceToGregoryOncePerKey) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces gregory(s, 12, FaceScheme::Gregory, "g"), gb(s, 12, FaceScheme::GB, "b");
  DifferenceField f;
  EXPECT_TRUE(f.follow(gregory.draw(), gb.draw(), 5));
  EXPECT_FALSE(f.follow(gregory.draw(), gb.draw(), 5));
  ASSERT_EQ(f.scene().surfaces.size(), 2u);
  // The pentagon is GB in both fillings: distance zero there (same surface, same samples).
  for (double d : f.scene().surfaces[1].mean) EXPECT_NEAR(d, 0, 1e-12);
  // The quad differs between Gregory and GB, but little: it interpolates the same boundary.
  EXPECT_GT(f.max_abs(), 0);
  EXPECT_LT(f.max_abs(), 0.1);
  EXPECT_EQ(f.range(), f.max_abs());
  const uint64_t rev = f.scene().surfaces[0].revision;
  EXPECT_TRUE(f.follow(gregory.draw(), gb.draw(), 6));
  EXPECT_NE(f.scene().surfaces[0].revision, rev);  // re-uploaded
}

TEST(EditorStatusLine, MessagesFadeAndFramesHaveAMedian) {
  StatusLine s;
  const auto t0 = StatusLine::Clock::now();
  s.say("saved x.json", t0);
  EXPECT_EQ(s.message(t0 + std::chrono::seconds(1)), "saved x.json");
  EXPECT_EQ(s.message(t0 + std::chrono::seconds(9)), "");
  EXPECT_EQ(s.median_frame_ms(), 0);
  for (double ms : {5.0, 1.0, 3.0}) s.add_frame(ms);
  EXPECT_EQ(s.median_frame_ms(), 3.0);
  for (int i = 0; i < 200; ++i) s.add_frame(10);
  EXPECT_EQ(s.median_frame_ms(), 10.0);  // only the recent frames count
}

TEST(EditorLayout, ViewportBetweenBarsAndPanelAndSplitForComparison) {
  EditorLayout l{{1440, 900}, 20, 26, 1.5};
  const ViewRect v = l.viewport();
  EXPECT_EQ(v.x, 0);
  EXPECT_EQ(v.y, 20);
  EXPECT_EQ(v.width, 1440 - 340 * 1.5);
  EXPECT_EQ(v.height, 900 - 20 - 26);
  const auto two = l.panels(2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].width + two[1].width, v.width);
  EXPECT_EQ(two[1].x, two[0].width);
  EXPECT_EQ(l.panel_at(Vec2(10, 30), 2), 0);
  EXPECT_EQ(l.panel_at(Vec2(two[1].x + 1, 30), 2), 1);
  EXPECT_EQ(l.panel_at(Vec2(1400, 30), 1), -1);  // the side panel
  EXPECT_EQ(l.panel_at(Vec2(10, 5), 1), -1);     // the menu bar
}

}  // namespace
}  // namespace pl
