// Text burned into an Image on the CPU with stb_easy_font (Debian libstb-dev, header only),
// so labels need no font file and look the same at every size. GL-free.
#pragma once

#include <string>

#include "render/image.hpp"

namespace pl {

// Width and height in pixels of `text` at integer `scale` (1 = the font's native ~7 px cap).
int text_width(const std::string& text, int scale);
int text_height(int scale);

// Draws `text` with its top-left corner at (x, y) (y down).
void draw_text(Image& image, int x, int y, const std::string& text, int scale,
               const std::array<float, 3>& rgb);

// Fills an axis-aligned rectangle with rounded corners of radius r, blended with alpha a.
void fill_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r,
                       const std::array<float, 3>& rgb, float a);

}  // namespace pl
