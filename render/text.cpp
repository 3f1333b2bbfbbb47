#include "render/text.hpp"

#include <algorithm>
#include <cmath>

#include "render/font.hpp"

namespace pl {

int text_width(const std::string& text, double scale) {
  return static_cast<int>(std::ceil(Font::labels().width(text, kFontPixelsPerScale * scale)));
}

int text_height(double scale) {
  return static_cast<int>(std::lround(Font::labels().cap_height(kFontPixelsPerScale * scale)));
}

void draw_text(Image& image, int x, int y, const std::string& text, double scale, const Rgb& rgb) {
  const Font& font = Font::labels();
  const double px = kFontPixelsPerScale * scale;
  font.draw(image, x, y + font.cap_height(px), text, px, rgb);
}

namespace {

// Coverage of pixel (x, y) by the rounded rectangle, and by the same rectangle shrunk by `inset`.
double rounded_coverage(int x, int y, int x0, int y0, int x1, int y1, int r, double inset) {
  const double rr = std::max(0.0, r - inset);
  const double a0 = x0 + inset, b0 = y0 + inset, a1 = x1 - inset, b1 = y1 - inset;
  // Distance outside the inner rectangle shrunk by rr: > rr is outside the rounded corner.
  const double dx = std::max({a0 + rr - (x + 0.5), (x + 0.5) - (a1 - rr), 0.0});
  const double dy = std::max({b0 + rr - (y + 0.5), (y + 0.5) - (b1 - rr), 0.0});
  const double d = std::max(
      {std::hypot(dx, dy) - rr, a0 - (x + 0.5), (x + 0.5) - a1, b0 - (y + 0.5), (y + 0.5) - b1});
  return std::clamp(0.5 - d, 0.0, 1.0);
}

}  // namespace

void fill_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r, const Rgb& rgb,
                       float a) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      image.blend(x, y, rgb, a * float(rounded_coverage(x, y, x0, y0, x1, y1, r, 0.0)));
}

void stroke_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r, double width,
                         const Rgb& rgb, float a) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const double ring = rounded_coverage(x, y, x0, y0, x1, y1, r, 0.0) -
                          rounded_coverage(x, y, x0, y0, x1, y1, r, width);
      image.blend(x, y, rgb, a * float(std::max(0.0, ring)));
    }
}

}  // namespace pl
