// Text burned into an Image on the CPU with the embedded TrueType font (render/font.hpp), sized in
// UI units: `scale` 1 is a 10 px font (capitals about 7 px), and any positive scale is exact, so
// a label is equally crisp in an 800 px and a 4096 px picture. GL-free.
#pragma once

#include <string>

#include "render/color_map.hpp"
#include "render/image.hpp"

namespace pl {

inline constexpr double kFontPixelsPerScale = 10.0;

// Width in pixels of `text`, and the height of its capitals (what a label is centred by).
int text_width(const std::string& text, double scale);
int text_height(double scale);

// Draws `text` with the top of its capitals at (x, y) (y down); descenders go below.
void draw_text(Image& image, int x, int y, const std::string& text, double scale, const Rgb& rgb);

// Fills an axis-aligned rectangle with rounded corners of radius r, blended with alpha a.
void fill_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r, const Rgb& rgb,
                       float a);
// The outline of the same rectangle, `width` pixels wide inside its edge.
void stroke_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r, double width,
                         const Rgb& rgb, float a);

}  // namespace pl
