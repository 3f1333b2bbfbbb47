// What the display modes promise a designer: the highlight colour is used by no colour map and no
// other overlay; zebra stripes carry no isophote lines unless asked for; the isophote mode looks
// clearly different from the shaded mode (with or without its lines).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render/palette.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

double distance(const Rgb& a, const Rgb& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(Palette, HighlightIsNoColourMapsAndNoOverlaysColour) {
  double to_map = 1e9;
  for (int i = 0; i <= 1000; ++i)
    to_map = std::min(to_map, distance(palette::kHighlight, color_map(i / 1000.0)));
  // The curvature map's nearest colour (its warm middle) is far from the highlight's yellow.
  EXPECT_GT(to_map, 0.5) << to_map;
  for (const Rgb& c : palette::kPointKinds) EXPECT_GT(distance(palette::kHighlight, c), 0.35);
  for (const Rgb& c :
       {palette::kNetLine, palette::kDerivedNetLine, palette::kTangentArrow, palette::kTwistArrow,
        palette::kNetworkCurve, palette::kBorder, palette::kCombTeeth, palette::kCombEnvelope})
    EXPECT_GT(distance(palette::kHighlight, c), 0.6);
  // Point kinds tell apart from each other.
  for (std::size_t i = 0; i < palette::kPointKinds.size(); ++i)
    for (std::size_t j = i + 1; j < palette::kPointKinds.size(); ++j)
      EXPECT_GT(distance(palette::kPointKinds[i], palette::kPointKinds[j]), 0.35) << i << " " << j;
}

TEST(Palette, HighlightedCurvesAreDrawnInTheHighlightColour) {
  PATCHLAB_REQUIRE_GL();
  DrawScene d;
  d.surfaces.push_back(test::bezier_mesh(3, 3, test::saddle_points(), 16, "saddle"));
  // The saddle's middle curve v = 1/2, on the surface.
  const BezierPatch patch(3, 3, test::saddle_points());
  Polyline middle;
  for (int i = 0; i <= 32; ++i) middle.push_back(patch.evaluate({i / 32.0, 0.5}).p);
  d.highlights.push_back(middle);
  SceneRenderer renderer;
  const GpuScene gpu(d);
  const Image image = render_frame(
      renderer, test::one_panel(gpu, d, parse_display_mode("gaussian"), 320, 240, ViewPreset::Top));
  int highlighted = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      highlighted +=
          distance({p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f}, palette::kHighlight) < 0.1;
    }
  // A 4 px line (3 px at this size) across the framed width, over the colour map: at least two
  // rows of pure highlight colour along it.
  EXPECT_GT(highlighted, 2 * 150);
}

Image render_saddle(DisplaySettings settings, ViewPreset view = ViewPreset::Iso) {
  DrawScene d;
  d.surfaces.push_back(test::bezier_mesh(3, 3, test::saddle_points(), 24, "saddle"));
  SceneRenderer renderer;
  const GpuScene gpu(d);
  settings.transparent = true;  // the surface's pixels are the opaque ones
  return render_frame(renderer, test::one_panel(gpu, d, settings, 400, 300, view));
}

// Mean absolute difference (0..255, over the colour channels) on the pixels covered in both.
double mean_difference(const Image& a, const Image& b) {
  double sum = 0;
  long n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] < 255 || b.rgba[i + 3] < 255) continue;
    for (int k = 0; k < 3; ++k) sum += std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k]));
    n += 3;
  }
  return n ? sum / n : 0;
}

TEST(DisplayModes, ZebraLeavesOutIsophoteLinesUnlessAskedFor) {
  PATCHLAB_REQUIRE_GL();
  DisplaySettings zebra = parse_display_mode("zebra");
  DisplaySettings with_overlay = zebra;
  with_overlay.isophote_lines = true;  // the editor's isophote checkbox left on
  EXPECT_FALSE(shows_isophote_lines(with_overlay));
  EXPECT_EQ(render_saddle(zebra, ViewPreset::Front).rgba,
            render_saddle(with_overlay, ViewPreset::Front).rgba);
  // Asked for by name: drawn.
  const DisplaySettings asked = parse_display_mode("zebra+isophotes");
  EXPECT_TRUE(asked.isophotes_over_zebra);
  EXPECT_TRUE(shows_isophote_lines(asked));
  EXPECT_GT(mean_difference(render_saddle(zebra, ViewPreset::Front),
                            render_saddle(asked, ViewPreset::Front)),
            1.0);
  // Over other modes the overlay stays.
  EXPECT_TRUE(shows_isophote_lines(parse_display_mode("mean+isophotes")));
}

TEST(DisplayModes, IsophoteModeLooksClearlyDifferentFromShaded) {
  PATCHLAB_REQUIRE_GL();
  const Image iso = render_saddle(parse_display_mode("isophotes"));
  const Image shaded = render_saddle(parse_display_mode("shaded"));
  const Image shaded_lines = render_saddle(parse_display_mode("shaded+isophotes"));
  const double plain = mean_difference(iso, shaded), lined = mean_difference(iso, shaded_lines);
  std::printf("isophote mode vs shaded: %.1f levels, vs shaded with lines: %.1f levels\n", plain,
              lined);
  EXPECT_GT(plain, 20.0);
  EXPECT_GT(lined, 15.0);
}

}  // namespace
}  // namespace pl
