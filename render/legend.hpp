// The colour legend burned into the final image: an opaque panel with a vertical bar of
// color_map(), numbered ticks at lo, lo/2, 0, hi/2, hi and a title, in the label font. GL-free.
#pragma once

#include <string>
#include <vector>

#include "render/color_map.hpp"
#include "render/image.hpp"

namespace pl {

// What a legend shows: "mean curvature" over the frame's range, or the comparison's distance.
struct LegendSpec {
  std::string title;
  ColorRange range;
};

// Tick labels, e.g. "-1.25", "0", "3.2e-05": 3 significant digits, no trailing noise.
std::string format_tick(double value);

// The UI scale of burned-in text and panels for an image of this size (text.hpp's unit: 1 is a
// 10 px font): readable on 800 px, not shouting on 4096 px; continuous, so text scales exactly.
double legend_scale(int width, int height);

// The legend panel's size in pixels for a bar of bar_height pixels.
int legend_width(const LegendSpec& legend, double scale);
int legend_height(double scale, int bar_height);
// The bar height a legend gets in an image of this height: half of it, at least 40 px.
int legend_bar_height(int image_height);

// Draws the panel with its top-left corner at (x, y).
void draw_legend_at(Image& image, const LegendSpec& legend, double scale, int x, int y,
                    int bar_height);

// The legend at the right edge of `image`, vertically centred, and the width it takes there
// (margins included), so panels can be laid out beside it.
void draw_legend(Image& image, const ColorRange& range, const std::string& title, double scale);
int legend_reserved_width(const ColorRange& range, const std::string& title, double scale);

// Several legends at the right edge of `image`, one under the other (in order, right-aligned),
// the group vertically centred; they share the height a single legend would have, each bar at
// least 40 px (so with many they may reach past the image, as a single one may).
void draw_legends(Image& image, const std::vector<LegendSpec>& legends, double scale);

// The margin around legends and keys.
inline int panel_margin(double scale) {
  return static_cast<int>(8 * scale + 0.5);
}

}  // namespace pl
