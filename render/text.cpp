#include "render/text.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pl {

namespace {

// stb_easy_font's quad vertex: x, y, z as floats, then an RGBA byte colour.
struct FontVertex {
  float x, y, z;
  unsigned char color[4];
};
static_assert(sizeof(FontVertex) == 16);

}  // namespace

int text_width(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

int text_height(int scale) {
  return 7 * scale;
}

void draw_text(Image& image, int x, int y, const std::string& text, int scale,
               const std::array<float, 3>& rgb) {
  std::string copy = text;
  // The font uses about 270 bytes per character; twice that is safe.
  std::vector<FontVertex> quads(copy.size() * 40 + 64);
  const int n = stb_easy_font_print(0, 0, copy.data(), nullptr, quads.data(),
                                    static_cast<int>(quads.size() * sizeof(FontVertex)));
  for (int q = 0; q < n; ++q) {
    const FontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
    const float fx0 = std::min({v[0].x, v[1].x, v[2].x, v[3].x});
    const float fx1 = std::max({v[0].x, v[1].x, v[2].x, v[3].x});
    const float fy0 = std::min({v[0].y, v[1].y, v[2].y, v[3].y});
    const float fy1 = std::max({v[0].y, v[1].y, v[2].y, v[3].y});
    const int x0 = x + static_cast<int>(std::lround(fx0 * scale));
    const int x1 = x + static_cast<int>(std::lround(fx1 * scale));
    const int y0 = y + static_cast<int>(std::lround(fy0 * scale));
    const int y1 = y + static_cast<int>(std::lround(fy1 * scale));
    for (int py = y0; py < y1; ++py)
      for (int px = x0; px < x1; ++px) image.blend(px, py, rgb, 1.0f);
  }
}

void fill_rounded_rect(Image& image, int x0, int y0, int x1, int y1, int r,
                       const std::array<float, 3>& rgb, float a) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      // Distance outside the inner rectangle shrunk by r: > r is outside the rounded corner.
      const double dx = std::max({double(x0 + r) - (x + 0.5), (x + 0.5) - double(x1 - r), 0.0});
      const double dy = std::max({double(y0 + r) - (y + 0.5), (y + 0.5) - double(y1 - r), 0.0});
      const double d = std::hypot(dx, dy) - r;
      const float coverage = static_cast<float>(std::clamp(0.5 - d, 0.0, 1.0));
      image.blend(x, y, rgb, a * coverage);
    }
}

}  // namespace pl
