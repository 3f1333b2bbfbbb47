// The editor model's event routing, each checked on the document it leaves: a drag of a point
// (the select tool, the document's drag, one undo step), Esc (tool, then selection), a
// right-click on empty space (the menu for nothing), a dropped file (asked about unsaved work
// first, then opened) and the autosave of unsaved work (written, and gone after a save).
#include <gtest/gtest.h>

#include <filesystem>

#include "model_driver.hpp"

namespace pl::test {

namespace {

namespace fs = std::filesystem;

const fs::path kDefaultScene = fs::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json";

DocumentSession default_scene_session() {
  DocumentSession session({fs::path(PATCHLAB_SOURCE_DIR) / "assets"});
  session.open(kDefaultScene);
  return session;
}

Vec3 vertex_position(EditorModel& m, int v) {
  return m.doc().scene().network->vertices.at(v);
}

}  // namespace

TEST(Events, DraggingAVertexMovesItInTheViewPlaneAndOneUndoTakesItBack) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  ASSERT_TRUE(m.doc().scene().network);
  ASSERT_EQ(m.tools().active().name(), "Select");
  const Vec3 before = vertex_position(m, 2);
  const Vec2 at = whole_pixel(d.vertex(2));
  const ViewRect rect = m.layout().panels(m.views().panels())[0];
  const Camera camera = m.nav().camera();
  const double wpp = world_per_pixel(camera, rect, before);

  d.press(at);
  ASSERT_TRUE(m.doc().dragging()) << "a press on a vertex starts a drag";
  for (int dx = 10; dx <= 40; dx += 10) d.drag_to(at + Vec2(dx, 0));
  d.release();
  ASSERT_FALSE(m.doc().dragging());
  EXPECT_EQ(m.selection().points(), std::vector<PointRef>{PointRef::vertex(2)});

  // 40 pixels to the right in the view plane through the vertex (as the window would map them).
  const Vec3 moved = vertex_position(m, 2);
  const Vec3 expected = before + 40 * wpp * camera.right();
  EXPECT_LT(glm::length(moved - expected), 1e-6 * (1 + glm::length(before)))
      << "moved by " << glm::length(moved - before) << ", expected " << 40 * wpp;

  d.key("Ctrl+Z");
  EXPECT_EQ(vertex_position(m, 2), before) << "undo restores the vertex bit for bit";
  EXPECT_FALSE(m.doc().can_undo());
}

TEST(Events, EscapeLeavesTheToolThenClearsTheSelection) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  d.click(d.vertex(0));
  ASSERT_EQ(m.selection().size(), 1u);
  d.key("V");
  ASSERT_EQ(m.tools().active().name(), "Add Vertex");
  d.key("Esc");
  EXPECT_EQ(m.tools().active().name(), "Select");
  EXPECT_EQ(m.selection().size(), 1u);
  d.key("Esc");
  EXPECT_TRUE(m.selection().empty());
}

TEST(Events, ARightClickOnEmptySpaceOpensTheMenuForNothing) {
  ModelDriver d(1280, 720, default_scene_session());
  EditorModel& m = d.model();
  d.click(d.vertex(0));
  ASSERT_EQ(m.selection().size(), 1u);
  const ViewRect rect = m.layout().panels(1)[0];
  d.click(Vec2(rect.x + 5, rect.y + rect.height - 5), 1);  // a corner of the view: nothing there
  ASSERT_EQ(m.context_target(), ContextTarget::Empty);
  EXPECT_EQ(m.selection().size(), 1u) << "the menu acts on the selection as it is";
  EXPECT_FALSE(m.actions().for_context(ContextTarget::Empty).empty());
}

TEST(Events, ADroppedFileAsksAboutUnsavedWorkThenOpens) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  d.new_scene();
  d.key("V");
  d.click(d.world_to_pixel(Vec3(0.2, 0.1, 0)));
  ASSERT_TRUE(m.doc().dirty());

  d.model().drop(kDefaultScene);
  d.settle();
  EXPECT_EQ(d.shell().discard_questions, 1);
  EXPECT_EQ(m.doc().scene().network->vertices.size(), 1u) << "the unsaved work is still there";

  d.key("Ctrl+Z");
  ASSERT_FALSE(m.doc().dirty());
  d.model().drop(kDefaultScene);
  d.settle();
  EXPECT_EQ(d.shell().discard_questions, 1);
  EXPECT_EQ(d.shell().errors, 0) << d.shell().last_error;
  ASSERT_TRUE(m.doc().scene().network);
  EXPECT_GT(m.doc().scene().network->vertices.size(), 1u);
  EXPECT_NE(m.status().message().find("default.json"), std::string::npos) << m.status().message();
  EXPECT_EQ(m.tools().active().name(), "Add Vertex") << "the tool stays; its picks went";
}

TEST(Events, UnsavedWorkIsAutosavedAndASaveDeletesIt) {
  TempDir state("autosave");
  TempDir work("work");
  EditorModelOptions options;
  options.autosave_dir = state.path();
  ModelDriver d(1280, 720, DocumentSession(), options);
  EditorModel& m = d.model();
  d.new_scene();
  d.key("V");
  d.click(d.world_to_pixel(Vec3(0.3, -0.2, 0)));
  ASSERT_TRUE(m.doc().dirty());
  d.settle();  // a frame ticks the autosave
  std::vector<fs::path> written;
  for (const auto& e : fs::directory_iterator(state.path())) written.push_back(e.path());
  ASSERT_FALSE(written.empty()) << "no autosave of the unsaved vertex";

  d.key("Ctrl+S");
  ASSERT_EQ(d.shell().save_as_requests, 1);
  m.save_as(work.path() / "one.json");
  d.settle();
  EXPECT_FALSE(m.doc().dirty());
  EXPECT_TRUE(fs::exists(work.path() / "one.json"));
  for (const fs::path& p : written) EXPECT_FALSE(fs::exists(p)) << p << " was kept after a save";
}

}  // namespace pl::test
