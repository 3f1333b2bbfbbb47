// The editor's selection as the renderer draws it (SceneRenderer::draw_selection), read back from
// an offscreen render seen from the top: in the curvature colours the selected surface keeps the
// colour map's hue and saturation (the legend still reads it) and the selection shows as an
// outline in its colour; in the other modes it is tinted, as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/gl.hpp"
#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

constexpr int kSize = 240;
constexpr std::array<float, 3> kOrange = {0.96f, 0.62f, 0.16f};  // the editor's accent
const SelectionStyle kStyle = {{kOrange[0], kOrange[1], kOrange[2], 0.30f},
                               {kOrange[0], kOrange[1], kOrange[2], 1.0f},
                               3.5f,
                               true};

// z = -(x^2 + y^2) / 2 over [-1, 1]^2: mean curvature negative all over (with the normal up), so
// every pixel is on the blue side of the colour map, far in hue from the orange accent.
std::vector<Vec3> bowl_points() {
  std::vector<Vec3> p = test::paraboloid_points();
  for (Vec3& q : p) q.z = -q.z;
  return p;
}

// The bowl's border: its four sides as line segments.
std::vector<Vec3> bowl_border() {
  std::vector<Vec3> out;
  constexpr int kSteps = 32;
  auto z = [](double x, double y) { return -0.5 * (x * x + y * y); };
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < kSteps; ++k) {
      for (int e = 0; e < 2; ++e) {
        const double t = -1 + 2.0 * (k + e) / kSteps;
        const double x = side == 0 ? t : side == 1 ? 1 : side == 2 ? -t : -1;
        const double y = side == 0 ? -1 : side == 1 ? t : side == 2 ? 1 : -t;
        out.emplace_back(x, y, z(x, y));
      }
    }
  return out;
}

struct Bowl {
  DrawScene scene = [] {
    DrawScene d;
    d.surfaces.push_back(test::bezier_mesh(2, 2, bowl_points(), 24, "bowl"));
    return d;
  }();
  // Orthographic: the bowl's border is the square [-1, 1]^2 on screen.
  Camera camera = preset_camera(ViewPreset::Top, scene.bounds(), 1.0, true);
  Viewport viewport{0, 0, kSize, kSize, 1.0};

  std::array<double, 2> pixel(const Vec3& p) const {
    const glm::dvec4 c = camera.projection(1.0) * camera.view() * glm::dvec4(p, 1.0);
    return {(c.x / c.w + 1) * 0.5 * kSize, (1 - c.y / c.w) * 0.5 * kSize};
  }
};

template <class F>
Image render(const SceneRenderer& renderer, const GpuScene& gpu, const Bowl& b,
             const DisplaySettings& settings, F extra) {
  OffscreenTarget target(kSize, kSize);
  target.bind();
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(gpu, b.camera, settings, {-1, 1}, b.viewport);
  extra();
  Image image(kSize, kSize);
  target.read_into(image, 0, 0);
  return image;
}

struct Hsv {
  double hue, saturation, value;  // degrees, 0..1, 0..1
};

Hsv hsv(const uint8_t* p) {
  const double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
  const double hi = std::max({r, g, b}), lo = std::min({r, g, b}), c = hi - lo;
  double h = 0;
  if (c > 0) {
    if (hi == r)
      h = 60 * std::fmod((g - b) / c + 6, 6.0);
    else if (hi == g)
      h = 60 * ((b - r) / c + 2);
    else
      h = 60 * ((r - g) / c + 4);
  }
  return {h, hi > 0 ? c / hi : 0, hi};
}

double hue_distance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 360 - d);
}

DisplaySettings curvature_mode() {
  DisplaySettings s;
  s.base = BaseMode::Curvature;
  s.curvature = CurvatureKind::Mean;
  return s;
}

// The bowl drawn in `settings`: plain, and selected (its border the outline).
struct Renders {
  Image plain, selected;
};
Renders plain_and_selected(const Bowl& b, const DisplaySettings& settings) {
  const GpuScene gpu(b.scene);
  const SceneRenderer renderer;
  GpuPrimitives outline;
  outline.set(bowl_border(), {});
  const int bowl[1] = {0};
  return {render(renderer, gpu, b, settings, [] {}), render(renderer, gpu, b, settings, [&] {
            renderer.draw_selection(gpu, bowl, outline, b.camera, settings, kStyle, b.viewport);
          })};
}

TEST(SelectionRender, CurvatureColoursKeepTheirHueWhenSelected) {
  PATCHLAB_REQUIRE_GL();
  const Bowl b;
  const auto [plain, selected] = plain_and_selected(b, curvature_mode());
  // The bowl's square on screen, less a margin for the outline along its border.
  const auto lo = b.pixel({-1, 1, 0}), hi = b.pixel({1, -1, 0});
  ASSERT_GT(hi[0] - lo[0], 100) << "the bowl should fill most of the view";
  const int margin = 8;
  int compared = 0, kept = 0;
  double worst_hue = 0, worst_saturation = 0;
  for (int y = int(lo[1]) + margin; y < int(hi[1]) - margin; ++y)
    for (int x = int(lo[0]) + margin; x < int(hi[0]) - margin; ++x) {
      const Hsv a = hsv(plain.at(x, y)), c = hsv(selected.at(x, y));
      if (a.saturation < 0.15) continue;  // the map's near-white middle has no hue to keep
      ++compared;
      const double dh = hue_distance(a.hue, c.hue), ds = a.saturation - c.saturation;
      worst_hue = std::max(worst_hue, dh);
      worst_saturation = std::max(worst_saturation, ds);
      if (dh <= 4.0 && ds <= 0.05) ++kept;
    }
  ASSERT_GT(compared, 5000) << "the bowl's colours should be saturated blues";
  EXPECT_EQ(kept, compared) << "of " << compared << " pixels, " << compared - kept
                            << " changed colour: hue by up to " << worst_hue
                            << " degrees, saturation down by up to " << worst_saturation;

  // The selection shows: the accent along the border, where the plain render has none.
  auto orange = [](const uint8_t* p) {
    return std::abs(p[0] / 255.0 - kOrange[0]) < 0.1 && std::abs(p[1] / 255.0 - kOrange[1]) < 0.1 &&
           std::abs(p[2] / 255.0 - kOrange[2]) < 0.1;
  };
  int accent = 0, accent_before = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      accent += orange(selected.at(x, y));
      accent_before += orange(plain.at(x, y));
    }
  const double perimeter = 2 * ((hi[0] - lo[0]) + (hi[1] - lo[1]));
  EXPECT_EQ(accent_before, 0);
  EXPECT_GT(accent, 2 * perimeter) << "the outline should be about 3 pixels wide all round";
}

TEST(SelectionRender, OtherModesAreTinted) {
  PATCHLAB_REQUIRE_GL();
  const Bowl b;
  for (const BaseMode mode : {BaseMode::Shaded, BaseMode::Isophotes, BaseMode::Zebra}) {
    DisplaySettings settings;
    settings.base = mode;
    const auto [plain, selected] = plain_and_selected(b, settings);
    // The centre moves towards the orange: more red, less blue.
    const auto c = b.pixel({0, 0, 0});
    const uint8_t *p = plain.at(int(c[0]), int(c[1])), *s = selected.at(int(c[0]), int(c[1]));
    EXPECT_GT(int(s[0]) - int(s[2]), int(p[0]) - int(p[2]) + 20) << "mode " << int(mode);
  }
}

}  // namespace
}  // namespace pl
