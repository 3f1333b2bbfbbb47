// The comparison's GUI-free logic: the panes' setup (kept as keywords), their grid, the titles,
// the figures worker (off the hot path, cancelled by a newer request), and every pane following
// a drag incrementally to the numbers of a fresh evaluation.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/editor/logic/compare_figures.hpp"
#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/io/scene_io.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {
namespace {

const std::filesystem::path kAssets = PATCHLAB_SOURCE_DIR "/assets";

TEST(CompareLayout, SetupFromKeywordsFallsBackToTheDefault) {
  const CompareSetup d = default_compare_setup();
  EXPECT_EQ(compare_setup_from("gregory,gb", "gregory"), d);
  EXPECT_EQ(compare_setup_from("gregory,teapot", "gregory"), d);  // unknown scheme
  EXPECT_EQ(compare_setup_from("gb", "gb"), d);                   // one pane is no comparison
  EXPECT_EQ(compare_setup_from("gb,gb,gb,gb,gb", "gb"), d);       // five panes are not offered
  EXPECT_EQ(compare_setup_from("", ""), d);
  const CompareSetup s = compare_setup_from("gb,gregory,gb", "gregory");
  EXPECT_EQ(s.schemes.size(), 3u);
  EXPECT_EQ(s.base, FaceScheme::Gregory);
  EXPECT_EQ(s.base_pane(), 1);
  EXPECT_EQ(schemes_keywords(s), "gb,gregory,gb");
  // A base no pane shows: the first pane's scheme.
  EXPECT_EQ(compare_setup_from("gb,gb", "gregory").base, FaceScheme::GB);
}

TEST(CompareLayout, PaneCountsKeepPanesAndAddTheSchemesNotShown) {
  const std::vector<FaceScheme> all = comparable_schemes();
  CompareSetup s = default_compare_setup();
  for (int count : kComparePaneCounts) {
    const CompareSetup c = with_pane_count(s, count);
    ASSERT_EQ(int(c.schemes.size()), count);
    EXPECT_EQ(c.schemes[0], s.schemes[0]);
    EXPECT_EQ(c.schemes[1], s.schemes[1]);
    // Every scheme is shown once before any is shown twice.
    for (std::size_t i = 0; i < std::min(c.schemes.size(), all.size()); ++i)
      EXPECT_EQ(
          std::count(c.schemes.begin(), c.schemes.begin() + std::min(c.schemes.size(), all.size()),
                     c.schemes[i]),
          1);
  }
  EXPECT_EQ(with_pane_count(s, 5), s);  // not offered: unchanged
  // Shrinking drops the last panes; a base that goes goes to the first pane.
  CompareSetup gb_base = s;
  gb_base.base = FaceScheme::GB;
  const CompareSetup six = with_pane_count(gb_base, 6);
  EXPECT_EQ(six.base, FaceScheme::GB);
  CompareSetup one_of_each = with_pane_scheme(s, 1, FaceScheme::Gregory);
  EXPECT_EQ(one_of_each.schemes,
            (std::vector<FaceScheme>{FaceScheme::Gregory, FaceScheme::Gregory}));
  EXPECT_EQ(with_pane_scheme(gb_base, 1, FaceScheme::Gregory).base, FaceScheme::Gregory);
}

TEST(CompareLayout, PanesTileTheView) {
  const ViewRect view{10, 20, 1001, 601};
  for (int count : {1, 2, 3, 4, 6}) {
    const std::vector<ViewRect> r = pane_rects(view, count);
    ASSERT_EQ(int(r.size()), count);
    double area = 0;
    for (const ViewRect& p : r) {
      area += p.width * p.height;
      EXPECT_GE(p.x, view.x);
      EXPECT_GE(p.y, view.y);
      EXPECT_LE(p.x + p.width, view.x + view.width);
      EXPECT_LE(p.y + p.height, view.y + view.height);
      EXPECT_EQ(p.x, std::floor(p.x));
    }
    EXPECT_EQ(area, view.width * view.height) << count;  // no gap, no overlap
  }
  // 4: two rows of two; 6: two rows of three; 3: one row.
  EXPECT_EQ(pane_rects(view, 4)[2].x, view.x);
  EXPECT_GT(pane_rects(view, 4)[2].y, view.y);
  EXPECT_EQ(pane_rects(view, 6)[3].x, view.x);
  EXPECT_EQ(pane_rects(view, 3)[2].y, view.y);
}

TEST(CompareLayout, EverySchemeHasATitle) {
  for (FaceScheme s : comparable_schemes()) {
    EXPECT_FALSE(scheme_title(s).empty());
    EXPECT_LE(scheme_short_title(s).size(), scheme_title(s).size());
  }
  EXPECT_EQ(scheme_title(FaceScheme::GB), "Generalized Bezier");
  EXPECT_EQ(scheme_short_title(FaceScheme::GB), "GB");
}

TEST(CompareFigures, FaceChoiceIsTheSelectionElseTheMostSidedFace) {
  const Scene s = read_scene(kAssets / "gb-hole-filling.json");
  EXPECT_EQ(figures_faces(*s.network, {}), std::vector<int>{1});  // the hexagon
  EXPECT_EQ(figures_faces(*s.network, {3, 0, 3, 99}), (std::vector<int>{3, 0}));
}

SchemeComparison wait_for(CompareFigures& f) {
  for (int i = 0; i < 6000 && !f.poll(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_FALSE(f.busy());
  EXPECT_TRUE(f.error().empty()) << f.error();
  return f.result().value_or(SchemeComparison{});
}

TEST(CompareFigures, ComputesOffThreadAndANewerRequestReplacesTheOlder) {
  const Scene s = read_scene(kAssets / "default.json");
  CompareFigures f;
  f.timing_ms = 1;
  FiguresKey key{1, {1}, comparable_schemes(), FaceScheme::GB, 8};
  EXPECT_TRUE(f.request(s, key));
  EXPECT_FALSE(f.request(s, key));  // the same key is being computed
  FiguresKey newer = key;
  newer.revision = 2;
  EXPECT_TRUE(f.request(s, newer));  // cancels the first
  const SchemeComparison c = wait_for(f);
  EXPECT_EQ(f.result_key(), newer);
  ASSERT_EQ(c.faces.size(), 1u);
  EXPECT_EQ(c.faces[0].name, "pentagon");
  // The same numbers as the command line's computation.
  ComparisonOptions o;
  o.faces = {1};
  o.density = 8;
  o.timing_ms = 0;
  const SchemeComparison direct = compare_schemes(s, o, "scene");
  for (std::size_t i = 0; i < c.faces[0].schemes.size(); ++i) {
    EXPECT_EQ(c.faces[0].schemes[i].cannot_fill, direct.faces[0].schemes[i].cannot_fill);
    EXPECT_EQ(c.faces[0].schemes[i].bending_energy, direct.faces[0].schemes[i].bending_energy);
    EXPECT_EQ(c.faces[0].schemes[i].max_distance_to_base,
              direct.faces[0].schemes[i].max_distance_to_base);
  }
  EXPECT_FALSE(f.request(s, newer));  // computed already
  f.cancel();
  EXPECT_FALSE(f.busy());
}

// Every pane is a LiveSurfaces of its scheme: a vertex drag is followed incrementally and ends
// on the numbers of a fresh evaluation of the dragged scene, in every pane.
TEST(CompareFigures, EveryPaneFollowsADragToTheFreshNumbers) {
  Scene scene = read_scene(kAssets / "gb-hole-filling.json");
  std::vector<std::unique_ptr<LiveSurfaces>> panes;
  const CompareSetup six = with_pane_count(default_compare_setup(), 6);
  for (FaceScheme s : six.schemes)
    panes.push_back(std::make_unique<LiveSurfaces>(scene, 8, s, "pane", 0));
  const Vec3 start = scene.network->vertices[0];
  for (int step = 1; step <= 5; ++step) {
    scene.network->vertices[0] = start + Vec3(0.01 * step, -0.02 * step, 0.03 * step);
    for (auto& p : panes) p->sync(scene, uint64_t(step));
  }
  for (std::size_t i = 0; i < panes.size(); ++i) {
    const LiveSurfaces fresh(scene, 8, six.schemes[i], "fresh", 5);
    const auto& a = panes[i]->surfaces().surfaces;
    const auto& b = fresh.surfaces().surfaces;
    ASSERT_EQ(a.size(), b.size());
    double worst = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
      for (std::size_t j = 0; j < a[k].evaluator->sample_count(); ++j)
        worst =
            std::max(worst, glm::length(a[k].evaluator->position(j) - b[k].evaluator->position(j)));
    EXPECT_LT(worst, 1e-12) << "pane " << i << " " << scheme_keyword(six.schemes[i]);
  }
}

}  // namespace
}  // namespace pl
