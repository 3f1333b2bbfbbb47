// Renders an unlit ("flat") curvature map of an exact paraboloid seen from the top and reads
// pixels back at surface samples: each pixel must show the colour map at the core's curvature
// there. The fragment value is interpolated from the sample and its ring of neighbours, so the
// pixel must match color_map(t) for some t between the ring's extremes (a narrow interval, which
// the test also checks so it cannot pass vacuously).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

// 8-bit output rounding (half a level) plus the float texture's linear interpolation between
// 1024 entries of a piecewise-linear map, which is exact except within one entry of a stop.
constexpr double kColorTolerance = 1.5 / 255.0;
// Guard against a vacuous pass: the ring of a checked sample may span at most this fraction of
// the map (a few of its distinguishable colours), so matching within the ring's interval means
// the colour really tracks the core value. At density 48 the rings span up to about 0.055.
constexpr double kMaxRingSpread = 0.08;

struct Readback {
  Image image;
  glm::dmat4 view_projection;
};

Readback render_top_view(const DrawScene& scene, const DisplaySettings& settings,
                         const ColorRange& range, int size) {
  SceneRenderer renderer;
  GpuScene gpu(scene);
  Camera camera = preset_camera(ViewPreset::Top, scene.bounds(), 1.0, true);
  OffscreenTarget target(size, size);
  target.bind();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(gpu, camera, settings, range, {0, 0, size, size, 1.0});
  Readback r{Image(size, size), camera.projection(1.0) * camera.view()};
  target.read_into(r.image, 0, 0);
  return r;
}

void check_curvature_map(CurvatureKind kind, const ColorRange& range) {
  const SurfaceMesh mesh = test::bezier_mesh(2, 2, test::paraboloid_points(), 48);
  DrawScene scene;
  scene.surfaces.push_back(mesh);
  DisplaySettings settings;
  settings.base = BaseMode::Curvature;
  settings.curvature = kind;
  settings.curvature_lighting = false;
  const int size = 240;
  const Readback r = render_top_view(scene, settings, range, size);

  std::vector<std::set<uint32_t>> ring(mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) ring[t[a]].insert(t[b]);
  const std::vector<double>& values = curvature_values(mesh, kind);

  int checked = 0;
  for (std::size_t i = 0; i < mesh.positions.size(); i += 7) {
    const Vec3& p = mesh.positions[i];
    if (std::max(std::abs(p.x), std::abs(p.y)) > 0.9) continue;  // away from the silhouette
    const glm::dvec4 c = r.view_projection * glm::dvec4(p, 1.0);
    const int px = static_cast<int>(std::floor((c.x / c.w + 1) / 2 * size));
    const int py = static_cast<int>(std::floor((1 - (c.y / c.w + 1) / 2) * size));
    ASSERT_TRUE(px >= 0 && px < size && py >= 0 && py < size);
    double tmin = 1, tmax = 0;
    for (uint32_t j : ring[i]) {
      tmin = std::min(tmin, range.normalized(values[j]));
      tmax = std::max(tmax, range.normalized(values[j]));
    }
    ASSERT_LT(tmax - tmin, kMaxRingSpread) << "sample " << i;
    const uint8_t* pixel = r.image.at(px, py);
    double best = 1e9;
    for (int s = 0; s <= 200; ++s) {
      const Rgb m = color_map(tmin + (tmax - tmin) * s / 200.0);
      double d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(pixel[k] / 255.0 - m[k]));
      best = std::min(best, d);
    }
    const Rgb expected = color_map(range.normalized(values[i]));
    EXPECT_LE(best, kColorTolerance)
        << curvature_name(kind) << " at sample " << i << " (" << p.x << ", " << p.y << "): value "
        << values[i] << " pixel (" << int(pixel[0]) << ", " << int(pixel[1]) << ", "
        << int(pixel[2]) << ") expected about (" << expected[0] * 255 << ", " << expected[1] * 255
        << ", " << expected[2] * 255 << ")";
    EXPECT_EQ(pixel[3], 255);
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

// z = r^2 / 2 has H = 1 and K = 1 at the apex, falling towards the corners; the ranges put the
// values across both halves of the map and across its stops.
TEST(CurvatureReadback, MeanCurvatureColoursMatchTheCore) {
  PATCHLAB_REQUIRE_GL();
  check_curvature_map(CurvatureKind::Mean, {-0.6, 1.2});
}

TEST(CurvatureReadback, GaussianCurvatureColoursMatchTheCore) {
  PATCHLAB_REQUIRE_GL();
  check_curvature_map(CurvatureKind::Gaussian, {-1.0, 1.1});
}

TEST(CurvatureReadback, KminColoursMatchTheCore) {
  PATCHLAB_REQUIRE_GL();
  check_curvature_map(CurvatureKind::Kmin, {-0.5, 1.5});
}

TEST(CurvatureReadback, TransparentBackgroundStaysClear) {
  PATCHLAB_REQUIRE_GL();
  DrawScene scene;
  scene.surfaces.push_back(test::bezier_mesh(2, 2, test::paraboloid_points(), 8));
  DisplaySettings settings;
  settings.transparent = true;
  const Readback r = render_top_view(scene, settings, {}, 64);
  // The paraboloid's square fills the view up to the framing margin; the corner pixel is outside.
  EXPECT_EQ(r.image.at(0, 0)[3], 0);
  EXPECT_EQ(r.image.at(32, 32)[3], 255);
}

}  // namespace
}  // namespace pl
