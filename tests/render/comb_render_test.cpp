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
  std::vector<Vec3> square;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) square.emplace_back(-1.5 + 3 * i, -1.5 + 3 * j, 0);
  d.surfaces.push_back(test::bezier_mesh(1, 1, square, 4, "floor"));
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

TEST(CombRender, CombPixelsLieOnTheProjectedTeethAndEnvelope) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene scene = arc_scene();
  SceneRenderer renderer;
  GpuScene gpu(scene);
  ASSERT_GT(gpu.comb_scale(), 0);
  FrameRequest r;
  r.width = 400;
  r.height = 300;
  r.settings = parse_display_mode("shaded+network");
  r.camera = preset_camera(ViewPreset::Top, scene.bounds(), 400.0 / 300.0);
  r.panels.push_back({&gpu, ""});
  const Image plain = render_frame(renderer, r);
  r.settings = parse_display_mode("shaded+network+combs");
  const Image combs = render_frame(renderer, r);

  // The comb's segments in pixels (top row first), at the scale the renderer uses.
  const CurvatureComb& comb = scene.network_combs[0];
  const double scale = gpu.comb_scale();
  const glm::dmat4 vp = r.camera.projection(400.0 / 300.0) * r.camera.view();
  auto pixel = [&](const Vec3& p) {
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    return glm::dvec2((c.x / c.w + 1) / 2 * r.width, (1 - c.y / c.w) / 2 * r.height);
  };
  std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
  for (std::size_t i = 0; i < comb.points.size(); ++i) {
    // The longest tooth must be under the renderer's cap, or the tips below would be wrong.
    ASSERT_LT(glm::length(scale * comb.teeth[i]), 3 * gpu.comb_reference_length());
    if (i % comb.tooth_stride == 0)
      segments.emplace_back(pixel(comb.points[i]), pixel(comb.tip(i, scale)));
    if (i + 1 < comb.points.size())
      segments.emplace_back(pixel(comb.tip(i, scale)), pixel(comb.tip(i + 1, scale)));
  }
  int changed = 0, stray = 0;
  double worst = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      int d = 0;
      for (int k = 0; k < 4; ++k)
        d = std::max(d, std::abs(int(plain.at(x, y)[k]) - combs.at(x, y)[k]));
      if (d <= 2) continue;  // rasteriser noise
      ++changed;
      double nearest = 1e300;
      for (const auto& [a, b] : segments)
        nearest = std::min(nearest, distance_to_segment({x + 0.5, y + 0.5}, a, b));
      worst = std::max(worst, nearest);
      // Half the envelope's width (1.8 px at this size times pixel_scale 0.75 floor... at most
      // 1.8) plus one pixel of feather and one of multisampling.
      if (nearest > 3.5) ++stray;
    }
  std::printf("comb render: %d changed pixels, farthest %.2f px from a comb segment\n", changed,
              worst);
  EXPECT_GT(changed, 400);  // 17 teeth and an envelope around the arc, not a few stray pixels
  EXPECT_EQ(stray, 0);
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
