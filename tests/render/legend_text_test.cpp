// Text burned into pictures: the embedded TrueType font scales exactly, and the legend of a
// 4096 x 4096 picture has crisp text (sharp antialiased edges, neither blocky nor blurred), opaque
// behind it, against its golden image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "golden.hpp"
#include "render/default_view.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/text.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

TEST(LabelFont, IsEmbeddedAndScalesExactly) {
  EXPECT_GT(embedded_font_data().size(), 100000u);  // a real TrueType file, not a bitmap font
  const Font& f = Font::labels();
  const std::string text = "mean curvature -0.411";
  const double w10 = f.width(text, 10), w77 = f.width(text, 77);
  EXPECT_GT(w10, 50);
  EXPECT_NEAR(w77 / w10, 7.7, 1e-6);          // outlines scale linearly: no size steps
  EXPECT_NEAR(f.cap_height(100), 72.9, 0.5);  // DejaVu Sans: capitals 0.729 em
  // UTF-8 beyond ASCII: the minus sign and é are glyphs of the font, not the missing box.
  EXPECT_NE(f.width("\xE2\x88\x92", 20), f.width("\xEF\xBF\xBF", 20));
  EXPECT_GT(f.width("é", 20), 0);
}

TEST(LabelFont, DrawsInkWhereTheTextIs) {
  Image image(200, 40);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = 255;
  draw_text(image, 10, 10, "H", 2.0, {0, 0, 0});
  // A capital H at scale 2: 20 px font, capitals 14.6 px tall from y = 10 down.
  int ink_rows = 0;
  for (int y = 0; y < image.height; ++y) {
    bool ink = false;
    for (int x = 0; x < image.width; ++x) ink |= image.at(x, y)[0] < 128;
    ink_rows += ink;
    if (ink) {
      EXPECT_GE(y, 10);
      EXPECT_LE(y, 25);
    }
  }
  EXPECT_NEAR(ink_rows, 15, 1);
}

// Pixels of a text block by how much ink they carry: paper (< 15 %), ink (> 85 %) or partial, and
// the partial pixels between a paper and an ink pixel along rows (the width of an edge).
struct InkStats {
  int ink = 0, partial = 0;
  std::vector<int> edge_widths;  // per paper/ink transition along a row
  double partial_fraction() const { return double(partial) / std::max(1, ink + partial); }
  int median_edge() const {
    std::vector<int> w = edge_widths;
    if (w.empty()) return -1;
    std::nth_element(w.begin(), w.begin() + w.size() / 2, w.end());
    return w[w.size() / 2];
  }
};

InkStats ink_stats(const Image& image, int x0, int y0, int x1, int y1, const Rgb& paper) {
  InkStats s;
  for (int y = y0; y < y1; ++y) {
    int partial = 0, last = -1;  // last: 0 paper, 1 ink
    for (int x = x0; x < x1; ++x) {
      // Ink fraction from the green channel between the paper and the ink colours.
      const double ink =
          (paper[1] * 255 - image.at(x, y)[1]) / ((paper[1] - palette::kInk[1]) * 255);
      const int state = ink < 0.15 ? 0 : ink > 0.85 ? 1 : -1;
      if (state < 0) {
        ++s.partial;
        ++partial;
        continue;
      }
      s.ink += state;
      if (last >= 0 && state != last) s.edge_widths.push_back(partial);
      last = state;
      partial = 0;
    }
  }
  return s;
}

TEST(LegendAt4096, TextIsCrispAndMatchesTheGolden) {
  PATCHLAB_REQUIRE_GL();
  const DrawScene d = test::file_draw_scene(test::asset("default.json"));
  SceneRenderer renderer;
  const GpuScene gpu(d);
  const FrameRequest r = test::one_panel(gpu, d, parse_display_mode("mean"), 4096, 4096);
  const Image image = render_frame(renderer, r);
  const FrameLayout layout = frame_layout(r);
  ASSERT_TRUE(layout.legend);
  const int w = legend_width(*layout.legend, layout.scale);
  const int h = legend_height(layout.scale, layout.legend_bar);
  const Image legend = test::crop(image, layout.legend_x, layout.legend_y, w, h);
  test::compare_with_golden("legend-4096", legend);

  // The title's band: capitals of a ~77 px font. Crisp: edges one pixel of antialiasing wide
  // (an upscaled bitmap font has blocky edges without partial pixels, a blurred one wide bands
  // of them), so partial pixels are a small share of the ink.
  const int pad = static_cast<int>(std::lround(7 * layout.scale));
  const int cap = text_height(layout.scale);
  EXPECT_GT(cap, 50);
  const InkStats title = ink_stats(legend, pad, pad, w - pad, pad + cap, palette::kPanel);
  ASSERT_GT(title.edge_widths.size(), 500u);
  EXPECT_EQ(title.median_edge(), 1);
  EXPECT_GT(title.partial_fraction(), 0.03);
  EXPECT_LT(title.partial_fraction(), 0.3);
  std::printf("legend title at 4096 px: %d edges, median width %d px, partial share %.3f\n",
              int(title.edge_widths.size()), title.median_edge(), title.partial_fraction());
  // Opaque: the panel's paper pixels are exactly the panel colour, whatever is behind.
  const uint8_t* corner = legend.at(pad / 2 + 2, h / 2);
  EXPECT_EQ(corner[0], 255);
  EXPECT_EQ(corner[3], 255);
}

}  // namespace
}  // namespace pl
