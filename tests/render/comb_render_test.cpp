// Curvature combs in the renderer: the `combs` mode token, and a render whose comb pixels are
// where the core's comb geometry projects (teeth and envelope), nowhere else.
#include <gtest/gtest.h>

#include <cmath>

#include "core/curve/curvature_comb.hpp"
#include "render/display_settings.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

TEST(CombMode, ParsesCombsAsAnOverlay) {
  const DisplaySettings a = parse_display_mode("shaded+network+combs");
  EXPECT_TRUE(a.combs);
  EXPECT_TRUE(a.network_curves);
  EXPECT_EQ(a.base, BaseMode::Shaded);
  const DisplaySettings b = parse_display_mode("combs");
  EXPECT_TRUE(b.combs);
  EXPECT_EQ(b.base, BaseMode::Shaded);
  EXPECT_TRUE(parse_display_mode("mean+borders+combs").combs);
  EXPECT_FALSE(parse_display_mode("shaded+network").combs);
  EXPECT_THROW(parse_display_mode("shaded+comb"), std::invalid_argument);
  EXPECT_THROW(parse_display_mode("combs+"), std::invalid_argument);
  EXPECT_THROW(parse_display_mode("Combs"), std::invalid_argument);
  try {
    parse_display_mode("network+curvature-combs");
    ADD_FAILURE() << "accepted a bad token";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"curvature-combs\""), std::string::npos) << e.what();
  }
}

// A flat grey square at z = 0 with a cubic arc above it, bulging towards +y and rising in z.
DrawScene arc_scene() {
  DrawScene d;
  d.surfaces.push_back(test::floor_square(1.5));
  const BezierCurve arc({{-1, -0.5, 0.2}, {-0.6, 0.9, 0.3}, {0.6, 0.9, 0.3}, {1, -0.5, 0.2}});
  Polyline l;
  for (int i = 0; i <= 64; ++i) l.push_back(arc.point(i / 64.0));
  d.network_curves.push_back(l);
  d.network_combs.push_back(curvature_comb(arc, 16));
  return d;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 d = b - a;
  const double t =
      glm::dot(d, d) > 0 ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

// How far from its segment a pixel centre the line shader touches can be, at the 400x300 size of
// these tests (pixel_scale 0.75, so the envelope, the widest comb line, is w = 1.8 * 0.75 px):
// the fragment's alpha reaches 0 at w/2 + 0.5 px across the line, the quad runs h/2 px past each
// end (h = w/2 + 1, line.geom.glsl), and a 4x MSAA sample lies up to sqrt(0.375^2 + 0.125^2) px
// from its pixel's centre.
const double kEnvelopeWidth = 1.8 * 0.75;
const double kCombPixelReach =
    std::hypot(0.5 * kEnvelopeWidth + 0.5, 0.5 * (0.5 * kEnvelopeWidth + 1.0)) +
    std::hypot(0.375, 0.125);

struct CombPixels {
  int changed = 0, stray = 0;
  double worst = 0;                // px from the nearest expected segment
  std::vector<bool> changed_mask;  // per pixel, row-major from the top
};

// Renders `scene` from the top at 400x300 with network curves, without and with combs, and
// measures the pixels the combs changed against the segments (in pixels) computed by
// `segments(pixel, scale, cap)` from the core's comb.
template <class Segments>
CombPixels measure_combs(const DrawScene& scene, Segments segments) {
  SceneRenderer renderer;
  GpuScene gpu(scene);
  EXPECT_GT(gpu.comb_scale(), 0);
  FrameRequest r;
  r.width = 400;
  r.height = 300;
  r.settings = parse_display_mode("shaded+network");
  r.camera = preset_camera(ViewPreset::Top, scene.bounds(), 400.0 / 300.0);
  r.panels.emplace_back().scene = &gpu;
  const Image plain = render_frame(renderer, r);
  r.settings = parse_display_mode("shaded+network+combs");
  const Image combs = render_frame(renderer, r);
  const glm::dmat4 vp = r.camera.projection(400.0 / 300.0) * r.camera.view();
  auto pixel = [&](const Vec3& p) {
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    return glm::dvec2((c.x / c.w + 1) / 2 * r.width, (1 - c.y / c.w) / 2 * r.height);
  };
  // The renderer's cap: 3 reference lengths (times the scale multiplier, 1 here).
  const std::vector<std::pair<glm::dvec2, glm::dvec2>> segs =
      segments(pixel, gpu.comb_scale(), 3 * gpu.comb_reference_length());
  CombPixels m;
  m.changed_mask.assign(std::size_t(r.width) * r.height, false);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      int d = 0;
      for (int k = 0; k < 4; ++k)
        d = std::max(d, std::abs(int(plain.at(x, y)[k]) - combs.at(x, y)[k]));
      if (d <= 2) continue;  // rasteriser noise
      ++m.changed;
      m.changed_mask[std::size_t(y) * r.width + x] = true;
      double nearest = 1e300;
      for (const auto& [a, b] : segs)
        nearest = std::min(nearest, distance_to_segment({x + 0.5, y + 0.5}, a, b));
      m.worst = std::max(m.worst, nearest);
      if (nearest > kCombPixelReach) ++m.stray;
    }
  return m;
}

// The tip the renderer draws: scale * tooth, shortened to `cap` (the flat-topped stretch).
Vec3 capped_tip(const CurvatureComb& c, std::size_t i, double scale, double cap) {
  const Vec3 t = scale * c.teeth[i];
  const double len = glm::length(t);
  return c.points[i] + (len > cap ? t * (cap / len) : t);
}

TEST(CombRender, CombPixelsLieOnTheProjectedTeethAndEnvelope) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene scene = arc_scene();
  const CurvatureComb& comb = scene.network_combs[0];
  const CombPixels m = measure_combs(scene, [&](auto pixel, double scale, double cap) {
    std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
    for (std::size_t i = 0; i < comb.points.size(); ++i) {
      // The longest tooth must be under the renderer's cap: this test is about uncapped tips.
      EXPECT_LT(glm::length(scale * comb.teeth[i]), cap);
      if (i % comb.tooth_stride == 0)
        segments.emplace_back(pixel(comb.points[i]), pixel(comb.tip(i, scale)));
      if (i + 1 < comb.points.size())
        segments.emplace_back(pixel(comb.tip(i, scale)), pixel(comb.tip(i + 1, scale)));
    }
    return segments;
  });
  std::printf("comb render: %d changed pixels, farthest %.2f px from a comb segment (bound %.2f)\n",
              m.changed, m.worst, kCombPixelReach);
  EXPECT_GT(m.changed, 400);  // 17 teeth and an envelope around the arc, not a few stray pixels
  EXPECT_EQ(m.stray, 0);
}

// A cubic with a near-cusp at t = 1/2 (C'(1/2) = (0.75 delta, 0, 0), C''(1/2) about (6, -6, 0)):
// teeth grow far past the cap around it, to about 1e25 at the cusp sample itself, where
// scale * tooth squared overflows a float.
DrawScene cusp_scene(double delta) {
  DrawScene d;
  d.surfaces.push_back(test::floor_square(1.5));
  const BezierCurve c({{-1, -0.6, 0.2}, {1, 0.4, 0.2}, {-1 + delta, 0.4, 0.2}, {1, -0.6, 0.2}});
  Polyline l;
  for (int i = 0; i <= 64; ++i) l.push_back(c.point(i / 64.0));
  d.network_curves.push_back(l);
  d.network_combs.push_back(curvature_comb(c, 16));
  return d;
}

// Teeth past the cap are drawn at the cap, in their own direction: the envelope runs flat at the
// cap's distance there. Checked on the pixels: every comb pixel is near the capped teeth and
// envelope, and the capped tips (the cusp's included, about 1e25 curvature units long) are drawn.
TEST(CombRender, TeethPastTheCapAreDrawnAtTheCapEvenNearACusp) {
  PATCHLAB_REQUIRE_GL();
  // delta 1e-2: one sample past the cap; 1e-12: a stretch of them, the middle one ~1e25.
  for (const auto& [delta, min_capped] : {std::pair{1e-2, 1}, std::pair{1e-12, 3}}) {
    const DrawScene scene = cusp_scene(delta);
    const CurvatureComb& comb = scene.network_combs[0];
    const std::size_t cusp = comb.points.size() / 2;  // t = 1/2
    ASSERT_EQ(cusp % comb.tooth_stride, 0u);          // a drawn tooth
    if (delta < 1e-6) {
      ASSERT_GT(glm::length(comb.teeth[cusp]), 1e24);  // the overflow case
    }
    std::vector<glm::dvec2> capped_tips;  // pixels where a capped tooth ends
    int capped = 0;
    const CombPixels m = measure_combs(scene, [&](auto pixel, double scale, double cap) {
      std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
      for (std::size_t i = 0; i < comb.points.size(); ++i) {
        const bool over = glm::length(scale * comb.teeth[i]) > cap;
        capped += over;
        if (i % comb.tooth_stride == 0) {
          segments.emplace_back(pixel(comb.points[i]), pixel(capped_tip(comb, i, scale, cap)));
          if (over) capped_tips.push_back(pixel(capped_tip(comb, i, scale, cap)));
        }
        if (i + 1 < comb.points.size())
          segments.emplace_back(pixel(capped_tip(comb, i, scale, cap)),
                                pixel(capped_tip(comb, i + 1, scale, cap)));
      }
      return segments;
    });
    std::printf("cusp delta %g: %d samples past the cap, %d changed pixels, farthest %.2f px\n",
                delta, capped, m.changed, m.worst);
    EXPECT_GE(capped, min_capped) << delta;
    EXPECT_GT(m.changed, 400) << delta;
    EXPECT_EQ(m.stray, 0) << delta;
    // Each capped tip is drawn: a changed pixel within half a pixel of it.
    ASSERT_FALSE(capped_tips.empty());
    for (const glm::dvec2& tip : capped_tips) {
      bool drawn = false;
      for (int dy = -1; dy <= 1 && !drawn; ++dy)
        for (int dx = -1; dx <= 1 && !drawn; ++dx) {
          const int x = int(std::floor(tip.x)) + dx, y = int(std::floor(tip.y)) + dy;
          if (x >= 0 && y >= 0 && x < 400 && y < 300 &&
              glm::length(glm::dvec2(x + 0.5, y + 0.5) - tip) <= 1.0)
            drawn = drawn || m.changed_mask[std::size_t(y) * 400 + x];
        }
      EXPECT_TRUE(drawn) << "delta " << delta << ": capped tip at " << tip.x << ", " << tip.y;
    }
  }
}

TEST(CombRender, CommonCombLengthForSideBySidePanels) {
  PATCHLAB_REQUIRE_GL();
  DrawScene a = arc_scene(), b = arc_scene();
  for (Vec3& t : b.network_combs[0].teeth) t *= 2.0;  // twice the curvature
  GpuScene ga(a), gb(b);
  DisplaySettings s = parse_display_mode("network+combs");
  const DisplaySettings common = common_comb_length(s, {&ga, &gb});
  ASSERT_TRUE(common.comb_length);
  EXPECT_DOUBLE_EQ(*common.comb_length, std::min(ga.comb_scale(), gb.comb_scale()));
  EXPECT_FALSE(common_comb_length(s, {&ga}).comb_length);
  s.comb_length = 0.5;
  EXPECT_EQ(*common_comb_length(s, {&ga, &gb}).comb_length, 0.5);
}

}  // namespace
}  // namespace pl
