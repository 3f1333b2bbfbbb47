// The editor's highlights in the renderer: a tint over chosen surfaces that stays hidden where
// another surface is in front, and guide lines (grid, selected curves) drawn in their colour
// where seen and faintly where hidden. Read back from an offscreen render seen from the top.
#include <gtest/gtest.h>

#include "render/gl.hpp"
#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

constexpr int kSize = 240;

struct TopView {
  // A floor at z = 0 over [-1.5, 1.5]^2 (surface 0) and, above part of it, a raised square at
  // z = 0.5 over [0, 1]^2 (surface 1).
  DrawScene scene = [] {
    DrawScene d;
    d.surfaces.push_back(test::bezier_mesh(1, 1, test::square_corners(-1.5, 1.5, 0), 4, "floor"));
    d.surfaces.push_back(test::bezier_mesh(1, 1, test::square_corners(0, 1, 0.5), 4, "raised"));
    return d;
  }();
  Camera camera = preset_camera(ViewPreset::Top, scene.bounds(), 1.0);
  Viewport viewport{0, 0, kSize, kSize, 1.0};

  // The image pixel (top-left origin) where p projects.
  std::array<int, 2> pixel(const Vec3& p) const {
    const glm::dvec4 c = camera.projection(1.0) * camera.view() * glm::dvec4(p, 1.0);
    return {int((c.x / c.w + 1) * 0.5 * kSize), int((1 - c.y / c.w) * 0.5 * kSize)};
  }
};

// Draws the scene, then `extra`, and reads the image back.
template <class F>
Image render(const SceneRenderer& renderer, const GpuScene& gpu, const TopView& v, F extra) {
  OffscreenTarget target(kSize, kSize);
  target.bind();
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(gpu, v.camera, DisplaySettings{}, {-1, 1}, v.viewport);
  extra();
  Image image(kSize, kSize);
  target.read_into(image, 0, 0);
  return image;
}

std::array<int, 3> rgb(const Image& image, std::array<int, 2> px) {
  const uint8_t* p = image.at(px[0], px[1]);
  return {p[0], p[1], p[2]};
}

TEST(HighlightRender, TintShowsOnlyWhereTheSurfaceIsSeen) {
  PATCHLAB_REQUIRE_GL();
  const TopView v;
  const GpuScene gpu(v.scene);
  const SceneRenderer renderer;
  const int floor[1] = {0};
  const Image plain = render(renderer, gpu, v, [] {});
  const Image tinted = render(renderer, gpu, v, [&] {
    renderer.draw_tint(gpu, floor, v.camera, {1.0f, 0.0f, 0.0f, 0.5f}, v.viewport);
  });
  // The floor where it is seen: half way to red.
  const auto seen = v.pixel({-1, -1, 0});
  const auto a = rgb(plain, seen), b = rgb(tinted, seen);
  EXPECT_GT(b[0], a[0] + 30) << "red " << a[0] << " -> " << b[0];
  EXPECT_LT(b[1], a[1] - 30);
  EXPECT_LT(b[2], a[2] - 30);
  // Where the raised square hides the floor, nothing changes.
  const auto hidden = v.pixel({0.5, 0.5, 0.5});
  EXPECT_EQ(rgb(plain, hidden), rgb(tinted, hidden));
  // Indices outside the scene are ignored.
  const int bad[2] = {-1, 7};
  const Image none = render(renderer, gpu, v, [&] {
    renderer.draw_tint(gpu, bad, v.camera, {1.0f, 0.0f, 0.0f, 0.5f}, v.viewport);
  });
  EXPECT_EQ(none.rgba, plain.rgba);
}

TEST(HighlightRender, GuideLinesSeenAndFaintlyHidden) {
  PATCHLAB_REQUIRE_GL();
  const TopView v;
  const GpuScene gpu(v.scene);
  const SceneRenderer renderer;
  // A line on the floor at y = 0.5, passing under the raised square for x in [0, 1].
  GpuPrimitives line;
  line.set({Vec3(-1.2, 0.5, 0), Vec3(1.2, 0.5, 0)}, {});
  const std::array<float, 4> blue = {0.0f, 0.0f, 1.0f, 1.0f};
  const Image plain = render(renderer, gpu, v, [] {});
  const Image faint = render(renderer, gpu, v, [&] {
    renderer.draw_guides(line, v.camera, blue, 4.0f, true, v.viewport);
  });
  const Image solid = render(renderer, gpu, v, [&] {
    renderer.draw_guides(line, v.camera, blue, 4.0f, false, v.viewport);
  });
  const auto seen = v.pixel({-0.6, 0.5, 0}), under = v.pixel({0.5, 0.5, 0});
  // Seen: the line's colour.
  EXPECT_LT(rgb(solid, seen)[0], 20);
  EXPECT_GT(rgb(solid, seen)[2], 235);
  // Hidden under the raised square: nothing without show_hidden, a faint blue with it.
  EXPECT_EQ(rgb(solid, under), rgb(plain, under));
  const auto p = rgb(plain, under), f = rgb(faint, under);
  EXPECT_GT(f[2], p[2]);
  EXPECT_LT(f[0], p[0]);
  EXPECT_GT(f[0], 100);  // faint: most of the surface's colour remains
}

}  // namespace
}  // namespace pl
