// What the editor shows about a document once another replaced it (File > Open, File > New):
// the status bar's evaluation figures are the new scene's (its own evaluation), not those of the
// scene before, and the settle time waits for a release in it; the curvature legend belongs to
// surfaces, so an empty scene or one of free curves only shows none (and gives the view its
// width back), while a scene with surfaces keeps it.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "model_driver.hpp"

namespace pl::test {

namespace {

namespace fs = std::filesystem;

const fs::path kDefaultScene = fs::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json";

// Figures no evaluation of these small scenes comes near: the previous scene's, as they stood.
constexpr double kBeforeMs = 1e6;

void expect_the_new_scenes_figures(EditorModel& m, const char* after) {
  EXPECT_LT(m.status().eval_ms, kBeforeMs) << after << ": the previous scene's figure stayed";
  EXPECT_EQ(m.status().eval_ms, m.views().last_eval_ms())
      << after << ": not the evaluation of the scene shown";
  EXPECT_EQ(m.status().settle_ms, 0) << after << ": no release measured in this scene yet";
}

}  // namespace

TEST(NewDocument, TheStatusFiguresAfterOpenAndNewAreTheNewScenes) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  m.open_file(kDefaultScene);
  d.settle();
  ASSERT_TRUE(m.doc().scene().network);
  EXPECT_GT(m.status().eval_ms, 0) << "opening evaluates the scene: its time is shown";
  EXPECT_EQ(m.status().eval_ms, m.views().last_eval_ms());

  m.status().eval_ms = kBeforeMs;
  m.status().settle_ms = kBeforeMs;
  m.open_file(kDefaultScene);
  d.settle();
  EXPECT_EQ(d.shell().errors, 0) << d.shell().last_error;
  expect_the_new_scenes_figures(m, "Open");

  m.status().eval_ms = kBeforeMs;
  m.status().settle_ms = kBeforeMs;
  d.key("Ctrl+N");
  ASSERT_FALSE(m.doc().dirty());
  expect_the_new_scenes_figures(m, "New");
}

TEST(NewDocument, NoCurvatureLegendWithoutASurface) {
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  m.prefs().display.base = BaseMode::Curvature;
  d.new_scene();
  EXPECT_TRUE(m.legends({-1, 1}).empty()) << "an empty scene has no curvature to colour";
  EXPECT_EQ(m.layout().legends, 0);
  EXPECT_EQ(m.layout().legend_width(), 0) << "the view keeps its width";

  // Free curves only: still no surface.
  d.key("B");
  for (const Vec3& p : {Vec3(-0.5, 0, 0), Vec3(0, 0.5, 0), Vec3(0.5, 0, 0)})
    d.click(d.world_to_pixel(p));
  d.key("Enter");
  ASSERT_EQ(m.doc().scene().curves.size(), 1u);
  EXPECT_TRUE(m.legends({-1, 1}).empty());
  EXPECT_EQ(m.layout().legends, 0);

  // A scene with surfaces shows its curvature legend.
  m.open_file(kDefaultScene);
  d.settle();
  const std::vector<LegendSpec> shown = m.legends({-2, 3});
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0].title, "mean curvature");
  EXPECT_EQ(shown[0].range.lo, -2);
  EXPECT_EQ(m.layout().legends, 1);
  EXPECT_GT(m.layout().legend_width(), 0);
}

}  // namespace pl::test
