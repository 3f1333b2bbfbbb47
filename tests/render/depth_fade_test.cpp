// Overlays behind a surface are faded, not hidden: pixels read back where a point, a net line and
// an arrow lie behind an opaque square carry a fraction of their colour (less than in front of it,
// more than nothing), and a point lying on a curved surface is drawn whole.
#include <gtest/gtest.h>

#include <cmath>

#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render/palette.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

constexpr int kSize = 400;

// The square [-1.5, 1.5]^2 at z = 0 seen from above (+z), orthographic, so model (x, y) maps to
// pixel (200 + 100 x, 200 - 100 y).
Camera top_camera() {
  Camera c;
  c.orthographic = true;
  c.yaw = -1.5707963267948966;
  c.pitch = 1.5707963267948966;
  c.target = Vec3(0.0);
  c.distance = 2.0 / std::tan(0.5 * c.fov_y);  // half height 2
  c.scene_radius = 3;
  return c;
}

Image render(const DrawScene& scene, const std::string& mode) {
  SceneRenderer renderer;
  GpuScene gpu(scene);
  FrameRequest r;
  r.width = r.height = kSize;
  r.settings = parse_display_mode(mode);
  r.point_key = false;
  r.panels.emplace_back().scene = &gpu;
  r.camera = top_camera();
  return render_frame(renderer, r);
}

DrawScene floor_only() {
  DrawScene d;
  d.surfaces.push_back(test::floor_square(1.5));
  return d;
}

Vec3 rgb_at(const Image& image, double x, double y) {
  const uint8_t* p = image.at(int(std::lround(200 + 100 * x)), int(std::lround(200 - 100 * y)));
  return {p[0], p[1], p[2]};
}

// How much of the overlay's colour a pixel carries over the plain floor: 0 nothing, 1 all of it
// (the same pixel of the scene with the overlay in front of the floor).
double strength(const Vec3& pixel, const Vec3& plain, const Vec3& in_front) {
  return glm::length(pixel - plain) / glm::length(in_front - plain);
}

TEST(DepthFade, PointsLinesAndArrowsBehindASurfaceAreFaded) {
  PATCHLAB_REQUIRE_GL();
  const Image plain = render(floor_only(), "shaded+control-net");
  // The same overlays in front of the floor (z = +0.5) and behind it (z = -0.5).
  Image rendered[2];
  for (int side = 0; side < 2; ++side) {
    DrawScene d = floor_only();
    const double z = side == 0 ? 0.5 : -0.5;
    d.net.points = {{-0.8, 0.8, z}, {0.2, -0.6, z}, {1.2, -0.6, z}};
    d.net.kinds = {ControlPointKind::Inner, ControlPointKind::Boundary, ControlPointKind::Boundary};
    d.net.segments = {{1, 2}};
    d.arrows.push_back({{-1.0, -1.0, z}, {0.2, -1.0, z}, ArrowKind::Tangent});
    rendered[side] = render(d, "shaded+control-net");
  }
  const Image& front = rendered[0];
  const Image& behind = rendered[1];
  struct Probe {
    const char* what;
    double x, y;
  };
  for (const Probe& p :
       {Probe{"point", -0.8, 0.8}, Probe{"line", 0.7, -0.6}, Probe{"arrow shaft", -0.6, -1.0}}) {
    const double s =
        strength(rgb_at(behind, p.x, p.y), rgb_at(plain, p.x, p.y), rgb_at(front, p.x, p.y));
    // Faded, not hidden: the hidden pass draws at 22 % (lines, arrows) or 30 % (points) opacity.
    EXPECT_GT(s, 0.12) << p.what << " behind the surface is hidden";
    EXPECT_LT(s, 0.5) << p.what << " behind the surface is not faded";
    std::printf("%s behind the surface: %.2f of its colour\n", p.what, s);
  }
  // In front, a point is its kind's colour.
  const Vec3 inner = rgb_at(front, -0.8, 0.8);
  const Rgb& expected = palette::kPointKinds[int(ControlPointKind::Inner)];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(inner[k], expected[k] * 255, 3) << k;
}

TEST(DepthFade, APointOnACurvedSurfaceIsDrawnWhole) {
  PATCHLAB_REQUIRE_GL();
  // Points lying on the bowl z = (x^2 + y^2) / 2 seen from above: the triangles around them are
  // chords, which lie above a convex surface, nearer the eye than the points, and the surface is
  // tilted up to 50 degrees under them. Each point's whole disc must still pass the depth test.
  DrawScene d;
  d.surfaces.push_back(test::bezier_mesh(2, 2, test::paraboloid_points(), 12, "bowl"));
  for (double x : {-0.9, -0.3, 0.4, 0.9})
    for (double y : {-0.7, 0.0, 0.8}) {
      d.net.points.emplace_back(x, y, 0.5 * (x * x + y * y));
      d.net.kinds.push_back(ControlPointKind::Inner);
    }
  SceneRenderer renderer;
  GpuScene gpu(d);
  FrameRequest r;
  r.width = r.height = kSize;
  r.settings = parse_display_mode("shaded+control-net");
  r.point_key = false;
  r.panels.emplace_back().scene = &gpu;
  r.camera = top_camera();
  const Image image = render_frame(renderer, r);
  const glm::dmat4 vp = r.camera.projection(1.0) * r.camera.view();
  const Rgb& inner = palette::kPointKinds[int(ControlPointKind::Inner)];
  // Pixel scale at 400 px is 0.75: discs 7.5 px wide; a ring 2 px from the centre is inside the
  // fill (the dark outline starts about 2.3 px out).
  for (const Vec3& p : d.net.points) {
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    const double px = (c.x / c.w * 0.5 + 0.5) * kSize, py = (0.5 - c.y / c.w * 0.5) * kSize;
    for (int a = 0; a < 8; ++a) {
      const double t = a * 0.785398;
      const uint8_t* q = image.at(int(px + 1.5 * std::cos(t)), int(py + 1.5 * std::sin(t)));
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(q[k], inner[k] * 255, 40) << "point (" << p.x << ", " << p.y << ") cut";
    }
  }
}

}  // namespace
}  // namespace pl
