// The GUI-free logic behind the editor's panels and view: the continuity warning threshold, the
// layout with its legend column and the comparison's titles, the probe's distance, the theme's
// text contrast, the view a patch opens with and the orbit that keeps the model on screen.
#include <gtest/gtest.h>

#include <cmath>

#include "app/editor/logic/camera_control.hpp"
#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/difference_field.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/view_navigator.hpp"
#include "app/editor/theme.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "render/default_view.hpp"

namespace pl {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(PATCHLAB_SOURCE_DIR) / "assets";

// The default scene evaluated, with face 1's (the pentagon's) inner control points lifted: its
// boundary stays where it was (G0 holds), its cross-boundary tangents change (G1 breaks).
SceneSurfaces default_with_kinked_face(const Scene& scene, double lift) {
  TessellationCache cache;
  SceneSurfaces s = evaluate_scene(scene, 16, std::nullopt, cache, "default");
  PatchEvaluator& e = *s.surfaces[1].evaluator;
  for (std::size_t k = 0; k < e.patch().size(); ++k)
    if (e.patch().kind(k) != ControlPointKind::Boundary)
      e.move_control_point(k, e.patch().control_point(k) + Vec3(0, 0, lift));
  return s;
}

TEST(EditorContinuity, NoWarningOnTheDefaultSceneAtTheDefaultThreshold) {
  const Scene s = read_scene(kAssets / "default.json");
  const double threshold = default_preferences().continuity_threshold_deg;
  EXPECT_EQ(threshold, 0.1);
  LiveSurfaces live(s, 16, std::nullopt, "default");
  ContinuityMonitor m;
  ASSERT_TRUE(m.follow(s, live.surfaces(), 0));
  ASSERT_EQ(m.report().edges.size(), 1u);
  // The shared edge is G1 to rounding (1e-14 degrees): shown, but no warning, no highlight.
  EXPECT_LT(m.report().edges[0].max_normal_angle_deg, 1e-9);
  EXPECT_TRUE(m.warnings(0, threshold).empty());
  EXPECT_EQ(m.warned_edge(0, threshold), -1);
  EXPECT_FALSE(m.any_warning(threshold));
  // Every shipped network is G1 the same way: no false alarm on any of them.
  for (const char* name : {"gregory-blob-closed.json", "gregory-cap-open.json",
                           "gb-hole-filling.json", "gb-concave-l.json"}) {
    const Scene a = read_scene(kAssets / name);
    LiveSurfaces la(a, 16, std::nullopt, name);
    ContinuityMonitor ma;
    ma.follow(a, la.surfaces(), 0);
    EXPECT_FALSE(ma.report().edges.empty()) << name;
    EXPECT_FALSE(ma.any_warning(threshold)) << name;
  }
}

TEST(EditorContinuity, WarnsAboutAnEdgeOverTheThreshold) {
  const Scene s = read_scene(kAssets / "default.json");
  const SceneSurfaces kinked = default_with_kinked_face(s, 0.05);
  ContinuityMonitor m;
  m.follow(s, kinked, 1);
  ASSERT_EQ(m.report().edges.size(), 1u);
  const EdgeReport& e = m.report().edges[0];
  EXPECT_LT(e.max_gap, 1e-12);             // the boundary did not move
  EXPECT_GT(e.max_normal_angle_deg, 0.5);  // the tangent planes did
  EXPECT_EQ(m.warnings(0, 0.1), std::vector<int>{0});
  EXPECT_EQ(m.warned_edge(0, 0.1), e.edge);
  EXPECT_TRUE(m.any_warning(0.1));
  // A threshold above the angle: the figures stay, the warning goes.
  EXPECT_TRUE(m.warnings(0, e.max_normal_angle_deg * 1.01).empty());
  EXPECT_EQ(m.warned_edge(0, e.max_normal_angle_deg * 1.01), -1);
  EXPECT_EQ(m.warned_edge(0, e.max_normal_angle_deg * 0.99), e.edge);
}

TEST(EditorContinuity, OneLabelledReportPerFillingAndRecomputedWhenTheyChange) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces gregory(s, 16, FaceScheme::Gregory, "g"), gb(s, 16, FaceScheme::GB, "b");
  const SceneSurfaces kinked = default_with_kinked_face(s, 0.05);
  ContinuityMonitor m;
  const ContinuityMonitor::Input two[2] = {{"Gregory filling", &gregory.surfaces()},
                                           {"GB filling", &kinked}};
  EXPECT_TRUE(m.follow(s, two, 3));
  EXPECT_FALSE(m.follow(s, two, 3));  // same revision, same fillings
  ASSERT_EQ(m.fillings().size(), 2u);
  EXPECT_EQ(m.fillings()[0].label, "Gregory filling");
  EXPECT_EQ(m.fillings()[1].label, "GB filling");
  // Each panel highlights its own filling's edge only.
  EXPECT_EQ(m.warned_edge(0, 0.1), -1);
  EXPECT_EQ(m.warned_edge(1, 0.1), m.fillings()[1].report.edges[0].edge);
  EXPECT_EQ(m.warned_edge(2, 0.1), -1);  // no such panel
  // The comparison turned off at the same revision: one filling again.
  EXPECT_TRUE(m.follow(s, gb.surfaces(), 3));
  ASSERT_EQ(m.fillings().size(), 1u);
  EXPECT_EQ(m.fillings()[0].label, "");
}

TEST(EditorContinuity, ThresholdIsKeptInThePreferences) {
  Preferences p = default_preferences();
  p.continuity_threshold_deg = 0.025;
  EXPECT_EQ(preferences_from_text(preferences_to_text(p)).continuity_threshold_deg, 0.025);
  // Out of range or malformed: the default.
  for (const char* bad : {"continuity_threshold_deg = -1\n", "continuity_threshold_deg = 95\n",
                          "continuity_threshold_deg = x\n", "continuity_threshold_deg = 0\n"})
    EXPECT_EQ(preferences_from_text(bad).continuity_threshold_deg, 0.1) << bad;
}

TEST(EditorLayout, LegendColumnBesideTheViewNeverOverIt) {
  EditorLayout l{{1600, 1000}, 20, 26, 1.0};
  const ViewRect plain = l.viewport();
  EXPECT_EQ(l.legend_width(), 0);
  l.legends = 2;
  const ViewRect v = l.viewport();
  const ViewRect c = l.legend_column();
  EXPECT_EQ(c.width, EditorLayout::kLegendWidth);
  EXPECT_EQ(v.width + c.width, plain.width);
  EXPECT_EQ(c.x, v.x + v.width);  // right of the view, left of the side panel
  EXPECT_EQ(c.x + c.width, 1600 - l.side_panel_width());
  // Both comparison panels lie left of the column.
  for (int count : kComparePaneCounts)
    for (const ViewRect& p : l.panels(count)) EXPECT_LE(p.x + p.width, c.x);
  // A narrow window: the column takes at most a third of what the side panel leaves.
  EditorLayout narrow{{600, 500}, 20, 26, 1.0};
  narrow.legends = 1;
  EXPECT_LE(narrow.legend_width(), (600 - narrow.side_panel_width()) / 3);
}

TEST(EditorLayout, LegendsForEachColouredView) {
  DisplaySettings d;
  const ColorRange k{-2, 3};
  d.base = BaseMode::Shaded;
  EXPECT_TRUE(view_legends(d, false, false, true, k, 1).empty());
  EXPECT_TRUE(view_legends(d, true, false, true, k, 1).empty());
  EXPECT_TRUE(view_legends(d, false, true, true, k, 1).empty());  // D without the comparison
  auto shaded_difference = view_legends(d, true, true, true, k, 0.5);
  ASSERT_EQ(shaded_difference.size(), 1u);
  EXPECT_EQ(shaded_difference[0].title, "distance to Gregory");
  EXPECT_EQ(shaded_difference[0].range.lo, -0.5);
  EXPECT_EQ(shaded_difference[0].range.hi, 0.5);
  d.base = BaseMode::Curvature;
  d.curvature = CurvatureKind::Mean;
  auto curvature = view_legends(d, true, false, true, k, 0.5);
  ASSERT_EQ(curvature.size(), 1u);  // one range for both panels
  EXPECT_EQ(curvature[0].title, "mean curvature");
  // With distances in the other panes the base pane keeps a legend of its own.
  auto both = view_legends(d, true, true, true, k, 0.5);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].title, "Gregory: mean curvature");
  EXPECT_EQ(both[0].range.hi, 3);
  EXPECT_EQ(both[1].title, "distance to Gregory");
  auto gb_base = view_legends(d, true, true, true, k, 0.5, "Generalized Bezier");
  EXPECT_EQ(gb_base[0].title, "Generalized Bezier: mean curvature");
  EXPECT_EQ(gb_base[1].title, "distance to Generalized Bezier");
  // No surface shown (an empty scene, free curves only): nothing is coloured, no legend.
  EXPECT_TRUE(view_legends(d, false, false, false, k, 0.5).empty());
  EXPECT_TRUE(view_legends(d, true, true, false, k, 0.5).empty());
}

TEST(EditorLayout, ComparisonTitlesFitTheirPanel) {
  auto width = [](const std::string& t) { return 7.0 * double(t.size()); };  // 7 px a letter
  const FaceScheme G = FaceScheme::Gregory, B = FaceScheme::GB;
  const std::string full = compare_pane_title(B, false, true, G, 1000, width);
  EXPECT_EQ(full, "Generalized Bezier, coloured by distance to Gregory");
  const std::string mid = compare_pane_title(B, false, true, G, 200, width);
  EXPECT_EQ(mid, "GB: distance to Gregory");
  EXPECT_LE(width(mid), 200);
  EXPECT_EQ(compare_pane_title(B, false, true, G, 40, width), "GB");
  EXPECT_EQ(compare_pane_title(B, false, false, G, 1000, width), "Generalized Bezier");
  EXPECT_EQ(compare_pane_title(B, false, false, G, 100, width), "GB");
  EXPECT_EQ(compare_pane_title(G, true, true, G, 100, width), "Gregory (base)");
  EXPECT_EQ(compare_pane_title(G, true, false, G, 100, width), "Gregory");
  // Any scheme: GB as the base, Gregory coloured by its distance to it.
  EXPECT_EQ(compare_pane_title(G, false, true, B, 1000, width),
            "Gregory, coloured by distance to Generalized Bezier");
}

TEST(EditorProbe, ReadsTheDistanceOfTheDifferenceColouring) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces gregory(s, 12, FaceScheme::Gregory, "g"), gb(s, 12, FaceScheme::GB, "b");
  DifferenceField f;
  ProbeHit probe;
  probe.surface = 0;
  probe.triangle = 5;
  EXPECT_FALSE(f.distance_at(probe));  // nothing computed yet
  f.follow(gregory.draw(), gb.draw(), 1);
  const SurfaceMesh& m = f.scene().surfaces[0];
  const auto& tri = m.triangles[5];
  // At a corner of the triangle: that sample's distance; inside: the barycentric mix.
  probe.b1 = 1;
  probe.b2 = 0;
  EXPECT_EQ(*f.distance_at(probe), m.mean[tri[1]]);
  probe.b1 = 0.25;
  probe.b2 = 0.5;
  EXPECT_NEAR(*f.distance_at(probe),
              0.25 * m.mean[tri[0]] + 0.25 * m.mean[tri[1]] + 0.5 * m.mean[tri[2]], 1e-15);
  probe.surface = 7;
  EXPECT_FALSE(f.distance_at(probe));
  probe.surface = 0;
  probe.triangle = int(m.triangles.size());
  EXPECT_FALSE(f.distance_at(probe));
}

// WCAG 2 relative luminance and contrast ratio, computed here from the definition.
double luminance(const ThemeColour& c) {
  auto lin = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
  return 0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2]);
}
double contrast(const ThemeColour& a, const ThemeColour& b) {
  const double x = luminance(a), y = luminance(b);
  return (std::max(x, y) + 0.05) / (std::min(x, y) + 0.05);
}

TEST(EditorTheme, TextAndHintsReadableOnEveryBackground) {
  for (const ThemeColour& bg : {kThemeWindow, kThemeFrame, kThemeMenuBar, kThemePopup}) {
    EXPECT_GE(contrast(kThemeText, bg), 7.0);      // body text: WCAG AAA
    EXPECT_GE(contrast(kThemeHintText, bg), 4.5);  // hints, help, disabled: WCAG AA
  }
  // Hints stay quieter than the text they explain.
  EXPECT_LT(luminance(kThemeHintText), luminance(kThemeText));
}

// A GB dome over the regular hexagon whose normal S_u x S_v points down (-z): seen from the iso
// direction (above), it shows its back.
std::shared_ptr<GBPatch> dome_facing_down() {
  const int n = 6, d = 4;
  std::vector<Vec3> p(GBPatch::point_count(n, d));
  const GBPatch shape(n, d, p);
  for (int k = 0; k < shape.layers(); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) {
        const Vec2 a = shape.polygon().vertex(i - 1), b = shape.polygon().vertex(i);
        const Vec2 q = (a + (double(j) / d) * (b - a)) * (1.0 - 0.8 * k / d);
        // Mirrored in y: the domain's counter-clockwise sides run clockwise seen from above.
        p[shape.index(i, j, k)] = {q.x, -q.y, 0.3 * k};
      }
  p[0] = {0, 0, 0.9};
  return std::make_shared<GBPatch>(n, d, std::move(p));
}

TEST(EditorView, APatchOpensFacingTheCamera) {
  Scene s;
  s.patches.push_back({"dome", dome_facing_down()});
  const LiveSurfaces live(s, 24, std::nullopt, "dome");
  const DrawScene* scenes[1] = {&live.draw()};
  const SurfaceMesh* meshes[1] = {&live.draw().surfaces[0]};
  const Vec3 n = mean_normal(meshes);
  ASSERT_LT(n.z, -0.5);  // the premise: the front faces down
  ViewNavigator nav;
  nav.open_view(scenes, 1.6);
  EXPECT_TRUE(nav.framed());
  const Camera& c = nav.camera();
  // The eye is on the front side: looking against the mean normal.
  EXPECT_GT(glm::dot(glm::normalize(n), c.eye() - c.target), 0.5 * glm::length(c.eye() - c.target));
  // Every surface point is inside the view, and the surface fills a good part of it.
  const ViewRect rect{0, 0, 1600, 1000};
  double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
  for (const Vec3& q : live.draw().surfaces[0].positions) {
    const auto w = project_to_window(c, rect, q);
    ASSERT_TRUE(w);
    EXPECT_TRUE(rect.contains(*w));
    lo_x = std::min(lo_x, w->x), hi_x = std::max(hi_x, w->x);
    lo_y = std::min(lo_y, w->y), hi_y = std::max(hi_y, w->y);
  }
  EXPECT_GT(std::max((hi_x - lo_x) / rect.width, (hi_y - lo_y) / rect.height), 0.7);
  // An empty scene: the iso view of the unit cube about the origin.
  ViewNavigator empty;
  empty.open_view({}, 1.6);
  EXPECT_TRUE(empty.framed());
  EXPECT_NEAR(glm::length(empty.camera().target), 0, 1e-12);
}

TEST(EditorView, EachComparisonPanelIsFramedTightly) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces gregory(s, 16, FaceScheme::Gregory, "g"), gb(s, 16, FaceScheme::GB, "b");
  const DrawScene* scenes[2] = {&gregory.draw(), &gb.draw()};
  EditorLayout l{{1600, 1000}, 20, 26, 1.0};
  const ViewRect half = l.panels(2)[0];
  ViewNavigator nav;
  nav.preset(ViewPreset::Iso, Box{Vec3(-1), Vec3(3)}, half.aspect());  // framed on a loose box
  nav.frame_tightly(scenes, half.aspect());
  // Every point drawn is inside the half panel and touches (within the margin) one of its sides.
  double reach = 0;
  for (const Vec3& q : framing_points(scenes)) {
    const auto w = project_to_window(nav.camera(), half, q);
    ASSERT_TRUE(w);
    EXPECT_TRUE(half.contains(*w));
    reach = std::max({reach, std::abs(w->x - half.x - half.width / 2) / (half.width / 2),
                      std::abs(w->y - half.y - half.height / 2) / (half.height / 2)});
  }
  EXPECT_GT(reach, 0.85);
}

// Difference colouring adds the legend column beside the GB panel: both halves get narrower
// while the window does not. The model framed across them stays inside, and comes back to the
// same size when the column goes; a window resize keeps the vertical extent.
TEST(EditorView, TheLegendColumnDoesNotCutAFramedModel) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces gregory(s, 16, FaceScheme::Gregory, "g"), gb(s, 16, FaceScheme::GB, "b");
  const DrawScene* scenes[2] = {&gregory.draw(), &gb.draw()};
  const std::vector<Vec3> points = framing_points(scenes);
  EditorLayout l{{1600, 1000}, 20, 26, 1.0};
  const ViewRect wide = l.panels(2)[0];
  ViewNavigator nav;
  nav.frame_tightly(scenes, wide.aspect());
  nav.follow_panel(l.display, 2, wide.width);
  const Camera framed = nav.camera();
  auto widest = [&](const ViewRect& rect) {  // the model's widest reach from the panel centre
    double reach = 0;
    for (const Vec3& q : points) {
      const auto w = project_to_window(nav.camera(), rect, q);
      EXPECT_TRUE(w);
      if (w) reach = std::max(reach, std::abs(w->x - rect.x - rect.width / 2) / (rect.width / 2));
    }
    return reach;
  };
  const double reach = widest(wide);
  ASSERT_GT(reach, 0.85);  // the premise: the model spans the panel
  l.legends = 1;
  const ViewRect narrow = l.panels(2)[0];
  ASSERT_LT(narrow.width, 0.95 * wide.width);
  nav.follow_panel(l.display, 2, narrow.width);
  EXPECT_LT(widest(narrow), 1.0);
  EXPECT_NEAR(widest(narrow), reach, 0.02);
  l.legends = 0;
  nav.follow_panel(l.display, 2, wide.width);
  EXPECT_NEAR(nav.camera().distance, framed.distance, 1e-9 * framed.distance);
  // A smaller window or the comparison turning off: no zoom.
  const double back = nav.camera().distance;
  l.display = {1200, 1000};
  nav.follow_panel(l.display, 2, l.panels(2)[0].width);
  nav.follow_panel(l.display, 1, l.panels(1)[0].width);
  EXPECT_EQ(nav.camera().distance, back);
  // Framing again at the new width: the next call only records it.
  nav.frame_tightly(scenes, narrow.aspect());
  const double d = nav.camera().distance;
  nav.follow_panel(l.display, 1, narrow.width);
  EXPECT_EQ(nav.camera().distance, d);
}

TEST(EditorView, OrbitAboutTheSelectionKeepsTheModelOnScreen) {
  const Scene s = read_scene(kAssets / "default.json");
  const LiveSurfaces live(s, 16, std::nullopt, "default");
  const DrawScene* scenes[1] = {&live.draw()};
  const std::vector<Vec3> model = orbit_sample(scenes, 4096);
  ASSERT_GT(model.size(), 500u);
  EXPECT_LE(model.size(), 4096u);
  const ViewRect rect{0, 20, 1260, 850};
  // The pivot: a corner of the model (a selected vertex near the edge of the view).
  const Vec3 pivot = s.network->vertices[5];
  // How far the model gets out of the view during a long orbit drag beyond what cannot be
  // helped (a model seen wider than the view overflows by half the excess on each side), in
  // pixels: 0 when it never does.
  auto drag = [&](bool keep) {
    ViewNavigator nav;
    nav.open_view(scenes, rect.aspect());
    const ScreenBox start = screen_box(nav.camera(), rect, model);
    EXPECT_GE(start.lo.x, rect.x);  // the premise: the model starts inside the view
    EXPECT_LE(start.hi.y, rect.y + rect.height);
    nav.begin(ViewNavigator::Gesture::Orbit, Vec2(600, 400), pivot,
              keep ? model : std::vector<Vec3>{});
    double out = 0;
    for (int step = 1; step <= 150; ++step) {
      nav.move(Vec2(600 + 9 * step, 400 + 3 * step), rect);
      const ScreenBox b = screen_box(nav.camera(), rect, model);
      if (b.empty()) return 1e9;
      const double ex = std::max(0.0, 0.5 * ((b.hi.x - b.lo.x) - rect.width)),
                   ey = std::max(0.0, 0.5 * ((b.hi.y - b.lo.y) - rect.height));
      out = std::max({out, rect.x - b.lo.x - ex, rect.y - b.lo.y - ey,
                      b.hi.x - (rect.x + rect.width) - ex, b.hi.y - (rect.y + rect.height) - ey});
    }
    nav.end();
    return out;
  };
  // Without the rule the model swings off the view (the premise of the test) ...
  EXPECT_GT(drag(false), 100.0);
  // ... with it every point stays on screen (to a pixel: a pan is exact only at one depth).
  EXPECT_LE(drag(true), 1.0);
}

TEST(EditorView, KeepInViewLeavesThePivotWhereItIsWhenTheModelStaysIn) {
  Camera c = preset_camera(ViewPreset::Iso, Box{Vec3(-1), Vec3(1)}, 1.5);
  const ViewRect rect{0, 0, 1500, 1000};
  const std::vector<Vec3> model = {Vec3(-0.3), Vec3(0.3), Vec3(0.3, -0.3, 0), Vec3(-0.3, 0.3, 0)};
  const Vec3 pivot(0.2, 0.1, 0);
  const ScreenBox was = screen_box(c, rect, model);
  const Vec2 pivot_before = *project_to_window(c, rect, pivot);
  orbit_about(c, pivot, 0.1, 0.05);
  const Camera orbited = c;
  keep_in_view(c, rect, model, was);
  EXPECT_EQ(c.target, orbited.target);  // still inside: no correction
  EXPECT_LT(glm::length(*project_to_window(c, rect, pivot) - pivot_before), 1e-6);
  // A model already out of place is not pulled back, only kept from going further.
  Camera d = preset_camera(ViewPreset::Iso, Box{Vec3(-1), Vec3(1)}, 1.5);
  pan_pixels(d, rect, 0.9 * rect.width, 0);  // far to the right, partly out of the view
  const ScreenBox now = screen_box(d, rect, model);
  ASSERT_GT(now.hi.x, rect.width);
  const Camera panned = d;
  ScreenBox further = now;  // it was further out: left alone
  further.lo.x += 20, further.hi.x += 20;
  keep_in_view(d, rect, model, further);
  EXPECT_EQ(d.target, panned.target);
  ScreenBox nearer = now;  // it went further out than it was: back to there
  nearer.lo.x -= 30, nearer.hi.x -= 30;
  keep_in_view(d, rect, model, nearer);
  const ScreenBox back = screen_box(d, rect, model);
  EXPECT_NEAR(back.lo.x + back.hi.x, nearer.lo.x + nearer.hi.x, 0.5);
  EXPECT_NEAR(back.lo.y + back.hi.y, now.lo.y + now.hi.y, 0.5);
}

}  // namespace
}  // namespace pl
