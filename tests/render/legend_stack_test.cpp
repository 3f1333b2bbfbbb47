// draw_legends: the legends of a picture (the editor's screenshot) one under the other at its
// right edge. One legend is exactly draw_legend's; two are two separate opaque panels, each with
// its colour bar, inside the image. GL-free.
#include <gtest/gtest.h>

#include <cmath>

#include "render/legend.hpp"
#include "render/palette.hpp"

namespace pl {
namespace {

// The opaque white panels a column crosses (runs of at least 10 white pixels), as [top, bottom).
std::vector<std::pair<int, int>> panels_in_column(const Image& image, int x) {
  std::vector<std::pair<int, int>> runs;
  int start = -1;
  for (int y = 0; y <= image.height; ++y) {
    const bool white = y < image.height && image.at(x, y)[0] == 255 && image.at(x, y)[1] == 255 &&
                       image.at(x, y)[2] == 255 && image.at(x, y)[3] == 255;
    if (white && start < 0) start = y;
    if (!white && start >= 0) {
      if (y - start >= 10) runs.emplace_back(start, y);
      start = -1;
    }
  }
  return runs;
}

TEST(LegendStack, OneLegendIsDrawLegends) {
  for (const auto& [w, h] : {std::pair{800, 600}, std::pair{1920, 1080}, std::pair{300, 200}}) {
    const double scale = legend_scale(w, h);
    Image a(w, h), b(w, h);
    draw_legend(a, {-2, 3}, "mean curvature", scale);
    draw_legends(b, {{"mean curvature", {-2, 3}}}, scale);
    EXPECT_EQ(a.rgba, b.rgba) << w << "x" << h;
  }
}

TEST(LegendStack, TwoLegendsAreTwoPanelsOneUnderTheOther) {
  const int w = 1000, h = 600;
  const double scale = legend_scale(w, h);
  Image image(w, h);
  const std::vector<LegendSpec> legends = {{"Gregory: mean curvature", {-1.5, 2}},
                                           {"distance to Gregory", {-0.01, 0.01}}};
  draw_legends(image, legends, scale);
  // A column inside every panel's right padding (they are right-aligned at the margin).
  const int x = w - panel_margin(scale) - int(4 * scale) - 2;
  const auto runs = panels_in_column(image, x);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_GE(runs[0].first, 0);
  EXPECT_LE(runs[1].second, h);
  EXPECT_LT(runs[0].second, runs[1].first);
  // Each panel holds a colour bar: the colour map's top (hi) colour in its rows.
  const Rgb top = color_map(1.0);
  for (const auto& [y0, y1] : runs) {
    bool bar = false;
    for (int y = y0; y < y1 && !bar; ++y)
      for (int px = w / 2; px < w && !bar; ++px) {
        const uint8_t* p = image.at(px, y);
        bar = std::abs(p[0] - top[0] * 255) < 3 && std::abs(p[1] - top[1] * 255) < 3 &&
              std::abs(p[2] - top[2] * 255) < 3;
      }
    EXPECT_TRUE(bar) << "no colour bar in the panel at rows " << y0 << ".." << y1;
  }
  // Together no taller than one legend alone.
  Image alone(w, h);
  draw_legend(alone, legends[0].range, legends[0].title, scale);
  const auto one = panels_in_column(alone, x);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_LE(runs[1].second - runs[0].first, one[0].second - one[0].first + 2);
}

}  // namespace
}  // namespace pl
