// points_seen: marks drawn in 2D over a view (the editor's knot ticks and joint labels) ask the
// depth buffer whether a surface hides the curve point they mark. A curve on a floor passes under
// a raised square (seen from the top): its points under the square are hidden, the others and
// the points on the square itself are seen, in a multisampled target (the screenshot's and the
// tests') and a single-sampled one (the editor's reduced view).
#include "render/depth_probe.hpp"

#include <gtest/gtest.h>

#include "render/gl.hpp"
#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render/reduced_target.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

constexpr int kSize = 240;

// A floor at z = 0 over [-1.5, 1.5]^2, a raised square at z = 0.5 over [0, 1]^2, and a free
// curve on the floor at y = 0.5 that passes under the square for x in [0, 1].
DrawScene covered_curve() {
  DrawScene d;
  d.surfaces.push_back(test::bezier_mesh(1, 1, test::square_corners(-1.5, 1.5, 0), 4, "floor"));
  d.surfaces.push_back(test::bezier_mesh(1, 1, test::square_corners(0, 1, 0.5), 4, "raised"));
  d.free_curves.push_back({Vec3(-1.2, 0.5, 0), Vec3(1.2, 0.5, 0)});
  return d;
}

// The curve's marks: x from -1.1 to 1.1 in steps of 0.1 on the floor at y = 0.5.
std::vector<Vec3> marks() {
  std::vector<Vec3> p;
  for (int k = -11; k <= 11; ++k) p.emplace_back(0.1 * k, 0.5, 0.0);
  return p;
}

// Seen from the top, orthographic: the raised square covers the marks with x in [0, 1] exactly.
// In perspective it covers a little more (it is nearer the eye): `slack` leaves that out.
void expect_covered_marks_hidden(const std::vector<char>& seen, double slack = 0.05) {
  const std::vector<Vec3> p = marks();
  ASSERT_EQ(seen.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p[i].x;
    if (x > slack && x < 1 - slack) {
      EXPECT_EQ(seen[i], 0) << "x = " << x << " is under the raised square";
    } else if (x < -slack || x > 1 + slack) {
      EXPECT_EQ(seen[i], 1) << "x = " << x << " is in the open";
    }
  }
}

void draw(const SceneRenderer& renderer, const GpuScene& gpu, const Camera& camera) {
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(gpu, camera, DisplaySettings{}, {-1, 1}, {0, 0, kSize, kSize, 1.0});
}

TEST(DepthProbe, CurveMarksUnderASurfaceAreHidden) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene scene = covered_curve();
  const GpuScene gpu(scene);
  const SceneRenderer renderer;
  const Camera camera = preset_camera(ViewPreset::Top, scene.bounds(), 1.0, true);
  const Viewport v{0, 0, kSize, kSize, 1.0};

  OffscreenTarget multisampled(kSize, kSize);
  multisampled.bind();
  draw(renderer, gpu, camera);
  expect_covered_marks_hidden(points_seen(camera, v, marks()));
  // In perspective (the editor's default view) the same, the square a little larger.
  const Camera perspective = preset_camera(ViewPreset::Top, scene.bounds(), 1.0);
  draw(renderer, gpu, perspective);
  expect_covered_marks_hidden(points_seen(perspective, v, marks()), 0.25);
  draw(renderer, gpu, camera);
  // On the raised square's top (a surface point is on it, not behind it), and over it.
  const std::vector<Vec3> on_top = {Vec3(0.5, 0.5, 0.5), Vec3(0.25, 0.75, 0.5),
                                    Vec3(0.5, 0.5, 0.8)};
  for (char s : points_seen(camera, v, on_top)) EXPECT_EQ(s, 1);

  ReducedTarget single;
  single.bind(kSize, kSize);
  draw(renderer, gpu, camera);
  expect_covered_marks_hidden(points_seen(camera, v, marks()));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST(DepthProbe, ViewportOffsetAndPointsOutside) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene scene = covered_curve();
  const GpuScene gpu(scene);
  const SceneRenderer renderer;
  // The view in the right half of a wider target, as a comparison pane.
  OffscreenTarget target(2 * kSize, kSize);
  target.bind();
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Camera camera = preset_camera(ViewPreset::Top, scene.bounds(), 1.0, true);
  const Viewport v{kSize, 0, kSize, kSize, 1.0};
  renderer.draw(gpu, camera, DisplaySettings{}, {-1, 1}, v);
  expect_covered_marks_hidden(points_seen(camera, v, marks()));
  // Far outside the view (nothing drawn there can hide it) and behind the eye.
  const Vec3 eye = camera.eye(), back = eye - 10.0 * camera.forward();
  const std::vector<char> s = points_seen(camera, v, std::vector<Vec3>{Vec3(50, 0, 0), back});
  EXPECT_EQ(s[0], 1);
  EXPECT_EQ(s[1], 0);
  EXPECT_TRUE(points_seen(camera, v, {}).empty());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace pl
