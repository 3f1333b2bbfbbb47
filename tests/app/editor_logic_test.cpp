// The editor's GUI-free logic: XDG paths, default scene, file listing, preferences, point names,
// invocation, the probe and the comparison's distance field.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "render/draw_scene_builder.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/editor_invocation.hpp"
#include "app/editor/logic/editor_paths.hpp"
#include "app/editor/logic/file_listing.hpp"
#include "app/editor/logic/grid_scene.hpp"
#include "app/editor/logic/live_curves.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/point_names.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "cli_test_util.hpp"
#include "core/analysis/surface_distance.hpp"
#include "core/patch/side_curve.hpp"

namespace pl {
namespace {

namespace fs = std::filesystem;

TEST(EditorPaths, XdgRules) {
  EXPECT_EQ(*xdg_dir("/x/cfg", "/home/u", ".config"), fs::path("/x/cfg/patchlab"));
  EXPECT_EQ(*xdg_dir(nullptr, "/home/u", ".config"), fs::path("/home/u/.config/patchlab"));
  EXPECT_EQ(*xdg_dir("", "/home/u", ".local/state"), fs::path("/home/u/.local/state/patchlab"));
  // Relative values are invalid by the XDG spec: never the working directory.
  EXPECT_EQ(*xdg_dir("rel", "/home/u", ".config"), fs::path("/home/u/.config/patchlab"));
  EXPECT_FALSE(xdg_dir("rel", "also-rel", ".config"));
  EXPECT_FALSE(xdg_dir(nullptr, nullptr, ".config"));
}

TEST(EditorPaths, DefaultSceneIsFoundFromAnywhere) {
  const auto p = default_scene_path(fs::path("/nonexistent/bin/patchlab"));
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->is_absolute());
  EXPECT_TRUE(fs::is_regular_file(*p));
  EXPECT_EQ(p->filename(), "default.json");
}

TEST(EditorFileListing, DirectoriesFirstFilteredSorted) {
  test::TempDir dir;
  const fs::path root = dir.file("b.json", "{}").parent_path();
  dir.file("A.GBP", "");
  dir.file("c.txt", "");
  dir.file(".hidden.json", "{}");
  fs::create_directories(root / "sub");
  const DirListing l = list_directory(root, {".json", ".gbp"});
  ASSERT_TRUE(l.error.empty());
  ASSERT_EQ(l.entries.size(), 3u);
  EXPECT_EQ(l.entries[0].name, "sub");
  EXPECT_TRUE(l.entries[0].directory);
  EXPECT_EQ(l.entries[1].name, "A.GBP");
  EXPECT_EQ(l.entries[2].name, "b.json");
  EXPECT_FALSE(list_directory(root / "missing", {}).error.empty());
  EXPECT_EQ(resolve_typed_name("/d", "part", ".json"), fs::path("/d/part.json"));
  EXPECT_EQ(resolve_typed_name("/d", "/e/x.gbp", ".json"), fs::path("/e/x.gbp"));
}

TEST(EditorPreferences, RoundTripAndBadValuesIgnored) {
  Preferences p = default_preferences();
  p.display.base = BaseMode::Zebra;
  p.display.curvature = CurvatureKind::Kmax;
  p.display.zebra_count = 21;
  p.fine_density = 40;
  p.last_directory = "/some/where";
  const Preferences q = preferences_from_text(preferences_to_text(p));
  EXPECT_EQ(q.display.base, BaseMode::Zebra);
  EXPECT_EQ(q.display.curvature, CurvatureKind::Kmax);
  EXPECT_EQ(q.display.zebra_count, 21);
  EXPECT_EQ(q.fine_density, 40);
  EXPECT_EQ(q.last_directory, "/some/where");
  const Preferences bad = preferences_from_text("fine_density = -3\nbase = nonsense\nzzz\n");
  EXPECT_EQ(bad.fine_density, default_preferences().fine_density);
  EXPECT_EQ(bad.display.base, BaseMode::Isophotes);  // the editor starts with isophotes
}

// The isophote mode draws its lines; the other modes start without them (zebra stripes would
// get black lines over black stripes, Shaded would look like the isophote mode), and the
// switch in the zebra mode asks for lines over the stripes.
TEST(EditorPreferences, IsophoteLinesFollowTheMode) {
  DisplaySettings d = default_preferences().display;
  EXPECT_EQ(d.base, BaseMode::Isophotes);
  EXPECT_TRUE(isophote_switch(d) && shows_isophote_lines(d));
  set_isophote_switch(d, false);  // the mode's own lines stay
  EXPECT_TRUE(shows_isophote_lines(d));
  for (BaseMode m : {BaseMode::Shaded, BaseMode::Zebra, BaseMode::Curvature}) {
    d.base = m;
    EXPECT_FALSE(isophote_switch(d)) << int(m);
    EXPECT_FALSE(shows_isophote_lines(d)) << int(m);
  }
  d.base = BaseMode::Zebra;
  set_isophote_switch(d, true);
  EXPECT_TRUE(shows_isophote_lines(d));
  Preferences p;
  p.display = d;
  const Preferences kept = preferences_from_text(preferences_to_text(p));
  EXPECT_TRUE(shows_isophote_lines(kept.display));
  set_isophote_switch(d, false);
  EXPECT_FALSE(shows_isophote_lines(d));
  d.base = BaseMode::Shaded;
  set_isophote_switch(d, true);
  EXPECT_TRUE(shows_isophote_lines(d));
  d.base = BaseMode::Zebra;  // lines over shading do not put them over stripes
  EXPECT_FALSE(shows_isophote_lines(d));
}

TEST(EditorPointNames, ParseWhatDescribePrints) {
  for (const PointRef& r :
       {PointRef::vertex(3), PointRef::handle(5, 1), PointRef::patch_point(0, 7)})
    EXPECT_EQ(parse_point_name(describe(r)), r);
  EXPECT_FALSE(parse_point_name("vertex"));
  EXPECT_FALSE(parse_point_name("edge 2 handle 2"));
  EXPECT_FALSE(parse_point_name("vertex 1 extra"));
}

TEST(EditorInvocation, EditorOrCli) {
  using V = std::vector<std::string>;
  EXPECT_TRUE(is_editor_invocation(V{}));
  EXPECT_TRUE(is_editor_invocation(V{"scene.json"}));
  EXPECT_TRUE(is_editor_invocation(V{"--bench-drag"}));
  EXPECT_FALSE(is_editor_invocation(V{"analyze", "x.json"}));
  EXPECT_FALSE(is_editor_invocation(V{"--help"}));
  EXPECT_FALSE(is_editor_invocation(V{"frobnicate"}));
}

TEST(EditorProbe, HitsTheNearestTriangleAndInterpolates) {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}};
  m.normals.assign(6, Vec3(0, 0, 1));
  m.mean = {0, 1, 2, 10, 10, 10};
  m.gaussian = m.kmin = m.kmax = m.mean;
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const Ray down{Vec3(0.25, 0.5, 5), Vec3(0, 0, -1)};
  const std::vector<SurfaceMesh> meshes{m};
  const auto hit = probe_surfaces(meshes, down);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->position.z, 2, 1e-12);  // the upper triangle is hit first
  EXPECT_NEAR(hit->mean, 10, 1e-12);
  const Ray up{Vec3(0.25, 0.5, 1), Vec3(0, 0, -1)};
  const auto low = probe_surfaces(meshes, up);
  ASSERT_TRUE(low);
  EXPECT_NEAR(low->mean, 0.25 * 1 + 0.5 * 2, 1e-12);  // barycentric in (x, y)
  EXPECT_FALSE(probe_surfaces(meshes, Ray{Vec3(3, 3, 5), Vec3(0, 0, -1)}));
}

TEST(EditorDifference, SignedDistanceBetweenParallelPlanes) {
  // A fine grid at z = 0 and a coarser, shifted grid at z = 0.1: every distance is 0.1 and
  // positive on the side the normals point to.
  auto grid = [](int n, double z, double shift) {
    SurfaceMesh m;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        m.positions.push_back(Vec3(shift + double(j) / n, double(i) / n, z));
    m.normals.assign(m.positions.size(), Vec3(0, 0, 1));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({a, d, c});
      }
    return m;
  };
  const SurfaceMesh lower = grid(20, 0, 0), upper = grid(7, 0.1, 0.01);
  const std::vector<double> d =
      signed_distance_to(upper.positions, {lower.positions, lower.normals, lower.triangles});
  for (std::size_t i = 0; i < d.size(); ++i)
    if (upper.positions[i].x <= 1) {
      EXPECT_NEAR(d[i], 0.1, 1e-12) << i;
    }
  const std::vector<double> back =
      signed_distance_to(lower.positions, {upper.positions, upper.normals, upper.triangles});
  for (std::size_t i = 0; i < back.size(); ++i)
    if (lower.positions[i].x >= 0.01) {
      EXPECT_NEAR(back[i], -0.1, 1e-12) << i;
    }
}

TEST(EditorLiveSurfaces, IncrementalSyncMatchesAFreshEvaluation) {
  Scene s = make_grid_network_scene(2, 2);
  LiveSurfaces live(s, 8, std::nullopt, "grid");
  const std::vector<uint64_t> before = [&] {
    std::vector<uint64_t> r;
    for (const SurfaceMesh& m : live.draw().surfaces) r.push_back(m.revision);
    return r;
  }();
  set_point_position(s, PointRef::vertex(0), Vec3(-0.1, -0.05, 0.2));  // a corner: one face
  const std::vector<int> changed = live.sync(s, 1);
  EXPECT_FALSE(changed.empty());
  EXPECT_LT(changed.size(), 4u);  // the far faces are untouched and not re-uploaded
  LiveSurfaces fresh(s, 8, std::nullopt, "grid");
  ASSERT_EQ(fresh.draw().surfaces.size(), live.draw().surfaces.size());
  for (std::size_t k = 0; k < fresh.draw().surfaces.size(); ++k) {
    const SurfaceMesh &a = live.draw().surfaces[k], &b = fresh.draw().surfaces[k];
    const bool was_changed = std::find(changed.begin(), changed.end(), int(k)) != changed.end();
    EXPECT_EQ(a.revision != before[k], was_changed);
    for (std::size_t i = 0; i < a.positions.size(); ++i)
      EXPECT_LT(glm::length(a.positions[i] - b.positions[i]), 1e-12);
  }
  EXPECT_EQ(live.points().find(PointRef::vertex(0)), 0);
  EXPECT_EQ(live.points().positions[0], Vec3(-0.1, -0.05, 0.2));
}

// Borders and combs (LiveCurves) of live surfaces against those of a fresh evaluation.
void expect_same_curves(const LiveCurves& a, const LiveCurves& b) {
  ASSERT_EQ(a.borders().size(), b.borders().size());
  EXPECT_EQ(a.on_network(), b.on_network());
  std::vector<const CurvatureComb*> ca = a.border_refs(), cb = b.border_refs();
  const std::vector<const CurvatureComb*> na = a.network_comb_refs(), nb = b.network_comb_refs();
  ASSERT_EQ(ca.size(), cb.size());
  ASSERT_EQ(na.size(), nb.size());
  ca.insert(ca.end(), na.begin(), na.end());
  cb.insert(cb.end(), nb.begin(), nb.end());
  for (std::size_t c = 0; c < ca.size(); ++c) {
    // Exact: the curves come from the patches, whose control points a sync sets to the scene's
    // bit for bit (only the tessellated samples are updated by axpy), so both sides evaluate the
    // same patches at the same parameters.
    EXPECT_EQ(ca[c]->points, cb[c]->points) << c;
    EXPECT_EQ(ca[c]->teeth, cb[c]->teeth) << c;
    EXPECT_EQ(ca[c]->tooth_stride, cb[c]->tooth_stride) << c;
  }
}

// Free curves get combs in the editor like network edges: one per span, equal to the CLI's
// (free_curve_combs), none without combs; a moved point resamples its own curve only.
TEST(EditorLiveCurves, FreeCurvesHaveCombsAndAnEditResamplesItsCurveOnly) {
  Scene s = load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" /
                       "bspline-knot-multiplicity.json");
  ASSERT_GE(s.curves.size(), 2u);
  LiveSurfaces live(s, 8, std::nullopt, "curves", 0);
  LiveCurves curves(false, 12);
  curves.follow(s, live.surfaces(), 0, 0, {});
  EXPECT_TRUE(curves.free_curve_combs().empty());
  EXPECT_TRUE(curves.free_comb_refs().empty());
  curves.configure(true, 12);
  curves.follow(s, live.surfaces(), 0, 0, {});
  ASSERT_EQ(curves.free_curve_combs().size(), s.curves.size());
  EXPECT_EQ(curves.last_free_curves_resampled(), s.curves.size());
  std::size_t total = 0;
  for (std::size_t c = 0; c < s.curves.size(); ++c) {
    const std::vector<CurvatureComb> expected = free_curve_combs(s.curves[c], 12);
    ASSERT_EQ(curves.free_curve_combs()[c].size(), curve_spans(s.curves[c]).size());
    ASSERT_EQ(curves.free_curve_combs()[c].size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(curves.free_curve_combs()[c][k].points, expected[k].points);
      EXPECT_EQ(curves.free_curve_combs()[c][k].teeth, expected[k].teeth);
      EXPECT_FALSE(expected[k].teeth.empty());
    }
    total += expected.size();
  }
  EXPECT_EQ(curves.free_comb_refs().size(), total);

  set_point_position(s, PointRef::curve_point(1, 2), s.curves[1].points[2] + Vec3(0, 0.3, 0.1));
  live.sync(s, 1);
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 0, 1, {}));
  EXPECT_EQ(curves.last_free_curves_resampled(), 1u);
  const std::vector<CurvatureComb> moved = free_curve_combs(s.curves[1], 12);
  for (std::size_t k = 0; k < moved.size(); ++k)
    EXPECT_EQ(curves.free_curve_combs()[1][k].teeth, moved[k].teeth);

  // A point of a long B-spline: the comb is resampled on the p + 1 spans the point moves only,
  // and equals the whole curve's comb sampled afresh.
  SceneCurve long_curve;
  long_curve.type = CurveType::BSpline;
  long_curve.degree = 3;
  for (int i = 0; i < 1000; ++i) long_curve.points.push_back({0.01 * i, std::sin(0.05 * i), 0});
  for (int i = 0; i < 1004; ++i) long_curve.knots.push_back(std::clamp(i - 3, 0, 997));
  s.curves.push_back(long_curve);
  live.sync(s, 2);
  curves.follow(s, live.surfaces(), 1, 2, {});
  std::size_t all_spans = 0;  // a curve added: every curve resampled
  for (const SceneCurve& c : s.curves) all_spans += curve_spans(c).size();
  EXPECT_EQ(all_spans, total + 997);
  EXPECT_EQ(curves.last_free_spans_resampled(), all_spans);
  set_point_position(s, PointRef::curve_point(int(s.curves.size()) - 1, 500),
                     s.curves.back().points[500] + Vec3(0, 0.2, 0.1));
  live.sync(s, 3);
  curves.follow(s, live.surfaces(), 2, 3, {});
  EXPECT_EQ(curves.last_free_curves_resampled(), 1u);
  EXPECT_EQ(curves.last_free_spans_resampled(), 4u);
  const std::vector<CurvatureComb> fresh = free_curve_combs(s.curves.back(), 12);
  ASSERT_EQ(curves.free_curve_combs().back().size(), fresh.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    EXPECT_EQ(curves.free_curve_combs().back()[k].points, fresh[k].points) << k;
    EXPECT_EQ(curves.free_curve_combs().back()[k].teeth, fresh[k].teeth) << k;
  }

  // Combs off again: none kept.
  curves.configure(false, 12);
  curves.follow(s, live.surfaces(), 3, 3, {});
  EXPECT_TRUE(curves.free_curve_combs().empty());
}

TEST(EditorLiveCurves, FollowIncrementalSyncsAndResampleWithoutReevaluating) {
  Scene s = make_grid_network_scene(2, 2);
  LiveSurfaces live(s, 8, std::nullopt, "grid", 0);
  LiveCurves curves(false, 12);
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 0, 0, {}));
  EXPECT_FALSE(curves.follow(s, live.surfaces(), 0, 0, {}));  // up to date: nothing to do
  // Combs off: bare borders (points, no teeth), no network combs.
  ASSERT_EQ(curves.borders().size(), 4u);
  for (const CurvatureComb* c : curves.border_refs()) {
    EXPECT_EQ(c->points.size(), std::size_t(kCurveSegments) + 1);
    EXPECT_TRUE(c->teeth.empty());
  }
  EXPECT_TRUE(curves.network_combs().empty());
  // Every border here is a network face's side: its comb is drawn with the network's.
  EXPECT_EQ(curves.border_on_network(), std::vector<bool>(16, true));

  // Combs on: resampled from the same surfaces, no sync.
  curves.configure(true, 12);
  const uint64_t serial = curves.serial();
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 0, 0, {}));
  EXPECT_GT(curves.serial(), serial);
  EXPECT_EQ(curves.network_combs().size(), s.network->edges.size());
  for (const CurvatureComb* c : curves.border_refs()) EXPECT_EQ(c->teeth.size(), c->points.size());

  // An edit: only the changed surfaces' curves are recomputed, and all match a fresh build.
  set_point_position(s, PointRef::vertex(0), Vec3(-0.1, -0.05, 0.2));
  const std::vector<int> changed = live.sync(s, 1);
  ASSERT_FALSE(changed.empty());
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 0, 1, changed));
  LiveSurfaces fresh(s, 8, std::nullopt, "grid", 1);
  LiveCurves fresh_curves(true, 12);
  fresh_curves.follow(s, fresh.surfaces(), 1, 1, {});
  expect_same_curves(curves, fresh_curves);
  // The curves do not depend on the density: a coarse evaluation of the same revision shares them.
  LiveSurfaces coarse(s, 3, std::nullopt, "grid", 1);
  EXPECT_FALSE(curves.follow(s, coarse.surfaces(), 0, 1, changed));

  // A sync from a revision the curves were not at (e.g. after an undo the other density saw):
  // everything is resampled, not just `changed`.
  set_point_position(s, PointRef::vertex(8), Vec3(2.1, 2.05, -0.3));
  live.sync(s, 2);
  set_point_position(s, PointRef::vertex(0), Vec3(0, 0, 0));
  const std::vector<int> last = live.sync(s, 3);
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 2, 3, last));  // the curves are at 1, not 2
  LiveSurfaces fresh3(s, 8, std::nullopt, "grid", 3);
  LiveCurves fresh3_curves(true, 12);
  fresh3_curves.follow(s, fresh3.surfaces(), 3, 3, {});
  expect_same_curves(curves, fresh3_curves);

  // A new tooth count resamples every comb from the surfaces as they are.
  curves.configure(true, 5);
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 3, 3, {}));
  const CurvatureComb expected = side_comb(live.surfaces().surfaces[2].evaluator->patch(), 1, 5);
  EXPECT_EQ(curves.borders()[2][1].points, expected.points);
  EXPECT_EQ(curves.borders()[2][1].teeth, expected.teeth);
  EXPECT_THROW(curves.configure(true, 0), std::invalid_argument);
  // Combs off again: no teeth anywhere.
  curves.configure(false, 5);
  EXPECT_TRUE(curves.follow(s, live.surfaces(), 3, 3, {}));
  for (const CurvatureComb* c : curves.border_refs()) EXPECT_TRUE(c->teeth.empty());
  EXPECT_TRUE(curves.network_combs().empty());
}

}  // namespace
}  // namespace pl
