// The curvature colour legend burned into the final image: a vertical bar of color_map() with
// numbered ticks at lo, lo/2, 0, hi/2, hi and a title. GL-free.
#pragma once

#include <string>

#include "render/color_map.hpp"
#include "render/image.hpp"

namespace pl {

// Tick labels, e.g. "-1.25", "0", "3.2e-05": 3 significant digits, no trailing noise.
std::string format_tick(double value);

// Draws the legend at the right edge of `image`, vertically centred. `scale` is the integer
// text scale (>= 1); everything else is sized from it.
void draw_legend(Image& image, const ColorRange& range, const std::string& title, int scale);

// Width in pixels the legend takes at the right edge, margins included, so panels can be laid
// out beside it.
int legend_reserved_width(const ColorRange& range, const std::string& title, int scale);

// The text scale for an image of this size: readable on 800 px, not shouting on 4096 px.
int legend_scale(int width, int height);

}  // namespace pl
