// The default view faces a patch's front: the iso view while it sees the front, otherwise the
// mean normal's side; and a patch facing away from the iso direction renders front side only,
// filling a good part of the frame.
#include "render/default_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/io/scene_io.hpp"
#include "core/patch/flip_orientation.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

Vec3 iso_direction() {
  return -preset_camera(ViewPreset::Iso, Box(), 1.0).forward();
}

SurfaceMesh evaluated(std::shared_ptr<Patch> patch, int density = 24) {
  static TessellationCache cache;
  PatchEvaluator ev(std::move(patch), cache.get(patch->domain(), density));
  return make_surface_mesh(ev, "patch");
}

std::shared_ptr<Patch> wave() {
  return read_scene(test::asset("bezier-wave.json")).patches.at(0).patch;
}

TEST(DefaultView, KeepsTheIsoViewOfAPatchFacingIt) {
  const SurfaceMesh m = evaluated(wave());
  const SurfaceMesh* meshes[] = {&m};
  EXPECT_GT(glm::length(mean_normal(meshes)), 0.9);
  EXPECT_LT(glm::length(default_view_direction(meshes) - iso_direction()), 1e-12);
}

TEST(DefaultView, LooksAtTheFrontOfAPatchFacingAway) {
  const SurfaceMesh m = evaluated(std::shared_ptr<Patch>(flipped_orientation(*wave()).patch));
  const SurfaceMesh* meshes[] = {&m};
  const Vec3 n = glm::normalize(mean_normal(meshes));
  EXPECT_LT(glm::dot(n, iso_direction()), 0);  // the iso view would see its back
  const Vec3 d = default_view_direction(meshes);
  EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
  // Along the normal, tilted 15 degrees towards the iso direction.
  EXPECT_NEAR(glm::dot(d, n), std::cos(15.0 * M_PI / 180), 1e-9);
}

TEST(DefaultView, ClosedShapesKeepTheIsoView) {
  const DrawScene d = test::file_draw_scene(test::asset("gregory-blob-closed.json"));
  std::vector<const SurfaceMesh*> meshes;
  for (const SurfaceMesh& m : d.surfaces) meshes.push_back(&m);
  EXPECT_LT(glm::length(mean_normal(meshes)), 0.05);
  EXPECT_LT(glm::length(default_view_direction(meshes) - iso_direction()), 1e-12);
}

// Covered pixels of a transparent render and the share of them showing the back-face colour
// (terracotta: red well above blue; the front is a cool grey).
struct Coverage {
  double covered = 0, back = 0;
};
Coverage coverage(const Image& image) {
  long n = 0, back = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    if (image.rgba[i + 3] < 255) continue;
    ++n;
    back += int(image.rgba[i]) - int(image.rgba[i + 2]) > 30;
  }
  return {double(n) / (image.width * image.height), n ? double(back) / n : 0.0};
}

TEST(DefaultView, APatchFacingAwayIsSeenFromTheFrontAndFillsTheFrame) {
  PATCHLAB_REQUIRE_GL();
  DrawScene d;
  d.surfaces.push_back(evaluated(std::shared_ptr<Patch>(flipped_orientation(*wave()).patch)));
  SceneRenderer renderer;
  const GpuScene gpu(d);
  DisplaySettings shaded = parse_display_mode("shaded");
  shaded.transparent = true;  // the surface's pixels are the opaque ones
  const Coverage seen = coverage(render_frame(renderer, test::one_panel(gpu, d, shaded, 800, 600)));
  // The iso view of the same patch shows its back.
  const Coverage iso =
      coverage(render_frame(renderer, test::one_panel(gpu, d, shaded, 800, 600, ViewPreset::Iso)));
  std::printf("flipped wave: default view covers %.2f (back %.3f), iso view %.2f (back %.3f)\n",
              seen.covered, seen.back, iso.covered, iso.back);
  EXPECT_GT(iso.back, 0.95);
  EXPECT_LT(seen.back, 0.01);
  EXPECT_GT(seen.covered, 0.3);
}

// With combs drawn, the default view frames their tips too (a comb stands out of the curve by
// up to kCombCap reference lengths, and the tight framing on the curve alone cut it off).
TEST(DefaultView, FramesTheCombTipsWhenCombsAreDrawn) {
  // A flat cubic whose curvature peaks near its ends: long teeth where the frame is tight.
  const BezierCurve curve({{0, 0, 0}, {0.1, 1.0, 0}, {2.9, 1.0, 0}, {3, 0, 0}});
  DrawScene d;
  Polyline line;
  for (int i = 0; i <= 64; ++i) line.push_back(curve.point(i / 64.0));
  d.free_curves.push_back(line);
  d.free_curve_combs.push_back(curvature_comb(curve, 32));
  const DrawScene* scenes[] = {&d};
  DisplaySettings settings = parse_display_mode("shaded+combs");
  std::vector<Vec3> tips;
  append_comb_tips(d, settings, tips);
  ASSERT_EQ(tips.size(), d.free_curve_combs[0].points.size());
  const double aspect = 4.0 / 3.0;
  auto outside = [&](const Camera& c) {
    const glm::dmat4 m = c.projection(aspect) * c.view();
    int out = 0;
    for (const Vec3& p : tips) {
      const glm::dvec4 q = m * glm::dvec4(p, 1.0);
      out += std::abs(q.x / q.w) > 1.0 || std::abs(q.y / q.w) > 1.0;
    }
    return out;
  };
  EXPECT_EQ(outside(default_camera(scenes, aspect, &settings)), 0);
  std::printf("comb tips outside the frame: %d of %zu without the combs' framing, 0 with it\n",
              outside(default_camera(scenes, aspect)), tips.size());
  // The tips are where the renderer draws them: point + scale * tooth, within the cap.
  const double scale =
      automatic_comb_scale(d.free_curve_combs, glm::length(d.bounds().hi - d.bounds().lo));
  const CurvatureComb& comb = d.free_curve_combs[0];
  const double cap = kCombCap * kDefaultCombFraction * glm::length(d.bounds().hi - d.bounds().lo);
  for (std::size_t i = 0; i < tips.size(); ++i) {
    const double len = glm::length(tips[i] - comb.points[i]);
    EXPECT_NEAR(len, std::min(cap, scale * glm::length(comb.teeth[i])), 1e-12) << i;
  }
  // Without combs shown, no tips are framed.
  const DisplaySettings shaded = parse_display_mode("shaded");
  EXPECT_EQ(framing_points(scenes, nullptr).size(), framing_points(scenes, &shaded).size());
  EXPECT_EQ(framing_points(scenes, &settings).size(),
            framing_points(scenes, &shaded).size() + tips.size());
}

}  // namespace
}  // namespace pl
